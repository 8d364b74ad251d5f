#!/bin/sh
# lab/gsl_source.sh APTDIR SRCDIR - unpacks into SRCDIR Debian's source of
# the GSL that is installed (libgsl-dev's version), for the lab's module.
#
# apt fetches it with a package list of its own under APTDIR (a deb-src
# line for the suite the system already uses, signed by the same Debian
# archive key), so the system's sources and lists are not touched; apt
# checks the list's signature and the files' hashes as for any package.
# Only the upstream tarball is unpacked: Debian's patches to GSL touch no
# file the lab compiles.
set -eu
apt_dir=$1
src_dir=$2
version=$(dpkg-query -W -f='${Version}' libgsl-dev 2>/dev/null) ||
    { echo "lab: libgsl-dev is not installed (make deps)" >&2; exit 1; }
suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache" "$apt_dir/download"
apt_dir=$(cd "$apt_dir" && pwd)
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
{
    echo "deb-src [signed-by=$keyring] http://deb.debian.org/debian $suite main"
    echo "deb-src [signed-by=$keyring] http://deb.debian.org/debian-security $suite-security main"
    echo "deb-src [signed-by=$keyring] http://deb.debian.org/debian $suite-updates main"
} >"$apt_dir/sources.list"
apt_opts="-q -o Dir::Etc::SourceList=$apt_dir/sources.list -o Dir::Etc::SourceParts=/dev/null
          -o Dir::State::Lists=$apt_dir/lists -o Dir::Cache=$apt_dir/cache
          -o APT::Sandbox::User=root"
# shellcheck disable=SC2086
apt-get $apt_opts update >"$apt_dir/update.log" 2>&1 ||
    { cat "$apt_dir/update.log" >&2; exit 1; }
# The installed version first; should the archive have moved past it, the
# suite's current one, said aloud (book-check compares the page's numbers
# with the native program's, so a difference that matters would show).
rm -f "$apt_dir"/download/gsl_*
# shellcheck disable=SC2086
if ! (cd "$apt_dir/download" && apt-get $apt_opts source --download-only "gsl=$version") \
    >"$apt_dir/source.log" 2>&1; then
    echo "lab: Debian's source of gsl $version is gone from the archive; taking the suite's" >&2
    # shellcheck disable=SC2086
    (cd "$apt_dir/download" && apt-get $apt_opts source --download-only gsl) \
        >"$apt_dir/source.log" 2>&1 || { cat "$apt_dir/source.log" >&2; exit 1; }
fi
orig=$(ls "$apt_dir"/download/gsl_*.orig.tar.gz | head -1)
rm -rf "$src_dir"
mkdir -p "$src_dir"
tar -xzf "$orig" -C "$src_dir" --strip-components=1
