# plots/data_pi_convergence.sh BIN DATA - RMS error of pi, plain and stratified.
# pi_convergence.csv (plots/rms.awk columns) and pi_convergence_slopes.csv
# (plots/fit.awk): `pi --method plain|stratified --csv` at N = 10^2 ... 10^8,
# two points per decade, 64 seeds per point (quick: up to 10^6).
source "$(dirname "$0")/lib.sh"
p=$(prog pi)
hi=8 seeds=64
[ "$PLOTS_QUICK" = 1 ] && hi=6
raw=$(new_raw pi_convergence)
for m in plain stratified; do
    sweep "$raw" "$p" "$(n_list 2 "$hi" 2)" "$seeds" 100000 --method "$m"
done
rms_publish "$raw" pi pi_convergence fit
