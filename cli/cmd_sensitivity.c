/* slipfield sensitivity SCENE --rows N --out FILE [--evals FILE]
 *                       [--bootstrap B] [--level P] [--threads T]
 *                       [--log-lr LO,HI] [--cv LO,HI] [--vb LO,HI] [--mu LO,HI]
 * First-order and total Sobol' indices of the QoI ratios over l/R, the
 * COF's CV, v_b and the mean COF, the field as the fifth input
 * (solver/stats/sensitivity.h). */
#include "cli.h"
#include "sensitivity.h"
#include "montecarlo.h"
#include "sf_error.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Rows below which the study warns.  The Ishigami function through the
 * same estimators (solver/stats/sobol.h; 3 inputs and 2 dummies, 2000 designs
 * of 300 resamples each, 95% percentile intervals): the worst index's
 * interval covers its analytic value 73% of the time at 8 rows, 82% at
 * 16, 86% at 32, 90% at 64 (the floor cases/sensitivity/ishigami.md
 * holds at 256 rows) and 92% at 128; intervals wider than 1 are 27% of
 * them at 8 rows, 3.8% at 32, 0.5% at 64 and none from 96; a nonzero
 * index falls outside [-0.05, 1.05] in up to 15% of designs at 8 rows,
 * 5% at 32, 0.6% at 64. */
#define MIN_ROWS 64
/* An index outside [-NOISE_LO, 1 + NOISE_LO], or an interval wider than
 * NOISE_WIDTH: the estimate is noise. */
#define NOISE_LO 0.05
#define NOISE_WIDTH 1.0
/* A total index below SMALL_ST: its percentile interval covers less than
 * its level (docs/design.md sec. 7.8, cases/sensitivity/field-law-coverage). */
#define SMALL_ST 0.1

/* The rule of thumb for a run's CPU time at T = 100 s on one core (a
 * field run and its deterministic reference, `slipfield run` and
 * `slipfield sensitivity --rows 2` timed over narrow ranges; it grows
 * about as T): 0.05 s at most for l/R >= 1, 0.5 s down to l/R = 0.1
 * (even at v_b = 0.6, mu_mean = 0.2), and at l/R = 0.01 from 0.2-0.5 s
 * (v_b = 0.2, mu_mean = 0.5) to 30-90 s (v_b = 0.6 or mu_mean = 0.2). */
static double run_cost_max(double log_lr_lo)
{
    return log_lr_lo >= 0 ? 0.05 : log_lr_lo >= -1 ? 0.5 : 90;
}

static void usage(FILE *f)
{
    fputs("usage: slipfield sensitivity SCENE --rows N --out FILE [--evals FILE]\n"
          "                             [--bootstrap B] [--level P] [--threads T]\n"
          "                             [--log-lr LO,HI] [--cv LO,HI] [--vb LO,HI] [--mu LO,HI]\n"
          "Sobol' indices of the QoI ratios (pv_x, pv_F, stick fraction over the\n"
          "deterministic model at the same parameters, as in sweep) with respect to\n"
          "log10 l/R, the COF's CV, the belt speed v_b and the mean COF, each uniform on\n"
          "its range, and the random field itself (the fifth input: each row of the\n"
          "design draws its own field, shared by the evaluations that keep that row's\n"
          "field). Pick-freeze with two sample matrices A, B of N rows: N x 7 runs.\n"
          "First order (Saltelli 2010), total (Jansen); percentile intervals from a\n"
          "bootstrap over rows.\n"
          "  --rows N          rows of A and B (at least 2)\n"
          "  --out FILE        TSV, one row per QoI and input: S1 and its interval and\n"
          "                    bootstrap std, ST likewise, the rows used and excluded (a\n"
          "                    non-finite value in any run of a row), the resamples and\n"
          "                    the ratio's variance\n"
          "  --evals FILE      TSV, one row per run: block, row, the row its field comes\n"
          "                    from, the parameters, the ratios and the QoIs\n"
          "  --bootstrap B     bootstrap resamples (default 1000; 0: no intervals)\n"
          "  --level P         the intervals' level in (0, 1) (default 0.95)\n"
          "  --threads T       OpenMP threads (default: all); results do not depend on it\n"
          "  --log-lr LO,HI    range of log10 l/R (default -2,3: the paper's 0.01 to 1000)\n"
          "  --cv LO,HI        range of the COF's CV (default 0.1,0.3)\n"
          "  --vb LO,HI        range of v_b [m/s] (default 0.1,0.6: Fig. 12)\n"
          "  --mu LO,HI        range of the mean COF (default 0.2,1: Fig. 13)\n"
          "The scene needs cof = field; its l, v_b, mu_mean and mu_std are the study's\n"
          "(a key the scene sets is reported as ignored).\n"
          "Bit-identical output for any thread count.\n"
          "On stderr: before the runs, their number and a rule of thumb for their time\n"
          "(at T = 100 s on one core: 0.05 s a run for l/R >= 1, 0.5 s for l/R >= 0.1,\n"
          "up to 90 s at l/R = 0.01 with a fast belt or a low mean COF; about as T);\n"
          "then progress: on a terminal a live count with an ETA, otherwise one line\n"
          "per stage (the first runs' time and the estimate of the rest, the runs done,\n"
          "the bootstrap done). Warnings: fewer than 64 rows (the bootstrap intervals\n"
          "cover less than 90% at the 95% level and the indices can fall outside\n"
          "[0, 1], as the Ishigami function shows), and any index outside\n"
          "[-0.05, 1.05] or with an interval wider than 1 (noise: more rows). A note\n"
          "when a total index is below 0.1: its interval covers less than its level\n"
          "(0.87-0.93 at 95%, 256-1024 rows, on a field functional with exact indices).\n",
          f);
}

/* "LO,HI": two finite numbers, LO < HI. */
static int opt_range(const char *cmd, const char *v, void *dst)
{
    double *r = dst;
    char *end, *end2;
    errno = 0;
    r[0] = strtod(v, &end);
    if (end != v && *end == ',') {
        r[1] = strtod(end + 1, &end2);
        if (end2 != end + 1 && !*end2 && !errno && isfinite(r[0]) && isfinite(r[1]) && r[0] < r[1])
            return SF_EXIT_OK;
    }
    fprintf(stderr, "slipfield %s: expected a range LO,HI of two finite numbers with LO < HI, got '%s'\n", cmd, v);
    return SF_EXIT_USAGE;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void warn_rows(size_t n, const char *how)
{
    if (n < MIN_ROWS)
        fprintf(stderr, "slipfield sensitivity: warning: %zu rows %s, below %d: the pick-freeze estimators' "
                        "bootstrap intervals are not reliable there (on the Ishigami function they cover less "
                        "than 90%% at the 95%% level) and the indices can fall outside [0, 1]; use --rows %d or "
                        "more\n", n, how, MIN_ROWS, MIN_ROWS);
}

/* "12 s", "3.5 min", "2.1 h" */
static void fmt_time(char *b, size_t len, double t)
{
    if (t < 120)
        snprintf(b, len, "%.2g s", t);
    else if (t < 7200)
        snprintf(b, len, "%.2g min", t / 60);
    else
        snprintf(b, len, "%.2g h", t / 3600);
}

/* One line: the runs, and the rule of thumb's time for them. */
static void cost_line(size_t n, const sf_sens_ranges *R, double T)
{
    size_t runs = n * (SF_SENS_D + 2);
    double c = run_cost_max(R->lo[SF_SENS_LOGLR]);
    char t[32];
    fmt_time(t, sizeof t, (double)runs * c * T / 100);
    char why[160];
    if (c > 1)
        snprintf(why, sizeof why, "at T = 100 s a run at l/R = 0.01 takes 0.5 s at v_b = 0.2, mu_mean = 0.5 and up "
                                  "to %g s with a fast belt or a low mean COF", c);
    else
        snprintf(why, sizeof why, "at T = 100 s a run takes at most %g s for l/R >= %g", c, c > 0.1 ? 0.1 : 1.0);
    fprintf(stderr, "slipfield sensitivity: %d blocks x %zu rows = %zu runs at T = %g s, l/R down to %.3g: up to "
                    "%s of CPU by the rule of thumb (%s; see --help); the first runs' time will give the "
                    "estimate\n", SF_SENS_D + 2, n, runs, T, pow(10, R->lo[SF_SENS_LOGLR]), t, why);
}

static const char *const qoi_name[SF_SWEEP_NQ] = { "pv_x_ratio", "pv_F_ratio", "stick_fraction_ratio" };

/* One line when a printed total index is below SMALL_ST: how many, and
 * the smallest, with the level such intervals were measured to have. */
static void warn_small_st(const sf_sens *S, size_t nboot)
{
    size_t k = 0;
    int wq = 0, wi = 0;
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        for (int i = 0; i < SF_SENS_D; i++) {
            double st = S->res[q].idx[i].st;
            if (!(st < SMALL_ST))
                continue;
            if (!k++ || st < S->res[wq].idx[wi].st) {
                wq = q;
                wi = i;
            }
        }
    if (k && nboot)
        fprintf(stderr, "slipfield sensitivity: note: %zu total indices below %g (the smallest: ST of %s for %s, "
                        "%.3g): such an interval covers less than its level (95%% intervals on a field functional "
                        "with exact indices: 0.87 at ST = 0.02 and 0.90 at 0.075 with 256 rows, 0.91-0.93 with "
                        "1024; docs/design.md sec. 7.8)\n", k, SMALL_ST, sf_sens_input_name(wi), qoi_name[wq],
                S->res[wq].idx[wi].st);
}

/* One line when any index is outside [-NOISE_LO, 1 + NOISE_LO] or its
 * interval is wider than NOISE_WIDTH: how many, and the worst. */
static void warn_noise(const sf_sens *S)
{
    size_t bad = 0, all = 0;
    double worst = 0, wv = 0, wlo = 0, whi = 0;
    int wq = 0, wi = 0, wt = 0;
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        for (int i = 0; i < SF_SENS_D; i++)
            for (int t = 0; t < 2; t++) {
                const sf_sobol_index *x = &S->res[q].idx[i];
                double v = t ? x->st : x->s1, lo = t ? x->st_lo : x->s1_lo, hi = t ? x->st_hi : x->s1_hi;
                double w = isfinite(lo) && isfinite(hi) ? hi - lo : 0;
                double score = fmax(fmax(-NOISE_LO - v, v - 1 - NOISE_LO), w - NOISE_WIDTH);
                all++;
                if (!(score > 0))
                    continue;
                if (!bad++ || score > worst) {
                    worst = score;
                    wv = v;
                    wlo = lo;
                    whi = hi;
                    wq = q;
                    wi = i;
                    wt = t;
                }
            }
    if (bad)
        fprintf(stderr, "slipfield sensitivity: warning: %zu of %zu indices outside [%g, %g] or with an interval "
                        "wider than %g, e.g. %s of %s: %s = %.3g [%.3g, %.3g]: not to be trusted (an index lies "
                        "in [0, 1]); more rows narrow them\n", bad, all, -NOISE_LO, 1 + NOISE_LO, NOISE_WIDTH,
                sf_sens_input_name(wi), qoi_name[wq], wt ? "ST" : "S1", wv, wlo, whi);
}

int sf_cmd_sensitivity(int argc, char **argv)
{
    const char *path, *out_path = NULL, *ev_path = NULL;
    size_t n = 0, nboot = 1000, threads = 0;
    double level = 0.95, rg[SF_SENS_NPAR][2];
    sf_sens_ranges R;
    sf_sens_ranges_default(&R);
    for (int i = 0; i < SF_SENS_NPAR; i++) {
        rg[i][0] = R.lo[i];
        rg[i][1] = R.hi[i];
    }
    const sf_opt opts[] = {
        { "--rows", SF_OPT_SIZE, &n, 2, 1000000, NULL },
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
        { "--evals", SF_OPT_STRING, &ev_path, 0, 0, NULL },
        { "--bootstrap", SF_OPT_SIZE, &nboot, 0, 1000000, NULL },
        { "--level", SF_OPT_DOUBLE, &level, 0, 0, NULL },
        { "--threads", SF_OPT_SIZE, &threads, 1, 1024, NULL },
        { "--log-lr", SF_OPT_FN, rg[SF_SENS_LOGLR], 0, 0, opt_range },
        { "--cv", SF_OPT_FN, rg[SF_SENS_CV], 0, 0, opt_range },
        { "--vb", SF_OPT_FN, rg[SF_SENS_VB], 0, 0, opt_range },
        { "--mu", SF_OPT_FN, rg[SF_SENS_MU], 0, 0, opt_range },
    };
    int rc = sf_cli_parse("sensitivity", argc, argv, opts, sizeof opts / sizeof opts[0], &path, usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    if (!n || !out_path) {
        fprintf(stderr, "slipfield sensitivity: --rows and --out are required\n");
        return SF_EXIT_USAGE;
    }
    if (!(level > 0 && level < 1)) {
        fprintf(stderr, "slipfield sensitivity: --level must be in (0, 1) (got %g)\n", level);
        return SF_EXIT_USAGE;
    }
    for (int i = 0; i < SF_SENS_NPAR; i++) {
        R.lo[i] = rg[i][0];
        R.hi[i] = rg[i][1];
    }
    char err[300];
    if (sf_sens_ranges_check(&R, err, sizeof err)) {
        fprintf(stderr, "slipfield sensitivity: %s\n", err);
        return SF_EXIT_USAGE;
    }
    sf_scene s;
    if (sf_cli_load_scene("sensitivity", path, &s))
        return SF_EXIT_USAGE;
    if (s.cof != SF_COF_FIELD) {
        fprintf(stderr, "slipfield sensitivity: %s: the study needs cof = field (the field is one of its inputs)\n",
                path);
        return SF_EXIT_USAGE;
    }
    if (!(s.T > s.t_skip)) {
        fprintf(stderr, "slipfield sensitivity: T = %g s is not above t_skip = %g s: no cycle to measure\n", s.T,
                s.t_skip);
        return SF_EXIT_USAGE;
    }
    static const char *const keys[][2] = { { "l", "--log-lr" }, { "v_b", "--vb" }, { "mu_mean", "--mu" },
                                           { "mu_std", "--cv and --mu" } };
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        if (sf_scene_was_set(&s, keys[k][0]))
            fprintf(stderr, "slipfield sensitivity: %s: warning: key '%s' is ignored: the study draws it from its "
                            "range (%s)\n", path, keys[k][0], keys[k][1]);
    sf_cli_interrupt_hint("");
    int writer = sf_mc_rank(NULL) == 0;
    sf_out out = { 0 }, ev = { 0 };
    if (writer) {
        if ((rc = sf_cli_open("sensitivity", out_path, path, &out)))
            return rc;
        if (ev_path && (rc = sf_cli_open("sensitivity", ev_path, path, &ev))) {
            sf_cli_close("sensitivity", &out, 0);
            return rc;
        }
    }
    if (writer) {
        warn_rows(n, "given");
        cost_line(n, &R, s.T);
    }
    sf_mc_stage_lines(1);
    double t0 = now_s();
    sf_sens *S;
    rc = sf_sens_run(&s, &R, n, nboot, level, (int)threads, "slipfield sensitivity", &S, err, sizeof err);
    if (rc)
        fprintf(stderr, "slipfield sensitivity: %s\n", *err ? err : sf_strerror(rc));
    if (!writer) {
        sf_sens_free(S);
        return sf_cli_status(rc);
    }
    if (!rc) {
        sf_sens_write_indices(out.f, S);
        if (ev_path)
            sf_sens_write_evals(ev.f, S);
        if (nboot)
            fprintf(stderr, "slipfield sensitivity: bootstrap done (%zu resamples), %.1f s in all\n", nboot,
                    now_s() - t0);
        else
            fprintf(stderr, "slipfield sensitivity: indices done (no bootstrap), %.1f s in all\n", now_s() - t0);
        if (S->res[0].n_excluded)
            fprintf(stderr, "slipfield sensitivity: warning: %zu of %zu rows excluded (a run with a non-finite "
                            "ratio)\n", S->res[0].n_excluded, n);
        if (n >= MIN_ROWS)
            warn_rows(S->res[0].n_used, "used");
        warn_noise(S);
        warn_small_st(S, nboot);
    }
    sf_sens_free(S);
    int st = sf_cli_close("sensitivity", &out, !rc);
    if (ev_path && sf_cli_close("sensitivity", &ev, !rc) && !rc)
        st = SF_EXIT_USAGE;
    return rc ? sf_cli_status(rc) : st;
}
