# plots/qmc_points.gp - the first 256 points in 2D of every point source of
# `qmc`, as small multiples. Data: qmc_points.csv (plots/data_qmc_points.sh).
# The grey lines cut the square into the 16 x 16 cells of side 1/16: a
# (0,2)-net in base 2 of 256 points (every Sobol variant) has exactly one
# point in each of them, and in each cell of every other 256-cell grid of
# 2^a x 2^b boxes, which random points are far from.
W = 1500; H = 1040
load 'plots/style.gp'
f = datadir.'/qmc_points.csv'
methods = 'mc jitter halton sobol sobol-xor sobol-owen'
titles = '"Monte Carlo (PCG32)" "jittered 16 x 16 grid" "Halton (2, 3), permuted digits" "Sobol, unscrambled" "Sobol, random XOR shift" "Sobol, Owen-scrambled"'
unset key
set size ratio -1
set xrange [0:1]; set yrange [0:1]
set format x '%g'; set format y '%g'
set xtics 0, 0.25, 1 scale 0.5
set ytics 0, 0.25, 1 scale 0.5
set grid noxtics noytics
do for [k = 1:15] {
    set arrow k from k / 16.0, 0 to k / 16.0, 1 nohead lc rgb '#dddddd' lw 1 back
    set arrow 100 + k from 0, k / 16.0 to 1, k / 16.0 nohead lc rgb '#dddddd' lw 1 back
}
set multiplot layout 2, 3 title "{/:Bold The first 256 points of each source in 2D} (grey: the 16 x 16 cells of side 1/16)" font ',14'
do for [i = 1:6] {
    set title word(titles, i) font ',13'
    plot f using (sel(1, word(methods, i)) ? $3 : NaN):4 with points pt 7 ps 0.45 lc rgb '#0072B2'
}
unset multiplot
