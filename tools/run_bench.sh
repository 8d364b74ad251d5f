#!/usr/bin/env bash
# make bench: runs every benchmark program in $MC_BUILD/bench/ (default
# build/bench/) in name order, each printing its own table. Exits 1 if any
# benchmark fails (e.g. bench_mc when the 1- and 2-thread estimates differ).
set -u
build=${MC_BUILD:-build}
failed=0 ran=0
for b in "$build"/bench/*; do
    [ -f "$b" ] && [ -x "$b" ] || continue
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
