#!/bin/sh
# Layering (issue 16): the solver library must not include the harness or
# the CLI, the harness must not include the CLI.  tests/ and bench/ may
# include everything.  The compile rules enforce this too (per-directory
# -I flags in the Makefile); this check names the offending line and also
# catches a relative path ("../cli/cli.h") that -I would not stop.
#   solver/        may include solver/ only
#   verification/  may include solver/ and verification/ (and build/gen)
# Exit 1 on an upward include.
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
if [ $st -eq 0 ]; then
    echo "layering: solver/ -> solver/ only; verification/ -> solver/, verification/: ok"
else
    echo "layering: upward #include (see above)" >&2
fi
exit $st
