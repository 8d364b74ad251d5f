# plots/data_qmc_convergence.sh BIN DATA - RMS error of every point source of
# `qmc` on the four integrands of mc/testfn.h in two dimensions.
# qmc_convergence.csv (plots/rms.awk columns, the integrand in the program
# column) and qmc_convergence_slopes.csv (plots/fit.awk, on the absolute
# error): `qmc --integrand I --method all --dim 2 --scrambles 2 --csv` at
# N = 2^4 ... 2^16 points per scramble (powers of two, where Sobol sets are
# complete nets), 16 seeds per point (quick: up to 2^12, 8 seeds). The
# n column counts evaluations: 2N for the random methods (two scrambles or
# streams), N for unscrambled Sobol, whose one deterministic set makes the
# RMS over seeds its plain |error|.
source "$(dirname "$0")/lib.sh"
p=$(prog qmc)
hi=16 seeds=16
[ "$PLOTS_QUICK" = 1 ] && hi=12 seeds=8
nlist=$(awk -v hi="$hi" 'BEGIN { for (m = 4; m <= hi; m++) print 2 ^ m }')
out=$DATA/qmc_convergence.csv.tmp
first=1
base=500000
for integrand in pi smooth peak gauss; do
    raw=$(new_raw "qmc_convergence_$integrand")
    sweep "$raw" "$p" "$nlist" "$seeds" "$base" --integrand "$integrand" --method all --dim 2 --scrambles 2
    base=$((base + 100000))
    if [ $first = 1 ]; then rms "$integrand" <"$raw"; else rms "$integrand" <"$raw" | tail -n +2; fi
    first=0
    rm -f "$raw"
done >"$out"
fit rms_error <"$out" >"$DATA/qmc_convergence_slopes.csv.tmp"
publish qmc_convergence_slopes.csv qmc_convergence.csv
