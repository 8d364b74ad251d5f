#!/usr/bin/env bash
# book/tests/run.sh BUILD - proves that the book's filter stops the build on
# every kind of broken listing, run, number and figure. Each fixture chapter
# of fixtures/ is built alone against the fixture sources of fixtures/src/;
# cases.txt gives the one line each must fail with (`file:line: message`),
# and "good", the positive control, must build. "unused" builds the chapter
# that uses one of the two regions of fixtures/src-unused/, then runs the
# whole-tree check, which must name the other one. "uncited" and
# "missing-ref-comment" run the whole-tree check of citations over
# fixtures/src-refs (an entry that nothing cites) and fixtures/src-refs-missing
# (a comment that cites a key with no entry); the fixture chapters cite the
# entries of fixtures/src-refs/book/references.md.
# Prints a line per case and the totals as "book fixtures: N passed, N failed".
set -u
B=$(cd "${1:-build}" && pwd) || exit 1
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0

build_fixture() { # $1 = chapter, $2 = source root; output in $tmp/out, $tmp/err
    rm -rf "$tmp/state" && mkdir -p "$tmp/state/runs" "$tmp/state/cwd"
    # One anchor of a numbered chapter, for the links of wrong-chapter.
    echo "ch-pi 01-pi.html" >"$tmp/state/anchors"
    BOOK_BUILD=$B BOOK_OUT=$tmp/book BOOK_STATE=$tmp/state BOOK_RUNS=$tmp/state/cwd BOOK_SRC=$2 \
        BOOK_REFS=$PWD/fixtures/src-refs/book/references.md pandoc --fail-if-warnings --lua-filter ../mcbox.lua -f markdown -t html5 \
        -o "$tmp/out" "$1" 2>"$tmp/err"
}

verdict() { # $1 = name, $2 = ok (0/1), $3 = what went wrong
    if [ "$2" = 1 ]; then
        passed=$((passed + 1))
        echo "ok    book fixture $1"
    else
        failed=$((failed + 1))
        echo "FAIL  book fixture $1: $3"
    fi
}

while IFS=$'\t' read -r name want; do
    case $name in '#'* | '') continue ;; esac
    if [ "$name" = unused ]; then
        printf -- '```{.listing file=mc/used.c name=used}\n```\n' >"$tmp/uses.md"
        build_fixture "$tmp/uses.md" "$PWD/fixtures/src-unused"
        BOOK_BUILD=$B BOOK_STATE=$tmp/state BOOK_SRC=$PWD/fixtures/src-unused \
            pandoc -f markdown -t plain --lua-filter ../mcbox.lua -M book-check-regions=true \
            -o /dev/null </dev/null 2>"$tmp/err"
        rc=$?
    elif [ "$name" = uncited ] || [ "$name" = missing-ref-comment ]; then
        tree=src-refs
        [ "$name" = uncited ] || tree=src-refs-missing
        rm -rf "$tmp/state" && mkdir -p "$tmp/state"
        BOOK_BUILD=$B BOOK_STATE=$tmp/state BOOK_SRC=$PWD/fixtures/$tree \
            pandoc -f markdown -t plain --lua-filter ../mcbox.lua -M book-check-citations=true \
            -o /dev/null </dev/null 2>"$tmp/err"
        rc=$?
    else
        build_fixture "fixtures/$name.md" "$PWD/fixtures/src"
        rc=$?
    fi
    first=$(head -1 "$tmp/err")
    if [ "${want%% *}" = PASS ]; then
        if [ $rc = 0 ] && grep -qE "${want#PASS }" "$tmp/out"; then verdict "$name" 1
        else verdict "$name" 0 "exit $rc, stderr: $first"; fi
    elif [ $rc = 0 ]; then
        verdict "$name" 0 "the build succeeded"
    elif [[ $first =~ $want ]]; then
        verdict "$name" 1
    else
        verdict "$name" 0 "exit $rc with '$first', expected /$want/"
    fi
done <cases.txt
echo "book fixtures: $passed passed, $failed failed"
[ $failed = 0 ]
