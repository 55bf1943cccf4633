#!/bin/sh
# make test: the command line as people use it.  Outputs: a regular file is
# replaced atomically, a character device, a FIFO or a link such as
# /dev/stdout is written in place and stays what it was, the input scene is
# never overwritten; exit statuses (2 with the reason for what the user
# fixes: usage, size cap, a disc off its strip, T <= t_skip, a full device,
# stdout on a full device); an interrupted sweep; help; getopt_long habits;
# ignored scene keys; the report's Re-run line.
# Safe as root: /dev is only written after the same test passed on a copy
# of the node made here (mknod), so a regression replaces the copy, never
# /dev/null, /dev/full or /dev/stdout.
set -u
sf_name=cli
. "$(dirname "$0")/common.sh"
bin=${1:-build/slipfield}
case $bin in /*) ;; *) bin=$top/$bin ;; esac
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "cli-test: FAIL $*" >&2; }
# expect STATUS FRAGMENT CMD...: exit status and a fragment of stderr
expect() {
    want=$1 frag=$2; shift 2
    "$@" > "$tmp/out" 2> "$tmp/err"; rc=$?
    if [ $rc -eq "$want" ] && { [ -z "$frag" ] || grep -qF -- "$frag" "$tmp/err"; }; then ok
    else bad "'$*': exit $rc (want $want), stderr: $(head -c 300 "$tmp/err") (want '$frag')"; fi
}
# err_has / err_lacks FRAGMENT WHAT: the last expect's stderr
err_has()   { grep -qF -- "$1" "$tmp/err" && ok || bad "$2: no '$1' in: $(head -c 600 "$tmp/err")"; }
err_lacks() { grep -qF -- "$1" "$tmp/err" && bad "$2: '$1' in: $(head -c 600 "$tmp/err")" || ok; }
cd "$tmp" || exit 1
printf 'cof = uniform\nntheta = 5\nnpsi = 4\n' > s.scene   # 20 surface rows
cp s.scene s.orig
rows=21   # header + 5 x 4

# ---- outputs ----------------------------------------------------------------
expect 0 "" "$bin" surface s.scene --out new.tsv
[ "$(wc -l < new.tsv)" -eq $rows ] && [ -z "$(ls | grep '\.tmp')" ] && ok || bad "a new file: $(wc -l < new.tsv) rows"
ln -s new.tsv link.tsv
expect 0 "" "$bin" surface s.scene --out link.tsv
[ -L link.tsv ] && [ "$(wc -l < new.tsv)" -eq $rows ] && ok || bad "a symbolic link was replaced"
# the input scene, by its name, by a hard link, through a symbolic link
ln s.scene hard.scene; ln -s s.scene soft.scene
for o in s.scene hard.scene soft.scene; do
    expect 2 "is the input scene" "$bin" surface s.scene --out $o
done
cmp -s s.scene s.orig && [ -L soft.scene ] && ok || bad "the input scene was changed"

# character devices and a link to stdout: copies first (see the header).
# Not root: the real nodes (a rename over them would fail, not replace
# them).  Root without mknod here: no device is tested.
devnull=/dev/null devfull=/dev/full devices=1
if [ "$(id -u)" = 0 ]; then
    if mknod null c 1 3 2>/dev/null && mknod full c 1 7 2>/dev/null && echo x > null; then
        devnull=$tmp/null devfull=$tmp/full
    else
        echo "cli-test: cannot make device nodes under $tmp: character devices not tested" >&2
        devices=0
    fi
fi
ln -s /proc/self/fd/1 stdout-link
copies_ok=$devices
check_dev() {   # check_dev PATH: written in place, still a character device
    expect 0 "" "$bin" surface s.scene --out "$1"
    if [ -c "$1" ] && [ -z "$(ls "$(dirname "$1")" | grep "$(basename "$1")\.tmp")" ]; then ok
    else bad "$1 is no longer a character device (or a temporary file was left)"; copies_ok=0; fi
}
check_full() {  # check_full PATH: exit 2 with the reason, still a device
    expect 2 "No space left on device" "$bin" surface s.scene --out "$1"
    [ -c "$1" ] && ok || { bad "$1 is no longer a character device"; copies_ok=0; }
}
if [ $devices = 1 ]; then
    check_dev "$devnull"
    check_full "$devfull"
fi
n=$("$bin" surface s.scene --out stdout-link | wc -l)
[ "$n" -eq $rows ] && [ -L stdout-link ] && ok || { bad "--out a link to stdout: $n rows, link kept: $([ -L stdout-link ] && echo yes || echo no)"; copies_ok=0; }
# stdout redirected to a file (appending): the output goes through stdout's own offset
echo first > app.tsv
"$bin" surface s.scene --out stdout-link >> app.tsv
[ "$(wc -l < app.tsv)" -eq $((rows + 1)) ] && [ "$(head -1 app.tsv)" = first ] && ok || bad "--out a link to stdout, appended: $(wc -l < app.tsv) lines"
if [ "$devnull" != /dev/null ] && [ $copies_ok = 1 ]; then   # the real nodes, now that the copies are safe
    check_dev /dev/null
    check_full /dev/full
    n=$("$bin" surface s.scene --out /dev/stdout | wc -l)
    [ "$n" -eq $rows ] && [ -L /dev/stdout ] && ok || bad "--out /dev/stdout: $n rows"
fi
# stdout on a full device, --out - and the default
if [ $devices = 1 ]; then   # (a shell redirection: in place, whatever the program does)
    expect 2 "error writing stdout: No space left on device" sh -c '"$0" surface s.scene > "$1"' "$bin" "$devfull"
    expect 2 "error writing stdout: No space left on device" sh -c '"$0" surface s.scene --out - > "$1"' "$bin" "$devfull"
fi
# a FIFO: its reader gets every row
mkfifo fifo
timeout 30 cat fifo > from-fifo & reader=$!
expect 0 "" timeout 30 "$bin" surface s.scene --out fifo
wait $reader
[ -p fifo ] && [ "$(wc -l < from-fifo)" -eq $rows ] && ok || bad "FIFO: $(wc -l < from-fifo) rows read, still a FIFO: $([ -p fifo ] && echo yes || echo no)"
# a folder, a folder that does not exist
mkdir dir
expect 2 "Is a directory" "$bin" surface s.scene --out dir
expect 2 "cannot write" "$bin" surface s.scene --out no/such/dir/x.tsv
[ -z "$(find . -name '*.tmp*')" ] && ok || bad "temporary files left: $(find . -name '*.tmp*')"

# ---- exit statuses --------------------------------------------------------
expect 2 "unknown option: --bogus" "$bin" surface s.scene --bogus
expect 2 "" "$bin" nosuchcommand
printf 'nx = 1000000\nny = 1000000\n' > big.scene
expect 2 "over the size cap" "$bin" field big.scene --out big.tsv
[ ! -e big.tsv ] && ok || bad "the refused field left big.tsv"
printf 'cof = field\nstrip_halfwidth = 0.0001\ny0 = 0.05\nT = 15\nt_skip = 0\ncells = 8\n' > strip.scene
expect 2 "left the belt strip" "$bin" run strip.scene --out strip.tsv --summary strip.txt
[ ! -e strip.tsv ] && [ ! -e strip.txt ] && ok || bad "the failed run left its outputs"
# the scene's samples obeys the cap of --realisations: refused at once, file:line
printf 'cof = uniform\nsamples = 1e9\n' > many.scene
expect 2 "many.scene:2: key 'samples': must be >= 1 and <= 1e+07" timeout 10 "$bin" sweep many.scene --param T --values 20 --out many.tsv
expect 2 "--realisations takes a whole number from 1 to 10000000" "$bin" sweep many.scene --param T --values 20 --realisations 1e9 --out many.tsv
printf 'cof = uniform\nT = 30\nt_skip = 10\n' > sw.scene
expect 2 "not above t_skip" "$bin" sweep sw.scene --param T --values 40,5 --realisations 2 --out sw.tsv
[ ! -e sw.tsv ] && ok || bad "the refused sweep left sw.tsv"
expect 2 "in [t_skip, T] (pv_x = nan): raise T" "$bin" sweep sw.scene --param T --values 12 --realisations 2 --out sw.tsv
# --param: a wrong name is named, with the nearest valid one and the list
expect 2 "unknown parameter 'l_over_r'; did you mean l_over_R?" "$bin" sweep sw.scene --param l_over_r --values 1 --realisations 2 --out sw.tsv
err_has "valid parameters: l_over_R, m, k, v_b, R, l, mu_mean" "--param: the valid names"
expect 2 "not a numeric scene key" "$bin" sweep sw.scene --param cof --values 1 --realisations 2 --out sw.tsv
# two stages: bad targets and pilots are refused before any work
for a in "--target-se 0" "--target-se -0.1" "--target-se nan" "--target-se x"; do
    expect 2 "--target-se" "$bin" sweep sw.scene --param T --values 20 --realisations 5 $a --out sw.tsv
done
expect 2 "--pilot needs --target-se or --estimator (not plain)" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --pilot 3 --out sw.tsv
expect 2 "--pilot takes a whole number from 2" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --target-se 0.1 --pilot 1 --out sw.tsv
expect 2 "the pilot needs 2 to 5" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --target-se 0.1 --pilot 6 --out sw.tsv
expect 2 "do not combine" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --target-se 0.1 --control-variate --out sw.tsv
expect 2 "--control-variate takes no value" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --control-variate=1 --out sw.tsv
expect 2 "--estimator takes plain, mlmc, mlmc-boxes, mlmc-sub, antithetic or auto" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator mc --out sw.tsv
expect 2 "does not combine" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator mlmc --control-variate --out sw.tsv
expect 2 "the pilot needs 2 to 5" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator mlmc --pilot 6 --out sw.tsv
expect 2 "need a plan that draws cell averages" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator mlmc-boxes --out sw.tsv
expect 2 "need a plan that draws point values" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator mlmc-sub --out sw.tsv
expect 2 "--estimator antithetic does not combine" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator antithetic --resume --out sw.tsv
expect 2 "the pilot needs 2 to 5" "$bin" sweep sw.scene --param T --values 20 --realisations 5 --estimator antithetic --pilot 6 --out sw.tsv
[ ! -e sw.tsv ] && ok || bad "a refused two-stage sweep left sw.tsv"
printf 'cof = variable\nT = 14\nt_skip = 4\n' > var.scene
expect 0 "" "$bin" sweep var.scene --param T --values 14 --realisations 6 --target-se 1e-9 --pilot 3 --out st.tsv --summary st.sum
[ "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "stop") c = i; if ($i == "n") n = i } } NR == 2 { print $n, $c }' st.sum)" = "6 cap" ] \
    && ok || bad "two-stage sweep at the cap: $(cat st.sum)"
# antithetic pairs: one variable per realisation, the pairs in the summary
expect 0 "" "$bin" sweep var.scene --param T --values 14 --realisations 6 --estimator antithetic --pilot 3 --out an.tsv --diagnostics an.diag
[ "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "anti_n") c = i } NR == 2 { print ($c >= 3 && $c <= 6) }' an.diag)" = "1" ] \
    && ok || bad "antithetic sweep: anti_n: $(cat an.diag)"
expect 0 "" "$bin" sweep var.scene --param T --values 14 --realisations 6 --estimator auto --pilot 3 --out au.tsv --summary au.sum
[ "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "estimator") c = i } NR == 2 { print $c }' au.sum)" = "antithetic" ] \
    && ok || bad "auto sweep on one variable: the estimator column: $(cat au.sum)"
# off a terminal: one line per point on stderr, and stdout is the table alone
expect 0 "slipfield sweep: point 1/2 (T = 14): 6 realisations in" "$bin" sweep var.scene --param T --values 14,15 --realisations 6 --out pt.tsv
err_has "slipfield sweep: point 2/2 (T = 15): 6 realisations in" "sweep: the second point's line"
[ "$(grep -c '^slipfield sweep: point [0-9]*/2 ' "$tmp/err")" -eq 2 ] && [ ! -s "$tmp/out" ] && ok \
    || bad "sweep off a terminal: not one line per point, or stdout not empty: $(cat "$tmp/err")"
expect 0 "point 2/2" "$bin" sweep var.scene --param T --values 14,15 --realisations 6 --out -
cmp -s "$tmp/out" pt.tsv && ok || bad "sweep --out -: stdout is not the table alone"
if script --version 2>/dev/null | grep -q util-linux; then   # on a terminal: the live count, no point lines
    script -qec "'$bin' sweep var.scene --param T --values 14,15 --realisations 6 --out pt.tsv" /dev/null > "$tmp/err" 2>&1 < /dev/null
    err_has "T = 15: 6/6 realisations" "sweep on a terminal: live count"
    err_lacks "point 1/2" "sweep on a terminal: a point line"
fi
# an estimator at a target standard error: met (stop target), or held at the cap (said)
expect 0 "" "$bin" sweep var.scene --param T --values 14 --realisations 40 --estimator antithetic --pilot 3 --target-se 0.05 --out at.tsv --summary at.sum
[ "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "stop") c = i } NR == 2 { print $c }' at.sum)" = "target" ] \
    && ok || bad "antithetic sweep at a target: stop: $(cat at.sum)"
expect 0 "is below what the estimator's sizing says --target-se 1e-09 needs" "$bin" sweep var.scene --param T --values 14 --realisations 6 --estimator antithetic --pilot 3 --target-se 1e-9 --out at.tsv --summary at.sum
[ "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "stop") c = i; if ($i == "n") n = i } } NR == 2 { print $n, $c }' at.sum)" = "6 cap" ] \
    && ok || bad "antithetic sweep at the cap: $(cat at.sum)"
# the summary: one answer per ratio and point, whatever the estimator; the diagnostics beside it
printf 'cof = field\nT = 20\nt_skip = 10\n' > sum.scene
expect 0 "" "$bin" sweep sum.scene --param l_over_R --values 0.5,2 --realisations 8 --threads 1 --out pl.tsv \
    --summary pl.sum --diagnostics pl.diag
# (a column none of whose rows holds a number)
nancols() { awk -F'\t' 'NR == 1 { nf = NF; for (i = 1; i <= NF; i++) h[i] = $i; next }
    { for (i = 1; i <= NF; i++) if ($i !~ /^-?nan$/) seen[i] = 1 }
    END { for (i = 1; i <= nf; i++) if (!seen[i]) printf "%s ", h[i] }' "$1"; }
[ "$(wc -l < pl.sum)" -eq 3 ] && [ -z "$(nancols pl.sum)" ] && ok || bad "a plain sweep's summary: all-nan columns: $(nancols pl.sum)"
[ "$(head -1 pl.sum)" = "$(printf 'param\tvalue')$(for q in pv_x pv_F stick_fraction; do
    printf '\t%s_ratio_estimate[-]\t%s_ratio_se[-]\t%s_ratio_ci95_lo[-]\t%s_ratio_ci95_hi[-]\t%s_ratio_u_num[-]' $q $q $q $q $q
    done)$(printf '\tn\testimator\tstop')" ] && ok || bad "a plain sweep's summary header: $(head -1 pl.sum)"
# plain: the estimate is the diagnostics' ratio mean, its interval the Student one
[ "$(awk -F'\t' 'NR == FNR && FNR == 1 { for (i = 1; i <= NF; i++) if ($i == "pv_F_ratio_estimate[-]") e = i; next }
    NR == FNR { v[FNR] = $e; next } FNR == 1 { for (i = 1; i <= NF; i++) if ($i == "pv_F_ratio_mean[-]") m = i; next }
    { print (v[FNR] == $m) }' pl.sum pl.diag | tr -d '\n')" = "11" ] && ok || bad "plain: estimate is not the ratio mean"
# the diagnostics: the former summary's header, exactly
old=$(printf 'param\tvalue\tn')
for qu in pv_x:m pv_F:N stick_fraction:-; do q=${qu%:*} u=${qu#*:}
    old=$old$(printf '\t%s_n_used\t%s_n_excluded\t%s_mean[%s]\t%s_std[%s]\t%s_se[%s]\t%s_ci95_lo[%s]\t%s_ci95_hi[%s]\t%s_det[%s]\t%s_ratio_mean[-]\t%s_ratio_std[-]\t%s_ratio_se[-]\t%s_num_n\t%s_num_bias[%s]\t%s_num_bias_se[%s]\t%s_u_num_mean[%s]' \
        $q $q $q $u $q $u $q $u $q $u $q $u $q $u $q $q $q $q $q $u $q $u $q $u); done
old=$old$(printf '\tstop\tn_pilot')
for q in pv_x pv_F stick_fraction; do old=$old$(printf '\t%s_ratio_ci95_lo[-]\t%s_ratio_ci95_hi[-]' $q $q); done
for q in pv_x pv_F stick_fraction; do
    old=$old$(printf '\t%s_cv_ratio_mean[-]\t%s_cv_ratio_se[-]\t%s_cv_ratio_ci95_lo[-]\t%s_cv_ratio_ci95_hi[-]\t%s_cv_vrf[-]' $q $q $q $q $q); done
old=$old$(printf '\tml_n0\tml_n1\tml_cost0\tml_cost1\tml_cost_plain')
for q in pv_x pv_F stick_fraction; do
    old=$old$(printf '\t%s_ml_ratio_mean[-]\t%s_ml_ratio_se[-]\t%s_ml_ratio_ci95_lo[-]\t%s_ml_ratio_ci95_hi[-]\t%s_ml_var0[-]\t%s_ml_var1[-]\t%s_ml_vrf[-]' $q $q $q $q $q $q $q); done
old=$old$(printf '\tanti_n\tanti_cost\tanti_cost_plain')
for q in pv_x pv_F stick_fraction; do
    old=$old$(printf '\t%s_anti_n_used\t%s_anti_ratio_mean[-]\t%s_anti_ratio_se[-]\t%s_anti_ratio_ci95_lo[-]\t%s_anti_ratio_ci95_hi[-]\t%s_anti_rho[-]\t%s_anti_vrf[-]' $q $q $q $q $q $q $q); done
old=$old$(printf '\testimator')
[ "$(head -1 pl.diag)" = "$old" ] && [ "$(head -1 pl.diag | awk -F'\t' '{ print NF }')" -eq 122 ] && [ "$(wc -l < pl.diag)" -eq 3 ] \
    && ok || bad "--diagnostics: not the former summary's header: $(head -1 pl.diag)"
# auto: at l/R = 2 (circulant strip) two levels run; their estimate is the summary's, with n and work
expect 0 "" "$bin" sweep sum.scene --param l_over_R --values 0.5,2 --realisations 8 --estimator auto --threads 1 \
    --out au2.tsv --summary au2.sum --diagnostics au2.diag
[ "$(awk -F'\t' 'NR == FNR && FNR == 1 { for (i = 1; i <= NF; i++) { if ($i == "pv_x_ratio_estimate[-]") e = i; if ($i == "estimator") s = i }; next }
    NR == FNR { v[FNR] = $e; est[FNR] = $s; next } FNR == 1 { for (i = 1; i <= NF; i++) if ($i == "pv_x_ml_ratio_mean[-]") m = i; next }
    { print est[FNR], (v[FNR] == $m && $m != "nan") }' au2.sum au2.diag | sed -n 2p)" = "mlmc 1" ] \
    && ok || bad "auto at l/R = 2: the summary's estimate is not the two-level one: $(cat au2.sum)"
[ -z "$(nancols au2.sum)" ] && [ "$(awk -F'\t' 'NR == 1 { print $18, $19 }' au2.sum)" = "n work" ] \
    && ok || bad "auto: summary columns: $(head -1 au2.sum) (all nan: $(nancols au2.sum))"
# long: 3 rows per point, the wide form's numbers
expect 0 "" "$bin" sweep sum.scene --param l_over_R --values 0.5,2 --realisations 8 --estimator auto --threads 1 \
    --out au2.tsv --summary au2.long --summary-format long
[ "$(head -1 au2.long)" = "$(printf 'param\tvalue\tqoi\testimate\tse\tci_lo\tci_hi\tu_num\tn\testimator\tstop\tunit')" ] \
    && [ "$(wc -l < au2.long)" -eq 7 ] && ok || bad "long summary: $(cat au2.long)"
[ "$(awk -F'\t' 'NR > 1 { for (q = 0; q < 3; q++) print $1, $2, $(3 + 5 * q), $(4 + 5 * q), $(5 + 5 * q), $(6 + 5 * q), $(7 + 5 * q), $18, $20, $21 }' au2.sum)" \
    = "$(awk -F'\t' 'NR > 1 { print $1, $2, $4, $5, $6, $7, $8, $9, $10, $11 }' au2.long)" ] \
    && ok || bad "long summary: not the wide one's numbers"
expect 2 "--summary-format takes wide or long (got 'tall')" "$bin" sweep sum.scene --param l_over_R --values 2 \
    --realisations 8 --out x.tsv --summary x.sum --summary-format tall
expect 2 "--summary-format needs --summary" "$bin" sweep sum.scene --param l_over_R --values 2 --realisations 8 \
    --out x.tsv --summary-format long
# run: no QoI is said; no --out nor --summary prints the summary
printf 'cof = uniform\nT = 12\n' > t12.scene
expect 0 "warning: no quantity of interest" "$bin" run t12.scene
grep -q '^pv_x = nan' "$tmp/out" && ok || bad "run without --out/--summary: no summary on stdout"
# run refuses T <= t_skip as sweep does (t_skip defaults to 10 s), leaving nothing
printf 'cof = uniform\nT = 5\n' > t5.scene
expect 2 "t5.scene: T = 5 s is not above t_skip = 10 s" "$bin" run t5.scene --out t5.tsv --summary t5.sum
[ ! -e t5.tsv ] && [ ! -e t5.sum ] && [ ! -s "$tmp/out" ] && ok || bad "run at T <= t_skip left output"
printf 'cof = uniform\nT = 10\n' > t10.scene
expect 2 "T = 10 s is not above t_skip = 10 s" "$bin" run t10.scene --explain
# run --explain: a CV beyond the plan's calibrated range (0.05-1) is flagged, Table 1's is not
printf 'cof = field\nmu_mean = 0.5\nmu_std = 2\nT = 20\n' > cv4.scene
expect 0 "" "$bin" run cv4.scene --explain
grep -q "^plan warning: CV = mu_std / mu_mean = 4 is beyond the range the plan's error models were calibrated on (CV 0.05-1" \
    "$tmp/out" && ok || bad "run --explain at CV 4: no calibration warning: $(grep -i cv "$tmp/out")"
printf 'cof = field\nT = 20\n' > cv02.scene
expect 0 "" "$bin" run cv02.scene --explain
grep -q "beyond the range" "$tmp/out" && bad "run --explain at CV 0.2 warns of its CV" || ok
# run and sweep: an embedding at its padding cap is said (usable: exit 0)
printf 'l = 50\npad_cap = 1\nT = 20\n' > trunc.scene
expect 0 "warning: the COF field's circulant embedding reached its padding cap" "$bin" run trunc.scene --summary tr.sum
expect 0 "l = 50: warning: the COF field's circulant embedding reached its padding cap" "$bin" sweep trunc.scene \
    --param l --values 50 --realisations 2 --out tr.tsv
# sweep --control-variate on a tiled field: no companion, said
printf 'cof = field\ncof_generator = tiles\nT = 14\nt_skip = 4\ncells = 8\nrtol = 1e-6\n' > tcv.scene
expect 0 "warning: the field is a tiled window that follows the disc (cof_generator = tiles): no control-variate" \
    "$bin" sweep tcv.scene --param T --values 14 --realisations 2 --control-variate --out tcv.tsv

# ---- sweeps: the swept value overrides the scene's; interruption -------------
expect 0 "" "$bin" sweep sw.scene --param T --values 20 --realisations 2 --out T.tsv
[ "$(cut -f1,2 T.tsv | sed -n 2p)" = "T	20" ] && ok || bad "sweep --param T over a scene that sets T"
printf 'T = 30\nt_skip = 10\ncells = 8\nrtol = 1e-6\n' > long.scene
sweep="$bin sweep long.scene --param l_over_R --values 1 --realisations 5000 --threads 1 --out cut.tsv"
started() { for _ in $(seq 1 600); do [ -s cut.tsv.ckpt0 ] && return; sleep 0.05; done; }
$sweep 2> int.err & pid=$!; started; kill -INT $pid; wait $pid; rc=$?
[ $rc -eq 130 ] && grep -q "interrupted: rerun with --resume" int.err && [ -z "$(ls | grep 'cut\.tsv\.tmp')" ] && [ ! -e cut.tsv ] \
    && ok || bad "SIGINT: exit $rc, '$(cat int.err)', left: $(ls | grep cut)"
rm -f cut.tsv.ckpt0
$sweep 2> /dev/null & pid=$!; started; kill -KILL $pid; wait $pid 2> /dev/null
[ -n "$(ls | grep 'cut\.tsv\.tmp[0-9]')" ] && ok || bad "SIGKILL left no temporary file (the next check tests nothing)"
rm -f cut.tsv.ckpt0   # (a different sweep follows: its checkpoint would not match)
expect 0 "left by an interrupted run" $sweep --realisations 3 --resume --values 2
[ -z "$(ls | grep 'cut\.tsv\.tmp')" ] && ok || bad "--resume left: $(ls | grep 'cut\.tsv\.tmp')"

# ---- evaluate: an external design in, a row of results per design row out -------
printf 'cof = field\nT = 20\nt_skip = 10\nl = 0.5\n' > ev.scene
col() { awk -F'\t' -v n="$1" -v r="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i } NR == r + 1 && c { print $c }' "$3"; }
printf 'l_over_R\tmu_std\n1\t0.1\n0.6\t0.05\n1\t0.1\n' > ev.tsv
expect 0 "" "$bin" evaluate ev.scene --design ev.tsv --out ev1.tsv --threads 1
expect 0 "" "$bin" evaluate ev.scene --design ev.tsv --out ev2.tsv --threads 2
cmp -s ev1.tsv ev2.tsv && [ "$(wc -l < ev1.tsv)" -eq 4 ] && [ "$(cut -f12 ev1.tsv | grep -c "^ok$")" -eq 3 ] \
    && [ "$(head -1 ev1.tsv | cut -f1-6)" = "l_over_R	mu_std	pv_x[m]	pv_x_ratio[-]	u_pv_x[m]	pv_F[N]" ] \
    && ok || bad "evaluate: 1 and 2 threads differ, or rows or columns missing: $(cat ev1.tsv)"
# realisation 2: evaluate's row, run --realisation 2 (with and without a history) and the sweep's row 2, bit for bit
printf 'realisation\tl\n2\t0.5\n' > evr.tsv
expect 0 "" "$bin" evaluate ev.scene --design evr.tsv --out evr.out
expect 0 "" "$bin" run ev.scene --realisation 2 --summary evr.sum
expect 0 "" "$bin" run ev.scene --realisation 2 --out evr.hist --summary evrh.sum
expect 0 "" "$bin" sweep ev.scene --param l --values 0.5 --realisations 3 --out evs.tsv
a=$(col 'pv_x[m]' 1 evr.out) b=$(sed -n 's/^pv_x = //p' evr.sum) h=$(sed -n 's/^pv_x = //p' evrh.sum)
c=$(col 'pv_x[m]' 3 evs.tsv) d=$(col 'pv_x[m]' 3 ev1.tsv)
[ "$(col realisation 3 evs.tsv)" = 2 ] && [ -n "$a" ] && [ "$a" != nan ] && [ "$a" = "$b" ] && [ "$a" = "$h" ] \
    && [ "$a" = "$c" ] && [ "$a" = "$d" ] && [ -s evr.hist ] && ok \
    || bad "realisation 2: evaluate $a, run $b, run --out $h, sweep row 2 $c, default design row 2 $d"
[ "$(col 'pv_x_ratio[-]' 1 evr.out)" = "$(col pv_x_ratio 3 evs.tsv)" ] && grep -q '^realisation = 2$' evr.sum \
    && ok || bad "realisation 2: evaluate's ratio is not the sweep's, or run's summary does not name it"
expect 2 "--realisation takes a whole number from 0 to 9999999" "$bin" run ev.scene --realisation -1
# a seed column: the field run draws at that seed (realisation 2's stream seed: realisation 2's field)
printf 'seed\n%s\n' "$(sed -n 's/^stream_seed = //p' evr.sum)" > evseed.tsv
expect 0 "" "$bin" evaluate ev.scene --design evseed.tsv --out evseed.out
[ "$(col 'pv_x[m]' 1 evseed.out)" = "$a" ] && ok || bad "seed column: $(cat evseed.out), realisation 2: $a"
# bad input: exit 2 with file:line:column before any run, no output
printf 'l\tfoo\n0.5\t1\n' > evb.tsv
expect 2 "evb.tsv:1:3: unknown column 'foo'" "$bin" evaluate ev.scene --design evb.tsv --out evb.out
printf 'l\tmu_std\n0.5\t0.1\n0.5\t-1\n' > evb.tsv
expect 2 "evb.tsv:3:5: key 'mu_std': must be >= 0 (got -1)" "$bin" evaluate ev.scene --design evb.tsv --out evb.out
printf 'l\tmu_std\n0.5\tabc\n' > evb.tsv
expect 2 "evb.tsv:2:5: key 'mu_std': expected a finite number, got 'abc'" "$bin" evaluate ev.scene --design evb.tsv --out evb.out
printf 'realisation\tseed\n1\t2\n' > evb.tsv
expect 2 "evb.tsv:1: columns 'seed' and 'realisation' both choose" "$bin" evaluate ev.scene --design evb.tsv --out evb.out
printf 'l\tmu_std\n0.5\n' > evb.tsv
expect 2 "evb.tsv:2: 1 cell, the header has 2 columns" "$bin" evaluate ev.scene --design evb.tsv --out evb.out
expect 2 "is the design" "$bin" evaluate ev.scene --design evb.tsv --out evb.tsv
[ ! -e evb.out ] && [ "$(cat evb.tsv)" = "$(printf 'l\tmu_std\n0.5')" ] && ok || bad "a refused design left evb.out or changed the design"
# a row that fails fails alone: its status says why, the others are filled, exit 1
printf 'T\trealisation\n20\t0\n5\t1\n20\t2\n' > evf.tsv
expect 1 "evf.tsv:3: row 1 failed: T = 5 s is not above t_skip = 10 s" "$bin" evaluate ev.scene --design evf.tsv --out evf.out
[ "$(col status 1 evf.out)" = ok ] && [ "$(col status 3 evf.out)" = ok ] && [ "$(col status 2 evf.out)" != ok ] \
    && [ "$(col 'pv_x[m]' 3 evf.out)" = "$a" ] && [ "$(col 'pv_x[m]' 1 evf.out)" != nan ] \
    && ok || bad "evaluate with a failing row: $(cat evf.out)"

# ---- sensitivity: refusals leave nothing; bytes do not depend on the threads ---
printf 'cof = field\nT = 20\nt_skip = 2\ncells = 6\nrtol = 1e-6\nstrip_halfwidth = 0.05\n' > sa.scene
narrow="--log-lr -0.3,-0.2 --cv 0.15,0.25 --vb 0.2,0.25 --mu 0.45,0.55 --bootstrap 20"
expect 2 "--rows takes a whole number from 2" "$bin" sensitivity sa.scene --rows 1 --out sa.tsv
expect 2 "--level must be in (0, 1)" "$bin" sensitivity sa.scene --rows 2 --level 1.5 --out sa.tsv
expect 2 "expected a range LO,HI" "$bin" sensitivity sa.scene --rows 2 --cv 0.3,0.1 --out sa.tsv
expect 2 "expected a range LO,HI" "$bin" sensitivity sa.scene --rows 2 --vb 0.1 --out sa.tsv
expect 2 "mu_mean: the range must be positive" "$bin" sensitivity sa.scene --rows 2 --mu 0,1 --out sa.tsv
expect 2 "--rows and --out are required" "$bin" sensitivity sa.scene --rows 2
expect 2 "needs cof = field" "$bin" sensitivity sw.scene --rows 2 --out sa.tsv
printf 'cof = field\nT = 1.5\nt_skip = 1\n' > sshort.scene
expect 2 "raise T" "$bin" sensitivity sshort.scene --rows 2 $narrow --out sa.tsv
[ ! -e sa.tsv ] && [ -z "$(ls | grep 'sa\.tsv')" ] && ok || bad "a refused sensitivity study left $(ls | grep sa.tsv)"
expect 0 "" "$bin" sensitivity sa.scene --rows 2 $narrow --threads 1 --out sa1.tsv --evals se1.tsv
expect 0 "" "$bin" sensitivity sa.scene --rows 2 $narrow --threads 2 --out sa2.tsv --evals se2.tsv
cmp -s sa1.tsv sa2.tsv && cmp -s se1.tsv se2.tsv && [ "$(wc -l < sa1.tsv)" -eq 16 ] && [ "$(wc -l < se1.tsv)" -eq 15 ] \
    && ok || bad "sensitivity: 1 and 2 threads differ, or rows missing ($(wc -l < sa1.tsv), $(wc -l < se1.tsv))"

# ---- sensitivity guards its user: stderr off a terminal ------------------------
# 2 rows: below the threshold, the cost line, the stages, the indices flagged
expect 0 "warning: 2 rows given, below 64" "$bin" sensitivity sa.scene --rows 2 $narrow --threads 1 --out sg.tsv
err_has "slipfield sensitivity: 7 blocks x 2 rows = 14 runs at T = 20 s" "cost line"
err_has "of CPU by the rule of thumb" "cost line"
err_has "slipfield sensitivity: the first 2 of 14 runs took" "stage: the first runs' time"
err_has "slipfield sensitivity: 14 runs done in" "stage: runs done"
err_has "slipfield sensitivity: bootstrap done (20 resamples)" "stage: bootstrap done"
err_has "indices outside [-0.05, 1.05] or with an interval wider than 1" "indices out of range at 2 rows"
[ "$(grep -c 'runs took\|runs done\|bootstrap done' "$tmp/err")" -eq 3 ] && ok || bad "not one line per stage: $(cat "$tmp/err")"
# the scene sets none of l, v_b, mu_mean, mu_std: no key warning
err_lacks "is ignored" "a key the scene does not set"
# 64 rows (cheap runs: l/R near 10): no row warning
expect 0 "7 blocks x 64 rows = 448 runs" "$bin" sensitivity sa.scene --rows 64 --log-lr 1,1.1 --cv 0.15,0.25 --vb 0.2,0.25 \
    --mu 0.45,0.55 --bootstrap 20 --threads 1 --out sg.tsv
err_lacks "rows given" "64 rows"; err_lacks "rows used" "64 rows"
err_has "slipfield sensitivity: 448 runs done in" "stage: runs done at 64 rows"
err_has "total indices below 0.1 (the smallest: ST of" "small total indices: their intervals' measured level"
# a key the scene sets is reported, with the option that replaces it; the others not
cp sa.scene sl.scene; printf 'l = 0.2\nmu_mean = 0.5\n' >> sl.scene
expect 0 "warning: key 'l' is ignored: the study draws it from its range (--log-lr)" \
    "$bin" sensitivity sl.scene --rows 2 $narrow --threads 1 --out sg.tsv
err_has "key 'mu_mean' is ignored: the study draws it from its range (--mu)" "a set key"
err_lacks "key 'v_b'" "a key the scene does not set"
err_lacks "key 'mu_std'" "a key the scene does not set"
# on a terminal (util-linux script): the live count, no stage lines
if script --version 2>/dev/null | grep -q util-linux; then
    script -qec "'$bin' sensitivity sa.scene --rows 2 $narrow --threads 1 --out sg.tsv" /dev/null > "$tmp/err" 2>&1 < /dev/null
    err_has "slipfield sensitivity: 14/14 realisations" "terminal: live count"
    err_lacks "runs done" "terminal: a stage line"
fi

# ---- help -------------------------------------------------------------------
for c in verify field run sweep evaluate sensitivity surface wrench; do
    expect 0 "" "$bin" help $c
    grep -q "^usage: slipfield $c" "$tmp/out" && ok || bad "help $c: $(head -1 "$tmp/out")"
done
expect 2 "no help on 'foo'" "$bin" help foo
expect 0 "" "$bin" --help
grep -q -- "--version" "$tmp/out" && ok || bad "--help does not list --version"
grep -q "^  evaluate " "$tmp/out" && ok || bad "--help does not list evaluate"
grep -q "^130 interrupted by SIGINT" "$tmp/out" && ok || bad "--help does not list exit status 130"
expect 0 "" "$bin" help verify
grep -q "^130 interrupted by SIGINT" "$tmp/out" && ok || bad "help verify does not list exit status 130"
sh "$top/scripts/man.sh" "$bin" > man.1 && awk '/^\.SH EXIT STATUS/ { on = 1 } /^\.SH ENV/ { on = 0 } on' man.1 | grep -q '^\.B 130' \
    && ok || bad "the man page's EXIT STATUS does not list 130"
expect 0 "" "$bin" help scene
grep -q "^Case-only keys" "$tmp/out" && grep -q "^check " "$tmp/out" && ok || bad "help scene does not mark the case-only keys"

# ---- getopt_long habits ------------------------------------------------------
expect 0 "" "$bin" surface --out=eq.tsv s.scene
cmp -s eq.tsv new.tsv && ok || bad "--out=FILE"
expect 0 "" "$bin" surface --xb=0.1 s.scene --out after.tsv
[ "$(wc -l < after.tsv)" -eq $rows ] && ok || bad "options after the scene"
expect 0 "" "$bin" surface --out dash.tsv -- s.scene
[ -s dash.tsv ] && ok || bad "-- before the scene"
expect 2 "--resume takes no value" "$bin" sweep sw.scene --resume=1
expect 2 "--out needs a value" "$bin" surface s.scene --out

# ---- scene keys a command ignores ---------------------------------------------
printf 'cof = uniform\nu = -0.1\nntheta = 5\n' > keys.scene
expect 0 "key 'u' is ignored by surface" "$bin" surface keys.scene --out keys.tsv
expect 0 "key 'ntheta' is ignored by wrench" "$bin" wrench keys.scene
expect 0 "key 'u' is ignored: --vx given" "$bin" wrench keys.scene --vx 0.1 --vy 0 --spin 0
printf 'cof = uniform\nu = -0.2\n' > u.scene
"$bin" wrench u.scene --out u.tsv 2> /dev/null && "$bin" wrench u.scene --vx 0 --vy 0 --spin 0 --out flags.tsv 2> /dev/null \
    && cmp -s u.tsv flags.tsv && ok || bad "wrench: the scene's u, v, w are not its default motion"
printf 'cof = uniform\nnx = 4\nny = 4\nsamples = 3\n' > f.scene
expect 0 "" "$bin" field f.scene --out f.tsv
[ "$(cut -f1 f.tsv | sort -u | grep -c '^[0-9]')" -eq 3 ] && ok || bad "field: the scene's samples is not the default"

# ---- the example scene runs ----------------------------------------------------
expect 0 "" "$bin" run "$top/examples/disc.scene"
grep -q '^cycles = [1-9]' "$tmp/out" && ok || bad "examples/disc.scene: $(grep cycles "$tmp/out")"

# ---- the report's Re-run line: its own folder ------------------------------------
expect 0 "" "$bin" verify "$top/cases/contact/central-symmetry.md" --reports rep
grep -q 'Re-run: `build/slipfield verify [^`]* --reports reports/rerun`' rep/contact/central-symmetry/report.md && ok \
    || bad "Re-run line: $(grep Re-run rep/contact/central-symmetry/report.md)"

echo "cli-test: $pass passed, $fail failed"
[ $fail -eq 0 ]
