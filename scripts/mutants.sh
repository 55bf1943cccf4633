#!/bin/sh
# make mutants: apply each seeded defect in tests/mutants/*.mut to a scratch
# copy of the tree, build it, run the cases the mutant names, and report
# whether the cases caught it (verify exits 1).  A mutant whose text is not
# found exactly once is stale: that is an error, not a pass.
#
# Mutant file format (one per defect):
#   # what the defect is
#   file: solver/field.c
#   find: exact text (one line)
#   replace: replacement text
#   cases: cases/field/*.md cases/lognormal/*.md
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
list=${*:-$(ls tests/mutants/*.mut 2>/dev/null)}
[ -n "$list" ] || { echo "no mutants in tests/mutants" >&2; exit 2; }
work=$(mktemp -d /tmp/sf-mutants.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
caught=0; missed=0; broken=0; total=0
report="$top/reports/mutants.md"
mkdir -p "$top/reports"
tmp_report="$report.tmp$$"
{ echo "# Mutation testing"; echo; echo "| mutant | file | verdict | cases that failed |"; echo "|---|---|---|---|"; } > "$tmp_report"
for m in $list; do
    total=$((total + 1))
    name=$(basename "$m" .mut)
    file=$(sed -n 's/^file: //p' "$m")
    find=$(sed -n 's/^find: //p' "$m")
    repl=$(sed -n 's/^replace: //p' "$m")
    cases=$(sed -n 's/^cases: //p' "$m")
    dir="$work/$name"
    mkdir -p "$dir"
    git ls-files -co --exclude-standard | grep -v '^reports/' | tar -cf - -T - | tar -xf - -C "$dir"
    n=$(FIND="$find" perl -0ne '$c = () = /\Q$ENV{FIND}\E/g; print $c' "$dir/$file" 2>/dev/null || echo 0)
    if [ "$n" != 1 ]; then
        echo "STALE  $name: '$find' found $n times in $file"
        echo "| $name | $file | **stale** (text found $n times) | |" >> "$tmp_report"
        broken=$((broken + 1)); continue
    fi
    FIND="$find" REPL="$repl" perl -0pi -e 's/\Q$ENV{FIND}\E/$ENV{REPL}/' "$dir/$file"
    if ! make -C "$dir" -s build/slipfield >"$dir/build.log" 2>&1; then
        echo "BROKEN $name: does not build (see a fresh run)"; tail -5 "$dir/build.log"
        echo "| $name | $file | **does not build** | |" >> "$tmp_report"
        broken=$((broken + 1)); continue
    fi
    (cd "$dir" && ./build/slipfield verify --jobs 2 --reports "$dir/reports" $cases) > "$dir/verify.log" 2>&1
    rc=$?
    failed=$(grep -E '^(FAIL|ERROR)' "$dir/verify.log" | awk '{print $2}' | tr '\n' ' ')
    if [ $rc -eq 1 ]; then
        echo "CAUGHT $name by: $failed"
        echo "| $name | $file | caught | $failed |" >> "$tmp_report"
        caught=$((caught + 1))
    else
        echo "MISSED $name (verify exit $rc)"
        echo "| $name | $file | **missed** (exit $rc) | |" >> "$tmp_report"
        missed=$((missed + 1))
    fi
done
score=$(awk -v c=$caught -v t=$total 'BEGIN { printf "%.0f", t ? 100 * c / t : 0 }')
{ echo; echo "Mutation score: $caught of $total caught ($score%); $missed missed; $broken stale or broken."; } >> "$tmp_report"
mv "$tmp_report" "$report"
echo "mutation score: $caught/$total ($score%), report: reports/mutants.md"
echo "mutants: $caught passed, $((missed + broken)) failed"
[ $missed -eq 0 ] && [ $broken -eq 0 ]
