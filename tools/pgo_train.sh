#!/bin/sh
# Training for the profile-guided build (PGO in the Makefile): $1 is the
# instrumented cornell_box, $2 the directory its counts go to (one .gcda
# per object, read back when the library objects are compiled again). The
# book scene with its mixture, the benchmark's work, dominates the counts;
# the small renders after it keep the other scenes and strategies from
# looking cold. One thread and fixed seeds: the same counts every time.
set -eu
cb=$1
dir=$2
mkdir -p "$dir"
find "$dir" -name '*.gcda' -exec rm -f {} +
out=$dir/train.pfm
run() {
    "$cb" --threads 1 --seed 1 -o "$out" "$@" >/dev/null 2>&1 ||
        { echo "pgo_train.sh: cornell_box $* failed" >&2; exit 1; }
}
run --scene book --width 96 --spp 16
run --scene book-metal --width 24 --spp 4
run --scene book --width 48 --spp 8 --strategy bdpt --roulette
run --scene lambert --width 32 --spp 4 --strategy bdpt --roulette
run --scene lambert --width 24 --spp 4 --strategy lighttrace
run --scene lambert --width 24 --spp 4 --strategy mis
run --scene lambert --width 24 --spp 4 --strategy light
run --scene furnace --width 16 --spp 4 --strategy cosine
run --scene sphere-light --width 16 --spp 4 --strategy uniform
rm -f "$out"
