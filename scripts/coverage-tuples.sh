#!/bin/sh
# The stored estimator tuples of cases/montecarlo/coverage-estimators.md:
# what each estimator's interval is a function of, drawn by the tool
# itself (`slipfield sweep --tuples`), at l/R = 0.03 (cell averages), 0.1
# (tiles), 1 and 10, the paper's Table 1 disc (examples/disc.scene) with
# T = 100 s, t_skip = 10 s:
#   antithetic        the pairs (G, -G), every point;
#   mlmc              level 0's coarse samples and level 1's (fine, coarse)
#                     pairs, every point;
#   mlmc-sub          the same on every 2nd node (the circulant strip: 1, 10);
#   mlmc-boxes        the same on boxes of boxes (cell averages: 0.03);
#   control-variate   (ratios, companion C) (not on tiles: 0.03, 1, 10).
# Each is one sweep at --realisations N --pilot N (the estimators' pilot
# is the whole pool: no stages, N pairs; level 0 as its sizes ask, up to
# 4 N), so the rows are the estimator's own samples, stream for stream.
# The output does not depend on the thread count, and a rerun is
# bit-identical:
#   sh scripts/coverage-tuples.sh > cases/montecarlo/coverage-estimators.tsv
# SLIPFIELD=path picks the binary (default build/slipfield); THREADS=N the
# threads (default 2); POINTS="LR:N:ESTIMATORS ..." the points, their pool
# sizes and estimators (ESTIMATORS comma-separated; default below).
# 17 min of CPU at the default points (1026 s user on 2 threads).
set -eu
BIN=${SLIPFIELD:-build/slipfield}
sf_name=coverage-tuples; . "$(dirname "$0")/common.sh"
case $BIN in /*) ;; *) BIN=$top/$BIN ;; esac
points=${POINTS:-0.03:250:antithetic,mlmc,mlmc-boxes,control-variate 0.1:250:antithetic,mlmc 1:2000:antithetic,mlmc,mlmc-sub,control-variate 10:2000:antithetic,mlmc,mlmc-sub,control-variate}
rev=$("$BIN" --version | sed -n '1s/^slipfield \([^ ]*\).*/\1/p')   # the version, not the commit (as coverage-data.sh)
sed 's/^T = .*/T = 100/' examples/disc.scene > "$tmp/disc100.scene"
grep -q '^T = 100$' "$tmp/disc100.scene" || { echo "coverage-tuples: examples/disc.scene has no T line" >&2; exit 1; }
echo "# Estimator tuples (cases/montecarlo/coverage-estimators.md): examples/disc.scene with"
echo "# T = 100 s, t_skip = 10 s; l/R:N:estimators = $points;"
echo "# by slipfield sweep --tuples of slipfield $rev; regenerate with:"
echo "# sh scripts/coverage-tuples.sh > this file"
first=1
for pc in $points; do
    lr=${pc%%:*} rest=${pc#*:}
    n=${rest%%:*} ests=${rest#*:}
    for e in $(echo "$ests" | tr , ' '); do
        case $e in control-variate) how=--control-variate ;; *) how="--estimator $e --pilot $n" ;; esac
        # shellcheck disable=SC2086
        nice -n 15 "$BIN" sweep "$tmp/disc100.scene" --param l_over_R --values "$lr" --realisations "$n" $how \
            --out "$tmp/rows" --tuples "$tmp/t" --threads "${THREADS:-2}" 2> "$tmp/log" ||
            { echo "coverage-tuples: l/R = $lr, $e failed:" >&2; cat "$tmp/log" >&2; exit 1; }
        if [ $first = 1 ]; then cat "$tmp/t"; first=0; else tail -n +2 "$tmp/t"; fi
    done
done
