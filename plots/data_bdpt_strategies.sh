# plots/data_bdpt_strategies.sh BIN DATA - one path of three segments in the
# Cornell box and the weight of each of its strategies (see
# examples/figure_paths.c). bdpt_strategies.csv: what `figure_paths path`
# prints.
source "$(dirname "$0")/lib.sh"
p=$(prog figure_paths)
"$p" path --seed 7 >"$DATA/bdpt_strategies.csv.tmp" || die "figure_paths path failed"
publish bdpt_strategies.csv
