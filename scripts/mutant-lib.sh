# Sourced by mutants.sh and mutants-fresh.sh: how a mutant file is read.
mut_key() {    # mut_key FILE KEY: the value of `KEY: ...` in a mutant file
    sed -n "s/^$2: //p" "$1"
}
text_count() { # text_count FILE TEXT: how often TEXT occurs in FILE, verbatim
    FIND="$2" perl -0ne '$c = () = /\Q$ENV{FIND}\E/g; print $c' "$1" 2>/dev/null || echo 0
}
