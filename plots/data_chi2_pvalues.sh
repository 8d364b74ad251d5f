# plots/data_chi2_pvalues.sh BIN DATA - the chi-square p-value over many seeds.
# chi2_pvalues.csv: case,seed,n,chi2,dof,p for the correct pair (cosine
# sampler, cosine pdf) and a wrong one (uniform in theta and phi, claimed
# uniform in solid angle): 200 seeds of 10^5 samples (quick: 60 of 2 10^4).
source "$(dirname "$0")/lib.sh"
n=100000 seeds=200
[ "$PLOTS_QUICK" = 1 ] && n=20000 seeds=60
p=$(prog plotdata_chi2)
"$p" pvalues --samples "$n" --seeds "$seeds" --seed 1000 \
    >"$DATA/chi2_pvalues.csv.tmp"
publish chi2_pvalues.csv
