#!/usr/bin/env bash
# book/check.sh BUILD - the checks of `make book-check`, over BUILD/book as
# `make book` left it:
#   1. the filter's broken fixtures (book/tests/run.sh): each must fail;
#   2. links and anchors resolve, nothing is loaded from the network
#      (book/check_links.py);
#   3. the EPUB passes epubcheck;
#   4. every page in headless Chromium: no console error, every <math>
#      rendered with a size, a screenshot each (book/check_browser.py);
#   5. the warp lab (lab.html) driven through its controls: live on load,
#      rows pass, a negative control fails, the page's statistic is `warp
#      chi2`'s, the estimator, the own-warp box (right, wrong, inconsistent,
#      broken code), a phone, JavaScript off (book/check_lab.py);
#   6. the checkers of 2 and 4 reject book/tests/broken-site/, a site
#      broken on purpose in every way they look for (their negative control).
# Ends with "N passed, N failed" over every case of every check.
set -u
cd "$(dirname "$0")/.."
B=$(cd "${1:-build}" && pwd) || exit 1
BOOK=$B/book
log=$(mktemp)
tmp=$(mktemp -d)
trap 'rm -rf "$log" "$tmp"' EXIT
passed=0 failed=0

tally() { # adds the "N passed, N failed" line of $log
    local line
    line=$(grep -E '(^|: )[0-9]+ passed, [0-9]+ failed$' "$log" | tail -1 | sed 's/^.*: //')
    if [ -z "$line" ]; then
        failed=$((failed + 1))
        return
    fi
    passed=$((passed + ${line%% passed*}))
    local f=${line#*, }
    failed=$((failed + ${f%% failed*}))
}

echo "== the filter's broken fixtures"
bash book/tests/run.sh "$B" | tee "$log"
tally

if [ ! -f "$BOOK/index.html" ]; then
    echo "FAIL  no built book in $BOOK (make book)"
    echo "$passed passed, $((failed + 1)) failed"
    exit 1
fi

echo "== links and offline"
python3 book/check_links.py "$BOOK" | tee "$log"
tally

echo "== EPUB"
# Debian installs epubcheck as an executable jar, which runs only where the
# kernel knows jars; java -jar runs it everywhere.
jar=/usr/share/java/epubcheck.jar
if [ -f "$jar" ] && command -v java >/dev/null 2>&1; then
    if java -jar "$jar" -q "$BOOK/mcbox.epub" >"$log" 2>&1; then
        passed=$((passed + 1))
        echo "ok    epubcheck mcbox.epub"
    else
        failed=$((failed + 1))
        echo "FAIL  epubcheck mcbox.epub:"
        head -20 "$log"
    fi
else
    failed=$((failed + 1))
    echo "FAIL  epubcheck is not installed (make book-deps installs it)"
fi

echo "== a real browser"
python3 book/check_browser.py "$BOOK" | tee "$log"
tally

echo "== the warp lab in a browser"
# Its rows, a negative control, the estimator, the own-warp box, the
# command line's numbers, a phone and JavaScript off (book/check_lab.py); the time of the module's
# build and of this check, for the CI's budget.
t0=$SECONDS
python3 book/check_lab.py "$BOOK" "$B/bin" | tee "$log"
tally
echo "lab: the check took $((SECONDS - t0)) s"

echo "== negative control: a site broken on purpose"
cp -r book/tests/broken-site "$tmp/site"
expect_caught() { # $1 = checker, $2.. = what its output must name
    local checker=$1 what
    shift
    if python3 "$checker" "$tmp/site" >"$log" 2>&1; then
        failed=$((failed + 1))
        echo "FAIL  $checker passed the broken site"
        return
    fi
    for what in "$@"; do
        if grep -qF -- "$what" "$log"; then
            passed=$((passed + 1))
            echo "ok    $(basename "$checker") catches: $what"
        else
            failed=$((failed + 1))
            echo "FAIL  $(basename "$checker") misses: $what"
        fi
    done
}
expect_caught book/check_links.py "stylesheet href= loads from the network" "img src= loads from the network" \
    "href=missing.html: no file" "no id 'nowhere'" "stylesheet loads from the network"
expect_caught book/check_browser.py "1 of 2 <math> elements have no rendered size" \
    "console error: deliberate console error" "requests http://example.invalid/figure.png"

echo "book-check: screenshots in $BOOK/screenshots/"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
