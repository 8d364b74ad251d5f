#!/bin/sh
# Runs each libFuzzer target $1/fuzz_NAME for $2 seconds on a working copy
# of its seed corpus (tests/fuzz/corpus/NAME, copied into $1/corpus/NAME,
# where what the fuzzer finds accumulates between runs). Prints one line
# per target (runs, corpus size, crashes) and the closing
# "N passed, N failed"; a target passes when libFuzzer exits 0 (no crash,
# leak, timeout or sanitizer report). Crash inputs are kept in $1.
set -u
dir=$1 secs=$2
shift 2
passed=0 failed=0
for name in "$@"; do
    work="$dir/corpus/$name"
    mkdir -p "$work"
    cp -n tests/fuzz/corpus/"$name"/* "$work"/ 2>/dev/null || true
    log="$dir/fuzz_$name.log"
    "$dir/fuzz_$name" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$dir/crash-$name-" -print_final_stats=1 "$work" >"$log" 2>&1
    rc=$?
    runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
    files=$(find "$work" -type f | wc -l)
    crashes=$(find "$dir" -maxdepth 1 -name "crash-$name-*" | wc -l)
    if [ "$rc" = 0 ]; then
        passed=$((passed + 1))
        echo "fuzz $name: ${runs:-?} inputs in ${secs} s, corpus $files files, 0 crashes"
    else
        failed=$((failed + 1))
        echo "fuzz $name: FAILED (exit status $rc), ${runs:-?} inputs, $crashes crash file(s):"
        tail -30 "$log"
    fi
done
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
