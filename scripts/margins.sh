#!/bin/sh
# scripts/margins.sh [RUNS_DIR]: how close the passing cases came to their
# tolerances over a fresh-seed study (scripts/false-alarm.sh keeps each
# run's results.json as RUNS_DIR/SEED.json.gz; default
# reports/false-alarm/runs).  A case's margin is its tightest row's share
# of its allowance (verification/results.h: |diff| / tol, or alpha / p for
# a statistical row; above 1 exactly when the case fails).
#
# A count of failures bounds a rate only to about 3 / runs.  A case whose
# tolerance is meant to hold at every seed (`seed_proof`) says more through
# its margins: how far below 1 their upper tail ends.  Per such case this
# extrapolates P(margin > 1) two ways, both models stated, and keeps the
# larger:
#   lognormal   ln m ~ Normal(mean, sd) over the runs with m > 0 (times
#               their share), P = Q(-mean / sd);
#   Pareto tail the top k = max(5, n / 5) values of ln m above the next one
#               (u) taken as exponential (a Pareto tail of m, heavier than
#               the lognormal): P = (k / n) exp(u / beta), beta their mean
#               excess over u (the Hill estimator).
# A statistical case (`alpha`) spends its declared alpha (alpha / p is
# uniform-driven, not a tail to extrapolate); a pinned case draws nothing.
# Writes RUNS_DIR/../margins.tsv and margins.md; prints the summary.
set -eu
sf_name=margins; . "$(dirname "$0")/common.sh"
runs=${1:-reports/false-alarm/runs}
[ -d "$runs" ] || { echo "margins.sh: no such directory: $runs" >&2; exit 2; }
out=$(dirname "$runs")
set -- "$runs"/*.json.gz
[ -f "$1" ] || { echo "margins.sh: no runs (*.json.gz) in $runs" >&2; exit 2; }
# one line per (seed, case): seed id verdict margin (the case level of
# results.json: its keys are indented three spaces, a row's five)
for f in "$@"; do
    s=$(basename "$f" .json.gz)
    gzip -dc "$f" | awk -v s="$s" '
        /^   "id": /      { id = $2; gsub(/[",]/, "", id) }
        /^   "verdict": / { v = $2; gsub(/[",]/, "", v) }
        /^   "margin": /  { m = $2; gsub(/,/, "", m); print s "\t" id "\t" v "\t" m }'
done > "$tmp/m.tsv"
nruns=$#
# the cases in every run (run 1 holds the whole tier, the others the
# random cases only)
cut -f2 "$tmp/m.tsv" | sort | uniq -c | awk -v n="$nruns" '$1 == n { print $2 }' > "$tmp/ids"
: > "$tmp/kind"
while read -r id; do
    f=cases/$id.md
    k=none
    if [ -f "$f" ]; then
        if [ -n "$(scene_val "$f" alpha)" ]; then k="alpha=$(scene_val "$f" alpha)"
        elif [ -n "$(scene_val "$f" seed_proof)" ]; then k=seed_proof
        elif [ "$(scene_val "$f" pin_seed)" = true ]; then k=pinned; fi
    fi
    printf '%s\t%s\n' "$id" "$k" >> "$tmp/kind"
done < "$tmp/ids"
sort "$tmp/m.tsv" -k2,2 > "$tmp/ms.tsv"
awk -F'\t' -v OFS='\t' '
    function qnorm(z) { return 0.5 * erfc(z / sqrt(2)) }
    function erfc(x,   t, z, p, y) { # Numerical Recipes erfcc: relative error < 1.2e-7
        z = x < 0 ? -x : x; t = 1 / (1 + 0.5 * z)
        p = -0.82215223 + t * 0.17087277; p = 1.48851587 + t * p; p = -1.13520398 + t * p
        p = 0.27886807 + t * p; p = -0.18628806 + t * p; p = 0.09678418 + t * p
        p = 0.37409196 + t * p; p = 1.00002368 + t * p; p = -1.26551223 + t * p
        y = t * exp(-z * z + p)
        return x >= 0 ? y : 2 - y }
    NR == FNR { kind[$1] = $2; next }
    !($2 in kind) { next }
    { id = $2; n[id]++; if ($3 != "pass") fail[id]++
      if ($4 != "null" && $4 + 0 > 0) { np[id]++; L[id, np[id]] = log($4 + 0) }
      if ($4 != "null" && $4 + 0 > mx[id]) mx[id] = $4 + 0 }
    END {
      print "case", "kind", "runs", "failures", "max_margin", "runs_margin_gt0", "p_lognormal", "p_pareto", "p_tail"
      for (id in n) {
        pl = "-"; pp = "-"; pt = "-"
        m = np[id] + 0
        if (kind[id] == "seed_proof" && m >= 10) {
            s = 0; ss = 0
            for (i = 1; i <= m; i++) { s += L[id, i]; ss += L[id, i] ^ 2 }
            mu = s / m; sd = sqrt((ss - m * mu * mu) / (m - 1))
            pl = sd > 0 ? (m / n[id]) * qnorm(-mu / sd) : (mu > 0)
            # sort the log margins (insertion: a few hundred at most)
            for (i = 1; i <= m; i++) a[i] = L[id, i]
            for (i = 2; i <= m; i++) { x = a[i]; j = i - 1; while (j >= 1 && a[j] > x) { a[j + 1] = a[j]; j-- } a[j + 1] = x }
            k = int(n[id] / 5); if (k < 5) k = 5; if (k > m - 1) k = m - 1
            u = a[m - k]; b = 0
            for (i = m - k + 1; i <= m; i++) b += a[i] - u
            b /= k
            pp = (b > 0) ? (k / n[id]) * exp(u / b) : 0
            if (pp > k / n[id]) pp = k / n[id]
            pt = pl > pp ? pl : pp
            pl = sprintf("%.2g", pl); pp = sprintf("%.2g", pp); pt = sprintf("%.2g", pt)
        }
        print id, kind[id], n[id], fail[id] + 0, sprintf("%.3g", mx[id]), m, pl, pp, pt
      }
    }' "$tmp/kind" "$tmp/ms.tsv" | { read -r h; echo "$h"; sort; } > "$out/margins.tsv"
awk -F'\t' 'NR > 1 && $9 != "-" { s += $9; n++; if ($9 > w) { w = $9; wc = $1 } }
     NR > 1 && $2 ~ /^alpha=/ { na++ }
     NR > 1 && $4 > 0 { f += $4 }
     END { printf "%d runs; %d seed_proof cases: extrapolated false-alarm probability %.2g in all (largest %.2g, %s); %d statistical cases (their share of the budget: the index ledger); %d case failures\n",
           '"$nruns"', n, s, w, (wc == "" ? "-" : wc), na, f }' "$out/margins.tsv" > "$out/margins-summary.txt"
{
    echo "# Margins of the random cases across fresh seeds"
    echo
    echo "$(cat "$out/margins-summary.txt")"
    echo
    echo "A case's margin is its tightest row's share of its allowance (above 1: it fails). For a case whose"
    echo "tolerance is meant to hold at every seed (seed_proof), the upper tail of its margins over the runs is"
    echo "extrapolated to P(margin > 1): a lognormal fit of ln m, and a Pareto tail (the Hill estimator on the"
    echo "top fifth, at least 5 values), the larger kept (p_tail). Both are models of the tail beyond the"
    echo "runs, not counts: they say which seed_proof claims are comfortable and which sit near their edge."
    echo "A statistical case spends its declared alpha."
    echo
    echo "| case | kind | runs | failures | max margin | runs with margin > 0 | P lognormal | P Pareto tail | P(margin > 1) |"
    echo "|---|---|---|---|---|---|---|---|---|"
    awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9 }' "$out/margins.tsv"
} > "$out/margins.md"
cat "$out/margins-summary.txt"
