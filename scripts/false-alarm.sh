#!/bin/sh
# make verify SEED=random REPEAT=N: rerun every case that draws random
# numbers (quick tier unless TIER=full) N times with fresh seeds and
# measure how often each fails.  A case with `alpha` should fail about
# alpha N times (its nominal false-alarm rate); a case without alpha gates
# a random quantity deterministically (a count, a fitted order on one
# realisation) and has no stated rate: any failure there is reported.
# Which cases draw random numbers is measured, not declared: every
# candidate runs once with --seed 1 and once with --seed 2, and a case
# whose results table or findings differ between the two draws random
# numbers that reach its verdict (reports/false-alarm/random-cases.txt).
# CASES='...' limits the candidates.  Writes reports/false-alarm/report.md
# and a gnuplot plot.  Many more failures than alpha N means a flaky (or
# wrong) check; mutants (make mutants) and make power show it is not
# toothless.
set -eu
N=${1:-20}
TIER=${2:-quick}
JOBS=${3:-2}
BIN=${SLIPFIELD:-build/slipfield}   # a copy keeps a long study safe from rebuilds
sf_name=fa; . "$(dirname "$0")/common.sh"
out=reports/false-alarm
mkdir -p "$out"
cand=""
for f in ${CASES:-cases/*/*.md}; do
    in_tier "$f" "$TIER" || continue
    cand="$cand $f"
done
# which candidates draw random numbers: two seeds, compare the results
"$BIN" verify --seed 1 --jobs "$JOBS" --reports "$tmp/s1" $cand > /dev/null 2>&1 || true
"$BIN" verify --seed 2 --jobs "$JOBS" --reports "$tmp/s2" $cand > /dev/null 2>&1 || true
body() { sed -n '/^## Results/,/^## Plots/p' "$1" 2>/dev/null || true; }
cases=""
: > "$out/random-cases.txt"
for f in $cand; do
    id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
    body "$tmp/s1/$id/report.md" > "$tmp/b1"
    body "$tmp/s2/$id/report.md" > "$tmp/b2"
    if ! cmp -s "$tmp/b1" "$tmp/b2"; then
        cases="$cases $f"
        echo "$f" >> "$out/random-cases.txt"
    fi
done
i=0
while [ $i -lt "$N" ]; do
    "$BIN" verify --seed random --jobs "$JOBS" --reports "$tmp/r" $cases > "$tmp/run$i.log" 2>&1 || true
    i=$((i + 1))
    [ -t 2 ] && printf '\rfalse-alarm: %d/%d runs' "$i" "$N" >&2
done
[ -t 2 ] && echo >&2
# per case: failures over N, nominal alpha from the scene
{
    echo "case	alpha	failures	runs"
    for f in $cases; do
        id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
        a=$(scene_val "$f" alpha)
        [ -n "$a" ] || a=-
        k=$(cat "$tmp"/run*.log | grep -E "^(FAIL|ERROR) +$id " | wc -l)
        echo "$id	$a	$k	$N"
    done
} > "$out/rates.tsv"
awk -F'\t' 'NR > 1 && $2 != "-" { n++; f += $3; ea += $2 * $4; r += $4 }
     NR > 1 && $2 == "-" { m++; g += $3; rr += $4 }
     END { printf "%d statistical cases (alpha) x %d runs: %d failures, expected at most %.2f (sum of alpha x runs)\n", n, r / (n ? n : 1), f, ea;
           printf "%d random cases without alpha x %d runs: %d failures (no stated rate: each is a finding)\n", m, rr / (m ? m : 1), g }' \
    "$out/rates.tsv" > "$out/summary.txt"
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
    echo "Each case that draws random numbers (tier $TIER; found by running every case with two seeds and"
    echo "comparing results: random-cases.txt) re-run $N times with fresh random seeds"
    echo "(\`slipfield verify --seed random\`). A case's nominal false-alarm rate is its alpha (tests"
    echo "within a case are Bonferroni-combined, so the case-level rate is at most alpha); a case with"
    echo "alpha '-' states no rate (a deterministic gate on a random quantity): any failure is a finding."
    echo
    cat "$out/summary.txt"
    echo
    echo "| case | alpha | failures | runs |"
    echo "|---|---|---|---|"
    awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s |\n", $1, $2, $3, $4 }' "$out/rates.tsv"
    echo
    echo "![false-alarm rates](false_alarm.png)"
} > "$out/report.md.tmp"
mv "$out/report.md.tmp" "$out/report.md"
cat "$out/summary.txt"
