#!/bin/sh
# Layering (issue 16): the solver library must not include the harness or
# the CLI, the harness must not include the CLI.  tests/ and bench/ may
# include everything.  The compile rules enforce this too (per-directory
# -I flags in the Makefile); this check names the offending line and also
# catches a relative path ("../cli/cli.h") that -I would not stop.
#   solver/        may include solver/ only
#   verification/  may include solver/ and verification/ (and build/gen)
#   solver/        no include cycle between its modules
# Exit 1 on an upward include or a cycle.
set -u
cd "$(dirname "$0")/.."
st=0
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
    echo "layering: solver/ -> solver/ only, no include cycle; verification/ -> solver/, verification/: ok"
else
    echo "layering: an upward #include or an include cycle (see above)" >&2
fi
exit $st
