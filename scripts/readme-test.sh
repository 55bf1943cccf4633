#!/bin/sh
# README.md is a door: at most 300 lines, its Quick start in the first 30,
# and every command in its ```sh blocks runs (from a scratch folder,
# against this tree's build/, examples/ and python/): the make targets are
# CI's own steps and are only checked to exist.  Also: docs/design.md at
# most 1200 lines.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
readme=$top/README.md
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "readme-test: FAIL $*" >&2; }
n=$(wc -l < "$readme")
[ "$n" -le 300 ] && ok || bad "README.md has $n lines (at most 300)"
# docs/design.md is the design, not a notebook: records go to docs/studies/
n=$(wc -l < "$top/docs/design.md")
[ "$n" -le 1200 ] && ok || bad "docs/design.md has $n lines (at most 1200: move records to docs/studies/)"
q=$(grep -n '^## Quick start' "$readme" | head -1 | cut -d: -f1)
[ -n "$q" ] && [ "$q" -le 30 ] && ok || bad "no '## Quick start' in README.md's first 30 lines"
work=$(mktemp -d /tmp/sf-readme.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
ln -s "$top/build" "$work/build"; ln -s "$top/examples" "$work/examples"; ln -s "$top/python" "$work/python"
ln -s "$top/cases" "$work/cases"
awk '/^```sh/ { on = 1; next } /^```/ { on = 0 } on' "$readme" | sed 's/[[:space:]]*#.*$//' |
    grep -v '^[[:space:]]*$' > "$work/commands"
while IFS= read -r cmd; do
    case "$cmd" in
    make\ *)
        t=$(echo "$cmd" | awk '{ print $2 }')
        grep -q "^$t:" "$top/Makefile" && ok || bad "README names 'make $t', which the Makefile has not" ;;
    *)
        if (cd "$work" && sh -c "$cmd") > "$work/out" 2> "$work/err" < /dev/null; then ok
        else bad "'$cmd' exited non-zero: $(tail -2 "$work/err")"; fi ;;
    esac
done < "$work/commands"
[ -s "$work/summary.tsv" ] && head -1 "$work/summary.tsv" | grep -q 'pv_x_ratio_estimate' && ok \
    || bad "the Quick start's sweep wrote no summary with pv_x_ratio_estimate"
echo "readme-test: $pass passed, $fail failed"
[ $fail -eq 0 ]
