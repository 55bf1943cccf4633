/* Checks of the Gaussian random-field generator (circulant embedding,
 * paper Appendix A).  Oracles are written here independently of the
 * solver: Eq. 2 itself, direct (non-FFT) DFT sums, GSL Cholesky. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "field.h"
#include "scene.h"
#include "sf_error.h"
#include "tiles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_sort.h>

/* Exact Sigma of the m x n grid (the oracle): p x p, p = m n. */
static gsl_matrix *exact_sigma(const sf_scene *s)
{
    size_t m = s->nx, n = s->ny, p = m * n;
    gsl_matrix *S = gsl_matrix_alloc(p, p);
    for (size_t a = 0; a < p; a++)
        for (size_t b = 0; b < p; b++) {
            double hx = ((double)(a % m) - (double)(b % m)) * s->dx;
            double hy = ((double)(a / m) - (double)(b / m)) * s->dy;
            gsl_matrix_set(S, a, b, ref_sq_exp(hx, hy, s->l));
        }
    return S;
}

/* Plot produced vs exact correlation along both axes, and |error|. */
static void plot_cov(sf_result *r, const sf_case *c, const double *cov)
{
    const sf_scene *s = &c->scene;
    size_t m = s->nx, n = s->ny;
    double *x = check_alloc(m * sizeof *x), *yc = check_alloc(m * sizeof *yc), *ye = check_alloc(m * sizeof *ye);
    double *x2 = check_alloc(n * sizeof *x2), *yc2 = check_alloc(n * sizeof *yc2);
    double *e = check_alloc(m * sizeof *e);
    for (size_t i = 0; i < m; i++) {
        x[i] = (double)i * s->dx;
        yc[i] = cov[i];
        ye[i] = ref_sq_exp(x[i], 0, s->l);
        e[i] = fabs(yc[i] - ye[i]);
    }
    for (size_t j = 0; j < n; j++) {
        x2[j] = (double)j * s->dy;
        yc2[j] = cov[m * j];
    }
    sf_plot *p = sf_result_plot(r, "covariance", "Produced covariance vs Eq. 2 along the grid axes",
                                "lag [m]", "correlation [-]");
    sf_plot_series(p, "exact exp(-r^2/l^2)", SF_STYLE_LINES, m, x, ye);
    sf_plot_series(p, "produced, x lags", SF_STYLE_POINTS, m, x, yc);
    sf_plot_series(p, "produced, y lags", SF_STYLE_POINTS, n, x2, yc2);
    sf_plot *q = sf_result_plot(r, "covariance_error", "Produced covariance error along x",
                                "lag [m]", "|C - Sigma| [-]");
    sf_plot_log(q, 0, 1);
    sf_plot_series(q, "|C - Sigma|", SF_STYLE_LINESPOINTS, m, x, e);
    if (c->spec.tolerance > 0)
        sf_plot_hline(q, "tolerance", c->spec.tolerance);
    free(x); free(yc); free(ye); free(x2); free(yc2); free(e);
}

/* Produced covariance (no sampling) vs Sigma at every grid lag. */
static int chk_exact_covariance(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_field *f;
    int rc = check_field_plan(c, r, &f);
    if (!sf_usable(rc))
        return rc;
    double *cov = check_alloc(s->nx * s->ny * sizeof *cov);
    sf_field_covariance(f, cov);
    double err = 0.0;
    for (size_t j = 0; j < s->ny; j++)
        for (size_t i = 0; i < s->nx; i++) {
            double e = fabs(cov[i + s->nx * j] - ref_sq_exp((double)i * s->dx, (double)j * s->dy, s->l));
            err = sf_max(err, e);
        }
    sf_check_le(r, "max |C_produced - Sigma| over grid lags", err, c->spec.tolerance);
    sf_check_abs(r, "error reported by the plan vs recomputed here", sf_field_get_info(f)->cov_error, err,
                 1e-15 + 1e-12 * err);
    plot_cov(r, c, cov);
    free(cov);
    sf_field_free(f);
    return SF_SUCCESS;
}

/* The fields a statistical check samples: the circulant plan of the
 * scene, or (cof_generator = tiles) the tiled generator on a lattice of
 * spacing dx/sx, dy/sy (sx, sy the smallest integers that make it at most
 * l/4, where its produced covariance is Eq. 2 to round-off), read every
 * sx-th column and sy-th row: an nx x ny patch whose columns straddle
 * the seam between noise tiles -1 and 0 (lattice column 0), one new key
 * per field drawn from the case's stream. */
typedef struct {
    sf_field *f;
    sf_tiles *t;
    size_t m, n, sx, sy, lm, ln;   /* patch, subsampling, lattice patch */
    long i0;
    double *buf;
} field_src;

static int src_open(const sf_case *c, sf_result *r, field_src *src)
{
    const sf_scene *s = &c->scene;
    memset(src, 0, sizeof *src);
    src->m = s->nx;
    src->n = s->ny;
    if (s->cof_generator != SF_COFGEN_TILES) {
        int rc = check_field_plan(c, r, &src->f);
        return rc == SF_ETRUNC ? SF_EFAIL : rc;
    }
    src->sx = (size_t)ceil(4 * s->dx / s->l - 1e-12);
    src->sy = (size_t)ceil(4 * s->dy / s->l - 1e-12);
    src->lm = (s->nx - 1) * src->sx + 1;
    src->ln = (s->ny - 1) * src->sy + 1;
    src->i0 = -(long)(src->lm / 2);
    sf_tiles_spec ts = { src->ln, s->dx / (double)src->sx, s->dy / (double)src->sy, s->l, 0, 0 };
    int rc = sf_tiles_alloc(&ts, &src->t);
    if (rc)
        return rc;
    src->buf = check_alloc(src->lm * src->ln * sizeof *src->buf);
    size_t K;
    sf_tiles_weights(src->t, 0, &K);
    sf_note(r, "Tiled generator: lattice %.4g x %.4g m (every %zu-th column, %zu-th row read), kernel half-width %zu "
               "columns, %zu-column noise tiles; the patch spans lattice columns %ld..%ld (a tile seam at 0); one "
               "key per field.\n",
            ts.dx, ts.dy, src->sx, src->sy, K, sf_tiles_tile_cols(src->t), src->i0, src->i0 + (long)src->lm - 1);
    return SF_SUCCESS;
}

static uint64_t draw_key(gsl_rng *rng)
{
    uint64_t key = (uint64_t)gsl_rng_get(rng) << 32;
    return key ^ (uint64_t)gsl_rng_get(rng);
}

/* The circulant path draws through check_field_sample, so a power run's
 * generator-only alternatives reach it; the tiled path has no
 * alternative yet (its cases name no power_alt). */
static void src_sample(const sf_case *c, field_src *src, gsl_rng *rng, double *g)
{
    if (src->f) {
        check_field_sample(c, src->f, rng, g, src->m * src->n);
        return;
    }
    sf_tiles_set_key(src->t, draw_key(rng));
    sf_tiles_fill(src->t, src->i0, src->lm, src->buf, src->lm);
    for (size_t j = 0; j < src->n; j++)
        for (size_t i = 0; i < src->m; i++)
            g[i + src->m * j] = src->buf[i * src->sx + src->lm * j * src->sy];
}

static void src_close(field_src *src)
{
    sf_field_free(src->f);
    sf_tiles_free(src->t);
    free(src->buf);
}

/* Eigenvalues by FFTW vs direct DFT sums (independent of FFTW). */
static int chk_eigen_direct(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_field *f;
    int rc = check_field_plan(c, r, &f);
    if (!sf_usable(rc))
        return rc;
    const sf_field_info *in = sf_field_get_info(f);
    size_t M = in->px * in->py;
    double *a = check_alloc(M * sizeof *a), *b = check_alloc(M * sizeof *b);
    sf_field_eigenvalues(f, a);
    ref_eigenvalues(in->px, in->py, s->dx, s->dy, s->l, b);
    double err = 0.0, mx = 0.0;
    for (size_t k = 0; k < M; k++) {
        err = sf_max(err, fabs(a[k] - b[k]));
        mx = sf_max(mx, fabs(b[k]));
    }
    sf_check_le(r, "max |lambda_FFT - lambda_direct| / max |lambda|", err / mx, c->spec.tolerance);
    /* the spectrum, sorted, for the plot */
    double *idx = check_alloc(M * sizeof *idx);
    for (size_t k = 0; k < M; k++) {
        idx[k] = (double)k;
        b[k] = fabs(b[k]) / mx;
    }
    memcpy(a, b, M * sizeof *a);
    gsl_sort(a, 1, M);
    for (size_t k = 0; k < M / 2; k++) {
        double t = a[k]; a[k] = a[M - 1 - k]; a[M - 1 - k] = t;
    }
    sf_plot *p = sf_result_plot(r, "spectrum", "Embedding eigenvalues (direct DFT), sorted",
                                "rank", "|lambda| / lambda_max [-]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "|lambda| / lambda_max", SF_STYLE_LINES, M, idx, a);
    free(a); free(b); free(idx);
    sf_field_free(f);
    return SF_SUCCESS;
}

/* Truncated embedding: the error the plan reports must be the error of
 * the covariance it really produces, recomputed here by direct DFTs. */
static int chk_truncation_reported(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_field *f;
    int rc = check_field_plan(c, r, &f);
    if (!sf_usable(rc))
        return rc;
    const sf_field_info *in = sf_field_get_info(f);
    size_t M = in->px * in->py, m = s->nx, n = s->ny;
    double *lam = check_alloc(M * sizeof *lam), *cov = check_alloc(m * n * sizeof *cov);
    ref_eigenvalues(in->px, in->py, s->dx, s->dy, s->l, lam);
    ref_produced_cov(lam, in->px, in->py, m, n, cov);
    double err = 0.0;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < m; i++) {
            double e = fabs(cov[i + m * j] - ref_sq_exp((double)i * s->dx, (double)j * s->dy, s->l));
            err = sf_max(err, e);
        }
    sf_check_true(r, "the plan says it truncated (SF_ETRUNC)", rc == SF_ETRUNC && in->truncated,
                  rc == SF_ETRUNC ? "SF_ETRUNC returned" : "no truncation reported");
    sf_check_rel(r, "reported covariance error vs direct recomputation", in->cov_error, err, c->spec.tolerance);
    sf_check_ge(r, "true covariance error (must be visible, not round-off)", err, 1e-10);
    sf_note(r, "True max |C - Sigma| of the truncated embedding: %.6g (plan reports %.6g).\n", err, in->cov_error);
    plot_cov(r, c, cov);
    free(lam); free(cov);
    sf_field_free(f);
    return SF_SUCCESS;
}

/* Sampled covariance vs Sigma: whiten with the exact Cholesky factor and
 * test S = (1/N) sum z z^T = I by the likelihood-ratio statistic
 * N (tr S - ln det S - p) ~ chi2(p(p+1)/2) (known mean; Bartlett factor). */
static int chk_sampled_covariance(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t m = s->nx, n = s->ny, p = m * n, N = s->samples;
    if (p > 400)
        return SF_EINVAL;
    field_src f;
    int rc = src_open(c, r, &f);
    if (rc) {
        src_close(&f);
        return rc;
    }
    check_wlrt lrt;
    if (check_wlrt_init(&lrt, exact_sigma(s))) {
        src_close(&f);
        return SF_EFAIL;
    }
    gsl_rng *rng = sf_case_rng(c);
    size_t H = m > 1 ? m : 2;
    double *acc = check_alloc(H * sizeof *acc), *acc2 = check_alloc(H * sizeof *acc2);
    double *g = check_alloc(p * sizeof *g);
    for (size_t k = 0; k < N; k++) {
        src_sample(c, &f, rng, g);
        /* empirical correlation along x, per sample (for the plot) */
        for (size_t h = 0; h < m; h++) {
            double sum = 0;
            size_t cnt = 0;
            for (size_t j = 0; j < n; j++)
                for (size_t i = 0; i + h < m; i++, cnt++)
                    sum += g[i + m * j] * g[i + h + m * j];
            double v = sum / (double)cnt;
            acc[h] += v;
            acc2[h] += v * v;
        }
        check_wlrt_add(&lrt, g);
    }
    double stat, trp, pd = (double)p, Nd = (double)N;
    double pval = check_wlrt_done(&lrt, &stat, &trp);
    double dof = pd * (pd + 1) / 2;
    char t[160];
    snprintf(t, sizeof t, "whitened LRT of Cov = Sigma (p = %zu points, chi2 dof %.0f)", p, dof);
    sf_check_pvalue(r, t, pval, c->spec.alpha, N);
    sf_note(r, "LRT statistic %.2f on %.0f degrees of freedom (mean %.0f, sd %.1f under the null); "
               "tr(S)/p = %.5f.\n", stat, dof, dof, sqrt(2 * dof), trp);
    /* plot: empirical correlation with a 3-sigma band from the per-sample spread */
    double *x = check_alloc(m * sizeof *x), *mean = check_alloc(m * sizeof *mean);
    double *lo = check_alloc(m * sizeof *lo), *hi = check_alloc(m * sizeof *hi), *ex = check_alloc(m * sizeof *ex);
    for (size_t h = 0; h < m; h++) {
        x[h] = (double)h * s->dx;
        mean[h] = acc[h] / Nd;
        double var = (acc2[h] / Nd - mean[h] * mean[h]) / Nd;
        lo[h] = mean[h] - 3 * sqrt(var > 0 ? var : 0);
        hi[h] = mean[h] + 3 * sqrt(var > 0 ? var : 0);
        ex[h] = ref_sq_exp(x[h], 0, s->l);
    }
    sf_plot *pl = sf_result_plot(r, "empirical_correlation", "Sampled correlation along x vs Eq. 2",
                                 "lag [m]", "correlation [-]");
    sf_plot_band(pl, "empirical +-3 standard errors", m, x, lo, hi);
    sf_plot_series(pl, "exact exp(-r^2/l^2)", SF_STYLE_LINES, m, x, ex);
    sf_plot_series(pl, "empirical mean", SF_STYLE_POINTS, m, x, mean);
    free(x); free(mean); free(lo); free(hi); free(ex);
    free(acc); free(acc2); free(g);
    gsl_rng_free(rng);
    src_close(&f);
    return SF_SUCCESS;
}

/* Per-point mean 0 and variance 1: Bonferroni over the grid points for
 * the mean (z test) and the variance (chi-square, known mean). */
static int chk_pointwise_moments(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t p = s->nx * s->ny, N = s->samples;
    field_src f;
    int rc = src_open(c, r, &f);
    if (rc) {
        src_close(&f);
        return rc;
    }
    gsl_rng *rng = sf_case_rng(c);
    double *g = check_alloc(p * sizeof *g), *s1 = check_alloc(p * sizeof *s1), *s2 = check_alloc(p * sizeof *s2);
    for (size_t k = 0; k < N; k++) {
        src_sample(c, &f, rng, g);
        for (size_t a = 0; a < p; a++) {
            s1[a] += g[a];
            s2[a] += g[a] * g[a];
        }
    }
    double pmin_mean = 1, pmin_var = 1, zmax = 0, vworst = 1;
    double *idx = check_alloc(p * sizeof *idx), *mu = check_alloc(p * sizeof *mu), *va = check_alloc(p * sizeof *va);
    for (size_t a = 0; a < p; a++) {
        double mean = s1[a] / (double)N, var = s2[a] / (double)N;
        double z = mean * sqrt((double)N);
        double pm = sf_z_pvalue(z), pv = sf_var_pvalue(var, 1.0, N, 1);
        pmin_mean = sf_min(pmin_mean, pm);
        if (!(pv >= pmin_var) && !isnan(pmin_var)) vworst = var;   /* a NaN is the most extreme */
        pmin_var = sf_min(pmin_var, pv);
        zmax = sf_max(zmax, fabs(z));
        idx[a] = (double)a;
        mu[a] = mean;
        va[a] = var;
    }
    double pm_adj = sf_min(1.0, pmin_mean * (double)p), pv_adj = sf_min(1.0, pmin_var * (double)p);
    char t[160];
    snprintf(t, sizeof t, "mean = 0 at every point (z test, Bonferroni over %zu points)", p);
    sf_check_pvalue(r, t, pm_adj, c->spec.alpha / 2, N);
    snprintf(t, sizeof t, "variance = 1 at every point (chi-square, Bonferroni over %zu points)", p);
    sf_check_pvalue(r, t, pv_adj, c->spec.alpha / 2, N);
    sf_note(r, "Largest |z| of a point mean: %.3f; most extreme point variance: %.4f. "
               "alpha is split equally between the two families (Bonferroni).\n", zmax, vworst);
    double zc = gsl_cdf_ugaussian_Qinv(c->spec.alpha / 4 / (double)p) / sqrt((double)N);
    sf_plot *pl = sf_result_plot(r, "moments", "Per-point sample mean and variance",
                                 "grid point index [-]", "value [-]");
    double *lo = check_alloc(p * sizeof *lo), *hi = check_alloc(p * sizeof *hi);
    for (size_t a = 0; a < p; a++) { lo[a] = -zc; hi[a] = zc; }
    sf_plot_band(pl, "mean acceptance band", p, idx, lo, hi);
    double vlo = gsl_cdf_chisq_Pinv(c->spec.alpha / 4 / (double)p, (double)N) / (double)N;
    double vhi = gsl_cdf_chisq_Qinv(c->spec.alpha / 4 / (double)p, (double)N) / (double)N;
    for (size_t a = 0; a < p; a++) { lo[a] = vlo; hi[a] = vhi; }
    sf_plot_band(pl, "variance acceptance band", p, idx, lo, hi);
    sf_plot_series(pl, "sample mean", SF_STYLE_POINTS, p, idx, mu);
    sf_plot_series(pl, "sample variance", SF_STYLE_POINTS, p, idx, va);
    free(lo); free(hi); free(idx); free(mu); free(va);
    free(g); free(s1); free(s2);
    gsl_rng_free(rng);
    src_close(&f);
    return SF_SUCCESS;
}

/* Re and Im of one FFT are independent: sample correlation between the
 * two fields at the same point and at lags along x, Fisher z test,
 * Bonferroni over the pairs tested. */
static int chk_re_im_independence(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t m = s->nx, n = s->ny, p = m * n, N = s->samples;
    size_t nl = m < 4 ? m : 4;          /* lags 0..3 along x */
    size_t npts = p < 16 ? p : 16;       /* reference points */
    sf_field *f;
    int rc = check_field_plan(c, r, &f);
    if (rc)
        return rc == SF_ETRUNC ? SF_EFAIL : rc;
    gsl_rng *rng = sf_case_rng(c);
    double *re = check_alloc(p * sizeof *re), *im = check_alloc(p * sizeof *im);
    size_t T = npts * nl;
    double *sxy = check_alloc(T * sizeof *sxy), *sxx = check_alloc(T * sizeof *sxx), *syy = check_alloc(T * sizeof *syy);
    for (size_t k = 0; k < N; k++) {
        check_field_sample_pair(c, f, rng, re, im, p);
        for (size_t q = 0; q < npts; q++) {
            size_t a = (q * (p / npts)) % p;
            for (size_t h = 0; h < nl; h++) {
                size_t b = (a % m) + h < m ? a + h : a - h;
                size_t t = q * nl + h;
                sxy[t] += re[a] * im[b];
                sxx[t] += re[a] * re[a];
                syy[t] += im[b] * im[b];
            }
        }
    }
    double pmin = 1, rmax = 0;
    double *lag = check_alloc(T * sizeof *lag), *rho = check_alloc(T * sizeof *rho);
    for (size_t t = 0; t < T; t++) {
        double rr = sxy[t] / sqrt(sxx[t] * syy[t]);
        double z = atanh(rr) * sqrt((double)N - 3.0);
        double pv = sf_z_pvalue(z);
        pmin = sf_min(pmin, pv);
        rmax = sf_max(rmax, fabs(rr));
        lag[t] = (double)t;
        rho[t] = rr;
    }
    char tt[160];
    snprintf(tt, sizeof tt, "corr(Re, Im) = 0 at %zu point pairs (Fisher z, Bonferroni)", T);
    sf_check_pvalue(r, tt, sf_min(1.0, pmin * (double)T), c->spec.alpha, N);
    sf_note(r, "Largest |sample correlation| between the real and imaginary fields: %.4f "
               "(1/sqrt(N) = %.4f).\n", rmax, 1 / sqrt((double)N));
    double zc = tanh(gsl_cdf_ugaussian_Qinv(c->spec.alpha / 2 / (double)T) / sqrt((double)N - 3.0));
    double *lo = check_alloc(T * sizeof *lo), *hi = check_alloc(T * sizeof *hi);
    for (size_t t = 0; t < T; t++) { lo[t] = -zc; hi[t] = zc; }
    sf_plot *pl = sf_result_plot(r, "re_im_correlation", "Sample correlation between real and imaginary fields",
                                 "pair index (point x lag) [-]", "correlation [-]");
    sf_plot_band(pl, "acceptance band", T, lag, lo, hi);
    sf_plot_series(pl, "corr(Re(a), Im(b))", SF_STYLE_POINTS, T, lag, rho);
    free(lo); free(hi); free(lag); free(rho);
    free(re); free(im); free(sxy); free(sxx); free(syy);
    gsl_rng_free(rng);
    sf_field_free(f);
    return SF_SUCCESS;
}

static double chisq_cdf(double x, void *params)
{
    return gsl_cdf_chisq_P(x, *(double *)params);
}

/* Agreement in distribution with a direct Cholesky sampler (GSL) on the
 * same small grid: two-sample KS on a point value, a neighbour contrast
 * and the Mahalanobis norm, plus one-sample KS of the embedding sampler's
 * Mahalanobis norm against chi2(p).  Bonferroni over the four tests. */
static int chk_cholesky_agreement(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t m = s->nx, n = s->ny, p = m * n, N = s->samples;
    if (p > 400 || p < 2)
        return SF_EINVAL;
    field_src f;
    int rc = src_open(c, r, &f);
    if (rc) {
        src_close(&f);
        return rc;
    }
    gsl_matrix *L = exact_sigma(s);
    if (gsl_linalg_cholesky_decomp1(L)) {
        gsl_matrix_free(L);
        src_close(&f);
        return SF_EFAIL;
    }
    gsl_rng *rng = sf_case_rng(c);
    gsl_rng *rng2 = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng2, s->seed + 7919);
    gsl_vector *v = gsl_vector_alloc(p), *w = gsl_vector_alloc(p);
    double *stat[2][3];
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 3; b++)
            stat[a][b] = check_alloc(N * sizeof(double));
    double *g = check_alloc(p * sizeof *g);
    size_t mid = p / 2;
    for (size_t k = 0; k < N; k++) {
        for (int src = 0; src < 2; src++) {
            if (src == 0) {
                src_sample(c, &f, rng, g);
            } else {
                for (size_t a = 0; a < p; a++)
                    gsl_vector_set(w, a, gsl_ran_gaussian(rng2, 1.0));
                gsl_blas_dtrmv(CblasLower, CblasNoTrans, CblasNonUnit, L, w);
                for (size_t a = 0; a < p; a++)
                    g[a] = gsl_vector_get(w, a);
            }
            for (size_t a = 0; a < p; a++)
                gsl_vector_set(v, a, g[a]);
            gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, L, v);
            double q;
            gsl_blas_ddot(v, v, &q);
            stat[src][0][k] = g[mid];
            stat[src][1][k] = g[0] - g[1];
            stat[src][2][k] = q;
        }
    }
    const char *names[3] = { "value at the centre point", "neighbour difference G(0,0) - G(dx,0)",
                             "Mahalanobis norm G^T Sigma^-1 G" };
    double pvals[4], D;
    double dof = (double)p;
    for (int a = 0; a < 2; a++)   /* aggregated by the KS tests; only part is plotted */
        for (int b = 0; b < 3; b++)
            sf_result_data(r, a ? "Cholesky statistics" : "embedding statistics", N, stat[a][b]);
    double *copy = check_alloc(N * sizeof *copy);
    memcpy(copy, stat[0][2], N * sizeof *copy);
    pvals[3] = sf_ks_test(copy, N, chisq_cdf, &dof, &D);
    for (int b = 0; b < 3; b++)
        pvals[b] = sf_ks2_test(stat[0][b], N, stat[1][b], N, &D);
    for (int b = 0; b < 3; b++) {
        char t[160];
        snprintf(t, sizeof t, "two-sample KS, embedding vs Cholesky: %s", names[b]);
        sf_check_pvalue(r, t, pvals[b], c->spec.alpha / 4, N);
    }
    sf_check_pvalue(r, "one-sample KS of the embedding's Mahalanobis norm vs chi2(p)", pvals[3], c->spec.alpha / 4, N);
    sf_note(r, "Four tests share alpha = %.3g equally (Bonferroni). Both samplers draw %zu fields "
               "on the same %zu x %zu grid.\n", c->spec.alpha, N, m, n);
    /* QQ plot of the Mahalanobis norms (both sorted by the KS tests) */
    double *qx = check_alloc(N * sizeof *qx);
    for (size_t k = 0; k < N; k++)
        qx[k] = gsl_cdf_chisq_Pinv(((double)k + 0.5) / (double)N, dof);
    sf_plot *pl = sf_result_plot(r, "qq_mahalanobis", "QQ plot of the Mahalanobis norm against chi2(p)",
                                 "chi2(p) quantile [-]", "sample quantile [-]");
    sf_plot_series(pl, "y = x", SF_STYLE_LINES, N, qx, qx);
    sf_plot_series(pl, "circulant embedding", SF_STYLE_POINTS, N, qx, copy);
    sf_plot_series(pl, "Cholesky (GSL)", SF_STYLE_POINTS, N, qx, stat[1][2]);
    free(qx); free(copy); free(g);
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 3; b++)
            free(stat[a][b]);
    gsl_vector_free(v);
    gsl_vector_free(w);
    gsl_rng_free(rng);
    gsl_rng_free(rng2);
    gsl_matrix_free(L);
    src_close(&f);
    return SF_SUCCESS;
}

/* Padding across a sweep.  mode 0: sweep = l/dx on the scene's grid;
 * mode 1: sweep = l/domain (domain = (nx-1) dx, dx adjusted, l fixed).
 * Claims: every plan that did not hit the cap produces Sigma to the
 * tolerance; every plan that hit it says so; minimal embedding is PSD
 * exactly while l is below ~0.19 of the domain (docs/design.md sec. 4.2). */
static int padding_sweep(const sf_case *c, sf_result *r, int mode)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (K == 0)
        return SF_EINVAL;
    double *x = check_alloc(K * sizeof *x), *pad = check_alloc(K * sizeof *pad);
    double *lmin = check_alloc(K * sizeof *lmin), *cerr = check_alloc(K * sizeof *cerr);
    double *lmin_min = check_alloc(K * sizeof *lmin_min), *ratio_dom = check_alloc(K * sizeof *ratio_dom);
    size_t worst = 0, silent_trunc = 0, ncap = 0;
    double worst_err = 0, last_ok = 0, first_bad = INFINITY;
    sf_note(r, "| %s | l/domain | minimal: lambda_min/lambda_max | padding factor | L_half / l | clamped | truncated | max abs cov error |\n|---|---|---|---|---|---|---|---|",
            mode ? "l/domain" : "l/dx");
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        double dom;
        if (mode == 0) {
            s.dx = s.dy = s.l / c->spec.sweep.v[k];
        } else {
            dom = s.l / c->spec.sweep.v[k];
            s.dx = s.dy = dom / (double)(s.nx - 1);
        }
        dom = s.dx * (double)(s.nx - 1);
        sf_field_spec spec;
        sf_field_spec_default(&spec, s.nx, s.ny, s.dx, s.dy, s.l);
        spec.pad_cap = s.pad_cap;
        spec.eig_rel_tol = s.eig_tol;
        sf_field *f = NULL, *fmin_ = NULL;
        int rc = sf_field_alloc(&spec, &f);
        spec.no_padding = 1;
        int rc2 = sf_field_alloc(&spec, &fmin_);
        if (!sf_usable(rc) || !sf_usable(rc2)) {
            sf_field_free(f);
            sf_field_free(fmin_);
            return rc ? rc : rc2;
        }
        const sf_field_info *in = sf_field_get_info(f), *im = sf_field_get_info(fmin_);
        x[k] = c->spec.sweep.v[k];
        ratio_dom[k] = s.l / dom;
        pad[k] = (double)in->px / (double)in->px_min;
        lmin[k] = fabs(im->lambda_min / im->lambda_max);
        lmin_min[k] = im->lambda_min / im->lambda_max;
        cerr[k] = in->cov_error;
        double lhalf = 0.5 * (double)in->px * s.dx / s.l;
        int min_ok = im->lambda_min >= -s.eig_tol * im->lambda_max;
        if (min_ok) last_ok = sf_max(last_ok, ratio_dom[k]);
        if (!min_ok) first_bad = sf_min(first_bad, ratio_dom[k]);
        if (in->truncated) {
            ncap++;
            if (rc != SF_ETRUNC) silent_trunc++;
        } else if (!(in->cov_error <= worst_err) && !isnan(worst_err)) {   /* a NaN is the worst */
            worst_err = sf_max(worst_err, in->cov_error);
            worst = k;
        }
        sf_note(r, "| %.4g | %.4g | %.3g | %.3g | %.3g | %zu | %s | %.3g |", x[k], ratio_dom[k],
                lmin_min[k], pad[k], lhalf, in->n_clamped, in->truncated ? "yes" : "no", in->cov_error);
        sf_field_free(f);
        sf_field_free(fmin_);
    }
    sf_note(r, "\nMinimal embedding was PSD (to the relative floor %.0e) up to l/domain = %.3g and failed from %.3g on.\n",
            s0->eig_tol, last_ok, first_bad);
    char t[160];
    snprintf(t, sizeof t, "max covariance error over plans that did not hit the cap (worst at %s = %.4g)",
             mode ? "l/domain" : "l/dx", x[worst]);
    sf_check_le(r, t, worst_err, c->spec.tolerance);
    sf_check_true(r, "every plan that hit the padding cap returned SF_ETRUNC", silent_trunc == 0,
                  silent_trunc ? "a truncation went unreported" : "all truncations reported");
    if (isfinite(first_bad)) {
        sf_check_le(r, "largest l/domain where minimal embedding works, below the first failure", last_ok, first_bad);
        sf_check_true(r, "minimal-embedding threshold l/domain within [0.1, 0.3] (docs/design.md sec. 4.2: ~0.19)",
                      first_bad >= 0.1 && last_ok <= 0.3, "threshold located");
    }
    sf_plot *p = sf_result_plot(r, "min_eigenvalue", "Minimal embedding: most negative eigenvalue",
                                mode ? "l / domain [-]" : "l / dx [-]", "|lambda_min| / lambda_max [-]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "minimal embedding", SF_STYLE_LINESPOINTS, K, x, lmin);
    sf_plot_hline(p, "relative floor (eig_tol)", s0->eig_tol);
    sf_plot *q = sf_result_plot(r, "padding", "Padding needed and covariance error after padding",
                                mode ? "l / domain [-]" : "l / dx [-]", "value [-]");
    sf_plot_log(q, 1, 1);
    sf_plot_series(q, "padding factor P/P_min", SF_STYLE_LINESPOINTS, K, x, pad);
    sf_plot_series(q, "max |C - Sigma| after padding", SF_STYLE_LINESPOINTS, K, x, cerr);
    sf_plot_hline(q, "tolerance", c->spec.tolerance);
    free(x); free(pad); free(lmin); free(cerr); free(lmin_min); free(ratio_dom);
    (void)ncap;
    return SF_SUCCESS;
}

static int chk_padding_sweep_ldx(const sf_case *c, sf_result *r) { return padding_sweep(c, r, 0); }
static int chk_padding_sweep_ldomain(const sf_case *c, sf_result *r) { return padding_sweep(c, r, 1); }

/* FFTW_MEASURE vs FFTW_ESTIMATE sampling plans: the same normals give the
 * same fields up to FFT round-off, and the same produced covariance bits
 * (it is fixed before the sampling plan exists). */
static int chk_planner_roundoff(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t p = s->nx * s->ny;
    sf_field_spec se, sm;
    sf_field_spec_from_scene(s, &se);
    se.measure = 0;
    sm = se;
    sm.measure = 1;
    sf_field *fe, *fm;
    int rc = sf_field_alloc(&se, &fe);
    if (!sf_usable(rc))
        return rc;
    if (!sf_usable(rc = sf_field_alloc(&sm, &fm))) {
        sf_field_free(fe);
        return rc;
    }
    double *a = check_alloc(4 * p * sizeof *a), *b = a + 2 * p, *ce = check_alloc(2 * p * sizeof *ce), *cm = ce + p;
    sf_field_covariance(fe, ce);
    sf_field_covariance(fm, cm);
    double dcov = 0, dmax = 0, amax = 0;
    for (size_t i = 0; i < p; i++)
        dcov = sf_max(dcov, fabs(ce[i] - cm[i]));
    /* for the plot: each sample's max difference (floored at 1e-18 so an
       exact 0 shows on the log axis) */
    size_t ns = s->samples ? s->samples : 1;
    double *pk = check_alloc(2 * ns * sizeof *pk), *pd = pk + ns;
    for (size_t k = 0; k < s->samples; k++) {
        double dk = 0;
        gsl_rng *g1 = gsl_rng_alloc(gsl_rng_mt19937), *g2 = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(g1, s->seed + k);
        gsl_rng_set(g2, s->seed + k);
        sf_field_sample_pair(fe, g1, a, a + p);
        sf_field_sample_pair(fm, g2, b, b + p);
        for (size_t i = 0; i < 2 * p; i++) {
            dmax = sf_max(dmax, fabs(a[i] - b[i]));
            amax = sf_max(amax, fabs(a[i]));
            dk = sf_max(dk, fabs(a[i] - b[i]));
        }
        pk[k] = (double)k;
        pd[k] = fmax(dk, 1e-18);
        gsl_rng_free(g1);
        gsl_rng_free(g2);
    }
    const sf_field_info *in = sf_field_get_info(fe);
    sf_note(r, "%zu sample pairs of a %zu x %zu grid (embedding %zu x %zu), each drawn from the same normals "
               "through an FFTW_ESTIMATE and an FFTW_MEASURE plan; largest |value| %.3g.", s->samples, s->nx, s->ny,
            in->px, in->py, amax);
    sf_check_le(r, "max |G_measure - G_estimate| over all points and samples", dmax, c->spec.tolerance);
    sf_check_abs(r, "produced covariance, measure minus estimate plan (bits)", dcov, 0, 0);
    if (s->samples) {
        /* the last sample's first grid row (x index fastest), both plans */
        double *xr = check_alloc(s->nx * sizeof *xr);
        for (size_t i = 0; i < s->nx; i++)
            xr[i] = (double)i * s->dx;
        sf_plot *pl = sf_result_plot(r, "planner_fields", "Last sample, first grid row: FFTW_ESTIMATE and FFTW_MEASURE plans",
                                     "x along the first grid row [m]", "Gaussian field G [dimensionless]");
        sf_plot_series(pl, "FFTW_ESTIMATE", SF_STYLE_LINES, s->nx, xr, a);
        sf_plot_series(pl, "FFTW_MEASURE", SF_STYLE_POINTS, s->nx, xr, b);
        free(xr);
    }
    sf_plot *pl = sf_result_plot(r, "planner_roundoff", "Max |G_measure - G_estimate| per sample pair",
                                 "sample pair [index]", "max |difference| (floored at 1e-18) [dimensionless]");
    sf_plot_log(pl, 0, 1);
    sf_plot_series(pl, "max over the grid", SF_STYLE_POINTS, s->samples, pk, pd);
    sf_plot_hline(pl, "tolerance", c->spec.tolerance);
    free(pk);
    free(a);
    free(ce);
    sf_field_free(fe);
    sf_field_free(fm);
    return SF_SUCCESS;
}

/* Largest |e| so far; a NaN sticks (a check on NaN data must fail). */
static void upd_max(double *m, double e)
{
    if (isnan(*m))
        return;
    if (isnan(e) || fabs(e) > *m)
        *m = fabs(e);
}

/* The oracle's noise: the stream tiles.h documents, indexed here on its
 * own (floor division into tiles of tw columns, nyp + 2 K rows a column). */
typedef struct {
    gsl_rng *rng;
    uint64_t key;
    size_t tw, nr;
    long tile[4];
    double *buf[4];
    int used;
} oracle_noise;

static double oracle_xi(oracle_noise *on, long i, size_t row)
{
    long tile = (long)floor((double)i / (double)on->tw);
    int k = 0;
    while (k < on->used && on->tile[k] != tile)
        k++;
    if (k == on->used) {
        k = on->used < 4 ? on->used++ : 3;
        on->tile[k] = tile;
        if (!on->buf[k])
            on->buf[k] = check_alloc(on->tw * on->nr * sizeof(double));
        gsl_rng_set(on->rng, (unsigned long)sf_tiles_tile_seed(on->key, tile));
        for (size_t n = 0; n < on->tw * on->nr; n++)
            on->buf[k][n] = gsl_ran_gaussian_ziggurat(on->rng, 1.0);
    }
    return on->buf[k][(size_t)(i - tile * (long)on->tw) * on->nr + row];
}

/* The oracle's kernel: Eq. 2's square root exp(-2 r^2 / l^2) at spacing
 * h, cut where tiles.h documents (6 l/sqrt(2)), normalised to sum w^2 = 1. */
static double *oracle_kernel(double h, double l, size_t *K)
{
    *K = (size_t)ceil(6 * (l / M_SQRT2) / h);
    double *w = check_alloc((2 * *K + 1) * sizeof *w), s2 = 0;
    for (size_t a = 0; a <= 2 * *K; a++) {
        double x = ((double)a - (double)*K) * h;
        w[a] = exp(-2 * x * x / (l * l));
        s2 += w[a] * w[a];
    }
    for (size_t a = 0; a <= 2 * *K; a++)
        w[a] /= sqrt(s2);
    return w;
}

/* The tiled generator: (1) the covariance it produces, a finite sum over
 * its kernel weights recomputed here, against Eq. 2 at every lag up to
 * and past the kernel's reach; (2) its fields against a direct 2-D
 * convolution of the documented noise stream with the oracle's own
 * kernel, over columns that straddle two tile seams and negative indices;
 * (3) random access: the same columns made one by one, last first, by a
 * fresh generator are the same bits. */
static int chk_tiles_exact(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_tiles_spec ts = { s->ny, s->dx, s->dy, s->l, 0, 0 };
    sf_tiles *t, *t2;
    if (sf_tiles_alloc(&ts, &t) || sf_tiles_alloc(&ts, &t2))
        return SF_EFAIL;
    size_t Kx, Ky, tw = sf_tiles_tile_cols(t);
    const double *wx = sf_tiles_weights(t, 0, &Kx), *wy = sf_tiles_weights(t, 1, &Ky);
    /* (1) produced covariance */
    size_t Px = 2 * Kx + 3, Py = 2 * Ky + 3;
    double *cx = check_alloc(Px * sizeof *cx), *cy = check_alloc(Py * sizeof *cy);
    for (size_t p = 0; p < Px; p++)
        for (size_t a = 0; a + p <= 2 * Kx; a++)
            cx[p] += wx[a] * wx[a + p];
    for (size_t q = 0; q < Py; q++)
        for (size_t b = 0; b + q <= 2 * Ky; b++)
            cy[q] += wy[b] * wy[b + q];
    double err = 0, rep = 0;
    for (size_t q = 0; q < Py; q++)
        for (size_t p = 0; p < Px; p++) {
            double C = cx[p] * cy[q];
            upd_max(&err, C - ref_sq_exp((double)p * s->dx, (double)q * s->dy, s->l));
            upd_max(&rep, C - sf_tiles_covariance(t, (long)p, -(long)q));
        }
    sf_check_le(r, "max |C_produced - Eq. 2| over lags 0..2K+2 along x and y (2-D)", err, c->spec.tolerance);
    sf_check_le(r, "covariance the generator reports vs recomputed here from its weights", rep, 1e-15);
    /* (2) fields vs the oracle */
    gsl_rng *rng = sf_case_rng(c);
    uint64_t key = draw_key(rng);
    gsl_rng_free(rng);
    long i0 = -(long)tw - 6;
    size_t m = tw + 12, ny = s->ny, nyp = (ny + 15) / 16 * 16, Kox, Koy;
    double *ox = oracle_kernel(s->dx, s->l, &Kox), *oy = oracle_kernel(s->dy, s->l, &Koy);
    oracle_noise on = { gsl_rng_alloc(sf_rng_splitmix64), key, tw, nyp + 2 * Koy, { 0 }, { NULL }, 0 };
    double *g = check_alloc(m * ny * sizeof *g), *g2 = check_alloc(m * ny * sizeof *g2);
    sf_tiles_set_key(t, key);
    sf_tiles_fill(t, i0, m, g, m);
    double derr = 0;
    for (size_t j = 0; j < ny; j++)
        for (size_t cc = 0; cc < m; cc++) {
            long i = i0 + (long)cc;
            double sum = 0;
            for (size_t a = 0; a <= 2 * Kox; a++)
                for (size_t b = 0; b <= 2 * Koy; b++)   /* xi(i - a', j - b') at noise row j - b' + Ky */
                    sum += ox[a] * oy[b] * oracle_xi(&on, i - ((long)a - (long)Kox), j + 2 * Koy - b);
            upd_max(&derr, g[cc + m * j] - sum);
        }
    sf_check_le(r, "max |G - direct 2-D convolution of the documented noise| over columns straddling two tile seams",
                derr, 1e-12);
    /* (3) random access */
    sf_tiles_set_key(t2, key);
    for (size_t cc = m; cc-- > 0;)
        sf_tiles_fill(t2, i0 + (long)cc, 1, g2 + cc, m);
    int same = !memcmp(g, g2, m * ny * sizeof *g);
    sf_check_true(r, "columns made one by one, last first, by a fresh generator: the same bits", same,
                  same ? "identical" : "differ");
    sf_note(r, "Kernel half-widths Kx = %zu, Ky = %zu lattice steps (6 l/sqrt(2)); %zu-column noise tiles; columns "
               "%ld..%ld compared with the oracle (seams at %ld and 0). Produced covariance error %.3g, field error "
               "%.3g.\n", Kx, Ky, tw, i0, i0 + (long)m - 1, -(long)tw, err, derr);
    /* plot: produced covariance along the axes vs Eq. 2, and the error */
    double *lx = check_alloc(Px * sizeof *lx), *ex = check_alloc(Px * sizeof *ex), *ee = check_alloc(Px * sizeof *ee);
    double *ly = check_alloc(Py * sizeof *ly), *eyv = check_alloc(Py * sizeof *eyv);
    for (size_t p = 0; p < Px; p++) {
        lx[p] = (double)p * s->dx;
        ex[p] = cx[p] * cy[0];
        ee[p] = fmax(fabs(ex[p] - ref_sq_exp(lx[p], 0, s->l)), 1e-20);
    }
    for (size_t q = 0; q < Py; q++) {
        ly[q] = (double)q * s->dy;
        eyv[q] = cx[0] * cy[q];
    }
    sf_plot *pl = sf_result_plot(r, "covariance", "Tiled generator: produced covariance vs Eq. 2", "lag [m]",
                                 "correlation [-]");
    sf_plot_series(pl, "produced, x lags", SF_STYLE_POINTS, Px, lx, ex);
    sf_plot_series(pl, "produced, y lags", SF_STYLE_POINTS, Py, ly, eyv);
    for (size_t p = 0; p < Px; p++)
        cx[p] = ref_sq_exp(lx[p], 0, s->l);
    sf_plot_series(pl, "Eq. 2 exp(-r^2/l^2)", SF_STYLE_LINES, Px, lx, cx);
    sf_plot *q = sf_result_plot(r, "covariance_error", "Tiled generator: |C - Eq. 2| along x (floored at 1e-20)",
                                "lag [m]", "|C - Sigma| [-]");
    sf_plot_log(q, 0, 1);
    sf_plot_series(q, "|C - Eq. 2|", SF_STYLE_LINESPOINTS, Px, lx, ee);
    if (c->spec.tolerance > 0)
        sf_plot_hline(q, "tolerance", c->spec.tolerance);
    free(lx); free(ex); free(ee); free(ly); free(eyv);
    for (int k = 0; k < 4; k++)
        free(on.buf[k]);
    gsl_rng_free(on.rng);
    free(ox); free(oy); free(g); free(g2); free(cx); free(cy);
    sf_tiles_free(t);
    sf_tiles_free(t2);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_field[] = {
    { "field_planner_roundoff", chk_planner_roundoff,
      "FFTW_MEASURE vs FFTW_ESTIMATE plans: same fields to round-off" },
    { "field_tiles_exact", chk_tiles_exact,
      "tiled generator: produced covariance vs Eq. 2, fields vs a direct convolution, random access" },
    { "field_exact_covariance", chk_exact_covariance,
      "produced covariance (no sampling) vs Sigma at every grid lag" },
    { "field_eigen_direct", chk_eigen_direct,
      "embedding eigenvalues by FFTW vs direct DFT sums" },
    { "field_truncation_reported", chk_truncation_reported,
      "truncated embedding reports the exact covariance error" },
    { "field_sampled_covariance", chk_sampled_covariance,
      "whitened likelihood-ratio test of the sampled covariance" },
    { "field_pointwise_moments", chk_pointwise_moments,
      "per-point mean 0 and variance 1 (Bonferroni)" },
    { "field_re_im_independence", chk_re_im_independence,
      "real and imaginary fields uncorrelated (Fisher z)" },
    { "field_cholesky_agreement", chk_cholesky_agreement,
      "agreement in distribution with a GSL Cholesky sampler (KS)" },
    { "field_padding_sweep_ldx", chk_padding_sweep_ldx,
      "eigenvalue minimum and padding across l/dx" },
    { "field_padding_sweep_ldomain", chk_padding_sweep_ldomain,
      "eigenvalue minimum and padding across l/domain" },
    { NULL, NULL, NULL }
};
