#!/bin/sh
# The runner's isolation, proven: a case that aborts, one that segfaults and
# one that hangs past its time limit are each reported as that case's
# failure (with a report saying so) while the passing case still passes;
# and killing a run mid-way leaves no summary and no report for a case whose
# verdict it did not reach.
set -u
sf_name=iso
. "$(dirname "$0")/common.sh"
bin=${1:-build/slipfield}
fail=0
ok() { :; }
bad() { echo "isolation: FAIL $*" >&2; fail=1; }
SF_SELFTEST=1 "$bin" verify --jobs 2 --timeout 2 --reports "$tmp/r" tests/isolation/*.md > "$tmp/out" 2>&1
rc=$?
[ $rc -eq 1 ] || bad "verify exit $rc, expected 1"
for k in abort segv hang; do
    grep -qE "^ERROR +isolation/$k " "$tmp/out" || bad "$k not reported as ERROR"
    grep -qiE "signal|time|killed" "$tmp/r/isolation/$k/report.md" 2>/dev/null || bad "$k: no report naming the crash"
done
grep -qE "^PASS +isolation/pass " "$tmp/out" || bad "the passing case did not pass"
grep -c '<testcase' "$tmp/r/junit.xml" | grep -qx 4 || bad "junit.xml does not list the 4 cases"
# a check that produces rows but no plot is an ERROR, not a pass
SF_SELFTEST=1 "$bin" verify --jobs 1 --reports "$tmp/np" tests/noplot/noplot.md > "$tmp/np.out" 2>&1
[ $? -eq 1 ] && grep -qE "^ERROR +noplot/noplot .*no plot" "$tmp/np.out" || bad "a check without a plot was not an ERROR"
# a gnuplot warning, or a plot with nothing to draw, is a failing row naming the plot
SF_SELFTEST=1 "$bin" verify --jobs 1 --reports "$tmp/bp" tests/noplot/badplot.md > "$tmp/bp.out" 2>&1
[ $? -eq 1 ] && grep -qE "^FAIL +noplot/badplot .*plot flat_log" "$tmp/bp.out" || bad "a gnuplot warning did not fail the case"
grep -q "plot nothing_to_draw:.*no point to draw" "$tmp/bp/noplot/badplot/report.md" 2>/dev/null || bad "an empty plot did not fail the case"
grep -q "^Warning" "$tmp/bp.out" && bad "gnuplot's warning leaked to the terminal"
# kill mid-run: the hang case is in flight when the runner is killed
SF_SELFTEST=1 "$bin" verify --jobs 1 --timeout 60 --reports "$tmp/k" tests/isolation/pass.md tests/isolation/hang.md > /dev/null 2>&1 &
pid=$!
sleep 1.5
kill -TERM $pid 2>/dev/null
wait $pid 2>/dev/null
sleep 0.5
[ ! -e "$tmp/k/index.md" ] && [ ! -e "$tmp/k/junit.xml" ] || bad "a killed run left a summary"
[ ! -e "$tmp/k/isolation/hang/report.md" ] || bad "a killed run left a report for the unfinished case"
pgrep -f "reports $tmp/k" > /dev/null && bad "case processes outlived the killed runner"
ls "$tmp/k"/isolation/*/*.tmp* > /dev/null 2>&1 && bad "temporary files left behind"
[ $fail -eq 0 ] && echo "isolation: crash, abort, time-out and kill handled"
exit $fail
