#!/bin/sh
# exercises/run.sh DIR BUILD... - the table of `make exercises`.
#
# Runs every build (DIR/NAME-all --build B --table), two at a time
# (EX_PARALLEL), and prints one row per build: exercise, build, expected verdict, verdict,
# key figure. A build named NAME is the reader's file as it is (the shipped
# stub: expected FAIL), NAME-ref the reference (expected PASS), NAME-slipK
# a classic wrong answer (expected FAIL). Exit status 1 when any row
# differs from its expectation, or when the number of statistical tests of
# the reference rows is not EX_FAMILY of exercises/check_exercise.h (the
# level every test runs at would then be wrong). EX_START (date +%s.%N)
# is when the build began; the total time is printed from it.
set -u
dir=$1
shift
jobs=${EX_PARALLEL:-2}
# The builds run side by side: one OpenMP thread each (the check's
# quadrature would otherwise start a thread per core in every one).
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Run the builds, EX_PARALLEL at a time; each writes $tmp/BUILD. Build
# NAME is DIR/NAME-all as it is, NAME-ref and NAME-slipK its --build ref
# and --build slipK.
printf '%s\n' "$@" | xargs -P "$jobs" -I{} sh -c '
    case $2 in
    *-ref) prog=${2%-ref} opt="--build ref" ;;
    *-slip[0-9]*) prog=${2%-slip*} opt="--build slip${2##*-slip}" ;;
    *) prog=$2 opt= ;;
    esac
    "$1/$prog-all" $opt --table >"$3/$2" 2>"$3/$2.err"; echo $? >"$3/$2.rc"' sh "$dir" {} "$tmp"

family=$(sed -n 's/^#define EX_FAMILY \([0-9]*\).*/\1/p' exercises/check_exercise.h)
alpha=$(sed -n 's/^#define EX_ALPHA \([0-9.e-]*\).*/\1/p' exercises/check_exercise.h)
printf '%-16s %-44s %-8s %-8s %s\n' exercise build expected got "key figure"
bad=0 rows=0 tests=0
tab=$(printf '\t')
for b in "$@"; do
    rows=$((rows + 1))
    case $b in
    *-ref) name=${b%-ref} want=PASS ;;
    *-slip[0-9]*) name=${b%-slip*} want=FAIL ;;
    *) name=$b want=FAIL ;;
    esac
    read -r rc <"$tmp/$b.rc"
    got= build= key= n=
    IFS=$tab read -r got build key n <"$tmp/$b" || true
    [ "$build" = yours ] && build="stub (exercises/$name.c)"
    # No verdict line, an exit status above 1, or anything on stderr (a
    # sanitizer's report) is an error, never a failure that was expected.
    if [ -z "$got" ] || [ "$rc" -gt 1 ] || [ -s "$tmp/$b.err" ]; then
        got=ERROR
        key="exit $rc: $(head -c 120 "$tmp/$b.err" | tr '\n' ' ')"
    fi
    mark=
    if [ "$got" != "$want" ]; then
        bad=$((bad + 1))
        mark=" <-- unexpected"
    fi
    [ "$want" = PASS ] && tests=$((tests + ${n:-0}))
    printf '%-16s %-44s %-8s %-8s %s%s\n' "$name" "$build" "$want" "$got" "$key" "$mark"
done
if [ "$tests" -ne "$family" ]; then
    echo "exercises: the reference rows ran $tests statistical tests but" \
        "exercises/check_exercise.h says EX_FAMILY $family: update it" >&2
    bad=$((bad + 1))
fi
level=$(awk -v a="$alpha" -v m="$family" 'BEGIN { printf "%.3g", 1 - exp(log(1 - a) / m) }')
end=$(date +%s.%N)
secs=$(awk -v s="${EX_START:-$end}" -v e="$end" 'BEGIN { printf "%.1f", e - s }')
echo "$rows builds, $bad unexpected; $tests statistical tests in the reference rows, each at" \
    "level $level (Sidak): false-alarm rate $alpha for the table; total ${secs} s (build included)"
echo "$((rows - bad)) passed, $bad failed"
[ "$bad" -eq 0 ]
