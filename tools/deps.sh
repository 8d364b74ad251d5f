#!/bin/sh
# Installs the Debian packages given as arguments when some are missing.
# Cheap when everything is there: one pkg-config check and two `command -v`,
# no apt call. As root it uses apt-get; otherwise sudo apt-get. With
# --always first, the packages are asked of dpkg one by one instead (for
# lists other than the build's, which the quick check does not cover).
set -eu
quick=1
if [ "${1:-}" = "--always" ]; then
    quick=0
    shift
fi
if [ "$quick" = 1 ] && command -v pkg-config >/dev/null 2>&1 &&
   pkg-config --exists cmocka gsl libpng OpenEXR 2>/dev/null &&
   command -v cc >/dev/null 2>&1 && command -v gnuplot >/dev/null 2>&1 &&
   command -v pandoc >/dev/null 2>&1 &&
   [ -f /usr/share/texmf/fonts/opentype/public/tex-gyre-math/texgyrepagella-math.otf ]; then
    exit 0
fi
missing=""
for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -n "$missing" ] || exit 0
if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
echo "make deps: installing$missing"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing
echo "make deps: installed$missing"
