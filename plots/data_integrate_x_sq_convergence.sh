# plots/data_integrate_x_sq_convergence.sh BIN DATA - RMS error of the
# integral of x^2 over [0, 2] with the uniform, linear and quadratic pdfs.
# integrate_x_sq_convergence.csv (plots/rms.awk columns) and
# integrate_x_sq_convergence_slopes.csv (plots/fit.awk; the quadratic pdf
# has zero error, so no slope): `integrate_x_sq --pdf all --csv` at
# N = 10^1 ... 10^6, two points per decade, 32 seeds (quick: up to 10^4).
source "$(dirname "$0")/lib.sh"
p=$(prog integrate_x_sq)
hi=6 seeds=32
[ "$PLOTS_QUICK" = 1 ] && hi=4
raw=$(new_raw integrate_x_sq_convergence)
sweep "$raw" "$p" "$(n_list 1 "$hi" 2)" "$seeds" 200000 --pdf all
rms_publish "$raw" integrate_x_sq integrate_x_sq_convergence fit
