# plots/lib.sh - what the data scripts of `make plots` share (sourced, bash).
#
# Every data script is called as `bash plots/data_<stem>.sh BIN DATA` with
# BIN the directory of the built programs and DATA where the CSV files go.
# PLOTS_QUICK=1 (set by `make plots-check`) runs the same experiments with
# fewer samples and seeds, so CI checks the whole pipeline in seconds.
#
# Seeds: run k of a sweep uses --seed BASE + 1000 * (index of N) + s, so no
# two runs of a figure share a stream: the RMS errors at neighbouring N are
# independent and a straight-line fit through them is an honest one.

set -euo pipefail

PLOTS_QUICK=${PLOTS_QUICK:-0}
# One thread per program: make -j2 already keeps both cores busy with two
# experiments, and idle OpenMP threads would only spin.
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
script=$(basename "$0" .sh)
script=${script#data_}

die() {
    echo "plots/$script: $*" >&2
    exit 1
}

[ $# -eq 2 ] || die "usage: bash plots/data_$script.sh BIN DATA"
BIN=$1
DATA=$2
mkdir -p "$DATA"
LIBDIR=$(dirname "${BASH_SOURCE[0]}")

# One program from BIN, which must exist.
prog() {
    [ -x "$BIN/$1" ] || die "$BIN/$1 is missing (build it with make all)"
    echo "$BIN/$1"
}

# Sample counts 10^lo ... 10^hi with `per` points per decade, rounded.
n_list() {
    awk -v lo="$1" -v hi="$2" -v per="$3" \
        'BEGIN { for (k = lo * per; k <= hi * per; k++) printf "%d\n", int(10 ^ (k / per) + 0.5) }'
}

# sweep OUT PROGRAM "N LIST" SEEDS BASE ARGS...
# Runs PROGRAM ARGS --samples N --seed S --csv for every N and every seed and
# appends the CSV rows (headers included; the reducers skip them) to OUT.
sweep() {
    local out=$1 p=$2 nlist=$3 seeds=$4 base=$5
    shift 5
    local k=0 n s
    for n in $nlist; do
        k=$((k + 1))
        for ((s = 1; s <= seeds; s++)); do
            "$p" "$@" --samples "$n" --seed $((base + 1000 * k + s)) --csv >>"$out" ||
                die "$(basename "$p") $* --samples $n --seed $((base + 1000 * k + s)) failed"
        done
    done
}

# rms TAG < program CSV rows  ->  the RMS table (see plots/rms.awk).
rms() {
    awk -F, -v tag="$1" -f "$LIBDIR/rms.awk"
}

# fit COLUMN < RMS table  ->  one fitted log-log slope per series (plots/fit.awk).
fit() {
    awk -F, -v ycol="$1" -f "$LIBDIR/fit.awk"
}

# new_raw STEM  ->  the path of an empty scratch file for STEM's sweep rows.
new_raw() {
    : >"$DATA/$1.raw.tmp"
    echo "$DATA/$1.raw.tmp"
}

# rms_publish RAW TAG STEM [fit]: reduces the sweep rows in RAW to the RMS
# table STEM.csv (series tagged TAG) and, with "fit", its fitted slopes
# STEM_slopes.csv; removes RAW and publishes the files (STEM.csv last).
rms_publish() {
    local raw=$1 tag=$2 stem=$3
    rms "$tag" <"$raw" >"$DATA/$stem.csv.tmp"
    rm -f "$raw"
    if [ "${4:-}" = fit ]; then
        fit rms_error <"$DATA/$stem.csv.tmp" >"$DATA/${stem}_slopes.csv.tmp"
        publish "${stem}_slopes.csv" "$stem.csv"
    else
        publish "$stem.csv"
    fi
}

# Scripts write NAME.tmp and, when everything succeeded, publish the
# files in order (the figure's main CSV last, as make looks at that one), so
# an interrupted or failed run never leaves a half-written file that make
# would take as up to date.
publish() {
    local f
    for f in "$@"; do
        mv "$DATA/$f.tmp" "$DATA/$f"
    done
}
