# plots/integrate_x_sq_convergence.gp - RMS error of the integral of x^2 over
# [0, 2] (= 8/3) against N for three sampling densities. Data:
# integrate_x_sq_convergence.csv and _slopes.csv
# (plots/data_integrate_x_sq_convergence.sh). Points: RMS error over
# independent seeds (+-1 sd of an RMS from that many seeds); solid lines:
# log-log least-squares fits; dashed: the prediction sigma / sqrt(N) from
# the analytic variances per sample, 256/45 (uniform) and 8/9 (linear).
# The quadratic density is proportional to the integrand: every sample
# weighs exactly 8/3, its error is zero up to round-off, which a log axis
# cannot show at the scale of the others: those points sit on the axis.
W = 1000; H = 680
load 'plots/style.gp'
f = datadir.'/integrate_x_sq_convergence.csv'
sf = datadir.'/integrate_x_sq_convergence_slopes.csv'
stats sf using (sel(2, 'uniform') ? $3 : NaN) name 'SU' nooutput
stats sf using (sel(2, 'uniform') ? $4 : NaN) name 'IU' nooutput
stats sf using (sel(2, 'linear') ? $3 : NaN) name 'SL' nooutput
stats sf using (sel(2, 'linear') ? $4 : NaN) name 'IL' nooutput
stats f using 4 name 'SEEDS' nooutput
stats f using 3 name 'N' nooutput
stats f using (sel(2, 'linear') ? $5 : NaN) name 'EL' nooutput
stats f using (sel(2, 'quadratic') ? $5 : NaN) name 'Q' nooutput
seeds = SEEDS_min
rel = 1 / sqrt(2 * seeds)
ylo = EL_min / 8

set title sprintf("{/:Bold ∫_0^2 x^2 dx = 8/3 by importance sampling: RMS error over %d seeds per point}", seeds) font ',14'
set logscale xy
set xlabel 'N, samples per estimate'
set ylabel 'RMS error of the estimate (absolute)'
set xrange [N_min / 2 : N_max * 2]
stats f using (sel(2, 'uniform') ? $5 : NaN) name 'EU' nooutput
set yrange [ylo : EU_max * 60]
set key top right
fitline(n, s, i) = 10 ** i * n ** s
# The quadratic density's error is 0 (or round-off): a log axis has no
# place for it, and a marker pinned to the bottom would read as an error
# of ylo. It gets a legend entry and no marker.
qtitle = Q_max == 0 ? 'quadratic p = 3x^2/8: error exactly 0 at every N (not drawn: no 0 on a log axis)' : \
    sprintf('quadratic p = 3x^2/8: error at most %.0e, round-off (not drawn)', Q_max)
plot sqrt(256.0 / 45 / x) with lines lt 1 dt 2 lw 1.5 title 'predicted √(256/45 / N)', \
     sqrt(8.0 / 9 / x) with lines lt 2 dt 2 lw 1.5 title 'predicted √(8/9 / N)', \
     f using (sel(2, 'uniform') ? $3 : NaN):5:($5 * (1 - rel)):($5 * (1 + rel)) with yerrorbars lt 1 title 'uniform p = 1/2', \
     fitline(x, SU_min, IU_min) with lines lt 1 title sprintf('uniform, fitted slope %.3f', SU_min), \
     f using (sel(2, 'linear') ? $3 : NaN):5:($5 * (1 - rel)):($5 * (1 + rel)) with yerrorbars lt 2 title 'linear p = x/2', \
     fitline(x, SL_min, IL_min) with lines lt 2 title sprintf('linear, fitted slope %.3f', SL_min), \
     NaN with points lt 3 pt 11 ps 1.6 title qtitle
