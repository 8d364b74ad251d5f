# plots/hemisphere_mappings.gp - the lecture's table of hemisphere mappings.
# Data: hemisphere_mappings.csv (plots/data_hemisphere_mappings.sh): the
# same uniform (u1, u2) warped six ways. Top row: seen from above (x, y);
# bottom row: seen from the side (x, z). Uniform in (theta, phi) crowds the
# pole; uniform is uniform in solid angle; cosine is uniform in the top view
# (it is the projected disc); Phong and GGX concentrate about the normal.
W = 1800; H = 560
load 'plots/style.gp'
f = datadir.'/hemisphere_mappings.csv'
stats f using (sel(1, 'cosine') ? 1 : NaN) name 'S' nooutput
names = 'theta-phi uniform cosine phong-40 ggx-0.5 ggx-0.25'
titles = '"uniform in (θ, φ)" "uniform (solid angle)" "cosine: cos θ / π" "Phong lobe, n = 40" "GGX, α = 0.5" "GGX, α = 0.25"'
unset key; unset grid
set format x '%g'; set format y '%g'
set parametric
set trange [0:2*pi]
set samples 200
set xrange [-1.05:1.05]
set xtics -1, 1, 1 offset 0, 0.3
set tics scale 0.5
set multiplot title sprintf("{/:Bold Hemisphere mappings about the normal +z} (%d directions each, the same uniform points warped six ways)", S_records) font ',14'
# Panel geometry in pixels, so that both views keep x, y and z at one scale:
# the top view is a 236 x 236 square, the side view 236 x 118.
L = 80; pw = 236; gap = 50; top = 85; side_top = top + pw + 58
sx(px) = px / (1.0 * W)
sy(py) = 1 - py / (1.0 * H)
set label 1 '{/:Bold top view} (from +z)' at screen sx(25), sy(top + pw / 2) center rotate by 90
set label 2 '{/:Bold side view} (from -y)' at screen sx(25), sy(side_top + pw / 4) center rotate by 90
do for [i = 1:6] {
    m = word(names, i)
    left = L + (i - 1) * (pw + gap)
    set lmargin at screen sx(left); set rmargin at screen sx(left + pw)
    # top view: the unit disc, x to the right, y up
    set tmargin at screen sy(top); set bmargin at screen sy(top + pw)
    set yrange [-1.05:1.05]
    set ytics -1, 1, 1
    set title word(titles, i) font ',13' offset 0, -0.3
    set xlabel 'x' offset 0, 1.2
    set ylabel 'y' offset 1, 0
    if (i > 1) { unset label 1; unset label 2 }
    plot cos(t), sin(t) with lines lc rgb '#888888' lw 1, \
         f using (sel(1, m) ? $2 : NaN):3 with points pt 7 ps 0.22 lc rgb '#700072B2'
    # side view: the half disc, x to the right, z up
    set tmargin at screen sy(side_top); set bmargin at screen sy(side_top + pw / 2)
    set yrange [0:1.05]
    set ytics 0, 1, 1
    unset title
    set ylabel 'z' offset 1, 0
    plot cos(t / 2), sin(t / 2) with lines lc rgb '#888888' lw 1, \
         f using (sel(1, m) ? $2 : NaN):4 with points pt 7 ps 0.22 lc rgb '#70D55E00'
}
unset multiplot
