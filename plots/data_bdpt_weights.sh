# plots/data_bdpt_weights.sh BIN DATA - the strategies' weights as the path's
# wall vertex moves up the wall (see examples/figure_paths.c).
# bdpt_weights.csv: what `figure_paths weights` prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_paths)
"$p" weights --seed 1 >"$DATA/bdpt_weights.csv.tmp" || die "figure_paths weights failed"
publish bdpt_weights.csv
