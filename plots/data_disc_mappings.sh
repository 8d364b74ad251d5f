# plots/data_disc_mappings.sh BIN DATA - a grid of the unit square under the
# polar and the concentric disc mappings (see examples/figure_geometry.c).
# disc_mappings.csv: what `figure_geometry disc` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" disc  >"$DATA/disc_mappings.csv.tmp" || die "figure_geometry disc failed"
publish disc_mappings.csv
