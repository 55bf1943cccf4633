#!/bin/sh
# make fuzz: build libFuzzer targets for the scene parser and the case
# reader with clang (ASan + UBSan), run each for FUZZ_TIME seconds from the
# seed corpus, and fail on any crash (the input is kept in build/fuzz/).
# A crash found becomes a regression test: copy the input into
# tests/bad-input/ with its expected message (see tests/bad-input/MANIFEST).
set -eu
T=${1:-60}
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
out=build/fuzz
mkdir -p "$out/obj"
CC=${FUZZ_CC:-clang}
PKG=$(pkg-config --cflags gsl fftw3 libcmark-gfm jansson 2>/dev/null || true)
LIBS="-lcmark-gfm-extensions $(pkg-config --libs libcmark-gfm gsl fftw3 jansson 2>/dev/null || echo -lcmark-gfm -lgsl -lgslcblas -lfftw3 -ljansson) -lm"
# solver/ and its layer folders (solver/LAYERS), as the Makefile's INC_solver
SOLVER_DIRS="solver $(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' -e 's|^|solver/|' solver/LAYERS | paste -sd' ' -)"
SOLVER_I=$(printf -- '-I%s ' $SOLVER_DIRS)
FL="-std=c11 -D_POSIX_C_SOURCE=200809L -g -O1 -fno-omit-frame-pointer $SOLVER_I-Iverification -Ibuild/gen -Wno-unknown-pragmas"
objs=""
# shellcheck disable=SC2086
for src in $(for d in $SOLVER_DIRS; do ls "$d"/*.c; done | sort) verification/*.c verification/checks/*.c; do
    o="$out/obj/$(echo "$src" | tr / _).o"
    if [ ! -f "$o" ] || [ "$src" -nt "$o" ]; then
        $CC $FL $PKG -fsanitize=fuzzer-no-link,address,undefined -c "$src" -o "$o"
    fi
    objs="$objs $o"
done
status=0
for t in scene case; do
    $CC $FL -fsanitize=fuzzer,address,undefined tests/fuzz/fuzz_$t.c $objs $LIBS -o "$out/fuzz_$t"
    mkdir -p "$out/corpus-$t" "$out/crash-$t"
    cp tests/fuzz/corpus-$t/* "$out/corpus-$t/"
    echo "fuzz: $t for $T s"
    if ! "$out/fuzz_$t" -max_total_time="$T" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
            -artifact_prefix="$out/crash-$t/" "$out/corpus-$t" > "$out/fuzz_$t.log" 2>&1; then
        echo "fuzz: $t CRASHED; input and log in $out/crash-$t/ and $out/fuzz_$t.log" >&2
        tail -30 "$out/fuzz_$t.log" >&2
        status=1
    else
        grep -E '^#[0-9]+.*(DONE|pulse)' "$out/fuzz_$t.log" | tail -1
    fi
done
[ $status = 0 ] && echo "fuzz: clean"
exit $status
