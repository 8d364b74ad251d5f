# plots/bdpt_weights.gp - the balance heuristic's weights of the four
# strategies of one family of three-segment paths. Data: bdpt_weights.csv
# (plots/data_bdpt_weights.sh, examples/figure_paths.c weights): the path
# camera, floor point x2, wall point x1, lamp point x0 of figure_paths,
# with x1 moved up the green wall (x = 555, z = 280, below the lamp);
# rt_bdpt_mis_weight for s = 0 .. 3 light vertices at each height where x2
# sees x1, and their sum.
W = 1200; H = 500
load 'plots/style.gp'
f = datadir.'/bdpt_weights.csv'
set datafile columnheaders
set multiplot layout 1, 2 title "{/:Bold The balance heuristic's weights along a family of paths}\nx_1 slides up the green wall; the camera, x_2 on the floor and x_0 on the lamp stay put (rt\\_bdpt\\_mis\\_weight)" font ',12'
set format x '%g'; set format y '%g'
set xrange [0:555]
set xlabel 'height of x_1 on the wall'
set ylabel 'weight'
set yrange [0:1.05]
set key at graph 0.98, 0.9 right top
set title 'linear scale: the four weights and their sum'
plot f using 1:2 with lines lt 1 notitle, \
     f using 1:3 with lines lt 2 notitle, \
     f using 1:4 with lines lt 3 notitle, \
     f using 1:5 with lines lt 4 notitle, \
     f using 1:6 with lines lt 7 lw 1 dt 2 title 'sum'
set logscale y
set format y '10^{%L}'
set yrange [1e-9:2]
set key at graph 0.5, 0.3 center top
set title 'log scale: s = 0 never gets much'
plot f using 1:2 with lines lt 1 title 's = 0 (the camera path hits the lamp)', \
     f using 1:3 with lines lt 2 title 's = 1 (a lamp point joined to x_1)', \
     f using 1:4 with lines lt 3 title 's = 2 (x_0 x_1 joined to x_2)', \
     f using 1:5 with lines lt 4 title 's = 3 (x_0 x_1 x_2 joined to the camera)'
unset multiplot
