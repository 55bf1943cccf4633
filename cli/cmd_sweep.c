/* slipfield sweep SCENE --param NAME --values A,B,C --realisations N
 *                 --out FILE [--summary FILE [--summary-format wide|long]]
 *                 [--diagnostics FILE] [--tuples FILE] [--threads T] [--resume]
 *                 [--target-se X [--pilot N0]]
 * Monte Carlo over realisations at each parameter value; ratios to the
 * deterministic model at the same parameters. */
#include "cli.h"
#include "sweep.h"
#include "mcstop.h"
#include "model.h"
#include "unum.h"
#include "montecarlo.h"
#include "sf_error.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>

static void usage(FILE *f)
{
    fputs("usage: slipfield sweep SCENE --param NAME --values A,B,C --realisations N --out FILE\n"
          "                       [--summary FILE [--summary-format wide|long]]\n"
          "                       [--diagnostics FILE] [--tuples FILE] [--threads T] [--resume]\n"
          "                       [--target-se X [--pilot N0] | --control-variate |\n"
          "                        --estimator mlmc|mlmc-boxes|mlmc-sub|antithetic|auto\n"
          "                        [--pilot N0]]\n"
          "Monte Carlo sweep: at each value of NAME, N realisations of the scene.\n"
          "  --param NAME      a numeric scene key, or l_over_R (l = value x R), or\n"
          "                    mu_mean (at the scene's CV: mu_std scales with it)\n"
          "  --out FILE        TSV: param value realisation, the ratios pv_x_ratio pv_F_ratio\n"
          "                    stick_fraction_ratio to the deterministic model (uniform COF\n"
          "                    at mu_mean, same T, t_skip and stepper), then pv_x [m],\n"
          "                    pv_F [N], stick_fraction [-]; with --summary or\n"
          "                    --diagnostics, the companion solve of u_num (below) of\n"
          "                    realisations 0 .. ceil(N/4) - 1: its pv_x_coarse [m],\n"
          "                    pv_F_coarse [N], stick_fraction_coarse [-], its assumed\n"
          "                    error ratio unum_rho and the plan's a-priori relative\n"
          "                    error unum_apriori (nan for the others)\n"
          "  --summary FILE    TSV, one row per value: param, value, then per ratio q of\n"
          "                    pv_x_ratio, pv_F_ratio, stick_fraction_ratio the answer of\n"
          "                    the estimator that ran: q_estimate[-] (plain, target-se:\n"
          "                    the ratio mean; control-variate: the regression estimate;\n"
          "                    mlmc*: the two-level estimate; antithetic: the pairs'),\n"
          "                    q_se[-], its 95% interval q_ci95_lo[-] q_ci95_hi[-] (Student\n"
          "                    t; Stein's for --target-se: the interval the two stages\n"
          "                    guarantee), q_u_num[-], the numerical error of the mean\n"
          "                    in ratio units (u_num_mean / det, below); then n (the\n"
          "                    field draws averaged: realisations; mlmc*: ml_n0 + ml_n1;\n"
          "                    antithetic: the pairs), work (cell evaluations; only for\n"
          "                    the estimators that record it: mlmc*, antithetic, auto),\n"
          "                    estimator and stop (fixed, target or cap)\n"
          "  --summary-format long  the summary as one row per value and ratio: param\n"
          "                    value qoi estimate se ci_lo ci_hi u_num n estimator stop\n"
          "                    unit (\"-\": the unit of estimate .. u_num); wide (default):\n"
          "                    as above\n"
          "  --diagnostics FILE  TSV, one row per value, every statistic: n, and per QoI\n"
          "                    the realisations used and excluded (a non-finite value is\n"
          "                    excluded, never averaged), mean, std (n - 1), standard\n"
          "                    error of the mean, 95% confidence interval (Student t),\n"
          "                    the deterministic value, and the ratio's mean, std and\n"
          "                    standard error; the numerical error of the mean: a\n"
          "                    coarser companion solve (as run --summary's u_num) of the\n"
          "                    first ceil(N/4) realisations (at least 2), their signed\n"
          "                    error estimates' mean (num_bias), its standard error and\n"
          "                    u_num_mean = 3 (|num_bias| + t se) (up to ~1/3 more CPU,\n"
          "                    also for --summary); then stop, the pilot's size (n_pilot,\n"
          "                    0 for a fixed N) and per QoI the ratio mean's 95% interval\n"
          "                    the design guarantees; then each estimator's columns (nan\n"
          "                    without it) and estimator\n",
          f);
    fputs("  --tuples FILE     TSV, what each estimator's interval is a function of, one\n"
          "                    row per sample: param value estimator level index, then\n"
          "                    a_* and b_* per ratio (pv_x, pv_F, stick_fraction; [-]):\n"
          "                    level row (plain, target-se: a the ratios), cv (a the\n"
          "                    ratios, b_pv_x the companion C, b_pv_F its known mean),\n"
          "                    pair (antithetic: a G's ratios, b -G's), level0 (mlmc*:\n"
          "                    a level 0's sample), level1 (mlmc*: a fine, b coarse),\n"
          "                    cost (a_pv_x, a_pv_F: each level's mean work per sample\n"
          "                    [cell evaluations]; antithetic: a pair's)\n",
          f);
    fputs("  --realisations N  realisations per value (default: the scene's samples, if\n"
          "                    it sets the key)\n"
          "  --target-se X     two stages (Stein): N0 realisations, then as many more as\n"
          "                    the pilot's spread says every ratio mean needs for a\n"
          "                    standard error of X (> 0, dimensionless), at most N\n"
          "                    (--realisations is then the cap); the interval uses the\n"
          "                    pilot's spread and keeps its 95% coverage\n"
          "  --pilot N0        the first stage, the floor on N (2 <= N0 <= N; default\n"
          "                    min(20, N)); only with --target-se\n"
          "  --control-variate each realisation also gives its COF averaged over fixed\n"
          "                    points on the disc's nominal path (known mean: mu_mean);\n"
          "                    the diagnostics add per QoI the regression estimator of the\n"
          "                    ratio mean (cv_ratio_mean, se, 95% interval at n - 2\n"
          "                    degrees of freedom) and its variance reduction factor\n"
          "                    (cv_vrf); nan for a tiled field (no companion: the\n"
          "                    summary gives plain Monte Carlo's estimate there)\n",
          f);
    fputs("  --estimator mlmc  two levels on one field: a coarse plan (half the rings,\n"
          "                    rtol 1e-5) and the scene's; N (--realisations) sets the\n"
          "                    target, the variance of plain Monte Carlo with N; a pilot\n"
          "                    of N0 pairs (--pilot, default min(10, N)) starts the\n"
          "                    sizes, recomputed from every sample so far in stages\n"
          "                    that at most double a level; the diagnostics add ml_n0,\n"
          "                    ml_n1, each level's work, and per ratio the estimate,\n"
          "                    its interval, each level's variance and the variance\n"
          "                    reduction factor; the rows are level 1's fine\n"
          "                    realisations; its 95% interval covers 0.939-0.945\n"
          "                    (measured, Table 1, T = 100 s, N = 40), the stick\n"
          "                    fraction's at l/R = 0.1 0.92 (plain's own there)\n"
          "  --estimator mlmc-boxes  two levels where the plan draws cell averages (small\n"
          "                    l/R): the fine plan's cells rounded up to a multiple of 4;\n"
          "                    level 1 runs the coarse plan (a quarter of the cells per\n"
          "                    diameter, rtol 1e-5) on the means of 4 x 4 of the fine\n"
          "                    field's boxes (the law of the coarse model, exactly);\n"
          "                    level 0 draws its own coarse fields, in antithetic pairs;\n"
          "                    the diagnostics' columns as --estimator mlmc\n"
          "  --estimator mlmc-sub  two levels where the plan draws point values on the\n"
          "                    circulant strip: level 1 runs the coarse plan of mlmc on\n"
          "                    the fine field at every 2nd node (the law of the field on\n"
          "                    the coarser grid, exactly); level 0 draws its own on that\n"
          "                    grid, in antithetic pairs; the rows are plain's first n1;\n"
          "                    pv_F's 95% interval at l/R = 10 covers only 0.88\n"
          "                    (measured, as antithetic's)\n"
          "  --estimator antithetic  pairs of the drawn field G and its antithetic -G\n"
          "                    (negated before the lognormal map; -G has G's law): one\n"
          "                    draw, two runs, the pair mean unbiased; a pilot of N0\n"
          "                    pairs (--pilot, default min(10, N)) starts the pairs\n"
          "                    for plain Monte Carlo's variance with N (in mlmc's\n"
          "                    stages); the diagnostics add anti_n, a pair's and a plain\n"
          "                    realisation's work, and per ratio the estimate, its\n"
          "                    interval (Student over the pair means), rho =\n"
          "                    corr(Q(G), Q(-G)) and the variance reduction factor;\n"
          "                    the rows are the pairs' G members; its 95% interval\n"
          "                    covers 0.937-0.951 (measured, Table 1, T = 100 s, N = 40),\n"
          "                    pv_F's at l/R = 10 only 0.89 (a few skewed pair means)\n"
          "  --estimator auto  per value: mlmc-boxes where the plan draws cell averages;\n"
          "                    on the circulant strip mlmc-sub at l/R < 0.5, mlmc at\n"
          "                    0.5 <= l/R < 5; antithetic on tiles and at l/R >= 5 (a\n"
          "                    rule from measurements; the summary's estimator column\n"
          "                    says which ran)\n"
          "  --estimator E --target-se X  the estimator's sizes for a standard error X [-]\n"
          "                    of every ratio mean instead of plain's at N (N then\n"
          "                    the cap on level 1 or on the pairs); the summary's stop\n"
          "                    says target, or cap where a level was held at its cap\n"
          "  --threads T       OpenMP threads (default: all); results do not depend on it\n"
          "  --resume          continue from FILE.ckpt<k> checkpoints of an interrupted run\n"
          "                    (and remove the temporary files a killed run left)\n"
          "The swept value overrides the scene's value of NAME.\n"
          "Realisation i of every value uses its own stream (seed, i): bit-identical\n"
          "output for any thread count. Progress on stderr: a live count on a\n"
          "terminal; off one (a CI log), one line per point: its realisations and time.\n",
          f);
}

static int parse_values(const char *v, double *out, size_t cap, size_t *n)
{
    *n = 0;
    const char *p = v;
    while (*p) {
        char *end;
        errno = 0;
        double x = strtod(p, &end);
        if (end == p || errno || !isfinite(x) || *n == cap || (*end && *end != ','))
            return -1;
        out[(*n)++] = x;
        p = *end ? end + 1 : end;
    }
    return *n ? 0 : -1;
}

/* Remove the temporary files that a killed run (SIGKILL: no clean-up)
 * left beside out: "<out>.tmp<pid>" and "<out>.ckpt<k>.tmp", of processes
 * that no longer run. */
/* --param: l_over_R or a numeric scene key */
static int param_ok(const sf_key *k)
{
    return k->type == SF_KEY_DOUBLE || k->type == SF_KEY_SIZE || k->type == SF_KEY_ULONG;
}

/* Edit distance of two short names (capped at 3: only "close" matters). */
static size_t name_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), d[64];
    if (la >= 63 || lb >= 63)
        return 3;
    for (size_t j = 0; j <= lb; j++)
        d[j] = j;
    for (size_t i = 1; i <= la; i++) {
        size_t diag = d[0];
        d[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t up = d[j];
            size_t best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best)
                best = up + 1;
            if (d[j - 1] + 1 < best)
                best = d[j - 1] + 1;
            d[j] = best;
            diag = up;
        }
    }
    return d[lb] < 3 ? d[lb] : 3;
}

/* 0 when NAME is a parameter --param takes; else says why, with the
 * nearest names (the same letters in another case first) and the list. */
static int check_param(const char *name)
{
    sf_scene d;
    sf_scene_default(&d);
    sf_keytab t = sf_scene_keytab(&d);
    if (!strcmp(name, "l_over_R"))
        return 0;
    const char *near = NULL;
    size_t best = 3;
    for (size_t k = 0; k < t.n; k++) {
        if (!strcmp(t.keys[k].name, name)) {
            if (param_ok(&t.keys[k]))
                return 0;
            fprintf(stderr, "slipfield sweep: --param %s: not a numeric scene key (it cannot be swept)\n", name);
            return -1;
        }
    }
    for (size_t k = 0; k <= t.n; k++) {
        const char *kn = k < t.n ? t.keys[k].name : "l_over_R";
        if (k < t.n && !param_ok(&t.keys[k]))
            continue;
        size_t dist = strcasecmp(kn, name) ? name_distance(kn, name) : 0;
        if (dist < best && 2 * dist < strlen(name)) {   /* close, for a name this long */
            best = dist;
            near = kn;
        }
    }
    fprintf(stderr, "slipfield sweep: --param: unknown parameter '%s'", name);
    if (near)
        fprintf(stderr, "; did you mean %s?", near);
    fputs("\nvalid parameters: l_over_R", stderr);
    size_t col = 28;
    for (size_t k = 0; k < t.n; k++) {
        if (!param_ok(&t.keys[k]))
            continue;
        size_t w = strlen(t.keys[k].name) + 2;
        if (col + w > 79) {
            fputs(",\n  ", stderr);
            col = 2;
        } else {
            fputs(", ", stderr);
        }
        fputs(t.keys[k].name, stderr);
        col += w;
    }
    fputc('\n', stderr);
    return -1;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void remove_stale_tmp(const char *out)
{
    char dir[1100];
    const char *slash = strrchr(out, '/'), *base = slash ? slash + 1 : out;
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - out) + 1 : 1, slash ? out : ".");
    size_t bl = strlen(base);
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d))) {
        const char *n = e->d_name, *t;
        if (strncmp(n, base, bl) || n[bl] != '.' || !(t = strstr(n + bl, ".tmp")))
            continue;
        char *end;
        long pid = strtol(t + 4, &end, 10);
        int ours = t == n + bl ? t[4] && !*end && pid > 0 && kill((pid_t)pid, 0) != 0 && errno == ESRCH
                               : !strncmp(n + bl, ".ckpt", 5) && !t[4];
        if (ours) {
            char p[2200];
            snprintf(p, sizeof p, "%.*s%s", slash ? (int)(slash - out) + 1 : 0, out, n);
            if (unlink(p) == 0)
                fprintf(stderr, "slipfield sweep: removed %s, left by an interrupted run\n", p);
        }
    }
    closedir(d);
}

int sf_cmd_sweep(int argc, char **argv)
{
    const char *path, *param = NULL, *values = NULL, *out_path = NULL, *sum_path = NULL, *estimator = NULL;
    const char *diag_path = NULL, *sum_format = NULL, *tup_path = NULL;
    size_t n = 0, threads = 0, pilot = 0;
    double target_se = NAN;
    int resume = 0, cv = 0;
    const sf_opt opts[] = {
        { "--control-variate", SF_OPT_FLAG, &cv, 0, 0, NULL },
        { "--param", SF_OPT_STRING, &param, 0, 0, NULL },
        { "--values", SF_OPT_STRING, &values, 0, 0, NULL },
        { "--realisations", SF_OPT_SIZE, &n, 1, SF_MAX_SAMPLES, NULL },
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
        { "--summary", SF_OPT_STRING, &sum_path, 0, 0, NULL },
        { "--summary-format", SF_OPT_STRING, &sum_format, 0, 0, NULL },
        { "--diagnostics", SF_OPT_STRING, &diag_path, 0, 0, NULL },
        { "--tuples", SF_OPT_STRING, &tup_path, 0, 0, NULL },
        { "--threads", SF_OPT_SIZE, &threads, 1, 1024, NULL },
        { "--resume", SF_OPT_FLAG, &resume, 0, 0, NULL },
        { "--target-se", SF_OPT_DOUBLE, &target_se, 0, 0, NULL },
        { "--pilot", SF_OPT_SIZE, &pilot, 2, SF_MAX_SAMPLES, NULL },
        { "--estimator", SF_OPT_STRING, &estimator, 0, 0, NULL },
    };
    int rc = sf_cli_parse("sweep", argc, argv, opts, sizeof opts / sizeof opts[0], &path, usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    double v[SF_LIST_MAX];
    size_t nv;
    if (!param || !values || !out_path) {
        fprintf(stderr, "slipfield sweep: --param, --values and --out are required\n");
        return SF_EXIT_USAGE;
    }
    if (check_param(param))
        return SF_EXIT_USAGE;
    if (parse_values(values, v, SF_LIST_MAX, &nv)) {
        fprintf(stderr, "slipfield sweep: --values: expected up to %d comma-separated finite numbers, got '%s'\n",
                SF_LIST_MAX, values);
        return SF_EXIT_USAGE;
    }
    int sum_long = sum_format && !strcmp(sum_format, "long");
    if (sum_format && !sum_long && strcmp(sum_format, "wide")) {
        fprintf(stderr, "slipfield sweep: --summary-format takes wide or long (got '%s')\n", sum_format);
        return SF_EXIT_USAGE;
    }
    if (sum_format && !sum_path) {
        fprintf(stderr, "slipfield sweep: --summary-format needs --summary\n");
        return SF_EXIT_USAGE;
    }
    sf_scene s0;
    if (sf_cli_load_scene("sweep", path, &s0))
        return SF_EXIT_USAGE;
    if (n)
        sf_cli_key_overridden("sweep", path, &s0, "samples", "--realisations");
    else if (sf_scene_was_set(&s0, "samples"))
        n = s0.samples;
    else {
        fprintf(stderr, "slipfield sweep: --realisations is required (or the scene's samples key)\n");
        return SF_EXIT_USAGE;
    }
    sf_model_spec spec = { SF_MODEL_PLAIN, n, pilot, target_se, cv, (int)threads, NULL, resume, NULL };
    if (sf_model_estimator(estimator, &spec.by)) {
        fprintf(stderr, "slipfield sweep: --estimator takes plain, mlmc, mlmc-boxes, mlmc-sub, antithetic or auto "
                        "(got '%s')\n", estimator);
        return SF_EXIT_USAGE;
    }
    {
        char why[300];
        if (sf_model_spec_check(&spec, why, sizeof why)) {
            fprintf(stderr, "slipfield sweep: %s\n", why);
            return SF_EXIT_USAGE;
        }
    }
    int staged = !isnan(target_se), paired = spec.by != SF_MODEL_PLAIN, anti = spec.by == SF_MODEL_ANTITHETIC ||
                                                                               spec.by == SF_MODEL_AUTO;
    char err[300];
    for (size_t k = 0; k < nv; k++) {   /* validate every value before any work */
        sf_scene t = s0;
        if (sf_sweep_set(&t, param, v[k], err, sizeof err)) {
            fprintf(stderr, "slipfield sweep: %s\n", err);
            return SF_EXIT_USAGE;
        }
        if (!(t.T > t.t_skip)) {
            fprintf(stderr, "slipfield sweep: %s = %g: T = %g s is not above t_skip = %g s: no cycle to measure\n",
                    param, v[k], t.T, t.t_skip);
            return SF_EXIT_USAGE;
        }
    }
    if (resume && strcmp(out_path, "-"))
        remove_stale_tmp(out_path);
    sf_cli_interrupt_hint(strcmp(out_path, "-") ? ": rerun with --resume" : "");
    /* under MPI every rank computes, rank 0 writes */
    int writer = sf_mc_rank(NULL) == 0;
    sf_out out = { 0 }, sum = { 0 }, diag = { 0 }, tup = { 0 };
    FILE *null = NULL;
    if (!writer) {
        null = fopen("/dev/null", "w");
        if (!null)
            return SF_EXIT_INTERNAL;
        out.f = sum.f = diag.f = tup.f = null;
        out.is_stdout = sum.is_stdout = diag.is_stdout = tup.is_stdout = 1;
    } else {
        if ((rc = sf_cli_open("sweep", out_path, path, &out)))
            return rc;
        if (sum_path && (rc = sf_cli_open("sweep", sum_path, path, &sum))) {
            sf_cli_close("sweep", &out, 0);
            return rc;
        }
        if (diag_path && (rc = sf_cli_open("sweep", diag_path, path, &diag))) {
            sf_cli_close("sweep", &out, 0);
            if (sum_path)
                sf_cli_close("sweep", &sum, 0);
            return rc;
        }
        if (tup_path && (rc = sf_cli_open("sweep", tup_path, path, &tup))) {
            sf_cli_close("sweep", &out, 0);
            if (sum_path)
                sf_cli_close("sweep", &sum, 0);
            if (diag_path)
                sf_cli_close("sweep", &diag, 0);
            return rc;
        }
    }
    /* the summary's work column: every point's estimator records its work */
    int work = paired;
    sf_sweep_write_header(out.f);
    if (sum_path && sum_long)
        sf_sweep_summary_long_header(sum.f);
    else if (sum_path)
        sf_sweep_summary_header(sum.f, work);
    if (diag_path)
        sf_sweep_diagnostics_header(diag.f);
    if (tup_path)
        sf_sweep_tuples_header(tup.f);
    int ok = 1, fail = SF_SUCCESS;
    /* off a terminal (a CI log: no live count) one line per point, on stderr */
    int lines = writer && !isatty(2);
    for (size_t k = 0; k < nv && ok; k++) {
        double t0 = now_s();
        sf_scene s = s0;
        sf_sweep_set(&s, param, v[k], err, sizeof err);
        sf_cof_plan *cp = NULL;   /* the point's COF plan, only to warn of a truncated embedding */
        if (sf_cof_plan_alloc(&s, &cp, NULL, 0) == SF_SUCCESS) {
            char where[1100];
            snprintf(where, sizeof where, "%s, %s = %g", path, param, v[k]);
            sf_cli_warn_truncated("sweep", where, &s, cp);
            const sf_cof_plan_info *in = sf_cof_plan_get_info(cp);
            if (cv && in->kind == SF_COF_FIELD && in->generator == SF_COFGEN_TILES)
                fprintf(stderr, "slipfield sweep: %s: warning: the field is a tiled window that follows the disc "
                                "(%s): no control-variate companion: the summary gives plain Monte Carlo's estimate "
                                "(estimator plain), the diagnostics' cv columns are nan; cof_generator = circulant "
                                "draws the whole strip\n",
                        where, s.cof_generator == SF_COFGEN_TILES ? "cof_generator = tiles"
                                                                  : "cof_generator = auto, the strip above 2^"
                                                                    SF_STR(SF_COF_AUTO_LOG2) " points");
        }
        sf_cof_plan_free(cp);
        char ck[1100], label[128];
        snprintf(ck, sizeof ck, "%s.ckpt%zu", out_path, k);
        snprintf(label, sizeof label, "%s = %g", param, v[k]);
        sf_sweep_point p;
        const char *ckp = strcmp(out_path, "-") ? ck : NULL;
        spec.checkpoint = ckp;
        spec.label = label;
        rc = sf_model_point(&s, &spec, 0, &p, err, sizeof err);
        if (rc) {
            fprintf(stderr, "slipfield sweep: %s = %g: %s\n", param, v[k], *err ? err : sf_strerror(rc));
            ok = 0;
            fail = rc;
        } else {
            if (p.n_valid < p.n)
                fprintf(stderr, "slipfield sweep: %s = %g: warning: %zu of %zu realisations formed no quantity of "
                                "interest (no complete cycle after t_skip: nan ratios, left out of the means)\n",
                        param, v[k], p.n - p.n_valid, p.n);
            static const char *const qname_cli[SF_SWEEP_NQ] = { "pv_x", "pv_F", "stick_fraction" };
            for (int q = 0; anti && q < SF_SWEEP_NQ; q++)
                if (p.anti.q[q].m < p.anti.n)
                    fprintf(stderr, "slipfield sweep: %s = %g: warning: %zu of %zu antithetic pairs have a member that "
                                    "formed no %s (nan): left out of that ratio's estimate (the diagnostics' %s_anti_n_used)\n",
                            param, v[k], p.anti.n - p.anti.q[q].m, p.anti.n, qname_cli[q], qname_cli[q]);
            if (p.from_checkpoint)
                fprintf(stderr, "slipfield sweep: %s = %g: %zu of %zu realisations from the checkpoint\n", param,
                        v[k], p.from_checkpoint, p.n);
            if (staged && p.stop == SF_MCSTOP_CAP)
                fprintf(stderr, "slipfield sweep: %s = %g: the cap of %zu realisations is below what %s says "
                                "--target-se %g needs: the interval is wider than the target\n",
                        param, v[k], n, paired ? "the estimator's sizing" : "the pilot", target_se);
            if ((sum_path || diag_path) && sf_unum_sweep(&s, &p, (int)threads, err, sizeof err))
                fprintf(stderr, "slipfield sweep: %s = %g: warning: no numerical error of the means (its companion "
                                "failed: %s)\n", param, v[k], err);
            if (lines) {
                fprintf(stderr, "slipfield sweep: point %zu/%zu (%s = %g): %zu realisations in %.3g s", k + 1, nv,
                        param, v[k], p.n, now_s() - t0);
                if (p.from_checkpoint)
                    fprintf(stderr, " (%zu from the checkpoint)", p.from_checkpoint);
                fputc('\n', stderr);
            }
            sf_sweep_write_rows(out.f, param, v[k], &p);   /* with the companions u_num_mean is made of */
            if (sum_path && sum_long)
                sf_sweep_summary_long_rows(sum.f, param, v[k], &p);
            else if (sum_path)
                sf_sweep_summary_row(sum.f, param, v[k], &p, work);
            if (diag_path)
                sf_sweep_diagnostics_row(diag.f, param, v[k], &p);
            if (tup_path)
                sf_sweep_write_tuples(tup.f, param, v[k], &p);
        }
        sf_sweep_point_free(&p);
    }
    if (!writer) {
        fclose(null);
        return sf_cli_status(fail);
    }
    int st = sf_cli_close("sweep", &out, ok);
    if (sum_path && sf_cli_close("sweep", &sum, ok) && ok)
        st = SF_EXIT_USAGE;
    if (diag_path && sf_cli_close("sweep", &diag, ok) && ok)
        st = SF_EXIT_USAGE;
    if (tup_path && sf_cli_close("sweep", &tup, ok) && ok)
        st = SF_EXIT_USAGE;
    if (ok && !st && strcmp(out_path, "-"))   /* complete: the checkpoints are no longer needed */
        for (size_t k = 0; k < nv; k++) {
            char ck[1100];
            snprintf(ck, sizeof ck, "%s.ckpt%zu", out_path, k);
            unlink(ck);
        }
    return ok ? st : sf_cli_status(fail);
}
