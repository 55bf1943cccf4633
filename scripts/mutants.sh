#!/bin/sh
# make mutants: apply each seeded defect in tests/mutants/*.mut to a scratch
# copy of the tree, build it, run the cases the mutant names, and report
# whether the cases caught it (verify exits 1).  A mutant whose text is not
# found exactly once is stale: that is an error, not a pass.
#
# Mutant file format (one per defect):
#   # what the defect is
#   file: solver/field/field.c
#   find: exact text (one line)
#   replace: replacement text
#   cases: cases/field/*.md cases/lognormal/*.md
#   eq: 5,7          the paper's equations it breaks (2..15, A.1; "none")
#   moderate: yes    a defect of 10% or less (factor 1.05, a small sign, a
#                    10% length scale): docs/design.md sec. 7.4; its cases must be
#                    quick-tier cases, since the quick tier must catch it
#
# The scratch copy takes the tree's build/ along (timestamps kept), so only
# the mutated file recompiles.  reports/mutants.md gets the verdicts and the
# map from each equation to its mutants and the cases that caught them.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
. scripts/mutant-lib.sh
list=${*:-$(ls tests/mutants/*.mut 2>/dev/null)}
[ -n "$list" ] || { echo "no mutants in tests/mutants" >&2; exit 2; }
work=$(mktemp -d /tmp/sf-mutants.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
caught=0; missed=0; broken=0; total=0; mod_total=0; mod_caught=0
report="$top/reports/mutants.md"
mkdir -p "$top/reports"
tmp_report="$report.tmp$$"
eqmap="$work/eqmap.tsv"   # eq <TAB> mutant <TAB> moderate <TAB> verdict <TAB> cases
: > "$eqmap"
{ echo "# Mutation testing"; echo; echo "| mutant | file | eq. | moderate | verdict | cases that failed |"; echo "|---|---|---|---|---|---|"; } > "$tmp_report"
# a case file's tier (quick unless its scene block says tier = full or
# tier = paper; both count as "not quick" below)
tier_of() { grep -qE '^[[:space:]]*tier[[:space:]]*=[[:space:]]*(full|paper)' "$1" && echo full || echo quick; }
for m in $list; do
    total=$((total + 1))
    name=$(basename "$m" .mut)
    file=$(mut_key "$m" file)
    find=$(mut_key "$m" find)
    repl=$(mut_key "$m" replace)
    cases=$(mut_key "$m" cases)
    eqs=$(mut_key "$m" eq | tr -d ' ')
    moderate=$(mut_key "$m" moderate | tr -d ' ')
    [ -n "$eqs" ] || eqs=unmapped
    [ -n "$moderate" ] || moderate=no
    [ "$moderate" = yes ] && mod_total=$((mod_total + 1))
    row_end() { for e in $(echo "$eqs" | tr ',' ' '); do printf '%s\t%s\t%s\t%s\t%s\n' "$e" "$name" "$moderate" "$1" "$2" >> "$eqmap"; done; }
    if [ "$moderate" = yes ]; then
        full=""
        for cf in $cases; do [ -f "$cf" ] && [ "$(tier_of "$cf")" = full ] && full="$full $cf"; done
        if [ -n "$full" ]; then
            echo "BROKEN $name: a moderate mutant must be caught by quick-tier cases; full tier:$full"
            echo "| $name | $file | $eqs | $moderate | **names full-tier cases** | |" >> "$tmp_report"
            row_end broken ""; broken=$((broken + 1)); continue
        fi
    fi
    dir="$work/$name"
    mkdir -p "$dir"
    git ls-files -co --exclude-standard | grep -v '^reports/' | tar -cf - -T - | tar -xf - -C "$dir"
    [ -d build ] && tar -cf - build | tar -xf - -C "$dir"
    n=$(text_count "$dir/$file" "$find")
    if [ "$n" != 1 ]; then
        echo "STALE  $name: '$find' found $n times in $file"
        echo "| $name | $file | $eqs | $moderate | **stale** (text found $n times) | |" >> "$tmp_report"
        row_end stale ""; broken=$((broken + 1)); continue
    fi
    FIND="$find" REPL="$repl" perl -0pi -e 's/\Q$ENV{FIND}\E/$ENV{REPL}/' "$dir/$file"
    touch "$dir/$file"
    if ! make -C "$dir" -s build/slipfield >"$dir/build.log" 2>&1; then
        echo "BROKEN $name: does not build (see a fresh run)"; tail -5 "$dir/build.log"
        echo "| $name | $file | $eqs | $moderate | **does not build** | |" >> "$tmp_report"
        row_end broken ""; broken=$((broken + 1)); continue
    fi
    # a mutant that names only full-tier cases (a pinned regression too
    # costly for the quick tier) runs them at that tier
    vtier=full
    for cf in $cases; do [ -f "$cf" ] && [ "$(tier_of "$cf")" = quick ] && vtier=quick; done
    (cd "$dir" && ./build/slipfield verify --tier $vtier --jobs 2 --reports "$dir/reports" $cases) > "$dir/verify.log" 2>&1
    rc=$?
    failed=$(grep -E '^(FAIL|ERROR)' "$dir/verify.log" | awk '{print $2}' | tr '\n' ' ')
    if [ $rc -eq 1 ]; then
        echo "CAUGHT $name by: $failed"
        echo "| $name | $file | $eqs | $moderate | caught | $failed |" >> "$tmp_report"
        row_end caught "$failed"
        caught=$((caught + 1))
        [ "$moderate" = yes ] && mod_caught=$((mod_caught + 1))
    else
        echo "MISSED $name (verify exit $rc)"
        echo "| $name | $file | $eqs | $moderate | **missed** (exit $rc) | |" >> "$tmp_report"
        row_end missed ""
        missed=$((missed + 1))
    fi
    rm -rf "$dir"
done
score=$(awk -v c=$caught -v t=$total 'BEGIN { printf "%.0f", t ? 100 * c / t : 0 }')
{
    echo
    echo "Mutation score: $caught of $total caught ($score%); $missed missed; $broken stale or broken."
    echo "Moderate mutants (a defect of 10% or less, caught by quick-tier cases): $mod_caught of $mod_total caught."
    echo
    echo "## Equations, their mutants and the cases that catch them"
    echo
    echo "Every equation of the paper (2-15, A.1) should have at least one moderate mutant"
    echo "that the quick tier catches. Factor-level mutants (moderate: no) are kept but do not count."
    echo
    echo "| eq. | moderate mutants (verdict) | caught by | other mutants |"
    echo "|---|---|---|---|"
    for e in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 A.1 none unmapped; do
        mods=$(awk -F'\t' -v e="$e" '$1 == e && $3 == "yes" { printf "%s%s (%s)", sep, $2, $4; sep = ", " }' "$eqmap")
        by=$(awk -F'\t' -v e="$e" '$1 == e && $3 == "yes" && $4 == "caught" { print $5 }' "$eqmap" | tr ' ' '\n' | sed '/^$/d' | sort -u | tr '\n' ' ')
        others=$(awk -F'\t' -v e="$e" '$1 == e && $3 != "yes" { printf "%s%s (%s)", sep, $2, $4; sep = ", " }' "$eqmap")
        case "$e" in none|unmapped) [ -z "$mods$others" ] && continue ;; esac
        [ -n "$mods" ] || mods="**none**"
        echo "| $e | $mods | $by | $others |"
    done
} >> "$tmp_report"
mv "$tmp_report" "$report"
echo "mutation score: $caught/$total ($score%); moderate: $mod_caught/$mod_total; report: reports/mutants.md"
echo "mutants: $caught passed, $((missed + broken)) failed"
[ $missed -eq 0 ] && [ $broken -eq 0 ]
