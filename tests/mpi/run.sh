#!/usr/bin/env bash
# tests/mpi/run.sh - the programs under mpirun (Open MPI) give the bytes of
# one process, and a run that fails or is stopped ends as one process does.
# Run by `make test-mpi MPI=1`, which builds both the MPI programs
# ($MC_BUILD, e.g. build/mpi/) and the plain ones ($MC_REF, e.g. build/).
#
# - For K = 1, 2, 3 ranks and 1 or 2 OpenMP threads per rank: pi (every
#   method, 2e6 points; the stratified method also at 12345 points, whose
#   grid has an odd last row and extra points) prints the same bytes as
#   the plain program, and cornell_box (a 24x24 image at 12 spp, as PFM:
#   the 32-bit floats of every pixel) writes the same file, and qmc (7
#   scrambles of every method, split over the ranks) prints the same
#   table. Negative
#   control: another seed must give other bytes.
# - The same for cornell_box's strategies that splat (lighttrace, bdpt
#   with and without --roulette, a 20x20 image at 6 spp), for K = 1, 2, 3
#   and 1 or 3 threads per rank.
# - An output path that cannot be written (its directory is a file): exit
#   non-zero within 10 s, one line on stderr, no file of any name left.
#   A bad option: exit 2, one line.
# - SIGINT to mpirun during a render, or SIGTERM to one rank: a complete
#   PNG is written and stderr says how many samples it holds.
# Ends with the line "N passed, N failed" that .ci/run totals.
set -u
build=${MC_BUILD:-build/mpi}
ref=${MC_REF:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# CI runs as root in a container: Open MPI refuses root without these; in a
# container, its shared-memory transport may not use cross-memory attach.
# One machine: shared memory only (ob1 over self and vader), so that no
# network or InfiniBand component is probed and warns.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_pml=ob1 OMPI_MCA_btl=self,vader
# -q: no banners of mpirun's own; --oversubscribe: 3 ranks on 2 cores;
# --bind-to none: a rank's OpenMP threads are not all pinned to one core.
mpirun=(mpirun -q --oversubscribe --bind-to none)
passed=0 failed=0
check() { # $1 = name, $2 = 0 when it passed, $3 = what went wrong
    if [ "$2" = 0 ]; then
        passed=$((passed + 1))
        echo "ok    $1"
    else
        failed=$((failed + 1))
        echo "FAIL  $1: $3"
    fi
}

# The newest child process of $1 named $2 (from /proc: procps may be
# missing on a bare CI image).
newest_child() {
    local best=0 p n
    for p in /proc/[0-9]*; do
        [ "$(cat "$p/comm" 2>/dev/null)" = "$2" ] || continue
        [ "$(cut -d' ' -f4 "$p/stat" 2>/dev/null)" = "$1" ] || continue
        n=${p#/proc/}
        [ "$n" -gt "$best" ] && best=$n
    done
    [ "$best" != 0 ] && echo "$best"
}

"$ref/bin/pi" --samples 2e6 --seed 7 >"$tmp/pi.ref"
"$ref/bin/pi" --method stratified --samples 12345 --seed 7 >"$tmp/pi_odd.ref"
"$ref/bin/cornell_box" --width 24 --spp 12 --seed 3 -o "$tmp/box.ref.pfm" >/dev/null
"$ref/bin/qmc" --integrand peak --dim 3 --samples 1000 --scrambles 7 --seed 5 --csv >"$tmp/qmc.ref"
for k in 1 2 3; do
    for t in 1 2; do
        OMP_NUM_THREADS=$t "${mpirun[@]}" -np "$k" "$build/bin/pi" --samples 2e6 --seed 7 >"$tmp/pi.out" 2>"$tmp/err"
        rc=$?
        OMP_NUM_THREADS=$t "${mpirun[@]}" -np "$k" "$build/bin/pi" --method stratified --samples 12345 \
            --seed 7 >"$tmp/pi_odd.out" 2>>"$tmp/err"
        rc=$((rc + $?))
        cmp -s "$tmp/pi.ref" "$tmp/pi.out" && cmp -s "$tmp/pi_odd.ref" "$tmp/pi_odd.out" && [ $rc = 0 ]
        check "pi, $k rank(s) x $t thread(s): same bytes" $? "exit $rc, $(diff "$tmp/pi.ref" "$tmp/pi.out" | head -3) $(head -2 "$tmp/err")"
        rm -f "$tmp/box.pfm"
        OMP_NUM_THREADS=$t "${mpirun[@]}" -np "$k" "$build/bin/cornell_box" --width 24 --spp 12 --seed 3 \
            -o "$tmp/box.pfm" >/dev/null 2>"$tmp/err"
        rc=$?
        cmp -s "$tmp/box.ref.pfm" "$tmp/box.pfm" && [ $rc = 0 ]
        check "cornell_box, $k rank(s) x $t thread(s): same image bytes" $? "exit $rc, $(head -2 "$tmp/err")"
        OMP_NUM_THREADS=$t "${mpirun[@]}" -np "$k" "$build/bin/qmc" --integrand peak --dim 3 --samples 1000 \
            --scrambles 7 --seed 5 --csv >"$tmp/qmc.out" 2>"$tmp/err"
        rc=$?
        cmp -s "$tmp/qmc.ref" "$tmp/qmc.out" && [ $rc = 0 ]
        check "qmc, $k rank(s) x $t thread(s): same bytes" $? "exit $rc, $(diff "$tmp/qmc.ref" "$tmp/qmc.out" | head -3) $(head -2 "$tmp/err")"
    done
done

# The strategies that splat light paths onto any pixel: each rank renders
# its rows and keeps its splats in exact sums (render/splat.h), which rank
# 0 adds: the bytes of one process, here at 3 threads too (the splat sums
# are per thread).
splat_strategies=("lighttrace" "bdpt" "bdpt --roulette")
for s in "${splat_strategies[@]}"; do
    name=${s// /_}
    # shellcheck disable=SC2086 # $s holds the strategy and its flag
    "$ref/bin/cornell_box" --width 20 --spp 6 --seed 3 --strategy $s -o "$tmp/$name.ref.pfm" >/dev/null
    for k in 1 2 3; do
        for t in 1 3; do
            rm -f "$tmp/$name.pfm"
            # shellcheck disable=SC2086
            OMP_NUM_THREADS=$t "${mpirun[@]}" -np "$k" "$build/bin/cornell_box" --width 20 --spp 6 --seed 3 \
                --strategy $s -o "$tmp/$name.pfm" >/dev/null 2>"$tmp/err"
            rc=$?
            cmp -s "$tmp/$name.ref.pfm" "$tmp/$name.pfm" && [ $rc = 0 ]
            check "cornell_box --strategy $s, $k rank(s) x $t thread(s): same image bytes" $? \
                "exit $rc, $(head -2 "$tmp/err")"
        done
    done
done
# shellcheck disable=SC2086
"${mpirun[@]}" -np 2 "$build/bin/cornell_box" --width 20 --spp 6 --seed 4 --strategy bdpt \
    -o "$tmp/bdpt.pfm" >/dev/null 2>&1
! cmp -s "$tmp/bdpt.ref.pfm" "$tmp/bdpt.pfm"
check "negative control: cornell_box --strategy bdpt --seed 4 differs from --seed 3" $? "the same bytes"

# The comparison can fail: another seed gives other bytes.
"${mpirun[@]}" -np 2 "$build/bin/cornell_box" --width 24 --spp 12 --seed 4 -o "$tmp/box.pfm" >/dev/null 2>&1
! cmp -s "$tmp/box.ref.pfm" "$tmp/box.pfm"
check "negative control: cornell_box --seed 4 differs from --seed 3" $? "the same bytes"

# Unwritable: the target's directory is a regular file (root ignores
# permissions, so a read-only directory would not do).
touch "$tmp/notadir"
mkdir "$tmp/out"
t0=$(date +%s)
timeout 20 "${mpirun[@]}" -np 2 "$build/bin/cornell_box" --width 200 --spp 5000 \
    -o "$tmp/notadir/x.png" >/dev/null 2>"$tmp/err"
rc=$?
secs=$(($(date +%s) - t0))
lines=$(wc -l <"$tmp/err")
[ $rc != 0 ] && [ $rc != 124 ] && [ $secs -le 10 ] && [ "$lines" = 1 ] && [ ! -e "$tmp/notadir/x.png" ] &&
    [ -z "$(ls -A "$tmp/out")" ]
check "unwritable output, 2 ranks: non-zero exit within 10 s, one line, no file" $? \
    "exit $rc after $secs s, $lines line(s): $(head -3 "$tmp/err")"

"${mpirun[@]}" -np 3 "$build/bin/cornell_box" --width 0 -o "$tmp/out/x.png" >"$tmp/out.txt" 2>"$tmp/err"
rc=$?
lines=$(wc -l <"$tmp/err")
[ $rc = 2 ] && [ "$lines" = 1 ] && [ ! -s "$tmp/out.txt" ] && [ -z "$(ls -A "$tmp/out")" ]
check "bad option, 3 ranks: exit 2, one line" $? "exit $rc, $lines line(s): $(head -3 "$tmp/err")"

# SIGINT to mpirun, which sends SIGTERM to every rank and SIGKILL a second
# later (odls_base_sigkill_timeout): the ranks stop, rank 0 gathers and
# writes within that second. Retried with a longer delay when the signal
# came before the programs had started.
for delay in 2 4 8; do
    rm -f "$tmp/out/int.png"
    "${mpirun[@]}" -np 2 "$build/bin/cornell_box" --width 64 --spp 1e6 --threads 1 \
        -o "$tmp/out/int.png" >"$tmp/out.txt" 2>"$tmp/err" &
    pid=$!
    sleep "$delay"
    kill -INT $pid
    wait $pid
    rc=$?
    grep -q samples "$tmp/err" && break
done
head=$(head -c 8 "$tmp/out/int.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')
n=$(sed -n 's/.* holds \([0-9]*\) samples.*/\1/p' "$tmp/err")
[ $rc != 0 ] && [ "$head" = 89504e470d0a1a0a ] && [ "${n:-0}" -gt 0 ] &&
    [ "$(ls -A "$tmp/out")" = int.png ]
check "SIGINT to mpirun, 2 ranks: partial PNG written with its sample count" $? \
    "exit $rc, header '$head', stderr: $(head -3 "$tmp/err")"

# SIGTERM to one rank only (the newest process, not mpirun): it tells the
# others, every rank stops and rank 0 writes; no time limit applies, as
# mpirun is not stopping the job. Exit 128 + 15.
for delay in 2 4 8; do
    rm -f "$tmp/out/int.png"
    "${mpirun[@]}" -np 3 "$build/bin/cornell_box" --width 64 --spp 1e6 --threads 1 \
        -o "$tmp/out/int.png" >"$tmp/out.txt" 2>"$tmp/err" &
    pid=$!
    sleep "$delay"
    rank=$(newest_child "$pid" cornell_box)
    # Not started yet (a loaded machine): end the job, try a longer delay.
    if [ -n "$rank" ]; then kill -TERM "$rank"; else kill -INT $pid; fi
    wait $pid
    rc=$?
    [ -n "$rank" ] && grep -q samples "$tmp/err" && break
done
head=$(head -c 8 "$tmp/out/int.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')
n=$(sed -n 's/.* holds \([0-9]*\) samples.*/\1/p' "$tmp/err")
[ $rc = 143 ] && [ "$head" = 89504e470d0a1a0a ] && [ "${n:-0}" -gt 0 ] && [ "$(ls -A "$tmp/out")" = int.png ]
check "SIGTERM to one of 3 ranks: all stop, partial PNG with its sample count, exit 143" $? \
    "exit $rc, header '$head', stderr: $(head -3 "$tmp/err")"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
