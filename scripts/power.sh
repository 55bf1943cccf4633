#!/bin/sh
# make power [R=N]: the measured power of each statistical case.  Every
# case whose scene names a moderate alternative (`power_alt = KEY*FACTOR`
# or `KEY+DELTA`; quick tier unless TIER=full) is re-run R times with fresh
# seeds while its DATA GENERATOR draws under that alternative
# (`slipfield verify --alternative scene`; the oracle keeps the case's
# scene).  Power = fraction of runs the case rejects (FAIL), with a 95%
# Wilson score interval.  Writes reports/power/report.md (+ power.png) and
# reports/power.md (the same table).  A run that ends in ERROR is not a
# rejection: it is counted apart and makes the script fail.
set -eu
R=${1:-50}
TIER=${2:-quick}
JOBS=${3:-2}
BIN=${SLIPFIELD:-build/slipfield}   # a copy keeps a long study safe from rebuilds
sf_name=power; . "$(dirname "$0")/common.sh"
out=reports/power
mkdir -p "$out"
cases=""
for f in ${CASES:-cases/*/*.md}; do
    [ -n "$(scene_val "$f" power_alt)" ] || continue
    in_tier "$f" "$TIER" || continue
    cases="$cases $f"
done
[ -n "$cases" ] || { echo "power: no case names a power_alt" >&2; exit 2; }
i=0
t0=$(date +%s)
while [ $i -lt "$R" ]; do
    "$BIN" verify --seed random --alternative scene --jobs "$JOBS" --reports "$tmp/r" $cases > "$tmp/run$i.log" 2>&1 || true
    i=$((i + 1))
    [ -t 2 ] && printf '\rpower: %d/%d runs' "$i" "$R" >&2
done
[ -t 2 ] && echo >&2
t1=$(date +%s)
{
    echo "case	alternative	alpha	rejected	errors	runs"
    for f in $cases; do
        id=$(echo "$f" | sed 's|^cases/||; s|\.md$||')
        a=$(scene_val "$f" alpha)
        alt=$(scene_val "$f" power_alt)
        k=$(cat "$tmp"/run*.log | grep -E "^FAIL +$id " | wc -l)
        e=$(cat "$tmp"/run*.log | grep -E "^ERROR +$id " | wc -l)
        echo "$id	$alt	$a	$k	$e	$R"
    done
} > "$out/power.tsv"
# Wilson score interval (z = 1.96) for k successes in n runs
awk -F'\t' 'NR > 1 { n = $6; k = $4; p = k / n; z = 1.96; d = 1 + z * z / n;
     c = (p + z * z / (2 * n)) / d; h = z * sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d;
     lo = c - h; hi = c + h; if (lo < 0) lo = 0; if (hi > 1) hi = 1;
     printf "%s\t%s\t%s\t%d\t%d\t%d\t%.3f\t%.3f\t%.3f\n", $1, $2, $3, $4, $5, $6, p, lo, hi }' \
    "$out/power.tsv" > "$tmp/power.tab"
awk -F'\t' '{ print NR, $7, $8, $9 }' "$tmp/power.tab" > "$tmp/plot.dat"
gnuplot <<GP
set terminal pngcairo size 900,500 font "DejaVu Sans,10" noenhanced
set output "$out/power.png"
set title "Measured power per statistical case ($R runs under its alternative, fresh seeds)"
set xlabel "case (index in the table) [-]"
set ylabel "fraction of runs rejected [-]"
set yrange [0:1.05]
set key bottom left
plot "$tmp/plot.dat" using 1:2:3:4 with yerrorbars pt 7 title "power, 95% Wilson interval", \
     0.9 with lines dt 2 title "target 0.9"
GP
{
    echo "# Power of the statistical checks"
    echo
    echo "Each case that names a moderate alternative (scene key \`power_alt\`; tier $TIER) re-run $R times"
    echo "with fresh seeds (\`slipfield verify --seed random --alternative scene\`): the data generator draws"
    echo "under the alternative, the oracle does not. Power = fraction of runs the case rejected (FAIL);"
    echo "95% Wilson score interval. Target: 0.9 at the case's alpha. Wall time $((t1 - t0)) s ($JOBS jobs)."
    echo
    echo "| case | alternative | alpha | rejected | errors | runs | power | 95% CI |"
    echo "|---|---|---|---|---|---|---|---|"
    awk -F'\t' '{ printf "| %s | `%s` | %s | %d | %d | %d | %.2f | [%.2f, %.2f] |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9 }' "$tmp/power.tab"
    echo
    echo "![measured power](power/power.png)"
} > "$out/report.md.tmp"
sed 's|](power/power.png)|](power.png)|' "$out/report.md.tmp" > "$out/report.md"
mv "$out/report.md.tmp" reports/power.md
rm -f "$out/report.md.tmp"
awk -F'\t' '{ printf "%-44s %-18s power %.2f [%.2f, %.2f] (%d/%d)%s\n", $1, $2, $7, $8, $9, $4, $6, $5 ? "  ERRORS: " $5 : "" }' "$tmp/power.tab"
! awk -F'\t' '$5 > 0 { bad = 1 } END { exit !bad }' "$tmp/power.tab"
