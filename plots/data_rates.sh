# plots/data_rates.sh PROGRAM BIN DATA - RMS error against N of every
# estimator one chapter program prints, for the convergence_rates figure.
# rates_PROGRAM.csv (plots/rms.awk columns): PROGRAM ARGS --csv at
# N = 10^2 ... 10^5, two points per decade, 64 seeds (quick: up to 10^4,
# 16 seeds). ARGS selects every method the program has: its "rates" line of
# plots/rates.list.
# Three decades and 64 seeds give the slope as precisely (about +-0.015) as
# four decades and 32 seeds, at a fifth of the cost.
name=${1:-}
shift
source "$(dirname "$0")/lib.sh"
line=$(awk -v n="$name" '$1 == "rates" && $2 == n { $1 = $2 = ""; print; found = 1 }
    END { exit !found }' "$LIBDIR/rates.list") ||
    die "no convergence sweep defined for '$name' in plots/rates.list"
read -r -a args <<<"$line"
p=$(prog "$name")
hi=5 seeds=64
[ "$PLOTS_QUICK" = 1 ] && hi=4 seeds=16
raw=$(new_raw "rates_$name")
sweep "$raw" "$p" "$(n_list 2 "$hi" 2)" "$seeds" 300000 "${args[@]}"
rms_publish "$raw" "$name" "rates_$name"
