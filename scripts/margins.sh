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
# its margins: how far below 1 their upper tail ends.  Per row of such a
# case whose margin moves with the seed (a row at the same margin in every
# run does not depend on it) this extrapolates P(margin > 1) two ways, both
# models stated, and keeps the larger; the case's is the sum over its rows:
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
# per run: the case level (C seed id verdict margin) and every row
# (R seed id row margin) of results.json: a case's keys are indented
# three spaces, a row's five
for f in "$@"; do
    s=$(basename "$f" .json.gz)
    gzip -dc "$f" | awk -v s="$s" -v OFS='\t' '
        /^   "id": /         { id = $2; gsub(/[",]/, "", id); row = 0 }
        /^   "verdict": /    { v = $2; gsub(/[",]/, "", v) }
        /^   "margin": /     { m = $2; gsub(/,/, "", m); print "C", s, id, v, m }
        /^     "quantity": / { row++ }
        /^     "margin": /   { m = $2; gsub(/,/, "", m); print "R", s, id, row, m }'
done > "$tmp/m.tsv"
nruns=$#
# the cases in every run (run 1 holds the whole tier, the others the
# random cases only)
awk -F'\t' '$1 == "C" { print $3 }' "$tmp/m.tsv" | sort | uniq -c | awk -v n="$nruns" '$1 == n { print $2 }' > "$tmp/ids"
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
# per seed_proof case, per row whose margin moves with the seed (a row at
# the same margin in every run does not depend on it: a count against its
# own bound, a planted value), the two tail fits; the case's chance is the
# sum over its rows (Bonferroni)
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
    !($3 in kind) { next }
    $1 == "C" { id = $3; n[id]++; if ($4 != "pass") fail[id]++; if ($5 != "null" && $5 + 0 > mx[id]) mx[id] = $5 + 0; next }
    $1 == "R" && $5 != "null" { k = $3 SUBSEP $4; rn[k]++; rv[k, rn[k]] = $5 + 0; rows[$3] = rows[$3] " " $4 }
    END {
      print "case", "kind", "runs", "failures", "max_margin", "seed_rows", "max_seed_margin", "p_lognormal", "p_pareto", "p_tail"
      for (id in n) {
        pl = "-"; pp = "-"; pt = "-"; nsr = "-"; msm = "-"
        if (kind[id] == "seed_proof") {
            split(rows[id], rl, " "); delete seen; nsr = 0; msm = 0; sl = 0; sp = 0; st = 0; fitted = 0
            for (q in rl) {
                r = rl[q]; if (r in seen) continue; seen[r] = 1
                k = id SUBSEP r; m = rn[k]
                if (m < 10) continue
                lo = hi = rv[k, 1]
                for (i = 2; i <= m; i++) { if (rv[k, i] < lo) lo = rv[k, i]; if (rv[k, i] > hi) hi = rv[k, i] }
                if (hi - lo <= 1e-12 * hi) continue   # the same in every run
                nsr++; if (hi > msm) msm = hi
                c = 0; s1 = 0; s2 = 0
                for (i = 1; i <= m; i++) if (rv[k, i] > 0) { c++; a[c] = log(rv[k, i]); s1 += a[c]; s2 += a[c] ^ 2 }
                if (c < 10) continue
                fitted = 1
                mu = s1 / c; sd = sqrt((s2 - c * mu * mu) / (c - 1))
                rl_p = sd > 0 ? (c / m) * qnorm(-mu / sd) : (mu > 0)
                for (i = 2; i <= c; i++) { x = a[i]; j = i - 1; while (j >= 1 && a[j] > x) { a[j + 1] = a[j]; j-- } a[j + 1] = x }
                kk = int(m / 5); if (kk < 5) kk = 5; if (kk > c - 1) kk = c - 1
                u = a[c - kk]; b = 0
                for (i = c - kk + 1; i <= c; i++) b += a[i] - u
                b /= kk
                rp_p = (b > 0) ? (kk / m) * exp(u / b) : 0
                if (rp_p > kk / m) rp_p = kk / m
                sl += rl_p; sp += rp_p; st += (rl_p > rp_p ? rl_p : rp_p)
            }
            if (fitted) { pl = sprintf("%.2g", sl); pp = sprintf("%.2g", sp); pt = sprintf("%.2g", st) }
            msm = sprintf("%.3g", msm)
        }
        print id, kind[id], n[id], fail[id] + 0, sprintf("%.3g", mx[id]), nsr, msm, pl, pp, pt
      }
    }' "$tmp/kind" "$tmp/m.tsv" | { read -r h; echo "$h"; sort; } > "$out/margins.tsv"
awk -F'\t' 'NR > 1 && $10 != "-" { s += $10; n++; if ($10 > w) { w = $10; wc = $1 } }
     NR > 1 && $2 ~ /^alpha=/ { na++ }
     NR > 1 && $4 > 0 { f += $4 }
     END { printf "%d runs; %d seed_proof cases with rows that move with the seed: extrapolated false-alarm probability %.2g in all (largest %.2g, %s); %d statistical cases (their share of the budget: the index ledger); %d case failures\n",
           '"$nruns"', n, s, w, (wc == "" ? "-" : wc), na, f }' "$out/margins.tsv" > "$out/margins-summary.txt"
{
    echo "# Margins of the random cases across fresh seeds"
    echo
    echo "$(cat "$out/margins-summary.txt")"
    echo
    echo "A case's margin is its tightest row's share of its allowance (above 1: it fails). For a case whose"
    echo "tolerance is meant to hold at every seed (seed_proof), each row whose margin moves with the seed has"
    echo "the upper tail of its margins over the runs extrapolated to P(margin > 1): a lognormal fit of ln m,"
    echo "and a Pareto tail (the Hill estimator on the top fifth, at least 5 values), the larger kept; the"
    echo "case's P is the sum over those rows. Both are models of the tail beyond the runs, not counts, and"
    echo "at a few tens of runs they are rough: they say which seed_proof claims are comfortable and which"
    echo "sit near their edge."
    echo "A statistical case spends its declared alpha."
    echo
    echo "| case | kind | runs | failures | max margin | rows that move with the seed | their max margin | P lognormal | P Pareto tail | P(margin > 1) |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
    awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10 }' "$out/margins.tsv"
} > "$out/margins.md"
cat "$out/margins-summary.txt"
