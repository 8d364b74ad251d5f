#!/bin/sh
# exercises/run.sh DIR BUILD... - the table of `make exercises`.
#
# Runs every build (DIR/NAME-all --build B --table), two at a time
# (EX_PARALLEL), and prints one row per build: exercise, build, expected
# verdict, verdict, key figure. A build named NAME is the reader's file as
# it is (the shipped stub: expected FAIL), NAME-ref the reference
# (expected PASS), NAME-slipK a classic wrong answer (expected FAIL, and
# FAIL of the check its fixture names: failing only through another check
# is unexpected), NAME-altK a correct answer written differently (expected
# PASS). Then, per exercise, its consistent slips (parts that agree with
# each other, a wrong law) failing for their check and its alternatives
# passing; every exercise must have at least one of each. Exit status 1
# when any row differs from its expectation, when an exercise lacks a
# consistent slip or an alternative, or when the number of statistical
# tests of the reference rows is not EX_FAMILY of
# exercises/check_exercise.h (the level every test runs at would then be
# wrong). EX_START (date +%s.%N) is when the build began; the total time
# is printed from it.
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
    *-alt[0-9]*) prog=${2%-alt*} opt="--build alt${2##*-alt}" ;;
    *) prog=$2 opt= ;;
    esac
    "$1/$prog-all" $opt --table >"$3/$2" 2>"$3/$2.err"; echo $? >"$3/$2.rc"' sh "$dir" {} "$tmp"

family=$(sed -n 's/^#define EX_FAMILY \([0-9]*\).*/\1/p' exercises/check_exercise.h)
alpha=$(sed -n 's/^#define EX_ALPHA \([0-9.e-]*\).*/\1/p' exercises/check_exercise.h)
printf '%-16s %-52s %-8s %-8s %s\n' exercise build expected got "key figure"
bad=0 rows=0 tests=0
tab=$(printf '\t')
summary=$tmp/summary
: >"$summary"
for b in "$@"; do
    rows=$((rows + 1))
    case $b in
    *-ref) name=${b%-ref} want=PASS ;;
    *-slip[0-9]*) name=${b%-slip*} want=FAIL ;;
    *-alt[0-9]*) name=${b%-alt*} want=PASS ;;
    *) name=$b want=FAIL ;;
    esac
    read -r rc <"$tmp/$b.rc"
    got= build= key= n= failed= kind= intended=
    IFS=$tab read -r got build key n failed kind intended <"$tmp/$b" || true
    [ "$build" = yours ] && build="stub (exercises/$name.c)"
    # No verdict line, an exit status above 1, or anything on stderr (a
    # sanitizer's report) is an error, never a failure that was expected.
    if [ -z "$got" ] || [ "$rc" -gt 1 ] || [ -s "$tmp/$b.err" ]; then
        got=ERROR
        key="exit $rc: $(head -c 120 "$tmp/$b.err" | tr '\n' ' ')"
    fi
    mark=
    # A slip must fail the check it names, not just any check.
    on_target=yes
    case $b in
    *-slip[0-9]*)
        case ",$failed," in
        *",$intended,"*) ;;
        *) on_target=no ;;
        esac
        [ "$intended" = - ] || [ -z "$intended" ] && on_target=no
        ;;
    esac
    if [ "$got" != "$want" ]; then
        bad=$((bad + 1))
        mark=" <-- unexpected"
    elif [ "$on_target" = no ]; then
        bad=$((bad + 1))
        mark=" <-- unexpected: fails $failed, not its check '$intended'"
    fi
    [ "$want" = PASS ] && [ "$kind" = reference ] && tests=$((tests + ${n:-0}))
    case $b in
    *-slip[0-9]*)
        ok=no
        [ "$got" = FAIL ] && [ "$on_target" = yes ] && ok=yes
        echo "$name slip ${b##*-slip} ${kind:-?} ${intended:--} $ok" >>"$summary" ;;
    *-alt[0-9]*)
        ok=no
        [ "$got" = PASS ] && ok=yes
        echo "$name alt ${b##*-alt} alternative - $ok" >>"$summary" ;;
    esac
    printf '%-16s %-52s %-8s %-8s %s%s\n' "$name" "$build" "$want" "$got" "$key" "$mark"
done

# Per exercise: the consistent slips that fail for their check, and the
# correct alternatives that pass. An exercise without one of each, or with
# one that does not behave, counts as unexpected.
echo
echo "per exercise: consistent slips (a wrong law whose parts agree with each other) failing"
echo "for their check; correct answers written differently from the library's passing"
for b in "$@"; do
    case $b in *-ref) echo "${b%-ref}" ;; esac
done >"$tmp/names"
awk 'FNR == NR { order[++n] = $1; next }
    $2 == "slip" && $4 == "consistent" {
        cs[$1]++; if ($6 == "yes") cf[$1]++
        slips[$1] = slips[$1] (slips[$1] ? ", " : "") "slip" $3 " " $5 }
    $2 == "alt" {
        as[$1]++; if ($6 == "yes") ap[$1]++
        alts[$1] = alts[$1] (alts[$1] ? ", " : "") "alt" $3 }
    END {
        for (i = 1; i <= n; i++) {
            e = order[i]
            wrong = cs[e] < 1 || as[e] < 1 || cf[e] != cs[e] || ap[e] != as[e]
            printf "  %-16s %d of %d consistent slips fail for their check (%s); " \
                "%d of %d alternatives pass (%s)%s\n", e, cf[e], cs[e],
                slips[e] ? slips[e] : "none", ap[e], as[e], alts[e] ? alts[e] : "none",
                wrong ? "  <-- unexpected" : ""
        }
    }' "$tmp/names" "$summary" >"$tmp/per-exercise"
cat "$tmp/per-exercise"
bad=$((bad + $(grep -c 'unexpected$' "$tmp/per-exercise")))

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
