# plots/data_qmc_points.sh BIN DATA - the first 256 points in 2D of every
# point source of `qmc`. qmc_points.csv: method,i,x,y from
# `qmc points --method M --dim 2 --samples 256 --seed 7` (the random and
# scrambled sources at one seed; jitter is its 16 x 16 grid).
source "$(dirname "$0")/lib.sh"
p=$(prog qmc)
out=$DATA/qmc_points.csv.tmp
echo method,i,x,y >"$out"
for m in mc jitter halton sobol sobol-xor sobol-owen; do
    "$p" points --method "$m" --dim 2 --samples 256 --seed 7 |
        awk -F, -v m="$m" 'NR > 1 { print m "," $0 }' >>"$out" || die "qmc points --method $m failed"
done
publish qmc_points.csv
