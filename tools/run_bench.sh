#!/usr/bin/env bash
# make bench: runs every benchmark program in $MC_BUILD/bench/ (default
# build/bench/) in name order, each printing its own table. Exits 1 if any
# benchmark fails (e.g. bench_mc when the 1- and 2-thread estimates differ).
#
# With MC_MPI=1 (make bench MPI=1) it measures the MPI build instead
# (tools/mpi_bench.sh): one process against mpirun, and the figures of
# docs/scaling.md.
set -u
build=${MC_BUILD:-build}
if [ "${MC_MPI:-0}" = 1 ]; then
    exec bash "$(dirname "$0")/mpi_bench.sh"
fi
failed=0 ran=0
for b in "$build"/bench/*; do
    [ -f "$b" ] && [ -x "$b" ] || continue
    # The verdict table of the real samplers runs for most of an hour: it
    # has its own target, make real-table (mk/real.mk).
    [ "$(basename "$b")" = real_samplers_table ] && continue
    ran=$((ran + 1))
    echo "== $(basename "$b")"
    "$b"
    rc=$?
    if [ "$rc" != 0 ]; then
        echo "$(basename "$b"): FAILED (exit status $rc)"
        failed=$((failed + 1))
    fi
    echo
done
[ "$ran" -gt 0 ] || echo "make bench: no benchmark programs in $build/bench/"
echo "make bench: $ran benchmarks, $failed failed"
[ "$failed" = 0 ]
