#!/usr/bin/env bash
# Runs the cmocka test programs given as arguments, two at a time, prints
# one line per group as it finishes (name, tests, passed, failed, seconds)
# and the full output of the groups that failed (of every group with
# MC_TEST_VERBOSE=1), then the negative-control tally and one closing line
# "N passed, N failed" summed over every group. With JUNIT=1 each group also writes cmocka's
# JUnit XML to $MC_BUILD/test-results/<group>.xml. The output of a group
# that passed a full run is kept in $MC_BUILD/test-logs/<group>.log.
# Environment passed to the tests: MC_BUILD (the build directory, where the
# programs under test live), MC_TEST_SEED (optional seed override).
set -u
build=${MC_BUILD:-build}
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
jobs_max=${MC_TEST_JOBS:-2}
# A hung test must not hang make test, soak or CI: each group gets at most
# MC_TEST_TIMEOUT seconds (timeout(1) then exits 124, counted as a failure).
limit=${MC_TEST_TIMEOUT:-900}
if [ "${JUNIT:-0}" = 1 ]; then
    mkdir -p "$build/test-results"
    rm -f "$build/test-results"/*.xml
fi

run_one() { # $1 = test program; writes $logs/<name>.log, .secs and .rc (last)
    local t=$1 name t0
    name=$(basename "$t")
    t0=$(date +%s.%N)
    if [ "${JUNIT:-0}" = 1 ]; then
        CMOCKA_MESSAGE_OUTPUT=xml CMOCKA_XML_FILE="$build/test-results/%g.xml" \
            MC_BUILD="$build" timeout "$limit" "$t" >"$logs/$name.log" 2>&1
    else
        MC_BUILD="$build" timeout "$limit" "$t" >"$logs/$name.log" 2>&1
    fi
    local rc=$?
    awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f\n", b - a }' >"$logs/$name.secs"
    # The whole group's output, kept for the book's boxes of tests
    # (tools/test_verdicts.sh): only a full run at the tests' own seeds,
    # in text, that passed.
    if [ "$rc" = 0 ] && [ "${JUNIT:-0}" != 1 ] && [ -z "${MC_TEST_ONLY:-}" ] &&
        [ -z "${MC_TEST_SEED:-}" ]; then
        mkdir -p "$build/test-logs" && cp "$logs/$name.log" "$build/test-logs/$name.log.tmp" &&
            mv "$build/test-logs/$name.log.tmp" "$build/test-logs/$name.log"
    else
        rm -f "$build/test-logs/$name.log"
    fi
    echo $rc >"$logs/$name.rc.tmp" && mv "$logs/$name.rc.tmp" "$logs/$name.rc"
}

passed=0 failed=0
# One line per group as it finishes: name, tests, passed, failed, seconds;
# the group's full output only when it failed (or with MC_TEST_VERBOSE=1).
report() { # $1 = test program
    local t=$1 name rc p f n secs
    name=$(basename "$t")
    rc=$(cat "$logs/$name.rc" 2>/dev/null || echo 1)
    secs=$(cat "$logs/$name.secs" 2>/dev/null || echo "?")
    p="" f=""
    if [ "${JUNIT:-0}" = 1 ]; then
        for x in "$build/test-results/"*.xml; do
            [ -f "$x" ] || continue
            grep -q "name=\"$name\"" "$x" 2>/dev/null || continue
            n=$(grep -o '<testsuite [^>]*' "$x" | grep -o ' tests="[0-9]*"' | grep -o '[0-9]*' | head -1)
            fl=$(grep -o '<testsuite [^>]*' "$x" | grep -o ' failures="[0-9]*"' | grep -o '[0-9]*' | head -1)
            er=$(grep -o '<testsuite [^>]*' "$x" | grep -o ' errors="[0-9]*"' | grep -o '[0-9]*' | head -1)
            f=$(( ${fl:-0} + ${er:-0} )); p=$(( ${n:-0} - f ))
        done
    else
        p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$logs/$name.log" | tail -1)
        f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$logs/$name.log" | tail -1)
    fi
    local notes=()
    if [ "$rc" = 124 ]; then
        notes+=("$name: timed out after $limit s")
    fi
    if [ -z "$p" ] && [ -z "$f" ]; then
        # No summary: the program crashed or could not start. One failure.
        notes+=("$name: no cmocka summary (exit status $rc): counted as 1 failed")
        p=0 f=1
    fi
    p=${p:-0} f=${f:-0}
    if [ "$rc" != 0 ] && [ "$f" = 0 ]; then
        notes+=("$name: exit status $rc with no failed test: counted as 1 failed")
        f=1
    fi
    if [ "$f" != 0 ] || [ "${MC_TEST_VERBOSE:-0}" = 1 ]; then
        cat "$logs/$name.log"
    fi
    for x in "${notes[@]+"${notes[@]}"}"; do echo "$x"; done
    printf '%-26s %4d tests %4d passed %3d failed %7s s%s\n' "$name" $((p + f)) "$p" "$f" "$secs" \
        "$([ "$f" != 0 ] && echo '   <- FAILED')"
    passed=$((passed + p)) failed=$((failed + f))
    : >"$logs/$name.done"
}

# Reports every group that has finished and is not yet reported.
report_finished() {
    for t in "$@"; do
        local name
        name=$(basename "$t")
        if [ -f "$logs/$name.rc" ] && [ ! -f "$logs/$name.done" ]; then
            report "$t"
        fi
    done
}

running=0
for t in "$@"; do
    run_one "$t" &
    running=$((running + 1))
    if [ "$running" -ge "$jobs_max" ]; then
        wait -n
        running=$((running - 1))
        report_finished "$@"
    fi
done
while [ "$running" -gt 0 ]; do
    wait -n
    running=$((running - 1))
    report_finished "$@"
done
wait
report_finished "$@"
# One total over every group that ran negative controls.
grep -h '^negative controls: caught [0-9]*/[0-9]*' "$logs"/*.log 2>/dev/null |
    sed 's/^negative controls: caught \([0-9]*\)\/\([0-9]*\).*/\1 \2/' |
    awk '{ k += $1; m += $2 } END { if (m > 0) printf "negative controls: caught %d/%d\n", k, m }'
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
