# plots/pi_convergence.gp - RMS error of the pi estimate against N, plain
# against stratified (jittered) points. Data: pi_convergence.csv and
# pi_convergence_slopes.csv (plots/data_pi_convergence.sh). Points: RMS
# error over independent seeds, with the +-1 sd uncertainty of an RMS from
# that many seeds (relative sd 1/sqrt(2 seeds)). Solid lines: least-squares
# fits in log-log, their slopes in the legend. Dashed: the reference rates
# N^-1/2 (plain Monte Carlo) and N^-3/4 (jittering a shape with a smooth
# boundary in 2D), drawn above and below the data.
W = 1000; H = 680
load 'plots/style.gp'
f = datadir.'/pi_convergence.csv'
sf = datadir.'/pi_convergence_slopes.csv'
stats sf using (sel(2, 'plain') ? $3 : NaN) name 'SP' nooutput
stats sf using (sel(2, 'plain') ? $4 : NaN) name 'IP' nooutput
stats sf using (sel(2, 'stratified') ? $3 : NaN) name 'SS' nooutput
stats sf using (sel(2, 'stratified') ? $4 : NaN) name 'IS' nooutput
stats f using 4 name 'SEEDS' nooutput
stats f using 3 name 'N' nooutput
stats f using ((sel(2, 'plain') && $3 == N_max) ? $5 : NaN) name 'EP' nooutput
stats f using ((sel(2, 'stratified') && $3 == N_max) ? $5 : NaN) name 'ES' nooutput
stats f using ((sel(2, 'plain') && $3 == N_min) ? $5 : NaN) name 'E0' nooutput
stats f using ((sel(2, 'stratified') && $3 == N_min) ? $5 : NaN) name 'E1' nooutput
seeds = SEEDS_min
rel = 1 / sqrt(2 * seeds)

set title sprintf("{/:Bold Estimating π by hits in the quarter disc: RMS error over %d seeds per point}", seeds) font ',14'
set logscale xy
set xlabel 'N, samples per estimate'
set ylabel 'RMS error of the estimate of π (absolute)'
set xrange [N_min / 2 : N_max * 2]
set key bottom left
set label 1 sprintf("at N = 10^{%.0f}: stratified is %.0f times more accurate\n(RMS %.1e against %.1e)", log10(N_max), EP_max / ES_max, ES_max, EP_max) at graph 0.97, graph 0.92 right
fitline(n, s, i) = 10 ** i * n ** s
plot E0_max * 3 * (x / N_min) ** -0.5 with lines lc rgb '#999999' dt 2 lw 1.5 title 'reference N^{-1/2}', \
     E1_max / 4 * (x / N_min) ** -0.75 with lines lc rgb '#999999' dt 4 lw 1.5 title 'reference N^{-3/4}', \
     f using (sel(2, 'plain') ? $3 : NaN):5:($5 * (1 - rel)):($5 * (1 + rel)) with yerrorbars lt 1 title 'plain: uniform points in the square', \
     fitline(x, SP_min, IP_min) with lines lt 1 title sprintf('plain, fitted slope %.3f', SP_min), \
     f using (sel(2, 'stratified') ? $3 : NaN):5:($5 * (1 - rel)):($5 * (1 + rel)) with yerrorbars lt 2 title 'stratified: one jittered point per grid cell', \
     fitline(x, SS_min, IS_min) with lines lt 2 title sprintf('stratified, fitted slope %.3f', SS_min)
