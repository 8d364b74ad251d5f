# plots/rms.awk - RMS error over seeds, per method and sample count.
#
# Input: the CSV rows of chapter programs run with --csv over many seeds
# (columns method,n,estimate,stderr,exact,z,...; header lines are skipped).
# Output: program,method,n,seeds,rms_error,rel_rms_error,mean_stderr,
# mean_variance,exact
# where rms_error = sqrt(mean over seeds of (estimate - exact)^2): the
# error one run makes, typically, measured rather than predicted; and
# mean_stderr is the program's own predicted standard error, for comparison,
# and mean_variance the variance per sample it implies, stderr^2 * n.
# Rows are grouped by method (in the order methods first appear), then in
# the order the sample counts appear: each series is one contiguous block.
# Run as: awk -F, -v tag=PROGRAM -f plots/rms.awk
$1 == "method" { next }
NF < 5 { next }
{
    if ($5 == "") {
        printf "rms.awk: %s method %s has no exact value\n", tag, $1 > "/dev/stderr"
        bad = 1
        exit
    }
    key = $1 SUBSEP $2
    if (!($1 in nsizes))
        morder[++nmethods] = $1
    if (!(key in count)) {
        order[$1, ++nsizes[$1]] = key
        method[key] = $1
        size[key] = $2
        exact[key] = $5
    }
    count[key]++
    d = $3 - $5
    sq[key] += d * d
    se[key] += $4
    var[key] += $4 * $4 * $2
}
END {
    if (bad)
        exit 2
    print "program,method,n,seeds,rms_error,rel_rms_error,mean_stderr,mean_variance,exact"
    for (a = 1; a <= nmethods; a++) {
        for (i = 1; i <= nsizes[morder[a]]; i++) {
            k = order[morder[a], i]
            r = sqrt(sq[k] / count[k])
            printf "%s,%s,%s,%d,%.6e,%.6e,%.6e,%.6e,%.17g\n", tag, method[k], size[k], count[k],
                   r, r / (exact[k] < 0 ? -exact[k] : exact[k]), se[k] / count[k],
                   var[k] / count[k], exact[k]
        }
    }
}
