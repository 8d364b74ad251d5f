#!/bin/sh
# make book-program BOOK_SRC=DIR: builds the book's own programs of "Ray
# Tracing: The Rest of Your Life" at release v1.123.0 for make bench: the
# final chapter's main.cc, for the error table of bench_render (600 x 600
# pixels, 100 samples per pixel, one thread, a P3 image on standard
# output), and pi.cc, for bench_mc's "vs book" column (10000^2 iterations,
# each a plain and a stratified point). The code is not part of mcbox and
# is not fetched here; DIR is a checkout the user makes (the README, "The
# noisy caustic", gives the command):
#
#   git clone --branch v1.123.0 https://github.com/petershirley/raytracingtherestofyourlife
#
# The only changes are the three lines of main.cc that set the image size
# (500 x 500) and the samples (10), and the line of pi.cc that sets the
# iterations (30000^2, half a minute); each must appear once, as at
# v1.123.0, or the build stops, so that another release is not timed under
# the old one's name. bench_mc counts the points of 10000^2 iterations
# (BOOK_PI_POINTS). $1 the checkout, $2 the renderer to write; pi is
# written beside it.
set -eu
src=${1:?usage: book_program.sh DIR OUT}
out=${2:?usage: book_program.sh DIR OUT}
die() {
    echo "book_program.sh: $*" >&2
    exit 2
}
once() { # $1 file, $2 line: present exactly once, or not the release
    n=$(grep -cF "$2" "$1" || true)
    [ "$n" = 1 ] || die "$1: '$2' appears $n times, not once: not the v1.123.0 release"
}
for f in main.cc pi.cc; do
    [ -f "$src/$f" ] || die "$src/$f: no such file (a checkout of the book's code at v1.123.0 is needed)"
done
for line in 'int nx = 500;' 'int ny = 500;' 'int ns = 10;'; do
    once "$src/main.cc" "$line"
done
once "$src/pi.cc" 'int sqrt_N = 30000;'
command -v g++ >/dev/null 2>&1 || die "g++ not found (make deps installs build-essential)"
dir=$(dirname "$out")
mkdir -p "$dir"
sed -e 's/int nx = 500;/int nx = 600;/' -e 's/int ny = 500;/int ny = 600;/' \
    -e 's/int ns = 10;/int ns = 100;/' "$src/main.cc" >"$dir/main600.cc"
# -O3 as mcbox's own build; -w: the 2018 code has warnings that are not ours to fix.
g++ -O3 -w -I"$src" "$dir/main600.cc" -o "$out"
sed -e 's/int sqrt_N = 30000;/int sqrt_N = 10000;/' "$src/pi.cc" >"$dir/pi10000.cc"
g++ -O3 -w "$dir/pi10000.cc" -o "$dir/pi"
echo "book_program.sh: built $out (600x600, 100 spp) and $dir/pi (10000^2 iterations), from $src"
