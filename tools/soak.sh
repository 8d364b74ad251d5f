#!/usr/bin/env bash
# make soak SEEDS=K: runs the whole test suite K times with MC_TEST_SEED =
# 1..K and prints the fraction of runs with at least one failure, to compare
# with the false-alarm rate the thresholds promise (README, "How the tests
# decide").
#
# With MC_MPI=1 (make soak SEEDS=K MPI=1) the seeds are spread over the
# ranks of `mpirun -np R` (R = MC_SOAK_RANKS, default the processor count;
# MC_SOAK_MPIRUN adds mpirun options, e.g. a host file): this script runs
# on every rank, rank r taking the seeds s with (s - 1) % R == r, one group
# at a time; mpirun carries each rank's lines back. The list of failing
# (seed, test) pairs follows the failure rate.
set -u
k=$1; shift
case "$k" in
    '' | *[!0-9]* | 0) echo "make soak: SEEDS must be a whole number >= 1, not '$k'" >&2; exit 2 ;;
esac
here=$(dirname "$0")
rank=${OMPI_COMM_WORLD_RANK:-} ranks=${OMPI_COMM_WORLD_SIZE:-}
if [ "${MC_MPI:-0}" = 1 ] && [ -z "$rank" ]; then
    # The launcher: the same script on every rank, then the totals.
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    out=$(mktemp)
    trap 'rm -f "$out"' EXIT
    # shellcheck disable=SC2086
    mpirun -q --oversubscribe --bind-to none ${MC_SOAK_MPIRUN:-} -np "${MC_SOAK_RANKS:-$(nproc)}" \
        bash "$0" "$k" "$@" >"$out"
    rc=$?
    grep -v '^pair ' "$out" | sort -t ' ' -k2,2n -s
    bad=$(grep -c '^seed [0-9]*: .*<- FAILED:$' "$out")
    awk -v b="$bad" -v k="$k" 'BEGIN { printf "soak: %d of %d seeds had a failure (%.3f)\n", b, k, b / k }'
    if grep -q '^pair ' "$out"; then
        echo "failing (seed, test) pairs:"
        grep '^pair ' "$out" | sort -k2,2n -k3 | awk '{ printf "  (%s, %s)\n", $2, $3 }'
    fi
    [ "$rc" = 0 ] || echo "soak: mpirun exit status $rc"
    exit 0
fi
worker=0
if [ -n "$rank" ]; then
    # A rank: the test programs it starts are not MPI processes.
    worker=1
    for v in $(env | sed -n 's/^\(OMPI_[A-Za-z0-9_]*\|PMIX_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
    export MC_TEST_JOBS=1
else
    rank=0 ranks=1
fi
# The failed tests of a run_tests.sh log as "pair SEED GROUP/TEST" lines:
# a group's output comes before its summary line, which names the group.
pairs() { # $1 = seed, $2 = log
    awk -v s="$1" '/^\[  FAILED  \] [a-z]/ { t[$4] = 1 }
        /<- FAILED$/ { for (x in t) print "pair " s " " $1 "/" x; delete t }' "$2" | sort -u
}
# A group whose source never asks mc_test_seed for its seed gives the same
# result under every MC_TEST_SEED (bad-input, bit-for-bit and file tests):
# it runs once, not K times.
seeded=() fixed=()
for t in "$@"; do
    if grep -q mc_test_seed "tests/$(basename "$t").c" 2>/dev/null; then seeded+=("$t"); else fixed+=("$t"); fi
done
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if [ ${#fixed[@]} -gt 0 ] && [ "$rank" = 0 ]; then
    if bash "$here/run_tests.sh" "${fixed[@]}" >"$log" 2>&1; then
        echo "groups without a seed, run once: $(tail -1 "$log")"
    else
        echo "groups without a seed, run once: $(tail -1 "$log")  <- FAILED:"
        grep -E '^\[  FAILED  \] [a-z]' "$log" | head -5
    fi
fi
set -- "${seeded[@]}"
bad=0 found=$(mktemp)
trap 'rm -f "$log" "$found"' EXIT
for s in $(seq $((rank + 1)) "$ranks" "$k"); do
    if MC_TEST_SEED=$s bash "$here/run_tests.sh" "$@" >"$log" 2>&1; then
        echo "seed $s: $(tail -1 "$log")"
    else
        bad=$((bad + 1))
        echo "seed $s: $(tail -1 "$log")  <- FAILED:"
        # The failed tests and their messages (passing z-tests print their
        # seed too); on a rank, prefixed by the seed, which the launcher
        # sorts the ranks' lines by.
        grep -E '^\[  FAILED  \] [a-z]|^ERROR|rejects|is false' "$log" | head -5 |
            if [ $worker = 1 ]; then sed "s/^/seed $s:   /"; else cat; fi
        pairs "$s" "$log" >>"$found"
    fi
done
if [ $worker = 1 ]; then
    cat "$found"
    exit 0
fi
awk -v b="$bad" -v k="$k" 'BEGIN { printf "soak: %d of %d seeds had a failure (%.3f)\n", b, k, b / k }'
if [ -s "$found" ]; then
    echo "failing (seed, test) pairs:"
    awk '{ printf "  (%s, %s)\n", $2, $3 }' "$found"
fi
