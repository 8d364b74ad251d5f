#!/usr/bin/env bash
# tools/test_verdicts.sh PROG... - what the cmocka test programs PROG of
# the build $MC_BUILD (default build) print, for the book's boxes of tests
# (book/README.md): each program's output from the run `make test` kept of
# this very build ($MC_BUILD/test-logs/PROG.log: a full run at the tests'
# own seeds that passed, newer than the program and than every program and
# library of the build, which a test may call), or, without one, from
# running it now. So a book built after `make test` reads the verdicts of
# that run instead of running the suite a second time, and a book built
# alone runs the tests itself. Exits 1 when a program it runs fails or is
# missing.
set -u
build=${MC_BUILD:-build}
rc=0
for t in "$@"; do
    prog=$build/tests/$t
    log=$build/test-logs/$t.log
    if [ ! -x "$prog" ]; then
        echo "test_verdicts.sh: no test program $prog" >&2
        rc=1
    elif [ -f "$log" ] &&
        [ -z "$(find "$prog" "$build/bin" "$build/lib" -newer "$log" -print -quit 2>/dev/null)" ]; then
        cat "$log"
    else
        MC_BUILD="$build" "$prog" 2>&1 || rc=1
    fi
done
exit $rc
