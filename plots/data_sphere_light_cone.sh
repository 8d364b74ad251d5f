# plots/data_sphere_light_cone.sh BIN DATA - the cone toward a sphere light
# and directions drawn from pdf_toward_sphere (see
# examples/figure_geometry.c). sphere_light_cone.csv: what `figure_geometry
# cone` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" cone --points 400 --seed 3 >"$DATA/sphere_light_cone.csv.tmp" || die "figure_geometry cone failed"
publish sphere_light_cone.csv
