#!/usr/bin/env bash
# make soak SEEDS=K: runs the whole test suite K times with MC_TEST_SEED =
# 1..K and prints the fraction of runs with at least one failure, to compare
# with the false-alarm rate the thresholds promise (README, "How the tests
# decide").
set -u
k=$1; shift
case "$k" in
    '' | *[!0-9]* | 0) echo "make soak: SEEDS must be a whole number >= 1, not '$k'" >&2; exit 2 ;;
esac
log=$(mktemp)
trap 'rm -f "$log"' EXIT
bad=0
for s in $(seq 1 "$k"); do
    if MC_TEST_SEED=$s bash "$(dirname "$0")/run_tests.sh" "$@" >"$log" 2>&1; then
        echo "seed $s: $(tail -1 "$log")"
    else
        bad=$((bad + 1))
        echo "seed $s: $(tail -1 "$log")  <- FAILED:"
        grep -E '^\[  FAILED  \] [a-z]|seed' "$log" | head -5
    fi
done
awk -v b="$bad" -v k="$k" 'BEGIN { printf "soak: %d of %d seeds had a failure (%.3f)\n", b, k, b / k }'
