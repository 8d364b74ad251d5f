# plots/data_hemisphere_mappings.sh BIN DATA - the lecture's table of
# hemisphere mappings. hemisphere_mappings.csv: mapping,x,y,z with 2500
# directions per mapping from `warp sample`: uniform in (theta, phi),
# uniform in solid angle, cosine-weighted, Phong n = 40, GGX alpha = 0.5
# and alpha = 0.25 (the same seed for all: the same u, warped six ways).
source "$(dirname "$0")/lib.sh"
w=$(prog warp)
n=2500
out=$DATA/hemisphere_mappings.csv.tmp
echo mapping,x,y,z >"$out"
while read -r label name params; do
    # shellcheck disable=SC2086
    "$w" sample "$name" $params --n "$n" --seed 21 |
        awk -v m="$label" '{ printf "%s,%.6f,%.6f,%.6f\n", m, $1, $2, $3 }' >>"$out"
done <<'LIST'
theta-phi theta-phi
uniform hemisphere
cosine cosine
phong-40 phong --param n=40
ggx-0.5 ggx --param alpha=0.5
ggx-0.25 ggx --param alpha=0.25
LIST
publish hemisphere_mappings.csv
