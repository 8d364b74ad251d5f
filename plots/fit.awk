# plots/fit.awk - least-squares slope of log10(error) against log10(N).
#
# Input: the table of plots/rms.awk (several programs may be concatenated;
# repeated header lines are skipped). ycol names the error column to fit
# (rms_error or rel_rms_error; the slope is the same, the intercept not).
# Output: program,method,slope,intercept,points,n_min,n_max with
# error ~ 10^intercept * N^slope. A series whose relative error never
# exceeds 1e-12 is round-off around an exact answer (a zero-variance
# estimator): it has no rate to fit and gets no row.
# Run as: awk -F, -v ycol=rms_error -f plots/fit.awk
$1 == "program" {
    for (c = 1; c <= NF; c++)
        col[$c] = c
    next
}
{
    key = $1 "," $2
    if (!(key in pts))
        order[++nkeys] = key
    pts[key] += 0
    if ($(col["rel_rms_error"]) + 0 > big[key] + 0)
        big[key] = $(col["rel_rms_error"]) + 0
    y = $(col[ycol]) + 0
    if (y <= 0)
        next
    x = log($(col["n"])) / log(10)
    y = log(y) / log(10)
    pts[key]++
    sx[key] += x; sy[key] += y; sxx[key] += x * x; sxy[key] += x * y
    n = $(col["n"]) + 0
    if (!(key in nmin) || n < nmin[key]) nmin[key] = n
    if (!(key in nmax) || n > nmax[key]) nmax[key] = n
}
END {
    print "program,method,slope,intercept,points,n_min,n_max"
    for (i = 1; i <= nkeys; i++) {
        k = order[i]
        m = pts[k]
        if (m < 2 || big[k] <= 1e-12)
            continue
        den = m * sxx[k] - sx[k] * sx[k]
        slope = (m * sxy[k] - sx[k] * sy[k]) / den
        icept = (sy[k] - slope * sx[k]) / m
        printf "%s,%.4f,%.4f,%d,%.0f,%.0f\n", k, slope, icept, m, nmin[k], nmax[k]
    }
}
