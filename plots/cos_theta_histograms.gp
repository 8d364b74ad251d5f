# plots/cos_theta_histograms.gp - sampled cos theta against the analytic
# marginal density. Data: cos_theta_histograms.csv
# (plots/data_cos_theta_histograms.sh). The marginal density of c = cos theta
# is the solid-angle density times 2 pi (the azimuth integrated out):
#   cosine   2 c
#   Phong    (n + 1) c^n
#   GGX      2 a^2 c / (1 + c^2 (a^2 - 1))^2   (D(h) cos theta_h, half vectors)
# The black steps are the analytic density averaged over each bin, what the
# bars must match exactly. Log scale: the lobes span decades, and the tails are where mistakes hide.
W = 1300; H = 900
load 'plots/style.gp'
f = datadir.'/cos_theta_histograms.csv'
stats f using (sel(1, 'cosine') ? $5 : NaN) name 'S' nooutput
cosine(c) = 2 * c
phong(c, n) = (n + 1) * c ** n
ggx(c, a) = 2 * a * a * c / (1 + c * c * (a * a - 1)) ** 2
set multiplot layout 2, 2 title sprintf("{/:Bold Histograms of sampled cos θ against the analytic density of cos θ} (%.0f directions per sampler, 50 bins)", S_sum) font ',14'
set format x '%g'
set xrange [0:1]
set xtics 0.1
set xlabel 'cos θ'
set ylabel 'probability density of cos θ'
set logscale y
set key top left
set samples 400
set style fill solid 0.45 noborder
set boxwidth 0.02 absolute
pick(s, p) = sel(1, s) && strcol(2) eq p

set title 'cosine-weighted'
set yrange [1e-3:40]
plot f using (pick('cosine', '-') ? ($3 + $4) / 2 : NaN):6 with boxes lt 1 title 'sampled', \
     f using (pick('cosine', '-') ? ($3 + $4) / 2 : NaN):7 with histeps lc rgb '#000000' lw 1 title 'analytic, averaged over each bin', \
     cosine(x) with lines lt 2 title 'analytic 2 cos θ'
set title 'Phong lobe, n = 40'
set yrange [1e-5:100]
plot f using (pick('phong', '40') ? ($3 + $4) / 2 : NaN):6 with boxes lt 1 title 'sampled', \
     f using (pick('phong', '40') ? ($3 + $4) / 2 : NaN):7 with histeps lc rgb '#000000' lw 1 title 'analytic, averaged over each bin', \
     phong(x, 40) with lines lt 2 title 'analytic 41 cos^{40} θ'
set title 'GGX half vectors, α = 0.5'
set yrange [1e-3:300]
plot f using (pick('ggx', '0.5') ? ($3 + $4) / 2 : NaN):6 with boxes lt 1 title 'sampled', \
     f using (pick('ggx', '0.5') ? ($3 + $4) / 2 : NaN):7 with histeps lc rgb '#000000' lw 1 title 'analytic, averaged over each bin', \
     ggx(x, 0.5) with lines lt 2 title 'analytic 2α^2 c / (1 + c^2(α^2 - 1))^2, c = cos θ_h'
set title 'GGX half vectors, α = 0.25'
set yrange [1e-3:100]
plot f using (pick('ggx', '0.25') ? ($3 + $4) / 2 : NaN):6 with boxes lt 1 title 'sampled', \
     f using (pick('ggx', '0.25') ? ($3 + $4) / 2 : NaN):7 with histeps lc rgb '#000000' lw 1 title 'analytic, averaged over each bin', \
     ggx(x, 0.25) with lines lt 2 title 'analytic 2α^2 c / (1 + c^2(α^2 - 1))^2, c = cos θ_h'
unset multiplot
