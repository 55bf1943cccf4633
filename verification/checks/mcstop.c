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
#include "stats.h"
#include "../stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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


/* ---- The printed intervals' coverage on the QoIs' own distributions ----
 *
 * cases/montecarlo/coverage-populations.md: three stored populations of
 * 10^4 sweep realisations each (l/R = 0.1, 1, 10; scripts/coverage-data.sh)
 * are the resampled world: a replication draws with replacement from one
 * of them (a GSL rng at the case seed), builds an sf_sweep_point of the
 * draws (det = 1: the values are the ratios) and asks the sweep's own code
 * for its answer: sf_sweep_point_stats and sf_sweep_estimate (the summary's
 * estimate and interval: the Student interval for a fixed N; with
 * n_pilot > 0 Stein's, sf_mcstop_interval), the two-stage N decided by
 * sf_mcstop_decide, the rule `sweep --target-se` runs.  The estimand is the
 * population's mean over its finite values, exact in that world. */
#define CP_NPT 3                 /* populations */
#define CP_NPROC 3               /* plain N = 20, plain N = 40, two-stage */
#define CP_ROWS (CP_NPT * CP_NPROC * SF_SWEEP_NQ)
#define CP_PILOT 20              /* sweep --pilot's default: min(20, N) */
#define CP_CAP 400               /* --realisations, the two-stage cap */
#define CP_NPLAN 30              /* target-se: the largest ratio sd / sqrt(30) */
static const size_t cp_n[CP_NPROC] = { 20, 40, 0 };
static const char *const cp_proc[CP_NPROC] = { "plain N=20", "plain N=40", "target-se" };
static const char *const cp_qn[SF_SWEEP_NQ] = { "pv_x_ratio", "pv_F_ratio", "stick_fraction_ratio" };
/* The documented levels: the coverage a procedure has on a population
 * where it is not the nominal 0.95, indexed [point][procedure][QoI] (0:
 * nominal), below it a shortfall.  Measured by this check at R = 10^6
 * replications (samples = 1000000, seed = 7 in a copy of the case: 100 s),
 * Clopper-Pearson 95% intervals of +-0.0005: every row whose interval
 * excludes 0.95 is listed at its measured coverage (the README's
 * estimator table states them). */
static const double cp_doc[CP_NPT][CP_NPROC][SF_SWEEP_NQ] = {
    { { 0, 0.9469, 0.9215 }, { 0.9490, 0.9437, 0.9173 }, { 0.9491, 0.9453, 0.9191 } },   /* l/R 0.1 */
    { { 0.9506, 0, 0.9449 }, { 0, 0, 0.9470 }, { 0.9509, 0.9506, 0.9445 } },              /* l/R 1 */
    { { 0.9470, 0.9490, 0.9506 }, { 0.9486, 0.9494, 0 }, { 0.9463, 0.9484, 0 } },         /* l/R 10 */
};

typedef struct {
    double lr;
    size_t n;        /* realisations */
    double *v;       /* n x SF_SWEEP_NQ */
} cp_pop;

static int cp_read(const sf_case *c, sf_result *r, cp_pop pop[CP_NPT], char *path, size_t plen)
{
    int np = -1, rc;
    FILE *f = check_data_open(c, r, path, plen, "sh scripts/coverage-data.sh", &rc);
    if (!f)
        return rc;
    char *line = NULL;
    size_t cap = 0, lineno = 0;
    while (!rc && getline(&line, &cap, f) > 0) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n' || !strncmp(line, "lr\t", 3))
            continue;
        double lr, x[SF_SWEEP_NQ];
        unsigned long i;
        if (sscanf(line, "%lf %lu %lf %lf %lf", &lr, &i, &x[0], &x[1], &x[2]) != 5) {
            sf_note(r, "%s:%zu: not a row of five numbers\n", path, lineno);
            rc = SF_EPARSE;
            break;
        }
        if (np < 0 || lr != pop[np].lr) {
            if (++np >= CP_NPT) {
                sf_note(r, "%s:%zu: more than %d populations\n", path, lineno, CP_NPT);
                rc = SF_EPARSE;
                break;
            }
            pop[np].lr = lr;
        }
        cp_pop *p = &pop[np];
        if (i != p->n) {
            sf_note(r, "%s:%zu: realisation %lu out of order\n", path, lineno, i);
            rc = SF_EPARSE;
            break;
        }
        p->v = realloc(p->v, (p->n + 1) * SF_SWEEP_NQ * sizeof *p->v);
        if (!p->v) {
            rc = SF_ENOMEM;
            break;
        }
        memcpy(p->v + p->n++ * SF_SWEEP_NQ, x, sizeof x);
    }
    free(line);
    fclose(f);
    if (!rc && np != CP_NPT - 1) {
        sf_note(r, "%s: %d populations, %d expected\n", path, np + 1, CP_NPT);
        rc = SF_EPARSE;
    }
    return rc;
}

/* The smallest misses count the two-sided exact test at p0 rejects (upper
 * side), at level a over R replications. */
static unsigned cp_reject_from(double p0, unsigned R, double a)
{
    unsigned k = (unsigned)(p0 * R);
    while (k < R && binom_p(k, p0, R, 1) >= a)
        k++;
    return k;
}

static int chk_coverage_populations(const sf_case *c, sf_result *r)
{
    unsigned R = (unsigned)c->scene.samples;
    double alpha = c->spec.alpha, a_row = alpha / CP_ROWS, p0 = 1 - SF_SWEEP_CI_LEVEL;
    cp_pop pop[CP_NPT];
    memset(pop, 0, sizeof pop);
    char path[4096];
    int rc = cp_read(c, r, pop, path, sizeof path);
    if (rc) {
        for (int k = 0; k < CP_NPT; k++)
            free(pop[k].v);
        return rc;
    }
    /* the populations: over the finite values */
    double mu[CP_NPT][SF_SWEEP_NQ], sd[CP_NPT][SF_SWEEP_NQ], sk[CP_NPT][SF_SWEEP_NQ], se[CP_NPT][SF_SWEEP_NQ];
    char tab[8192];
    size_t used = 0;
    for (int k = 0; k < CP_NPT; k++)
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            double *w = check_alloc(pop[k].n * sizeof *w);
            size_t m = 0;
            for (size_t i = 0; i < pop[k].n; i++)
                if (isfinite(pop[k].v[i * SF_SWEEP_NQ + q]))
                    w[m++] = pop[k].v[i * SF_SWEEP_NQ + q];
            mu[k][q] = gsl_stats_mean(w, 1, m);
            sd[k][q] = gsl_stats_sd_m(w, 1, m, mu[k][q]);
            sk[k][q] = gsl_stats_skew_m_sd(w, 1, m, mu[k][q], sd[k][q]);
            se[k][q] = sd[k][q] / sqrt((double)m);
            free(w);
            used += (size_t)snprintf(tab + used, sizeof tab - used, "| %g | %s | %zu of %zu | %.6f | %.4f | %.3f | %.5f |\n",
                                     pop[k].lr, cp_qn[q], m, pop[k].n, mu[k][q], sd[k][q], sk[k][q], se[k][q]);
        }
    sf_result_data(r, "the populations' means", CP_NPT * SF_SWEEP_NQ, &mu[0][0]);
    sf_result_data(r, "the populations' standard deviations", CP_NPT * SF_SWEEP_NQ, &sd[0][0]);
    sf_note(r, "The stored populations (%s; the estimand is the mean over the finite values):\n\n"
               "| l/R | ratio | finite | mean | sd | skewness | se of the mean |\n|---|---|---|---|---|---|---|\n%s\n",
            path, tab);

    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, c->scene.seed);
    sf_sweep_point pt;
    double *qoi = check_alloc(CP_CAP * SF_SWEEP_NQ * sizeof *qoi), *rat = check_alloc(CP_CAP * SF_SWEEP_NQ * sizeof *rat);
    unsigned miss[CP_ROWS] = { 0 };
    double zsum[CP_ROWS] = { 0 }, z2sum[CP_ROWS] = { 0 }, nsum[CP_NPT] = { 0 }, target[CP_NPT];
    unsigned capped[CP_NPT] = { 0 };
    for (int k = 0; k < CP_NPT && !rc; k++) {
        target[k] = 0;
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            target[k] = sf_max(target[k], sd[k][q] / sqrt((double)CP_NPLAN));
        double tg[SF_SWEEP_NQ] = { target[k], target[k], target[k] };   /* one --target-se for every ratio */
        sf_mcstop_spec st = { CP_PILOT, CP_CAP, tg };
        for (int j = 0; j < CP_NPROC && !rc; j++)
            for (unsigned rep = 0; rep < R && !rc; rep++) {
                size_t n = cp_n[j], drawn = 0;
                int stop = SF_MCSTOP_FIXED;
                if (!n) {   /* the pilot, then the rule's N */
                    for (; drawn < CP_PILOT; drawn++)
                        memcpy(qoi + drawn * SF_SWEEP_NQ, pop[k].v + gsl_rng_uniform_int(rng, pop[k].n) * SF_SWEEP_NQ,
                               SF_SWEEP_NQ * sizeof *qoi);
                    if ((rc = sf_mcstop_decide(&st, SF_SWEEP_NQ, qoi, &n, &stop)))
                        break;
                    nsum[k] += (double)n;
                    capped[k] += stop == SF_MCSTOP_CAP;
                }
                for (; drawn < n; drawn++)
                    memcpy(qoi + drawn * SF_SWEEP_NQ, pop[k].v + gsl_rng_uniform_int(rng, pop[k].n) * SF_SWEEP_NQ,
                           SF_SWEEP_NQ * sizeof *qoi);
                memset(&pt, 0, sizeof pt);
                pt.det[0] = pt.det[1] = pt.det[2] = 1;
                pt.qoi = qoi;
                pt.ratio = rat;
                pt.n = n;
                pt.n_pilot = cp_n[j] ? 0 : CP_PILOT;
                pt.stop = stop;
                pt.estimator = cp_n[j] ? SF_EST_PLAIN : SF_EST_TARGET;
                if ((rc = sf_sweep_point_stats(&pt)))
                    break;
                for (int q = 0; q < SF_SWEEP_NQ; q++) {
                    sf_sweep_answer a;
                    if ((rc = sf_sweep_estimate(&pt, q, &a)))
                        break;
                    int row = (k * CP_NPROC + j) * SF_SWEEP_NQ + q;
                    miss[row] += !(a.ci_lo <= mu[k][q] && mu[k][q] <= a.ci_hi);
                    double z = (a.estimate - mu[k][q]) / (sd[k][q] / sqrt((double)pt.rstat[q].n_used));
                    zsum[row] += z;
                    z2sum[row] += z * z;
                }
            }
    }
    gsl_rng_free(rng);
    free(qoi);
    free(rat);
    for (int k = 0; k < CP_NPT; k++)
        free(pop[k].v);
    if (rc) {
        sf_note(r, "The sweep's statistics failed: %s\n", sf_strerror(rc));
        return rc;
    }

    /* R: a true coverage of 0.90 fails the nominal row with power >= 0.9 */
    unsigned Rmin = 10;
    while (Rmin < 1000000 && gsl_cdf_binomial_Q(cp_reject_from(p0, Rmin, a_row) - 1, 0.10, Rmin) < 0.9)
        Rmin += 10;
    double pw90 = gsl_cdf_binomial_Q(cp_reject_from(p0, R, a_row) - 1, 0.10, R);
    double x[CP_ROWS], cov[CP_ROWS], lo[CP_ROWS], hi[CP_ROWS], bias[CP_ROWS], lvl[CP_ROWS];
    used = 0;
    for (int row = 0; row < CP_ROWS; row++) {
        int k = row / (CP_NPROC * SF_SWEEP_NQ), j = row / SF_SWEEP_NQ % CP_NPROC, q = row % SF_SWEEP_NQ;
        unsigned hit = R - miss[row];
        x[row] = row + 1;
        cov[row] = hit / (double)R;
        sf_clopper_pearson(hit, R, &lo[row], &hi[row]);
        bias[row] = zsum[row] / R;
        double bse = sqrt((z2sum[row] / R - bias[row] * bias[row]) / R);
        lvl[row] = cp_doc[k][j][q] > 0 ? cp_doc[k][j][q] : SF_SWEEP_CI_LEVEL;
        used += (size_t)snprintf(tab + used, sizeof tab - used, "| %g | %s | %s | %.4f [%.4f, %.4f] | %+.3f +- %.3f | %s |\n",
                                 pop[k].lr, cp_proc[j], cp_qn[q], cov[row], lo[row], hi[row], bias[row], bse,
                                 cp_doc[k][j][q] <= 0                   ? "nominal 0.95"
                                 : cp_doc[k][j][q] < SF_SWEEP_CI_LEVEL ? "documented shortfall"
                                                                       : "documented, above nominal");
    }
    sf_result_data(r, "the coverages", CP_ROWS, cov);
    sf_result_data(r, "the biases in se units", CP_ROWS, bias);
    sf_note(r, "%u replications per row (seed %lu), with replacement; two-stage: pilot %d, cap %d, target-se the "
               "largest ratio sd / sqrt(%d) (l/R %g: %.4g, N %.1f on average, %u capped; %g: %.4g, N %.1f, %u; %g: %.4g, "
               "N %.1f, %u).  Rows tested: %d (alpha %g / %d = %.3g each, two-sided exact binomial test of the misses "
               "at the row's level); a true coverage of 0.90 fails a nominal row with power %.4f at R = %u (R >= %u "
               "gives 0.9).  Bias: the mean over replications of (estimate - population mean) / (sd / sqrt(n)), "
               "n the values the estimate averaged, +- its standard error.\n\n"
               "| l/R | procedure | ratio | coverage [CP 95%%] | bias / se | level tested |\n|---|---|---|---|---|---|\n%s\n",
            R, c->scene.seed, CP_PILOT, CP_CAP, CP_NPLAN, pop[0].lr, target[0], nsum[0] / R, capped[0], pop[1].lr,
            target[1], nsum[1] / R, capped[1], pop[2].lr, target[2], nsum[2] / R, capped[2], CP_ROWS, alpha, CP_ROWS,
            a_row, pw90, R, Rmin, tab);
    sf_plot *pl = sf_result_plot(r, "coverage", "Printed 95% intervals: coverage of the population mean",
                                 "row (l/R 0.1, 1, 10; each: plain N=20, N=40, target-se; each: pv_x, pv_F, stick fraction)",
                                 "coverage [-]");
    sf_plot_band(pl, "Clopper-Pearson 95% intervals", CP_ROWS, x, lo, hi);
    sf_plot_series(pl, "measured coverage", SF_STYLE_POINTS, CP_ROWS, x, cov);
    sf_plot_series(pl, "level tested", SF_STYLE_LINES, CP_ROWS, x, lvl);
    sf_plot_hline(pl, "nominal", SF_SWEEP_CI_LEVEL);
    for (int row = 0; row < CP_ROWS; row++) {
        int k = row / (CP_NPROC * SF_SWEEP_NQ), j = row / SF_SWEEP_NQ % CP_NPROC, q = row % SF_SWEEP_NQ;
        char what[SF_LABEL_LEN];
        snprintf(what, sizeof what, "l/R %g, %s, %s: misses ~ Binomial(R, %.4f) (%s), two-sided exact test", pop[k].lr,
                 cp_proc[j], cp_qn[q], 1 - lvl[row], cp_doc[k][j][q] <= 0 ? "nominal" : "documented level");
        sf_check_pvalue(r, what, binom_p(miss[row], 1 - lvl[row], R, 1), a_row, R);
    }
    return SF_SUCCESS;
}

const sf_check_def sf_checks_mcstop[] = {
    { "mc_stein_coverage", chk_stein_coverage,
      "two-stage sample size: the interval covers a known mean at its level, fresh seeds" },
    { "mc_coverage_populations", chk_coverage_populations,
      "the sweep's printed intervals (plain, target-se) cover the mean of the QoIs' stored populations" },
    { NULL, NULL, NULL }
};
