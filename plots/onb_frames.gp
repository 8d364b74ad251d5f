# plots/onb_frames.gp - the orthonormal bases that onb_from_w (mc/onb.h)
# builds from five normals. Data: onb_frames.csv (plots/data_onb_frames.sh,
# examples/figure_geometry.c onb): each basis drawn at the point n of the
# unit sphere, its third axis along n (black) and the two tangents s (blue)
# and t (orange) that the function returns, in the tangent plane there.
W = 800; H = 700
load 'plots/style.gp'
f = datadir.'/onb_frames.csv'
unset grid
set view 64, 28, 1.6
set view equal xyz
set xrange [-1.4:1.4]; set yrange [-1.4:1.4]; set zrange [-1.4:1.5]
unset border; unset xtics; unset ytics; unset ztics
set key at screen 0.5, 0.08 center horizontal maxrows 1 noopaque nobox
set title "{/:Bold Five bases from onb\\_from\\_w}\neach at the point n of the unit sphere: n (black), s (blue) and t (orange) with s × t = n;\nthe last normal points below the equator, the branch where n_z < 0" font ',12'
splot f using (sel(1, 'sphere') ? $2 : NaN):3:4 with lines lc rgb '#d0d0d0' lw 0.8 notitle, \
      f using (sel(1, 'w') ? $2 : NaN):3:4 with lines lt 7 lw 2.5 title 'n (the given normal)', \
      f using (sel(1, 'u') ? $2 : NaN):3:4 with lines lt 1 lw 2.5 title 's', \
      f using (sel(1, 'v') ? $2 : NaN):3:4 with lines lt 2 lw 2.5 title 't'
