/* slipfield sensitivity SCENE --rows N --out FILE [--evals FILE]
 *                       [--bootstrap B] [--level P] [--threads T]
 *                       [--log-lr LO,HI] [--cv LO,HI] [--vb LO,HI] [--mu LO,HI]
 * First-order and total Sobol' indices of the QoI ratios over l/R, the
 * COF's CV, v_b and the mean COF, the field as the fifth input
 * (solver/sensitivity.h). */
#include "cli.h"
#include "sensitivity.h"
#include "montecarlo.h"
#include "sf_error.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

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
          "The scene needs cof = field; its l, v_b, mu_mean and mu_std are the study's.\n"
          "Bit-identical output for any thread count. Progress on stderr when it is a\n"
          "terminal.\n",
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
    static const char *const keys[] = { "l", "v_b", "mu_mean", "mu_std" };
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        sf_cli_key_overridden("sensitivity", path, &s, keys[k], "the study's ranges");
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
    sf_sens *S;
    rc = sf_sens_run(&s, &R, n, nboot, level, (int)threads, "sensitivity", &S, err, sizeof err);
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
        if (S->res[0].n_excluded)
            fprintf(stderr, "slipfield sensitivity: warning: %zu of %zu rows excluded (a run with a non-finite "
                            "ratio)\n", S->res[0].n_excluded, n);
    }
    sf_sens_free(S);
    int st = sf_cli_close("sensitivity", &out, !rc);
    if (ev_path && sf_cli_close("sensitivity", &ev, !rc) && !rc)
        st = SF_EXIT_USAGE;
    return rc ? sf_cli_status(rc) : st;
}
