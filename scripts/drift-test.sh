#!/bin/sh
# A seeded code defect that moves a metric but not a verdict must show up
# on the drift page.  Each tests/drift/*.mut (the format of tests/mutants/)
# is applied to a scratch copy of the tree that reuses this tree's build
# (only the mutated file is recompiled); its cases run first with this
# tree's binary (the baseline), then with the mutant's against that
# baseline.  Pass: the mutant's run exits 0 (verdicts unchanged) and
# drift.md lists a moved metric of the mutant's cases -- and no verdict
# change.  A mutant whose text is not found exactly once is stale: a
# failure.  The first mutant's cases also run against their own baseline
# with this tree's binary: that page must show no drift at all (each
# row's uncertainty is wide enough for a rerun); and case names on the
# page link to their reports.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 3
make=${MAKE:-make}
list=${*:-$(ls tests/drift/*.mut 2>/dev/null)}
[ -n "$list" ] || { echo "drift-test: no tests/drift/*.mut" >&2; exit 2; }
[ -x build/slipfield ] || { echo "drift-test: build/slipfield missing: run make all" >&2; exit 2; }
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
work=$(mktemp -d /tmp/sf-drift.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok    $*"; }
bad() { fail=$((fail + 1)); echo "FAIL  $*"; }
for m in $list; do
    name=$(basename "$m" .mut)
    file=$(sed -n 's/^file: //p' "$m")
    find=$(sed -n 's/^find: //p' "$m")
    repl=$(sed -n 's/^replace: //p' "$m")
    cases=$(sed -n 's/^cases: //p' "$m")
    dir="$work/$name"
    mkdir -p "$dir/build"
    git ls-files -co --exclude-standard | grep -v '^reports/' | while read -r f; do [ -e "$f" ] && echo "$f"; done | tar -cf - -T - | tar -xf - -C "$dir"
    # the objects keep their times, so make rebuilds only what the defect touches
    cp -a build/rel build/gen build/libslipfield.a build/libsfverify.a build/slipfield "$dir/build/"
    n=$(FIND="$find" perl -0ne '$c = () = /\Q$ENV{FIND}\E/g; print $c' "$dir/$file" 2>/dev/null || echo 0)
    if [ "$n" != 1 ]; then
        bad "$name: stale ('$find' found $n times in $file)"; continue
    fi
    FIND="$find" REPL="$repl" perl -0pi -e 's/\Q$ENV{FIND}\E/$ENV{REPL}/' "$dir/$file"
    if ! $make -C "$dir" -s --no-print-directory GIT_REV="$rev" build/slipfield > "$dir/build.log" 2>&1; then
        bad "$name: does not build"; tail -5 "$dir/build.log"; continue
    fi
    # shellcheck disable=SC2086
    build/slipfield verify --reports "$work/$name-base" $cases > "$work/$name-base.log" 2>&1
    rc0=$?
    # shellcheck disable=SC2086
    (cd "$dir" && ./build/slipfield verify --reports "$work/$name-mut" --baseline "$work/$name-base/results.json" $cases) \
        > "$work/$name-mut.log" 2>&1
    rc=$?
    if [ -z "${selfdone:-}" ]; then
        selfdone=1
        # shellcheck disable=SC2086
        build/slipfield verify --reports "$work/$name-self" --baseline "$work/$name-base/results.json" $cases \
            > "$work/$name-self.log" 2>&1
        if grep -q '^- \*\*No drift\*\*' "$work/$name-self/drift.md" 2>/dev/null; then
            ok "a run against itself ($cases): no drift"
        else
            bad "a run against itself ($cases) shows drift"
            sed -n '/^## /,$p' "$work/$name-self/drift.md" 2>/dev/null | head -8
        fi
    fi
    page="$work/$name-mut/drift.md"
    moved=$(sed -n '/^## Metrics that moved/,/^## /p' "$page" 2>/dev/null | grep -c '^| \[[a-z0-9_-]*/[a-z0-9_-]*\]')
    if [ $rc0 -ne 0 ] || [ $rc -ne 0 ]; then
        bad "$name: a verdict changed or a run failed (baseline exit $rc0, mutant exit $rc): not a drift-only defect"
        tail -3 "$work/$name-mut.log"
    elif grep -q '^## Verdict changes' "$page"; then
        bad "$name: the drift page reports a verdict change"
    elif [ "$moved" -ge 1 ]; then
        grep -q '^| \[[a-z0-9_-]*/[a-z0-9_-]*\]([a-z0-9_-]*/[a-z0-9_-]*/report\.md) |' "$page" ||
            bad "$name: the drift page does not link the cases to their reports"
        grep -q '/report\.html' "$work/$name-mut/drift.html" || bad "$name: drift.html does not link report.html"
        ok "$name: verdicts unchanged, $moved metric(s) moved on the drift page:"
        sed -n '/^## Metrics that moved/,/^## /p' "$page" | grep '^| \[' | head -3 | cut -c1-260 | sed 's/^/      /'
    else
        bad "$name: MISSED: no metric moved on the drift page"
    fi
done
echo "drift mutants: $pass passed, $fail failed"
[ $fail -eq 0 ]
