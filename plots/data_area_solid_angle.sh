# plots/data_area_solid_angle.sh BIN DATA - a parallelogram light seen from a
# point: the cone of its corners, its image on the unit sphere, sampled points
# and their directions (see examples/figure_geometry.c). area_solid_angle.csv:
# what `figure_geometry area` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" area --points 300 --seed 5 >"$DATA/area_solid_angle.csv.tmp" || die "figure_geometry area failed"
publish area_solid_angle.csv
