# plots/convergence_rates.gp - every estimator of the chapter programs: RMS
# relative error against N with its fitted slope. Data: convergence_rates.csv
# and convergence_rates_slopes.csv (plots/data_convergence_rates.sh).
# One panel per program (same axes everywhere, dashed guide N^-1/2 through
# 1/sqrt(N)); the right column gathers every fitted slope: plain Monte Carlo
# sits at -1/2 whatever the pdf, only stratification changes the rate.
# Estimators with zero error (the quadratic pdf of x^2) have no slope and no
# line; their panel says so.
W = 2000; H = 1150
load 'plots/style.gp'
f = datadir.'/convergence_rates.csv'
sf = datadir.'/convergence_rates_slopes.csv'
progs = system("awk -F, 'NR > 1 && !seen[$1]++ { printf \"%s \", $1 }' ".f)
nprog = words(progs)
methods(p) = system(sprintf("awk -F, -v p=%s '$1 == p && !seen[$2]++ { printf \"%%s \", $2 }' %s", p, f))
slope(p, m) = system(sprintf("awk -F, -v p=%s -v m=%s '$1 == p && $2 == m { print $3 }' %s", p, m, sf))
stats f using 4 name 'SEEDS' nooutput
label(p) = p eq 'pi' ? 'π by hits in the quarter disc' : \
    p eq 'integrate_x_sq' ? '∫_0^2 x^2 dx, three pdfs' : \
    p eq 'log_sin' ? '∫_0^π ln sin x dx' : \
    p eq 'estimate_halfway' ? '∫_0^{2π} e^{-x/2π} sin^2 x dx and its halfway point' : \
    p eq 'inverse_cdf' ? 'means of inverse-CDF samplers' : \
    p eq 'sphere_importance' ? '∫ cos^2 θ dω over the sphere' : \
    p eq 'cos_cubed' ? '∫ cos^3 θ dω over the hemisphere' : \
    p eq 'light_pdf' ? 'irradiance from a quad light' : \
    p eq 'sphere_light' ? 'irradiance from a sphere light' : \
    p eq 'projected_area' ? 'mean projected area' : \
    p eq 'mixture' ? 'mixture of cosine and light pdfs' : p

seeds = SEEDS_min == SEEDS_max ? sprintf('%d', SEEDS_min) : sprintf('%d to %d', SEEDS_min, SEEDS_max)
set multiplot title "{/:Bold Convergence of every estimator}: RMS relative error over ".seeds." seeds per point; legends give the least-squares slope in log-log" font ',15'
sx(px) = px / (1.0 * W)
sy(py) = 1 - py / (1.0 * H)
cols = 4; pw = 300; ph = 250; L = 85; T = 75; gx = 95; gy = 100
set logscale xy
set xrange [30:3e8]
set yrange [1e-8:3]
set xtics 100, 100, 1e8
set mxtics 10
set ytics 1e-8, 100, 1
set xlabel 'N, samples' offset 0, 0.5
set ylabel 'relative RMS error' offset 1, 0
set key bottom left font ',10' samplen 1.5 spacing 1.0 box opaque noenhanced
set title font ',12'
do for [k = 1:nprog] {
    p = word(progs, k)
    ms = methods(p)
    c = (k - 1) % cols; r = (k - 1) / cols
    set lmargin at screen sx(L + c * (pw + gx)); set rmargin at screen sx(L + c * (pw + gx) + pw)
    set tmargin at screen sy(T + r * (ph + gy)); set bmargin at screen sy(T + r * (ph + gy) + ph)
    set title label(p)
    plot 1 / sqrt(x) with lines lc rgb '#aaaaaa' dt 2 lw 1.2 title 'guide: 1/sqrt(N)', \
         for [i = 1:words(ms)] f using ((sel(1, p) && sel(2, word(ms, i))) ? $3 : NaN):6 with linespoints lt i ps 0.6 \
         title (slope(p, word(ms, i)) eq '' ? word(ms, i).': zero error, not drawn' : sprintf('%s: slope %s', word(ms, i), slope(p, word(ms, i))))
}

# A free grid cell holds the reading guide (drawn with the next plot).
if (nprog < 3 * cols) {
    c = nprog % cols; r = nprog / cols
    set label 10 "How to read this:\n\n• plain Monte Carlo converges as N^{-1/2}\n   whatever the pdf: a good pdf lowers\n   the line, it does not tilt it;\n• stratification (jittered π) tilts it:\n   N^{-3/4};\n• a pdf proportional to the integrand\n   has zero error (x^2 with 3x^2/8)." \
        at screen sx(L + c * (pw + gx) + 10), sy(T + r * (ph + gy) + 20) left front font ',11'
}
# Every slope at a glance: one row per estimator.
nslopes = system("awk 'END { print NR - 1 }' ".sf) + 0
unset logscale
set lmargin at screen sx(L + cols * (pw + gx) + 150); set rmargin at screen sx(W - 30)
set tmargin at screen sy(T); set bmargin at screen sy(T + 3 * ph + 2 * gy)
set title 'fitted slopes' font ',12'
set xrange [-0.85:-0.35]
set xtics -0.8, 0.1, -0.4 format '%.1f'
set mxtics 2
set yrange [nslopes + 0.5:0.5]
set ytics 1 format '' scale 0
set xlabel 'fitted slope'
unset ylabel
set grid x
unset key
set ytics () font ',10' noenhanced
do for [i = 1:nslopes] {
    set ytics add (system(sprintf("awk -F, 'NR == %d + 1 { print $1 \" \" $2 }' %s", i, sf)) i)
}
set arrow 1 from -0.5, graph 0 to -0.5, graph 1 nohead lc rgb '#555555' dt 2
set arrow 2 from -0.75, graph 0 to -0.75, graph 1 nohead lc rgb '#555555' dt 4
set label 1 '-1/2' at -0.5, graph 1 offset 0, 0.6 center
set label 2 '-3/4' at -0.75, graph 1 offset 0, 0.6 center
plot sf skip 1 using 3:($0 + 1) with points pt 7 ps 1.2 lc rgb '#0072B2'
unset multiplot
