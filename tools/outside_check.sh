#!/usr/bin/env bash
# tools/outside_check.sh - `make outside-check`: mcbox as a user gets it.
# Installs into a staging directory (DESTDIR=$B/stage, PREFIX=/usr), then
# checks the install as a packager and a user would: the files and
# nothing else, the soname and dependencies, the exported symbols against
# the header, the header alone in C and C++, pkg-config's answers and a
# program linked with them alone (shared and static, as GSL's build tests
# gsl.pc), the dispatcher, the man pages, and the outside project
# (outside/, copied out of the tree) built and run against the stage only.
# Then that no installed file names the staging directory, that a second
# install with another PREFIX compiles nothing and installs the same files
# (mcbox.pc is relocatable), and that uninstall leaves no mcbox file behind. Ends with
# "N passed, N failed"; exits 1 when a check failed.
#
# Environment: B (the build directory), MAKE, CC (the compiler of the build).
set -eu
B=${B:?B: the build directory}
MAKE=${MAKE:-make}
CC=${CC:-cc}
mkdir -p "$B"
bdir=$(cd "$B" && pwd)
stage=$bdir/stage
stage2=$bdir/stage-opt
work=$bdir/outside-work
project=$bdir/outside-project
passed=0 failed=0

ok() { passed=$((passed + 1)); echo "ok    $1"; }
bad() { failed=$((failed + 1)); echo "FAIL  $1"; }
# check TITLE COMMAND...: one counted check, COMMAND's output shown on failure.
check() {
    local title=$1 out
    shift
    if out=$("$@" 2>&1); then ok "$title"; else bad "$title"; printf '%s\n' "$out" | tail -20; fi
}
finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" = 0 ] && exit 0
    exit 1
}
# same A B: A equals B (trailing blanks of pkg-config's output ignored).
same() {
    local a=${1%"${1##*[! ]}"}
    [ "$a" = "$2" ] || { echo "got '$a', expected '$2'"; return 1; }
}

rm -rf "$stage" "$stage2" "$work" "$project"
mkdir -p "$work"

# --- the install -----------------------------------------------------------
echo "== make install DESTDIR=$stage PREFIX=/usr"
if ! "$MAKE" --no-print-directory install DESTDIR="$stage" PREFIX=/usr; then
    bad "make install DESTDIR=... PREFIX=/usr"
    finish
fi
ok "make install DESTDIR=... PREFIX=/usr"
hdr=$stage/usr/include/mcbox/check.h
version=$(awk '/^.define MCBOX_VERSION_(MAJOR|MINOR|PATCH) / { v = v sep $3; sep = "." }
               END { print v }' "$hdr")
major=${version%%.*}
lib=$stage/usr/lib

installed_files() { (cd "$1" && find . ! -type d | sed 's|^\./||' | LC_ALL=C sort); }
expected_files() { # $1 = prefix without the leading /
    printf '%s\n' "$1/bin/mcbox" "$1/bin/mcbox-check" "$1/bin/mcbox-scene" "$1/bin/mcbox-warp" \
        "$1/include/mcbox/check.h" "$1/include/mcbox/image.h" \
        "$1/lib/libmcbox.a" "$1/lib/libmcbox.so" \
        "$1/lib/libmcbox.so.$major" "$1/lib/libmcbox.so.$version" "$1/lib/pkgconfig/mcbox.pc" \
        "$1/share/man/man1/mcbox-check.1" "$1/share/man/man1/mcbox-scene.1" \
        "$1/share/man/man1/mcbox-warp.1" \
        "$1/share/man/man1/mcbox.1" | LC_ALL=C sort
}
check "the installed files, exactly" diff <(expected_files usr) <(installed_files "$stage")
check "symlinks libmcbox.so -> .so.$major -> .so.$version" \
    test "$(readlink "$lib/libmcbox.so")" = "libmcbox.so.$major" -a \
         "$(readlink "$lib/libmcbox.so.$major")" = "libmcbox.so.$version"

# --- the shared library ----------------------------------------------------
dyn=$(readelf -d "$lib/libmcbox.so.$version")
echo "$dyn" | grep -E 'SONAME|NEEDED' | sed 's/^ */      /'
check "SONAME libmcbox.so.$major" grep -q "Library soname: \[libmcbox.so.$major\]" <<<"$dyn"
# The OpenMP runtime: gcc's libgomp, or LLVM's libomp when clang built it.
if grep -q '\[libgomp\.so' <<<"$dyn"; then omp=gomp omp_flag=-lgomp; else omp=omp omp_flag=-fopenmp; fi
check "NEEDED libgsl and lib$omp (the library carries its dependencies)" \
    bash -c 'grep -q "\[libgsl\.so" <<<"$1" && grep -q "\[lib$2\.so" <<<"$1"' _ "$dyn" "$omp"
# The header's functions: the preprocessed header (no comments), every
# mcbox_ name followed by a parenthesis.
# The headers' functions and data (img_transfer_names[]): every mcbox_
# name followed by a parenthesis or a bracket, in the three headers.
header_functions() {
    cat "$hdr" "${hdr%/*}/image.h" "${hdr%/*}/image_io.h" | cc -E -P -x c - |
        grep -oE 'mcbox_[a-z0-9_]+ *[([]' | sed 's/ *[([]$//' | LC_ALL=C sort -u
}
exported() { nm -D --defined-only "$1" | awk '$2 != "A" { sub(/@.*/, "", $3); print $3 }' | LC_ALL=C sort; }
# clang's OpenMP reductions lock a common .gomp_critical_user_* variable that
# every object of a program must share: it stays global, by design.
static_globals() {
    nm -g --defined-only "$1" | awk 'NF == 3 && $3 !~ /^\.gomp_critical_user_/ { print $3 }' |
        LC_ALL=C sort
}
echo "      $(exported "$lib/libmcbox.so.$version" | wc -l) exported symbols, $(header_functions | wc -l) functions in mcbox/check.h and mcbox/image.h"
check "exported symbols of libmcbox.so = the header's functions" \
    diff <(header_functions) <(exported "$lib/libmcbox.so.$version")
check "global symbols of libmcbox.a = the header's functions" \
    diff <(header_functions) <(static_globals "$lib/libmcbox.a")

# --- pkg-config, and a program linked with its flags alone ---------------------
# mcbox.pc is relocatable (prefix=${pcfiledir}/../..): PKG_CONFIG_PATH alone
# finds the stage's header and library, no PKG_CONFIG_SYSROOT_DIR. Its paths
# go through the pkgconfig directory; normalized, they are the stage's.
# PKG_CONFIG_LIBDIR keeps the system's own directories out of the answers.
normalized() { # the flags with every -I and -L path made canonical
    local out= w
    for w in $1; do
        case $w in
        -I* | -L*) out="$out ${w:0:2}$(realpath -m "${w:2}")" ;;
        *) out="$out $w" ;;
        esac
    done
    echo "${out# }"
}
export PKG_CONFIG_LIBDIR=$lib/pkgconfig
check "pkg-config --modversion mcbox = $version" same "$(pkg-config --modversion mcbox)" "$version"
check "pkg-config --cflags mcbox" same "$(normalized "$(pkg-config --cflags mcbox)")" "-I$stage/usr/include"
check "pkg-config --libs mcbox" same "$(normalized "$(pkg-config --libs mcbox)")" "-L$lib -lmcbox"
check "pkg-config --libs --static mcbox" same "$(normalized "$(pkg-config --libs --static mcbox)")" \
    "-L$lib -lmcbox -lgsl -lgslcblas $omp_flag -lm"
check "PKG_CONFIG_PATH alone (no SYSROOT, no LIBDIR) finds the stage" \
    bash -c "out=\$(env -u PKG_CONFIG_LIBDIR -u PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_PATH='$lib/pkgconfig' \
                 pkg-config --cflags --libs mcbox) &&
             [ \"\$(realpath -m \"\$(env -u PKG_CONFIG_LIBDIR PKG_CONFIG_PATH='$lib/pkgconfig' \
                 pkg-config --variable=includedir mcbox)\")\" = '$stage/usr/include' ] &&
             grep -q -- '-lmcbox' <<<\"\$out\""
cflags=$(pkg-config --cflags mcbox) libs=$(pkg-config --libs mcbox)
static_libs=$(pkg-config --libs --static mcbox)

for h in check image; do
    echo "#include <mcbox/$h.h>" >"$work/alone.c"
    cp "$work/alone.c" "$work/alone.cpp"
    for cc in cc gcc clang; do
        command -v $cc >/dev/null || continue
        check "mcbox/$h.h alone, $cc -std=c99 -Wall -Wextra -Wpedantic" \
            $cc -std=c99 -Wall -Wextra -Wpedantic -Werror $cflags -c "$work/alone.c" -o "$work/alone.o"
    done
    for cxx in g++ clang++; do
        command -v $cxx >/dev/null || continue
        check "mcbox/$h.h alone, $cxx -std=c++11 -Wall -Wextra -Wpedantic" \
            $cxx -std=c++11 -Wall -Wextra -Wpedantic -Werror $cflags -c "$work/alone.cpp" -o "$work/alone.o"
    done
done

# A square sampler that is right: it must pass, through every kind of link.
printf '#define MCBOX_LINK_VERSION "%s"\n' "$version" >"$work/link.c"
cat >>"$work/link.c" <<'EOF'
#include <mcbox/check.h>
#include <stdio.h>
#include <string.h>

static void square(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    out->x[0] = u[0], out->x[1] = u[1];
}

static double one(const double *x, void *ctx)
{
    (void)x, (void)ctx;
    return 1.0;
}

int main(void)
{
    mcbox_sampler s = mcbox_sampler_init(MCBOX_SQUARE);
    s.sample = square, s.pdf = one;
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = 20000;
    mcbox_check_result r;
    int rc = mcbox_check_run(&s, &o, &r, NULL);
    printf("mcbox %s: %s%s\n", mcbox_version(), rc == 0 && r.pass ? "pass" : "FAIL ", r.message);
    return rc == 0 && r.pass && strcmp(mcbox_version(), MCBOX_LINK_VERSION) == 0 ? 0 : 1;
}
EOF
cp "$work/link.c" "$work/link.cpp"
check "cc + pkg-config --cflags --libs: links, runs, passes" \
    bash -c "cc -Wall -Wextra -Wpedantic $cflags '$work/link.c' -o '$work/link_shared' $libs &&
             LD_LIBRARY_PATH='$lib' '$work/link_shared'"
# Static: wholly with gcc's libgomp.a; LLVM's libomp has no static archive,
# so with it libmcbox.a alone is linked statically.
if [ "$omp" = gomp ]; then
    for cc in cc clang; do
        command -v $cc >/dev/null || continue
        check "$cc -static + pkg-config --libs --static: links, runs, passes" \
            bash -c "$cc -static $cflags '$work/link.c' -o '$work/link_static' $static_libs 2>'$work/static.err' &&
                     ! readelf -d '$work/link_static' 2>/dev/null | grep -q NEEDED &&
                     env -u LD_LIBRARY_PATH '$work/link_static'"
    done
else
    check "$CC + pkg-config --libs --static, libmcbox.a: links, runs, passes" \
        bash -c "$CC $cflags '$work/link.c' -o '$work/link_static' ${static_libs/-lmcbox/-Wl,-Bstatic -lmcbox -Wl,-Bdynamic} &&
                 ! readelf -d '$work/link_static' | grep -q libmcbox && env -u LD_LIBRARY_PATH '$work/link_static'"
fi
if command -v g++ >/dev/null; then
    check "g++ + pkg-config --cflags --libs (extern \"C\")" \
        bash -c "g++ -Wall -Wextra $cflags '$work/link.cpp' -o '$work/link_cxx' $libs &&
                 LD_LIBRARY_PATH='$lib' '$work/link_cxx'"
fi

# --- the programs and the man pages ------------------------------------------
bin=$stage/usr/bin
check "mcbox --version, mcbox check --version" \
    bash -c "'$bin/mcbox' --version | grep -q '^mcbox ' && '$bin/mcbox' check --version | grep -q '^mcbox-check '"
check "mcbox warp list (runs mcbox-warp)" bash -c "'$bin/mcbox' warp list | grep -q '^cosine '"
check "mcbox nope: exit 2, one line 'mcbox: ...' on stderr, nothing on stdout" \
    bash -c "out=\$('$bin/mcbox' nope 2>'$work/nope.err'); rc=\$?; [ \$rc = 2 ] && [ -z \"\$out\" ] &&
             [ \$(wc -l <'$work/nope.err') = 1 ] && grep -q '^mcbox: ' '$work/nope.err'"
if command -v man >/dev/null; then
    for page in mcbox mcbox-check mcbox-scene mcbox-warp; do
        check "man -l $page.1 renders, no warnings" \
            bash -c "MANWIDTH=80 man --warnings -l '$stage/usr/share/man/man1/$page.1' >'$work/$page.txt' 2>'$work/$page.err' &&
                     [ ! -s '$work/$page.err' ] && grep -q '^NAME' '$work/$page.txt' || { cat '$work/$page.err'; false; }"
    done
else
    echo "skip  man -l (man is not installed; pandoc built the pages)"
fi

# --- the outside project, against the stage only ----------------------------
echo "== the outside project (a copy of outside/ in $project)"
cp -R outside "$project"
rm -f "$project/my_warp"
export PATH=$bin:$PATH LD_LIBRARY_PATH=$lib
check "mcbox-check on PATH is the staged one" test "$(command -v mcbox-check)" = "$bin/mcbox-check"
# The outside project's make must not see mcbox's command-line variables.
if env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u MAKEOVERRIDES "$MAKE" -C "$project" check; then
    ok "make -C outside check (C API, mcbox-check --exec, negative controls)"
else
    bad "make -C outside check (C API, mcbox-check --exec, negative controls)"
fi
check "ldd my_warp: libmcbox.so.$major from the stage" \
    bash -c "ldd '$project/my_warp' | grep -q 'libmcbox.so.$major => $lib/libmcbox.so.$major '"
unset PKG_CONFIG_LIBDIR LD_LIBRARY_PATH

# --- nothing names the stage; another PREFIX compiles nothing -----------------
check "no staged file contains the DESTDIR path" bash -c "! grep -rlF '$stage' '$stage'"
marker=$work/before-second-install
touch "$marker"
sleep 1
echo "== make install DESTDIR=$stage2 PREFIX=/opt/mcbox"
check "make install DESTDIR=... PREFIX=/opt/mcbox" \
    "$MAKE" --no-print-directory install DESTDIR="$stage2" PREFIX=/opt/mcbox
rebuilt=$(find "$bdir/obj-pic" "$bdir/lib-pic" "$bdir/man" "$bdir/bin" "$bdir/obj" "$bdir/lib" \
    -newer "$marker" 2>/dev/null | head -5)
check "the second install compiled nothing (no object, library, page or program newer)" \
    test -z "$rebuilt"
[ -z "$rebuilt" ] || echo "      rebuilt: $rebuilt"
check "the two installs are the same files (mcbox.pc relocatable)" \
    diff -r "$stage/usr" "$stage2/opt/mcbox"
check "PREFIX=/opt/mcbox: pkg-config --variable=libdir, --cflags name that stage" \
    bash -c "export PKG_CONFIG_LIBDIR='$stage2/opt/mcbox/lib/pkgconfig';
             [ \"\$(realpath -m \"\$(pkg-config --variable=libdir mcbox)\")\" = '$stage2/opt/mcbox/lib' ] &&
             [ \"\$(pkg-config --cflags mcbox | sed 's/ *\$//')\" = '-I$stage2/opt/mcbox/lib/pkgconfig/../../include' ]"

# --- uninstall ---------------------------------------------------------------
check "make uninstall DESTDIR=... PREFIX=/usr" \
    "$MAKE" --no-print-directory uninstall DESTDIR="$stage" PREFIX=/usr
check "the stage holds no file after uninstall, nor include/mcbox" \
    bash -c "[ -z \"\$(find '$stage' ! -type d)\" ] && [ ! -e '$stage/usr/include/mcbox' ]"
check "make uninstall of the PREFIX=/opt/mcbox install" \
    bash -c "'$MAKE' --no-print-directory uninstall DESTDIR='$stage2' PREFIX=/opt/mcbox >/dev/null &&
             [ -z \"\$(find '$stage2' ! -type d)\" ]"
finish
