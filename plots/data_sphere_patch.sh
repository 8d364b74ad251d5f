# plots/data_sphere_patch.sh BIN DATA - a patch of the unit sphere, the angles
# theta and phi that place it and its solid angle (see
# examples/figure_geometry.c). sphere_patch.csv: what `figure_geometry sphere-
# patch` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" sphere-patch  >"$DATA/sphere_patch.csv.tmp" || die "figure_geometry sphere-patch failed"
publish sphere_patch.csv
