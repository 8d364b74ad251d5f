#!/usr/bin/env bash
# make bench MPI=1: the MPI build ($MC_BUILD, build/mpi/) against itself
# started without mpirun (one process, MPI never initialized; the same
# compiled code):
#  1. cornell_box (book scene, MC_BENCH_WIDTH^2 pixels at MC_BENCH_SPP) and
#     pi (plain, MC_BENCH_PI points): 1 process x 2 threads, 1 rank x 2
#     threads, 2 ranks x 1 thread: wall time (mpirun's start included), the
#     program's own time and paths/s, and the images compared byte for byte;
#     the overhead of the MPI path at K = 1;
#  2. what rank 0 can move (tests/mpi/handout.c): units handed out per
#     second, rows received per second;
#  3. how evenly rows interleaved over K ranks share the book scene's work
#     (tests/mpi/rowcost.c: ray segments per row), at 600 rows and resampled
#     to 2160 rows, and from all three the largest K whose efficiency stays
#     above 90% (docs/scaling.md explains the model).
set -u
build=${MC_BUILD:-build/mpi}
width=${MC_BENCH_WIDTH:-300} spp=${MC_BENCH_SPP:-64} pin=${MC_BENCH_PI:-4e9}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun -q --oversubscribe --bind-to none)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }

echo "== cornell_box --scene book --width $width --spp $spp"
printf '%-26s %9s %9s %11s  %s\n' run wall_s prog_s Mpaths/s image
box() { # $1 = label, $2 = output name, rest = command
    local label=$1 out=$2 t0 t1 line
    shift 2
    t0=$(now)
    "$@" --scene book --width "$width" --spp "$spp" -o "$tmp/$out.pfm" >"$tmp/$out.txt" 2>/dev/null
    t1=$(now)
    line=$(grep ' paths, ' "$tmp/$out.txt")
    local secs rate same=reference
    secs=$(echo "$line" | sed -n 's/.* dropped, \([0-9.]*\) s (\([0-9.]*\) Mpaths.*/\1/p')
    rate=$(echo "$line" | sed -n 's/.* dropped, \([0-9.]*\) s (\([0-9.]*\) Mpaths.*/\2/p')
    [ "$out" = one ] || { cmp -s "$tmp/one.pfm" "$tmp/$out.pfm" && same="same bytes" || same=DIFFERENT; }
    awk -v l="$label" -v a="$t0" -v b="$t1" -v s="$secs" -v r="$rate" -v x="$same" \
        'BEGIN { printf "%-26s %9.2f %9.2f %11.2f  %s\n", l, b - a, s, r, x }'
    awk -v a="$t0" -v b="$t1" -v r="$rate" 'BEGIN { print b - a, r }' >>"$tmp/box.tab"
}
box "1 process x 2 threads" one "$build/bin/cornell_box" --threads 2
box "1 rank x 2 threads" r1 "${mpirun[@]}" -np 1 "$build/bin/cornell_box" --threads 2
box "2 ranks x 1 thread" r2 "${mpirun[@]}" -np 2 "$build/bin/cornell_box" --threads 1
awk '{ w[NR] = $1; r[NR] = $2 } END {
    printf "MPI overhead at K = 1: %+.2f s wall (mpirun start and gather), %+.1f%% paths/s\n",
        w[2] - w[1], 100 * (r[2] / r[1] - 1) }' "$tmp/box.tab"
awk 'NR == 3 { printf "per rank: %.3g paths/s (2 ranks x 1 thread)\n", $2 * 1e6 / 2 }' "$tmp/box.tab" |
    tee "$tmp/rank_rate"

echo
echo "== pi --method plain --samples $pin"
printf '%-26s %9s  %s\n' run wall_s output
pi() { # $1 = label, $2 = name, rest = command
    local label=$1 out=$2 t0 t1 same=reference
    shift 2
    t0=$(now)
    "$@" --method plain --samples "$pin" >"$tmp/$out.pi" 2>/dev/null
    t1=$(now)
    [ "$out" = one ] || { cmp -s "$tmp/one.pi" "$tmp/$out.pi" && same="same bytes" || same=DIFFERENT; }
    awk -v l="$label" -v a="$t0" -v b="$t1" -v x="$same" 'BEGIN { printf "%-26s %9.2f  %s\n", l, b - a, x }'
}
pi "1 process x 2 threads" one "$build/bin/pi" --threads 2
pi "1 rank x 2 threads" r1 "${mpirun[@]}" -np 1 "$build/bin/pi" --threads 2
pi "2 ranks x 1 thread" r2 "${mpirun[@]}" -np 2 "$build/bin/pi" --threads 1

echo
echo "== what rank 0 can move (tests/mpi/handout.c)"
for k in 2 3; do "${mpirun[@]}" -np $k "$build/tests-mpi/handout"; done | tee "$tmp/handout"

echo
echo "== rows interleaved over K ranks: work of the busiest rank (tests/mpi/rowcost.c, 600x600, 2 spp)"
"$build/tests-mpi/rowcost" 600 2 >"$tmp/rows.csv"
gbs=$(sed -n 's/^ranks 2: rank 0 receives 11520000-byte messages at \([0-9.e+-]*\) GB\/s.*/\1/p' "$tmp/handout")
rate=$(sed -n 's/^per rank: \([0-9.e+-]*\) paths.*/\1/p' "$tmp/rank_rate")
start=$(awk '{ w[NR] = $1 } END { print w[2] - w[1] }' "$tmp/box.tab")
awk -F, -v gbs="$gbs" -v rate="$rate" -v start="$start" -f "$(dirname "$0")/mpi_scaling.awk" "$tmp/rows.csv"
