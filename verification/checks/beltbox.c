/* The cell averages on belt noise (cof_model = cell_average with
 * cof_generator = belt_noise; cellavg.h, cof.c, docs/design.md sec. 4.4):
 * the window's box values against a direct average of the fine field,
 * their law against the closed form, and the QoIs against the point model
 * on the same noise. */
#include "checks.h"
#include "common.h"
#include "cellavg.h"
#include "cof.h"
#include "lognormal.h"
#include "montecarlo.h"
#include "noise.h"
#include "numplan.h"
#include "stats.h"
#include "sweep.h"
#include "tiles.h"
#include "sf_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>

/* The case's scene as a belt-noise scene, its COF plan (which must take
 * box averages), the noise cells' side h and the filter's weights (nw of
 * them, from the plan's box over h). */
typedef struct {
    sf_scene s;
    sf_plan pl;
    sf_cof_plan *cp;
    double h;
    double *w;
    size_t nw;
} box_setup;

static void setup_free(box_setup *b)
{
    sf_cof_plan_free(b->cp);
    free(b->w);
}

static int setup(const sf_case *c, sf_result *r, box_setup *b)
{
    memset(b, 0, sizeof *b);
    b->s = c->scene;
    b->s.cof = SF_COF_FIELD;
    b->s.cof_generator = SF_COFGEN_BELT_NOISE;
    char err[300] = "";
    int rc = sf_plan_make(&b->s, &b->pl, err, sizeof err);
    if (!rc && !(b->pl.cof.box > 0 && b->pl.cof.belt_noise && b->pl.cof.box_step >= 1)) {
        snprintf(err, sizeof err, "the plan takes no box averages on belt noise at l/R = %g", b->s.l / b->s.R);
        rc = SF_EINVAL;
    }
    if (!rc)
        rc = sf_cof_plan_alloc(&b->s, &b->cp, err, sizeof err);
    if (rc) {
        sf_note(r, "\n**Cannot plan the scene:** %s\n", err);
        return rc;
    }
    b->h = b->pl.cof.dx / (double)b->pl.cof.box_step;
    b->nw = sf_cellavg_cubic_weights(b->pl.cof.box / b->h, NULL, 0);
    b->w = check_alloc(b->nw * sizeof *b->w);
    sf_cellavg_cubic_weights(b->pl.cof.box / b->h, b->w, b->nw);
    return SF_SUCCESS;
}

/* ---- exactness */

static const double *noise_col(void *z, long i) { return sf_noise_column(z, i); }

/* The direct average at fine cell (ic, jc) of realisation key (sign -1:
 * of -G): the (2E+1)^2 fine Gaussian values made afresh (tiles on the
 * noise at the plan's level, rows and columns around the cell only), the
 * Nataf map, then sum_q sum_p w_p w_q mu(p, q) in one double loop (the
 * window filters along y, then along x).  *bound: the round-off bound of
 * the two sums' difference, 2 gamma_k sum |w_p w_q| mu, k = 2 (2E + 1). */
static int direct_box(const box_setup *b, uint64_t key, double sign, long ic, long jc, double *out, double *bound)
{
    size_t nw = b->nw, E = (nw - 1) / 2;
    sf_tiles_spec ts = { nw, b->h, b->h, b->s.l, 0, 0 };
    sf_tiles *t;
    sf_noise *z = NULL;
    int rc = sf_tiles_alloc(&ts, &t);
    size_t ky, nr = rc ? 0 : sf_tiles_noise_rows(t, &ky);
    if (!rc)
        rc = sf_noise_alloc(b->pl.cof.noise_level, jc - (long)E - (long)ky, nr, &z);
    double *g = check_alloc(nw * nw * sizeof *g);
    if (!rc) {
        sf_tiles_set_noise(t, noise_col, z);
        sf_tiles_set_key(t, key);
        sf_noise_set_key(z, key);
        rc = sf_tiles_fill(t, ic - (long)E, nw, g, nw);
    }
    if (!rc) {
        sf_lognormal ln;
        sf_lognormal_init(&ln, b->s.mu_mean, b->s.mu_std);
        double sum = 0, mag = 0;
        for (size_t q = 0; q < nw; q++)
            for (size_t p = 0; p < nw; p++) {
                double mu = sf_lognormal_map(&ln, sign * g[p + nw * q]), a = b->w[p] * b->w[q] * mu;
                sum += a;
                mag += fabs(a);
            }
        double k = 2.0 * (double)nw, gam = k * DBL_EPSILON / (1 - k * DBL_EPSILON);
        *out = sum;
        *bound = 2 * gam * mag;
    }
    free(g);
    sf_tiles_free(t);
    sf_noise_free(z);
    return rc;
}

#define EX_KEYS 6      /* windows (3 fields and their antithetic partners) */
#define EX_POS 4       /* window positions along the belt per window */
#define EX_NODES 12    /* nodes compared per position */

static int chk_exact(const sf_case *c, sf_result *r)
{
    box_setup b;
    int rc = setup(c, r, &b);
    if (rc)
        return rc;
    const sf_cof_plan_info *in = &b.pl.cof;
    double beta = in->box / b.h;
    /* the weights integrate the cubic interpolant: exact for cubics */
    double dm = 0;
    for (int k = 0; k <= 3; k++) {
        double m = 0, E = (double)((b.nw - 1) / 2);
        for (size_t i = 0; i < b.nw; i++)
            m += b.w[i] * pow((double)i - E, k);
        double exact = k == 0 ? 1 : k == 2 ? beta * beta / 12 : 0;
        dm = sf_max(dm, fabs(m - exact) / (k == 2 ? beta * beta / 12 : 1));
    }
    sf_note(r, "\nl/R = %g: noise level %d (cells h = %.4g m = l/%.3g), boxes of %.4g m = %.3f h (%zu cells per "
               "diameter), box centres every %zu cells, filter of %zu weights. Each node compared: the window's value "
               "(filters along y then x, blocks of columns as the window slides) against the direct double sum over "
               "the same (2E+1)^2 fine cells, made afresh from the noise around the node alone; %d windows (3 keys "
               "and their antithetic partners) at %d positions along the belt, %d random nodes each.\n",
            b.s.l / b.s.R, in->noise_level, b.h, b.s.l / b.h, in->box, beta, b.pl.num.cells, in->box_step, b.nw,
            EX_KEYS, EX_POS, EX_NODES);
    sf_check_le(r, "the filter's moments 0..3 against the box average of x^k (exact for the cubic interpolant): "
                   "largest relative error (round-off)", dm, 1e-13);
    gsl_rng *rng = sf_case_rng(c), *pts = sf_case_rng(c);
    gsl_rng_set(pts, c->scene.seed + 1);
    double worst = 0, align = 0, ratio[EX_KEYS * EX_POS * EX_NODES], idx[EX_KEYS * EX_POS * EX_NODES];
    size_t nodes = 0;
    sf_cof *prev = NULL;
    for (int k = 0; k < EX_KEYS && !rc; k++) {
        sf_cof *w;
        double sign = k % 2 ? -1 : 1;
        if (k % 2 == 0) {
            gsl_rng_set(rng, sf_mc_seed(c->scene.seed, (size_t)k));
            rc = sf_cof_plan_draw(b.cp, rng, &w);
        } else
            rc = sf_cof_plan_antithetic(b.cp, prev, &w);
        if (rc)
            break;
        uint64_t key = sf_cof_key(w);
        for (int pos = 0; pos < EX_POS && !rc; pos++) {
            if (pos) {   /* the disc carried along -x by 0.3 to 1.7 R: slides of part of the window or all of it */
                double xb = -b.s.R * (0.3 + 1.4 * gsl_rng_uniform(pts)) * pos;
                if ((rc = sf_cof_follow(w, xb - b.s.R - in->margin, xb + b.s.R + in->margin)))
                    break;
            }
            size_t m, n;
            double x0, y0, dx, dy;
            const double *mu;
            sf_cof_grid_view(w, &m, &n, &x0, &y0, &dx, &dy, &mu);
            for (int q = 0; q < EX_NODES && !rc; q++) {
                size_t ci = (size_t)gsl_rng_uniform_int(pts, m), cj = (size_t)gsl_rng_uniform_int(pts, n);
                double x = x0 + (double)ci * dx, y = y0 + (double)cj * dy;
                long ic = lround(x / b.h - 0.5), jc = lround(y / b.h - 0.5);
                align = sf_max(align, sf_max(fabs(x / b.h - 0.5 - (double)ic), fabs(y / b.h - 0.5 - (double)jc)));
                double d, bound;
                if ((rc = direct_box(&b, key, sign, ic, jc, &d, &bound)))
                    break;
                ratio[nodes] = fabs(mu[ci + m * cj] - d) / bound;
                idx[nodes] = (double)nodes;
                worst = sf_max(worst, ratio[nodes]);
                nodes++;
            }
        }
        if (k % 2 == 0) {
            sf_cof_free(prev);
            prev = w;
        } else
            sf_cof_free(w);
    }
    sf_cof_free(prev);
    gsl_rng_free(rng);
    gsl_rng_free(pts);
    setup_free(&b);
    if (rc)
        return rc;
    sf_check_le(r, "nodes off the centres of the noise cells: largest |x/h - 1/2 - i|, |y/h - 1/2 - j| (rounding)",
                align, 1e-6);
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "window box value against the direct average, %zu nodes: largest |difference| / its "
             "round-off bound 2 gamma_k sum |w_p w_q mu|, k = 2 (2E + 1)", nodes);
    sf_check_le(r, q, worst, 1);
    sf_plot *pl = sf_result_plot(r, "beltbox-exact", "Window box values against the direct average, per node",
                                 "node (window, position, draw) [-]", "|difference| / round-off bound [-]");
    sf_plot_series(pl, "nodes", SF_STYLE_POINTS, nodes, idx, ratio);
    sf_plot_hline(pl, "bound", 1);
    return SF_SUCCESS;
}

/* ---- the law of the box averages */

/* D_n(L) = sum_{p,q} w_p w_q C(p - q + L)^n, C the tiles' produced 1-D
 * correlation at lag L fine cells: the box averages' covariance is
 * mubar^2 sum_n a_n D_n(Lx) D_n(Ly) (the series of cellavg.h on the
 * lattice, exact for the construction). */
static double dsum(const box_setup *b, const sf_tiles *t, int n, long L)
{
    double s = 0;
    for (size_t p = 0; p < b->nw; p++)
        for (size_t q = 0; q < b->nw; q++)
            s += b->w[p] * b->w[q] * pow(sf_tiles_covariance(t, (long)p - (long)q + L, 0), n);
    return s;
}

static double lattice_cov(const box_setup *b, const sf_cellavg *ca, const sf_tiles *t, long Lx)
{
    double s = 0;
    for (int n = ca->nterms; n >= 1; n--)
        s += ca->a[n - 1] * dsum(b, t, n, Lx) * dsum(b, t, n, 0);
    return ca->mubar * ca->mubar * s;
}

static int chk_stats(const sf_case *c, sf_result *r)
{
    box_setup b;
    int rc = setup(c, r, &b);
    if (rc)
        return rc;
    const sf_cof_plan_info *in = &b.pl.cof;
    size_t nwin = c->scene.samples;
    /* the box the quadrature's cells need: 2R / cells (the plan's), not the COF plan's own record */
    double cell = 2 * b.s.R / (double)b.pl.num.cells;
    sf_cellavg ca;
    sf_cellavg_init(&ca, b.s.mu_mean, b.s.mu_std, b.s.l, cell);
    box_setup bq = b;   /* the weights of the quadrature's cell */
    bq.nw = sf_cellavg_cubic_weights(cell / b.h, NULL, 0);
    bq.w = check_alloc(bq.nw * sizeof *bq.w);
    sf_cellavg_cubic_weights(cell / b.h, bq.w, bq.nw);
    sf_tiles_spec ts = { 1, b.h, b.h, b.s.l, 0, 0 };
    sf_tiles *t;
    if ((rc = sf_tiles_alloc(&ts, &t))) {
        free(bq.w);
        setup_free(&b);
        return rc;
    }
    size_t g = (size_t)fmax(1, lround(cell / in->dx));   /* the lag of the covariance row: about one box */
    double lag = (double)g * in->dx;
    double vd = lattice_cov(&bq, &ca, t, 0), cd = lattice_cov(&bq, &ca, t, (long)(g * in->box_step));
    double vc = sf_cellavg_var(&ca), cc = sf_cellavg_cov(&ca, lag, 0);
    sf_tiles_free(t);
    /* nodes at least a box + 6 l apart (correlation below exp(-36)) and their partners a lag along x */
    size_t sp = (size_t)ceil((cell + 6 * b.s.l) / in->dx);
    double *va = NULL, *vb = NULL;
    size_t N = 0, cap = 0;
    gsl_rng *rng = sf_case_rng(c);
    for (size_t k = 0; k < nwin && !rc; k++) {
        sf_cof *w;
        gsl_rng_set(rng, sf_mc_seed(c->scene.seed, k));
        if ((rc = sf_cof_plan_draw(b.cp, rng, &w)))
            break;
        size_t m, n;
        const double *mu;
        sf_cof_grid_view(w, &m, &n, NULL, NULL, NULL, NULL, &mu);
        for (size_t j = 0; j < n; j += sp)
            for (size_t i = 0; i + g < m; i += sp) {
                if (N == cap) {
                    cap = cap ? 2 * cap : 1024;
                    va = realloc(va, cap * sizeof *va);
                    vb = realloc(vb, cap * sizeof *vb);
                    if (!va || !vb)
                        abort();
                }
                va[N] = mu[i + m * j];
                vb[N] = mu[i + g + m * j];
                N++;
            }
        sf_cof_free(w);
    }
    gsl_rng_free(rng);
    if (rc || N < 100) {
        free(va);
        free(vb);
        free(bq.w);
        setup_free(&b);
        return rc ? rc : SF_EINVAL;
    }
    sf_result_data(r, "box values", N, va);
    sf_result_data(r, "box values a lag along x", N, vb);
    double a3 = c->spec.alpha / 3, mb = b.s.mu_mean;
    double mean = gsl_stats_mean(va, 1, N), sd = gsl_stats_sd(va, 1, N);
    double *u = check_alloc(N * sizeof *u);
    for (size_t i = 0; i < N; i++)
        u[i] = (va[i] - mb) * (va[i] - mb);
    double v = gsl_stats_mean(u, 1, N), sev = gsl_stats_sd(u, 1, N) / sqrt((double)N);
    for (size_t i = 0; i < N; i++)
        u[i] = (va[i] - mb) * (vb[i] - mb);
    double cv = gsl_stats_mean(u, 1, N), sec = gsl_stats_sd(u, 1, N) / sqrt((double)N);
    free(u);
    double zc = gsl_cdf_ugaussian_Qinv(a3 / 2), z99 = gsl_cdf_ugaussian_Qinv(0.01);
    sf_note(r, "\nl/R = %g, CV = %g: boxes of %.4g m (the quadrature's cells, %zu per diameter) = %.3g l over noise "
               "cells of l/%.3g; %zu windows, %zu nodes at least box + 6 l apart (correlation below exp(-36): "
               "independent to round-off), each with a partner %zu grid steps (%.4g m) along x. The law of the "
               "construction, exact (the tiles' produced correlation, the filter's weights, the lognormal series): "
               "Var = %.6g, Cov(lag) = %.6g; the continuous box average's closed form (sf_cellavg_var, "
               "sf_cellavg_cov): %.6g, %.6g. Measured: mean %.6f (mubar %.6f), variance about mubar %.6g (se %.2g), "
               "covariance at the lag %.6g (se %.2g). Each z-test two-sided at alpha/3 = %.3g (z %.2f); power 0.99 "
               "against a shift of (z + %.2f) se: a variance %.1f%% off, a covariance %.1f%% off, a mean %.2g off.\n",
            b.s.l / b.s.R, b.s.mu_std / b.s.mu_mean, cell, b.pl.num.cells, cell / b.s.l, b.s.l / b.h, nwin, N, g,
            lag, vd, cd, vc, cc, mean, mb, v, sev, cv, sec, a3, zc, z99, 100 * (zc + z99) * sev / vd,
            100 * (zc + z99) * sec / cd, (zc + z99) * sd / sqrt((double)N));
    sf_check_le(r, "the construction's variance against the continuous box average's: |Var / sf_cellavg_var - 1| "
                   "(the cubic interpolant's O((h/l)^4) error, cellavg.h: within 1%)", fabs(vd / vc - 1), 0.01);
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "mean of %zu box values = mubar (the filter's weights sum to 1): two-sided z-test", N);
    sf_check_pvalue(r, q, sf_z_pvalue((mean - mb) / (sd / sqrt((double)N))), a3, N);
    snprintf(q, sizeof q, "variance of %zu box values = the construction's exact %.5g: two-sided z-test (se from the "
             "squares' spread)", N, vd);
    sf_check_pvalue(r, q, sf_z_pvalue((v - vd) / sev), a3, N);
    snprintf(q, sizeof q, "covariance at a lag of %.4g m = the construction's exact %.5g: two-sided z-test", lag, cd);
    sf_check_pvalue(r, q, sf_z_pvalue((cv - cd) / sec), a3, N);
    double xs[2] = { 0, lag }, me[2] = { v, cv }, ex[2] = { vd, cd }, cl[2] = { vc, cc };
    sf_plot *pl = sf_result_plot(r, "beltbox-law", "Box averages on belt noise: covariance at lags 0 and about one box",
                                 "lag along x [m]", "covariance [COF^2]");
    sf_plot_series(pl, "measured", SF_STYLE_POINTS, 2, xs, me);
    sf_plot_series(pl, "construction, exact", SF_STYLE_LINESPOINTS, 2, xs, ex);
    sf_plot_series(pl, "continuous box average (sf_cellavg_cov)", SF_STYLE_DASHED, 2, xs, cl);
    free(va);
    free(vb);
    free(bq.w);
    setup_free(&b);
    return SF_SUCCESS;
}

/* ---- the QoIs: box averages against the point model on the same noise */

static const char *const qn[SF_SWEEP_NQ] = { "PV_x", "PV_F", "stick fraction" };

static int chk_qoi(const sf_case *c, sf_result *r)
{
    box_setup b;
    int rc = setup(c, r, &b);
    if (rc)
        return rc;
    size_t n = c->scene.samples;
    sf_scene sp = b.s;
    sp.cof_model = SF_COFMODEL_POINT;
    sf_plan pp;
    sf_cof_plan *cpp;
    char err[300] = "";
    if ((rc = sf_plan_make(&sp, &pp, err, sizeof err)) || (rc = sf_cof_plan_alloc(&sp, &cpp, err, sizeof err))) {
        sf_note(r, "\n**Cannot plan the point model:** %s\n", err);
        setup_free(&b);
        return rc;
    }
    double *q = check_alloc(2 * SF_SWEEP_NQ * n * sizeof *q), *e = check_alloc(n * sizeof *e);
    double *ix = check_alloc(n * sizeof *ix), *ea = check_alloc(SF_SWEEP_NQ * n * sizeof *ea);
    gsl_rng *rng = sf_case_rng(c);
    double t0 = check_cpu_seconds();
    for (size_t i = 0; i < n && !rc; i++) {
        double qc[SF_SWEEP_NQ], qp[SF_SWEEP_NQ];
        gsl_rng_set(rng, sf_mc_seed(c->scene.seed, i));   /* one key, so one white noise, for both */
        if ((rc = sf_sweep_realise(&b.s, b.cp, rng, qc)))
            break;
        gsl_rng_set(rng, sf_mc_seed(c->scene.seed, i));
        if ((rc = sf_sweep_realise(&sp, cpp, rng, qp)))
            break;
        for (int j = 0; j < SF_SWEEP_NQ; j++) {
            q[j * n + i] = qc[j];
            q[(SF_SWEEP_NQ + j) * n + i] = qp[j];
        }
    }
    double cpu = check_cpu_seconds() - t0;
    gsl_rng_free(rng);
    if (!rc) {
        sf_result_data(r, "QoIs, cell averages then the point model", 2 * SF_SWEEP_NQ * n, q);
        double marg = c->spec.tolerance, a3 = c->spec.alpha / SF_SWEEP_NQ;
        double bound = b.pl.num.err_quad + pp.num.err_quad + b.pl.num.err_time + pp.num.err_time;
        sf_note(r, "\nl/R = %g, CV = %g, v_b = %g m/s, mean COF %g (belt-speed number %.3g): the plan's box averages "
                   "(%zu cells per diameter, predicted QoI error %.2g) against the point model (%zu rings, %.2g), "
                   "each at its plan's rtol (%.2g, %.2g), on the same white noise (one key per pair: the box model "
                   "reads it one level coarser, whose cells are the sums of the point model's: the two Gaussian fields "
                   "correlate at 0.996 or more, as at a switch of noise level, so a pair differs by more than the "
                   "model's error); %zu pairs, %.1f s of CPU. Per QoI: the ratio of the means (interval null |log "
                   "ratio| <= log(1 + %g), Student t on the pairs' influence functions, df %zu) at alpha / 3 = %.3g; "
                   "beside it (not gated) the RMS and the largest of the pairs' differences over the point model's "
                   "mean, against the "
                   "sum of the two plans' predicted errors %.2g, and the shift the test detects at power 0.99.\n\n"
                   "| QoI | mean ratio | se (log) | detected at power 0.99 | RMS relative difference | largest |\n"
                   "|---|---|---|---|---|---|",
                b.s.l / b.s.R, b.s.mu_std / b.s.mu_mean, b.s.v_b, b.s.mu_mean, sf_numplan_belt_number(&b.s),
                b.pl.num.cells, b.pl.num.err_quad, pp.num.cells, pp.num.err_quad, b.pl.num.rtol, pp.num.rtol, n,
                cpu, marg, n - 1, a3, bound);
        for (int j = 0; j < SF_SWEEP_NQ; j++) {
            const double *x = q + j * n, *y = q + (SF_SWEEP_NQ + j) * n;
            double mx = gsl_stats_mean(x, 1, n), my = gsl_stats_mean(y, 1, n), big = 0, m2 = 0;
            double *u = check_alloc(n * sizeof *u);
            for (size_t i = 0; i < n; i++) {
                u[i] = (x[i] - mx) / mx - (y[i] - my) / my;
                e[i] = (x[i] - y[i]) / my;   /* over the mean: a pair with no stick in either has 0/0 as its own ratio */
                ea[j * n + i] = e[i];
                ix[i] = (double)i;
                big = sf_max(big, fabs(e[i]));
                m2 += e[i] * e[i];
            }
            double est = log(mx / my), se = gsl_stats_sd(u, 1, n) / sqrt((double)n);
            free(u);
            double df = (double)n - 1, mde = expm1(log1p(marg) + (gsl_cdf_tdist_Qinv(a3 / 2, df) +
                                                                  gsl_cdf_tdist_Qinv(0.01, df)) * se);
            sf_note(r, "| %s | %.5f | %.2g | %.2g | %.2g | %.2g |", qn[j], mx / my, se, mde, sqrt(m2 / (double)n),
                    big);
            char t[SF_LABEL_LEN];
            snprintf(t, sizeof t, "%s: |mean ratio - 1| <= %g (interval null, paired)", qn[j], marg);
            sf_check_pvalue(r, t, sf_interval_null_p(est, se, log1p(marg), df), a3, n);
        }
        sf_plot *pl = sf_result_plot(r, "beltbox-qoi", "(box averages - point model) / its mean, on the same noise, per pair",
                                     "pair [-]", "relative difference [-]");
        for (int j = 0; j < SF_SWEEP_NQ; j++)
            sf_plot_series(pl, qn[j], SF_STYLE_POINTS, n, ix, ea + j * n);
        sf_plot_hline(pl, "+ predicted", bound);
        sf_plot_hline(pl, "- predicted", -bound);
    }
    free(q);
    free(e);
    free(ix);
    free(ea);
    sf_cof_plan_free(cpp);
    setup_free(&b);
    return rc;
}

const sf_check_def sf_checks_beltbox[] = {
    { "beltbox_exact", chk_exact,
      "Box averages on belt noise: the window's values against a direct average of the fine field (round-off)" },
    { "beltbox_stats", chk_stats,
      "Box averages on belt noise: mean, variance and covariance against the exact law and the closed form" },
    { "beltbox_qoi", chk_qoi,
      "Box averages on belt noise against the point model on the same noise: QoI means and differences" },
    { NULL, NULL, NULL }
};
