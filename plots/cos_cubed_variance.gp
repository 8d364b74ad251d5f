# plots/cos_cubed_variance.gp - the integral of cos^3 theta over the
# hemisphere (= pi/2) with uniform and with cosine-weighted directions.
# Data: cos_cubed_variance.csv and _slopes.csv (plots/data_cos_cubed_variance.sh).
# Left: the variance per sample each run measured (stderr^2 N, averaged over
# the seeds) against the analytic values
#   uniform, weight 2 pi cos^3:  4 pi^2 E[cos^6] - pi^2/4 = 4 pi^2/7 - pi^2/4 = 9 pi^2/28
#   cosine,  weight pi cos^2:    pi^2 E[cos^4] - pi^2/4 = pi^2/3 - pi^2/4  = pi^2/12
# (cos theta uniform on [0, 1] under uniform directions, density 2c under
# cosine-weighted ones). Right: the resulting RMS error against N, with the
# predicted sqrt(variance / N) and the fitted slopes.
W = 1400; H = 620
load 'plots/style.gp'
f = datadir.'/cos_cubed_variance.csv'
sf = datadir.'/cos_cubed_variance_slopes.csv'
stats sf using (sel(2, 'uniform') ? $3 : NaN) name 'SU' nooutput
stats sf using (sel(2, 'uniform') ? $4 : NaN) name 'IU' nooutput
stats sf using (sel(2, 'cosine') ? $3 : NaN) name 'SC' nooutput
stats sf using (sel(2, 'cosine') ? $4 : NaN) name 'IC' nooutput
stats f using 4 name 'SEEDS' nooutput
stats f using 3 name 'N' nooutput
seeds = SEEDS_min
rel = 1 / sqrt(2 * seeds)
vu = 9 * pi ** 2 / 28
vc = pi ** 2 / 12
fitline(n, s, i) = 10 ** i * n ** s

set multiplot layout 1, 2 title sprintf("{/:Bold ∫ cos^3 θ dω over the hemisphere = π/2: uniform against cosine-weighted directions} (%d seeds per point)", seeds) font ',14'
set logscale x
set xrange [N_min / 2 : N_max * 2]
set xlabel 'N, samples per estimate'
set format y '%g'
set ylabel 'variance per sample of the weight f / p'
set yrange [0:4]
set key top right
set title sprintf('variance per sample: cosine sampling is %.1f times lower', vu / vc)
plot vu with lines lt 1 dt 2 title sprintf('uniform, analytic 9π^2/28 = %.3f', vu), \
     vc with lines lt 2 dt 2 title sprintf('cosine, analytic π^2/12 = %.3f', vc), \
     f using (sel(2, 'uniform') ? $3 : NaN):8 with linespoints lt 1 title 'uniform p = 1/(2π), measured', \
     f using (sel(2, 'cosine') ? $3 : NaN):8 with linespoints lt 2 title 'cosine p = cos θ / π, measured'

set logscale y
set format y '10^{%L}'
set ylabel 'RMS error of the estimate (absolute)'
set autoscale y
set key bottom left
set title 'RMS error against N'
plot sqrt(vu / x) with lines lt 1 dt 2 lw 1.5 title 'predicted √(9π^2/28 / N)', \
     sqrt(vc / x) with lines lt 2 dt 2 lw 1.5 title 'predicted √(π^2/12 / N)', \
     f using (sel(2, 'uniform') ? $3 : NaN):5:($5 * (1 - rel)):($5 * (1 + rel)) with yerrorbars lt 1 title 'uniform', \
     fitline(x, SU_min, IU_min) with lines lt 1 title sprintf('uniform, fitted slope %.3f', SU_min), \
     f using (sel(2, 'cosine') ? $3 : NaN):5:($5 * (1 - rel)):($5 * (1 + rel)) with yerrorbars lt 2 title 'cosine', \
     fitline(x, SC_min, IC_min) with lines lt 2 title sprintf('cosine, fitted slope %.3f', SC_min)
unset multiplot
