/* The variance-reduced Monte Carlo estimators (sweep.h: the control
 * variate, two levels -- plain, on boxes of boxes and on every 2nd node --,
 * antithetic pairs, and the estimators at a target standard error): each
 * estimate is what its definition says from its own runs, and its ratio
 * means equal plain Monte Carlo's on the same or independent streams. */
#include "checks.h"
#include "common.h"
#include "mcstop.h"
#include "antithetic.h"
#include "mlmc.h"
#include "cof.h"
#include "lognormal.h"
#include "montecarlo.h"
#include "sweep.h"
#include "sf_error.h"
#include "../stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_statistics_double.h>

static const char *const ratio_name[3] = { "PV_x", "PV_F", "stick fraction" };

/* the variance reduction factors vrf[k * 3 + q] of the three ratios over
 * the K sweep points at l/R = lr[k] */
static void plot_vrf(sf_result *r, const char *title, size_t K, const double *lr, const double *vrf)
{
    sf_plot *pl = sf_result_plot(r, "vrf", title, "l/R [-]", "variance reduction factor [-]");
    sf_plot_log(pl, 1, 1);
    for (int q = 0; q < 3; q++) {
        double *y = check_alloc(K * sizeof *y);
        for (size_t k = 0; k < K; k++)
            y[k] = vrf[k * 3 + q];
        sf_plot_series(pl, ratio_name[q], SF_STYLE_LINESPOINTS, K, lr, y);
        free(y);
    }
    sf_plot_hline(pl, "no reduction", 1);
}

/* ---- the control variate (sweep.h: sf_sweep_run_cv) ----
 *
 * Per sweep point: (1) the companion's sample mean against the field's
 * mean mu_mean: the estimator is unbiased exactly when E[C] = mu_mean.  A
 * z test with the scene's mu_std as the companions' std: C averages COF
 * values (bilinear interpolants of nodes) of std mu_std each, so its std
 * is at most mu_std (equal when the field is constant over the path), and
 * the test is exact in its variance where Student's t is not: the
 * companions are right-skewed (nearly lognormal at large l/R), a low
 * sample mean comes with a small sample sd, and t's lower tail is far
 * heavier than Student's (p = 9.6e-6 for a mean 3.1 standard deviations
 * low, at 1 fresh seed in 300); (2) exact, per ratio: the estimate minus
 * the plain mean is -beta (mean C - mu_mean) (the least-squares
 * intercept), recomputed here from the companions and the oracle's
 * mu_mean; (3) the variance reduction factor per QoI and point, reported,
 * and gated (>= 2) for PV_x and PV_F at the large l/R where the companion
 * all but fixes them.  The stick fraction's is reported, not gated: T_sk
 * in a finite window jumps with the COF (a stick phase cut by the window's
 * end), so its correlation with C has a heavy lower tail at n = 24 (300
 * fresh seeds: 1.80 at the least, 2.4-3.1 at five more, median 8.0;
 * PV_x and PV_F at least 11.4 and 61.8). */
static int chk_cv_unbiased(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param)
        return SF_EINVAL;
    size_t nrow = 3 + 1;
    double *lr = check_alloc(K * sizeof *lr), *vrf = check_alloc(K * 3 * sizeof *vrf);
    char tab[4096];
    size_t used = 0;
    int rc = SF_SUCCESS;
    double alpha = c->spec.alpha / (double)K;   /* one t-test per point */
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene s = *s0;
        sf_sweep_point p;
        char err[256] = "";
        rc = sf_sweep_set(&s, c->spec.sweep_param, c->spec.sweep.v[k], err, sizeof err);
        if (!rc)
            rc = sf_sweep_run_cv(&s, s0->samples, 0, NULL, 0, NULL, &p, err, sizeof err);
        if (rc) {
            sf_note(r, "**Sweep failed at %s = %g:** %s\n", c->spec.sweep_param, c->spec.sweep.v[k], err);
            break;
        }
        lr[k] = s.l / s.R;
        sf_result_data(r, "the companions", p.n, p.companion);
        double cm = gsl_stats_mean(p.companion, 1, p.n), sd = s0->mu_std;
        double z = sd > 0 ? (cm - s0->mu_mean) / (sd / sqrt((double)p.n)) : (cm == s0->mu_mean ? 0 : INFINITY);
        char what[SF_LABEL_LEN];
        /* the z test's minimum detectable shift of E[C] at power 0.99, relative to mu_mean; a shift d of E[C]
           biases each ratio's estimate by beta d */
        double mdec = (gsl_cdf_ugaussian_Pinv(1 - alpha / 2) + gsl_cdf_ugaussian_Pinv(0.99)) * sd /
                      sqrt((double)p.n) / s0->mu_mean;
        snprintf(what, sizeof what, "l/R = %g: companion's mean %.6g = mu_mean %g (z, std at most mu_std %g; MDE "
                 "%.2f%% of mu_mean at power 0.99)", lr[k], cm, s0->mu_mean, sd, 100 * mdec);
        sf_check_pvalue(r, what, 2 * gsl_cdf_ugaussian_Q(fabs(z)), alpha, p.n);
        double gap = 0;   /* |(cv - plain) + beta (mean C - mu_mean)| over the ratios */
        for (int q = 0; q < 3; q++) {
            double cmq = 0, ym = 0;
            size_t m = 0;
            for (size_t i = 0; i < p.n; i++) {
                double y = p.ratio[i * SF_SWEEP_NQ + q], cc = p.companion[i];
                if (isfinite(y) && isfinite(cc)) {
                    cmq += cc;
                    ym += y;
                    m++;
                }
            }
            cmq /= (double)m;
            ym /= (double)m;
            gap = sf_max(gap, fabs((p.cv[q].mean - ym) + p.cv[q].beta * (cmq - s0->mu_mean)));
            vrf[k * 3 + q] = p.cv[q].vrf;
            used += (size_t)snprintf(tab + used, sizeof tab - used,
                                     "| %g | %s | %.5f +- %.5f | %.5f +- %.5f | %.3g | %.3g | %.2f%% |\n", lr[k],
                                     ratio_name[q], p.rstat[q].mean, p.rstat[q].se, p.cv[q].mean, p.cv[q].se,
                                     p.cv[q].beta, p.cv[q].vrf,
                                     100 * fabs(p.cv[q].beta) * mdec * s0->mu_mean / fabs(p.rstat[q].mean));
        }
        snprintf(what, sizeof what, "l/R = %g: |cv - plain + beta (mean C - mu_mean)|, max over the ratios", lr[k]);
        sf_check_le(r, what, gap, 1e-12);
        if (lr[k] >= 100)
            for (int q = 0; q < 2; q++) {   /* PV_x, PV_F; the stick fraction's is reported (above) */
                snprintf(what, sizeof what, "l/R = %g: %s variance reduction factor", lr[k], ratio_name[q]);
                sf_check_ge(r, what, vrf[k * 3 + q], 2);
            }
        sf_sweep_point_free(&p);
    }
    (void)nrow;
    if (!rc) {
        sf_note(r, "%zu realisations per point (seed %lu). Ratio means, plain and with the control variate "
                   "(+- standard error), the slope beta, the variance reduction factor and the smallest bias of the "
                   "ratio's estimate that (1) detects at power 0.99 (beta x the companion's MDE, relative to the "
                   "plain mean; (2) sees any error in the known mean or the intercept exactly):\n\n"
                   "| l/R | QoI | plain | control variate | beta | reduction | MDE via (1) |\n"
                   "|---|---|---|---|---|---|---|\n%s\n",
                s0->samples, s0->seed, tab);
        plot_vrf(r, "Variance reduction of the control variate", K, lr, vrf);
    }
    free(lr);
    free(vrf);
    return rc;
}

/* ---- the two-level estimator (sweep.h: sf_sweep_run_mlmc, mlmc.h) ---- */

#define ML_PILOT 10   /* the CLI's default pilot */

/* the mean of the finite x[i] (i < n), their count and (var) variance */
static double finite_mean(const double *x, size_t n, size_t *m, double *var)
{
    double *v = check_alloc((n ? n : 1) * sizeof *v);
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i]))
            v[k++] = x[i];
    double mean = k ? gsl_stats_mean(v, 1, k) : NAN;
    *var = k > 1 ? gsl_stats_variance_m(v, 1, k, mean) : NAN;
    free(v);
    *m = k;
    return mean;
}

/* the estimators the checks below compare with plain Monte Carlo */
enum { EST_MLMC, EST_ANTI, EST_BOXES, EST_SUB };

/* Estimator est's point at scene s: plain's variance at n_plain, the
 * pilot ML_PILOT. */
static int est_run(const sf_scene *s, int est, size_t n_plain, sf_sweep_point *p, char *err, size_t errlen)
{
    switch (est) {
    case EST_MLMC:
        return sf_sweep_run_mlmc(s, n_plain, ML_PILOT, 0, NULL, p, err, errlen);
    case EST_BOXES:
        return sf_sweep_run_mlmc_boxes(s, n_plain, ML_PILOT, 0, NULL, p, err, errlen);
    case EST_SUB:
        return sf_sweep_run_mlmc_sub(s, n_plain, ML_PILOT, 0, NULL, p, err, errlen);
    default:
        return sf_sweep_run_antithetic(s, n_plain, ML_PILOT, 0, NULL, p, err, errlen);
    }
}

/* The estimator's point at scene s (its pilot ML_PILOT, plain's variance
 * at s->samples as the target) and plain Monte Carlo's of as many rows:
 * SF_SUCCESS, or the failure noted in r and both points freed. */
static int est_and_plain(const sf_scene *s, int est, sf_sweep_point *p, sf_sweep_point *pl, sf_result *r)
{
    char err[256] = "";
    memset(pl, 0, sizeof *pl);
    int rc = est_run(s, est, s->samples, p, err, sizeof err);
    if (!rc)
        rc = sf_sweep_run(s, p->n, 0, NULL, 0, NULL, pl, err, sizeof err);
    if (rc) {
        sf_note(r, "The sweep failed: %s\n", *err ? err : sf_strerror(rc));
        sf_sweep_point_free(p);
        sf_sweep_point_free(pl);
    }
    return rc;
}

/* The estimator's rows (p->qoi) that differ from plain's, bit for bit. */
static double rows_differ(const sf_sweep_point *p, const sf_sweep_point *pl)
{
    size_t diff = 0;
    for (size_t i = 0; i < p->n * SF_SWEEP_NQ; i++)
        diff += memcmp(&p->qoi[i], &pl->qoi[i], sizeof *p->qoi) != 0;
    return (double)diff;
}

/* The two levels' estimate and its se recomputed from the values point p
 * keeps (rows (1) and (2) of the checks below), with the plot of level
 * 1's differences. */
static void ml_recompute(const sf_sweep_point *p, sf_result *r)
{
    size_t n1 = p->ml.n[1], n0 = p->ml.n[0];
    double gap = 0, segap = 0;
    double *d = check_alloc(n1 * sizeof *d), *b = check_alloc((n0 ? n0 : 1) * sizeof *b), *x = check_alloc(n1 * sizeof *x);
    sf_plot *plt = sf_result_plot(r, "levels", "Level 1: fine - coarse ratio per pair (one field each)", "pair [-]",
                                  "fine - coarse ratio [-]");
    double *xf = check_alloc(n1 * sizeof *xf), *df = check_alloc(n1 * sizeof *df);
    for (int q = 0; q < 3; q++) {
        size_t nf = 0;   /* the plot shows the pairs whose difference is finite */
        for (size_t i = 0; i < n1; i++) {
            x[i] = (double)i;
            d[i] = (p->qoi[i * SF_SWEEP_NQ + q] - p->ml.coarse1[i * SF_SWEEP_NQ + q]) / p->det[q];
            if (isfinite(d[i])) {
                xf[nf] = x[i];
                df[nf++] = d[i];
            }
        }
        sf_plot_series(plt, ratio_name[q], SF_STYLE_POINTS, nf, xf, df);
        for (size_t i = 0; i < n0; i++)
            b[i] = p->ml.coarse0[i * SF_SWEEP_NQ + q] / p->det[q];
        size_t m0, m1;   /* the finite values (a realisation may form no QoI: excluded) */
        double v0, v1, mean = finite_mean(b, n0, &m0, &v0) + finite_mean(d, n1, &m1, &v1);
        char what[SF_LABEL_LEN];
        snprintf(what, sizeof what, "%s: level 0's coarse ratios", ratio_name[q]);
        sf_result_sample(r, what, m0, n0 - m0);
        snprintf(what, sizeof what, "%s: level 1's fine - coarse ratios", ratio_name[q]);
        sf_result_sample(r, what, m1, n1 - m1);
        gap = sf_max(gap, fabs(p->ml.q[q].mean - mean));
        double se = sqrt(v0 / (double)m0 + v1 / (double)m1);
        segap = sf_max(segap, fabs(p->ml.q[q].se - se) / se);
    }
    free(d);
    free(b);
    free(x);
    free(xf);
    free(df);
    sf_check_le(r, "|estimate - (level 0's mean coarse ratio + level 1's mean fine - coarse)|, max over the ratios "
                   "(sums of <= 4 N terms of order 1: round-off ~1e-14)", gap, 1e-12);
    sf_check_le(r, "relative |se - sqrt(var0 / m0 + var1 / m1)| over the m_l finite values, max over the ratios", segap,
                1e-10);
}

/* Exact, at one point: (1) each ratio's estimate is level 0's mean of
 * coarse ratios plus level 1's mean of fine - coarse, recomputed here
 * from the values the point keeps; (2) level 1's fine values are plain
 * Monte Carlo's first n1, bit for bit; (3) the first coarse value of each
 * level is what this check's own coarse run gives: a plan made from the
 * scene with the coarse settings as keys (half the rings, rtol 1e-5) on
 * the field of the level's stream (level 1: the plain stream 0; level 0:
 * the stream sf_mc_seed(seed, SF_MLMC_LEVEL0_STREAM)). */
static int chk_mlmc_levels(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    char err[256] = "";
    sf_sweep_point p, pl;
    int rc = est_and_plain(s, EST_MLMC, &p, &pl, r);
    if (rc)
        return rc;
    ml_recompute(&p, r);
    sf_check_le(r, "level 1's fine values that differ from plain Monte Carlo's first n1 (bits)", rows_differ(&p, &pl), 0);
    /* the coarse runs, made here from the scene */
    sf_plan fp, cp;
    sf_scene sc = *s;
    rc = sf_plan_make(s, &fp, err, sizeof err);
    if (!rc) {
        if (!fp.num.cell_average)
            sc.cells = fp.num.cells / 2 + fp.num.cells % 2 < 2 ? 2 : fp.num.cells / 2 + fp.num.cells % 2;
        sc.rtol = 1e-5;
        rc = sf_plan_make(&sc, &cp, err, sizeof err);
    }
    size_t differ = 0, none = 0;
    for (int lev = 0; lev < 2 && !rc; lev++) {
        sf_cof_plan *plan;
        sf_cof *cof;
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(rng, lev ? sf_mc_seed(s->seed, 0) : sf_mc_seed(sf_mc_seed(s->seed, SF_MLMC_LEVEL0_STREAM), 0));
        double out[SF_SWEEP_NQ];
        rc = sf_cof_plan_alloc(s, &plan, err, sizeof err);
        if (!rc && !(rc = sf_cof_plan_draw(plan, rng, &cof))) {
            rc = sf_sweep_solve(&sc, &cp, cof, out, NULL);
            sf_cof_free(cof);
        }
        if (!rc)
            sf_cof_plan_free(plan);
        gsl_rng_free(rng);
        const double *got = lev ? p.ml.coarse1 : p.ml.coarse0;
        /* bit for bit; a QoI that neither run forms (NaN in both: no
         * cycle in the window) is the same outcome */
        for (int q = 0; q < 3 && !rc; q++) {
            int both_none = isnan(got[q]) && isnan(out[q]);
            none += both_none;
            differ += !both_none && memcmp(&got[q], &out[q], sizeof out[q]) != 0;
        }
    }
    if (rc) {
        sf_note(r, "The coarse run failed: %s\n", *err ? err : sf_strerror(rc));
    } else {
        sf_check_le(r, "first coarse values (both levels, 3 QoIs) that differ from this check's coarse run on its "
                       "field (bits; the same operations)", (double)differ, 0);
        if (none)
            sf_note(r, "%zu of the 6 first coarse QoIs are formed by neither run (NaN in both: no cycle in the window), "
                       "the same outcome.\n", none);
        sf_note(r, "l/R = %g, %zu realisations' variance as the target (seed %lu): level 0 %zu coarse "
                   "realisations, level 1 %zu pairs (coarse plan: %zu -> %zu %s, rtol %g -> %g).\n",
                s->l / s->R, s->samples, s->seed, p.ml.n[0], p.ml.n[1], fp.num.cells, sc.cells ? sc.cells : fp.num.cells,
                fp.num.layout ? "cells per diameter" : "rings", fp.num.rtol, sc.rtol);
    }
    sf_sweep_point_free(&p);
    sf_sweep_point_free(&pl);
    return rc;
}

/* The derived coarse COF g of grid COF f against its definition,
 * computed here from coordinates.  Box means (b > 1): coarse node (X, Y)
 * is the centre of a box of side B = b box; the fine boxes that tile it
 * have their centres at X - B/2 + box (u + 1/2), u < b (and so in y),
 * and g's value is the mean of the b^2 fine values there.  A subsample
 * (b = 1): the fine value at (X, Y) itself.  Each such point must be a
 * fine node (|index - integer| <= 1e-9: the grids align).  *worst: the
 * largest |difference| relative to the mean COF; *misaligned: the points
 * that are not fine nodes or lie off the fine grid. */
static void derived_by_definition(const sf_cof *f, const sf_cof *g, size_t b, double mu_mean, double *worst,
                                  size_t *misaligned)
{
    size_t m, n, M, N;
    double x0, y0, dx, dy, X0, Y0, DX, DY;
    const double *u, *v;
    *worst = INFINITY;
    *misaligned = 1;
    if (sf_cof_grid_view(f, &m, &n, &x0, &y0, &dx, &dy, &u) || sf_cof_grid_view(g, &M, &N, &X0, &Y0, &DX, &DY, &v))
        return;
    double box = sf_cof_box(f), w = 0, lo = b > 1 ? 0.5 * box * (1 - (double)b) : 0;
    size_t bad = 0;
    for (size_t J = 0; J < N; J++)
        for (size_t I = 0; I < M; I++) {
            double X = X0 + (double)I * DX, Y = Y0 + (double)J * DY, sum = 0;
            for (size_t a = 0; a < b; a++)
                for (size_t c = 0; c < b; c++) {
                    double fi = (X + lo + box * (double)c - x0) / dx, fj = (Y + lo + box * (double)a - y0) / dy;
                    long i = lround(fi), j = lround(fj);
                    if (fabs(fi - (double)i) > 1e-9 || fabs(fj - (double)j) > 1e-9 || i < 0 || j < 0 ||
                        i >= (long)m || j >= (long)n) {
                        bad++;
                        continue;
                    }
                    sum += u[(size_t)i + m * (size_t)j];
                }
            w = sf_max(w, fabs(v[I + M * J] - sum / (double)(b * b)) / mu_mean);
        }
    *worst = w;
    *misaligned = bad;
}

/* Exact, at one point of two levels on a derived coarse field
 * (sf_sweep_run_mlmc_boxes, est EST_BOXES; sf_sweep_run_mlmc_sub,
 * EST_SUB): (1)-(2) the estimate and its se from the level values
 * (ml_recompute); (3) the derived field of stream 0's fine field against
 * its definition (derived_by_definition) and
 * its grid against level 0's own-draw grid (the law's support); (4) level
 * 1's first fine and coarse values and level 0's first value (the mean
 * of an antithetic pair of coarse runs on the level-0 stream's draw)
 * against this check's own runs, bit for bit; every 2nd node: (5) level
 * 1's fine values are plain Monte Carlo's first n1, bit for bit. */
static int derived_levels(const sf_case *c, sf_result *r, int est)
{
    const sf_scene *s = &c->scene;
    char err[256] = "";
    sf_sweep_point p, pl;
    int sub = est == EST_SUB, rc;
    if (sub) {
        if ((rc = est_and_plain(s, est, &p, &pl, r)))
            return rc;
    } else if ((rc = est_run(s, est, s->samples, &p, err, sizeof err))) {
        sf_note(r, "The sweep failed: %s\n", *err ? err : sf_strerror(rc));
        sf_sweep_point_free(&p);
        return rc;
    }
    ml_recompute(&p, r);
    if (sub) {
        sf_check_le(r, "level 1's fine values that differ from plain Monte Carlo's first n1 (bits)", rows_differ(&p, &pl),
                    0);
        sf_sweep_point_free(&pl);
    }
    size_t kb = sub ? SF_MLMC_SUB : SF_MLMC_BOX;
    sf_plan fp, cp, dp;
    sf_cof_plan *fplan = NULL, *dplan = NULL;
    sf_cof *f = NULL, *g = NULL, *h = NULL, *ha = NULL;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double q1[SF_SWEEP_NQ], qc[SF_SWEEP_NQ], q0[SF_SWEEP_NQ], q0a[SF_SWEEP_NQ];
    rc = sub ? sf_mlmc_sub_plans(s, &fp, &cp, &dp, err, sizeof err) : sf_mlmc_box_plans(s, &fp, &cp, &dp, err, sizeof err);
    if (!rc)
        rc = sf_cof_plan_build(s, &fp, &fplan, err, sizeof err);
    if (!rc)
        rc = sf_cof_plan_build(s, &dp, &dplan, err, sizeof err);
    gsl_rng_set(rng, sf_mc_seed(s->seed, 0));
    if (!rc && !(rc = sf_cof_plan_draw(fplan, rng, &f)))
        rc = sub ? sf_cof_subsample(f, kb, &g) : sf_cof_box_means(f, kb, &g);
    gsl_rng_set(rng, sf_mc_seed(sf_mc_seed(s->seed, SF_MLMC_LEVEL0_STREAM), 0));
    if (!rc && !(rc = sf_cof_plan_draw(dplan, rng, &h)))
        rc = sf_cof_plan_antithetic(dplan, h, &ha);
    if (!rc)
        rc = sf_sweep_solve(s, &fp, f, q1, NULL);
    if (!rc)
        rc = sf_sweep_solve(s, &cp, g, qc, NULL);
    if (!rc)
        rc = sf_sweep_solve(s, &cp, h, q0, NULL);
    if (!rc)
        rc = sf_sweep_solve(s, &cp, ha, q0a, NULL);
    if (rc) {
        sf_note(r, "The check's own runs failed: %s\n", *err ? err : sf_strerror(rc));
    } else {
        double worst;
        size_t bad;
        if (sub) {
            derived_by_definition(f, g, 1, s->mu_mean, &worst, &bad);
            sf_check_le(r, "max over the coarse nodes of |value - the fine value at its position| / mu_mean (copies: "
                           "exact)", worst, 0);
            sf_check_le(r, "coarse nodes that are not fine nodes, or lie off the fine strip", (double)bad, 0);
        } else {
            derived_by_definition(f, g, kb, s->mu_mean, &worst, &bad);
            sf_check_le(r, "max over the coarse nodes of |box mean - the mean of the b x b fine boxes that tile its "
                           "box| / mu_mean (sums of 16 values of order 1: round-off ~1e-15)", worst, 1e-12);
            sf_check_le(r, "fine box centres of a coarse box that are not fine nodes, or lie off the fine strip",
                        (double)bad, 0);
        }
        size_t M, N;
        double X0, Y0, DX;
        const sf_cof_plan_info *in = sf_cof_plan_get_info(dplan);
        sf_cof_grid_view(g, &M, &N, &X0, &Y0, &DX, NULL, NULL);
        double geo = (M != in->nx || N != in->ny) ? INFINITY
                     : sf_max(sf_max(fabs(X0 - in->x0), fabs(Y0 - in->y0)) / in->dx,
                              sf_max(fabs(DX - in->dx) / in->dx,
                                     sub ? fabs(sf_cof_box(g) - in->box) : fabs(sf_cof_box(g) - in->box) / in->box));
        sf_check_le(r, "the derived field's grid against level 0's own-draw grid (nodes, origin / spacing, spacing, box; "
                       "relative: round-off ~1e-15)", geo, 1e-12);
        if (sf_cof_plan_truncated(dplan) || sf_cof_plan_truncated(fplan))
            sf_note(r, "An embedding reached its padding cap (truncated): the two levels' laws differ by its "
                       "clamping.\n");
        size_t differ = 0, none = 0;
        for (int q = 0; q < 3; q++) {
            double want[3] = { q1[q], qc[q], 0.5 * (q0[q] + q0a[q]) };
            double got[3] = { p.qoi[q], p.ml.coarse1[q], p.ml.coarse0[q] };
            for (int k = 0; k < 3; k++) {
                int both_none = isnan(got[k]) && isnan(want[k]);
                none += both_none;
                differ += !both_none && memcmp(&got[k], &want[k], sizeof want[k]) != 0;
            }
        }
        sf_check_le(r, "level 1's first fine and coarse values and level 0's first pair mean (3 QoIs each) that differ "
                       "from this check's runs on the fields of their streams (bits; the same operations)",
                    (double)differ, 0);
        if (none)
            sf_note(r, "%zu of the 9 first values are formed by neither run (NaN in both), the same outcome.\n", none);
        sf_note(r, "l/R = %g, %zu realisations' variance as the target (seed %lu): level 0 %zu antithetic pairs of "
                   "coarse runs, level 1 %zu pairs; fine plan %zu %s (spacing %.4g m), coarse %zu (spacing %.4g m), "
                   "rtol %g -> %g; the derived field compared at %zu x %zu nodes.\n",
                s->l / s->R, s->samples, s->seed, p.ml.n[0], p.ml.n[1], fp.num.cells,
                fp.num.layout ? "cells per diameter" : "rings", fp.cof.dx, cp.num.cells, dp.cof.dx, fp.num.rtol,
                cp.num.rtol, M, N);
    }
    gsl_rng_free(rng);
    sf_cof_free(f);
    sf_cof_free(g);
    sf_cof_free(h);
    sf_cof_free(ha);
    sf_cof_plan_free(fplan);
    sf_cof_plan_free(dplan);
    sf_sweep_point_free(&p);
    return rc;
}

static int chk_mlmc_boxes(const sf_case *c, sf_result *r) { return derived_levels(c, r, EST_BOXES); }
static int chk_mlmc_sub(const sf_case *c, sf_result *r) { return derived_levels(c, r, EST_SUB); }

/* ---- antithetic pairs (sweep.h: sf_sweep_run_antithetic, antithetic.h) ---- */

/* The largest departure of COF a (drawn by plan pl of scene s) and its
 * antithetic b from the law's identity at every node they hold: the
 * lognormal point values ln a + ln b = 2 mu_g (a = exp(mu_g + sigma_g G),
 * b = exp(mu_g - sigma_g G)); cell averages a + b = 2 mu_mean (mubar -+
 * sd G).  A tiled window is compared at windows along the run's belt
 * (xb = -v_b t, t = 0 .. T), each made by both COFs afresh from their key. */
static double anti_identity(const sf_scene *s, const sf_cof *a, const sf_cof *b, size_t *nodes)
{
    sf_lognormal ln;
    sf_lognormal_init(&ln, s->mu_mean, s->mu_std);
    double worst = 0, span = s->v_b * s->T;
    int steps = sf_cof_window_margin(a) > 0 ? 8 : 1;
    *nodes = 0;
    for (int k = 0; k < steps; k++) {
        double xb = -span * (double)k / (double)(steps > 1 ? steps - 1 : 1);
        if (steps > 1 && (sf_cof_follow(a, xb - s->R, xb + s->R) || sf_cof_follow(b, xb - s->R, xb + s->R)))
            return INFINITY;
        size_t m, n, m2, n2;
        double xa, xb2, dx;
        const double *u, *v;
        if (sf_cof_grid_view(a, &m, &n, &xa, NULL, &dx, NULL, &u) ||
            sf_cof_grid_view(b, &m2, &n2, &xb2, NULL, NULL, NULL, &v) || n != n2)
            return INFINITY;
        /* the windows may stand at other lattice columns: compare the columns both hold */
        long off = lround((xa - xb2) / dx);   /* a's column i is b's column i + off */
        for (size_t j = 0; j < n; j++)
            for (size_t i = 0; i < m; i++) {
                long ib = (long)i + off;
                if (ib < 0 || ib >= (long)m2)
                    continue;
                double x = u[i + m * j], y = v[(size_t)ib + m2 * j];
                double d = sf_cof_box(a) > 0 ? x + y - 2 * s->mu_mean : log(x) + log(y) - 2 * ln.mu_g;
                worst = isfinite(d) ? sf_max(worst, fabs(d)) : INFINITY;
                (*nodes)++;
            }
    }
    return worst;
}

/* Exact, at one point: (1) each ratio's estimate is the mean of the pair
 * means, and its se their std / sqrt(m), recomputed here from the
 * members the point keeps; (2) the pairs' G members are plain Monte
 * Carlo's first n, bit for bit; (3) the antithetic field of stream 0's
 * draw obeys the law's identity at every node (anti_identity); (4) the
 * first antithetic member is what this check's own run on that field
 * gives, bit for bit. */
static int chk_anti_pairs(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    char err[256] = "";
    sf_sweep_point p, pl;
    int rc = est_and_plain(s, EST_ANTI, &p, &pl, r);
    if (rc)
        return rc;
    size_t n = p.anti.n;
    double gap = 0, segap = 0;
    double *h = check_alloc(n * sizeof *h), *xa = check_alloc(n * sizeof *xa), *xb = check_alloc(n * sizeof *xb);
    sf_plot *plt = sf_result_plot(r, "pairs", "Antithetic pairs: the ratio on -G against the ratio on G",
                                  "ratio on G [-]", "ratio on -G [-]");
    for (int q = 0; q < 3; q++) {
        size_t m = 0;
        for (size_t i = 0; i < n; i++) {
            double a = p.qoi[i * SF_SWEEP_NQ + q] / p.det[q], b = p.anti.qoi_anti[i * SF_SWEEP_NQ + q] / p.det[q];
            h[i] = isfinite(a) && isfinite(b) ? 0.5 * (a + b) : NAN;
            if (isfinite(h[i])) {
                xa[m] = a;
                xb[m++] = b;
            }
        }
        sf_plot_series(plt, ratio_name[q], SF_STYLE_POINTS, m, xa, xb);
        size_t k;
        double v, mean = finite_mean(h, n, &k, &v);
        char what[SF_LABEL_LEN];
        snprintf(what, sizeof what, "%s: pairs with both members finite", ratio_name[q]);
        sf_result_sample(r, what, k, n - k);
        gap = sf_max(gap, fabs(p.anti.q[q].mean - mean));
        segap = sf_max(segap, fabs(p.anti.q[q].se - sqrt(v / (double)k)) / sqrt(v / (double)k));
    }
    free(h);
    free(xa);
    free(xb);
    sf_check_le(r, "|estimate - mean of the pair means (Q(G) + Q(-G)) / 2|, max over the ratios (means of <= N "
                   "terms of order 1: round-off ~1e-15)", gap, 1e-12);
    sf_check_le(r, "relative |se - std of the pair means / sqrt(m)| over the m pairs with both members finite, max "
                   "over the ratios", segap, 1e-10);
    sf_check_le(r, "the pairs' G members that differ from plain Monte Carlo's first n (bits)", rows_differ(&p, &pl), 0);
    /* the antithetic of stream 0's field, made here */
    sf_plan fp;
    sf_cof_plan *plan = NULL;
    sf_cof *cof = NULL, *anti = NULL;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, sf_mc_seed(s->seed, 0));
    double out[SF_SWEEP_NQ], ident = INFINITY;
    size_t nodes = 0;
    rc = sf_plan_make(s, &fp, err, sizeof err);
    fp.history = 0;
    if (!rc)
        rc = sf_cof_plan_build(s, &fp, &plan, err, sizeof err);
    if (!rc)
        rc = sf_cof_plan_draw(plan, rng, &cof);
    if (!rc)
        rc = sf_cof_plan_antithetic(plan, cof, &anti);
    if (!rc)
        rc = sf_sweep_solve(s, &fp, anti, out, NULL);
    if (!rc)
        ident = anti_identity(s, cof, anti, &nodes);
    if (rc) {
        sf_note(r, "The antithetic run failed: %s\n", *err ? err : sf_strerror(rc));
    } else {
        int box = sf_cof_box(cof) > 0;
        sf_check_le(r, box ? "max over the nodes of |a + b - 2 mu_mean|, a the cell averages of G, b of -G (values "
                             "of order 0.1: round-off ~1e-16)"
                           : "max over the nodes of |ln a + ln b - 2 mu_g|, a the COF of G, b of -G (logs of "
                             "order 1: round-off ~1e-15)",
                    ident, 1e-12);
        size_t differ = 0, none = 0;
        for (int q = 0; q < 3; q++) {
            int both_none = isnan(p.anti.qoi_anti[q]) && isnan(out[q]);
            none += both_none;
            differ += !both_none && memcmp(&p.anti.qoi_anti[q], &out[q], sizeof out[q]) != 0;
        }
        sf_check_le(r, "first antithetic member's QoIs that differ from this check's run on stream 0's antithetic "
                       "field (bits; the same operations)", (double)differ, 0);
        if (none)
            sf_note(r, "%zu of the first antithetic member's 3 QoIs are formed by neither run (NaN in both: no cycle "
                       "in the window), the same outcome.\n", none);
        sf_note(r, "l/R = %g, %s, plain Monte Carlo's variance at %zu realisations as the target (seed %lu): %zu "
                   "pairs; the identity compared at %zu nodes. rho = corr(Q(G), Q(-G)): %.3f (PV_x), %.3f (PV_F), "
                   "%.3f (stick fraction).\n",
                s->l / s->R, box ? "cell averages" : sf_cof_window_margin(cof) > 0 ? "tiles" : "circulant strip",
                s->samples, s->seed, n, nodes, p.anti.q[0].rho, p.anti.q[1].rho, p.anti.q[2].rho);
    }
    gsl_rng_free(rng);
    sf_cof_free(cof);
    sf_cof_free(anti);
    sf_cof_plan_free(plan);
    sf_sweep_point_free(&p);
    sf_sweep_point_free(&pl);
    return rc;
}

/* Statistical, per sweep point: an estimator's ratio means (two levels,
 * or antithetic pairs) against plain Monte Carlo's on the same streams
 * (common random numbers): plain's realisation i is stream
 * sf_mc_seed(seed, i), which is antithetic pair i's G member and two
 * levels' level-1 fine run i (bit for bit, or, for mlmc-boxes' own fine
 * plan, the same field on a grid of one more cell per diameter).  Plain
 * runs N >= the estimator's shared count, so every shared unit is in
 * both.  The difference D = estimate - plain mean has Var D = se_est^2 +
 * se_plain^2 - 2 Cov, Cov = (shared / (m N)) cov(u_i, Q_i), u_i the
 * estimator's shared unit (a pair's mean ratio; level 1's fine - coarse)
 * and Q_i plain's ratio on its stream, the sample covariance over the
 * shared units; level 0 draws on streams of its own
 * (SF_MLMC_LEVEL0_STREAM) and is independent of plain.  Student's t =
 * D / sqrt(Var D) at the Satterthwaite degrees of freedom of its two
 * parts, two-sided at alpha / (3 K); the row names the minimum
 * detectable effect at power 0.99 (relative to plain's mean).  Each
 * estimator's sizes and work, and the variance reduction factor,
 * reported. */
/* Point k of case c's sweep: the scene s and plain Monte Carlo's scene
 * sp on independent streams (seed sf_mc_seed(seed, 1) xor 1). */
static int point_scenes(const sf_case *c, size_t k, sf_scene *s, sf_scene *sp, char *err, size_t errlen)
{
    *s = c->scene;
    int rc = sf_sweep_set(s, c->spec.sweep_param, c->spec.sweep.v[k], err, errlen);
    *sp = *s;
    sp->seed = sf_mc_seed(s->seed, 1) ^ 1;
    return rc;
}

/* Welch's t of an estimator's ratio mean (its se, df) against plain's
 * (pl), two-sided, at alpha: one row. */
static void welch_row(sf_result *r, double lr, int q, const char *name, double mean, double se, double df,
                      const sf_sweep_stat *pl, double alpha)
{
    double pdf = (double)pl->n_used - 1, a = se * se, b = pl->se * pl->se;
    double den = (a > 0 ? a * a / df : 0) + (b > 0 ? b * b / pdf : 0);
    double t = (mean - pl->mean) / sqrt(a + b), nu = den > 0 ? (a + b) * (a + b) / den : NAN;
    char what[SF_LABEL_LEN];
    snprintf(what, sizeof what, "l/R = %g: %s ratio mean, %s %.5f = plain %.5f (Welch t test, %.0f df)", lr,
             ratio_name[q], name, mean, pl->mean, nu);
    sf_check_pvalue(r, what, 2 * gsl_cdf_tdist_Q(fabs(t), nu), alpha, pl->n_used);
}

/* The minimum detectable effect of a two-sided t test at level alpha,
 * power 0.99, nu degrees of freedom, standard error se. */
static double mde99(double se, double nu, double alpha)
{
    if (!(nu > 0) || !isfinite(se))
        return NAN;
    return (gsl_cdf_tdist_Pinv(1 - alpha / 2, nu) + gsl_cdf_tdist_Pinv(0.99, nu)) * se;
}

/* The sample covariance of u_i and plain's ratios Q_i over the shared
 * units i < n whose both are finite (their count in *m). */
static double shared_cov(const double *u, const double *Q, size_t n, size_t *m)
{
    double su = 0, sq = 0, c = 0;
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(u[i]) && isfinite(Q[i])) {
            su += u[i];
            sq += Q[i];
            k++;
        }
    *m = k;
    if (k < 2)
        return 0;
    su /= (double)k;
    sq /= (double)k;
    for (size_t i = 0; i < n; i++)
        if (isfinite(u[i]) && isfinite(Q[i]))
            c += (u[i] - su) * (Q[i] - sq);
    return c / (double)(k - 1);
}

/* The paired row: D = mean - plain's on shared streams, Var D = se^2 +
 * plain's se^2 - 2 cov_ap (cov_ap = Cov(estimate, plain mean)); Student's
 * t at the Satterthwaite df of se^2 (df) and the rest (plain's n - 1).
 * The MDE at power 0.99, relative to plain's mean, in *mde. */
static void paired_row(sf_result *r, double lr, int q, const char *name, double mean, double se, double df,
                       const sf_sweep_stat *pl, double cov_ap, double alpha, double *mde)
{
    double a = se * se, b = pl->se * pl->se - 2 * cov_ap, v = a + b;
    if (!(v > 0))
        v = a;
    double bb = b > 0 ? b : 0, pdf = (double)pl->n_used - 1;
    double den = (a > 0 ? a * a / df : 0) + (bb > 0 ? bb * bb / pdf : 0);
    double nu = den > 0 ? v * v / den : NAN;
    double t = (mean - pl->mean) / sqrt(v);
    *mde = mde99(sqrt(v), nu, alpha) / fabs(pl->mean);
    char what[SF_LABEL_LEN];
    snprintf(what, sizeof what, "l/R = %g: %s ratio mean, %s %.5f - plain %.5f on shared streams = 0 (paired t, "
             "%.0f df; MDE %.2f%% at power 0.99)", lr, ratio_name[q], name, mean, pl->mean, nu, 100 * *mde);
    sf_check_pvalue(r, what, 2 * gsl_cdf_tdist_Q(fabs(t), nu), alpha, pl->n_used);
}

/* Antithetic pairs against plain Monte Carlo on the same streams, a
 * pair at a time: pair i's G member is plain's realisation i (bit for
 * bit), so estimate - plain mean over the m pairs is the mean of D_i =
 * (Q(-G_i) - Q(G_i)) / 2, zero in expectation exactly when the -G member
 * has G's law.  At rho near -1, D_i ~ -(Q(G_i) - E Q) carries Q's whole
 * spread; the companion C_i of G_i (sweep.h: sf_sweep_run_cv; its mean
 * is mu_mean exactly, and G_i is plain's field, untouched by the
 * antithetic map) all but fixes Q(G_i) at large l/R, so D_i is regressed
 * on C_i - mu_mean and the intercept tested: Student's t at m - 2 df
 * (without companions, a window of tiles: the mean of D_i at m - 1).  The
 * MDE at power 0.99, relative to plain's mean, in *mde. */
static void anti_pair_row(sf_result *r, double lr, int q, const sf_sweep_point *e, const sf_sweep_point *p,
                          double mu_mean, double alpha, double *mde)
{
    size_t n = e->anti.n < p->n ? e->anti.n : p->n, m = 0, mc = 0;
    double *d = check_alloc((n ? n : 1) * sizeof *d), *x = check_alloc((n ? n : 1) * sizeof *x);
    for (size_t i = 0; i < n; i++) {
        double a = e->ratio[i * SF_SWEEP_NQ + q], b = e->anti.qoi_anti[i * SF_SWEEP_NQ + q] / e->det[q];
        if (!isfinite(a) || !isfinite(b))
            continue;
        double cc = p->companion ? p->companion[i] : NAN;
        d[m] = 0.5 * (b - a);
        x[m] = cc - mu_mean;
        mc += isfinite(cc);
        m++;
    }
    double est = NAN, se = NAN, nu = NAN, beta = 0;
    if (mc == m && m > 3) {
        double c0, c1, v00, v01, v11, ss;
        gsl_fit_linear(x, 1, d, 1, m, &c0, &c1, &v00, &v01, &v11, &ss);
        est = c0;
        se = sqrt(v00);
        nu = (double)m - 2;
        beta = c1;
    } else if (m > 1) {
        est = gsl_stats_mean(d, 1, m);
        se = sqrt(gsl_stats_variance_m(d, 1, m, est) / (double)m);
        nu = (double)m - 1;
    }
    free(d);
    free(x);
    double t = est / se, pm = p->rstat[q].mean;
    *mde = mde99(se, nu, alpha) / fabs(pm);
    char what[SF_LABEL_LEN];
    snprintf(what, sizeof what, "l/R = %g: %s ratio mean, antithetic - plain on shared streams: (Q(-G) - Q(G)) / 2 "
             "%s = %.5f = 0 (paired t, %.0f df; MDE %.2f%% at power 0.99)", lr, ratio_name[q],
             mc == m ? "at C = mu_mean" : "per pair", est, nu, 100 * *mde);
    sf_check_pvalue(r, what, 2 * gsl_cdf_tdist_Q(fabs(t), nu), alpha, m);
    (void)beta;
}

static int estimator_unbiased(const sf_case *c, sf_result *r, int est)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param)
        return SF_EINVAL;
    double *lr = check_alloc(K * sizeof *lr), *vrf = check_alloc(K * 3 * sizeof *vrf);
    double *mde = check_alloc(K * 3 * sizeof *mde);
    char tab[6000], mtab[2000];
    size_t mused = 0;
    size_t used = 0;
    int rc = SF_SUCCESS;
    double alpha = c->spec.alpha / (double)(3 * K);
    int ml = est != EST_ANTI;
    const char *name = est == EST_MLMC    ? "two levels"
                       : est == EST_BOXES ? "boxes of boxes"
                       : est == EST_SUB   ? "every 2nd node"
                                          : "antithetic";
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene s, sp;
        sf_sweep_point e = { 0 }, p = { 0 };
        char err[256] = "";
        rc = point_scenes(c, k, &s, &sp, err, sizeof err);
        sp.seed = s.seed;   /* common random numbers: plain's realisation i is the estimator's shared unit i */
        /* antithetic: pairs to their cap, samples (a target no pilot meets), so every plain realisation is a
           pair's G member; plain with the companions of its fields */
        const double tiny[SF_SWEEP_NQ] = { 1e-100, 1e-100, 1e-100 };   /* squared: 1e-200 */
        if (!rc)
            rc = ml ? est_run(&s, est, s0->samples, &e, err, sizeof err)
                    : sf_anti_run(&s, s0->samples, ML_PILOT, tiny, 0, NULL, &e, err, sizeof err);
        size_t shared = ml ? e.ml.n[1] : e.anti.n, np = shared > s0->samples ? shared : s0->samples;
        if (!rc)
            rc = ml ? sf_sweep_run(&sp, np, 0, NULL, 0, NULL, &p, err, sizeof err)
                    : sf_sweep_run_cv(&sp, np, 0, NULL, 0, NULL, &p, err, sizeof err);
        if (rc) {
            sf_note(r, "**Sweep failed at %s = %g:** %s\n", c->spec.sweep_param, c->spec.sweep.v[k], err);
            sf_sweep_point_free(&e);
            sf_sweep_point_free(&p);
            break;
        }
        lr[k] = s.l / s.R;
        for (int q = 0; q < 3; q++) {
            const sf_sweep_ml *e_ml = &e.ml.q[q];
            const sf_sweep_anti *an = &e.anti.q[q];
            double mean = ml ? e_ml->mean : an->mean, se = ml ? e_ml->se : an->se;
            double df = ml ? e_ml->df : (double)an->m - 1, pse = p.rstat[q].se;
            /* the shared units u_i against plain's ratios on their streams */
            double *u = check_alloc((shared ? shared : 1) * sizeof *u), *Q = check_alloc((shared ? shared : 1) * sizeof *Q);
            for (size_t i = 0; i < shared; i++) {
                double f = e.ratio[i * SF_SWEEP_NQ + q];
                u[i] = ml ? f - e.ml.coarse1[i * SF_SWEEP_NQ + q] / e.det[q]
                          : 0.5 * (f + e.anti.qoi_anti[i * SF_SWEEP_NQ + q] / e.det[q]);
                Q[i] = p.ratio[i * SF_SWEEP_NQ + q];
            }
            size_t msh;
            double cv = shared_cov(u, Q, shared, &msh), mu = ml ? (double)e_ml->m[1] : (double)an->m;
            double cov_ap = msh > 1 ? (double)msh * cv / (mu * (double)p.rstat[q].n_used) : 0;
            free(u);
            free(Q);
            if (ml)
                paired_row(r, lr[k], q, name, mean, se, df, &p.rstat[q], cov_ap, alpha, &mde[k * 3 + q]);
            else
                anti_pair_row(r, lr[k], q, &e, &p, s0->mu_mean, alpha, &mde[k * 3 + q]);
            {   /* the independent-streams design's MDE at these sizes, for comparison */
                double a = se * se, b = pse * pse, pdf = (double)p.rstat[q].n_used - 1;
                double den = (a > 0 ? a * a / df : 0) + (b > 0 ? b * b / pdf : 0);
                double mi = mde99(sqrt(a + b), den > 0 ? (a + b) * (a + b) / den : NAN, alpha) / fabs(p.rstat[q].mean);
                mused += (size_t)snprintf(mtab + mused, sizeof mtab - mused, "| %g | %s | %.2f%% | %.2f%% |\n", lr[k],
                                          ratio_name[q], 100 * mde[k * 3 + q], 100 * mi);
            }
            vrf[k * 3 + q] = ml ? e_ml->vrf : an->vrf;
            if (ml)
                used += (size_t)snprintf(tab + used, sizeof tab - used,
                                         "| %g | %s | %.5f +- %.5f | %.5f +- %.5f | %zu / %zu | %.3g / %.3g | %.3g / "
                                         "%.3g | %.3g |\n", lr[k], ratio_name[q], p.rstat[q].mean, pse, mean, se,
                                         e.ml.n[0], e.ml.n[1], e_ml->var[0], e_ml->var[1], e.ml.cost[0],
                                         e.ml.cost[1], e_ml->vrf);
            else
                used += (size_t)snprintf(tab + used, sizeof tab - used,
                                         "| %g | %s | %.5f +- %.5f | %.5f +- %.5f | %zu | %.3f | %.3g / %.3g | %.3g "
                                         "|\n", lr[k], ratio_name[q], p.rstat[q].mean, pse, mean, se, e.anti.n,
                                         an->rho, e.anti.cost, e.anti.cost_fine, an->vrf);
        }
        sf_sweep_point_free(&e);
        sf_sweep_point_free(&p);
    }
    if (!rc && ml) {
        sf_note(r, "Plain Monte Carlo: %zu realisations per point on the estimator's streams (level 1's fine runs are "
                   "its first n1; the rows pair them: paired t); %s: plain's "
                   "variance at %zu as the target, a pilot of %d pairs (seed %lu). Ratio means (+- standard error), "
                   "each level's N (n0 %s / n1 pairs), variance (V0 of %s, V1 of fine - coarse), "
                   "work per sample [cell evaluations] and the variance reduction factor at equal work:\n\n"
                   "| l/R | QoI | plain | %s | n0 / n1 | V0 / V1 | C0 / C1 | reduction |\n"
                   "|---|---|---|---|---|---|---|---|\n%s\n",
                s0->samples, name, s0->samples, ML_PILOT, s0->seed,
                est != EST_MLMC ? "antithetic pairs of coarse runs" : "coarse realisations",
                est != EST_MLMC ? "a pair's mean coarse ratio" : "the coarse ratio", name, tab);
        plot_vrf(r, est == EST_BOXES ? "Variance reduction of two levels on boxes of boxes at equal work"
                    : est == EST_SUB ? "Variance reduction of two levels on every 2nd node at equal work"
                                     : "Variance reduction of the two-level estimator at equal work", K, lr, vrf);
    } else if (!rc) {
        sf_note(r, "Plain Monte Carlo: %zu realisations per point on the estimator's streams (pair i's G member is its "
                   "realisation i; the rows pair them: paired t); antithetic pairs: plain's "
                   "variance at %zu as the target, a pilot of %d pairs (seed %lu). Ratio means (+- standard error), "
                   "the pairs, rho = corr(Q(G), Q(-G)), the work of a pair and of a plain realisation [cell "
                   "evaluations] and the variance reduction factor at equal work:\n\n"
                   "| l/R | QoI | plain | antithetic | pairs | rho | work: pair / plain | reduction |\n"
                   "|---|---|---|---|---|---|---|---|\n%s\n",
                s0->samples, s0->samples, ML_PILOT, s0->seed, tab);
        plot_vrf(r, "Variance reduction of antithetic pairs at equal work", K, lr, vrf);
    }
    if (!rc)
        sf_note(r, "Minimum detectable effect (power 0.99, two-sided at alpha / %zu = %.3g, relative to plain's "
                   "mean) of each row: the paired design, and the independent-streams design (Welch) at the same "
                   "sizes, for comparison:\n\n| l/R | QoI | paired | independent |\n|---|---|---|---|\n%s\n",
                3 * K, alpha, mtab);
    free(lr);
    free(vrf);
    free(mde);
    return rc;
}

/* The estimators at a target standard error (sweep.h:
 * sf_sweep_run_estimator_se), per point with `--estimator auto`'s
 * choice: plain Monte Carlo's standard errors at s->samples realisations
 * on independent streams are the targets, the cap 4 x samples.  (1) The
 * point stopped at its targets, not its cap; (2) exact: each ratio's
 * standard error is within its target (the sizes' rule bounds sum V_l /
 * m_l by the target once every level holds what the final variances ask
 * for: a property of the values, to round-off); (3) Welch's t of the
 * estimate against plain's mean, alpha over the 3 K tests. */
static int chk_estimator_target(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param)
        return SF_EINVAL;
    double alpha = c->spec.alpha / (double)(3 * K);
    double *lrs = check_alloc(K * sizeof *lrs), *ratio = check_alloc(3 * K * sizeof *ratio);
    char tab[4000];
    size_t used = 0;
    int rc = SF_SUCCESS;
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene s, sp;
        sf_sweep_point e = { 0 }, p = { 0 };
        char err[256] = "";
        rc = point_scenes(c, k, &s, &sp, err, sizeof err);
        int est = rc ? -1 : sf_sweep_estimator_auto(&s);
        if (!rc)
            rc = sf_sweep_run(&sp, s0->samples, 0, NULL, 0, NULL, &p, err, sizeof err);
        double tse[SF_SWEEP_NQ];
        for (int q = 0; q < SF_SWEEP_NQ && !rc; q++)
            tse[q] = p.rstat[q].se;
        if (!rc)
            rc = sf_sweep_run_estimator_se(&s, est, tse, ML_PILOT, 4 * s0->samples, 0, NULL, &e, err, sizeof err);
        if (rc) {
            sf_note(r, "**Sweep failed at %s = %g:** %s\n", c->spec.sweep_param, c->spec.sweep.v[k], err);
            sf_sweep_point_free(&e);
            sf_sweep_point_free(&p);
            break;
        }
        double lr = lrs[k] = s.l / s.R;
        const char *name = sf_sweep_estimator_name(est);
        char what[SF_LABEL_LEN], found[120];
        snprintf(what, sizeof what, "l/R = %g (%s): stopped at its targets, not its cap", lr, name);
        snprintf(found, sizeof found, "stop = %s", sf_mcstop_reason(e.stop));
        sf_check_true(r, what, e.stop == SF_MCSTOP_TARGET, found);
        int anti = est == SF_EST_ANTITHETIC;
        for (int q = 0; q < 3; q++) {
            const sf_sweep_ml *m = &e.ml.q[q];
            const sf_sweep_anti *an = &e.anti.q[q];
            double mean = anti ? an->mean : m->mean, se = anti ? an->se : m->se;
            double df = anti ? (double)an->m - 1 : m->df, pse = p.rstat[q].se;
            snprintf(what, sizeof what, "l/R = %g: %s ratio, the estimate's se / its target (plain's se) - 1",
                     lr, ratio_name[q]);
            sf_check_le(r, what, se / tse[q] - 1, 1e-12);
            ratio[q * K + k] = se / tse[q];
            welch_row(r, lr, q, name, mean, se, df, &p.rstat[q], alpha);
            used += (size_t)snprintf(tab + used, sizeof tab - used, "| %g | %s | %s | %.5f +- %.5f | %.5f +- %.5f | "
                                     "%zu / %zu |\n", lr, name, ratio_name[q], p.rstat[q].mean, pse, mean, se,
                                     anti ? e.anti.n : e.ml.n[0], anti ? e.anti.n : e.ml.n[1]);
        }
        sf_sweep_point_free(&e);
        sf_sweep_point_free(&p);
    }
    if (!rc)
        sf_note(r, "Plain Monte Carlo: %zu realisations per point on independent streams, its standard errors the "
                   "estimator's targets (a pilot of %d, the cap %zu; seed %lu). Ratio means (+- standard error) and "
                   "the sizes (two levels: n0 / n1; antithetic: pairs):\n\n"
                   "| l/R | estimator | QoI | plain | estimator | sizes |\n|---|---|---|---|---|---|\n%s\n",
                s0->samples, ML_PILOT, 4 * s0->samples, s0->seed, tab);
    if (!rc) {
        sf_plot *pl = sf_result_plot(r, "se", "Estimators at plain Monte Carlo's standard errors", "l/R [-]",
                                     "standard error / its target [-]");
        sf_plot_log(pl, 1, 0);
        for (int q = 0; q < 3; q++)
            sf_plot_series(pl, ratio_name[q], SF_STYLE_LINESPOINTS, K, lrs, ratio + q * K);
        sf_plot_hline(pl, "target", 1);
    }
    free(lrs);
    free(ratio);
    return rc;
}

static int chk_mlmc_unbiased(const sf_case *c, sf_result *r) { return estimator_unbiased(c, r, EST_MLMC); }
static int chk_anti_unbiased(const sf_case *c, sf_result *r) { return estimator_unbiased(c, r, EST_ANTI); }
static int chk_boxes_unbiased(const sf_case *c, sf_result *r) { return estimator_unbiased(c, r, EST_BOXES); }
static int chk_sub_unbiased(const sf_case *c, sf_result *r) { return estimator_unbiased(c, r, EST_SUB); }

const sf_check_def sf_checks_estimators[] = {
    { "mc_mlmc_levels", chk_mlmc_levels,
      "two-level estimator: the estimate is its levels' means, level 1 is plain MC's streams, the coarse runs "
      "are the coarse plan's on the level's field" },
    { "mc_mlmc_unbiased", chk_mlmc_unbiased,
      "two-level estimator: its ratio means equal plain Monte Carlo's on independent streams; per-level N, V, C" },
    { "mc_mlmc_boxes", chk_mlmc_boxes,
      "two levels on boxes of boxes: the estimate is its levels' means, the coarse field is the b x b box means on "
      "level 0's own grid, the first values are the plans' runs on their streams' fields" },
    { "mc_mlmc_boxes_unbiased", chk_boxes_unbiased,
      "two levels on boxes of boxes: its ratio means equal plain Monte Carlo's on independent streams" },
    { "mc_mlmc_sub", chk_mlmc_sub,
      "two levels on every 2nd node: the estimate is its levels' means, level 1 is plain MC's streams, the coarse "
      "field is the fine one at every 2nd node on level 0's own grid, the first values are the plans' runs" },
    { "mc_mlmc_sub_unbiased", chk_sub_unbiased,
      "two levels on every 2nd node: its ratio means equal plain Monte Carlo's on independent streams" },
    { "mc_anti_pairs", chk_anti_pairs,
      "antithetic pairs: the estimate is the pair means' mean, the G members are plain MC's streams, the "
      "antithetic field obeys ln a + ln b = 2 mu_g (cell averages: a + b = 2 mu_mean)" },
    { "mc_anti_unbiased", chk_anti_unbiased,
      "antithetic pairs: its ratio means equal plain Monte Carlo's on independent streams; pairs, rho, reduction" },
    { "mc_estimator_target", chk_estimator_target,
      "estimators at a target standard error: they stop at it, their se is within it, their means equal plain "
      "Monte Carlo's on independent streams" },
    { "mc_cv_unbiased", chk_cv_unbiased,
      "control variate: the companion's mean is mu_mean, the estimator is the regression one, its reduction" },
    { NULL, NULL, NULL }
};
