#!/bin/sh
# make valgrind: a few quick cases (one per solver part; the runner's
# forked case processes are followed), the CLI and the allocation-failure
# unit test under memcheck; any
# memory error or definite leak fails.
set -eu
sf_name=vg
. "$(dirname "$0")/common.sh"
VG="valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite --show-leak-kinds=definite"
# the allocation-failure walks (tests/test_faults.c, solver with the fault
# hooks): no leak and no uninitialised read on any ENOMEM path.  The
# longest part, in three processes beside the rest: the two-level sweep's
# walk (~430 failing runs, 390 s on one core of the CI machine), halved
# (SF_WALK_PART: even and odd allocations), and the other walks (210 s),
# with the cases and the CLI below (50 s): about 330 s on 2 cores.  The
# walks of the estimators on pairs (sweeps_mlmc_derived: antithetic, two
# levels on boxes of boxes and on every 2nd node, ~1250 failing runs,
# ~18 min here) are left to make test, whose AddressSanitizer build runs
# each path under its leak checker
export CMOCKA_MESSAGE_OUTPUT=STDOUT
SF_TEST_ONLY=sweeps_mlmc SF_WALK_PART=0/2 $VG build/rel/tests/test_faults > "$tmp/faults-mlmc0.log" 2>&1 &
walk0=$!
SF_TEST_ONLY=sweeps_mlmc SF_WALK_PART=1/2 $VG build/rel/tests/test_faults > "$tmp/faults-mlmc1.log" 2>&1 &
walk1=$!
SF_TEST_SKIP='sweeps_mlmc*' $VG build/rel/tests/test_faults > "$tmp/faults.log" 2>&1 &
walk2=$!
trap 'kill "$walk0" "$walk1" "$walk2" 2> /dev/null || true; rm -rf "$tmp"' EXIT
$VG build/slipfield verify --jobs 1 --timeout 900 --reports "$tmp/reports" \
    cases/field/exact-covariance-minimal.md cases/lognormal/nataf-map-roundtrip.md \
    cases/contact/pure-spin-polar.md cases/surface/equator-mean-cof.md cases/deterministic/energy-1d.md \
    cases/plan/section-vs-full-surface.md
printf 'T = 20\nt_skip = 2\ncells = 8\nrtol = 1e-6\n' > "$tmp/s.scene"
$VG build/slipfield run "$tmp/s.scene" --out "$tmp/h.tsv" --summary "$tmp/q.txt"
$VG build/slipfield run "$tmp/s.scene" --explain > /dev/null
printf 'fftw_planner = measure\nnx = 32\nny = 32\n' >> "$tmp/s.scene"
SLIPFIELD_FFTW_WISDOM="$tmp/w.wis" $VG build/slipfield field "$tmp/s.scene" --samples 1 --out "$tmp/f.tsv"
$VG build/slipfield sweep "$tmp/s.scene" --param l_over_R --values 1,1000000 --realisations 2 --threads 1 --out "$tmp/w.tsv"
wait "$walk2" || { cat "$tmp/faults.log"; exit 1; }
wait "$walk0" || { cat "$tmp/faults-mlmc0.log"; exit 1; }
wait "$walk1" || { cat "$tmp/faults-mlmc1.log"; exit 1; }
echo "valgrind: clean"
