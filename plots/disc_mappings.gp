# plots/disc_mappings.gp - a grid of the unit square and its image under the
# two disc mappings of samplers/planar.h. Data: disc_mappings.csv
# (plots/data_disc_mappings.sh, examples/figure_geometry.c disc): the lines
# u1 = i/8 (blue) and u2 = j/8 (orange) through smp_unit_square_sample,
# smp_disc_polar_sample and smp_disc_concentric_sample, and one cell of the
# square (black) through each.
W = 1200; H = 460
load 'plots/style.gp'
f = datadir.'/disc_mappings.csv'
unset key; unset grid
set format x '%g'; set format y '%g'
set size ratio -1
set tics scale 0.5
set multiplot layout 1, 3 title "{/:Bold The unit square and its two images on the unit disc}\nBlue: lines of constant u_1; orange: lines of constant u_2; black: the cell [0.5, 0.625] × [0.75, 0.875] and its image" font ',12'
names = 'square polar concentric'
titles = '"the square (u_1, u_2)" "polar: φ = 2πu_1, r = √u_2" "concentric (Shirley and Chiu)"'
do for [i = 1:3] {
    m = word(names, i)
    if (i == 1) { set xrange [-0.05:1.05]; set yrange [-0.05:1.05]; set xtics 0, 0.5, 1; set ytics 0, 0.5, 1 } \
    else { set xrange [-1.05:1.05]; set yrange [-1.05:1.05]; set xtics -1, 1, 1; set ytics -1, 1, 1 }
    set title word(titles, i)
    plot f using (sel(1, m.'-u1') ? $2 : NaN):3 with lines lt 1 lw 1.2, \
         f using (sel(1, m.'-u2') ? $2 : NaN):3 with lines lt 2 lw 1.2, \
         f using (sel(1, m.'-cell') ? $2 : NaN):3 with lines lt 7 lw 2.5
}
unset multiplot
