#!/bin/sh
# Feed every input of tests/bad-input/MANIFEST to slipfield: each must exit
# with status 2, print a message containing the expected fragment (file,
# line and key where there is one), and leave no output file behind.
# Generated inputs: @missing (no such file), @directory (a directory),
# @hugeline (a 100 MB line, made here, not committed).
set -u
sf_name=bad
. "$(dirname "$0")/common.sh"
bin=${1:-build/slipfield}
pass=0; fail=0
while IFS='	' read -r file kind frag; do
    case "$file" in ''|'#'*) continue ;; esac
    case "$file" in
        @missing) path="tests/bad-input/no-such-file.scene" ;;
        @directory) path="tests/bad-input" ;;
        @hugeline) mkdir -p "$tmp/huge"; path="$tmp/huge/line.$([ "$kind" = case ] && echo md || echo scene)"
                   [ -f "$path" ] || head -c 104857600 /dev/zero | tr '\0' 'x' > "$path" ;;
        *) path="tests/bad-input/$file" ;;
    esac
    rm -rf "$tmp/out" "$tmp/reports"; mkdir -p "$tmp/out"
    if [ "$kind" = scene ]; then
        "$bin" field "$path" --samples 1 --out "$tmp/out/field.tsv" >/dev/null 2>"$tmp/err"; rc=$?
    else
        "$bin" verify --reports "$tmp/reports" "$path" >/dev/null 2>"$tmp/err"; rc=$?
    fi
    left=$(ls -A "$tmp/out")
    msg=$(head -c 400 "$tmp/err")
    if [ $rc -eq 2 ] && grep -qF -- "$frag" "$tmp/err" && [ -z "$left" ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "bad-input: FAIL $file ($kind): exit $rc, expected 2 and '$frag'; got: $msg; left behind: $left" >&2
    fi
done < tests/bad-input/MANIFEST
echo "bad inputs: $pass passed, $fail failed"
[ $fail -eq 0 ]
