# plots/data_efficiency.sh BIN DATA - the cost of an estimator: variance per
# sample times CPU time per sample.
# efficiency.csv: problem,method,n,variance,exact,cpu_seconds,
# seconds_per_sample,seconds_to_1pct. For every problem and sampling method
# (table: problem, program, option, methods) the program runs alone, on one thread, at N/4 and at N
# samples (N chosen so that the run takes about 0.25 s; quick: 0.04 s); the
# CPU time per sample is the difference over the difference in N, which
# cancels the start-up cost; best of two (quick: one). The variance per
# sample is stderr^2 N from the longer run. seconds_to_1pct =
# variance * seconds_per_sample / (0.01 exact)^2 is the CPU time it takes to
# bring the standard error down to 1% of the answer: lower is better.
# Stratified pi is left out: its variance per sample is not a constant.
# The mixture rows run `mixture --method NAME`, one integrand-density pair
# per process.
source "$(dirname "$0")/lib.sh"
target=0.25 repeats=2
[ "$PLOTS_QUICK" = 1 ] && target=0.04 repeats=1
tmp=$DATA/efficiency.run.tmp

# CPU seconds (user + system) of one run of "$@"; its stdout goes to $tmp.
cpu() {
    local t
    t=$({ TIMEFORMAT='%3U %3S'; time "$@" >"$tmp"; } 2>&1) || die "$* failed"
    awk '{ printf "%.3f\n", $1 + $2 }' <<<"$t"
}
# Best (smallest) CPU time of $repeats runs.
best() {
    local b="" t i
    for ((i = 0; i < repeats; i++)); do
        t=$(cpu "$@")
        if [ -z "$b" ] || awk -v a="$t" -v b="$b" 'BEGIN { exit !(a < b) }'; then b=$t; fi
    done
    echo "$b"
}

out=$DATA/efficiency.csv.tmp
echo problem,method,n,variance,exact,cpu_seconds,seconds_per_sample,seconds_to_1pct >"$out"
while read -r problem program option methods; do
    p=$(prog "$program")
    threads=()
    "$p" --help | grep -q -- '--threads' && threads=(--threads 1)
    for m in $methods; do
        run=("$p" "${threads[@]}" "$option" "$m" --seed 5 --csv --samples)
        # Calibrate: grow N tenfold until a run takes 20 ms, scale it to
        # the target time, then time N/4 and N.
        n=100000
        t0=$(cpu "${run[@]}" "$n")
        while awk -v t="$t0" -v n="$n" 'BEGIN { exit !(t < 0.02 && n < 1e9) }'; do
            n=$((n * 10))
            t0=$(cpu "${run[@]}" "$n")
        done
        n=$(awk -v t="$t0" -v n="$n" -v g="$target" 'BEGIN { n = n * g / t
            printf "%.0f\n", n < 4e5 ? 4e5 : (n > 4e9 ? 4e9 : n) }')
        t1=$(best "${run[@]}" $((n / 4)))
        t2=$(best "${run[@]}" "$n")
        awk -F, -v prob="$problem" -v m="$m" -v t1="$t1" -v t2="$t2" -v n="$n" '
            $1 == m {
                var = $4 * $4 * $2
                sps = (t2 - t1) / (n - n / 4)
                if (sps <= 0) sps = t2 / n
                printf "%s,%s,%s,%.6e,%.17g,%.3f,%.6e,%.6e\n", prob, m, $2, var, $5, t2, sps,
                       var * sps / (0.01 * $5) ^ 2
            }' "$tmp" >>"$out"
    done
done <<'LIST'
pi pi --method plain
integrate_x_sq integrate_x_sq --pdf uniform linear quadratic
log_sin log_sin --method plain importance
sphere_importance sphere_importance --method inverse gaussian rejection
cos_cubed cos_cubed --method uniform cosine
light_pdf light_pdf --method light cosine
sphere_light sphere_light --method area cone
mixture_light mixture --method light-cosine light-light light-mixture
mixture_sky mixture --method sky-cosine sky-mixture
LIST
rm -f "$tmp"
publish efficiency.csv
