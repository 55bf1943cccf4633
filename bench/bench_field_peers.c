/* make bench, field section (c): peers from Debian, run as scripts from
 * bench/peers/ through popen (benchmark-only: the project never depends on
 * them; absent peers are skipped with a note).  Each script times itself
 * (interpreter start-up excluded) and prints one line
 *   peer=NAME method=M n=N setup_s=S sample_s=T ...
 * Ours is measured in the same run, right after the peer, on the same grid,
 * spacing and correlation length exp(-r^2/l^2). */
#include "bench.h"
#include "bench_field.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct {
    int ok;
    double setup, sample, cov_err, tol_re;
    char msg[200];   /* the peer's last output line when it failed */
    char version[32];
} peer_out;

/* bench/peers/ next to the sources: $SF_BENCH_PEERS, else ./bench/peers
 * (make bench runs from the top), else <exe>/../../bench/peers. */
static void peers_dir(char *dir, size_t len)
{
    const char *env = getenv("SF_BENCH_PEERS");
    if (env && *env) {
        snprintf(dir, len, "%s", env);
        return;
    }
    if (access("bench/peers/rf_field.R", R_OK) == 0) {
        snprintf(dir, len, "bench/peers");
        return;
    }
    char exe[PATH_MAX];
    ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[k > 0 ? k : 0] = 0;
    for (int up = 0; up < 3; up++) {
        char *s = strrchr(exe, '/');
        if (s)
            *s = 0;
    }
    if (snprintf(dir, len, "%s/bench/peers", exe) >= (int)len)
        snprintf(dir, len, "bench/peers");
}

static double field_after(const char *line, const char *key)
{
    const char *s = strstr(line, key);
    return s ? atof(s + strlen(key)) : -1.0;
}

/* Run `interp 'dir/script' n dx l reps` and parse its peer= line. */
static peer_out run_peer(const char *interp, const char *script, size_t n, double dx, double l, int reps)
{
    peer_out o = { 0, -1, -1, -1, 0, "", "?" };
    char dir[PATH_MAX], cmd[PATH_MAX + 300], line[512];
    peers_dir(dir, sizeof dir);
    snprintf(cmd, sizeof cmd, "%s '%s/%s' %zu %.17g %.17g %d 2>&1", interp, dir, script, n, dx, l, reps);
    FILE *p = popen(cmd, "r");
    if (!p) {
        snprintf(o.msg, sizeof o.msg, "cannot start %s", interp);
        return o;
    }
    while (fgets(line, sizeof line, p)) {
        line[strcspn(line, "\n")] = 0;
        if (!strncmp(line, "peer=", 5)) {
            o.ok = 1;
            o.setup = field_after(line, "setup_s=");
            o.sample = field_after(line, "sample_s=");
            o.cov_err = field_after(line, "cov_err=");
            o.tol_re = field_after(line, "tol_re=");
            const char *v = strstr(line, "version=");
            if (v)
                sscanf(v + 8, "%31s", o.version);
        } else if (*line) {
            snprintf(o.msg, sizeof o.msg, "%.199s", line);
        }
    }
    int st = pclose(p);
    if (st != 0)
        o.ok = 0;
    if (!o.ok) {
        for (char *c = o.msg; *c; c++)
            if (*c == '|')
                *c = '/';
        fprintf(stderr, "bench: peer %s %s failed (status %d): %s\n", interp, script, st, o.msg);
    }
    return o;
}

static int have(const char *prog)
{
    char cmd[300];
    snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", prog);
    return system(cmd) == 0;
}

static void skipped(FILE *f, const char *who, const peer_out *o)
{
    fprintf(f, "%s: skipped, the peer is absent or failed (%s). The project never depends on it; "
               "`make bench` tries to install it (BENCH_PEERS=0: don't).\n", who, *o->msg ? o->msg : "no output");
}

int bench_field_peers(FILE *f, const fb_cost *circ, const fb_cost *chol, size_t nrun)
{
    const double dx = 0.025;
    fprintf(f, "## Field sampling vs peers (RandomFields, OpenTURNS)\n\n"
               "Benchmark-only peers from Debian, run as scripts in `bench/peers/` (each times itself inside the "
               "interpreter: start-up and package loading excluded); ours measured in the same run on the same "
               "grid and kernel exp(-r^2/l^2) (RandomFields `RMgauss(scale = l)`, OpenTURNS `SquaredExponential` "
               "theta = l/sqrt(2)). Ratio = our time / peer time: below 1 means we are faster. Per field: a "
               "circulant sample gives two fields, so ours is half a pair.\n");

    /* RandomFields circulant vs ours at l = 4 dx */
    const size_t rf_n[] = { 256, 1024 };
    const int rf_reps[] = { 30, 3 };
    fprintf(f, "\n### RandomFields circulant embedding (R) vs ours, l = 4 dx\n\n");
    peer_out o = { 0, 0, 0, 0, 0, "Rscript not found; install r-cran-randomfields", "?" };
    char *rows = NULL;
    size_t len = 0, ok = 0;
    FILE *t = open_memstream(&rows, &len);
    if (!t)
        return 1;
    for (size_t i = 0; i < 2 && have("Rscript"); i++) {
        o = run_peer("Rscript", "rf_field.R", rf_n[i], dx, 4 * dx, rf_reps[i]);
        if (!o.ok) {
            fprintf(t, "| %zu^2 | failed: %s | | | | | | |\n", rf_n[i], o.msg);
            break;
        }
        sf_field_spec spec;
        fb_cost c;
        sf_field_spec_default(&spec, rf_n[i], rf_n[i], dx, dx, 4 * dx);
        if (fb_circulant_costs(&spec, 1, 2.0, &c)) {
            fclose(t);
            free(rows);
            return 1;
        }
        fprintf(stderr, "bench: RandomFields %zu^2: set-up %.3g s, per field %.3g s; ours %.3g s, %.3g s\n",
                rf_n[i], o.setup, o.sample, c.setup, c.sample);
        fprintf(t, "| %zu^2 | %.3g | %.3g | %.3g | %.3g | %.1e | %.3f | %.3f |\n", rf_n[i], o.setup, o.sample,
                c.setup, c.sample, c.cov_err, c.setup / o.setup, c.sample / o.sample);
        ok++;
    }
    fclose(t);
    if (!ok) {
        skipped(f, "RandomFields", &o);
    } else {
        fprintf(f, "| grid | RF set-up [s] | RF per field [s] | ours set-up [s] | ours per field [s] | "
                   "ours cov. error (exact) | set-up ratio ours/RF | per-field ratio ours/RF |\n"
                   "|---|---|---|---|---|---|---|---|\n%s", rows);
        fprintf(f, "\nRandomFields version %s. Both are circulant embeddings, exact up to clamping. "
                   "RandomFields embeds in twice the grid per axis (about our minimal embedding, 2(n-1)) and "
                   "sets eigenvalues above its absolute tolerance tolRe = %g to zero, so its covariance error "
                   "is bounded by |tolRe| = %g (a bound from its options, not measured: RandomFields does not "
                   "expose the covariance it produces); ours clamps relative to lambda_max at 1e-12 and the "
                   "exact error is in the table. RF timings come from R's `proc.time` (1 ms resolution): set-up "
                   "= one call with n = 1 minus one field, per field = (call with n = 1 + reps minus call with "
                   "n = 1)/reps.\n",
                o.version, o.tol_re, -o.tol_re);
    }
    free(rows);

    /* OpenTURNS Cholesky vs our GSL Cholesky and our circulant at l = 2 dx,
     * on the grids of section (b) that it can factor */
    const size_t ot_n[] = { 32, 48 };
    fprintf(f, "\n### OpenTURNS Cholesky (Python) vs our GSL Cholesky and our circulant, l = 2 dx\n\n");
    peer_out q = { 0, 0, 0, 0, 0, "/usr/bin/python3 not found; install python3-openturns", "?" };
    rows = NULL;
    ok = 0;
    t = open_memstream(&rows, &len);
    if (!t)
        return 1;
    for (size_t i = 0; i < 2 && access("/usr/bin/python3", X_OK) == 0; i++) {
        size_t k = 0;
        while (k < nrun && chol[k].n != ot_n[i])
            k++;
        if (k == nrun)
            continue;
        q = run_peer("/usr/bin/python3", "ot_field.py", ot_n[i], dx, 2 * dx, 10);
        if (!q.ok) {
            fprintf(t, "| %zu^2 | failed: %s | | | | | | | | | | |\n", ot_n[i], q.msg);
            break;
        }
        fprintf(stderr, "bench: OpenTURNS %zu^2: set-up %.3g s, per field %.3g s (err %.1e)\n", ot_n[i], q.setup,
                q.sample, q.cov_err);
        fprintf(t, "| %zu^2 | %.3g | %.3g | %.1e | %.3g | %.3g | %.3g | %.3g | %.3f | %.3f | %.2g | %.2g |\n",
                ot_n[i], q.setup, q.sample, q.cov_err, chol[k].setup, chol[k].sample, circ[k].setup,
                circ[k].sample, chol[k].setup / q.setup, chol[k].sample / q.sample, circ[k].setup / q.setup,
                circ[k].sample / q.sample);
        ok++;
    }
    fclose(t);
    if (!ok) {
        skipped(f, "OpenTURNS", &q);
        free(rows);
        return 0;
    }
    fprintf(f, "| grid | OT set-up [s] | OT per field [s] | OT max abs(L L^T - Sigma) | GSL Chol. set-up [s] | "
               "GSL Chol. per field [s] | circulant set-up [s] | circulant per field [s] | set-up ratio "
               "GSL/OT | per-field ratio GSL/OT | set-up ratio circ/OT | per-field ratio circ/OT |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|\n%s", rows);
    free(rows);
    fprintf(f, "\nOpenTURNS version %s. All three are exact to round-off here (l = 2 dx keeps Sigma positive "
               "definite, see the Cholesky section; OpenTURNS' factor is checked by max abs(L L^T - Sigma) with "
               "numpy after its timing: the plain factorisation succeeds, so its process needs no diagonal "
               "nugget). OpenTURNS factors with LAPACK (`dpotrf`, blocked) on the system libblas/liblapack; ours "
               "with `gsl_linalg_cholesky_decomp1` on GSL's reference CBLAS. Our GSL/circulant numbers are those "
               "of the Cholesky section above, measured in this run. OpenTURNS has no circulant embedding, and "
               "its Cholesky process is the only one that gives the exact covariance (HMAT "
               "inflates the variance, Cholesky fails with bad_alloc beyond ~100^2 points), so larger grids are "
               "not compared.\n", q.version);
    return 0;
}
