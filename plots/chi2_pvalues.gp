# plots/chi2_pvalues.gp - is the chi-square test calibrated, and has it power?
# Data: chi2_pvalues.csv (plots/data_chi2_pvalues.sh): the p-value of the
# same test over many seeds, for the cosine sampler with its own pdf
# (correct) and for directions uniform in (theta, phi) claimed uniform in
# solid angle (wrong). Left: histograms of the p-values; a calibrated test
# gives a flat histogram (band: binomial +-2 sd per bin). Right: the
# empirical distribution function against the diagonal of U(0, 1), with the
# Kolmogorov-Smirnov 95% band.
W = 1400; H = 620
load 'plots/style.gp'
f = datadir.'/chi2_pvalues.csv'
stats f using (sel(1, 'correct') ? $6 : NaN) name 'C' nooutput
stats f using (sel(1, 'wrong') ? $6 : NaN) name 'X' nooutput
stats f using (sel(1, 'correct') ? ($6 < 0.05) : NaN) name 'C5' nooutput
stats f using (sel(1, 'wrong') ? ($6 == X_min) : NaN) name 'X0' nooutput
stats f using 3 name 'NS' nooutput
stats f using 5 name 'DOF' nooutput
seeds = C_records
nbins = 20
bw = 1.0 / nbins
mean = seeds / nbins
sd = sqrt(seeds * bw * (1 - bw))
bin(p) = bw * (p >= 1 ? nbins - 1 : floor(p / bw)) + bw / 2

set multiplot layout 1, 2 title sprintf("{/:Bold Chi-square p-values over %d seeds}: N = %.0f samples in %.0f cells of (φ, cos θ) per test\ncorrect pair: cosine-weighted sampler against its pdf cos θ / π;   wrong pair: θ and φ uniform, claimed uniform in solid angle (sin θ forgotten)", seeds, NS_max, DOF_max + 1) font ',13'
set format x '%g'; set format y '%g'
set xrange [0:1]
set xtics 0.1
set xlabel 'p-value'
set ylabel 'seeds per bin of width 0.05'
set logscale y
set yrange [0.8:seeds * 12]
set key top right
set boxwidth bw absolute
set style fill transparent solid 0.5 noborder
set title 'histogram (log scale): correct flat, wrong piled at 0'
plot '+' using 1:(mean - 2 * sd):(mean + 2 * sd) with filledcurves lc rgb '#cccccc' title 'calibrated: mean ± 2 sd per bin', \
     mean with lines lc rgb '#555555' dt 2 lw 1.5 notitle, \
     f using (sel(1, 'wrong') ? bin($6) : NaN):(1) smooth frequency with boxes fs solid 0.5 border lc rgb '#D55E00' lc rgb '#D55E00' \
       title 'wrong pair: '.(X_max == 0 ? 'every p = 0' : sprintf('largest p %.1g', X_max)), \
     f using (sel(1, 'correct') ? bin($6) : NaN):(1) smooth frequency with boxes fs solid 0.6 border lc rgb '#0072B2' lc rgb '#0072B2' \
       title sprintf('correct pair: %d of %d below 0.05', C5_sum, seeds)

unset logscale y
set yrange [0:1.05]
set ytics 0.1
set ylabel 'fraction of seeds with p-value ≤ x'
set xlabel 'p-value x'
set key bottom right
set title 'empirical distribution function of the p-values'
ks = 1.358 / sqrt(seeds)
set xrange [-0.02:1.02]
set samples 500
plot sample [t=0:1] '+' using 1:($1 - ks < 0 ? 0 : $1 - ks):($1 + ks > 1 ? 1 : $1 + ks) with filledcurves lc rgb '#dddddd' title 'Kolmogorov-Smirnov 95% band', \
     x with lines lc rgb '#555555' dt 2 lw 1.5 title 'U(0, 1): a calibrated test', \
     f using (sel(1, 'correct') ? $6 : NaN):(1.0 / seeds) smooth cumulative with steps lt 1 title 'correct pair', \
     f using (sel(1, 'wrong') ? $6 : NaN):(1.0 / seeds) smooth cumulative with steps lt 2 title 'wrong pair: all its mass at 0', \
     [t=0:1] '+' using (C_max + $1 * (1 - C_max)):(1) with lines lt 1 notitle, \
     [t=0:1] '+' using (X_max + $1 * (1 - X_max)):(1) with lines lt 2 notitle, \
     [t=0:1] '+' using (X_min):($1 * X0_sum / seeds) with lines lt 2 notitle
unset multiplot
