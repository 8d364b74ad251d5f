#!/usr/bin/env bash
# make soak SEEDS=K: runs the whole test suite K times with MC_TEST_SEED =
# 1..K and prints the fraction of runs with at least one failure, to compare
# with the false-alarm rate the thresholds promise (README, "Statistics").
set -u
k=$1; shift
bad=0
for s in $(seq 1 "$k"); do
    if MC_TEST_SEED=$s bash "$(dirname "$0")/run_tests.sh" "$@" >/tmp/mcbox-soak.$$ 2>&1; then
        echo "seed $s: $(tail -1 /tmp/mcbox-soak.$$)"
    else
        bad=$((bad + 1))
        echo "seed $s: $(tail -1 /tmp/mcbox-soak.$$)  <- FAILED:"
        grep -E '^\[  FAILED  \] [a-z]|seed' /tmp/mcbox-soak.$$ | head -5
    fi
done
rm -f /tmp/mcbox-soak.$$
awk -v b="$bad" -v k="$k" 'BEGIN { printf "soak: %d of %d seeds had a failure (%.3f)\n", b, k, b / k }'
