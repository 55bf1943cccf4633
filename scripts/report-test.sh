#!/bin/sh
# Tests of what CI and people read (run after `make verify` and
# `make test`): reports/junit.xml and CMocka's JUnit files validate against
# tests/junit.xsd (xmllint); every case report opens with Claim, Test,
# Result and ends with its history (docs/reports.md); Debian's headless Chromium renders
# reports/index.html and one case page; each screenshot must not be blank
# (pixel variance, read back with gnuplot), the pages must have no broken
# image (checked in the rendered DOM) and no link to a missing file.
set -u
root=${1:-reports}
cd "$(dirname "$0")/.." || exit 3
sh scripts/deps.sh chromium libxml2-utils || exit 1
[ -f "$root/index.html" ] || { echo "browser: $root/index.html missing: run 'make verify' first" >&2; exit 2; }
work=$(mktemp -d /tmp/sf-browser.XXXXXX)
trap 'rm -rf "$work"' EXIT INT TERM
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok    $*"; }
bad() { fail=$((fail + 1)); echo "FAIL  $*"; }

chrome() {  # chrome OUTFLAG URL
    timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$work/profile$$" --window-size=1200,1600 --virtual-time-budget=5000 \
        "$@" 2>/dev/null
}

for x in "$root/junit.xml" build/test-results/*.xml; do
    [ -f "$x" ] || continue
    if xmllint --noout --schema tests/junit.xsd "$x" 2>"$work/xmllint.log"; then ok "$x: valid JUnit XML"
    else bad "$x: not valid JUnit XML"; sed 's/^/      /' "$work/xmllint.log" | head -5; fi
done

# Every case report opens with Claim, Test, Result (docs/reports.md): the
# first paragraph after the title is **Claim...**, a test paragraph
# (**Test**, **The test**, **How**, **Tolerance** or **Check**) and then
# **Result.** come before the results table, and "History and studies",
# when there, is the last section.  Prints what is wrong, nothing if right.
layout() {
    awk '
        NR == 1 { if ($0 !~ /^# /) { print "no title"; bad = 1; exit } next }
        !claim && /^$/ { next }
        !claim { if ($0 !~ /^\*\*Claim/) { print "first paragraph is not **Claim**"; bad = 1; exit } claim = NR; next }
        /^## Results/ && !results { results = NR }
        !results && !test && /^\*\*(Test|The test|How|Tolerance|Check)/ { test = NR }
        !results && test && !result && /^\*\*Result\.\*\* / { result = NR }
        /^## / { last = $0; if ($0 == "## History and studies") hist = NR }
        END {
            if (bad) exit
            if (!test || !result || !results)
                printf "missing before ## Results:%s%s%s\n", test ? "" : " Test", result ? "" : " Result", results ? "" : " (no ## Results)"
            else if (hist && last != "## History and studies") print "History and studies is not the last section"
        }' "$1"
}
# the check itself: a right report passes, each wrong one is named
printf '# T\n\n**Claim.** c\n\n**Tolerance.** t\n\n**Result.** **PASS**: r\n\n## Results\n\n## History and studies\n\nh\n' > "$work/good.md"
printf '# T\n\n**Claim.** c\n\n**Result.** **PASS**: r\n\n**Check.** x\n\n## Results\n' > "$work/order.md"
printf '# T\n\n**Claim.** c\n\n**Test.** t\n\n**Result.** **PASS**: r\n\n## Results\n\n## History and studies\n\n## Scene\n' > "$work/hist.md"
printf '# T\n\nA paragraph.\n\n**Test.** t\n\n**Result.** **PASS**: r\n\n## Results\n' > "$work/noclaim.md"
if [ -z "$(layout "$work/good.md")" ] && [ -n "$(layout "$work/order.md")" ] && [ -n "$(layout "$work/hist.md")" ] &&
   [ -n "$(layout "$work/noclaim.md")" ]; then ok "the layout check passes a right report and names three wrong ones"
else bad "the layout check: good '$(layout "$work/good.md")', order '$(layout "$work/order.md")', history '$(layout "$work/hist.md")', no claim '$(layout "$work/noclaim.md")'"; fi
nrep=0; badrep=0
for md in "$root"/*/*/report.md; do
    [ -f "$md" ] || continue
    nrep=$((nrep + 1))
    why=$(layout "$md")
    if [ -n "$why" ]; then badrep=$((badrep + 1)); echo "      $md: $why"; fi
done
if [ "$nrep" -gt 0 ] && [ "$badrep" -eq 0 ]; then ok "$nrep case reports open with Claim, Test, Result; History last"
else bad "case reports' opening block: $badrep of $nrep wrong"; fi

case_page=$(sed -n 's/.*href="\([^"]*report\.html\)".*/\1/p' "$root/index.html" | head -n 1)
[ -n "$case_page" ] || { bad "index.html links to no case page"; echo "browser: $pass passed, $fail failed"; exit 1; }

for page in index.html "$case_page"; do
    file="$(cd "$root" && pwd)/$page"
    url="file://$file"
    shot="$work/shot.png"
    rm -f "$shot"
    chrome --screenshot="$shot" "$url" >/dev/null
    if [ ! -s "$shot" ]; then
        bad "$page: no screenshot"
        continue
    fi
    gnuplot -e "set table '$work/px.txt'; plot '$shot' binary filetype=png with rgbimage" 2>/dev/null
    var=$(awk 'NF >= 5 && $1 != "#" { n++; s += $3 + $4 + $5; q += ($3 + $4 + $5)^2 }
               END { if (n) printf "%.3f", q / n - (s / n)^2; else print 0 }' "$work/px.txt")
    if awk -v v="$var" 'BEGIN { exit !(v > 10) }'; then ok "$page: screenshot not blank (pixel variance $var)"
    else bad "$page: screenshot blank (pixel variance $var)"; fi

    dom=$(chrome --dump-dom "$url")
    broken=$(printf '%s' "$dom" | sed -n 's/.*data-broken-images="\([0-9]*\)".*/\1/p' | head -n 1)
    imgs=$(printf '%s' "$dom" | sed -n 's/.*data-images="\([0-9]*\)".*/\1/p' | head -n 1)
    if [ "$broken" = 0 ]; then ok "$page: no broken image ($imgs images)"
    else bad "$page: broken images: '${broken:-page did not load}'"; fi
    if [ "$page" != index.html ] && [ "${imgs:-0}" -lt 1 ]; then bad "$page: a case page without a plot"; fi

    dir=$(dirname "$file")
    missing=0
    for href in $(grep -o 'href="[^"]*"' "$file" | sed 's/href="\(.*\)"/\1/'); do
        case "$href" in http:*|https:*|mailto:*|\#*) continue ;; esac
        [ -e "$dir/${href%%#*}" ] || { missing=$((missing + 1)); echo "      missing link target: $href"; }
    done
    for src in $(grep -o 'src="[^"]*"' "$file" | sed 's/src="\(.*\)"/\1/'); do
        [ -e "$dir/$src" ] || { missing=$((missing + 1)); echo "      missing image: $src"; }
    done
    if [ $missing -eq 0 ]; then ok "$page: every link and image resolves"; else bad "$page: $missing dead links"; fi
done
echo "reports: $pass passed, $fail failed"
[ $fail -eq 0 ]
