#!/bin/sh
# An interrupted sweep resumes where it stopped: kill a sweep mid-way, run
# it again with --resume, and compare with an uninterrupted run (bytes);
# the resumed run must report realisations taken from the checkpoint.
set -u
bin=${1:-build/slipfield}
tmp=$(mktemp -d /tmp/sf-resume.XXXXXX)
trap 'rm -rf "$tmp"' EXIT INT TERM
printf 'T = 30\nt_skip = 10\ncells = 8\nrtol = 1e-6\n' > "$tmp/s.scene"
args="sweep $tmp/s.scene --param l_over_R --values 1 --realisations 200 --threads 2"
"$bin" $args --out "$tmp/full.tsv" 2>/dev/null || { echo "resume-test: the reference sweep failed" >&2; exit 1; }
"$bin" $args --out "$tmp/cut.tsv" 2>/dev/null &
pid=$!
# kill once a few realisations are checkpointed (poll: no timing assumption)
for _ in $(seq 1 600); do
    n=0
    [ -f "$tmp/cut.tsv.ckpt0" ] && n=$(wc -l < "$tmp/cut.tsv.ckpt0")
    [ "$n" -ge 6 ] && break
    sleep 0.05
done
kill -TERM $pid 2>/dev/null
wait $pid 2>/dev/null
[ -e "$tmp/cut.tsv" ] && { echo "resume-test: a killed sweep left its output as if complete" >&2; exit 1; }
[ -s "$tmp/cut.tsv.ckpt0" ] || { echo "resume-test: no checkpoint after the kill (too fast? raise the work)" >&2; exit 1; }
"$bin" $args --out "$tmp/cut.tsv" --resume 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
grep -q "from the checkpoint" "$tmp/err" || { echo "resume-test: nothing was taken from the checkpoint" >&2; exit 1; }
cmp "$tmp/full.tsv" "$tmp/cut.tsv" || { echo "resume-test: the resumed sweep differs from the uninterrupted one" >&2; exit 1; }
[ ! -e "$tmp/cut.tsv.ckpt0" ] || { echo "resume-test: the checkpoint outlived the completed sweep" >&2; exit 1; }
echo "resume-test: $(sed -n 's/.*: \([0-9]* of [0-9]*\) realisations from the checkpoint/\1/p' "$tmp/err") realisations resumed, output identical"
