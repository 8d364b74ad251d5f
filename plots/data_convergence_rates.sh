# plots/data_convergence_rates.sh BIN DATA - every estimator's RMS error
# against N in one table. convergence_rates.csv (plots/rms.awk columns):
# the RMS tables of pi_convergence, integrate_x_sq_convergence,
# cos_cubed_variance and rates_<program> for the other chapter programs
# (made before this script runs, by make); convergence_rates_slopes.csv:
# their fitted slopes, on the relative error (plots/fit.awk).
source "$(dirname "$0")/lib.sh"
tables=(pi_convergence integrate_x_sq_convergence log_sin estimate_halfway inverse_cdf
    sphere_importance cos_cubed_variance light_pdf sphere_light projected_area mixture)
out=$DATA/convergence_rates.csv.tmp
first=1
for t in "${tables[@]}"; do
    f=$DATA/$t.csv
    [ -f "$f" ] || f=$DATA/rates_$t.csv
    [ -f "$f" ] || die "$DATA/$t.csv or rates_$t.csv is missing (make makes it first)"
    if [ $first = 1 ]; then cat "$f"; else tail -n +2 "$f"; fi
    first=0
done >"$out"
fit rel_rms_error <"$out" >"$DATA/convergence_rates_slopes.csv.tmp"
publish convergence_rates_slopes.csv convergence_rates.csv
