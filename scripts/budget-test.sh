#!/bin/sh
# The runner's selection and its false-alarm budget, proven (make test):
# a selection that matches nothing (--only, --tags, a tier, a CASES glob)
# exits 2 with a message; each case's time limit is scaled from its
# recorded time (cases/times.tsv); a case whose only failure is a suspect
# p-value is replicated on a fresh stream (and passes when that passes),
# one below the floor fails at once; the index states the budget.
set -u
sf_name=budget
. "$(dirname "$0")/common.sh"
bin=${1:-build/slipfield}
fail=0
bad() { echo "budget-test: FAIL $*" >&2; fail=1; }
none() {   # none WHAT ARGS...: verify selects no case: exit 2 and a message
    what=$1; shift
    "$bin" verify --reports "$tmp/none" "$@" > /dev/null 2> "$tmp/err"; rc=$?
    [ $rc -eq 2 ] || bad "$what: exit $rc, expected 2"
    grep -qE "no case selected|cannot open" "$tmp/err" || bad "$what: no message ($(head -c 200 "$tmp/err"))"
    [ ! -e "$tmp/none/index.md" ] || bad "$what: wrote an index"
}
none "--only zzz" --only zzz cases/field/*.md
none "--tags nope" --tags nope cases/field/*.md
none "--tier paper on quick cases" --tier paper cases/field/*.md
none "a CASES glob matching nothing" 'cases/zzz*.md'
# time limits: CPU time 20x the recorded, at least 60 s; --timeout (wall) turns them off
"$bin" verify --list cases/field/exact-covariance-minimal.md | grep -q ' cpu_limit=60s wall_limit=900s$' ||
    bad "a fast case's CPU limit is not 60 s"
t=$(awk -F'\t' '$1 == "limits/large-lr-variable" { print $2 }' cases/times.tsv)
lim=$("$bin" verify --list cases/limits/large-lr-variable.md | sed -n 's/.* cpu_limit=\([0-9]*\)s .*/\1/p')
[ -n "$t" ] && [ -n "$lim" ] && awk -v t="$t" -v l="$lim" 'BEGIN { exit !(l >= 20 * t && l < 20 * t + 1 && l >= 60) }' ||
    bad "large-lr-variable: CPU limit '$lim' s is not 20x its recorded '$t' s"
"$bin" verify --timeout 7 --list cases/limits/large-lr-variable.md | grep -q ' cpu_limit=0s wall_limit=7s$' ||
    bad "--timeout does not replace the CPU limits"
# a case that spins past its CPU limit is stopped and says so (a 1 s limit
# from a table next to the test case)
mkdir -p "$tmp/c/spin"
cp tests/isolation/hang.md "$tmp/c/spin/spin.md"
sed -i 's/^check = selftest_hang$/check = selftest_spin/' "$tmp/c/spin/spin.md"
printf 'spin/spin\t0.01\n' > "$tmp/c/times.tsv"
SF_SELFTEST=1 SF_CASETIME_FLOOR=1 "$bin" verify --reports "$tmp/spin" "$tmp/c/spin/spin.md" > "$tmp/spin.out" 2>&1
grep -qE '^ERROR +spin/spin .*CPU-time limit of 1 s' "$tmp/spin.out" || bad "a spinning case was not stopped at its CPU limit: $(head -c 300 "$tmp/spin.out")"
# replication: seed 7 suspect then passes, seed 742 below the floor
SF_SELFTEST=1 "$bin" verify --reports "$tmp/r" tests/budget/*.md > "$tmp/out" 2>&1
[ $? -eq 1 ] || bad "the budget selftests: exit status, expected 1"
grep -qE '^PASS +budget/suspect ' "$tmp/out" || bad "a suspect p whose replication passes did not pass"
grep -q 'Replication.*At seed 7 ' "$tmp/r/budget/suspect/report.md" || bad "the replicated case's report does not say so"
grep -qE '^FAIL +budget/floor ' "$tmp/out" || bad "a p below the floor did not fail"
grep -q 'Replication' "$tmp/r/budget/floor/report.md" && bad "a p below the floor was replicated"
grep -qE '^PASS +budget/replicate ' "$tmp/out" || bad "a replicated deterministic row whose replication passes did not pass"
grep -q 'Replication.*At seed 7 .*with `replicate`' "$tmp/r/budget/replicate/report.md" ||
    bad "the replicated deterministic row's report does not say so"
grep -qE '^FAIL +budget/no-replicate ' "$tmp/out" || bad "a failing deterministic row without replicate did not fail"
grep -q 'Replication' "$tmp/r/budget/no-replicate/report.md" && bad "a deterministic row without replicate was replicated"
grep -qF '| [budget/replicate](budget/replicate/report.md) | statistical (replicate) | 0 | 0 | 0.5 | 0.25 | **yes** |' \
    "$tmp/r/index.md" || bad "the budget table's row for the replicated deterministic case (share alpha^2)"
grep -q '^## False-alarm budget' "$tmp/r/index.md" || bad "the index states no budget"
grep -qF '| [budget/suspect](budget/suspect/report.md) | statistical | 1 | 0.5 | 0.5 | 0.255 | **yes** |' "$tmp/r/index.md" ||
    bad "the budget table's row for the replicated case"
[ $fail -eq 0 ] && echo "budget-test: empty selections exit 2, time limits scaled, suspect p and replicate rows replicated, budget stated"
exit $fail
