#!/bin/sh
# make coverage: line and branch coverage of solver/ by what `make test` and
# the quick tier run, with solver/ built with --coverage (BUILD/cov/).
#   sh scripts/coverage.sh BUILD JOBS TEST...
# Runs the unit tests (the plain ones; the sanitised builds run the same
# code), the CLI scripts of make test (bad input, resume, results) and the
# quick tier with BUILD/cov/slipfield (less the long cases listed in
# tests/coverage-skip.txt, which cover nothing more; COV_ALL=1: every case);
# then lcov (branch coverage on) keeps
# solver/*.c, genhtml writes reports/coverage/index.html and this script
# reports/coverage/summary.md.  Fails when line or branch coverage is below
# the floor recorded in tests/coverage-floor.txt (the target is 95 % of
# lines, 85 % of branches; the file records the measured value when that
# is lower, and is raised whenever coverage rises: see the file).
set -u
build=$1 jobs=$2; shift 2
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
cov=$build/cov out=reports/coverage floor=tests/coverage-floor.txt
rc_lcov="--rc lcov_branch_coverage=1"
t0=$(date +%s)
st=0
if [ "${COV_RUN:-1}" != 0 ]; then   # COV_RUN=0: report the last runs' counts again
find "$cov" -name '*.gcda' -delete
# the quick tier's cases less those of tests/coverage-skip.txt (the longest
# at -O0, which reach no line or branch the others miss: see the file);
# COV_ALL=1 runs them all
cases=$(ls cases/*/*.md)
if [ "${COV_ALL:-0}" = 0 ]; then
    skip=$(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' tests/coverage-skip.txt)
    for c in $skip; do
        [ -f "cases/$c" ] || { echo "coverage: tests/coverage-skip.txt names cases/$c, which does not exist" >&2; exit 1; }
    done
    cases=$(printf '%s\n' $cases | grep -v -x -F "$(printf 'cases/%s\n' $skip)")
fi
rm -f "$cov/units.rc"
# the unit tests and the CLI scripts (one process at a time) run beside the
# quick tier (libgcov merges the counts of concurrent processes under a
# file lock)
(
    for t in "$@"; do
        CMOCKA_MESSAGE_OUTPUT=STDOUT "$t" > "$cov/$(basename "$t").log" 2>&1 ||
            { echo "coverage: unit test $(basename "$t") failed (see $cov/$(basename "$t").log)" >&2; echo 1 > "$cov/units.rc"; }
    done
    for s in bad-input resume-test results-test; do
        sh "scripts/$s.sh" "$cov/slipfield" > "$cov/$s.log" 2>&1 ||
            { echo "coverage: scripts/$s.sh failed (see $cov/$s.log)" >&2; echo 1 > "$cov/units.rc"; }
    done
) &
units=$!
# --timeout: a wall-time limit instead of the per-case CPU-time limits
# (cases/times.tsv records -O2 times; -O0 --coverage runs many times slower)
# shellcheck disable=SC2086
"$cov/slipfield" verify --jobs "$jobs" --tier quick --timeout 900 --reports "$cov/reports" $cases > "$cov/verify.log" 2>&1 ||
    { echo "coverage: the quick tier failed under coverage (see $cov/verify.log)" >&2; st=1; }
wait "$units"
[ -f "$cov/units.rc" ] && st=1
fi
t1=$(date +%s)
rm -rf "$out"; mkdir -p "$out"
# (lcov 1.16's geninfo prints perl warnings on stderr: kept in lcov.log)
lcov $rc_lcov --quiet --capture --directory "$cov/solver" --base-directory "$top" --output-file "$cov/all.info" 2> "$cov/lcov.log" &&
lcov $rc_lcov --quiet --extract "$cov/all.info" "$top/solver/*" --output-file "$out/solver.info" 2>> "$cov/lcov.log" ||
    { echo "coverage: lcov failed" >&2; exit 1; }
genhtml $rc_lcov --quiet --branch-coverage --legend --title "slipfield solver/ coverage (make test + quick tier)" \
    --output-directory "$out" "$out/solver.info" > /dev/null 2>> "$cov/lcov.log" || { echo "coverage: genhtml failed" >&2; exit 1; }
# the totals and the per-file table, from the tracefile (LF/LH, BRF/BRH)
awk -v floorfile="$floor" -v secs=$((t1 - t0)) '
    /^SF:/ { f = $0; sub(/^SF:.*\/solver\//, "solver/", f); fs[++n] = f }
    /^LF:/ { lf[f] = substr($0, 4); LF += lf[f] }
    /^LH:/ { lh[f] = substr($0, 4); LH += lh[f] }
    /^BRF:/ { bf[f] = substr($0, 5); BF += bf[f] }
    /^BRH:/ { bh[f] = substr($0, 5); BH += bh[f] }
    END {
        printf "# Coverage of solver/\n\nBy the unit tests, the CLI scripts of `make test` and the quick tier "
        printf "(`make coverage`, gcov + lcov; solver/ at -O0 --coverage); the runs took %d s.\n\n", secs
        printf "| | covered | total | %% |\n|---|---|---|---|\n"
        printf "| lines | %d | %d | %.2f |\n| branches | %d | %d | %.2f |\n\n", LH, LF, 100 * LH / LF, BH, BF, 100 * BH / BF
        printf "| file | lines %% | branches %% | uncovered branches |\n|---|---|---|---|\n"
        for (i = 1; i <= n; i++) {
            g = fs[i]
            printf "| %s | %.1f | %s | %d |\n", g, 100 * lh[g] / lf[g],
                   bf[g] ? sprintf("%.1f", 100 * bh[g] / bf[g]) : "-", bf[g] - bh[g]
        }
        printf "\nHTML: [index.html](index.html).\n"
        printf "%.2f %.2f\n", 100 * LH / LF, 100 * BH / BF > "/dev/stderr"
    }' "$out/solver.info" > "$out/summary.md" 2> "$cov/totals" ||
    { echo "coverage: no totals" >&2; exit 1; }
read -r lines branches < "$cov/totals"
# the floor: the larger of the target and the recorded measurement
# (tests/coverage-floor.txt: "lines N" and "branches N" lines; "target" the aim)
get() { sed -n "s/^$1[[:space:]]\{1,\}\([0-9.]\{1,\}\).*/\1/p" "$floor" | head -1; }
fl=$(get lines) fb=$(get branches) tl=$(get target_lines) tb=$(get target_branches)
verdict=$(awk -v l="$lines" -v b="$branches" -v fl="$fl" -v fb="$fb" -v tl="$tl" -v tb="$tb" 'BEGIN {
    ml = fl > tl ? fl : tl; mb = fb > tb ? fb : tb
    if (l + 0 < fl + 0 || b + 0 < fb + 0) { print "below the recorded floor"; exit }
    if (l + 0 < tl + 0 || b + 0 < tb + 0) { print "at or above the recorded floor, below the target"; exit }
    print "at or above the target" }')
{
    printf '\n**Floor** (%s): lines %s %%, branches %s %% recorded; target %s %% / %s %%. Measured: %s %% / %s %%: %s.\n' \
        "$floor" "$fl" "$fb" "$tl" "$tb" "$lines" "$branches" "$verdict"
} >> "$out/summary.md"
echo "coverage: solver/ lines $lines %, branches $branches % (runs $((t1 - t0)) s); $verdict; reports/coverage/summary.md"
case "$verdict" in below*) st=1 ;; esac
# a measured value above the recorded floor: say so (raise the file)
awk -v l="$lines" -v b="$branches" -v fl="$fl" -v fb="$fb" 'BEGIN { exit !(l - fl >= 0.5 || b - fb >= 0.5) }' &&
    echo "coverage: above the recorded floor by 0.5 points or more: raise $floor" >&2
exit $st
