#!/bin/sh
# make test: scripts/layering.sh (make layering) catches what it is for.
# Each defect is seeded in a scratch copy of the include-bearing folders;
# the check must fail on it and name the file, the line and the rule:
#   an upward include between layers (base/scene.c including sweep.h of
#   stats/), a same-layer include kept legal, a folder missing from
#   solver/LAYERS, an include cycle, solver/ including verification/.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 3
work=$(mktemp -d /tmp/sf-layering.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok    $*"; }
bad() { fail=$((fail + 1)); echo "FAIL  $*"; }
fresh() {   # a clean copy of the folders the check reads
    rm -rf "$work/t"; mkdir -p "$work/t"
    tar -cf - solver verification cli tests bench | tar -xf - -C "$work/t"
}
# run the check on the copy; $1 = what it must say (a grep -E pattern)
expect_fail() {
    what=$1 want=$2
    if sh scripts/layering.sh "$work/t" > "$work/out" 2>&1; then
        bad "$what: layering passed"
    elif grep -qE "$want" "$work/out"; then
        ok "$what: $(grep -E "$want" "$work/out" | head -1)"
    else
        bad "$what: failed without the expected message"; sed 's/^/      /' "$work/out" | head -5
    fi
}
fresh
if sh scripts/layering.sh "$work/t" > "$work/out" 2>&1; then ok "the tree as it is passes"; else bad "the tree fails: $(head -3 "$work/out")"; fi
# an upward include: a base file reaching into stats/, on a line of its own
fresh
f=$work/t/solver/base/scene.c
line=$(($(grep -n '^#include "scene.h"' "$f" | head -1 | cut -d: -f1) + 1))
sed -i "${line}i #include \"sweep.h\"" "$f"
expect_fail "upward include" "^solver/base/scene\.c:$line: #include \"sweep\.h\" \(solver/stats\) <- solver/base/ includes only its own folder and the layers below"
# the same folder and a layer below are allowed
fresh
f=$work/t/solver/dynamics/qoi.c
sed -i '0,/^#include "qoi.h"/s//#include "qoi.h"\n#include "cycle1d.h"\n#include "numplan.h"/' "$f"
if sh scripts/layering.sh "$work/t" > "$work/out" 2>&1; then ok "same-layer and downward includes pass"; else bad "a legal include fails: $(head -2 "$work/out")"; fi
# a folder that solver/LAYERS does not list
fresh
x=extra; mkdir -p "$work/t/solver/$x"; : > "$work/t/solver/$x/x.h"
expect_fail "unlisted folder" "/extra is not a layer of solver/LAYERS"
# an include cycle inside one layer (legal by folder, not by module)
fresh
f=$work/t/solver/base/sf_error.h
sed -i '0,/^#include/s//#include "scene.h"\n&/' "$f"
grep -q '#include "scene.h"' "$f" || sed -i '$a #include "scene.h"' "$f"
f2=$work/t/solver/base/scene.h
grep -q '#include "sf_error.h"' "$f2" || sed -i '$a #include "sf_error.h"' "$f2"
expect_fail "include cycle" "an include cycle among the modules"
# solver/ including the harness
fresh
printf '#include "result.h"\n' >> "$work/t/solver/field/noise.c"
expect_fail "solver/ includes verification/" "^solver/field/noise\.c:[0-9]+:.*<- solver/ includes only solver/"
echo "layering-test: $pass passed, $fail failed"
[ $fail -eq 0 ]
