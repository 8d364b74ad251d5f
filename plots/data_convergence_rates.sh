# plots/data_convergence_rates.sh BIN DATA - every estimator's RMS error
# against N in one table. convergence_rates.csv (plots/rms.awk columns):
# the RMS tables that plots/rates.list names, in its order: NAME.csv of a
# "table" line, rates_NAME.csv of a "rates" line (made before this script
# runs, by make); convergence_rates_slopes.csv:
# their fitted slopes, on the relative error (plots/fit.awk).
source "$(dirname "$0")/lib.sh"
tables=$(awk '$1 == "table" { print $2 } $1 == "rates" { print "rates_" $2 }' "$LIBDIR/rates.list")
out=$DATA/convergence_rates.csv.tmp
first=1
for t in $tables; do
    f=$DATA/$t.csv
    [ -f "$f" ] || die "$f is missing (make makes it first)"
    if [ $first = 1 ]; then cat "$f"; else tail -n +2 "$f"; fi
    first=0
done >"$out"
fit rel_rms_error <"$out" >"$DATA/convergence_rates_slopes.csv.tmp"
publish convergence_rates_slopes.csv convergence_rates.csv
