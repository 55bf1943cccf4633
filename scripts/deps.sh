#!/bin/sh
# Install what slipfield needs to build, test and plot, when it is missing.
# Debian packages; apt-get as root, or through sudo when that needs no
# password; otherwise print the exact command and fail.
set -u
PKGS="libgsl-dev libfftw3-dev libcmocka-dev gnuplot-nox pkg-config libcmark-gfm-dev libcmark-gfm-extensions-dev libjansson-dev python3-jsonschema python3-pandas python3-pytest"
[ $# -gt 0 ] && PKGS="$PKGS $*"

missing=""
if command -v dpkg-query >/dev/null 2>&1; then
    for p in $PKGS; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
    done
else
    # not Debian: check what the build actually uses
    command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
    for m in gsl fftw3 cmocka libcmark-gfm jansson; do
        pkg-config --exists "$m" 2>/dev/null || missing="$missing $m"
    done
    command -v gnuplot >/dev/null 2>&1 || missing="$missing gnuplot"
    python3 -c 'import jsonschema' 2>/dev/null || missing="$missing python3-jsonschema"
    python3 -c 'import pandas, pytest' 2>/dev/null || missing="$missing python3-pandas python3-pytest"
    if [ -n "$missing" ]; then
        echo "slipfield: missing:$missing" >&2
        echo "slipfield: install GSL, FFTW3, CMocka, cmark-gfm, jansson, gnuplot, pkg-config and Python's jsonschema, pandas and pytest with your package manager." >&2
        exit 1
    fi
    exit 0
fi
[ -z "$missing" ] && exit 0

cmd="apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends$missing"
if [ "$(id -u)" = 0 ]; then
    run=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    run="sudo"
else
    echo "slipfield: missing packages:$missing" >&2
    echo "slipfield: run as root:  $cmd" >&2
    exit 1
fi
echo "slipfield: installing:$missing" >&2
# apt-get, retried while another apt holds its lock (a second make
# started at once on a new machine): every 5 s, up to 10 min
apt() {
    i=0
    while :; do
        out=$($run env DEBIAN_FRONTEND=noninteractive apt-get "$@" 2>&1); st=$?
        [ $st -eq 0 ] && return 0
        case $out in
        *"Could not get lock"*) [ $i -lt 120 ] || break; i=$((i + 1)); sleep 5 ;;
        *) break ;;
        esac
    done
    printf '%s\n' "$out" >&2
    return $st
}
apt update -qq && apt install -y -qq --no-install-recommends $missing
rc=$?
if [ $rc -ne 0 ]; then
    echo "slipfield: package installation failed (exit $rc); run:  ${run:+sudo }$cmd" >&2
    exit 1
fi
exit 0
