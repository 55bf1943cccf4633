#!/bin/sh
# The stored reference populations of cases/montecarlo/coverage-populations.md:
# plain Monte Carlo realisations of the three QoI ratios, 10^4 at l/R = 1
# and 10 and 3000 at l/R = 0.1 (0.17 s of CPU each there, against 0.025 s
# at 1 and 0.003 s at 10), the paper's Table 1 disc (examples/disc.scene)
# with T = 100 s, t_skip = 10 s.  Realisation I is `slipfield sweep`'s
# realisation I (stream sf_mc_seed(scene seed, I)), drawn by
#   slipfield evaluate examples/disc.scene --design D --threads 2 --no-unum
# whose output does not depend on the thread count; the ratios are copied
# as evaluate prints them (%.17g), so a rerun is bit-identical:
#   sh scripts/coverage-data.sh > cases/montecarlo/coverage-populations.tsv
# SLIPFIELD=path picks the binary (default build/slipfield); THREADS=N the
# threads (default 2); POINTS="LR:COUNT ..." the points and their
# realisations (default "0.1:3000 1:10000 10:10000").
# Columns: lr (l/R), realisation, pv_x_ratio, pv_F_ratio,
# stick_fraction_ratio (to the deterministic model at the mean COF).
set -eu
BIN=${SLIPFIELD:-build/slipfield}
sf_name=coverage-data; . "$(dirname "$0")/common.sh"
case $BIN in /*) ;; *) BIN=$top/$BIN ;; esac
points=${POINTS:-0.1:3000 1:10000 10:10000}
rev=$("$BIN" --version | sed -n '1s/^slipfield \([^ ]*\).*/\1/p')   # the version, not the commit: the file is bit-identical across commits that leave the solver alone
echo "# Reference populations of the QoI ratios (cases/montecarlo/coverage-populations.md):"
echo "# examples/disc.scene with T = 100 s, t_skip = 10 s; realisations 0..COUNT-1 (sweep's) at"
echo "# l/R:COUNT = $points, by slipfield evaluate --no-unum of slipfield $rev;"
echo "# regenerate with: sh scripts/coverage-data.sh > this file"
printf 'lr\trealisation\tpv_x_ratio\tpv_F_ratio\tstick_fraction_ratio\n'
for pc in $points; do
    lr=${pc%%:*} n=${pc#*:}
    awk -v lr="$lr" -v n="$n" 'BEGIN { printf "l_over_R\tT\tt_skip\trealisation\n"; for (i = 0; i < n; i++) printf "%s\t100\t10\t%d\n", lr, i }' > "$tmp/d$lr.tsv"
    nice -n 15 "$BIN" evaluate examples/disc.scene --design "$tmp/d$lr.tsv" --out "$tmp/o$lr.tsv" \
        --threads "${THREADS:-2}" --no-unum 2> "$tmp/log$lr" || { echo "coverage-data: l/R = $lr failed:" >&2; cat "$tmp/log$lr" >&2; exit 1; }
    awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
        $c["status"] != "ok" { print "coverage-data: bad row: " $0 > "/dev/stderr"; exit 1 }
        { printf "%s\t%s\t%s\t%s\t%s\n", $c["l_over_R"], $c["realisation"], $c["pv_x_ratio[-]"], $c["pv_F_ratio[-]"], $c["stick_fraction_ratio[-]"] }' "$tmp/o$lr.tsv"
done
