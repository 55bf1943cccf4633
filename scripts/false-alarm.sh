#!/bin/sh
# make verify SEED=random REPEAT=N: rerun the statistical cases (those whose
# scene sets alpha; quick tier unless TIER=full) N times with fresh seeds
# and measure how often each fails against its nominal alpha.  Writes
# reports/false-alarm/report.md and a gnuplot plot.  A check with a fair
# false-alarm rate fails about alpha N times; many more means a flaky (or
# wrong) check, and mutants (make mutants) show it is not toothless.
set -eu
N=${1:-20}
TIER=${2:-quick}
JOBS=${3:-2}
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
out=reports/false-alarm
mkdir -p "$out"
tmp=$(mktemp -d /tmp/sf-fa.XXXXXX)
trap 'rm -rf "$tmp"' EXIT INT TERM
cases=""
for f in cases/*/*.md; do
    awk '/^```scene/ { f = 1; next } /^```/ { f = 0 } f && /^alpha = / { found = 1 } END { exit !found }' "$f" || continue
    if [ "$TIER" = quick ] && grep -q '^tier = full' "$f"; then continue; fi
    cases="$cases $f"
done
i=0
while [ $i -lt "$N" ]; do
    build/slipfield verify --seed random --jobs "$JOBS" --reports "$tmp/r" $cases > "$tmp/run$i.log" 2>&1 || true
    i=$((i + 1))
    [ -t 2 ] && printf '\rfalse-alarm: %d/%d runs' "$i" "$N" >&2
done
[ -t 2 ] && echo >&2
# per case: failures over N, nominal alpha from the scene
{
    echo "case	alpha	failures	runs"
    for f in $cases; do
        id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
        a=$(awk '/^```scene/ { f = 1; next } /^```/ { f = 0 } f && /^alpha = / { print $3 }' "$f")
        k=$(cat "$tmp"/run*.log | grep -E "^(FAIL|ERROR) +$id " | wc -l)
        echo "$id	$a	$k	$N"
    done
} > "$out/rates.tsv"
awk -F'\t' 'NR > 1 { n++; f += $3; ea += $2 * $4; r += $4 }
     END { printf "%d statistical cases x %d runs: %d failures, expected at most %.2f (sum of alpha x runs)\n", n, r / (n ? n : 1), f, ea }' \
    "$out/rates.tsv" > "$out/summary.txt"
awk -F'\t' 'NR > 1 { print NR - 1, ($3 / $4), $2 }' "$out/rates.tsv" > "$tmp/plot.dat"
gnuplot <<GP
set terminal pngcairo size 900,500 font "DejaVu Sans,10" noenhanced
set output "$out/false_alarm.png"
set title "Measured false-alarm rate per statistical case ($N runs, fresh seeds)"
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
    echo "Each statistical case (scene sets \`alpha\`; tier $TIER) re-run $N times with fresh random seeds"
    echo "(\`slipfield verify --seed random\`). A case's nominal false-alarm rate is its alpha (tests"
    echo "within a case are Bonferroni-combined, so the case-level rate is at most alpha)."
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
