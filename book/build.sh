#!/usr/bin/env bash
# book/build.sh BUILD - builds the book from book/*.md into BUILD/book/.
#
# Every chapter goes through pandoc twice with book/mcbox.lua: once to its
# HTML page, once to Markdown with every listing, run and number resolved,
# from which the EPUB is made (so the commands run once per build: the
# second pass reads their output from BUILD/book-state/runs). Then the
# pages of whole source files that listings link to, the contents page,
# and a last pass that fails if any marked region of the tree went unused.
# Any error of the filter or any pandoc warning stops the build.
#
# For writing one chapter: BOOK_DIR=DIR puts the output in DIR/book and
# DIR/book-state instead of BUILD's, and BOOK_ONLY="01 02" builds only the
# chapters with those numbers (and skips the check for unused regions).
set -euo pipefail
cd "$(dirname "$0")/.."
B=$(cd "${1:-build}" && pwd)
D=${BOOK_DIR:-$B}
mkdir -p "$D"
D=$(cd "$D" && pwd)
OUT=$D/book
STATE=$D/book-state
t0=$(date +%s%N)

rm -rf "$OUT" "$STATE"
mkdir -p "$OUT" "$STATE/runs" "$STATE/md" "$STATE/runs-cwd"
export BOOK_BUILD=$B BOOK_OUT=$OUT BOOK_STATE=$STATE BOOK_SRC=$PWD BOOK_RUNS=$STATE/runs-cwd
: >"$STATE/used-regions"
: >"$STATE/used-files"

mapfile -t chapters < <(ls book/[0-9][0-9]-*.md | sort)
if [ -n "${BOOK_ONLY:-}" ]; then
    keep=()
    for ch in "${chapters[@]}"; do
        for k in $BOOK_ONLY; do [[ $(basename "$ch") == "$k"-* ]] && keep+=("$ch"); done
    done
    chapters=("${keep[@]}")
fi
[ ${#chapters[@]} -gt 0 ] || { echo "book: no chapters in book/" >&2; exit 1; }
# The references page comes last, with every build (the chapters' [@key]
# citations link to its entries).
chapters+=(book/references.md)

title_of() { # the chapter's first level-1 heading, without its attributes
    sed -n 's/^# \(.*\)$/\1/p' "$1" | head -1 | sed 's/ *{[^}]*}$//'
}
summary_of() { sed -n 's/^summary: *//p' "$1" | head -1; }
stem_of() { basename "$1" .md; }

# Anchors: "id page" for every explicit {#id} of every chapter, so that a
# link to #id from another chapter reaches the right page.
for ch in "${chapters[@]}"; do
    grep -o '{#[A-Za-z0-9_:.-]*' "$ch" | sed "s/^{#//; s/\$/ $(stem_of "$ch").html/" || true
done >"$STATE/anchors"
echo "lab lab.html" >>"$STATE/anchors"

PANDOC=(pandoc --fail-if-warnings --lua-filter book/mcbox.lua -f markdown)
n=${#chapters[@]}
chapter() { # $1 = index: the chapter's HTML page, then its resolved Markdown
    local i=$1 ch=${chapters[$1]} stem
    stem=$(stem_of "$ch")
    local vars=(-M "pagetitle=$(title_of "$ch")" -V root=)
    if ((i > 0)); then
        vars+=(-V "prev=$(stem_of "${chapters[i - 1]}").html" -V "prevtitle=$(title_of "${chapters[i - 1]}")")
    fi
    if ((i + 1 < n)); then
        vars+=(-V "next=$(stem_of "${chapters[i + 1]}").html" -V "nexttitle=$(title_of "${chapters[i + 1]}")")
    fi
    "${PANDOC[@]}" -t html5 -s --template book/template.html --mathml "${vars[@]}" \
        -o "$OUT/$stem.html" "$ch" &&
        "${PANDOC[@]}" -t markdown -o "$STATE/md/$stem.md" "$ch"
}
# Two chapters at a time (the machine's two cores): their runs are
# independent, and a command two chapters share is cached by whichever
# finishes it first.
jobs_max=${BOOK_JOBS:-2}
rm -f "$STATE/failed"
for ((i = 0; i < n; i++)); do
    { chapter "$i" || touch "$STATE/failed"; } &
    while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
done
wait
[ ! -e "$STATE/failed" ] || exit 1

# The warp lab: a page beside the chapters that runs the WebAssembly module
# of `make lab` (BUILD/lab) with lab/lab.js (and lab/own.js, its own-warp
# box, loaded first). It is not in the EPUB, whose
# readers run no scripts; the chapters link to it from .html-only blocks.
# It is built after the chapters so that its links find their anchors.
[ -f "$B/lab/lab-wasm.js" ] || { echo "book: $B/lab/lab-wasm.js is missing (make lab builds it)" >&2; exit 1; }
mkdir -p "$OUT/lab"
cp "$B/lab/lab-wasm.js" lab/own.js lab/lab.js lab/lab.css "$OUT/lab/"
"${PANDOC[@]}" -t html5 -s --template book/template.html --mathml -M "pagetitle=$(title_of book/lab.md)" \
    -V root= -V labcss=lab/lab.css -V labscript=lab/lab-wasm.js -V labscript=lab/own.js -V labscript=lab/lab.js \
    -o "$OUT/lab.html" book/lab.md

# The pages of whole files, with line numbers (anchors L-1, L-2, ...): plain
# text in a page of the book's style, written by awk (pandoc's highlighting
# of fifty files would cost more than every other page together).
source_page() { # $1 = path of a source file
    local f=$1 page=$OUT/src/$1.html depth root
    mkdir -p "$(dirname "$page")"
    depth=$(tr -cd / <<<"src/$f" | wc -c)
    root=$(printf '../%.0s' $(seq 1 "$depth"))
    awk -v path="$f" -v root="$root" '
        function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); return s }
        BEGIN {
            print "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">"
            print "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            print "<title>" esc(path) " - mcbox</title>"
            print "<link rel=\"stylesheet\" href=\"" root "style.css\">\n</head>\n<body>"
            print "<nav class=\"book-nav\"><a href=\"" root "index.html\">Contents</a></nav>\n<main>"
            print "<h1><code>" esc(path) "</code></h1>\n<pre class=\"source-file\"><code>"
        }
        { printf "<span id=\"L-%d\"><a class=\"ln\" href=\"#L-%d\">%d</a>%s</span>\n", NR, NR, NR, esc($0) }
        END { print "</code></pre>\n</main>\n</body>\n</html>" }' "$f" >"$page"
}
sort -u "$STATE/used-files" | while read -r f; do source_page "$f"; done

# The contents page: book/index.md, then one line per chapter.
{
    cat book/index.md
    printf '\n::: {.contents}\n'
    for ch in "${chapters[@]}"; do
        case $(stem_of "$ch") in
        99-*) num=A ;;
        [0-9][0-9]-*) num=$((10#$(stem_of "$ch" | cut -d- -f1))) ;;
        *) num= ;;
        esac
        printf -- '- [%s]{.number} [%s](%s.html) [%s]{.summary}\n' "$num" "$(title_of "$ch")" \
            "$(stem_of "$ch")" "$(summary_of "$ch")"
    done
    printf ':::\n\nThe whole book as one file, for a reader: [mcbox.epub](mcbox.epub).\n'
} | pandoc --fail-if-warnings -f markdown -t html5 -s --template book/template.html \
    -M "pagetitle=Contents" -V root= -o "$OUT/index.html"

cp book/style.css "$OUT/style.css"
# The math font the stylesheet names, shipped with the pages (no reader's
# machine needs it installed, nothing is fetched).
MATH_FONT=/usr/share/texmf/fonts/opentype/public/tex-gyre-math/texgyrepagella-math.otf
[ -f "$MATH_FONT" ] || { echo "book: $MATH_FONT is missing (make deps installs fonts-texgyre-math)" >&2; exit 1; }
mkdir -p "$OUT/fonts"
cp "$MATH_FONT" "$OUT/fonts/"

# The EPUB, from the resolved Markdown of every chapter. Its stylesheet sits
# in styles/ beside the embedded fonts/ of the container.
sed 's#url("fonts/#url("../fonts/#' book/style.css >"$STATE/epub.css"
(cd "$STATE/md" && pandoc --fail-if-warnings -f markdown -t epub3 --mathml \
    --metadata title="mcbox: Monte Carlo, verified" --metadata lang=en \
    --css "$STATE/epub.css" --resource-path="$OUT" --epub-chapter-level=1 --toc-depth=1 \
    --epub-embed-font="$MATH_FONT" \
    -o "$OUT/mcbox.epub" $(for ch in "${chapters[@]}"; do echo "$(stem_of "$ch").md"; done))

# Every marked region of the tree is used by some chapter, and every
# figure of `make plots` is shown by some chapter.
if [ -z "${BOOK_ONLY:-}" ]; then
    for stem in $(sed -n '/^STEMS :=/,/[^\\]$/p' plots/Makefile.inc | sed 's/^STEMS :=//; s/\\//g'); do
        if ! grep -qx "plot $stem" "$STATE/figures" 2>/dev/null; then
            echo "plots/Makefile.inc:1: figure '$stem' is shown by no chapter" >&2
            exit 1
        fi
    done
    pandoc --fail-if-warnings -f markdown -t plain --lua-filter book/mcbox.lua \
        -M book-check-regions=true -o /dev/null </dev/null
    # Every [@key] of a chapter or a comment has an entry in
    # book/references.md, and every entry is cited.
    pandoc --fail-if-warnings -f markdown -t plain --lua-filter book/mcbox.lua \
        -M book-check-citations=true -o /dev/null </dev/null
fi

# What the build did, for the closing line and the README.
count() { [ -f "$1" ] && wc -l <"$1" || echo 0; }
words_of() { # prose only: fenced blocks and the front matter left out
    awk '/^(```|~~~)/ { fence = !fence; next } NR == 1 && /^---$/ { yaml = 1; next }
         yaml { if (/^---$/) yaml = 0; next } !fence' "$1" | wc -w
}
words=0
for ch in "${chapters[@]}"; do
    w=$(words_of "$ch")
    words=$((words + w))
    printf '%s %d\n' "$(stem_of "$ch")" "$w"
done >"$STATE/words"
t1=$(date +%s%N)
printf 'book: %d chapters, %d words, %d listings, %d runs, %d numbers, %d figures, %d source pages, %.1f s -> %s\n' \
    "$n" "$words" "$(count "$STATE/used-regions")" "$(count "$STATE/run-count")" \
    "$(count "$STATE/number-count")" "$(count "$STATE/figures")" "$(sort -u "$STATE/used-files" | wc -l)" \
    "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print (b - a) / 1e9 }')" "$OUT/index.html"
