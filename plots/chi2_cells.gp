# plots/chi2_cells.gp - one chi-square test of a sampler, cell by cell.
# Data: chi2_cells.csv (plots/data_chi2_cells.sh). Four panels: observed and
# expected counts of the cosine-weighted hemisphere sampler over the cells of
# (phi, cos theta) on one colour scale, their difference in standard
# deviations (obs - exp) / sqrt(exp), and the histogram of those differences
# against the standard normal density they should follow.
W = 1400; H = 1000
load 'plots/style.gp'
f = datadir.'/chi2_cells.csv'

stats f using 7 name 'OBS' nooutput
stats f using 8 name 'EXP' nooutput
stats f using ($9 * $9) name 'D2' nooutput
stats f using 9 name 'DIFF' nooutput
X2 = D2_sum; cells = D2_records; dof = cells - 1
pval = 1 - igamma(dof / 2.0, X2 / 2.0)
N = OBS_sum

set multiplot layout 2, 2 title sprintf("{/:Bold Chi-square test of the cosine-weighted hemisphere sampler, cell by cell}\nN = %.0f samples in %d cells of (φ, cos θ): Pearson X^2 = %.1f, %d degrees of freedom, p = %.2f", N, cells, X2, dof, pval) font ',13'
unset key
set format x '%g'; set format y '%g'
set xrange [0:2*pi]; set yrange [0:1]
set xtics ('0' 0, 'π/2' pi/2, 'π' pi, '3π/2' 3*pi/2, '2π' 2*pi)
set ytics 0.25
set xlabel 'azimuth φ (radians)'
set ylabel 'cos θ'
unset grid
set style fill solid 1.0 noborder
set palette defined (0 '#fff7bc', 0.35 '#fec44f', 0.7 '#d95f0e', 1 '#662506')
set cbrange [0:OBS_max]
set cblabel 'samples per cell'
# Cell centres of the regular grid, drawn as an image.
cell = 'using (($5+$6)/2):(($3+$4)/2):'

set title 'observed counts'
plot f @cell 7 with image
set title 'expected counts: N × the pdf cos θ / π integrated over the cell'
plot f @cell 8 with image

set title 'difference (observed - expected) / √expected'
set palette defined (-4 '#2166ac', -2 '#92c5de', 0 '#f7f7f7', 2 '#f4a582', 4 '#b2182b')
set cbrange [-4:4]
set cblabel 'standard deviations'
plot f @cell 9 with image

set title 'the differences against the standard normal density'
set xrange [-4.5:4.5]; set yrange [0:0.6]
set grid
set xtics auto; set ytics auto
set xlabel '(observed - expected) / √expected'
set ylabel 'density'
set key top left
bw = 0.5
bin(x) = bw * floor(x / bw) + bw / 2
set style fill solid 0.5 border lc rgb '#0072B2'
plot f using (bin($9)):(1.0 / (bw * cells)) smooth frequency with boxes lc rgb '#56B4E9' title sprintf('%d cells (mean %.2f, sd %.2f)', cells, DIFF_mean, DIFF_stddev), \
     exp(-x * x / 2) / sqrt(2 * pi) with lines lt 2 title 'N(0, 1)'
unset multiplot
