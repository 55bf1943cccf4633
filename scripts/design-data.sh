#!/bin/sh
# The stored measurements of the accuracy plan's error: run
# cases/plan/design-quick.md at `--seed FIRST..LAST` for each range given
# (one run at a time, --jobs 1) and write its per-point tables as one TSV
# on stdout.  The held-out seeds (cases/plan/errmodel-calibration.tsv) and
# the seeds err_pred was fitted on (cases/plan/errmodel-fit.tsv):
#   sh scripts/design-data.sh 3001 3040 > cases/plan/errmodel-calibration.tsv
#   sh scripts/design-data.sh 1001 1002 2001 2038 > cases/plan/errmodel-fit.tsv
# REPORTS=DIR keeps the runs' reports in DIR/rSEED and reuses any already
# there (a long study can be resumed; reports of another binary give that
# binary's data).  SLIPFIELD=path picks the binary (default build/slipfield).
# Columns: seed (the --seed), design_seed (the case's seed after the
# runner's mixing: the Latin hypercube's), i (the point), the point's
# l/R, CV, v_b, mean COF, T, qoi_tol, the plan's rings and rtol as the
# report prints them, cycles (levels 0/1/2), undecidable (1: a cycle at the
# window's edge, no cycle or no peak-to-valley), then per QoI (PV_x, PV_F,
# stick fraction) the achieved error a = |Q0 - Q2| / |Q2|, the reference's
# own error e = |Q1 - Q2| / |Q2| and the run's u_num / |Q0| (levels: the
# plan's settings; 2x its rings, rtol / 10; 3x its rings, rtol / 100).
set -eu
[ $# -ge 2 ] && [ $(($# % 2)) -eq 0 ] || { echo "usage: sh scripts/design-data.sh FIRST LAST [FIRST LAST ...] > FILE.tsv" >&2; exit 2; }
BIN=${SLIPFIELD:-build/slipfield}
sf_name=design-data; . "$(dirname "$0")/common.sh"
dir=${REPORTS:-$tmp}
[ -z "${REPORTS:-}" ] || mkdir -p "$dir"
case $BIN in /*) ;; *) BIN=$top/$BIN ;; esac
rev=$("$BIN" --version | sed -n '1s/^slipfield //p')
ranges=$(printf '%s..%s, ' "$@" | sed 's/, $//')
echo "# Measurements of the accuracy plan's error: cases/plan/design-quick.md at --seed $ranges"
echo "# (the case reading this file says what the seeds are for), measured by slipfield $rev;"
echo "# regenerate with: sh scripts/design-data.sh $* > this file"
echo "# columns: see scripts/design-data.sh"
printf 'seed\tdesign_seed\ti\tlr\tcv\tvb\tmu\tT\ttol\trings\trtol\tcycles\tundecidable\ta0\ta1\ta2\te0\te1\te2\tu0\tu1\tu2\n'
while [ $# -ge 2 ]; do
    s=$1
    while [ "$s" -le "$2" ]; do
        rep=$dir/r$s/plan/design-quick/report.md
        if [ ! -f "$rep" ]; then
            nice -n 15 "$BIN" verify --seed "$s" --jobs 1 --reports "$dir/r$s" cases/plan/design-quick.md > "$dir/log$s" 2>&1 || true
            [ -f "$rep" ] || { echo "design-data: seed $s left no report ($dir/log$s)" >&2; exit 1; }
        fi
        awk -v seed="$s" -F'|' '
            /^Latin hypercube of [0-9]+ points \(seed [0-9]+\)/ { ds = $0; sub(/.*\(seed /, "", ds); sub(/\).*/, "", ds) }
            /^\| [0-9]+ \| [0-9.e+-]+ \|/ {
                for (k = 2; k <= 15; k++) gsub(/^ +| +$/, "", $k)
                split($11, cy, " "); und = index($11, "(") > 0
                n = split($13 ", " $14 ", " $15, v, ", ")
                for (k = 1; k <= n; k++) sub(/^-nan$/, "nan", v[k])
                if (n != 9 || ds == "") { print "design-data: bad row: " $0 > "/dev/stderr"; exit 1 }
                printf "%s\t%s", seed, ds
                for (k = 2; k <= 10; k++) printf "\t%s", $k
                printf "\t%s\t%d", cy[1], und
                for (k = 1; k <= 9; k++) printf "\t%s", v[k]
                printf "\n"
            }' "$rep"
        s=$((s + 1))
    done
    shift 2
done
