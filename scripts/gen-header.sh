#!/bin/sh
# gen-header.sh FILE LINE...: write the LINEs to FILE only when FILE does
# not hold them already, so the objects that include FILE rebuild only on a change
# (the Makefile's FORCE'd rules for build/gen/*.h).
set -eu
mkdir -p "$(dirname "$1")"
f=$1; shift
printf '%s\n' "$@" > "$f.new"
if cmp -s "$f.new" "$f"; then rm -f "$f.new"; else mv "$f.new" "$f"; fi
