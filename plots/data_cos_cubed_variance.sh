# plots/data_cos_cubed_variance.sh BIN DATA - the integral of cos^3 theta
# over the hemisphere with uniform and cosine-weighted directions.
# cos_cubed_variance.csv (plots/rms.awk columns; mean_variance is the
# variance per sample the runs measured) and cos_cubed_variance_slopes.csv
# (plots/fit.awk): `cos_cubed --method all --csv` at N = 10^1 ... 10^6, two
# points per decade, 32 seeds (quick: up to 10^4).
source "$(dirname "$0")/lib.sh"
p=$(prog cos_cubed)
hi=6 seeds=32
[ "$PLOTS_QUICK" = 1 ] && hi=4
raw=$(new_raw cos_cubed_variance)
sweep "$raw" "$p" "$(n_list 1 "$hi" 2)" "$seeds" 400000 --method all
rms_publish "$raw" cos_cubed cos_cubed_variance fit
