#!/bin/sh
# The MPI build gives the serial bytes: a sweep run by the serial binary and
# by `mpirun -np 2` (and -np 3, more ranks than cores) must produce
# identical TSV files.
set -eu
serial=$1
mpi=$2
tmp=$(mktemp -d /tmp/sf-mpi.XXXXXX)
trap 'rm -rf "$tmp"' EXIT INT TERM
printf 'T = 30\nt_skip = 10\ncells = 8\nrtol = 1e-6\n' > "$tmp/s.scene"
"$serial" sweep "$tmp/s.scene" --param l_over_R --values 1,10,1000000 --realisations 7 --out "$tmp/serial.tsv" --summary "$tmp/serial-sum.tsv"
R="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && R="$R --allow-run-as-root"
for np in 2 3; do
    OMP_NUM_THREADS=1 $R -np $np "$mpi" sweep "$tmp/s.scene" --param l_over_R --values 1,10,1000000 --realisations 7 \
        --out "$tmp/mpi$np.tsv" --summary "$tmp/mpi$np-sum.tsv"
    cmp "$tmp/serial.tsv" "$tmp/mpi$np.tsv"
    cmp "$tmp/serial-sum.tsv" "$tmp/mpi$np-sum.tsv"
done
echo "mpi-test: mpirun -np 2 and -np 3 give the serial bytes"
