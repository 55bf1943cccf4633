/* The accuracy plan's error model against stored tables of the design
 * (design.c), without a solve: plan_errmodel (the predicted error at
 * held-out seeds) and plan_errfit (err_pred's constants refitted from the
 * data they were fitted on). */
#include "checks.h"
#include "common.h"
#include "design_common.h"
#include "../stats.h"
#include "numplan.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

/* ---- Stored design data: the design's per-point tables at fixed seeds
 * (scripts/design-data.sh writes them beside a case, as NAME.tsv for
 * NAME.md), read without a solve.  Every stored point's scene is rebuilt
 * from its design seed and index (the Latin hypercube of design.c) and
 * planned by the code under test.  Its settings must be the stored ones: the
 * stored errors describe those settings and no others, so a changed plan
 * makes the data stale, and the case fails.  A point decides as in
 * plan_design: every level counts the same cycles and at least one QoI's
 * reference is converged to qoi_tol; its error is the largest stored error
 * of those QoIs (two significant digits as printed). */
enum { ECOLS = 22, EC_SEED = 0, EC_DSEED = 1, EC_I = 2, EC_PT = 3, EC_UND = 12, EC_A = 13, EC_E = 16 };

typedef struct {
    double lr, cv, mu;           /* the point's scene (from its design seed, not the table's rounded print) */
    double ach;                  /* its error as stored */
    double err_total, err_pred;  /* the plan under test's budget and prediction */
    int fitted;                  /* err_pred is the fit's (inside its box, numplan.c) */
} stored_point;

typedef struct {
    char path[600], found[400], hdr[1200];
    size_t rows, stale, undecided, nonfinite, pts;
    stored_point *pt;                /* the decided points, pts of them */
    double *rings_st, *rings_now;    /* per row: the stored and the planned rings */
} stored_data;

static void stored_free(stored_data *d)
{
    free(d->pt);
    free(d->rings_st);
    free(d->rings_now);
}

/* Read case c's stored data into d (the caller frees it with stored_free,
 * whatever the return): SF_EIO (no file), SF_EPARSE (a malformed line) or
 * the planner's refusal, noted. */
static int stored_read(const sf_case *c, sf_result *r, const double *lo, const double *hi, stored_data *d)
{
    const sf_scene *s0 = &c->scene;
    size_t n = s0->samples;
    memset(d, 0, sizeof *d);
    if (check_data_path(c, d->path, sizeof d->path))
        return SF_EINVAL;
    FILE *f = fopen(d->path, "r");
    if (!f) {
        sf_note(r, "**Stored data missing:** cannot read %s: regenerate it with `sh scripts/design-data.sh FIRST LAST "
                   "> %s`.", d->path, d->path);
        return SF_EIO;
    }
    char *line = NULL, *fld[ECOLS];
    size_t cap = 0, lineno = 0, ncap = 0;
    while (getline(&line, &cap, f) > 0)
        ncap++;   /* at most this many points */
    rewind(f);
    d->pt = check_alloc(ncap * sizeof *d->pt);
    d->rings_st = check_alloc(ncap * sizeof *d->rings_st);
    d->rings_now = check_alloc(ncap * sizeof *d->rings_now);
    double *u = NULL;
    unsigned long dseed = 0;
    int rc = SF_SUCCESS;
    while (getline(&line, &cap, f) > 0) {
        lineno++;
        line[strcspn(line, "\r\n")] = 0;
        if (line[0] == '#') {
            size_t k = strlen(d->hdr);
            snprintf(d->hdr + k, sizeof d->hdr - k, "> %s\n", line + 1 + (line[1] == ' '));
            continue;
        }
        if (!line[0] || !strncmp(line, "seed\t", 5))
            continue;
        size_t nf = 1;
        for (const char *t = line; (t = strchr(t, '\t')); t++)
            nf++;
        int ok = nf == ECOLS;
        for (size_t k = 0; ok && k < ECOLS; k++) {
            fld[k] = k ? strchr(fld[k - 1], 0) + 1 : line;
            char *tab = strchr(fld[k], '\t');
            if (tab)
                *tab = 0;
        }
        double a[NQ], e[NQ], lr;
        char *end1 = NULL, *end2 = NULL;
        unsigned long ds = ok ? strtoul(fld[EC_DSEED], &end1, 10) : 0;
        size_t i = ok ? (size_t)strtoul(fld[EC_I], &end2, 10) : 0;
        ok = ok && !*end1 && !*end2 && i < n;
        for (int k = 0; k < NQ && ok; k++)
            ok = check_parse_num(fld[EC_A + k], &a[k]) && check_parse_num(fld[EC_E + k], &e[k]);
        if (!ok) {
            sf_note(r, "**%s:%zu: not a stored design point** (%d tab-separated columns wanted, a point index "
                       "below the design's %zu samples, numbers in the error columns).", d->path, lineno, ECOLS, n);
            rc = SF_EPARSE;
            break;
        }
        if (!u || ds != dseed) {
            free(u);
            u = design_points(dseed = ds, n);
        }
        sf_scene s;
        sf_plan pl;
        char err[256] = "";
        if ((rc = design_scene(s0, lo, hi, u + ND * i, &s, &lr, err, sizeof err)) ||
            (rc = sf_plan_make(&s, &pl, err, sizeof err))) {
            sf_note(r, "**%s:%zu: cannot plan the point:** %s", d->path, lineno, err);
            break;
        }
        d->rings_st[d->rows] = strtod(fld[EC_PT + 6], NULL);
        d->rings_now[d->rows] = pl.num.quadrature ? (double)pl.num.cells : 0;
        d->rows++;
        char want[200], got[200];
        design_point_text(want, sizeof want, "\t", lr, &s, &pl.num);
        snprintf(got, sizeof got, "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s", fld[EC_PT], fld[EC_PT + 1], fld[EC_PT + 2],
                 fld[EC_PT + 3], fld[EC_PT + 4], fld[EC_PT + 5], fld[EC_PT + 6], fld[EC_PT + 7]);
        if (strcmp(want, got)) {
            if (!d->stale++) {
                for (char *t = want; (t = strchr(t, '\t'));)
                    *t = ' ';
                for (char *t = got; (t = strchr(t, '\t'));)
                    *t = ' ';
                snprintf(d->found, sizeof d->found, "line %zu (seed %.12s, point %zu): stored l/R, CV, v_b, mu, T, "
                         "qoi_tol, rings, rtol '%.120s', planned now '%.120s'", lineno, fld[EC_SEED], i, got, want);
            }
            continue;
        }
        if (!strcmp(fld[EC_UND], "1")) {   /* undecidable as measured (a cycle at the edge, none, no PV_x) */
            d->undecided++;
            continue;
        }
        double pa = -1;
        for (int k = 0; k < NQ; k++) {
            if (!isfinite(a[k]) || !isfinite(e[k])) {
                d->nonfinite++;
                pa = NAN;
                break;
            }
            if (e[k] <= s.qoi_tol)   /* the reference converged to the tolerance under test */
                pa = sf_max(pa, a[k]);
        }
        if (!(pa >= 0)) {
            d->undecided += !isnan(pa);
            continue;
        }
        stored_point *p = &d->pt[d->pts++];
        p->lr = lr;
        p->cv = s.mu_std / s.mu_mean;
        p->mu = s.mu_mean;
        p->ach = pa;
        p->err_total = pl.num.err_total;
        p->err_pred = pl.num.err_pred;
        p->fitted = pl.num.pred_fitted;
    }
    free(line);
    free(u);
    fclose(f);
    return rc;
}

/* The rows every stored-data case shares (the data describe the plan under
 * test, finite, some decided: n of the named test), and the evidence of
 * stale data.  1: the data can be used. */
static int stored_gates(sf_result *r, const stored_data *d, const char *test)
{
    sf_note(r, "Stored data: %s, %zu design points (its header:)\n\n%s", d->path, d->rows, d->hdr);
    char t[700];
    if (d->stale)
        snprintf(t, sizeof t, "stored data stale: %zu of %zu points differ; regenerate with scripts/design-data.sh",
                 d->stale, d->rows);
    else
        snprintf(t, sizeof t, "all %zu stored points: the same design point and the same rings and rtol", d->rows);
    sf_check_true(r, "stored points describe the plan under test (each point's scene from its design seed, "
                     "the planner's rings and rtol as the measuring run printed them)", d->rows > 0 && !d->stale, t);
    sf_check_le(r, "decidable stored points with a non-finite error", (double)d->nonfinite, 0);
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "decided stored points (the %s's n)", test);
    sf_check_ge(r, q, (double)d->pts, 1);
    if (d->stale) {   /* the evidence: the settings planned now against the stored ones */
        sf_note(r, "\n**Stored data stale:** the plan under test does not make the settings the stored errors were "
                   "measured at (%zu of %zu points; the first, %s); regenerate them with `sh scripts/design-data.sh` "
                   "(the seeds in the header above).", d->stale, d->rows, d->found);
        sf_plot *pp = sf_result_plot(r, "errmodel_stale", "Stale stored data: the rings planned now against the stored",
                                     "rings the measuring run planned (stored) [-]", "rings the code under test plans [-]");
        sf_plot_series(pp, "stored design points", SF_STYLE_POINTS, d->rows, d->rings_st, d->rings_now);
        double dx[2] = { 0, SF_PLAN_MAX_RINGS };
        sf_plot_series(pp, "the same rings", SF_STYLE_LINES, 2, dx, dx);
    }
    return !d->stale && d->pts;
}

/* Run body on case c's stored data (its design box lo, hi; the data read
 * and gated by stored_read and stored_gates) when they can be used, and
 * free them: SF_SUCCESS when stale or without a decided point (a row
 * failed), SF_EINVAL (the scene), SF_EIO, SF_EPARSE, the planner's refusal
 * or body's return. */
typedef int stored_body(const sf_case *c, sf_result *r, const double *lo, const double *hi, const stored_data *d);

static int stored_run(const sf_case *c, sf_result *r, const char *test, stored_body *body)
{
    double lo[ND], hi[ND];
    stored_data d;
    memset(&d, 0, sizeof d);
    if (design_box(c, r, lo, hi))
        return SF_EINVAL;
    int rc = stored_read(c, r, lo, hi, &d);
    if (!rc && stored_gates(r, &d, test))
        rc = body(c, r, lo, hi, &d);
    stored_free(&d);
    return rc;
}

/* ---- plan_errmodel: the predicted error err_pred (numplan.c) against
 * stored, held-out measurements: the design's tables at seeds never used
 * to fit it.  The points whose stored error exceeds the recomputed
 * err_pred are counted: an exact one-sided binomial test of H0 'rate <=
 * 5%' at the case's alpha.  The stored errors carry two significant
 * digits; one within its print's rounding of the prediction counts as
 * above (against the model). */
#define ERR_LR_BINS 3

/* the largest value a 2-significant-digit print of x >= 0 may stand for */
static double print_hi(double x)
{
    return x > 0 ? x + 0.5 * pow(10, floor(log10(x)) - 1) : 0;
}

static int errmodel_body(const sf_case *c, sf_result *r, const double *lo, const double *hi, const stored_data *d)
{
    size_t pts = d->pts, over = 0, over_hi = 0, fitted = 0, bin_n[ERR_LR_BINS] = { 0 }, bin_over[ERR_LR_BINS] = { 0 };
    double *pred = check_alloc(pts * sizeof *pred), *ach = check_alloc(pts * sizeof *ach);
    double *ratio = check_alloc(pts * sizeof *ratio), *ratio_hi = check_alloc(pts * sizeof *ratio_hi);
    for (size_t j = 0; j < pts; j++) {
        const stored_point *q = &d->pt[j];
        double p = q->err_pred, ah = print_hi(q->ach);
        fitted += q->fitted;
        pred[j] = p;
        ach[j] = fmax(q->ach, 1e-17);
        ratio[j] = q->ach / p;
        ratio_hi[j] = ah / p;
        over += q->ach > p;
        over_hi += ah > p;
        double x = log(q->lr / lo[0]) / log(hi[0] / lo[0]) * ERR_LR_BINS;
        size_t b = x < 0 ? 0 : x >= ERR_LR_BINS ? ERR_LR_BINS - 1 : (size_t)x;
        bin_n[b]++;
        bin_over[b] += ah > p;
    }
    sf_note(r, "\n**The prediction against the stored errors** (%zu decidable points of %zu: %zu undecidable as "
               "measured; err_pred from the fit at %zu of them, the budget at the rest). A point's error is the "
               "largest stored error of its QoIs whose reference is converged to qoi_tol; %zu exceed the "
               "recomputed err_pred as printed, %zu when a print within its rounding counts as above (the "
               "gated count):\n", pts, d->rows, d->undecided, fitted, over, over_hi);
    design_rate_test(r, "decided points whose stored error exceeds the recomputed err_pred", over_hi, pts, UNDER_RATE,
              c->spec.alpha);
    size_t kc = design_binom_critical(pts, UNDER_RATE, c->spec.alpha);
    if (kc <= pts) {
        gsl_sort(ratio_hi, 1, pts);   /* the gate fails when kc points exceed: below the kc-th largest ratio */
        sf_note(r, "- Power on these data (deterministic): err_pred scaled by any factor below %.3g puts %zu or "
                   "more points above it, and the gate fails (a factor above it passes).",
                ratio_hi[pts - kc], kc);
    }
    sf_note(r, "\n| l/R (log thirds of %g-%g) | decided points | above err_pred | fraction |\n|---|---|---|---|",
            lo[0], hi[0]);
    for (int b = 0; b < ERR_LR_BINS; b++) {
        double e0 = lo[0] * pow(hi[0] / lo[0], (double)b / ERR_LR_BINS);
        double e1 = lo[0] * pow(hi[0] / lo[0], (double)(b + 1) / ERR_LR_BINS);
        sf_note(r, "| %.3g-%.3g | %zu | %zu | %.3f |%s", e0, e1, bin_n[b], bin_over[b],
                bin_n[b] ? (double)bin_over[b] / (double)bin_n[b] : 0, b + 1 == ERR_LR_BINS ? "\n" : "");
    }
    design_report_sharpness(r, ratio, pts);
    check_plot_vs_predicted(r, "errmodel_scatter", "Predicted vs stored achieved error (held-out seeds)",
                            "predicted relative QoI error err_pred (the plan's 95% bound) [-]",
                            "achieved relative QoI error of the point (stored) [-]", "decided design points",
                            "achieved = predicted", pts, pred, ach, 1e-5, 2e-2);
    free(pred);
    free(ach);
    free(ratio);
    free(ratio_hi);
    return SF_SUCCESS;
}

/* ---- plan_errfit: the provenance of err_pred's constants (numplan.c).
 * From the stored design data err_pred was fitted on, redo its fit: least
 * squares (GSL's gsl_multifit_linear) of y = ln(achieved / err_total) on
 * 1, ln(l/R), CV and mean COF over the decided points inside its box,
 * then the intercept lifted by the residuals' 95th percentile (GSL's
 * quantile: linear interpolation between order statistics), so that
 *   err_pred = err_total exp(b0 + q95) (l/R)^b1 exp(b2 CV + b3 mu)
 * and factor = exp(b0 + q95), lr_exp = -b1, cv_coef = b2, mu_coef = b3.
 * The code's constants (sf_numplan_pred_model_get) must be that fit to
 * their printed precision: written with 3 decimals, |code - refit| <=
 * 0.5e-3, plus FIT_ROUNDOFF for the fit's own floating point (an SVD of a
 * 4-column matrix with condition ~1e2: ~1e-13, bounded far above).  It
 * tells a constant that is not the fit of its data (a typo, an edit, a
 * refit on other data), not a wrong model: the constants' statistical
 * uncertainty (their standard errors, reported) is 100-600x larger. */
#define FIT_HALF_ULP 0.5e-3
#define FIT_ROUNDOFF 1e-9
#define FIT_QUANTILE 0.95
enum { NFIT = 4 };

static int errfit_body(const sf_case *c, sf_result *r, const double *lo, const double *hi, const stored_data *d)
{
    (void)c;
    (void)lo;
    (void)hi;
    size_t n = 0, zero = 0;
    for (size_t j = 0; j < d->pts; j++) {
        n += d->pt[j].fitted && d->pt[j].ach > 0;
        zero += d->pt[j].fitted && !(d->pt[j].ach > 0);
    }
    sf_check_ge(r, "decided stored points inside err_pred's box (the fit's n; 2x its parameters at least)", (double)n,
                2 * NFIT);
    sf_check_le(r, "decided points inside the box with a stored error of 0 (no logarithm)", (double)zero, 0);
    if (n < 2 * NFIT)
        return SF_SUCCESS;
    gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(n, NFIT);
    if (!w)
        return SF_ENOMEM;
    double *xd = check_alloc(n * NFIT * sizeof *xd), *yd = check_alloc(n * sizeof *yd), *rd = check_alloc(n * sizeof *rd);
    double bd[NFIT], cd[NFIT * NFIT], *ys = check_alloc(n * sizeof *ys), *rs = check_alloc(n * sizeof *rs), chisq;
    gsl_matrix_view Xv = gsl_matrix_view_array(xd, n, NFIT), cv_ = gsl_matrix_view_array(cd, NFIT, NFIT);
    gsl_vector_view yv = gsl_vector_view_array(yd, n), bv = gsl_vector_view_array(bd, NFIT), rv = gsl_vector_view_array(rd, n);
    gsl_matrix *X = &Xv.matrix, *cov = &cv_.matrix;
    gsl_vector *y = &yv.vector, *b = &bv.vector, *res = &rv.vector;
    for (size_t j = 0, k = 0; j < d->pts; j++) {
        const stored_point *q = &d->pt[j];
        if (!(q->fitted && q->ach > 0))
            continue;
        gsl_matrix_set(X, k, 0, 1);
        gsl_matrix_set(X, k, 1, log(q->lr));
        gsl_matrix_set(X, k, 2, q->cv);
        gsl_matrix_set(X, k, 3, q->mu);
        gsl_vector_set(y, k, ys[k] = log(q->ach / q->err_total));
        k++;
    }
    gsl_multifit_linear(X, y, b, cov, &chisq, w);
    gsl_multifit_linear_residuals(X, y, b, res);
    for (size_t k = 0; k < n; k++)
        rs[k] = gsl_vector_get(res, k);
    gsl_sort(rs, 1, n);
    double q95 = gsl_stats_quantile_from_sorted_data(rs, 1, n, FIT_QUANTILE);
    /* the quantile's distribution-free 95% interval [rs[jl], rs[jh]]
     * (0-based order statistics): the count X of residuals below the true
     * quantile is Bin(n, 0.95); P(X <= jl) <= 0.025 and P(X > jh) <= 0.025 */
    size_t jl = 0, jh = n - 1;
    while (jl + 1 < n && gsl_cdf_binomial_P((unsigned)(jl + 1), FIT_QUANTILE, (unsigned)n) <= 0.025)
        jl++;
    while (jh > jl + 1 && gsl_cdf_binomial_Q((unsigned)(jh - 1), FIT_QUANTILE, (unsigned)n) <= 0.025)
        jh--;
    double b0 = gsl_vector_get(b, 0);
    sf_numplan_pred_model m;
    sf_numplan_pred_model_get(&m);
    const char *name[NFIT] = { "factor (PF)", "l/R exponent (PL)", "CV coefficient (PC)", "mean COF coefficient (PM)" };
    double code[NFIT] = { m.factor, m.lr_exp, m.cv_coef, m.mu_coef };
    double fit[NFIT] = { exp(b0 + q95), -gsl_vector_get(b, 1), gsl_vector_get(b, 2), gsl_vector_get(b, 3) };
    double se[NFIT];
    for (int k = 0; k < NFIT; k++)
        se[k] = sqrt(gsl_matrix_get(cov, (size_t)k, (size_t)k));
    /* ln factor = b0 + q95: the intercept's se and the quantile's, read
     * off its interval as a normal one's (width / 3.92), in quadrature */
    double se_q = (rs[jh] - rs[jl]) / 3.92;
    double se_lnf = hypot(se[0], se_q);
    se[0] = fit[0] * se_lnf;
    size_t above = 0;
    for (size_t k = 0; k < n; k++)
        above += gsl_vector_get(res, k) > q95;
    sf_note(r, "\n**The refit** (%zu decided points inside the box; %zu of %zu decided points outside it left out): "
               "least squares of ln(achieved / err_total) on 1, ln(l/R), CV, mean COF: intercept b0 = %.4f, residual "
               "sd %.3f (sd of ln(achieved / err_total) itself %.3f); the residuals' %.0fth percentile %.4f "
               "(distribution-free 95%% interval [%.3f, %.3f]); ln factor = b0 + q95 = %.4f; %zu of %zu fitting "
               "points above the refit bound (%.1f%%).\n", n, d->pts - n - zero, d->pts, b0,
            sqrt(chisq / (double)(n - NFIT)), gsl_stats_sd(ys, 1, n), 100 * FIT_QUANTILE, q95, rs[jl], rs[jh],
            b0 + q95, above, n, 100.0 * (double)above / (double)n);
    sf_note(r, "| constant | refit from the data | numplan.c | code - refit | standard error of the fit (statistical) "
               "| se / allowed difference |\n|---|---|---|---|---|---|");
    for (int k = 0; k < NFIT; k++)
        sf_note(r, "| %s | %.5f | %.5g | %+.2e | %.3f | %.0f |%s", name[k], fit[k], code[k], code[k] - fit[k], se[k],
                se[k] / FIT_HALF_ULP, k + 1 == NFIT ? "\n" : "");
    sf_note(r, "The factor's standard error combines the intercept's (%.3f in ln) and the 95th percentile's (its "
               "interval's width / 3.92: %.3f in ln). The gate below is exact (the fit of fixed data): it holds the "
               "code's constants to the fit at their printed 3 decimals; their statistical uncertainty, tens to "
               "hundreds of times that, is what a different set of seeds would move them by.\n",
            sqrt(gsl_matrix_get(cov, 0, 0)), se_q);
    double *px = check_alloc(n * sizeof *px), *py = check_alloc(n * sizeof *py);
    for (size_t k = 0; k < n; k++) {   /* the refit bound at each fitting point, over err_total */
        py[k] = exp(ys[k]);
        px[k] = exp(ys[k] - gsl_vector_get(res, k) + q95);
    }
    sf_plot *pp = sf_result_plot(r, "errfit_scatter", "err_pred's fitting data against the refit bound",
                                 "refit bound / err_total at the point, exp(b0 + q95 + b1 ln(l/R) + b2 CV + b3 mu) [-]",
                                 "achieved error / err_total (stored) [-]");
    sf_plot_log(pp, 1, 1);
    sf_plot_series(pp, "decided design points inside the box", SF_STYLE_POINTS, n, px, py);
    double dx[2];
    gsl_stats_minmax(&dx[0], &dx[1], px, 1, n);
    sf_plot_series(pp, "achieved = the refit bound", SF_STYLE_LINES, 2, dx, dx);
    free(px);
    free(py);
    for (int k = 0; k < NFIT; k++) {
        char t[160];
        snprintf(t, sizeof t, "err_pred's %s in numplan.c against its refit from the stored design data", name[k]);
        sf_check_abs(r, t, code[k], fit[k], FIT_HALF_ULP + FIT_ROUNDOFF);
    }
    gsl_multifit_linear_free(w);
    free(xd);
    free(yd);
    free(rd);
    free(ys);
    free(rs);
    return SF_SUCCESS;
}

static int chk_errmodel(const sf_case *c, sf_result *r) { return stored_run(c, r, "calibration test", errmodel_body); }

static int chk_errfit(const sf_case *c, sf_result *r) { return stored_run(c, r, "fit", errfit_body); }

const sf_check_def sf_checks_design_stored[] = {
    { "plan_errmodel", chk_errmodel, "the plan's predicted error against stored held-out measurements of the design (no solve)" },
    { "plan_errfit", chk_errfit, "err_pred's constants (numplan.c) against their refit from the stored design data they were fitted on" },
    { NULL, NULL, NULL }
};
