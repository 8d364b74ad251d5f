# plots/mixture_lobes.gp - the two lobes of chapter 9's mixture and their
# sum. Data: mixture_lobes.csv (plots/data_mixture_lobes.sh,
# examples/figure_geometry.c mixture): pdf_value of pdf_cosine, of
# pdf_toward_quad (the light of examples/mixture.c) and of their 1/2 + 1/2
# pdf_mixture, for directions in the plane of the normal and the light's
# centre. Left: a polar plot (distance from the origin = density); right:
# the same densities against the angle, on a log scale.
W = 1200; H = 520
load 'plots/style.gp'
f = datadir.'/mixture_lobes.csv'
d2r = pi / 180
set multiplot layout 1, 2 title "{/:Bold The mixture's density is the weighted sum of its two lobes}\n(per unit solid angle, along the plane through the normal +z and the light's centre; positive angles lean toward the light)" font ',12'
set key top left
set format x '%g'; set format y '%g'
set size ratio -1
set xrange [-1.2:4.2]; set yrange [-0.6:6.2]
set xlabel 'density × sin(angle)'; set ylabel 'density × cos(angle)'
set title 'polar plot: the distance from the origin is the density'
plot f using (sel(1, 'cosine') ? $3 * sin($2 * d2r) : NaN):($3 * cos($2 * d2r)) with lines lt 1 lw 2 title 'cosine: cos θ / π', \
     f using (sel(1, 'light') ? $3 * sin($2 * d2r) : NaN):($3 * cos($2 * d2r)) with lines lt 2 lw 2 title 'toward the quad light', \
     f using (sel(1, 'mixture') ? $3 * sin($2 * d2r) : NaN):($3 * cos($2 * d2r)) with lines lt 7 lw 1.5 dt 2 title 'mixture, 1/2 + 1/2'
set size noratio
set logscale y
set format y '10^{%L}'
set xrange [-100:100]; set yrange [0.01:20]
set xtics -90, 30, 90
set xlabel 'angle from the normal (degrees)'; set ylabel 'density per steradian'
set title 'the same densities on a log scale'
plot f using (sel(1, 'cosine') ? $2 : NaN):($3 > 0 ? $3 : NaN) with lines lt 1 lw 2 title 'cosine', \
     f using (sel(1, 'light') ? $2 : NaN):($3 > 0 ? $3 : NaN) with lines lt 2 lw 2 title 'light', \
     f using (sel(1, 'mixture') ? $2 : NaN):($3 > 0 ? $3 : NaN) with lines lt 7 lw 1.5 dt 2 title 'mixture'
unset multiplot
