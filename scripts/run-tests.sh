#!/bin/sh
# Run the CMocka unit tests: plain build, then AddressSanitizer + UBSan.
# JUnit XML per group goes to BUILD/test-results/ (old files are removed
# first: CMocka 1.1.5 does not overwrite an existing XML file).
set -u
build=$1; shift
out="$build/test-results"
rm -rf "$out"; mkdir -p "$out"
fail=0; total=0
variant=plain
for t in "$@"; do
    if [ "$t" = "--" ]; then variant=sanitized; continue; fi
    total=$((total + 1))
    name=$(basename "$t")
    echo "== $name ($variant)"
    if ! CMOCKA_MESSAGE_OUTPUT=STDOUT \
         ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
         "$t"; then
        fail=$((fail + 1))
        echo "FAILED: $name ($variant)"
    fi
done
passed=$((total - fail))
echo "programs: $passed passed, $fail failed"
[ $fail -eq 0 ]
