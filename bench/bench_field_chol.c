/* make bench, field section (b): circulant embedding against a direct
 * Cholesky sampler built on GSL, as the number of grid points N = n^2
 * grows.  Cholesky: build the N x N covariance Sigma, factor it with
 * gsl_linalg_cholesky_decomp1 (set-up), then one field = L z with
 * gsl_blas_dtrmv on N ziggurat normals.  Its accuracy is measured as
 * max |L L^T - Sigma| (gsl_blas_dtrmm), the circulant's is the exact
 * sf_field_info.cov_error, so both are compared at round-off accuracy. */
#include "bench.h"
#include "bench_field.h"
#include "result.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_vector.h>

/* Sigma[p][q] of the squared-exponential kernel on the n x n grid, point
 * p = i + n j (the field layout of field.h); s = dx^2/l^2. */
static double sigma_at(size_t p, size_t q, size_t n, double s)
{
    double a = (double)(p % n) - (double)(q % n), b = (double)(p / n) - (double)(q / n);
    return exp(-(a * a + b * b) * s);
}

static void fill_sigma(gsl_matrix *S, size_t n, double dx, double l)
{
    size_t N = n * n;
    double s = dx * dx / (l * l);
    for (size_t p = 0; p < N; p++)
        for (size_t q = 0; q <= p; q++) {
            double v = sigma_at(p, q, n, s);
            gsl_matrix_set(S, p, q, v);
            gsl_matrix_set(S, q, p, v);
        }
}

/* max |L L^T - Sigma| with L the lower triangle of the factored A:
 * (L L^T)[p][q] = row p . row q over k <= q (q <= p), contiguous dots. */
static double chol_error(const gsl_matrix *A, size_t n, double dx, double l)
{
    double s = dx * dx / (l * l), err = 0.0;
    for (size_t p = 0; p < A->size1; p++) {
        gsl_vector_const_view rp = gsl_matrix_const_row(A, p);
        for (size_t q = 0; q <= p; q++) {
            gsl_vector_const_view a = gsl_vector_const_subvector(&rp.vector, 0, q + 1);
            gsl_vector_const_view b = gsl_matrix_const_subrow(A, q, 0, q + 1);
            double d;
            gsl_blas_ddot(&a.vector, &b.vector, &d);
            double e = fabs(d - sigma_at(p, q, n, s));
            if (e > err) err = e;
        }
    }
    return err;
}

static int chol_cost(size_t n, double dx, double l, fb_cost *out)
{
    enum { MAXR = 41 };
    double t[MAXR];
    size_t N = n * n, r = 0;
    gsl_matrix *A = gsl_matrix_alloc(N, N);
    gsl_vector *z = gsl_vector_alloc(N);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    int rc = 0;
    double t_start = now();
    while (!rc && fb_more(r, 1, 21, t_start, 1.0)) {
        double t0 = now();
        fill_sigma(A, n, dx, l);
        rc = gsl_linalg_cholesky_decomp1(A);
        t[r++] = now() - t0;
    }
    if (rc) {
        fprintf(stderr, "bench: Cholesky of the %zu x %zu covariance failed: %s\n", N, N, gsl_strerror(rc));
        goto done;
    }
    out->n = n;
    out->px = out->py = 0;
    out->reps_setup = r;
    out->setup = fb_median(t, r);
    r = 0;
    t_start = now();
    while (fb_more(r, 5, MAXR, t_start, 0.5)) {
        double t0 = now();
        for (size_t k = 0; k < N; k++)
            gsl_vector_set(z, k, gsl_ran_gaussian_ziggurat(rng, 1.0));
        gsl_blas_dtrmv(CblasLower, CblasNoTrans, CblasNonUnit, A, z);
        t[r++] = now() - t0;
    }
    out->reps_sample = r;
    out->sample = fb_median(t, r);
    out->cov_err = chol_error(A, n, dx, l);
done:
    gsl_rng_free(rng);
    gsl_vector_free(z);
    gsl_matrix_free(A);
    return rc;
}

/* Least-squares slope of log t against log N over points [from, to). */
static void fit_exponent(const double *N, const fb_cost *c, int setup, size_t from, size_t to,
                         double *slope, double *se)
{
    double x[FB_NCHOL] = { 0 }, y[FB_NCHOL] = { 0 }, c0, c1, v00, v01, v11, ss;
    size_t k = 0;
    for (size_t i = from; i < to; i++, k++) {
        x[k] = log(N[i]);
        y[k] = log(setup ? c[i].setup : c[i].sample);
    }
    gsl_fit_linear(x, 1, y, 1, k, &c0, &c1, &v00, &v01, &v11, &ss);
    *slope = c1;
    *se = k > 2 ? sqrt(v11) : NAN;
}

/* The 1-D symbol of the squared-exponential Toeplitz matrix,
 * f(w) = sum_k exp(-k^2 dx^2/l^2) e^{ikw}, by Poisson summation (positive
 * terms, no cancellation): f(w) = a sqrt(pi) sum_j exp(-a^2 (w + 2 pi j)^2/4)
 * with a = l/dx.  Its range holds the spectrum of every 1-D Toeplitz
 * section, and Sigma on an n x n grid is the Kronecker product of two of
 * them, so f(pi)^2 <= lambda(Sigma) <= f(0)^2. */
static double symbol(double w, double dx, double l)
{
    double a = l / dx, s = 0.0;
    for (int j = -20; j <= 20; j++) {
        double u = w + 2.0 * M_PI * j;
        s += exp(-a * a * u * u / 4.0);
    }
    return a * sqrt(M_PI) * s;
}

int bench_field_cholesky(FILE *f, const char *dir, fb_cost *circ, fb_cost *chol, size_t *nrun)
{
    static const size_t ns[FB_NCHOL] = { 8, 12, 16, 24, 32, 40, 48, 56, 64 };
    const double dx = 0.025, l = 2 * dx, max_chol = 10.0;
    double N[FB_NCHOL];
    size_t k = 0;
    const char *stopped = "";
    for (; k < FB_NCHOL; k++) {   /* GSL's handler is off: bench main calls sf_init() */
        N[k] = (double)(ns[k] * ns[k]);
        if (k > 0 && chol[k - 1].setup * pow(N[k] / N[k - 1], 3.0) > max_chol) {
            stopped = " (stopped: the next Cholesky was predicted above 10 s)";
            break;
        }
        sf_field_spec spec;
        sf_field_spec_default(&spec, ns[k], ns[k], dx, dx, l);
        if (fb_circulant_costs(&spec, 1, 0.5, &circ[k]) || chol_cost(ns[k], dx, l, &chol[k]))
            return 1;
        fprintf(stderr, "bench: N = %5.0f  Cholesky set-up %.3g s, per field %.3g s (err %.1e); "
                        "circulant set-up %.3g s, per field %.3g s (err %.1e)\n", N[k], chol[k].setup,
                chol[k].sample, chol[k].cov_err, circ[k].setup, circ[k].sample, circ[k].cov_err);
    }
    *nrun = k;
    double fmin = symbol(M_PI, dx, l), fmax = symbol(0.0, dx, l), f4 = symbol(M_PI, dx, 4 * dx);
    /* the l = 4 dx claim, checked in this run on a 16 x 16 grid */
    gsl_matrix *S4 = gsl_matrix_alloc(256, 256);
    fill_sigma(S4, 16, dx, 4 * dx);
    int rc4 = gsl_linalg_cholesky_decomp1(S4);
    gsl_matrix_free(S4);
    fprintf(f, "## Field sampling vs a direct Cholesky sampler (GSL) as N grows\n\n"
               "n x n grids, N = n^2 points, dx = %g m, l = 2 dx. Cholesky: build the N x N covariance Sigma and "
               "factor it with `gsl_linalg_cholesky_decomp1` (set-up), then one field is `gsl_blas_dtrmv` of L "
               "on N ziggurat normals. Circulant: `sf_field_alloc` (set-up), one field is half a "
               "`sf_field_sample_pair` call (one FFT gives two fields). Medians of repeated runs%s.\n\n"
               "Why l = 2 dx: Sigma is the Kronecker product of two 1-D Toeplitz matrices whose spectra lie in "
               "the range of the symbol f(w) = sum_k exp(-k^2 dx^2/l^2) e^{ikw} (evaluated by Poisson summation); "
               "at l = 2 dx, min f = f(pi) = %.3g and max f = f(0) = %.3g, so lambda_min(Sigma) >= %.2g and "
               "cond(Sigma) <= %.2g on every grid: numerically positive definite, and the Cholesky factor is "
               "accurate to round-off. At l = 4 dx, f(pi) = %.1e and the bound on lambda_min/lambda_max is "
               "%.0e, far below double round-off: Sigma is numerically singular (in this run "
               "`gsl_linalg_cholesky_decomp1` on the 16^2 grid at l = 4 dx returned: %s), so Cholesky would need "
               "a nugget and there would be no equal-accuracy comparison.\n\n"
               "| N | Cholesky set-up [s] | Cholesky per field [s] | max abs(L L^T - Sigma) | circulant embedding | "
               "circulant set-up [s] | circulant per field [s] | circulant cov. error (exact) | "
               "set-up ratio Chol/circ | per-field ratio Chol/circ |\n"
               "|---|---|---|---|---|---|---|---|---|---|\n",
            dx, stopped, fmin, fmax, fmin * fmin, (fmax / fmin) * (fmax / fmin), f4,
            (f4 / symbol(0.0, dx, 4 * dx)) * (f4 / symbol(0.0, dx, 4 * dx)), gsl_strerror(rc4));
    for (size_t i = 0; i < k; i++) {
        fb_cost *h = &chol[i], *c = &circ[i];
        fprintf(f, "| %.0f (%zu^2) | %.3g | %.3g | %.1e | %zu x %zu | %.3g | %.3g | %.1e | %.3g | %.3g |\n", N[i],
                ns[i], h->setup, h->sample, h->cov_err, c->px, c->py, c->setup, c->sample, c->cov_err,
                h->setup / c->setup, h->sample / c->sample);
    }
    /* exponents: all points, and the upper half where the leading term
     * dominates */
    size_t lo = k > 3 ? k - 4 : 0;
    const char *what[4] = { "Cholesky set-up", "Cholesky per field", "circulant set-up", "circulant per field" };
    const char *expect[4] = { "3 (N^3/3 flops)", "2 (N^2 flops)", "1 (N log N)", "1 (N log N)" };
    fprintf(f, "\nCost exponents p in t ~ N^p (`gsl_fit_linear` on log t vs log N; +- standard error of the "
               "slope):\n\n| quantity | p, all N (%.0f to %.0f) | p, largest 4 N (%.0f to %.0f) | expected |\n"
               "|---|---|---|---|\n", N[0], N[k - 1], N[lo], N[k - 1]);
    double pfit[4][2];
    for (int q = 0; q < 4; q++) {
        const fb_cost *c = q < 2 ? chol : circ;
        double sa, ea, sb, eb;
        fit_exponent(N, c, q % 2 == 0, 0, k, &sa, &ea);
        fit_exponent(N, c, q % 2 == 0, lo, k, &sb, &eb);
        pfit[q][0] = sa;
        pfit[q][1] = sb;
        fprintf(f, "| %s | %.2f +- %.2f | %.2f +- %.2f | %s |\n", what[q], sa, ea, sb, eb, expect[q]);
    }
    sf_result *r = sf_result_alloc();
    sf_plot *p = sf_result_plot(r, "field_cholesky_scaling", "Field sampler cost vs grid points (l = 2 dx)",
                                "grid points N [-]", "time [s]");
    sf_plot_log(p, 1, 1);
    double ys[4][FB_NCHOL];
    for (size_t i = 0; i < k; i++) {
        ys[0][i] = chol[i].setup;
        ys[1][i] = chol[i].sample;
        ys[2][i] = circ[i].setup;
        ys[3][i] = circ[i].sample;
    }
    for (int q = 0; q < 4; q++)
        sf_plot_series(p, what[q], SF_STYLE_LINESPOINTS, k, N, ys[q]);
    int rc = fb_render(r, dir);
    size_t slow = 0;   /* grids [0, slow) where the circulant field costs more */
    for (size_t i = 0; i < k; i++)
        if (circ[i].sample > chol[i].sample)
            slow = i + 1;
    char cross[160];
    if (slow == 0)
        snprintf(cross, sizeof cross, "Per field the circulant is faster on every grid");
    else if (slow == k)
        snprintf(cross, sizeof cross, "Per field the circulant is slower on every grid");
    else
        snprintf(cross, sizeof cross, "Per field the circulant is slower than the small dense product up to "
                 "N = %.0f and faster from N = %.0f on", N[slow - 1], N[slow]);
    fprintf(f, "\n![Cholesky vs circulant cost](field_cholesky_scaling.png)\n\n"
               "Both samplers are exact here (Cholesky to %.0e, circulant to %.0e at the largest N), so the "
               "times compare at equal accuracy. Over the largest four grids the fitted exponents are %.2f "
               "(Cholesky set-up; 3 expected), %.2f (Cholesky per field; 2 expected), %.2f and %.2f (circulant "
               "set-up and per field; 1 expected for N log N). Above 3 and 2 for Cholesky: GSL runs on its "
               "reference CBLAS (libgslcblas, no cache blocking), so the flop rate drops once L no longer fits "
               "in cache. Below 1 for the circulant set-up: at these small grids its fixed costs (FFTW plans, "
               "allocation) still dominate. %s; at N = %.0f the Cholesky set-up costs %.0f times the "
               "circulant's and each field %.0f times more.\n",
            chol[k - 1].cov_err, circ[k - 1].cov_err, pfit[0][1], pfit[1][1], pfit[2][1], pfit[3][1], cross,
            N[k - 1], chol[k - 1].setup / circ[k - 1].setup, chol[k - 1].sample / circ[k - 1].sample);
    return rc ? 1 : 0;
}
