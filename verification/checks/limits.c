/* Exact limits of the stochastic model (docs/design.md sec. 4.8):
 * large l/R, where the COF is one lognormal random variable over the whole
 * strip and every QoI ratio has a closed-form distribution; small l/R,
 * where the disc averages the field and the model homogenises towards the
 * deterministic one. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "cof.h"
#include "sweep.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sort.h>

/* A QoI ratio as a function of the drawn mu_s, from the closed form.
 * Both halves of the oracle are the checks' own (common.h): the lognormal
 * parameters from the target mean and std (ref_lognormal_par, not
 * solver/field/lognormal.c, which draws the realisations: a defect there must
 * not move the oracle with it) and the cycle (ref_cycle, not
 * solver/dynamics/cycle1d.c). */
typedef struct {
    const sf_scene *s;
    int q;               /* SF_SWEEP_PVX, PVF or SF */
    ref_ln_par ln;
    double det;          /* the closed-form value at mu_mean */
} qmap;

static double qoi_at(const qmap *m, double mu)
{
    ref_cycle1d c;
    if (ref_cycle(m->s, mu, &c))
        return NAN;
    double v = m->q == SF_SWEEP_PVX ? c.pv_x : (m->q == SF_SWEEP_PVF ? c.pv_F : c.sf);
    return v / m->det;
}

static double ln_cdf(const qmap *m, double mu)
{
    return gsl_cdf_lognormal_P(mu, m->ln.mu, m->ln.sigma);
}

typedef struct { const qmap *m; double target; } inv_par;
static double inv_f(double mu, void *p)
{
    const inv_par *ip = p;
    return qoi_at(ip->m, mu) - ip->target;
}

/* CDF of the ratio: every ratio increases with mu_s, so
 * P(ratio <= r) = F_mu(mu(r)), mu(r) by Brent. */
static double ratio_cdf(double r, void *params)
{
    const qmap *m = params;
    double lo = m->s->mu_mean * 1e-3, hi = m->s->mu_mean * 1e3;
    /* the 1-D model needs a cycle: clip to where the closed form exists */
    while (isnan(qoi_at(m, lo)))
        lo *= 1.5;
    while (isnan(qoi_at(m, hi)))
        hi /= 1.5;
    if (r <= qoi_at(m, lo))
        return ln_cdf(m, lo);
    if (r >= qoi_at(m, hi))
        return ln_cdf(m, hi);
    inv_par ip = { m, r };
    gsl_function F = { inv_f, &ip };
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(rs, &F, lo, hi);
    for (int it = 0; it < 200; it++) {
        gsl_root_fsolver_iterate(rs);
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(rs), gsl_root_fsolver_x_upper(rs), 0, 1e-14) == GSL_SUCCESS)
            break;
    }
    double mu = gsl_root_fsolver_root(rs);
    gsl_root_fsolver_free(rs);
    return ln_cdf(m, mu);
}

/* Large l/R: KS tests of the three ratio samples against their exact
 * distributions (one lognormal mu_s mapped through the closed-form cycle). */
static int chk_large_lr(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    char err[256] = "";
    sf_cof_plan *p;
    if (sf_cof_plan_alloc(s, &p, err, sizeof err))
        return SF_EINVAL;
    const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
    sf_note(r, "Plan at l/R = %g (l = %g m): %s.", s->l / s->R, s->l,
            in->shortcut ? "one random variable (the strip the disc can visit, diagonal E, has (E/l)^2 <= 1e-6: "
                           "every two of its points correlate at >= 1 - 1e-6)"
                         : "a strip field (the shortcut threshold is not reached: the field varies slightly over "
                           "the strip)");
    if (!in->shortcut)
        sf_note(r, " Strip field %zu x %zu at spacing %.4g m.", in->nx, in->ny, in->dx);
    sf_cof_plan_free(p);
    sf_sweep_point pt;
    sf_scene gs = check_gen_scene(c);   /* the realisations are drawn from the generator's scene */
    if (sf_sweep_run(&gs, s->samples, 0, NULL, 0, NULL, &pt, err, sizeof err)) {
        sf_note(r, "**Sweep failed:** %s", err);
        return SF_EFAIL;
    }
    const char *names[3] = { "PV_x ratio", "PV_F ratio", "stick-fraction ratio" };
    size_t n = pt.n;
    double *x = check_alloc(n * sizeof *x);
    ref_cycle1d cd;
    ref_cycle(s, s->mu_mean, &cd);
    double detv[3] = { cd.pv_x, cd.pv_F, cd.sf };
    for (int q = 0; q < 3; q++) {
        qmap m = { .s = s, .q = q, .det = detv[q], .ln = ref_lognormal_par(s->mu_mean, s->mu_std) };
        for (size_t i = 0; i < n; i++)   /* the ratios as the sweep reports them */
            x[i] = pt.ratio[3 * i + q];
        char dq[128];
        snprintf(dq, sizeof dq, "deterministic reference %s vs the closed form at the mean", q == 0 ? "PV_x [m]" :
                 q == 1 ? "PV_F [N]" : "stick fraction [-]");
        sf_check_rel(r, dq, pt.det[q], detv[q], 1e-7);
        double D, pv = sf_ks_test(x, n, ratio_cdf, &m, &D);
        char t[160];
        snprintf(t, sizeof t, "KS: %s vs its exact distribution (D = %.4f), Bonferroni x3", names[q], D);
        sf_check_pvalue(r, t, sf_min(1, 3 * pv), c->spec.alpha, n);
        /* plot: empirical CDF vs exact */
        gsl_sort(x, 1, n);
        double *ecdf = check_alloc(n * sizeof *ecdf), *ex = check_alloc(n * sizeof *ex);
        for (size_t i = 0; i < n; i++) {
            ecdf[i] = (double)(i + 1) / (double)n;
            ex[i] = ratio_cdf(x[i], &m);
        }
        char stem[32], title[96], xl[64];
        snprintf(stem, sizeof stem, "cdf_%d", q);
        snprintf(title, sizeof title, "Large l/R: %s, empirical vs exact CDF", names[q]);
        snprintf(xl, sizeof xl, "%s [-]", names[q]);
        sf_plot *pl = sf_result_plot(r, stem, title, xl, "cumulative probability [-]");
        double band = 1.36 / sqrt((double)n);   /* 95% KS band */
        double *lo = check_alloc(n * sizeof *lo), *hi = check_alloc(n * sizeof *hi);
        for (size_t i = 0; i < n; i++) {
            lo[i] = sf_max(ex[i] - band, 0);
            hi[i] = sf_min(ex[i] + band, 1);
        }
        sf_plot_band(pl, "95% KS band around the exact CDF", n, x, lo, hi);
        sf_plot_series(pl, "exact (lognormal mu_s through the closed-form cycle)", SF_STYLE_LINES, n, x, ex);
        sf_plot_series(pl, "sample", SF_STYLE_STEPS, n, x, ecdf);
        free(ecdf); free(ex); free(lo); free(hi);
    }
    sf_note(r, "\n%zu realisations, T = %g s, t_skip = %g s. Means (std): PV_x ratio %.4f (%.4f), PV_F ratio %.4f "
               "(%.4f; exact CV %.3g), stick-fraction ratio %.4f (%.4f). The paper's Fig. 11 reports a PV_F std "
               "near 0.2 for l/R > 100: the exact value is the COF's CV.\n", n, s->T, s->t_skip, pt.mean[0],
            pt.std[0], pt.mean[1], pt.std[1], s->mu_std / s->mu_mean, pt.mean[2], pt.std[2]);
    free(x);
    sf_sweep_point_free(&pt);
    return SF_SUCCESS;
}

/* Small l/R: homogenisation.  Over a sweep of l/R below the spread's peak
 * (l/R ~ 1), the spread of the PV_F and PV_x ratios over realisations and
 * the distance of their means from 1 fall with l/R: tested between the
 * sweep's ends, the values in between tabled and plotted. */
/* The sweep's last point (l/R = 1, where the ratios spread most: std
 * about 0.33 against 0.04 at 0.125) sets the mean test's standard error,
 * so it takes this many times the samples: at 16 a point the |mean - 1|
 * test's z averaged about 3.6 and missed the trend in 3 of 16 fresh-seed
 * runs (power about 0.8 at alpha / 4).  At 3x a field in another regime
 * at l/R = 0.125 (one sample of 16 in four holds one) raises that end's
 * standard error too: the first run missed in 5 of 120 fresh seeds
 * (z 2.3-2.8).  6x, the cheap end (l/R = 1 runs 4x faster than 0.125):
 * z about 7.9 without such a field, 5.2 with one. */
#define SMALL_LR_WIDE 6

/* The absolute deviations of the finite values of x[q], x[q + stride],
 * ... (n of them) from their median, into d (their count returned).  The
 * spread test ranks them (Mann-Whitney U, sf_mwu_greater_p): a few fields
 * at small l/R put a realisation in another oscillation regime (1.5% of
 * them at l/R = 0.125 here), and a test on the deviations' means (Brown-
 * Forsythe's Welch t) or on the variances (F) then reads the end's spread
 * from that one value; its rank moves U by at most the other sample's
 * size. */
static size_t absdev(const double *x, size_t stride, size_t n, double *d)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i * stride]))
            d[m++] = x[i * stride];
    if (!m)
        return 0;
    gsl_sort(d, 1, m);
    double med = gsl_stats_median_from_sorted_data(d, 1, m);
    for (size_t i = 0; i < m; i++)
        d[i] = fabs(d[i] - med);
    return m;
}

static int chk_small_lr(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (K < 4)
        return SF_EINVAL;
    double *lr = check_alloc(K * sizeof *lr), *sd[2], *mn[2], *lx = check_alloc(K * sizeof *lx), *ly = check_alloc(K * sizeof *ly);
    for (int q = 0; q < 2; q++) {
        sd[q] = check_alloc(K * sizeof(double));
        mn[q] = check_alloc(K * sizeof(double));
    }
    size_t nmax = SMALL_LR_WIDE * s0->samples, nd[2][2] = { { 0 } };
    double *dev[2][2];   /* [q][end]: absolute deviations from the median at the sweep's ends */
    for (int q = 0; q < 2; q++)
        for (int j = 0; j < 2; j++)
            dev[q][j] = check_alloc(nmax * sizeof(double));
    sf_note(r, "| l/R | mean PV_x ratio | std | mean PV_F ratio | std |\n|---|---|---|---|---|");
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        sf_sweep_set(&s, "l_over_R", c->spec.sweep.v[k], err, sizeof err);
        sf_sweep_point pt;
        if (sf_sweep_run(&s, k == K - 1 ? SMALL_LR_WIDE * s0->samples : s0->samples, 0, NULL, 0, NULL, &pt, err,
                         sizeof err)) {
            sf_note(r, "**Sweep failed at l/R = %g:** %s", c->spec.sweep.v[k], err);
            return SF_EFAIL;
        }
        lr[k] = c->spec.sweep.v[k];
        for (int q = 0; q < 2; q++) {
            mn[q][k] = pt.mean[q];
            sd[q][k] = pt.std[q];
            if (k == 0 || k == K - 1)
                nd[q][k != 0] = absdev(pt.ratio + q, SF_SWEEP_NQ, pt.n, dev[q][k != 0]);
        }
        sf_note(r, "| %g | %.4f | %.4f | %.4f | %.4f |", lr[k], mn[0][k], sd[0][k], mn[1][k], sd[1][k]);
        sf_sweep_point_free(&pt);
    }
    /* The trend is tested between the ends of the sweep, where the effect
     * is large: a regression slope over 4 points has 2 degrees of freedom
     * and too little power (measured: it failed 17 of 20 fresh-seed runs
     * of a true trend).  Four one-sided tests, Bonferroni: alpha / 4 each. */
    const char *nm[2] = { "PV_x", "PV_F" };
    size_t n = s0->samples, n1 = SMALL_LR_WIDE * n;
    double a4 = c->spec.alpha / 4;
    for (int q = 0; q < 2; q++) {
        double F = (sd[q][K - 1] * sd[q][K - 1]) / (sd[q][0] * sd[q][0]);
        double pF = sf_mwu_greater_p(dev[q][1], nd[q][1], dev[q][0], nd[q][0]);
        char t[220];
        snprintf(t, sizeof t, "%s ratio: spread larger at l/R = %g than at %g (variance ratio %.1f; one-sided "
                 "Mann-Whitney test on the absolute deviations from the median, p-value)", nm[q], lr[K - 1], lr[0], F);
        sf_check_le(r, t, pF, a4);
        sf_result_mark_statistical(r, a4);
        double se0 = sd[q][0] / sqrt((double)n), se1 = sd[q][K - 1] / sqrt((double)n1);
        double z = (fabs(mn[q][K - 1] - 1) - fabs(mn[q][0] - 1)) / hypot(se0, se1);
        snprintf(t, sizeof t, "%s ratio: |mean - 1| larger at l/R = %g than at %g (z = %.1f; one-sided z test p-value)",
                 nm[q], lr[K - 1], lr[0], z);
        sf_check_le(r, t, 1 - gsl_cdf_ugaussian_P(z), a4);
        sf_result_mark_statistical(r, a4);
    }
    (void)lx;
    (void)ly;
    sf_note(r, "\n%zu realisations per l/R (%zu at l/R = %g), T = %g s. As l/R falls the disc averages over more independent "
               "patches: the spread of every ratio falls (homogenisation) and the means approach the "
               "deterministic model's.\n", s0->samples, n1, lr[K - 1], s0->T);
    sf_plot *p = sf_result_plot(r, "homogenisation", "Spread of the ratios vs l/R (homogenisation)", "l/R [-]",
                                "std over realisations [-]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "PV_x ratio", SF_STYLE_LINESPOINTS, K, lr, sd[0]);
    sf_plot_series(p, "PV_F ratio", SF_STYLE_LINESPOINTS, K, lr, sd[1]);
    for (int q = 0; q < 2; q++) {
        free(sd[q]);
        free(mn[q]);
        free(dev[q][0]);
        free(dev[q][1]);
    }
    free(lr); free(lx); free(ly);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_limits[] = {
    { "limits_large_lr", chk_large_lr, "large l/R: QoI ratio distributions vs their closed forms (KS)" },
    { "limits_small_lr", chk_small_lr, "small l/R: spreads fall and means approach 1 (homogenisation)" },
    { NULL, NULL, NULL }
};
