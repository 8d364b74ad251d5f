# plots/data_sphere_scatter.sh BIN DATA - points of the three uniform-sphere
# samplers. sphere_scatter.csv: method,x,y,z with 2000 points per method
# from `sphere_plot --method inverse|gaussian|rejection` (inverse CDF
# z = 1 - 2u, normalized Gaussian vector, rejection from the ball), each
# with its own seed.
source "$(dirname "$0")/lib.sh"
p=$(prog sphere_plot)
out=$DATA/sphere_scatter.csv.tmp
echo method,x,y,z >"$out"
seed=11
for m in inverse gaussian rejection; do
    "$p" --method "$m" --samples 2000 --seed $((seed++)) |
        awk -v m="$m" 'NF == 3 { printf "%s,%.6f,%.6f,%.6f\n", m, $1, $2, $3 }' >>"$out"
done
publish sphere_scatter.csv
