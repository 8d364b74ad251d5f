# plots/qmc_convergence.gp - RMS error against the number of integrand
# evaluations for every point source of `qmc`, one panel per integrand of
# mc/testfn.h in 2D. Data: qmc_convergence.csv and qmc_convergence_slopes.csv
# (plots/data_qmc_convergence.sh). Points: RMS error over independent seeds;
# lines: least-squares fits in log-log, their slopes in the key. Dashed
# guides: N^-1/2, N^-1 and N^-3/2 through the Monte Carlo error at the
# smallest N, to read the slopes against.
W = 1500; H = 1100
load 'plots/style.gp'
f = datadir.'/qmc_convergence.csv'
sf = datadir.'/qmc_convergence_slopes.csv'
methods = 'mc jitter halton sobol sobol-xor sobol-owen'
names = '"Monte Carlo (PCG32)" "jittered grid" "Halton, permuted digits" "Sobol, unscrambled" "Sobol, random XOR shift" "Sobol, Owen-scrambled"'
slope(p, m) = real(system(sprintf("awk -F, -v p=%s -v m=%s '$1 == p && $2 == m { print $3 }' %s", p, m, sf)))
icept(p, m) = real(system(sprintf("awk -F, -v p=%s -v m=%s '$1 == p && $2 == m { print $4 }' %s", p, m, sf)))
stats f using 4 name 'SEEDS' nooutput
stats f using 3 name 'N' nooutput
titles = '"π: 4 [x^2 + y^2 < 1] (discontinuous)" "smooth: exp(x + y)" "Genz product peak, a = 5" "Genz Gaussian, a = 4"'
integrands = 'pi smooth peak gauss'
set multiplot layout 2, 2 title sprintf("{/:Bold Quasi-Monte Carlo in 2D}: RMS error over %d seeds per point against integrand evaluations N (random methods: 2 scrambles of N/2 points)", SEEDS_max) font ',14'
set logscale xy
set xrange [N_min / 1.5 : N_max * 1.5]
set xlabel 'N, integrand evaluations'
set ylabel 'RMS error'
set key bottom left font ',10' spacing 1.0 samplen 2
fitline(n, s, i) = 10 ** i * n ** s
do for [k = 1:4] {
    p = word(integrands, k)
    set title word(titles, k) font ',13'
    stats f using ((sel(1, p) && sel(2, 'mc') && $3 == 2 * N_min) ? $5 : NaN) name 'E0' nooutput
    e0 = E0_max; n0 = 2 * N_min
    plot e0 * (x / n0) ** -0.5 with lines lc rgb '#aaaaaa' dt 2 lw 1.2 notitle, \
         e0 * (x / n0) ** -1.0 with lines lc rgb '#aaaaaa' dt 4 lw 1.2 notitle, \
         e0 * (x / n0) ** -1.5 with lines lc rgb '#aaaaaa' dt 3 lw 1.2 title 'guides: N^{-1/2}, N^{-1}, N^{-3/2}', \
         for [i = 1:6] f using ((sel(1, p) && sel(2, word(methods, i))) ? $3 : NaN):5 with points lt i notitle, \
         for [i = 1:6] fitline(x, slope(p, word(methods, i)), icept(p, word(methods, i))) with lines lt i \
             title sprintf('%s: slope %.2f', word(names, i), slope(p, word(methods, i)))
}
unset multiplot
