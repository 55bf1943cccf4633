#!/bin/sh
# make verify SEED=random REPEAT=N: rerun the tier (quick unless
# TIER=full or paper) N times with fresh seeds; report the family-wise
# rate (runs in which any case failed, as CI sees it) with its exact
# one-sided 95% upper bound against the tier's false-alarm budget (the
# index states it: verification/budget.h), the runs, their time and the
# revision; and measure how often each case that draws random numbers fails.  A case with `alpha` should fail about
# alpha N times (its nominal false-alarm rate); a case without alpha gates
# a random quantity deterministically (a count, a fitted order on one
# realisation) and has no stated rate: any failure there is reported.
# Which cases draw random numbers is measured, not declared: every
# candidate runs once with --seed 1 and once with --seed 2, and a case
# whose results table or findings differ between the two draws random
# numbers that reach its verdict (reports/false-alarm/random-cases.txt),
# unless they differ again at --seed 1 run twice (a timed FFTW plan:
# reports/false-alarm/unrepeatable-cases.txt; rerun like the random ones).
# Run 1 is the whole tier; runs 2..N rerun only those random cases.  That
# is the same family-wise rate: a case that draws no random numbers
# computes the same bits, hence gives the same verdict, at every seed (a
# case's seed is mixed from --seed and its id, so a subset run gives each
# case the seed it has in the whole tier), so run i of the tier fails
# exactly when run i of the random cases fails or run 1's other cases
# did; their verdicts are carried over from run 1.  A long study then
# costs the random cases' time a run, not the tier's.
# CASES='...' limits the candidates; ALL_RANDOM=1 skips the detection
# and reruns every candidate every run (the paper tier, whose cases all
# draw fields: the detection would cost three runs of the tier);
# `touch reports/false-alarm/stop`
# ends a long study after the current run, with the report of the runs
# done.  Run i uses --seed SEED0 + i (SEED0=N in the environment;
# default: from the clock, so each study draws fresh seeds) and the report lists, per case, the seeds that failed
# (a failure is reproducible with `slipfield verify --seed S CASE`), a
# one-sided 95% Clopper-Pearson upper bound on the failure rate, and
# P(X >= failures) for X ~ Binomial(runs, alpha): below 0.05 the case fails
# more often than its alpha allows.  Writes reports/false-alarm/report.md
# and a gnuplot plot.  Many more failures than alpha N means a flaky (or
# wrong) check; mutants (make mutants) and make power show it is not
# toothless.
set -eu
N=${1:-20}
TIER=${2:-quick}
JOBS=${3:-2}
BIN=${SLIPFIELD:-build/slipfield}   # a copy keeps a long study safe from rebuilds
SEED0=${SEED0:-$(( $(date +%s) % 1000000 * 1000 ))}
sf_name=fa; . "$(dirname "$0")/common.sh"
out=reports/false-alarm
mkdir -p "$out"
rm -rf "$out/runs" "$out/stop"
mkdir -p "$out/runs"
cand=""
for f in ${CASES:-cases/*/*.md}; do
    in_tier "$f" "$TIER" || continue
    cand="$cand $f"
done
# which candidates draw random numbers: two seeds, compare the results
t_detect=$(date +%s)
if [ "${ALL_RANDOM:-0}" = 1 ]; then
    # declared, not measured: every candidate counts as drawing random numbers
    mkdir -p "$tmp/s1" "$tmp/s2"
else
"$BIN" verify --seed 1 --jobs "$JOBS" --tier "$TIER" --reports "$tmp/s1" $cand > /dev/null 2>&1 || true
"$BIN" verify --seed 2 --jobs "$JOBS" --tier "$TIER" --reports "$tmp/s2" $cand > /dev/null 2>&1 || true
fi
# a report's results, less its timings (a table column whose header, or a
# line that, names CPU or wall time): they differ from run to run and say
# nothing of the seed
body() {
    sed -n '/^## Results/,/^## Plots/p' "$1" 2>/dev/null | awk -F'|' -v OFS='|' '
        !/^\|/ { hdr = ""; if (!/CPU|wall time/) print; next }
        hdr == "" { hdr = $0; delete t; for (i = 1; i <= NF; i++) if ($i ~ /CPU|wall time/) t[i] = 1 }
        { for (i in t) $i = " "; print }' || true
}
differ=""
for f in $cand; do
    id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
    body "$tmp/s1/$id/report.md" > "$tmp/b1"
    body "$tmp/s2/$id/report.md" > "$tmp/b2"
    cmp -s "$tmp/b1" "$tmp/b2" || differ="$differ $f"
done
[ "${ALL_RANDOM:-0}" != 1 ] || differ="$cand"
# a case whose results differ at the same seed (a timed FFTW plan:
# fftw_planner = measure keeps whichever algorithm timed fastest) is not
# told apart from one that draws random numbers by two seeds: seed 1 again
# on the cases that differed sorts them.  Both kinds rerun every run (the
# verdict of neither can be carried over); only the first is listed as
# drawing random numbers, the other in unrepeatable-cases.txt.
[ -z "$differ" ] || [ "${ALL_RANDOM:-0}" = 1 ] || "$BIN" verify --seed 1 --jobs "$JOBS" --tier "$TIER" --reports "$tmp/s1b" $differ > /dev/null 2>&1 || true
cases="$differ"
: > "$out/random-cases.txt"
: > "$out/unrepeatable-cases.txt"
for f in $differ; do
    id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
    body "$tmp/s1/$id/report.md" > "$tmp/b1"
    body "$tmp/s1b/$id/report.md" > "$tmp/b2"
    if cmp -s "$tmp/b1" "$tmp/b2"; then
        echo "$f" >> "$out/random-cases.txt"
    else
        echo "$f" >> "$out/unrepeatable-cases.txt"
    fi
done
t_detect=$(( $(date +%s) - t_detect ))
# the tier's family-wise rate (a run fails when any case fails, as CI sees
# it): run 1 is every case of the tier; runs 2..N the random cases, with
# the verdicts of the others carried over from run 1 (see the top)
# the revision the binary was built from (a copy may predate the tree)
rev=$("$BIN" --version 2>/dev/null | sed -n '1s/.*(\(.*\)).*/\1/p')
[ -n "$rev" ] || rev=unknown
git diff --quiet HEAD -- cases 2>/dev/null || rev="$rev (cases with local changes)"
t_start=$(date +%s)
: > "$tmp/runs.tsv"
i=0
while [ $i -lt "$N" ]; do
    seed=$((SEED0 + i + 1))
    rc=0
    t0=$(date +%s)
    if [ $i -eq 0 ]; then
        "$BIN" verify --seed $seed --jobs "$JOBS" --tier "$TIER" --reports "$tmp/r" $cand > "$tmp/run$i.log" 2>&1 || rc=$?
        cp "$tmp/r/index.md" "$tmp/index-full.md" 2>/dev/null || true
        # the verdicts later runs carry over: failures of the cases that draw no random numbers
        grep -E '^(FAIL|ERROR) ' "$tmp/run0.log" | awk '{ print $2 }' | while read -r id; do
            echo " $cases " | grep -qF " cases/$id.md " || echo "$id"
        done > "$tmp/fixed-fails" || true
        nfix=$(wc -l < "$tmp/fixed-fails" | tr -d ' ')
    elif [ -n "$cases" ]; then
        "$BIN" verify --seed $seed --jobs "$JOBS" --tier "$TIER" --reports "$tmp/r" $cases > "$tmp/run$i.log" 2>&1 || rc=$?
        [ "$nfix" -eq 0 ] || [ "$rc" -ne 0 ] || rc=1
    else
        cp "$tmp/run0.log" "$tmp/run$i.log"; rc=$(sed -n '1p' "$tmp/runs.tsv" | cut -f2)
    fi
    nf=$(grep -cE '^(FAIL|ERROR) ' "$tmp/run$i.log" || true)
    [ $i -eq 0 ] || nf=$((nf + nfix))
    nrep=$(grep -c '| \*\*yes\*\* |$' "$tmp/r/index.md" 2>/dev/null || true)
    printf '%s\t%s\t%s\t%s\t%s\n' "$seed" "$rc" "$nf" "${nrep:-0}" "$(( $(date +%s) - t0 ))" >> "$tmp/runs.tsv"
    echo "$seed" > "$tmp/seed$i"
    # each run's results.json (every case's margin: how close each passing
    # case came to its tolerance), for a margin study across seeds
    [ ! -f "$tmp/r/results.json" ] || gzip -c "$tmp/r/results.json" > "$out/runs/$seed.json.gz"
    # every failing row (gate) of every case in this run, for the per-gate table
    for f in $cases; do
        id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
        [ -f "$tmp/r/$id/report.md" ] || continue
        grep -F '| **no** |' "$tmp/r/$id/report.md" | awk -F' \\| ' -v s="$seed" -v c="$id" '{ q = $1; sub(/^\| /, "", q); gsub(/, n = [0-9]+/, "", q); gsub(/ \(n = [0-9]+\)/, "", q); print s "\t" c "\t" q }' >> "$tmp/failrows.tsv" || true
    done
    i=$((i + 1))
    [ -t 2 ] && printf '\rfalse-alarm: %d/%d runs' "$i" "$N" >&2
    # `touch reports/false-alarm/stop` ends a long study after this run,
    # with the report of the runs done
    if [ -e "$out/stop" ]; then rm -f "$out/stop"; N=$i; fi
done
[ -t 2 ] && echo >&2
# per case: failures over N, nominal alpha from the scene
{
    echo "case	alpha	failures	runs	failing_seeds"
    for f in $cases; do
        id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
        a=$(scene_val "$f" alpha)
        [ -n "$a" ] || a=-
        k=0; fs=""
        i=0
        while [ $i -lt "$N" ]; do
            if grep -qE "^(FAIL|ERROR) +$id " "$tmp/run$i.log"; then
                k=$((k + 1)); fs="$fs$(cat "$tmp/seed$i") "
            fi
            i=$((i + 1))
        done
        echo "$id	$a	$k	$N	${fs:--}"
    done
} > "$out/rates.tsv"
# one-sided 95% Clopper-Pearson upper bound on the rate (k failures in n:
# the p with P(X <= k; n, p) = 0.05, by bisection) and the binomial tail
# P(X >= k; n, alpha) (below 0.05: more failures than alpha allows)
binom='function lcdf(k, n, p,   j, s, t) { s = 0; for (j = 0; j <= k; j++) { t = lgam(n + 1) - lgam(j + 1) - lgam(n - j + 1);
           if (p > 0) t += j * log(p); else if (j > 0) continue; if (p < 1) t += (n - j) * log(1 - p); else if (n > j) continue; s += exp(t) } return s }
       function lgam(x,   r) { r = 0; while (x < 8) { r -= log(x); x++ } return r + (x - 0.5) * log(x) - x + 0.918938533204673 + 1 / (12 * x) - 1 / (360 * x * x * x) }
       function utail(k, n, p,   j, s) { s = 0; for (j = k; j <= n; j++) s += exp(lgam(n + 1) - lgam(j + 1) - lgam(n - j + 1) + j * log(p) + (n - j) * log(1 - p)); return s }
       function upper(k, n,   lo, hi, m, i) { if (k >= n) return 1; lo = 0; hi = 1; for (i = 0; i < 60; i++) { m = (lo + hi) / 2; if (lcdf(k, n, m) > 0.05) lo = m; else hi = m } return hi }'
awk -F'\t' -v OFS='\t' "$binom"'
     NR == 1 { print $0, "upper95", "p_tail"; next }
     { u = upper($3, $4); t = ($2 == "-" || $3 == 0) ? "-" : sprintf("%.3g", utail($3, $4, $2));
       print $0, sprintf("%.3g", u), t }' "$out/rates.tsv" > "$tmp/rates2.tsv"
mv "$tmp/rates2.tsv" "$out/rates.tsv"
awk -F'\t' 'NR > 1 && $2 != "-" { n++; f += $3; ea += $2 * $4; r += $4 }
     NR > 1 && $2 == "-" { m++; g += $3; rr += $4 }
     END { printf "%d statistical cases (alpha) x %d runs: %d failures, expected at most %.2f (sum of alpha x runs)\n", n, r / (n ? n : 1), f, ea;
           printf "%d random cases without alpha x %d runs: %d failures (no stated rate: each is a finding)\n", m, rr / (m ? m : 1), g }' \
    "$out/rates.tsv" > "$out/summary.txt"
# the family-wise rate of the tier: runs that failed (any case), its exact
# one-sided 95% upper bound, against the budget the index states
t_total=$(( $(date +%s) - t_start ))
spent=$(sed -n 's/.*\*\*Budget \([0-9.e-]*\); spent \([0-9.e-]*\)\*\*.*/\1 \2/p' "$tmp/index-full.md" 2>/dev/null | head -n 1)
undeclared=""
for f in $(cat "$out/random-cases.txt"); do
    [ -n "$(scene_val "$f" alpha)$(scene_val "$f" seed_proof)" ] || [ "$(scene_val "$f" pin_seed)" = true ] ||
        undeclared="$undeclared ${f#cases/}"
done
cp "$tmp/runs.tsv" "$out/runs.tsv"
awk -F'\t' -v N="$N" -v T="$t_total" -v td="$t_detect" -v rev="$rev" -v tier="$TIER" -v spent="${spent:-? ?}" -v s0="$SEED0" "$binom"'
     { k += ($2 != 0); nc += $3; nr += $4; if ($2 != 0 && $2 != 1) odd++ }
     END { split(spent, b, " "); u = upper(k, N);
           printf "Tier %s, revision %s: %d of %d fresh-seed runs failed (rate %.3g; one-sided 95%% Clopper-Pearson upper bound %.3g); budget %s, spent by the declared shares %s: %s\n",
                  tier, rev, k, N, k / N, u, b[1], b[2],
                  u <= b[1] ? "the measured rate is shown within the budget" : (k / N <= b[1] ? "within the budget so far, not yet shown (the bound needs more runs: 0 failures in 299 runs bound it by 0.01)" : "the measured rate EXCEEDS the budget");
           printf "%d case failures in all, %d case replications; %d runs, %d s (%.1f s a run: the whole tier once in %d s, then the random cases in %.1f s a run; finding the random cases took %d s more), seeds %d .. %d%s\n",
                  nc, nr, N, T, T / N, t1, (N > 1 ? (T - t1) / (N - 1) : 0), td, s0 + 1, s0 + N, odd ? sprintf("; %d runs ended with an exit status other than 0 or 1", odd) : "" }
     NR == 1 { t1 = $5 }' \
    "$out/runs.tsv" > "$out/family.txt"
[ ! -s "$tmp/fixed-fails" ] || echo "cases that draw no random numbers and failed in run 1 (so in every run): $(tr '\n' ' ' < "$tmp/fixed-fails")" >> "$out/family.txt"
[ -z "$undeclared" ] || echo "random cases that declare neither alpha, seed_proof nor pin_seed (outside the budget):$undeclared" >> "$out/family.txt"
[ ! -s "$out/unrepeatable-cases.txt" ] || echo "cases whose results vary at a fixed seed (rerun every run, verdicts not carried over; whether a seed reaches them is not measured): $(tr '\n' ' ' < "$out/unrepeatable-cases.txt")" >> "$out/family.txt"
cat "$out/family.txt" "$out/summary.txt" > "$tmp/sum2" && mv "$tmp/sum2" "$out/summary.txt"
awk -F'\t' 'NR > 1 { print NR - 1, ($3 / $4), ($2 == "-" ? "NaN" : $2) }' "$out/rates.tsv" > "$tmp/plot.dat"
gnuplot <<GP
set terminal pngcairo size 900,500 font "DejaVu Sans,10" noenhanced
set output "$out/false_alarm.png"
set title "Measured false-alarm rate per random case ($N runs, fresh seeds)"
set xlabel "case (index in the table) [-]"
set ylabel "failure rate [-]"
set logscale y
set yrange [1e-4:1]
set key top left
plot "$tmp/plot.dat" using 1:(\$2 > 0 ? \$2 : 1e-4) with points pt 7 title "measured (0 drawn at 1e-4)", \
     "$tmp/plot.dat" using 1:3 with steps title "nominal alpha of the case"
GP
{
    echo "# False-alarm rate of the statistical checks"
    echo
    echo "## The tier, family-wise"
    echo
    echo "Each run is one \`slipfield verify --seed S --tier $TIER\` of every case of the tier, as CI runs it; a run"
    echo "fails when any case fails. The first run is the whole tier; the others run only the cases that draw"
    echo "random numbers (random-cases.txt), and those whose results vary at a fixed seed (unrepeatable-cases.txt),"
    echo "and carry over the first run's verdicts of the rest, which compute the same bits at any seed: the same"
    echo "family-wise rate at the random cases' cost. The index of each run"
    echo "states the tier's false-alarm budget and how its cases spend it; the measured rate and its exact"
    echo "(Clopper-Pearson) upper bound are set against it here."
    echo
    sed 's/^/- /' "$out/family.txt"
    echo
    echo "| seed | verify exit status | cases failed | cases replicated | time [s] |"
    echo "|---|---|---|---|---|"
    awk -F'\t' '{ printf "| %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5 }' "$out/runs.tsv"
    echo
    echo "## Per case"
    echo
    if [ "${ALL_RANDOM:-0}" = 1 ]; then
        echo "Each case of tier $TIER (ALL_RANDOM=1: every case declared to draw random numbers, not detected)"
        echo "re-run $N times with fresh random seeds"
    else
        echo "Each case that draws random numbers (tier $TIER; found by running every case with two seeds and"
        echo "comparing results, then the first seed again: random-cases.txt, unrepeatable-cases.txt) re-run $N times with fresh random seeds"
    fi
    echo "(\`slipfield verify --seed random\`). A case's nominal false-alarm rate is its alpha (tests"
    echo "within a case are Bonferroni-combined, so the case-level rate is at most alpha); a case with"
    echo "alpha '-' states no rate (a deterministic gate on a random quantity): any failure is a finding."
    echo
    cat "$out/summary.txt"
    echo
    echo "Seeds: run i used \`--seed $((SEED0 + 1))\` .. \`--seed $((SEED0 + N))\` (SEED0 = $SEED0). Upper 95%: one-sided"
    echo "Clopper-Pearson bound on the failure rate; P(X >= k): the chance of at least this many failures if"
    echo "the case failed at exactly its alpha (below 0.05: it fails more often than its alpha allows)."
    echo
    echo "| case | seeds | failures | alpha | upper 95% bound on the rate | P(X >= k) at alpha | failing seeds |"
    echo "|---|---|---|---|---|---|---|"
    awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $4, $3, $2, $6, $7, $5 }' "$out/rates.tsv"
    echo
    echo "A claims case gates several claims, each at its alpha (not corrected: each claim is its own"
    echo "question), so its case-level rate may reach alpha times its gates. Per gate (the failing rows,"
    echo "each compared with the case's alpha):"
    echo
    echo "| case | gate (row) | failures | runs | alpha | P(X >= k) at alpha | seeds |"
    echo "|---|---|---|---|---|---|---|"
    if [ -s "$tmp/failrows.tsv" ]; then
        awk -F'\t' -v OFS='\t' 'NR == FNR { if (FNR > 1) a[$1] = $2; next }
             { k = $2 SUBSEP $3; n[k]++; sd[k] = sd[k] $1 " " } END { for (k in n) { split(k, p, SUBSEP); print p[1], p[2], n[k], a[p[1]], sd[k] } }' \
            "$out/rates.tsv" "$tmp/failrows.tsv" | sort | awk -F'\t' -v N="$N" "$binom"'
             { t = ($4 == "-" || $4 == "") ? "-" : sprintf("%.3g", utail($3, N, $4));
               printf "| %s | %s | %d | %d | %s | %s | %s |\n", $1, $2, $3, N, $4, t, $5 }'
    else
        echo "| (none) | | 0 | $N | | | |"
    fi
    echo
    echo "![false-alarm rates](false_alarm.png)"
} > "$out/report.md.tmp"
mv "$out/report.md.tmp" "$out/report.md"
# how close the passing cases came: margins.md (each seed_proof case's tail)
if sh "$(dirname "$0")/margins.sh" "$out/runs" > "$tmp/margins.out" 2>&1; then
    { echo; echo "## Margins"; echo; sed 's/^/- /' "$tmp/margins.out"; echo "- Per case: [margins.md](margins.md)."; } >> "$out/report.md"
fi
cat "$out/summary.txt"
