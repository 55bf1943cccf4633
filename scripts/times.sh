#!/bin/sh
# sh scripts/times.sh [RESULTS.json...]: record each case's CPU time from
# one or more runs' results.json (default reports/results.json) into
# cases/times.tsv, the table `slipfield verify` scales each case's
# CPU-time limit from (20x, at least 60 s: verification/casetime.h).  Cases the
# given runs do not hold keep their recorded time; a case that appears in
# several runs keeps its largest time.  Run it after a change that makes
# a case much slower (or faster) on purpose, and commit the table.
set -eu
cd "$(dirname "$0")/.."
[ $# -gt 0 ] || set -- reports/results.json
python3 - "$@" <<'PY'
import json, os, sys
path = "cases/times.tsv"
times = {}
if os.path.exists(path):
    for line in open(path):
        if line.strip() and not line.startswith("#"):
            k, v = line.rstrip("\n").split("\t")
            times[k] = float(v)
new = {}
for f in sys.argv[1:]:
    for c in json.load(open(f))["cases"]:
        if c.get("verdict") in ("pass", "fail") and c.get("cpu_seconds") is not None:
            new[c["id"]] = max(new.get(c["id"], 0.0), c["cpu_seconds"])
times.update(new)
ids = sorted(k for k in times if os.path.exists("cases/%s.md" % k))
tmp = path + ".tmp"
with open(tmp, "w") as g:
    g.write("# Recorded CPU time [s] of each case (scripts/times.sh from a run's results.json).\n")
    g.write("# slipfield verify stops a case at max(60 s, 20x this) of CPU time: a hang costs a minute.\n")
    for k in ids:
        g.write("%s\t%.3g\n" % (k, times[k]))
os.replace(tmp, path)
print("%s: %d cases (%d from %s)" % (path, len(ids), len(new), " ".join(sys.argv[1:])))
PY
