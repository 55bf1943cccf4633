#!/bin/sh
# The time-stepping error of the accuracy plan's rtol (numplan.c (5)):
# N random design points (log10 l/R uniform in [-1.5, 3], CV in [0.05, 1],
# v_b in [0.1, 0.8] m/s, mean COF in [0.2, 1], T in [30, 100] s, t_skip
# 10 s), one field each (the point's seed), the plan's rings at the
# default qoi_tol; each point run at every rtol of RTOLS and at REF; per
# point and rtol the largest relative error of PV_x, PV_F and the stick
# fraction against REF, and the CPU time of the run [s].  TSV on stdout:
#   sh scripts/time-model-data.sh N SEED > FILE.tsv
# RTOLS='1e-5 3e-6 1e-6 3e-7 1e-7 1e-8 1e-10' and REF=1e-11 by default;
# SLIPFIELD=path picks the binary (default build/slipfield).
set -eu
[ $# -eq 2 ] || { echo "usage: sh scripts/time-model-data.sh N SEED > FILE.tsv" >&2; exit 2; }
N=$1
SEED=$2
RTOLS=${RTOLS:-1e-5 3e-6 1e-6 3e-7 1e-7 1e-8 1e-10}
REF=${REF:-1e-11}
BIN=${SLIPFIELD:-build/slipfield}
sf_name=time-model; . "$(dirname "$0")/common.sh"
case $BIN in /*) ;; *) BIN=$top/$BIN ;; esac
# one run: "pv_x pv_F stick_fraction cpu" (nan where a QoI is undefined;
# cpu: the run's user CPU time [s])
run() {
    printf 'cof = field\nl = %s\nmu_mean = %s\nmu_std = %s\nv_b = %s\nT = %s\nt_skip = 10\nseed = %s\nrtol = %s\nhistory = false\n' \
        "$2" "$3" "$4" "$5" "$6" "$1" "$7" > "$tmp/s.scene"
    : > "$tmp/sum"
    /usr/bin/time -f '%U' -o "$tmp/cpu" "$BIN" run "$tmp/s.scene" --summary "$tmp/sum" > /dev/null 2>&1 || true
    awk -F' = ' -v cpu="$(tail -n 1 "$tmp/cpu")" '$1 == "pv_x" { a = $2 } $1 == "pv_F" { b = $2 } $1 == "stick_fraction" { c = $2 }
        END { printf "%s %s %s %s", (a == "" ? "nan" : a), (b == "" ? "nan" : b), (c == "" ? "nan" : c), cpu }' "$tmp/sum"
}
echo "# time-stepping error against rtol $REF: sh scripts/time-model-data.sh $N $SEED, slipfield $("$BIN" --version | sed -n '1s/^slipfield //p')"
printf 'i\tseed\tl_over_R\tcv\tv_b\tmu_mean\tT\trtol\terr\tcpu_s\n'
i=0
while [ "$i" -lt "$N" ]; do
    # the point: awk's generator seeded by (SEED, i)
    set -- $(awk -v s="$SEED" -v i="$i" 'BEGIN { srand(s * 1000 + i); lr = 10 ^ (-1.5 + 4.5 * rand()); cv = 0.05 + 0.95 * rand();
        vb = 0.1 + 0.7 * rand(); mu = 0.2 + 0.8 * rand(); T = 30 + 70 * rand(); printf "%.6g %.6g %.6g %.6g %.6g", lr, cv, vb, mu, T }')
    lr=$1 cv=$2 vb=$3 mu=$4 T=$5
    l=$(awk -v a="$lr" 'BEGIN { printf "%.9g", a * 0.5 }')
    std=$(awk -v a="$cv" -v b="$mu" 'BEGIN { printf "%.9g", a * b }')
    pseed=$((SEED * 1000 + i))
    ref=$(run "$pseed" "$l" "$mu" "$std" "$vb" "$T" "$REF")
    for rt in $RTOLS; do
        q=$(run "$pseed" "$l" "$mu" "$std" "$vb" "$T" "$rt")
        set -- $q $ref
        cpu=$4
        err=$(echo "$1 $2 $3 $5 $6 $7" | awk '{ e = -1; for (k = 1; k <= 3; k++) if ($k != "nan" && $(k + 3) != "nan" && $(k + 3) != 0) {
            d = $k / $(k + 3) - 1; d = d < 0 ? -d : d; if (d > e) e = d }; if (e < 0) print "nan"; else printf "%.3g", e }')
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$i" "$pseed" "$lr" "$cv" "$vb" "$mu" "$T" "$rt" "$err" "$cpu"
    done
    i=$((i + 1))
done
