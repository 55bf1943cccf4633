#!/bin/sh
# make test: every seeded defect in tests/mutants/*.mut still applies (its
# `find:` text occurs exactly once in its file), and the cases it names
# exist.  A mutant left behind by a refactor stops proving that its cases
# have power, silently until the next `make mutants`; this makes it loud
# in every test run (seconds, no build).
set -u
cd "$(dirname "$0")/.."
bad=0; n=0
for m in tests/mutants/*.mut; do
    n=$((n + 1))
    file=$(sed -n 's/^file: //p' "$m")
    find=$(sed -n 's/^find: //p' "$m")
    cases=$(sed -n 's/^cases: //p' "$m")
    c=$(FIND="$find" perl -0ne '$c = () = /\Q$ENV{FIND}\E/g; print $c' "$file" 2>/dev/null || echo 0)
    if [ "$c" != 1 ]; then
        echo "mutants: STALE $(basename "$m" .mut): its text is found $c times in $file" >&2
        bad=$((bad + 1))
    fi
    [ -n "$cases" ] || { echo "mutants: $(basename "$m" .mut) names no case" >&2; bad=$((bad + 1)); }
    for cf in $cases; do
        [ -f "$cf" ] || { echo "mutants: $(basename "$m" .mut) names a missing case $cf" >&2; bad=$((bad + 1)); }
    done
done
echo "mutants: $((n - bad)) of $n apply (text found once, cases exist)"
[ "$bad" -eq 0 ]
