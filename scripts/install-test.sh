#!/bin/sh
# make test: `make install` into a temporary DESTDIR + PREFIX (and into a
# temporary PREFIX alone), then examples/cycle.c is built against what was
# installed with pkg-config -- shared and static -- and run, and so is the
# C++ consumer examples/consumer.cpp (the umbrella header, extern "C", the
# version); the installed slipfield and its man page work; `make uninstall`
# removes every file and the folders install created.
# Needs no root: everything goes under /tmp.
set -u
cd "$(dirname "$0")/.." || exit 3
make=${MAKE:-make}
work=$(mktemp -d /tmp/sf-install.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok    $*"; }
bad() { fail=$((fail + 1)); echo "FAIL  $*"; }
cc=${CC:-cc}
cxx=${CXX:-g++}
# groff renders the man page; g++ builds the C++ consumer
sh scripts/deps.sh groff-base $(command -v "$cxx" >/dev/null 2>&1 || echo g++) >/dev/null || exit 1

stage=$work/stage
prefix=/opt/slipfield
if $make -s --no-print-directory install DESTDIR="$stage" PREFIX="$prefix" > "$work/install.log" 2>&1; then
    ok "make install DESTDIR=... PREFIX=$prefix"
else
    bad "make install failed"; tail -20 "$work/install.log"
    # the README shows the example: the same text
sed -n '/^#include <slipfield\/cof.h>/,/^}/p' docs/library.md > "$work/readme.c"
sed -n '/^#include <slipfield\/cof.h>/,/^}/p' examples/cycle.c > "$work/example.c"
if [ -s "$work/example.c" ] && cmp -s "$work/readme.c" "$work/example.c"; then ok "docs/library.md shows examples/cycle.c as it is"
else bad "docs/library.md's example differs from examples/cycle.c"; fi
echo "install: $pass passed, $fail failed"; exit 1
fi
root=$stage$prefix
missing=""
for f in bin/slipfield lib/libslipfield.a lib/libslipfield.so lib/libslipfield.so.0 lib/pkgconfig/slipfield.pc \
         include/slipfield/oscillator.h include/slipfield/scene.h share/man/man1/slipfield.1; do
    [ -e "$root/$f" ] || missing="$missing $f"
done
[ -z "$missing" ] && ok "installed: binary, static and shared library, headers, slipfield.pc, man page" \
                  || bad "not installed:$missing"
[ -z "$(find "$stage" -mindepth 1 -maxdepth 1 ! -name opt)" ] && ok "nothing outside DESTDIR/PREFIX" || bad "files outside PREFIX: $(ls "$stage")"
soname=$(readelf -d "$root/lib/libslipfield.so" 2>/dev/null | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
target=$(readlink "$root/lib/libslipfield.so.0")
if [ "$soname" = libslipfield.so.0 ] && [ -f "$root/lib/$target" ] && [ "$(readlink "$root/lib/libslipfield.so")" = libslipfield.so.0 ]; then
    ok "shared library $target, soname $soname, linker name libslipfield.so"
else
    bad "shared library: soname '$soname', libslipfield.so.0 -> '$target'"
fi
# internal, not installed (Makefile's PRIVATE_HEADERS): sf_alloc.h, cof_x512.h
# (solver/ and its layer folders; installed flat in include/slipfield/)
public=$(find solver -name '*.h' | sort | grep -v -e '/sf_alloc\.h$' -e '/cof_x512\.h$')
nheaders=$(echo "$public" | wc -l)
[ "$(ls "$root/include/slipfield/"*.h | wc -l)" -eq "$nheaders" ] && ok "all $nheaders public solver headers" || bad "headers missing"
noguard=""; umbrella_missing=""
for h in $public; do
    b=$(basename "$h")
    [ "$b" = slipfield.h ] && continue
    grep -q 'extern "C"' "$h" || noguard="$noguard $b"
    grep -q "^#include \"$b\"" solver/slipfield.h || umbrella_missing="$umbrella_missing $b"
done
[ -z "$noguard" ] && ok "every installed header has extern \"C\" guards" || bad "no extern \"C\" guards:$noguard"
[ -z "$umbrella_missing" ] && ok "slipfield.h includes every public header" || bad "slipfield.h lacks:$umbrella_missing"
simd=$(grep -l -e immintrin -e '__m512' -e '__attribute__((target' "$root/include/slipfield/"*.h)
[ -z "$simd" ] && ok "no SIMD intrinsics in the installed headers" || bad "SIMD in installed headers: $simd"

# the example, against the installed library, with pkg-config
export PKG_CONFIG_SYSROOT_DIR="$stage" PKG_CONFIG_PATH="$root/lib/pkgconfig"
ver=$(for k in MAJOR MINOR PATCH; do sed -n "s/^#define SF_VERSION_$k \([0-9]*\)$/\1/p" solver/base/sf_version.h; done | paste -sd.)
if pkg-config --exists slipfield && [ "$(pkg-config --modversion slipfield)" = "$ver" ]; then
    ok "pkg-config finds slipfield $(pkg-config --modversion slipfield)"
else
    bad "pkg-config does not find slipfield"
fi
# shellcheck disable=SC2046
if $cc -std=c11 -Wall -Wextra -Wpedantic -Werror examples/cycle.c $(pkg-config --cflags --libs slipfield) -o "$work/cycle-shared" 2> "$work/cc.log"; then
    ok "examples/cycle.c builds with pkg-config --cflags --libs slipfield"
    if LD_LIBRARY_PATH="$root/lib" ldd "$work/cycle-shared" | grep -q "libslipfield.so.0 => $root/lib/"; then ok "it links the installed shared library"
    else bad "it does not load the installed shared library"; fi
    if out=$(LD_LIBRARY_PATH="$root/lib" "$work/cycle-shared"); then ok "it runs: $out"; else bad "it fails: $out"; fi
else
    bad "examples/cycle.c does not build against the installed library"; sed 's/^/      /' "$work/cc.log" | head -10
fi
# static: the archive plus what pkg-config --static adds
static_libs=$(pkg-config --static --libs slipfield | sed 's/-lslipfield//')
# shellcheck disable=SC2086
if $cc -std=c11 examples/cycle.c $(pkg-config --cflags slipfield) "$root/lib/libslipfield.a" $static_libs -o "$work/cycle-static" 2> "$work/cc2.log" \
   && ! ldd "$work/cycle-static" | grep -q libslipfield && out=$("$work/cycle-static"); then
    ok "static link (libslipfield.a + pkg-config --static) runs: $out"
else
    bad "static link failed"; sed 's/^/      /' "$work/cc2.log" | head -10
fi
# C++: the umbrella header and the version, against the shared library
# shellcheck disable=SC2046
if $cxx -std=c++11 -Wall -Wextra -Wpedantic -Werror examples/consumer.cpp $(pkg-config --cflags --libs slipfield) \
        -o "$work/consumer" 2> "$work/cxx.log"; then
    if out=$(LD_LIBRARY_PATH="$root/lib" "$work/consumer"); then ok "C++ consumer (examples/consumer.cpp) builds and runs: $out"
    else bad "C++ consumer fails: $out"; fi
else
    bad "examples/consumer.cpp does not build with $cxx"; sed 's/^/      /' "$work/cxx.log" | head -10
fi
unset PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_PATH

if "$root/bin/slipfield" --version | grep -q '^slipfield '; then ok "installed slipfield runs"; else bad "installed slipfield does not run"; fi
man_text=$(groff -man -Tutf8 -P-cbou "$root/share/man/man1/slipfield.1" 2>/dev/null)
if printf '%s' "$man_text" | grep -q 'SCENE KEYS' && printf '%s' "$man_text" | grep -q 'mu_k_ratio' &&
   printf '%s' "$man_text" | grep -q -- '--baseline FILE'; then
    ok "slipfield.1 renders (groff -man), with --help, each command's options and 'help scene'"
else
    bad "slipfield.1 does not render or lacks the help text"
fi
missing_sec=""
for sec in NAME SYNOPSIS DESCRIPTION OPTIONS 'EXIT STATUS' ENVIRONMENT FILES EXAMPLES 'SEE ALSO'; do
    printf '%s\n' "$man_text" | grep -qx "$sec" || missing_sec="$missing_sec '$sec'"
done
[ -z "$missing_sec" ] && ok "slipfield.1 has NAME, SYNOPSIS, DESCRIPTION, OPTIONS, EXIT STATUS, ENVIRONMENT, FILES, EXAMPLES" \
    || bad "slipfield.1 lacks the sections$missing_sec"
if [ -z "$(groff -man -Tutf8 -ww -z "$root/share/man/man1/slipfield.1" 2>&1)" ]; then ok "groff -ww: no warnings"; else bad "groff warns on slipfield.1"; fi

$make -s --no-print-directory uninstall DESTDIR="$stage" PREFIX="$prefix" > "$work/uninstall.log" 2>&1
left=$(find "$stage" -mindepth 1)
[ -z "$left" ] && ok "make uninstall removes every file and the folders install created" || bad "make uninstall left: $left"

# PREFIX alone (what a user without DESTDIR does)
p2=$work/prefix
if $make -s --no-print-directory install PREFIX="$p2" > "$work/install2.log" 2>&1 &&
   PKG_CONFIG_PATH="$p2/lib/pkgconfig" $cc -std=c11 examples/cycle.c $(PKG_CONFIG_PATH="$p2/lib/pkgconfig" pkg-config --cflags --libs slipfield) \
       -Wl,-rpath,"$p2/lib" -o "$work/cycle-prefix" 2>&1 && "$work/cycle-prefix" > /dev/null; then
    ok "make install PREFIX=tmp: the example builds and runs (rpath)"
else
    bad "make install PREFIX=tmp: the example does not build or run"
fi
pyd=$(ls -d "$p2"/lib/python3*/dist-packages 2>/dev/null | head -1)
if [ -n "$pyd" ] && (cd "$work" && PYTHONPATH="$pyd" /usr/bin/python3 -c '
import slipfield, math
r = slipfield.run("cof = field\nl = 0.5\nT = 20\nt_skip = 10\nstrip_halfwidth = 0.05\n", unum=False)
assert r["pv_x"] > 0 and math.isnan(r["u_pv_x"]), r
assert slipfield.library()._name.startswith("'"$p2"'"), slipfield.library()._name
') > "$work/py.log" 2>&1; then
    ok "make install PREFIX=tmp: the Python package imports and runs on the installed library"
else
    bad "make install PREFIX=tmp: the Python package: $(tail -3 "$work/py.log")"
fi
$make -s --no-print-directory uninstall PREFIX="$p2" > /dev/null 2>&1
[ ! -e "$p2" ] && ok "make uninstall PREFIX=tmp removes every file and folder (PREFIX too: install made it)" \
    || bad "uninstall PREFIX=tmp left: $(find "$p2")"
# a folder that was there before install stays, with what else it holds
p3=$work/existing
mkdir -p "$p3/lib"; : > "$p3/lib/other.so"
$make -s --no-print-directory install PREFIX="$p3" > /dev/null 2>&1
$make -s --no-print-directory uninstall PREFIX="$p3" > /dev/null 2>&1
[ "$(cd "$p3" && find . | sort | paste -sd' ')" = ". ./lib ./lib/other.so" ] && ok "uninstall keeps folders it did not create" \
    || bad "uninstall into an existing PREFIX left or took: $(cd "$p3" && find . | paste -sd' ')"
# the README shows the example: the same text
sed -n '/^#include <slipfield\/cof.h>/,/^}/p' docs/library.md > "$work/readme.c"
sed -n '/^#include <slipfield\/cof.h>/,/^}/p' examples/cycle.c > "$work/example.c"
if [ -s "$work/example.c" ] && cmp -s "$work/readme.c" "$work/example.c"; then ok "docs/library.md shows examples/cycle.c as it is"
else bad "docs/library.md's example differs from examples/cycle.c"; fi
echo "install: $pass passed, $fail failed"
[ $fail -eq 0 ]
