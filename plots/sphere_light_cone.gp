# plots/sphere_light_cone.gp - the cone of directions from a point toward a
# sphere light, in the plane through the point and the sphere's centre.
# Data: sphere_light_cone.csv (plots/data_sphere_light_cone.sh,
# examples/figure_geometry.c cone): the sphere's outline, the cone's two
# edges at cos θ_max from pdf_toward_sphere (smp_sphere_cone_cap), 40
# directions of pdf_generate drawn as rays up to where they meet the sphere
# (rt_sphere_hit_distance), and all the drawn directions as points on the
# unit circle about the point, where they fill the cone's cap. Every point
# is projected onto the plane y = 0.
W = 760; H = 700
load 'plots/style.gp'
f = datadir.'/sphere_light_cone.csv'
stats f using (sel(1, 'value:cos_theta_max') ? $2 : NaN) name 'C' nooutput
stats f using (sel(1, 'value:density') ? $2 : NaN) name 'D' nooutput
stats f using (sel(1, 'direction') ? 1 : NaN) name 'N' nooutput
unset key; unset grid
set format x '%g'; set format y '%g'
set size ratio -1
set xrange [-1.2:2.4]; set yrange [-0.3:3.4]
set xtics -1, 1, 2; set ytics 0, 1, 3
set tics scale 0.5
set xlabel 'x'; set ylabel 'z'
set parametric
set trange [0:2*pi]
set samples 200
set title sprintf("{/:Bold The cone from a point toward a sphere light}\nθ_{max} = %.1f°, density 1/(2π(1 - cos θ_{max})) = %.3f per steradian inside the cone, 0 outside\n(pdf\\_toward\\_sphere; %d directions from pdf\\_generate, 40 of them traced to the sphere)", acos(C_max) * 180 / pi, D_max, N_records) font ',12'
set label 1 'the point' at -0.08, -0.12 right
set label 2 'unit circle' at -0.75, 0.55 right textcolor rgb '#888888'
plot cos(t), sin(t) with lines lc rgb '#cccccc' lw 1, \
     f using (sel(1, 'sphere') ? $2 : NaN):4 with lines lt 2 lw 2.5, \
     f using (sel(1, 'edge') ? $2 : NaN):4 with lines lt 7 lw 1.5, \
     f using (sel(1, 'axis') ? $2 : NaN):4 with lines lt 7 lw 1 dt 2, \
     f using (sel(1, 'ray') ? $2 : NaN):4 with lines lc rgb '#a00072B2' lw 0.8, \
     f using (sel(1, 'direction') ? $2 : NaN):4 with points pt 7 ps 0.35 lc rgb '#40009E73'
