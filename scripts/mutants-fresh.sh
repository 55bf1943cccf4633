#!/bin/sh
# make test: every seeded defect in tests/mutants/*.mut still applies (its
# `find:` text occurs exactly once in its file), and the cases it names
# exist.  A mutant left behind by a refactor stops proving that its cases
# have power, silently until the next `make mutants`; this makes it loud
# in every test run (seconds, no build).
set -u
cd "$(dirname "$0")/.."
. scripts/mutant-lib.sh
bad=0; n=0
for m in tests/mutants/*.mut; do
    n=$((n + 1))
    file=$(mut_key "$m" file)
    cases=$(mut_key "$m" cases)
    c=$(text_count "$file" "$(mut_key "$m" find)")
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
