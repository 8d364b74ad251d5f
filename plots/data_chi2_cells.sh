# plots/data_chi2_cells.sh BIN DATA - one chi-square test, cell by cell.
# chi2_cells.csv: i,j,cos_lo,cos_hi,phi_lo,phi_hi,observed,expected,diff_sd
# for the cosine-weighted hemisphere sampler, 10^5 samples (quick: 2 10^4)
# in 16 x 32 cells of (cos theta, phi) (see examples/plotdata_chi2.c).
source "$(dirname "$0")/lib.sh"
n=100000
[ "$PLOTS_QUICK" = 1 ] && n=20000
p=$(prog plotdata_chi2)
"$p" cells --samples "$n" --seed 7 --cos-cells 16 --phi-cells 32 \
    >"$DATA/chi2_cells.csv.tmp"
publish chi2_cells.csv
