#!/bin/sh
# make test: no reference in the repository points at a file it does not
# have.  Every path under one of the tree's own folders (docs/, cases/,
# scripts/, tests/, solver/, verification/, cli/, bench/, examples/) that
# the C sources mention in a comment, or that a case, document, script,
# mutant or the Makefile mentions anywhere, must exist: as written, or with
# the extension a reader would add (.md for a case id, .c/.h for a module,
# .mut for a mutant, .sh for a script); a glob (cases/plan/qoi-tol*.md)
# must match something, and a{b,c} expands.  A path a script builds
# (tests/fuzz/fuzz_$t.c) is not a reference.  The design document is
# docs/design.md: a citation of DESIGN.md anywhere is dangling too.  Not read:
# generated trees (build/, reports/ but its README) and inputs that are
# wrong on purpose (tests/bad-input/, tests/fuzz/).
set -u
cd "$(dirname "$0")/.." || exit 3
files=$(git ls-files 2>/dev/null | grep -vE '^(build|tests/bad-input|tests/fuzz)/|^reports/[^R]' |
        grep -E '\.(c|h|md|sh|mut|gp|in)$|(^|/)Makefile$')
[ -n "$files" ] || { echo "refs-check: no tracked files (not a git checkout?)" >&2; exit 3; }
# paths named as examples or as absent on purpose, with the reason
allowed='cli/x.h tests/bad-input/no-such-file.scene cases/zzz*.md cases/}'   # layering.sh: a pattern; bad-input.sh: a missing file;
# budget-test.sh: a glob that must match nothing; false-alarm.sh: the shell's ${f#cases/}

# "LINE:TEXT" for the comments of a C file (strings and characters skipped)
c_comments() {
    awk '{ out = ""; n = length($0); i = 1
           while (i <= n) {
               c = substr($0, i, 1); d = substr($0, i, 2)
               if (inc) { if (d == "*/") { inc = 0; i += 2; out = out " "; continue } out = out c; i++; continue }
               if (q != "") { if (c == "\\") { i += 2; continue } if (c == q) q = ""; i++; continue }
               if (d == "/*") { inc = 1; i += 2; continue }
               if (d == "//") { out = out substr($0, i + 2); break }
               if (c == "\"" || c == "\047") q = c
               i++
           }
           q = ""
           if (out != "") print NR ":" out }' "$1"
}
exists() {   # exists PATH: as written, with a usual extension, or as a glob
    case $1 in
    *'{'*'}'*)
        pre=${1%%\{*}; rest=${1#*\{}; alts=${rest%%\}*}; post=${rest#*\}}
        old_ifs=$IFS; IFS=,
        set -- $alts
        IFS=$old_ifs
        for a in "$@"; do exists "$pre$a$post" || return 1; done
        return 0 ;;
    *'*'*|*'?'*)
        for g in $1; do [ -e "$g" ] && return 0; done; return 1 ;;
    esac
    for e in "" .md .c .h .mut .sh; do [ -e "$1$e" ] && return 0; done
    return 1
}
re='(^|[^A-Za-z0-9_./$-])(docs|cases|scripts|tests|solver|verification|cli|bench|examples)/[A-Za-z0-9_./*{},-]*[$%<]?'
out=$(for f in $files; do
    case $f in
    *.c|*.h) c_comments "$f" ;;
    *) grep -n '' "$f" ;;
    esac | grep -oE "^[0-9]+:|$re" |
        awk -v f="$f" '/^[0-9]+:$/ { line = substr($0, 1, length($0) - 1); next }
                       { m = $0; if (m !~ /^[A-Za-z]/) m = substr(m, 2)
                         if (m ~ /[$%<]$/) next      # a path the code builds
                         print f ":" line, m }'
done
# any text of any tracked file (fuzz seeds and C strings too) but this one
git grep -n 'DESIGN\.md' -- . ':!scripts/refs-check.sh' | awk -F: '{ print $1 ":" $2, "DESIGN.md" }')
bad=0; n=0
while read -r where p; do
    [ -n "$where" ] || continue
    n=$((n + 1))
    p=$(printf '%s' "$p" | sed 's/[.,]*$//')
    case " $allowed " in *" $p "*) continue ;; esac
    if [ "$p" = DESIGN.md ]; then
        echo "refs-check: $where cites DESIGN.md: the design document is docs/design.md" >&2; bad=$((bad + 1))
    elif ! exists "$p"; then
        echo "refs-check: $where mentions $p, which the repository does not have" >&2; bad=$((bad + 1))
    fi
done <<EOT
$out
EOT
if [ $bad -ne 0 ]; then
    echo "refs-check: $bad dangling reference(s) among $n" >&2
    exit 1
fi
echo "refs-check: $n references to the tree's own files, all present"
