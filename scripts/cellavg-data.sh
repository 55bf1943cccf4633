#!/bin/sh
# The stored measurements of the cell-average model's error against the
# point model on the same fine field: runs the check cellavg_vs_point at
# each point of a fixed Latin hypercube and writes every realisation's
# error as one TSV on stdout.  Two designs, drawn once and listed below
# (so that they do not depend on an awk's random numbers):
#   fit      12 points, seeds 681000001..012: what err_cell's belt-speed
#            and CV factors were fitted on (solver/plan/numplan.c);
#   holdout  16 points, seeds 681000101..116: never used to fit it.
#   sh scripts/cellavg-data.sh fit > cases/plan/cellavg-fit.tsv
#   sh scripts/cellavg-data.sh holdout > cases/plan/cellavg-calibration.tsv
# Box: l/R 0.02-0.044 (log; the cell-average range above 0.02: below it a
# point reference at 2.2 / (l/R) rings costs minutes a field), CV 0.05-1,
# v_b 0.1-0.8 m/s, mean COF 0.2-1, 32-60 cells per diameter; T = 20 s
# from rest (t_skip 10 s: the QoIs over the first cycles; over long
# windows a field's QoIs are not continuous in the quadrature, sec. 4.4 of
# docs/design.md); 8 fields a point, tiles, the point reference at
# ceil(2.2 / (l/R)) rings, rtol 1e-9 for both models.
# REPORTS=DIR keeps the runs' reports (and reuses them: a study can be
# resumed); SLIPFIELD=path picks the binary; JOBS=N runs N points at once.
# A point at which no field forms a QoI in the window (a long stick on a
# slow belt) is a comment line.  Columns: point, seed, l/R, CV, v_b [m/s], mean COF, cells, rings, T [s],
# field (the stream's position among those used), error (the largest
# relative difference of PV_x, PV_F and stick fraction, 4 digits).
set -eu
BIN=${SLIPFIELD:-build/slipfield}
sf_name=cellavg-data; . "$(dirname "$0")/common.sh"
dir=${REPORTS:-$tmp}
mkdir -p "$dir/cases/plan"
case $BIN in /*) ;; *) BIN=$top/$BIN ;; esac
rev=$("$BIN" --version | sed -n '1s/^slipfield //p')
case ${1:-} in
fit) seed0=681000000; design='1 0.0208 0.22 0.16 0.64 49 106
2 0.039 0.95 0.34 0.53 44 57
3 0.0243 0.39 0.63 0.33 59 91
4 0.0217 0.29 0.45 0.44 42 102
5 0.0382 0.21 0.2 0.68 37 58
6 0.0314 0.85 0.61 0.83 33 71
7 0.0418 0.79 0.32 0.78 54 53
8 0.0253 0.07 0.74 0.54 40 87
9 0.0317 0.75 0.48 0.22 48 70
10 0.0281 0.49 0.27 0.97 35 79
11 0.0266 0.61 0.57 0.93 52 83
12 0.0351 0.56 0.74 0.37 56 63' ;;
holdout) seed0=681000100; design='1 0.0349 0.98 0.56 0.89 42 64
2 0.0298 0.67 0.14 0.74 58 74
3 0.0315 0.42 0.35 0.57 60 70
4 0.0377 0.05 0.47 0.99 53 59
5 0.0206 0.25 0.73 0.95 55 107
6 0.0271 0.91 0.19 0.23 40 82
7 0.0264 0.4 0.77 0.62 46 84
8 0.033 0.17 0.69 0.5 38 67
9 0.0229 0.86 0.37 0.33 50 97
10 0.0416 0.75 0.17 0.83 43 53
11 0.0236 0.63 0.42 0.51 54 94
12 0.029 0.22 0.25 0.26 32 76
13 0.0219 0.54 0.65 0.67 36 101
14 0.0392 0.29 0.31 0.38 47 57
15 0.0419 0.82 0.6 0.44 33 53
16 0.0245 0.47 0.53 0.76 49 90' ;;
*) echo "usage: sh scripts/cellavg-data.sh fit|holdout > FILE.tsv" >&2; exit 2 ;;
esac
name=$1
T=20
echo "$design" | while read -r i lr cv vb mu cells rings; do
    f=$dir/cases/plan/cal-$i.md
    [ -f "$dir/r/plan/cal-$i/report.md" ] && continue
    std=$(awk -v c="$cv" -v m="$mu" 'BEGIN { printf "%.6g", c * m }')
    cat > "$f" <<EOF
# cellavg calibration point $i

One point of scripts/cellavg-data.sh's design.

\`\`\`scene
check = cellavg_vs_point
tolerance = 1000
cof = field
cof_generator = tiles
cells = $cells
rtol = 1e-9
T = $T
v_b = $vb
mu_mean = $mu
mu_std = $std
strip_halfwidth = 0.02
samples = 8
seed = $((seed0 + i))
sweep_param = l_over_R
sweep = $lr
sweep2 = $rings
tier = full
pin_seed = true
\`\`\`
EOF
done
set -- $(ls "$dir"/cases/plan/cal-*.md 2>/dev/null | while read -r f; do
    b=$(basename "$f" .md); [ -f "$dir/r/plan/$b/report.md" ] || echo "$f"; done)
[ $# -eq 0 ] || nice -n 15 "$BIN" verify --tier full --jobs "${JOBS:-1}" --timeout 3600 --reports "$dir/r" "$@" \
    > "$dir/log" 2>&1 || true
echo "# The cell-average model's error against the point model on the same fine field, at the points of"
echo "# scripts/cellavg-data.sh's design '$name' (seeds $((seed0 + 1))..), measured by slipfield $rev;"
echo "# regenerate with: sh scripts/cellavg-data.sh $name > this file"
echo "# columns: see scripts/cellavg-data.sh"
printf 'point\tseed\tlr\tcv\tvb\tmu\tcells\trings\tT\tfield\terror\n'
echo "$design" | while read -r i lr cv vb mu cells rings; do
    rep=$dir/r/plan/cal-$i/report.md
    [ -f "$rep" ] || { echo "cellavg-data: point $i left no report ($dir/log)" >&2; exit 1; }
    awk -v i="$i" -v s=$((seed0 + i)) -v lr="$lr" -v cv="$cv" -v vb="$vb" -v mu="$mu" -v c="$cells" \
        -v rg="$rings" -v T="$T" '
        /^- l\/R = [0-9.e+-]+:/ {
            for (k = 5; k <= NF; k++)
                printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t%s\n", i, s, lr, cv, vb, mu, c, rg, T, k - 4, $k
            found = NF - 4
        }
        /^l\/R = .* without a complete cycle in either run replaced/ { none = $0 }
        END {
            if (found == 0 && none != "")   # no field formed a QoI: the point cannot decide, and says so
                printf "# point %s: no field formed a QoI in the window (%s)\n", i, none
            else if (found != 8) { print "cellavg-data: point " i ": " found + 0 " errors in its report" > "/dev/stderr"; exit 1 }
        }' "$rep"
done
