#!/bin/sh
# make test: reports/results.json and the drift page, end to end, on a few
# fast cases (about a second).
#  1. a run's results.json validates against verification/results.schema.json
#     (Debian's python3-jsonschema, a real validator);
#  2. the same run again with --baseline: exit 0 and "No drift";
#  3. a baseline where one exact metric, one p-value and one verdict
#     differ: each is on the drift page, and the run still exits 0;
#  4. a case that now fails against a baseline where it passed: exit 1,
#     "to FAIL" on the page;
#  5. a missing or foreign baseline is bad input (exit 2);
#  6. a comparison whose fields form no QoI (tests/checks/no-qoi.md) fails
#     on its count of fields compared, with all its data finite;
#  7. a stored-data case (cases/plan/cellavg-calibration.md) without its
#     data, or with a malformed line, ends in ERROR naming the file (and
#     line); its stored errors doubled, or one of them NaN, fail it;
#  8. a case with claims of the paper: its claims array and the run's tally
#     in results.json agree with its claims.tsv (a header line, decimals).
# A seeded code defect that moves a metric is scripts/drift-test.sh.
set -u
bin=${1:-build/slipfield}
cd "$(dirname "$0")/.." || exit 3
py=/usr/bin/python3
sh scripts/deps.sh >/dev/null || exit 1
work=$(mktemp -d /tmp/sf-results.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok    $*"; }
bad() { fail=$((fail + 1)); echo "FAIL  $*"; }

validate() {  # validate FILE
    $py - "$1" verification/results.schema.json <<'EOF'
import json, sys, jsonschema
doc = json.load(open(sys.argv[1]))
schema = json.load(open(sys.argv[2]))
jsonschema.Draft202012Validator.check_schema(schema)
errs = sorted(jsonschema.Draft202012Validator(schema).iter_errors(doc), key=lambda e: list(e.path))
for e in errs[:5]:
    print("      %s: %s" % ("/".join(str(p) for p in e.path), e.message))
sys.exit(1 if errs else 0)
EOF
}

cases="cases/field/exact-covariance-padded.md cases/field/sampled-covariance-lrt.md cases/contact/pure-spin-polar.md"
"$bin" verify --reports "$work/a" $cases > "$work/a.log" 2>&1
rc=$?
[ $rc -eq 0 ] && ok "a first run passes" || { bad "a first run exits $rc"; cat "$work/a.log"; }
if validate "$work/a/results.json"; then ok "results.json validates against verification/results.schema.json"
else bad "results.json does not validate"; fi
grep -q 'results.json' "$work/a/index.md" && ok "the index links results.json" || bad "the index does not link results.json"

# a sweep case's statistics per point and QoI (u_num not estimated there:
# null, named in nonfinite), valid, and tabulated in its report
# one thread: under `make coverage` (-O0, --coverage) two threads spin past the
# case's CPU-time limit; the results do not depend on the thread count
OMP_NUM_THREADS=1 "$bin" verify --reports "$work/s" cases/validation/fig10-convergence.md > "$work/s.log" 2>&1
if validate "$work/s/results.json" && $py - "$work/s/results.json" <<'EOF'
import json, sys
sw = json.load(open(sys.argv[1]))["cases"][0]["sweep"]
sys.exit(not (len(sw) == 3 and all(x["u_num"] is None and x["nonfinite"]["u_num"] == "nan"
                                   and x["u_num_realisations"] == 0 and x["level"] == 0.95 for x in sw)))
EOF
then ok "a sweep case's results.json carries its points' statistics (u_num null: not estimated) and validates"
else bad "a sweep case's results.json: no valid sweep statistics"; fi
grep -q '^## Sweep statistics' "$work/s/validation/fig10-convergence/report.md" && ok "its report tabulates them" \
    || bad "its report has no sweep table"

# 8. the paper's claims: a claims array per case and the run's tally in
# results.json (valid), the same claims in claims.tsv under a header line,
# numbers in decimal
"$bin" verify --reports "$work/cl" cases/validation/quick-fig3-fields.md > "$work/cl.log" 2>&1
if validate "$work/cl/results.json" && $py - "$work/cl/results.json" "$work/cl/validation/quick-fig3-fields/claims.tsv" <<'EOF'
import csv, json, sys
d = json.load(open(sys.argv[1]))
cl = d["cases"][0]["claims"]
rows = list(csv.reader(open(sys.argv[2]), delimiter="\t", quoting=csv.QUOTE_NONE))
head = ["status", "measured", "ci_lo", "ci_hi", "alpha", "id", "text", "how", "note", "defs", "model_status",
        "model_n", "model_budget", "model_est", "model_lo", "model_hi", "model_mde", "model_alpha", "model_margin"]
ok = rows[0] == head and len(rows) == len(cl) + 1 and len(cl) >= 1
for r, c in zip(rows[1:], cl):
    ok &= r[0] == c["status"] and r[5] == c["id"] and r[6] == c["text"]
    for k, name in enumerate(["measured", "ci_lo", "ci_hi", "alpha"], 1):
        ok &= "0x" not in r[k]
        v = float(r[k])
        ok &= (c[name] is None and v != v) or c[name] == v
    ok &= r[10] == "none" and "model" not in c   # the quick case runs no model verdict
t = d["claims"]
ok &= t["total"] == len(cl) == t["confirmed"] + t["contradicted"] + t["undecided"]
ok &= t["confirmed"] == sum(c["status"] == "confirmed" for c in cl)
sys.exit(not ok)
EOF
then ok "claims: per case and tallied in results.json (valid), in claims.tsv under a header, in decimal"
else bad "claims: results.json and claims.tsv disagree, or no header, or not decimal"; cat "$work/cl/validation/quick-fig3-fields/claims.tsv"; fi
grep -q "The paper's claims in this run (1): \*\*1 confirmed\*\*" "$work/cl/index.md" && ok "the index's tally reads the new claims.tsv" \
    || bad "the index's tally: $(grep "claims in this run" "$work/cl/index.md")"

"$bin" verify --reports "$work/b" --baseline "$work/a/results.json" $cases > "$work/b.log" 2>&1
rc=$?
[ $rc -eq 0 ] && ok "the same run against itself exits 0" || bad "the same run against itself exits $rc"
grep -q 'No drift' "$work/b/drift.md" && ok "drift page: no drift" || { bad "drift reported on an unchanged run"; sed 's/^/      /' "$work/b/drift.md"; }
validate "$work/b/results.json" && ok "results.json with a baseline validates" || bad "results.json with a baseline does not validate"
grep -q 'drift.html' "$work/b/index.html" && ok "the HTML index links drift.html" || bad "the HTML index does not link drift.html"
[ -f "$work/b/drift.html" ] && ok "drift.html written" || bad "drift.html missing"

# 3. a baseline that differs in one exact metric (by 1e-9 relative, far
# above round-off, far below the tolerance), one p-value and one verdict
$py - "$work/a/results.json" "$work/c.json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
for c in d["cases"]:
    if c["id"] == "contact/pure-spin-polar":
        r = c["rows"][0]
        r["measured"] = r["measured"] * (1 + 1e-9)
    if c["id"] == "field/sampled-covariance-lrt":
        for r in c["rows"]:
            if r["kind"] == "statistical":
                r["measured"] = 1e-6
                break
    if c["id"] == "field/exact-covariance-padded":
        c["verdict"] = "fail"
json.dump(d, open(sys.argv[2], "w"))
EOF
"$bin" verify --reports "$work/c" --baseline "$work/c.json" $cases > "$work/c.log" 2>&1
rc=$?
[ $rc -eq 0 ] && ok "drift alone does not fail the run" || bad "a run with drift exits $rc"
page="$work/c/drift.md"
q=$($py -c 'import json,sys; d=json.load(open(sys.argv[1])); print([c for c in d["cases"] if c["id"]=="contact/pure-spin-polar"][0]["rows"][0]["quantity"])' "$work/a/results.json")
if grep -F "(contact/pure-spin-polar/report.md) | $q" "$page" | grep -q '| exact |'; then ok "a moved exact metric is on the drift page"
else bad "the moved exact metric is not on the drift page"; sed 's/^/      /' "$page"; fi
grep -q 'field/sampled-covariance-lrt/report.md) .*| statistical |' "$page" && ok "a moved p-value is on the drift page" || bad "the moved p-value is not on the drift page"
grep -q '| \[field/exact-covariance-padded\](field/exact-covariance-padded/report.md) | fail | \*\*pass\*\*' "$page" && ok "a verdict change is on the drift page" || bad "the verdict change is not on the drift page"
grep -q ', 2 metrics moved,' "$page" && ok "exactly the two changed rows moved" || bad "a row that did not change counted as moved (or one that did, not)"

# 4. a case that now fails where it passed: a copy of a case whose
# tolerance is tightened below its measured error
mkdir -p "$work/cases/drifttest"
cp cases/field/exact-covariance-padded.md "$work/cases/drifttest/cov.md"
"$bin" verify --reports "$work/d" "$work/cases/drifttest/cov.md" > "$work/d.log" 2>&1
sed -i 's/^tolerance = .*/tolerance = 1e-30/' "$work/cases/drifttest/cov.md"
"$bin" verify --reports "$work/e" --baseline "$work/d/results.json" "$work/cases/drifttest/cov.md" > "$work/e.log" 2>&1
rc=$?
[ $rc -eq 1 ] && ok "a verdict that changed to FAIL fails the run (exit 1)" || bad "a verdict changed to FAIL exits $rc"
grep -q '1 to FAIL or ERROR' "$work/e/drift.md" && ok "the drift page counts the change to FAIL" || bad "the drift page misses the change to FAIL"
validate "$work/e/results.json" && ok "results.json of a failing run validates" || bad "results.json of a failing run does not validate"

# 5. bad baselines
"$bin" verify --reports "$work/f" --baseline "$work/missing.json" $cases > /dev/null 2>&1
rc=$?; [ $rc -eq 2 ] && ok "a missing baseline: exit 2" || bad "a missing baseline exits $rc"
echo '{"cases": []}' > "$work/foreign.json"
"$bin" verify --reports "$work/f" --baseline "$work/foreign.json" $cases > /dev/null 2>&1
rc=$?; [ $rc -eq 2 ] && ok "a JSON file that is not a results.json: exit 2" || bad "a foreign baseline exits $rc"
"$bin" verify --reports "$work/nq" tests/checks/no-qoi.md > "$work/nq.out" 2>&1
rc=$?
if [ $rc -eq 1 ] && grep -q "FAIL  checks/no-qoi .*0 compared" "$work/nq.out" &&
   grep -q "| non-finite values .* | 0 | 0 | .* | yes |" "$work/nq/checks/no-qoi/report.md"; then
    ok "fields with no QoI: the comparison fails on its count, its data finite"
else
    bad "fields with no QoI: exit $rc, $(head -c 300 "$work/nq.out")"
fi
# 7. stored data: missing, malformed, and too small an err_cell for them
mkdir -p "$work/st/plan"
cp cases/plan/cellavg-calibration.md "$work/st/plan/"
stored() {  # stored NAME 'grep pattern for its console line' 'and for its report' WHAT
    "$bin" verify --reports "$work/$1" "$work/st/plan/cellavg-calibration.md" > "$work/$1.out" 2>&1
    rc=$?
    if [ $rc -eq 1 ] && grep -q "$2" "$work/$1.out" && grep -q "$3" "$work/$1/plan/cellavg-calibration/report.md"; then
        ok "$4"
    else
        bad "$4: exit $rc, $(head -c 300 "$work/$1.out")"
    fi
}
stored st1 "ERROR plan/cellavg-calibration" "Stored data missing.*cellavg-calibration.tsv" \
    "stored data missing: ERROR naming the file"
{ head -6 cases/plan/cellavg-calibration.tsv; printf '1\t1\t0.02\tx\t0.1\t0.5\t40\t110\t20\t1\t0.001\n'; } > "$work/st/plan/cellavg-calibration.tsv"
stored st2 "ERROR plan/cellavg-calibration" "cellavg-calibration.tsv:7: not a stored field" \
    "a malformed stored line: ERROR naming file and line"
awk -F'\t' 'BEGIN { OFS = "\t" } /^[0-9]/ { $11 = 2 * $11 } { print }' cases/plan/cellavg-calibration.tsv > "$work/st/plan/cellavg-calibration.tsv"
stored st3 "FAIL  plan/cellavg-calibration .*err_cell" "largest RMS over a point's fields / err_cell | 1.50" \
    "stored errors doubled (err_cell halved, seen from the data): FAIL"
awk -F'\t' 'BEGIN { OFS = "\t" } /^[0-9]/ && !d { $11 = "nan"; d = 1 } { print }' cases/plan/cellavg-calibration.tsv > "$work/st/plan/cellavg-calibration.tsv"
stored st4 "FAIL  plan/cellavg-calibration" "stored fields with a non-finite error | 1 " \
    "a non-finite stored error: FAIL on its count"
echo "results: $pass passed, $fail failed"
[ $fail -eq 0 ]
