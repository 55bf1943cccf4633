/* Checks of the lognormal COF field (Nataf map, paper Sec. 2.2).  The
 * oracle's lognormal parameters and correlation distortion are derived
 * here from the target moments, independently of solver/field/lognormal.c. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "lnfield.h"
#include "lognormal.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>

static double oracle_cdf(double h, void *params)
{
    const ref_ln_par *p = params;
    return h <= 0 ? 0.0 : gsl_cdf_gaussian_P(log(h) - p->mu, p->sigma);
}

/* Build the case's lognormal field.  A truncated embedding is an error
 * unless allow_cap (the pre-corrected kernel is indefinite: see there). */
static int build(const sf_case *c, sf_result *r, sf_lnfield **lf, int allow_cap)
{
    sf_scene gs = check_gen_scene(c);   /* the generator's scene: a power run's alternative */
    int rc = sf_lnfield_alloc(&gs, lf);
    if (!sf_usable(rc))
        return rc;
    const sf_field_info *in = sf_field_get_info(sf_lnfield_gaussian(*lf));
    sf_note(r, "Gaussian embedding %zu x %zu, lambda_min/lambda_max = %.3g, %zu clamped, "
               "max |C_produced - C_target| = %.3g%s.\n", in->px, in->py, in->lambda_min / in->lambda_max,
            in->n_clamped, in->cov_error, in->truncated ? " (truncated)" : "");
    return rc == SF_ETRUNC && !allow_cap ? SF_EFAIL : SF_SUCCESS;
}

/* Indices of grid points spaced at least `gap` apart in both directions:
 * correlation between them <= exp(-gap^2/l^2), i.e. independent samples. */
static size_t sparse_points(const sf_scene *s, double gap, size_t *idx, size_t cap)
{
    size_t sx = (size_t)ceil(gap / s->dx), sy = (size_t)ceil(gap / s->dy), k = 0;
    if (sx == 0) sx = 1;
    if (sy == 0) sy = 1;
    for (size_t j = 0; j < s->ny && k < cap; j += sy)
        for (size_t i = 0; i < s->nx && k < cap; i += sx)
            idx[k++] = i + s->nx * j;
    return k;
}

/* Marginal: KS of COF values at well-separated points against the exact
 * lognormal CDF. */
static int chk_marginal_ks(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_lnfield *lf;
    int rc = build(c, r, &lf, 0);
    if (rc) { sf_lnfield_free(lf); return rc; }
    size_t idx[64];
    size_t np = sparse_points(s, 6.0 * s->l, idx, 64);
    size_t N = s->samples * np, n = s->nx * s->ny;
    double *h = check_alloc(n * sizeof *h), *v = check_alloc(N * sizeof *v);
    gsl_rng *rng = sf_case_rng(c);
    for (size_t k = 0; k < s->samples; k++) {
        sf_lnfield_sample(lf, rng, NULL, h);
        for (size_t q = 0; q < np; q++)
            v[k * np + q] = h[idx[q]];
    }
    ref_ln_par par = ref_lognormal_par(s->mu_mean, s->mu_std);
    double D;
    sf_result_data(r, "COF samples (KS)", N, v);   /* only a subsample is plotted */
    double pval = sf_ks_test(v, N, oracle_cdf, &par, &D);
    char t[160];
    snprintf(t, sizeof t, "KS of the COF marginal vs lognormal(mean %.3g, std %.3g), CV = %.3g",
             s->mu_mean, s->mu_std, s->mu_std / s->mu_mean);
    sf_check_pvalue(r, t, pval, c->spec.alpha, N);
    sf_note(r, "%zu fields x %zu points spaced >= 6 l apart (correlation <= exp(-36)): %zu values; KS D = %.4g.\n",
            s->samples, np, N, D);
    /* QQ plot (v is sorted by the KS test) */
    size_t M = N < 2000 ? N : 2000;
    double *qx = check_alloc(M * sizeof *qx), *qy = check_alloc(M * sizeof *qy);
    for (size_t k = 0; k < M; k++) {
        double pr = ((double)k + 0.5) / (double)M;
        qx[k] = exp(par.mu + par.sigma * gsl_cdf_ugaussian_Pinv(pr));
        qy[k] = v[(size_t)(pr * (double)N)];
    }
    sf_plot *pl = sf_result_plot(r, "qq", "QQ plot of the COF against the target lognormal",
                                 "lognormal quantile [-]", "sample quantile of the COF [-]");
    sf_plot_series(pl, "y = x", SF_STYLE_LINES, M, qx, qx);
    sf_plot_series(pl, "COF samples", SF_STYLE_POINTS, M, qx, qy);
    free(qx); free(qy); free(h); free(v);
    gsl_rng_free(rng);
    sf_lnfield_free(lf);
    return SF_SUCCESS;
}

/* Mean and std of the COF: z tests with the exact sampling variance of the
 * mean (sigma^2/N) and of the variance ((mu4 - sigma^4)/N, lognormal mu4). */
static int chk_moments(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_lnfield *lf;
    int rc = build(c, r, &lf, 0);
    if (rc) { sf_lnfield_free(lf); return rc; }
    size_t idx[64];
    size_t np = sparse_points(s, 6.0 * s->l, idx, 64);
    size_t N = s->samples * np, n = s->nx * s->ny;
    double *h = check_alloc(n * sizeof *h);
    gsl_rng *rng = sf_case_rng(c);
    double s1 = 0, s2 = 0, mu = s->mu_mean, sd = s->mu_std;
    double *run_x = check_alloc(s->samples * sizeof *run_x), *run_m = check_alloc(s->samples * sizeof *run_m);
    double *lo = check_alloc(s->samples * sizeof *lo), *hi = check_alloc(s->samples * sizeof *hi);
    double za = gsl_cdf_ugaussian_Qinv(c->spec.alpha / 4);
    for (size_t k = 0; k < s->samples; k++) {
        sf_lnfield_sample(lf, rng, NULL, h);
        for (size_t q = 0; q < np; q++) {
            double x = h[idx[q]] - mu;   /* centred at the target for stability */
            s1 += x;
            s2 += x * x;
        }
        double cnt = (double)((k + 1) * np);
        run_x[k] = cnt;
        run_m[k] = mu + s1 / cnt;
        lo[k] = mu - za * sd / sqrt(cnt);
        hi[k] = mu + za * sd / sqrt(cnt);
    }
    double Nd = (double)N, mean = mu + s1 / Nd;
    double var = (s2 - s1 * s1 / Nd) / (Nd - 1);
    double w = 1.0 + (sd / mu) * (sd / mu);          /* exp(sigma_g^2) */
    double kurt = w * w * w * w + 2 * w * w * w + 3 * w * w - 3;  /* mu4 / sigma^4 */
    double zm = (mean - mu) / (sd / sqrt(Nd));
    double zv = (var - sd * sd) / sqrt((kurt - 1.0) * pow(sd, 4) / Nd);
    sf_check_pvalue(r, "mean of the COF = target (z test, exact sampling variance)", sf_z_pvalue(zm), c->spec.alpha / 2, N);
    sf_check_pvalue(r, "variance of the COF = target (z test, lognormal fourth moment)", sf_z_pvalue(zv), c->spec.alpha / 2, N);
    sf_note(r, "Sample mean %.6g (target %.6g), sample std %.6g (target %.6g); z = %.3f and %.3f. "
               "alpha split equally over the two tests (Bonferroni).\n", mean, mu, sqrt(var), sd, zm, zv);
    sf_plot *pl = sf_result_plot(r, "running_mean", "Running mean of the COF with its acceptance band",
                                 "number of values [-]", "mean COF [-]");
    sf_plot_log(pl, 1, 0);
    sf_plot_band(pl, "acceptance band (alpha/2)", s->samples, run_x, lo, hi);
    sf_plot_series(pl, "running mean", SF_STYLE_LINES, s->samples, run_x, run_m);
    sf_plot_hline(pl, "target mean", mu);
    free(h); free(run_x); free(run_m); free(lo); free(hi);
    gsl_rng_free(rng);
    sf_lnfield_free(lf);
    return SF_SUCCESS;
}

/* Positivity: every COF value of every field is finite and > 0, for each
 * CV in the sweep (mu_std = CV * mu_mean). */
static int chk_positivity(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    if (c->spec.sweep.n == 0)
        return SF_EINVAL;
    gsl_rng *rng = sf_case_rng(c);
    size_t n = s0->nx * s0->ny, bad = 0, total = 0;
    double *h = check_alloc(n * sizeof *h);
    double *cvs = check_alloc(c->spec.sweep.n * sizeof *cvs), *mins = check_alloc(c->spec.sweep.n * sizeof *mins);
    for (size_t k = 0; k < c->spec.sweep.n; k++) {
        sf_scene s = *s0;
        s.mu_std = c->spec.sweep.v[k] * s0->mu_mean;
        sf_lnfield *lf;
        int rc = sf_lnfield_alloc(&s, &lf);
        if (!sf_usable(rc)) { free(h); gsl_rng_free(rng); return rc; }
        double mn = INFINITY;
        for (size_t j = 0; j < s.samples; j++) {
            sf_lnfield_sample(lf, rng, NULL, h);
            for (size_t i = 0; i < n; i++) {
                total++;
                if (!(h[i] > 0.0) || !isfinite(h[i])) bad++;
                mn = sf_min(mn, h[i]);
            }
        }
        cvs[k] = c->spec.sweep.v[k];
        mins[k] = mn;
        sf_note(r, "CV = %.3g: smallest COF over %zu values = %.4g.", cvs[k], s.samples * n, mn);
        sf_lnfield_free(lf);
    }
    char t[160];
    snprintf(t, sizeof t, "COF values that are <= 0 or not finite (of %zu)", total);
    sf_check_le(r, t, (double)bad, 0.0);
    sf_plot *pl = sf_result_plot(r, "minimum", "Smallest COF value found vs CV", "CV [-]", "min COF [-]");
    sf_plot_log(pl, 1, 1);
    sf_plot_series(pl, "minimum over all samples", SF_STYLE_LINESPOINTS, c->spec.sweep.n, cvs, mins);
    free(h); free(cvs); free(mins);
    gsl_rng_free(rng);
    return SF_SUCCESS;
}

/* Empirical correlation of the COF field along x vs a target: per field,
 * the average over all pairs at lag h of (H_a - mu)(H_b - mu)/sigma^2 is
 * unbiased for rho_H(h); fields are iid, so a t test per lag (Bonferroni
 * over lags).  target = 0: distortion formula of the Gaussian Eq. 2;
 * target = 1: Eq. 2 itself (pre-corrected field). */
static int correlation_check(const sf_case *c, sf_result *r, int target)
{
    const sf_scene *s = &c->scene;
    sf_lnfield *lf;
    int rc = build(c, r, &lf, target);
    if (rc) { sf_lnfield_free(lf); return rc; }
    size_t m = s->nx, ny = s->ny, n = m * ny, N = s->samples;
    /* The expected COF correlation is the distortion of the Gaussian
     * covariance the plan really produces (exact, no sampling). */
    double *cprod = check_alloc(n * sizeof *cprod);
    sf_field_covariance(sf_lnfield_gaussian(lf), cprod);
    size_t H = (size_t)ceil(2.5 * s->l / s->dx);
    if (H > m - 1) H = m - 1;
    if (H < 1) return SF_EINVAL;
    double *h = check_alloc(n * sizeof *h);
    double *a1 = check_alloc((H + 1) * sizeof *a1), *a2 = check_alloc((H + 1) * sizeof *a2);
    gsl_rng *rng = sf_case_rng(c);
    double mu = s->mu_mean, var = s->mu_std * s->mu_std;
    for (size_t k = 0; k < N; k++) {
        sf_lnfield_sample(lf, rng, NULL, h);
        for (size_t d = 0; d <= H; d++) {
            double sum = 0;
            size_t cnt = 0;
            for (size_t j = 0; j < ny; j++)
                for (size_t i = 0; i + d < m; i++, cnt++)
                    sum += (h[i + m * j] - mu) * (h[i + d + m * j] - mu);
            double v = sum / (double)cnt / var;
            a1[d] += v;
            a2[d] += v * v;
        }
    }
    ref_ln_par par = ref_lognormal_par(s->mu_mean, s->mu_std);
    double pmin = 1, worst = 0, maxdist = 0, gap_target = 0;
    double *x = check_alloc((H + 1) * sizeof *x), *em = check_alloc((H + 1) * sizeof *em);
    double *ex = check_alloc((H + 1) * sizeof *ex), *rg = check_alloc((H + 1) * sizeof *rg);
    double *lo = check_alloc((H + 1) * sizeof *lo), *hi = check_alloc((H + 1) * sizeof *hi);
    double tq = gsl_cdf_tdist_Qinv(c->spec.alpha / 2 / (double)H, (double)N - 1);
    for (size_t d = 0; d <= H; d++) {
        x[d] = (double)d * s->dx;
        double rg_ = ref_sq_exp(x[d], 0, s->l);
        rg[d] = rg_;
        ex[d] = ref_rho_h(par.sigma, cprod[d]);
        if (target) gap_target = sf_max(gap_target, fabs(ex[d] - rg_));
        em[d] = a1[d] / (double)N;
        double se = sqrt((a2[d] / (double)N - em[d] * em[d]) / ((double)N - 1));
        lo[d] = em[d] - tq * se;
        hi[d] = em[d] + tq * se;
        maxdist = sf_max(maxdist, fabs(ex[d] - rg_));
        if (d == 0)
            continue;   /* lag 0 is the variance: tested in lognormal/moments */
        double tstat = (em[d] - ex[d]) / se;
        double pv = 2 * gsl_cdf_tdist_Q(fabs(tstat), (double)N - 1);
        if (!(pv >= pmin) && !isnan(pmin)) worst = x[d];   /* a NaN is the worst */
        pmin = sf_min(pmin, pv);
    }
    char t[200];
    snprintf(t, sizeof t, "empirical COF correlation = distortion of the produced Gaussian covariance "
             "at %zu lags (t test, Bonferroni; worst lag %.3g m)", H, worst);
    sf_check_pvalue(r, t, sf_min(1.0, pmin * (double)H), c->spec.alpha, N);
    if (target) {
        /* The claim: pre-correction removes the Nataf distortion, up to what
         * clamping the indefinite kernel costs.  Lipschitz bound of the
         * distortion on [-1, 1 + err] (clamping negatives adds mass, so the
         * produced variance is up to 1 + err):
         * |d rho_H/d rho_G| <= s^2 e^{s^2 (1 + err)}/(e^{s^2} - 1). */
        const sf_field_info *gi = sf_field_get_info(sf_lnfield_gaussian(lf));
        double s2 = par.sigma * par.sigma, raw = 0;
        double lip = s2 * exp(s2 * (1 + gi->cov_error)) / expm1(s2);
        for (int i = 0; i <= 200; i++)
            raw = sf_max(raw, i / 200.0 - ref_rho_h(par.sigma, i / 200.0));
        sf_check_le(r, "residual |rho_H - Eq. 2| / uncorrected Nataf distortion", gap_target / raw, c->spec.tolerance);
        sf_check_le(r, "residual |rho_H - Eq. 2| vs Lipschitz bound from the reported clamping error",
                    gap_target, lip * gi->cov_error * (1 + 1e-9) + 1e-14);
        sf_note(r, "Uncorrected distortion at this CV: %.4g; residual after pre-correction: %.4g "
                   "(%.1f%% of it). The pre-corrected squared-exponential kernel is not positive definite: "
                   "its spectrum goes negative at high frequency (relative size %.3g here), so padding "
                   "cannot help and the plan clamps (nearest PSD circulant) and reports the error.\n",
                raw, gap_target, 100 * gap_target / raw, -gi->lambda_min / gi->lambda_max);
        /* the plan's Gaussian kernel against the oracle's own pre-correction */
        double kerr = 0, e2 = expm1(par.sigma * par.sigma);
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < m; i++) {
                double rho = ref_sq_exp((double)i * s->dx, (double)j * s->dy, s->l);
                double want = log1p(rho * e2) / (par.sigma * par.sigma);
                kerr = sf_max(kerr, fabs(sf_field_target(sf_lnfield_gaussian(lf), (double)i * s->dx,
                                                        (double)j * s->dy) - want));
            }
        sf_check_le(r, "plan's pre-corrected Gaussian kernel vs inverse distortion of Eq. 2", kerr, 1e-13);
    }
    sf_note(r, "CV = %.3g, sigma_g = %.4f: largest gap between rho_H and rho_G over these lags = %.4f.\n",
            s->mu_std / s->mu_mean, par.sigma, maxdist);
    sf_plot *pl = sf_result_plot(r, "correlation", "COF correlation along x: empirical vs expected",
                                 "lag [m]", "correlation [-]");
    sf_plot_band(pl, "empirical, Bonferroni t interval", H + 1, x, lo, hi);
    sf_plot_series(pl, target ? "target Eq. 2" : "expected: distortion of Eq. 2", SF_STYLE_LINES, H + 1, x, ex);
    if (!target)
        sf_plot_series(pl, "Gaussian correlation Eq. 2 (undistorted)", SF_STYLE_LINES, H + 1, x, rg);
    sf_plot_series(pl, "empirical mean", SF_STYLE_POINTS, H + 1, x, em);
    free(h); free(a1); free(a2); free(x); free(em); free(ex); free(rg); free(lo); free(hi); free(cprod);
    gsl_rng_free(rng);
    sf_lnfield_free(lf);
    return SF_SUCCESS;
}

static int chk_correlation(const sf_case *c, sf_result *r) { return correlation_check(c, r, 0); }
static int chk_precorrected(const sf_case *c, sf_result *r) { return correlation_check(c, r, 1); }

/* E[H1 H2] for corr(G1, G2) = rho by one numerical integral over G1 (the
 * inner expectation over G2 | G1 is a lognormal mean): an oracle for the
 * distortion that shares no formula with the solver. */
typedef struct { double mu, s, rho; } pair_par;

static double pair_integrand(double z, void *p)
{
    const pair_par *q = p;
    double inner = exp(q->mu + q->s * q->rho * z + 0.5 * q->s * q->s * (1 - q->rho * q->rho));
    return gsl_ran_ugaussian_pdf(z) * exp(q->mu + q->s * z) * inner;
}

/* Integral over z in [-40, 40] (the normal tail beyond is < 1e-300) by
 * GSL's CQUAD; NaN when it does not converge, so the row fails. */
static double cquad(gsl_function *F, gsl_integration_cquad_workspace *ws)
{
    double val, err;
    size_t nev;
    if (gsl_integration_cquad(F, -40, 40, 0, 1e-13, ws, &val, &err, &nev))
        return NAN;
    return val;
}

static double numeric_rho_h(double mean, double std, double rho, gsl_integration_cquad_workspace *ws)
{
    ref_ln_par par = ref_lognormal_par(mean, std);
    pair_par q = { par.mu, par.sigma, rho };
    gsl_function F = { pair_integrand, &q };
    return (cquad(&F, ws) - mean * mean) / (std * std);
}

/* The paper's claim: Nataf distortion negligible for CV < 0.3 [48].
 * Quantified: max over rho of |rho_H - rho_G| per CV, the solver's
 * formula checked against numerical integration, and the claim checked at
 * CV = 0.3 against the tolerance. */
static int chk_distortion_claim(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (c->spec.sweep.n == 0)
        return SF_EINVAL;
    gsl_integration_cquad_workspace *ws = gsl_integration_cquad_workspace_alloc(200);
    size_t K = c->spec.sweep.n;
    double *cv = check_alloc(K * sizeof *cv), *md = check_alloc(K * sizeof *md), *lc = check_alloc(K * sizeof *lc);
    double worst_formula = 0, at_claim = -1;
    sf_note(r, "| CV | sigma_g | max of rho_G - rho_H | at rho_G | 1/e correlation length, lognormal / Gaussian |\n|---|---|---|---|---|");
    for (size_t k = 0; k < K; k++) {
        sf_lognormal ln;
        double mean = s->mu_mean, std = c->spec.sweep.v[k] * mean;
        if (sf_lognormal_init(&ln, mean, std)) { gsl_integration_cquad_workspace_free(ws); return SF_EINVAL; }
        double best = 0, at = 0;
        for (int i = 0; i <= 200; i++) {
            double rho = i / 200.0;
            double d = rho - sf_lognormal_rho_h(&ln, rho);
            if (!(d <= best) && !isnan(best)) at = rho;
            best = sf_max(best, d);
            if (i % 20 == 0) {
                double e = fabs(sf_lognormal_rho_h(&ln, rho) - numeric_rho_h(mean, std, rho, ws));
                worst_formula = sf_max(worst_formula, e);
            }
        }
        /* correlation length at 1/e: Gaussian r = l; lognormal solves rho_H(exp(-r^2/l^2)) = 1/e */
        double rg = sf_lognormal_rho_g(&ln, exp(-1.0));
        double ratio = sqrt(-log(rg));   /* r/l where the lognormal correlation is 1/e */
        cv[k] = c->spec.sweep.v[k];
        md[k] = best;
        lc[k] = ratio;
        if (fabs(cv[k] - 0.3) < 1e-12) at_claim = best;
        sf_note(r, "| %.3g | %.4f | %.5f | %.3f | %.5f |", cv[k], ln.sigma_g, best, at, ratio);
    }
    sf_check_le(r, "solver's distortion formula vs numerical integration (max abs)", worst_formula, 1e-9);
    if (at_claim < 0) { gsl_integration_cquad_workspace_free(ws); return SF_EINVAL; }
    sf_check_le(r, "max |rho_H - rho_G| at CV = 0.3 (the paper's 'negligible' bound)", at_claim, c->spec.tolerance);
    sf_note(r, "\nReading: at CV = 0.2 (Table 1) the lognormal correlation is at most %.4f below the Gaussian "
               "one; at CV = 1 the gap is ~0.08 and the 1/e correlation length shrinks by a few percent. "
               "'Negligible' holds at the 1e-2 level for CV <= 0.3.\n", md[K > 1 ? 1 : 0]);
    sf_plot *pl = sf_result_plot(r, "distortion", "Nataf correlation distortion vs CV",
                                 "CV [-]", "max |rho_H - rho_G| [-]");
    sf_plot_log(pl, 1, 1);
    sf_plot_series(pl, "max over rho_G in [0, 1]", SF_STYLE_LINESPOINTS, K, cv, md);
    sf_plot_hline(pl, "tolerance at CV = 0.3", c->spec.tolerance);
    free(cv); free(md); free(lc);
    gsl_integration_cquad_workspace_free(ws);
    return SF_SUCCESS;
}

/* Nataf map round trip: E[H] and sd[H] of exp(mu_g + sigma_g G) by
 * numerical integration equal the targets; the distortion's inverse is
 * its inverse.  Over the CVs of the sweep. */
/* power 1: E[H]; power 2: E[(H - centre)^2], centred at the target mean
 * so the small-CV variance is not lost to cancellation. */
typedef struct { double mu, s, centre; int power; } mom_par;

static double mom_integrand(double z, void *p)
{
    const mom_par *q = p;
    double h = exp(q->mu + q->s * z);
    return gsl_ran_ugaussian_pdf(z) * (q->power == 1 ? h : (h - q->centre) * (h - q->centre));
}

static int chk_map_roundtrip(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (c->spec.sweep.n == 0)
        return SF_EINVAL;
    gsl_integration_cquad_workspace *ws = gsl_integration_cquad_workspace_alloc(200);
    double wm = 0, ws_ = 0, wr = 0;
    size_t K = c->spec.sweep.n;
    double *cv = check_alloc(K * sizeof *cv), *em = check_alloc(K * sizeof *em), *es = check_alloc(K * sizeof *es);
    for (size_t k = 0; k < K; k++) {
        double mean = s->mu_mean, std = c->spec.sweep.v[k] * mean;
        sf_lognormal ln;
        if (sf_lognormal_init(&ln, mean, std)) { gsl_integration_cquad_workspace_free(ws); return SF_EINVAL; }
        double m1, m2;
        mom_par q = { ln.mu_g, ln.sigma_g, mean, 1 };
        gsl_function F = { mom_integrand, &q };
        m1 = cquad(&F, ws);
        q.power = 2;
        m2 = cquad(&F, ws);
        /* E[(H - mean)^2] = var + (m1 - mean)^2 */
        double sd = sqrt(sf_max(0.0, m2 - (m1 - mean) * (m1 - mean)));
        cv[k] = c->spec.sweep.v[k];
        em[k] = fabs(m1 - mean) / mean;
        es[k] = std > 0 ? fabs(sd - std) / std : sd;
        /* not fmax: it drops NaN, and a NaN must fail the row */
        wm = sf_max(wm, em[k]);
        ws_ = sf_max(ws_, es[k]);
        for (int i = -10; i <= 10; i++) {
            double rho = i / 10.0;
            wr = sf_max(wr, fabs(sf_lognormal_rho_g(&ln, sf_lognormal_rho_h(&ln, rho)) - rho));
        }
        sf_note(r, "CV = %.3g: mu_g = %.6f, sigma_g = %.6f, E[H] = %.12g, sd[H] = %.12g.", c->spec.sweep.v[k],
                ln.mu_g, ln.sigma_g, m1, sd);
    }
    sf_check_le(r, "max relative error of E[H] vs the target mean", wm, c->spec.tolerance);
    sf_check_le(r, "max relative error of sd[H] vs the target std", ws_, c->spec.tolerance);
    sf_check_le(r, "max |rho_G(rho_H(rho)) - rho| over rho in [-1, 1]", wr, c->spec.tolerance);
    sf_plot *pl = sf_result_plot(r, "roundtrip", "Nataf map: moments of exp(mu_g + sigma_g G) vs targets",
                                 "CV [-]", "relative error [-]");
    sf_plot_log(pl, 1, 1);
    sf_plot_series(pl, "E[H] vs target mean", SF_STYLE_LINESPOINTS, K, cv, em);
    sf_plot_series(pl, "sd[H] vs target std", SF_STYLE_LINESPOINTS, K, cv, es);
    sf_plot_hline(pl, "tolerance", c->spec.tolerance);
    free(cv); free(em); free(es);
    gsl_integration_cquad_workspace_free(ws);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_lognormal[] = {
    { "lognormal_marginal_ks", chk_marginal_ks, "KS test of the COF marginal against the exact lognormal CDF" },
    { "lognormal_moments", chk_moments, "mean and std of the COF within exact confidence bounds" },
    { "lognormal_positivity", chk_positivity, "every COF value finite and positive across CVs" },
    { "lognormal_correlation", chk_correlation, "empirical COF correlation vs the distortion formula" },
    { "lognormal_precorrected", chk_precorrected, "pre-corrected field hits the target correlation" },
    { "lognormal_distortion_claim", chk_distortion_claim, "the paper's 'negligible for CV < 0.3', quantified" },
    { "lognormal_map_roundtrip", chk_map_roundtrip, "Nataf parameters reproduce mean and std; distortion inverse" },
    { NULL, NULL, NULL }
};
