# plots/area_solid_angle.gp - from area to solid angle: a parallelogram
# light seen from a point. Data: area_solid_angle.csv
# (plots/data_area_solid_angle.sh, examples/figure_geometry.c area): the
# light's outline and its points from smp_parallelogram_sample, the lines
# from the point to its corners, its normal (pdf_quad_constants), its image
# on the unit sphere about the point and the sampled points' directions
# (pdf_quad_direction), and the numbers of the title: the light's area, the
# distance and cosine at its centre and the solid angle
# 1 / smp_area_to_solid_angle(1 / A, r^2, cos θ_l).
W = 860; H = 720
load 'plots/style.gp'
f = datadir.'/area_solid_angle.csv'
stats f using (sel(1, 'value:area') ? $2 : NaN) name 'A' nooutput
stats f using (sel(1, 'value:r') ? $2 : NaN) name 'R' nooutput
stats f using (sel(1, 'value:cos_light') ? $2 : NaN) name 'C' nooutput
stats f using (sel(1, 'value:omega') ? $2 : NaN) name 'OM' nooutput
unset grid
set view 48, 305, 1.5
set view equal xyz
set xrange [-1.1:1.1]; set yrange [-0.6:1.5]; set zrange [0:2.6]
unset border; unset xtics; unset ytics; unset ztics
set label 1 'the point' at 0, 0, -0.12 center
set key at screen 0.5, 0.06 center horizontal maxrows 2 noopaque nobox
set title sprintf("{/:Bold From area to solid angle: d ω = d A cos θ_l / r^2}\nlight area A = %.3f, distance to its centre r = %.3f, cos θ_l = %.3f there:\nA cos θ_l / r^2 = %.4f sr (1 / smp\\_area\\_to\\_solid\\_angle); its image on the unit sphere is the blue outline", A_max, R_max, C_max, OM_max) font ',12'
splot f using (sel(1, 'sphere') ? $2 : NaN):3:4 with lines lc rgb '#d0d0d0' lw 0.8 notitle, \
      f using (sel(1, 'cone') ? $2 : NaN):3:4 with lines lc rgb '#888888' lw 1 dt 2 title 'lines to the corners', \
      f using (sel(1, 'axis') ? $2 : NaN):3:4 with lines lt 7 lw 1 title 'r, to the centre', \
      f using (sel(1, 'quad') ? $2 : NaN):3:4 with lines lt 2 lw 2.5 title 'the light', \
      f using (sel(1, 'normal') ? $2 : NaN):3:4 with lines lt 3 lw 2.5 title 'its normal', \
      f using (sel(1, 'point') ? $2 : NaN):3:4 with points pt 7 ps 0.3 lc rgb '#80D55E00' notitle, \
      f using (sel(1, 'image') ? $2 : NaN):3:4 with lines lt 1 lw 2.5 title 'image on the unit sphere', \
      f using (sel(1, 'direction') ? $2 : NaN):3:4 with points pt 7 ps 0.3 lc rgb '#800072B2' notitle
