# plots/data_rates.sh PROGRAM BIN DATA - RMS error against N of every
# estimator one chapter program prints, for the convergence_rates figure.
# rates_PROGRAM.csv (plots/rms.awk columns): PROGRAM ARGS --csv at
# N = 10^2 ... 10^5, two points per decade, 64 seeds (quick: up to 10^4,
# 16 seeds). ARGS selects every method the program has (table below).
# Three decades and 64 seeds give the slope as precisely (about +-0.015) as
# four decades and 32 seeds, at a fifth of the cost.
name=${1:-}
shift
source "$(dirname "$0")/lib.sh"
case $name in
log_sin | sphere_importance | light_pdf | sphere_light) args=(--method all) ;;
projected_area) args=(--body all) ;;
estimate_halfway | inverse_cdf | mixture) args=() ;;
*) die "no convergence sweep defined for '$name'" ;;
esac
p=$(prog "$name")
hi=5 seeds=64
[ "$PLOTS_QUICK" = 1 ] && hi=4 seeds=16
raw=$(new_raw "rates_$name")
sweep "$raw" "$p" "$(n_list 2 "$hi" 2)" "$seeds" 300000 "${args[@]}"
rms_publish "$raw" "$name" "rates_$name"
