# plots/data_hemisphere_uniform_cosine.sh BIN DATA - the same uniforms warped
# to uniform and to cosine-weighted hemisphere directions (see
# examples/figure_geometry.c). hemisphere_uniform_cosine.csv: what
# `figure_geometry hemisphere` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_geometry)
"$p" hemisphere --points 1500 --seed 11 >"$DATA/hemisphere_uniform_cosine.csv.tmp" || die "figure_geometry hemisphere failed"
publish hemisphere_uniform_cosine.csv
