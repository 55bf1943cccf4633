#!/bin/sh
# Run the CMocka unit tests: the plain build, then the same tests built with
# AddressSanitizer + UBSan.  The plain build runs once more (beside them)
# with CMocka's XML output to write JUnit XML per group into BUILD/test-results/ (old
# files are removed first: CMocka 1.1.5 does not overwrite an existing XML
# file, docs/design.md sec. 10).
set -u
build=$1; shift
out="$build/test-results"
rm -rf "$out"; mkdir -p "$out"
fail=0; total=0
# the XML pass of the plain build runs beside the others (its output is
# only the XML files; a failure is the plain pass's to report)
(
    for t in "$@"; do
        [ "$t" = "--" ] && break
        CMOCKA_MESSAGE_OUTPUT=XML CMOCKA_XML_FILE="$out/%g.xml" "$t" >/dev/null 2>&1
    done
) &
xml=$!
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
wait "$xml"
# CI reporters keep only the first of two test cases with the same name.
dups=$(cat "$out"/*.xml 2>/dev/null | sed -n 's/.*<testcase name="\([^"]*\)".*/\1/p' | sort | uniq -d)
if [ -n "$dups" ]; then
    echo "FAILED: test names used in more than one group: $dups"
    fail=$((fail + 1))
fi
echo "JUnit XML: $out/"
passed=$((total - fail))
echo "programs: $passed passed, $fail failed"
[ $fail -eq 0 ]
