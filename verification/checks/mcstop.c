/* The two-stage sample size (solver/stats/mcstop.h) keeps its intervals'
 * coverage at fresh seeds.
 *
 * A cheap QoI with a known mean: per realisation one static COF mu drawn
 * from the scene's lognormal, and the oracle's 1-D limit cycle at mu
 * (ref_cycle: PV_x, PV_F, its stick fraction), whose means over the
 * lognormal are integrals computed here by adaptive quadrature (GSL
 * qag over |z| <= 12).  Each of R replications (realisation i on stream
 * sf_mc_seed(seed_r, i), seed_r = sf_mc_seed(case seed, r)) runs the
 * design through sf_mcstop_run, and its interval comes from
 * sf_mcstop_interval (what `slipfield sweep --target-se` prints): the misses per QoI are Binomial(R, 1 - level) when the
 * coverage is nominal.  (The variance-reduced estimators' checks, also
 * registered under mc_ names, are in estimators.c.) */
#include "checks.h"
#include "common.h"
#include "mcstop.h"
#include "montecarlo.h"
#include "sf_error.h"
#include "../stats.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_statistics_double.h>

#define NQ 4
#define SKEW_MISS 0.06  /* the skewed QoIs' allowance: coverage 0.95 - 0.01 */
#define N_PILOT 15      /* the floor */
#define N_PLAN 40       /* the targets: each QoI's sd / sqrt(N_PLAN) */
#define N_CAP 400
/* ln PV_F = ln(2 (1 - mu_k_ratio) m g) + ln mu is exactly normal: Stein's
 * interval is exact for it.  The others are skewed smooth functions of a
 * lognormal, where any Student interval on 15 to 400 values under-covers
 * a little. */
static const char *const qn[NQ] = { "ln PV_F", "PV_x", "PV_F", "stick fraction" };

typedef struct {
    const sf_scene *s;   /* the cycle's scene */
    ref_ln_par ln;       /* the COF's lognormal (the generator's) */
} draw_ctx;

static void cycle_qoi(const sf_scene *s, double mu, double *q)
{
    ref_cycle1d cy;
    if (ref_cycle(s, mu, &cy)) {
        q[0] = q[1] = q[2] = q[3] = NAN;
        return;
    }
    q[0] = log(cy.pv_F);
    q[1] = cy.pv_x;
    q[2] = cy.pv_F;
    q[3] = cy.sf;
}

static int realise(void *ws, size_t i, gsl_rng *rng, double *out)
{
    const draw_ctx *d = ws;
    (void)i;
    cycle_qoi(d->s, gsl_ran_lognormal(rng, d->ln.mu, d->ln.sigma), out);
    return SF_SUCCESS;
}

/* The integrand of E[q^pow] over z ~ N(0, 1), mu = exp(m + sigma z). */
typedef struct {
    const sf_scene *s;
    ref_ln_par ln;
    int q, pow;
} moment_ctx;

static double integrand(double z, void *p)
{
    const moment_ctx *m = p;
    double q[NQ];
    cycle_qoi(m->s, exp(m->ln.mu + m->ln.sigma * z), q);
    return pow(q[m->q], m->pow) * gsl_ran_ugaussian_pdf(z);
}

static double moment(const sf_scene *s, ref_ln_par ln, int q, int p, gsl_integration_workspace *w)
{
    moment_ctx m = { s, ln, q, p };
    gsl_function f = { integrand, &m };
    double v, e;
    /* |z| <= 12: the normal tail beyond holds < 1e-32 of the mass (and
       mu = 0 there, where the cycle is not defined) */
    if (gsl_integration_qag(&f, -12, 12, 0, 1e-12, 1000, GSL_INTEG_GAUSS41, w, &v, &e))
        return NAN;
    return v;
}

/* Exact binomial test of k misses in R at rate p0: two-sided, or
 * one-sided (too many misses). */
static double binom_p(unsigned k, double p0, unsigned R, int two_sided)
{
    double lo = gsl_cdf_binomial_P(k, p0, R), hi = k ? gsl_cdf_binomial_Q(k - 1, p0, R) : 1;
    if (!two_sided)
        return hi;
    double p = 2 * (lo < hi ? lo : hi);
    return p < 1 ? p : 1;
}

static int chk_stein_coverage(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_scene gs = check_gen_scene(c);
    unsigned R = (unsigned)s->samples;
    double alpha = c->spec.alpha;
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
    ref_ln_par ln = ref_lognormal_par(s->mu_mean, s->mu_std);
    double truth[NQ], sd[NQ], target[NQ];
    for (int q = 0; q < NQ; q++) {
        truth[q] = moment(s, ln, q, 1, w);
        sd[q] = sqrt(moment(s, ln, q, 2, w) - truth[q] * truth[q]);
        target[q] = sd[q] / sqrt((double)N_PLAN);
    }
    gsl_integration_workspace_free(w);
    sf_result_data(r, "the QoIs' means and standard deviations (quadrature)", NQ, truth);
    sf_result_data(r, "", NQ, sd);

    draw_ctx d = { &gs, ref_lognormal_par(gs.mu_mean, gs.mu_std) };
    sf_mc_ops ops = { NULL, NULL, realise };
    sf_mcstop_spec st = { N_PILOT, N_CAP, target };
    double *out = check_alloc(N_CAP * NQ * sizeof *out);
    double *nv = check_alloc(R * sizeof *nv);
    unsigned miss[NQ] = { 0 }, capped = 0;
    double worst_met = 0, worst_min = INFINITY;   /* max s0/sqrt(N)/X at the target; min s0/sqrt(N-1)/X */
    char err[200] = "";
    int rc = SF_SUCCESS;
    for (unsigned k = 0; k < R && !rc; k++) {
        unsigned long seed = sf_mc_seed(c->scene.seed, k);
        sf_mc_spec spec = { N_CAP, NQ, seed, 1, NULL, 0, 0, NULL };
        size_t n;
        int stop;
        rc = sf_mcstop_run(&spec, &st, &ops, &d, out, &n, &stop, NULL, err, sizeof err);
        if (rc)
            break;
        nv[k] = (double)n;
        capped += stop == SF_MCSTOP_CAP;
        double need = 0;   /* the largest s0 / sqrt(n) / X over the QoIs, at n = N and N - 1 */
        double need1 = 0;
        for (int q = 0; q < NQ; q++) {
            double lo, hi;
            sf_mcstop_interval(out + q, NQ, N_PILOT, n, SF_SWEEP_CI_LEVEL, &lo, &hi);
            miss[q] += !(lo <= truth[q] && truth[q] <= hi);
            double s0 = gsl_stats_sd(out + q, NQ, N_PILOT);
            need = sf_max(need, s0 / sqrt((double)n) / target[q]);
            need1 = sf_max(need1, s0 / sqrt((double)n - 1) / target[q]);
        }
        if (stop == SF_MCSTOP_TARGET)
            worst_met = sf_max(worst_met, need);
        if (stop == SF_MCSTOP_TARGET && n > N_PILOT)
            worst_min = sf_min(worst_min, need1);
    }
    if (rc) {
        sf_note(r, "The two-stage run failed: %s\n", *err ? err : sf_strerror(rc));
        free(out); free(nv);
        return rc;
    }
    sf_result_data(r, "the two-stage sample sizes", R, nv);
    double p0 = 1 - SF_SWEEP_CI_LEVEL, x[NQ], cov[NQ], lo[NQ], hi[NQ];
    /* the plot's band: the test's acceptance region, normal approximation */
    double z2 = gsl_cdf_ugaussian_Qinv(alpha / NQ / 2), z1 = gsl_cdf_ugaussian_Qinv(alpha / NQ);
    char tab[1024];
    size_t used = 0;
    for (int q = 0; q < NQ; q++) {
        x[q] = q + 1;
        cov[q] = 1 - miss[q] / (double)R;
        double pm = q ? SKEW_MISS : p0, w = sqrt(pm * (1 - pm) / R);
        lo[q] = 1 - pm - (q ? z1 : z2) * w;
        hi[q] = q ? 1 : 1 - p0 + z2 * w;
        used += (size_t)snprintf(tab + used, sizeof tab - used, "| %s | %.10g | %.4g | %u | %.4f |\n", qn[q], truth[q],
                                 sd[q], miss[q], cov[q]);
    }
    sf_note(r, "%u replications at fresh streams (seed %lu): pilot %d, cap %d, targets sd/sqrt(%d) from the "
               "quadrature (ln PV_F %.4g, PV_x %.4g m, PV_F %.4g N, stick fraction %.4g). N: mean %.1f, sd %.1f, "
               "%u of %u at the cap.\n\n| QoI | true mean | true sd | misses | coverage |\n|---|---|---|---|---|\n%s\n",
            R, c->scene.seed, N_PILOT, N_CAP, N_PLAN, target[0], target[1], target[2], target[3],
            gsl_stats_mean(nv, 1, R),
            gsl_stats_sd(nv, 1, R), capped, R, tab);
    sf_plot *pl = sf_result_plot(r, "coverage", "Two-stage intervals: coverage of the known mean per QoI",
                                 "QoI (1 ln PV_F, 2 PV_x, 3 PV_F, 4 stick fraction)", "coverage [-]");
    sf_plot_band(pl, "the tests' acceptance regions (normal approx.)", NQ, x, lo, hi);
    sf_plot_series(pl, "measured coverage", SF_STYLE_POINTS, NQ, x, cov);
    sf_plot_hline(pl, "nominal", SF_SWEEP_CI_LEVEL);
    /* exact: N = max(n0, ceil(s0^2 / X^2)); the ratios go through one
       division and one square root each (a few ulp) */
    sf_check_le(r, "where the pilot said every target is met: max over replications and QoIs of s0 / sqrt(N) / X",
                worst_met, 1 + 1e-12);
    sf_check_ge(r, "and not one realisation later than needed (N > n0): min of the largest s0 / sqrt(N - 1) / X",
                worst_min, 1 - 1e-12);
    for (int q = 0; q < NQ; q++) {
        char what[SF_LABEL_LEN];
        if (q == 0)
            snprintf(what, sizeof what, "%s (normal): interval misses in %u replications ~ Binomial(R, %.2f), "
                     "two-sided exact test", qn[q], R, p0);
        else
            snprintf(what, sizeof what, "%s (skewed): misses not above Binomial(R, %.2f), one-sided exact test",
                     qn[q], SKEW_MISS);
        sf_check_pvalue(r, what, binom_p(miss[q], q ? SKEW_MISS : p0, R, q == 0), alpha / NQ, R);
    }
    free(out); free(nv);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_mcstop[] = {
    { "mc_stein_coverage", chk_stein_coverage,
      "two-stage sample size: the interval covers a known mean at its level, fresh seeds" },
    { NULL, NULL, NULL }
};
