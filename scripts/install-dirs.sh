#!/bin/sh
# make install / uninstall: the folders that install created, so that
# uninstall removes those (when empty) and no others.
#   sh scripts/install-dirs.sh missing DESTDIR DIR...
#       prints DIR and each of its ancestors that does not exist under
#       DESTDIR yet (one a line, without DESTDIR), parents first
#   sh scripts/install-dirs.sh remove DESTDIR MANIFEST
#       removes the folders MANIFEST lists (under DESTDIR) that are empty,
#       children first, then MANIFEST
set -u
cmd=$1 destdir=$2; shift 2
case $cmd in
missing)
    for d in "$@"; do
        while [ -n "$d" ] && [ "$d" != / ] && [ "$d" != . ] && [ ! -d "$destdir$d" ]; do
            echo "$d"
            d=$(dirname "$d")
        done
    done | sort -u ;;
remove)
    manifest=$1
    [ -f "$destdir$manifest" ] || exit 0
    dirs=$(sort -r "$destdir$manifest")
    rm -f "$destdir$manifest"
    for d in $dirs; do rmdir "$destdir$d" 2>/dev/null; done
    exit 0 ;;
*) echo "install-dirs.sh: missing or remove" >&2; exit 2 ;;
esac
