#!/bin/sh
# gen-header.sh FILE LINE: write LINE to FILE only when FILE does not hold
# it already, so the objects that include FILE rebuild only on a change
# (the Makefile's FORCE'd rules for build/gen/*.h).
set -eu
mkdir -p "$(dirname "$1")"
printf '%s\n' "$2" > "$1.new"
if cmp -s "$1.new" "$1"; then rm -f "$1.new"; else mv "$1.new" "$1"; fi
