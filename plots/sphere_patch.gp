# plots/sphere_patch.gp - a patch of the unit sphere and the angles that
# place it: the area element d ω = sin θ dθ dφ. Data: sphere_patch.csv
# (plots/data_sphere_patch.sh, examples/figure_geometry.c sphere-patch):
# every curve is a set of directions of smp_spherical_direction (meridians,
# parallels, the patch's four edges and its hatching, the arcs of θ and φ);
# the patch's solid angle comes from smp_uniform_sphere_invert of its
# corners, whose (u1, u2) carry d ω = 4π du1 du2.
W = 860; H = 640
load 'plots/style.gp'
f = datadir.'/sphere_patch.csv'
stats f using (sel(1, 'value:omega') ? $2 : NaN) name 'OM' nooutput
stats f using (sel(1, 'value:approx') ? $2 : NaN) name 'AP' nooutput
unset key; unset grid
set view 60, 72, 1.45
set view equal xyz
set xrange [-1.05:1.05]; set yrange [-1.05:1.05]; set zrange [0:1.35]
unset border; unset xtics; unset ytics; unset ztics
set xyplane at 0
set title sprintf("{/:Bold A patch of the unit sphere: 50° ≤ θ ≤ 65°, 20° ≤ φ ≤ 50°}\nsolid angle %.4f sr (exact, from smp\\_uniform\\_sphere\\_invert); sin θ Δθ Δφ = %.4f sr at the upper edge", OM_max, AP_max) font ',12'
set label 1 'x' at 1.38, 0, 0 center
set label 2 'y' at 0, 1.38, 0 center
set label 3 'z' at 0, 0, 1.42 center
set label 4 'θ' at first 0.21, 0.08, 0.44 center font ',14'
set label 5 'φ' at first 0.58, 0.1, 0.0 center font ',14'
set label 6 'sin θ' at first 0.36, 0.13, 0.74 center textcolor rgb '#009E73'
splot f using (sel(1, 'sphere') ? $2 : NaN):3:4 with lines lc rgb '#c8c8c8' lw 0.8, \
      f using (sel(1, 'axis') ? $2 : NaN):3:4 with lines lt 7 lw 1.2, \
      f using (sel(1, 'ray') ? $2 : NaN):3:4 with lines lt 7 lw 1 dt 2, \
      f using (sel(1, 'angle') ? $2 : NaN):3:4 with lines lt 7 lw 1.5, \
      f using (sel(1, 'sin') ? $2 : NaN):3:4 with lines lt 3 lw 2, \
      f using (sel(1, 'fill') ? $2 : NaN):3:4 with lines lc rgb '#D55E00' lw 1, \
      f using (sel(1, 'patch') ? $2 : NaN):3:4 with lines lt 2 lw 3, \
      f using (sel(1, 'label:dtheta') ? $2 : NaN):3:4:('dθ') with labels font ',13', \
      f using (sel(1, 'label:dphi') ? $2 : NaN):3:4:('sin θ dφ') with labels font ',13'
