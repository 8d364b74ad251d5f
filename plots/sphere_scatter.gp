# plots/sphere_scatter.gp - the three uniform-sphere samplers, side by side.
# Data: sphere_scatter.csv (plots/data_sphere_scatter.sh), 2000 points each.
# Points on the near half of the sphere are drawn dark, those behind it
# light, so the eye can judge the uniformity in depth; the circles are the
# equator and the meridian plane x = 0, the dark one the sphere's outline.
W = 1500; H = 580
load 'plots/style.gp'
f = datadir.'/sphere_scatter.csv'
stats f using (sel(1, 'inverse') ? 1 : NaN) name 'S' nooutput
unset grid
rx = 62; rz = 35
# Unit vector towards the viewer of `set view rx, rz`.
ex = sin(rx * pi / 180) * sin(rz * pi / 180)
ey = -sin(rx * pi / 180) * cos(rz * pi / 180)
ez = cos(rx * pi / 180)
front(x, y, z) = x * ex + y * ey + z * ez >= 0
set view rx, rz
set view equal xyz
set xrange [-1:1]; set yrange [-1:1]; set zrange [-1:1]
unset border; unset xtics; unset ytics; unset ztics
# Two unit vectors across the line of sight: the silhouette circle.
ax = cos(rz * pi / 180); ay = sin(rz * pi / 180); az = 0
bx = ey * az - ez * ay; by = ez * ax - ex * az; bz = ex * ay - ey * ax
set parametric
set urange [0:2*pi]; set vrange [0:1]
set isosamples 2, 2
set samples 200
set key at screen 0.5, 0.07 center horizontal noopaque nobox
set multiplot layout 1, 3 title sprintf("{/:Bold Three uniform samplers of the unit sphere} (%d points each; each claims the density 1/(4π) per unit solid angle)\nPoints crowd toward each outline by projection alone: near the rim the sphere is seen edge-on, so equal areas look narrower.", S_records) font ',13' margins 0.02, 0.98, 0.1, 0.78 spacing 0.02, 0
# Short stubs of the positive axes outside the sphere, for orientation.
set arrow 1 from 1, 0, 0 to 1.3, 0, 0 lc rgb '#555555' lw 1.2 size 0.05, 20
set arrow 2 from 0, 1, 0 to 0, 1.3, 0 lc rgb '#555555' lw 1.2 size 0.05, 20
set arrow 3 from 0, 0, 1 to 0, 0, 1.3 lc rgb '#555555' lw 1.2 size 0.05, 20
set label 1 'x' at 1.4, 0, 0 center
set label 2 'y' at 0, 1.4, 0 center
set label 3 'z' at 0, 0, 1.42 center
do for [i = 1:3] {
    m = word('inverse gaussian rejection', i)
    set title word('"inverse CDF: z = 1 - 2u, φ = 2πu" "normalized Gaussian vector (x, y, z) / |(x, y, z)|" "rejection: uniform in the ball, then normalized"', i) offset 0, 3.2
    splot cos(u), sin(u), 0 with lines lc rgb '#bbbbbb' lw 1 notitle, \
          0, cos(u), sin(u) with lines lc rgb '#bbbbbb' lw 1 notitle, \
          ax * cos(u) + bx * sin(u), ay * cos(u) + by * sin(u), az * cos(u) + bz * sin(u) with lines lc rgb '#555555' lw 1.5 notitle, \
          f using (sel(1, m) && !front($2, $3, $4) ? $2 : NaN):3:4 with points pt 7 ps 0.35 lc rgb '#a6cbe3' title (i == 2 ? 'behind the sphere' : ''), \
          f using (sel(1, m) && front($2, $3, $4) ? $2 : NaN):3:4 with points pt 7 ps 0.35 lc rgb '#0b4f8a' title (i == 2 ? 'in front' : '')
}
unset multiplot
