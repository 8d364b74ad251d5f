#!/bin/sh
# make book-program BOOK_SRC=DIR: builds the book's own program, the final
# chapter's main.cc of "Ray Tracing: The Rest of Your Life" at release
# v1.123.0, for the error table of make bench: 600 x 600 pixels, 100
# samples per pixel, one thread, a P3 image on standard output. The code is
# not part of mcbox and is not fetched here; DIR is a checkout the user
# makes (the README, "The noisy caustic", gives the command):
#
#   git clone --branch v1.123.0 https://github.com/petershirley/raytracingtherestofyourlife
#
# The only change is the three lines that set the image size (500 x 500)
# and the samples (10); each must appear once, as at v1.123.0, or the build
# stops, so that another release is not timed under the old one's name.
# $1 the checkout, $2 the program to write.
set -eu
src=${1:?usage: book_program.sh DIR OUT}
out=${2:?usage: book_program.sh DIR OUT}
die() {
    echo "book_program.sh: $*" >&2
    exit 2
}
[ -f "$src/main.cc" ] || die "$src/main.cc: no such file (a checkout of the book's code at v1.123.0 is needed)"
for line in 'int nx = 500;' 'int ny = 500;' 'int ns = 10;'; do
    n=$(grep -cF "$line" "$src/main.cc" || true)
    [ "$n" = 1 ] || die "$src/main.cc: '$line' appears $n times, not once: not the v1.123.0 release"
done
command -v g++ >/dev/null 2>&1 || die "g++ not found (make deps installs build-essential)"
dir=$(dirname "$out")
mkdir -p "$dir"
sed -e 's/int nx = 500;/int nx = 600;/' -e 's/int ny = 500;/int ny = 600;/' \
    -e 's/int ns = 10;/int ns = 100;/' "$src/main.cc" >"$dir/main600.cc"
# -O3 as mcbox's own build; -w: the 2018 code has warnings that are not ours to fix.
g++ -O3 -w -I"$src" "$dir/main600.cc" -o "$out"
echo "book_program.sh: built $out (600x600, 100 spp, from $src)"
