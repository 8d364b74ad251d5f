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
# A group whose source never asks mc_test_seed for its seed gives the same
# result under every MC_TEST_SEED (bad-input, bit-for-bit and file tests):
# it runs once, not K times.
seeded=() fixed=()
for t in "$@"; do
    if grep -q mc_test_seed "tests/$(basename "$t").c" 2>/dev/null; then seeded+=("$t"); else fixed+=("$t"); fi
done
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if [ ${#fixed[@]} -gt 0 ]; then
    if bash "$(dirname "$0")/run_tests.sh" "${fixed[@]}" >"$log" 2>&1; then
        echo "groups without a seed, run once: $(tail -1 "$log")"
    else
        echo "groups without a seed, run once: $(tail -1 "$log")  <- FAILED:"
        grep -E '^\[  FAILED  \] [a-z]' "$log" | head -5
    fi
fi
set -- "${seeded[@]}"
bad=0
for s in $(seq 1 "$k"); do
    if MC_TEST_SEED=$s bash "$(dirname "$0")/run_tests.sh" "$@" >"$log" 2>&1; then
        echo "seed $s: $(tail -1 "$log")"
    else
        bad=$((bad + 1))
        echo "seed $s: $(tail -1 "$log")  <- FAILED:"
        # The failed tests and their messages (passing z-tests print their seed too).
        grep -E '^\[  FAILED  \] [a-z]|^ERROR|rejects|is false' "$log" | head -5
    fi
done
awk -v b="$bad" -v k="$k" 'BEGIN { printf "soak: %d of %d seeds had a failure (%.3f)\n", b, k, b / k }'
