# plots/data_onb_frames.sh BIN DATA - the bases that onb_from_w builds from
# five normals (see examples/figure_geometry.c). onb_frames.csv: what
# `figure_geometry onb` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" onb  >"$DATA/onb_frames.csv.tmp" || die "figure_geometry onb failed"
publish onb_frames.csv
