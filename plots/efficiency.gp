# plots/efficiency.gp - which sampling method pays: variance per sample times
# CPU time per sample, as bars (lower is better). Data: efficiency.csv
# (plots/data_efficiency.sh). Each bar is the CPU time one thread needs to
# bring the standard error down to 1% of the answer; bars of one problem
# share a colour. Importance sampling pays when it cuts the variance more
# than it adds to the time per sample. A zero-variance method has a bar of
# height 0, which a log axis cannot draw: it is labelled on the axis.
W = 1600; H = 720
load 'plots/style.gp'
f = datadir.'/efficiency.csv'
stats f using 8 name 'E' nooutput
stats f using ($8 > 0 ? $8 : NaN) name 'EP' nooutput
label(p) = p eq 'pi' ? "π\nhit or miss" : \
    p eq 'integrate_x_sq' ? "∫_0^2 x^2 dx" : \
    p eq 'log_sin' ? "∫_0^π ln sin x dx" : \
    p eq 'sphere_importance' ? "∫ cos^2 θ dω\nsphere" : \
    p eq 'cos_cubed' ? "∫ cos^3 θ dω\nhemisphere" : \
    p eq 'light_pdf' ? "irradiance\nquad light" : \
    p eq 'sphere_light' ? "irradiance\nsphere light" : \
    p eq 'mixture_light' ? "mixture example:\nirradiance, quad light" : \
    p eq 'mixture_sky' ? "mixture example:\nlight + sky, reflected" : p
ylo = EP_min / 30
yhi = EP_max * 60
set title "{/:Bold Cost of an estimate: CPU time to reach a standard error of 1% of the answer}\n(variance per sample × CPU seconds per sample / (0.01 × answer)^2, one thread; lower is better; one colour per integral)" font ',13'
set logscale y
set yrange [ylo:yhi]
set ylabel 'CPU seconds to 1% standard error'
set xlabel 'sampling method'
set format y '10^{%L}'
set xtics rotate by 30 right nomirror noenhanced font ',10'
set grid noxtics ytics
unset key
set style fill solid 0.8 noborder
set boxwidth 0.75
# Bar x: the row index plus one gap per new problem (state kept in g).
xpos(p) = ($0 == 0 ? (g = 1, prev = p) : p ne prev ? (g = g + 1, prev = p) : 0, $0 + g)
# Ten distinct colours (Tableau 10, as 0xRRGGBB in decimal): one per
# integral for up to ten integrals, where lt 1..6 of style.gp repeated.
colours = "5142951 15896107 14767961 7780274 5873999 15583560 11565729 16752039 10253663 12234924"
colour(k) = int(word(colours, int(k - 1) % 10 + 1))
# One label per problem, centred over its bars: problems in order with their
# first and last row (0-based), from the data file.
groups = system("awk -F, 'NR > 1 { if ($1 != p) { if (p != \"\") print p, a, NR - 3; p = $1; a = NR - 2 } } END { print p, a, NR - 2 }' ".f)
ngroups = words(groups) / 3
do for [k = 1:ngroups] {
    p = word(groups, 3 * k - 2)
    centre = (word(groups, 3 * k - 1) + word(groups, 3 * k)) / 2.0 + k
    set label k label(p) at centre, yhi / 4 center font ',10'
}
set xrange [-0.4 : E_records + ngroups + 0.9]
plot f skip 1 using (xpos(strcol(1))):($8 > 0 ? $8 : NaN):(colour(g)):xtic(2) with boxes lc rgb variable, \
     f skip 1 using (xpos(strcol(1))):($8 > 0 ? $8 : ylo * 2):($8 > 0 ? sprintf('%.1e', $8) : "0: zero variance") with labels offset 0, 0.7 font ',8'
