#!/bin/sh
# make layering: the include rules, each error naming the file, the line
# and the rule it breaks.  tests/ and bench/ may include everything.  The
# compile rules enforce this too (per-directory -I flags in the Makefile);
# this check names the offending line and also catches a relative path
# ("../cli/cli.h") that -I would not stop.
#   solver/        may include solver/ only
#   solver/<layer>/ may include its own folder and the layers below it,
#                  in the order of solver/LAYERS (bottom up; header names
#                  are unique across solver/, so a name maps to one
#                  folder); the top of solver/ (slipfield.h, model.c)
#                  may include every layer
#   verification/  may include solver/ and verification/ (and build/gen)
#   solver/        no include cycle between its modules
# Exit 1 on an upward include or a cycle.
#   sh scripts/layering.sh [ROOT]   check the tree at ROOT (default: this
#                                   one; the layering test of make test
#                                   seeds defects in a copy)
set -u
cd "${1:-$(dirname "$0")/..}" || exit 2
st=0
layers=$(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' solver/LAYERS)
[ -n "$layers" ] || { echo "layering: solver/LAYERS lists no layer" >&2; exit 2; }
for l in $layers; do
    [ -d "solver/$l" ] || { echo "layering: solver/LAYERS names solver/$l, which does not exist" >&2; st=1; }
done
for d in $(find solver -mindepth 1 -type d | sort); do
    case " $(echo $layers) " in *" $(basename "$d") "*) ;; *)
        echo "layering: $d is not a layer of solver/LAYERS (add it there, in its place bottom up)" >&2; st=1 ;; esac
done
# $1 = directory, $2 = extended regex of headers it must not include
check() {
    dir=$1 bad=$2 why=$3
    hits=$(find "$dir" -name '*.[ch]' -exec grep -HnE "^[[:space:]]*#[[:space:]]*include[[:space:]]*[\"<]($bad)" {} + 2>/dev/null)
    if [ -n "$hits" ]; then
        printf '%s\n' "$hits" | sed "s|\$| <- $why|" >&2
        st=1
    fi
}
hdrs() {  # the header names of directory $1, as an alternation
    find "$1" -name '*.h' -exec basename {} \; | sort -u | sed 's/\./\\./g' | paste -sd'|' -
}
vh=$(hdrs verification) ch=$(hdrs cli) th=$(hdrs tests) bh=$(hdrs bench)
# an upward include by path (../verification/x.h, cli/x.h) or by a name
# that lives only upstairs (result.h, cli.h, ...)
check solver "([.]*/)*(verification|cli|tests|bench)/|$vh|$ch|$th|$bh|sf_rev\.h|plot_style\.h" "solver/ includes only solver/"
check verification "([.]*/)*(cli|tests|bench)/|$ch|$th|$bh" "verification/ must not include cli/, tests/ or bench/"
# Inside solver/: each header name belongs to one folder (names are
# unique: the #includes are bare names, found by the -I flags), and a file
# of layer i includes only headers of layers 0..i.  "name rank folder"
# lines; rank 0 is the bottom layer, the top of solver/ ranks above all.
rank=0 map=""
for l in $layers; do
    map="$map$(find "solver/$l" -maxdepth 1 -name '*.h' -exec basename {} \; | sed "s|\$| $rank solver/$l|")
"
    rank=$((rank + 1))
done
top=$rank
map="$map$(find solver -maxdepth 1 -name '*.h' -exec basename {} \; | sed "s|\$| $top solver|")"
dup=$(printf '%s\n' "$map" | awk 'NF { n[$1]++; d[$1] = d[$1] " " $3 } END { for (h in n) if (n[h] > 1) print h ":" d[h] }')
if [ -n "$dup" ]; then
    printf 'layering: a header name in two solver folders (the bare #include would be ambiguous): %s\n' "$dup" >&2
    st=1
fi
order=$(echo $layers | sed 's/ / < /g')
up=$(for f in $(find solver -name '*.[ch]' | sort); do
    d=$(dirname "$f")
    r=$(printf '%s\n' "$map" | awk -v d="$d" '$3 == d { print $2; exit }')
    [ -n "$r" ] || r=$top
    grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$f" |
        sed -n 's/^\([0-9]*\):[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1 \2/p' |
        while read -r line h; do
            printf '%s\n' "$map" | awk -v h="$h" -v r="$r" -v f="$f" -v line="$line" -v d="$d" -v order="$order" '
                $1 == h { found = 1
                          if ($2 > r) printf "%s:%d: #include \"%s\" (%s) <- %s/ includes only its own folder and the layers below (solver/LAYERS: %s)\n", f, line, h, $3, d, order }
                END { if (!found && h !~ /\//) printf "%s:%d: #include \"%s\" <- not a header of solver/: %s/ includes only solver/\n", f, line, h, d }'
        done
done)
if [ -n "$up" ]; then
    printf '%s\n' "$up" >&2
    st=1
fi
# Inside solver/, the modules (x.c with x.h) include each other without a
# cycle: a plan flows one way, scene -> numplan (the plan, made first) ->
# the builders (cof, oscillator, ...); numplan.c asking cof.c for the
# strip while cof.c asks numplan.c for the model was such a cycle.
edges=$(for f in $(find solver -name '*.[ch]' | sort); do
    m=$(basename "$f"); m=${m%.*}
    sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([A-Za-z0-9_]*\)\.h".*/\1/p' "$f" |
        while read -r d; do [ "$d" != "$m" ] && echo "$m $d"; done
done | sort -u)
if ! printf '%s\n' "$edges" | tsort >/dev/null 2>&1; then
    cyc=$(printf '%s\n' "$edges" | tsort 2>&1 >/dev/null | sed -n 's/^tsort: \([A-Za-z0-9_]*\)$/\1/p' | paste -sd' ' -)
    echo "solver/: an include cycle among the modules: $cyc <- the plan must flow one way (numplan -> builders)" >&2
    st=1
fi
if [ $st -eq 0 ]; then
    echo "layering: solver/ -> solver/ only, each layer -> itself and below ($order), no include cycle; verification/ -> solver/, verification/: ok"
else
    echo "layering: an upward #include or an include cycle (see above)" >&2
fi
exit $st
