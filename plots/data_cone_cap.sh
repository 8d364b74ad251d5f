# plots/data_cone_cap.sh BIN DATA - the cap a cone cuts from the unit sphere
# and uniform points in it (see examples/figure_geometry.c). cone_cap.csv:
# what `figure_geometry cap` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" cap --points 500 --seed 7 >"$DATA/cone_cap.csv.tmp" || die "figure_geometry cap failed"
publish cone_cap.csv
