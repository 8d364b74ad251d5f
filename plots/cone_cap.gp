# plots/cone_cap.gp - the cap that a cone of half-angle theta_max cuts from
# the unit sphere, seen from the side. Data: cone_cap.csv
# (plots/data_cone_cap.sh, examples/figure_geometry.c cap): the circle and
# the cap's rim from smp_spherical_direction, points of
# smp_uniform_cone_sample and, at the right, the same points carried
# horizontally to the cylinder around the sphere (spread sideways by their
# row number, to be seen), where they are uniform in height (Archimedes: the cap's area is 2π h, h = 1 - cos θ_max).
W = 900; H = 660
load 'plots/style.gp'
f = datadir.'/cone_cap.csv'
stats f using (sel(1, 'value:cos_theta_max') ? $2 : NaN) name 'C' nooutput
stats f using (sel(1, 'value:omega') ? $2 : NaN) name 'O' nooutput
stats f using (sel(1, 'point') ? 1 : NaN) name 'N' nooutput
c = C_max; h = 1 - c
unset key; unset grid
set format x '%g'; set format y '%g'
set size ratio -1
set xrange [-1.25:1.55]; set yrange [-1.1:1.2]
set xtics -1, 1, 1; set ytics -1, 1, 1
set tics scale 0.5
set xlabel 'x'; set ylabel 'z'
set title sprintf("{/:Bold The cap of a cone of half-angle θ_{max} = %.0f°, from the side}\nsolid angle 2πh = %.4f (1 / smp\\_uniform\\_cone\\_pdf); %d points of smp\\_uniform\\_cone\\_sample,\nand (right) their heights on the cylinder around the sphere: uniform in [cos θ_{max}, 1]", acos(c) * 180 / pi, O_max, N_records) font ',12'
# The cylinder of Archimedes and the height h of the cap.
set arrow 1 from 1.3, -1 to 1.3, 1 nohead lc rgb '#999999' lw 1
set arrow 2 from 1.45, c to 1.45, 1 heads size 0.03, 90 lc rgb '#000000' lw 1.5
set label 1 'h' at 1.49, (1 + c) / 2 left
set arrow 3 from -1.1, c to 1.3, c nohead dt 3 lc rgb '#999999'
set arrow 4 from -1.1, 1 to 1.3, 1 nohead dt 3 lc rgb '#999999'
set label 2 'θ_{max}' at 0.09, 0.33 left
plot f using (sel(1, 'circle') ? $2 : NaN):4 with lines lc rgb '#888888' lw 1, \
     f using (sel(1, 'edge') ? $2 : NaN):4 with lines lt 7 lw 1.5, \
     f using (sel(1, 'cap') ? $2 : NaN):4 with lines lt 2 lw 4, \
     f using (sel(1, 'point') ? $2 : NaN):4 with points pt 7 ps 0.35 lc rgb '#600072B2', \
     f using (sel(1, 'point') ? 1.24 + 0.12 * (int($0) % 37) / 37.0 : NaN):4 with points pt 7 ps 0.3 lc rgb '#60D55E00'
