#!/bin/sh
# The MPI build gives the serial bytes: a sweep run by the serial binary and
# by `mpirun -np 2` (and -np 3, more ranks than cores) must produce
# identical TSV files (the per-realisation table, the summary, the
# diagnostics).
set -eu
serial=$1
mpi=$2
tmp=$(mktemp -d /tmp/sf-mpi.XXXXXX)
trap 'rm -rf "$tmp"' EXIT INT TERM
# the lognormal strip, the tiles' neighbourhood and the one-variable
# limit; then the cell-averaged COF (real sampler) at small l/R
printf 'T = 30\nt_skip = 10\ncells = 8\nrtol = 1e-6\n' > "$tmp/s.scene"
printf 'T = 30\nt_skip = 10\ncof_model = cell_average\ncells = 32\nrtol = 1e-6\n' > "$tmp/c.scene"
R="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && R="$R --allow-run-as-root"
for sc in s:1,10,1000000 c:0.01,0.03; do
    name=${sc%%:*}; values=${sc#*:}
    "$serial" sweep "$tmp/$name.scene" --param l_over_R --values "$values" --realisations 7 \
        --out "$tmp/$name-serial.tsv" --summary "$tmp/$name-serial-sum.tsv" --diagnostics "$tmp/$name-serial-diag.tsv"
    for np in 2 3; do
        OMP_NUM_THREADS=1 $R -np $np "$mpi" sweep "$tmp/$name.scene" --param l_over_R --values "$values" \
            --realisations 7 --out "$tmp/$name-mpi$np.tsv" --summary "$tmp/$name-mpi$np-sum.tsv" \
            --diagnostics "$tmp/$name-mpi$np-diag.tsv"
        cmp "$tmp/$name-serial.tsv" "$tmp/$name-mpi$np.tsv"
        cmp "$tmp/$name-serial-sum.tsv" "$tmp/$name-mpi$np-sum.tsv"
        cmp "$tmp/$name-serial-diag.tsv" "$tmp/$name-mpi$np-diag.tsv"
    done
done
# the paired estimators sized in stages and at a target (each stage's
# decision is a function of the values in index order, whichever rank
# computed them): auto's rule picks two levels on every 2nd node at 0.3,
# two levels on one field at 1 and antithetic pairs at 10
for est in "auto --target-se 0.02" "antithetic" "mlmc"; do
    tag=$(echo "$est" | cut -d' ' -f1)
    # shellcheck disable=SC2086
    "$serial" sweep "$tmp/s.scene" --param l_over_R --values 0.3,1,10 --realisations 24 --pilot 4 \
        --estimator $est --out "$tmp/e-$tag-serial.tsv" --summary "$tmp/e-$tag-serial-sum.tsv" \
        --diagnostics "$tmp/e-$tag-serial-diag.tsv" 2> /dev/null
    for np in 2 3; do
        # shellcheck disable=SC2086
        OMP_NUM_THREADS=1 $R -np $np "$mpi" sweep "$tmp/s.scene" --param l_over_R --values 0.3,1,10 \
            --realisations 24 --pilot 4 --estimator $est --out "$tmp/e-$tag-mpi$np.tsv" \
            --summary "$tmp/e-$tag-mpi$np-sum.tsv" --diagnostics "$tmp/e-$tag-mpi$np-diag.tsv" 2> /dev/null
        cmp "$tmp/e-$tag-serial.tsv" "$tmp/e-$tag-mpi$np.tsv"
        cmp "$tmp/e-$tag-serial-sum.tsv" "$tmp/e-$tag-mpi$np-sum.tsv"
        cmp "$tmp/e-$tag-serial-diag.tsv" "$tmp/e-$tag-mpi$np-diag.tsv"
    done
done
echo "mpi-test: mpirun -np 2 and -np 3 give the serial bytes (lognormal strip, one variable, cell averages; the estimators auto at a target, antithetic, mlmc)"
