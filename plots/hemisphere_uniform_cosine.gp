# plots/hemisphere_uniform_cosine.gp - uniform against cosine-weighted
# hemisphere directions. Data: hemisphere_uniform_cosine.csv
# (plots/data_hemisphere_uniform_cosine.sh, examples/figure_geometry.c
# hemisphere): the same (u1, u2) through smp_uniform_hemisphere_sample and
# smp_cosine_hemisphere_sample. Top row from the side (x, z), bottom row
# from above (x, y): cosine-weighted points thin out toward the horizon and
# are uniform in the top view.
W = 1000; H = 760
load 'plots/style.gp'
f = datadir.'/hemisphere_uniform_cosine.csv'
stats f using (sel(1, 'uniform') ? 1 : NaN) name 'S' nooutput
stats f using (sel(1, 'value:uniform_pdf') ? $2 : NaN) name 'PU' nooutput
stats f using (sel(1, 'value:cosine_pdf_pole') ? $2 : NaN) name 'PC' nooutput
unset key; unset grid
set format x '%g'; set format y '%g'
set parametric
set trange [0:2*pi]
set samples 200
set size ratio -1
set tics scale 0.5
set xrange [-1.05:1.05]; set xtics -1, 1, 1
set multiplot layout 2, 2 title sprintf("{/:Bold The same %d uniform points, warped two ways}\nuniform: density %.4f = 1/(2π) everywhere; cosine: density cos θ / π, %.4f = 1/π at the pole, 0 at the horizon", S_records, PU_max, PC_max) font ',12'
set yrange [-0.05:1.05]; set ytics 0, 1, 1
set xlabel 'x' offset 0, 1; set ylabel 'z' offset 1, 0
set title 'smp\_uniform\_hemisphere\_sample, from the side'
plot cos(t / 2), sin(t / 2) with lines lc rgb '#888888' lw 1, \
     f using (sel(1, 'uniform') ? $2 : NaN):4 with points pt 7 ps 0.25 lc rgb '#600072B2'
set title 'smp\_cosine\_hemisphere\_sample, from the side'
plot cos(t / 2), sin(t / 2) with lines lc rgb '#888888' lw 1, \
     f using (sel(1, 'cosine') ? $2 : NaN):4 with points pt 7 ps 0.25 lc rgb '#60D55E00'
set yrange [-1.05:1.05]; set ytics -1, 1, 1
set ylabel 'y'
set title 'uniform, from above'
plot cos(t), sin(t) with lines lc rgb '#888888' lw 1, \
     f using (sel(1, 'uniform') ? $2 : NaN):3 with points pt 7 ps 0.25 lc rgb '#600072B2'
set title 'cosine-weighted, from above: uniform in the disc'
plot cos(t), sin(t) with lines lc rgb '#888888' lw 1, \
     f using (sel(1, 'cosine') ? $2 : NaN):3 with points pt 7 ps 0.25 lc rgb '#60D55E00'
unset multiplot
