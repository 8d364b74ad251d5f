# plots/style.gp - what every figure of `make plots` shares. Each script sets
# W and H (pixels) and then loads this file; make passes on the command line
#   fmt     'png' (pngcairo) or 'svg'
#   outfile the figure to write
#   datadir the directory of the CSV data files
# Colours: the Okabe-Ito palette, distinguishable with every common form of
# colour blindness; line types 1-8 use it in order.
if (!exists("fmt")) fmt = 'png'
if (!exists("datadir")) datadir = 'build/plots/data'
if (!exists("W")) W = 1000
if (!exists("H")) H = 650
if (fmt eq 'svg') {
    set terminal svg size W, H dynamic enhanced font 'DejaVu Sans,13' background '#ffffff'
} else {
    set terminal pngcairo size W, H enhanced font 'DejaVu Sans,11' background '#ffffff'
}
set output outfile
set encoding utf8
set datafile separator comma
set datafile missing ''
set linetype 1 lc rgb '#0072B2' lw 2 pt 7 ps 0.9
set linetype 2 lc rgb '#D55E00' lw 2 pt 5 ps 0.9
set linetype 3 lc rgb '#009E73' lw 2 pt 9 ps 1.0
set linetype 4 lc rgb '#CC79A7' lw 2 pt 11 ps 1.0
set linetype 5 lc rgb '#E69F00' lw 2 pt 13 ps 1.0
set linetype 6 lc rgb '#56B4E9' lw 2 pt 15 ps 1.0
set linetype 7 lc rgb '#000000' lw 2 pt 3 ps 1.0
set linetype 8 lc rgb '#F0E442' lw 2 pt 1 ps 1.0
set linetype cycle 8
set grid back lc rgb '#dddddd' lw 1
set border lw 1.2
set key box opaque samplen 2.5 spacing 1.2
set style textbox opaque noborder
# log10 tick labels as powers of ten
set format x '10^{%L}'
set format y '10^{%L}'
# Row of a CSV file where column 1 equals s (others are skipped):
# plot f using (sel(1, 'plain') ? $2 : NaN):3
sel(c, s) = strcol(c) eq s
