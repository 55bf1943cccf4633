/* Circulant embedding of a homogeneous Gaussian field (paper Appendix A).
 *
 * Embedding: along an axis with m points and spacing d, the first row of the
 * circulant of period P >= 2(m-1) is c(j) = rho(min(j, P-j) d); its top-left
 * m x m block is the Toeplitz covariance (A.1).  The eigenvalues are the DFT
 * of c (real, c is even).  Sampling (A, step 4): Gamma = F (Lambda/M)^(1/2) xi
 * with complex xi = xi1 + i xi2; Re and Im are two independent N(0, Sigma)
 * fields whenever Lambda >= 0.
 */
#include "field.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <string.h>
#include <complex.h>
#include <fftw3.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>

struct sf_field {
    sf_field_spec spec;
    sf_field_info info;
    size_t M;
    double *lx, *ly;        /* raw 1-D eigenvalues (separable path) */
    double *lam;            /* raw 2-D eigenvalues, before clamping, of a general kernel
                               (the separable paths rebuild them by rows: eig_row) */
    double *amp;            /* sqrt(max(lambda, 0)/M): M of them, or the stored half
                               (px/2 + 1) py of a real sampler; NULL for a separable
                               kernel (its draw makes them from lx, ly: amp_of) */
    double *arow;           /* a separable kernel's amplitudes of one row (px), made per draw */
    double *cov;            /* produced covariance at grid lags, m*n (NULL until measured) */
    fftw_complex *work;
    size_t nwork;           /* complex values work holds */
    fftw_plan plan;
    double *kept;           /* second field of the last FFT */
    int have_kept;
    double *tx, *ty;        /* separable-sum kernel: sep_fn(t, min(i, px-i) dx) at tx[i + px t] (ty alike) */
    size_t tpx, tpy;        /* the periods the tables were made for */
    double *sx, *sy;        /* their 1-D DFTs per term (real: each row is even): the 2-D
                               eigenvalues are sum_t sx[kx + px t] sy[ky + py t] */
};

static double sq_exp(double r, double l)
{
    double q = r / l;
    return exp(-q * q);
}

static double kernel_at(const sf_field_spec *s, double hx, double hy)
{
    if (s->sep_terms > 0) {
        double v = 0;
        for (int t = s->sep_terms - 1; t >= 0; t--)   /* smallest terms first */
            v += s->sep_fn(t, hx, s->sep_params) * s->sep_fn(t, hy, s->sep_params);
        return v;
    }
    double r = hypot(hx, hy);
    return s->kernel ? s->kernel(r, s->kernel_params) : sq_exp(r, s->l);
}

void sf_field_spec_default(sf_field_spec *spec, size_t m, size_t n,
                           double dx, double dy, double l)
{
    memset(spec, 0, sizeof *spec);
    spec->m = m;
    spec->n = n;
    spec->dx = dx;
    spec->dy = dy;
    spec->l = l;
    spec->eig_rel_tol = 1e-12;
    spec->pad_cap = 16.0;
    spec->max_points = (size_t)1 << 25;
}

/* Smallest P >= n with no prime factor above 7: FFTW's fast sizes. */
static size_t nice_size(size_t n)
{
    if (n <= 1)
        return 1;
    for (size_t p = n;; p++) {
        size_t q = p;
        while (q % 2 == 0) q /= 2;
        while (q % 3 == 0) q /= 3;
        while (q % 5 == 0) q /= 5;
        while (q % 7 == 0) q /= 7;
        if (q == 1)
            return p;
    }
}

static size_t min_period(size_t m)
{
    return m <= 1 ? 1 : 2 * (m - 1);
}

/* The DFTs of `rows` real even sequences of period P (v[j + P r], j < P),
 * in place: v[k + P r] becomes the DFT, real since each row is even.  One
 * FFTW plan (FFTW_ESTIMATE, in place) for all rows. */
static int dft_even_rows(size_t P, size_t rows, double *v)
{
    fftw_complex *buf = SF_FALLIBLE(fftw_alloc_complex(P));
    if (!buf)
        return SF_ENOMEM;
    fftw_plan p = SF_FALLIBLE(fftw_plan_dft_1d((int)P, buf, buf, FFTW_FORWARD, FFTW_ESTIMATE));
    if (!p) {
        fftw_free(buf);
        return SF_ENOMEM;
    }
    for (size_t r = 0; r < rows; r++) {
        for (size_t j = 0; j < P; j++)
            buf[j] = v[j + P * r];
        fftw_execute(p);
        for (size_t k = 0; k < P; k++)
            v[k + P * r] = creal(buf[k]);
    }
    fftw_destroy_plan(p);
    fftw_free(buf);
    return SF_SUCCESS;
}

/* 1-D eigenvalues of the squared-exponential circulant of period P. */
static int eig_1d(size_t P, double d, double l, double *lam)
{
    for (size_t j = 0; j < P; j++) {
        size_t jj = j < P - j ? j : P - j;
        lam[j] = sq_exp((double)jj * d, l);
    }
    return dft_even_rows(P, 1, lam);
}

/* NaN-propagating max (fmax and `if (x > m)` drop a NaN, so one NaN
 * eigenvalue or covariance lag would vanish from lambda_min/max and
 * cov_error).  solver/ cannot use verification/stats.h's sf_max, hence
 * this internal copy of the one-liner. */
static double nan_max(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : (a > b ? a : b);
}

static double nan_min(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : (a < b ? a : b);
}

static void min_max(const double *v, size_t n, double *mn, double *mx)
{
    *mn = v[0];
    *mx = v[0];
    for (size_t i = 1; i < n; i++) {
        *mn = nan_min(*mn, v[i]);
        *mx = nan_max(*mx, v[i]);
    }
}

/* Choose the period along one axis: grow by ~25% until the 1-D eigenvalues
 * clear the relative floor or the cap is reached.  Returns the eigenvalues
 * (caller frees) and sets *hit_cap. */
static int pad_axis(const sf_field_spec *s, size_t m, double d,
                    size_t *P_out, double **lam_out, int *hit_cap)
{
    size_t pmin = min_period(m);
    size_t cap = (size_t)ceil(s->pad_cap * (double)pmin);
    size_t P = nice_size(pmin);
    *hit_cap = 0;
    for (;;) {
        double *lam = sf_malloc(P * sizeof *lam);
        if (!lam)
            return SF_ENOMEM;
        int rc = eig_1d(P, d, s->l, lam);
        if (rc) {
            free(lam);
            return rc;
        }
        double mn, mx;
        min_max(lam, P, &mn, &mx);
        if (mn >= -s->eig_rel_tol * mx || s->no_padding) {
            *P_out = P;
            *lam_out = lam;
            *hit_cap = mn < -s->eig_rel_tol * mx;
            return SF_SUCCESS;
        }
        size_t next = nice_size(P + (P / 4 > 0 ? P / 4 : 1));
        if (next > cap || next > s->max_points) {
            *P_out = P;
            *lam_out = lam;
            *hit_cap = 1;
            return SF_SUCCESS;
        }
        free(lam);
        P = next;
    }
}

static int build_separable(sf_field *f)
{
    const sf_field_spec *s = &f->spec;
    int capx, capy, rc;
    size_t px, py;
    rc = pad_axis(s, s->m, s->dx, &px, &f->lx, &capx);
    if (rc)
        return rc;
    rc = pad_axis(s, s->n, s->dy, &py, &f->ly, &capy);
    if (rc)
        return rc;
    if (px > s->max_points / py)
        return SF_ETOOBIG;
    f->info.px = px;
    f->info.py = py;
    f->info.separable = 1;
    f->info.truncated = capx || capy;
    f->M = px * py;   /* the 2-D eigenvalues lx[kx] ly[ky]: eig_row */
    return SF_SUCCESS;
}

/* The separable-sum kernel's 1-D tables for periods (px, py): each
 * factor once per lag, so the M entries of the first row cost
 * sep_terms multiply-adds each (the same sum, in the same order, as
 * kernel_at); and their 1-D DFTs, from which the 2-D eigenvalues follow
 * without a 2-D FFT (the DFT of a sum of outer products is the sum of
 * the outer products of the DFTs). */
static int sep_tables(sf_field *f, size_t px, size_t py)
{
    const sf_field_spec *s = &f->spec;
    size_t T = (size_t)s->sep_terms;
    free(f->tx);
    free(f->ty);
    free(f->sx);
    free(f->sy);
    f->sx = f->sy = NULL;
    f->tpx = f->tpy = 0;
    f->tx = sf_malloc(T * px * sizeof *f->tx);
    f->ty = sf_malloc(T * py * sizeof *f->ty);
    if (!f->tx || !f->ty)
        return SF_ENOMEM;
    for (size_t t = 0; t < T; t++) {
        for (size_t i = 0; i < px; i++)
            f->tx[i + px * t] = s->sep_fn((int)t, (double)(i < px - i ? i : px - i) * s->dx, s->sep_params);
        for (size_t j = 0; j < py; j++)
            f->ty[j + py * t] = s->sep_fn((int)t, (double)(j < py - j ? j : py - j) * s->dy, s->sep_params);
    }
    f->tpx = px;
    f->tpy = py;
    f->sx = sf_malloc(T * px * sizeof *f->sx);
    f->sy = sf_malloc(T * py * sizeof *f->sy);
    if (!f->sx || !f->sy)
        return SF_ENOMEM;
    memcpy(f->sx, f->tx, T * px * sizeof *f->sx);
    memcpy(f->sy, f->ty, T * py * sizeof *f->sy);
    int rc = dft_even_rows(px, T, f->sx);
    if (!rc)
        rc = dft_even_rows(py, T, f->sy);
    /* even exactly, not to round-off: lambda(-k) = lambda(k) bit for bit,
     * which a real sampler's Hermitian draw needs (draw_real) */
    for (size_t t = 0; t < T; t++) {
        for (size_t k = 1; 2 * k < px; k++)
            f->sx[px - k + px * t] = f->sx[k + px * t];
        for (size_t k = 1; 2 * k < py; k++)
            f->sy[py - k + py * t] = f->sy[k + py * t];
    }
    return rc;
}

/* Row ky of the separable-sum embedding's 2-D eigenvalues (sep_tables):
 * lam[kx] = sum_t sx[kx + px t] sy[ky + py t], kx < px, smallest terms
 * first as in kernel_at.  M sep_terms multiply-adds in all, in place of a
 * 2-D FFT of the first row (eigenvalues equal to it to round-off:
 * tests/test_cellavg.c). */
static void sep_eig_row(const sf_field *f, size_t ky, double *lam)
{
    size_t px = f->tpx, py = f->tpy, T = (size_t)f->spec.sep_terms;
    for (size_t kx = 0; kx < px; kx++)
        lam[kx] = 0;
    for (size_t t = T; t-- > 0;) {
        const double *a = f->sx + px * t;
        double b = f->sy[ky + py * t];
        for (size_t kx = 0; kx < px; kx++)
            lam[kx] += a[kx] * b;
    }
}

/* Entry (i, j) of the embedding's first row for periods (px, py). */
static double first_row_at(const sf_field *f, size_t px, size_t py, size_t i, size_t j)
{
    const sf_field_spec *s = &f->spec;
    if (s->sep_terms > 0 && f->tx && f->tpx == px && f->tpy == py) {
        double v = 0;
        for (int t = s->sep_terms - 1; t >= 0; t--)
            v += f->tx[i + px * (size_t)t] * f->ty[j + py * (size_t)t];
        return v;
    }
    size_t ii = i < px - i ? i : px - i, jj = j < py - j ? j : py - j;
    return kernel_at(s, (double)ii * s->dx, (double)jj * s->dy);
}

/* The work array with room for n complex values (kept when it has them:
 * the eigenvalues' FFT and the sampler share it, so a plan touches one
 * M-sized complex array, not two). */
static int work_for(sf_field *f, size_t n)
{
    if (f->work && f->nwork == n)
        return SF_SUCCESS;
    fftw_free(f->work);
    f->nwork = 0;
    f->work = SF_FALLIBLE(fftw_alloc_complex(n));
    if (!f->work)
        return SF_ENOMEM;
    f->nwork = n;
    return SF_SUCCESS;
}

/* General (non-separable) kernel: 2-D first row, 2-D FFT, in the work
 * array of a complex sampler of these periods (a general kernel's sampler
 * is complex: spec_valid). */
static int eig_2d(sf_field *f, size_t px, size_t py, double *lam)
{
    size_t M = px * py;
    int rc = work_for(f, M);
    if (rc)
        return rc;
    fftw_complex *buf = f->work;
    fftw_plan p = SF_FALLIBLE(fftw_plan_dft_2d((int)py, (int)px, buf, buf, FFTW_FORWARD, FFTW_ESTIMATE));
    if (!p)
        return SF_ENOMEM;
    for (size_t j = 0; j < py; j++)
        for (size_t i = 0; i < px; i++)
            buf[i + px * j] = first_row_at(f, px, py, i, j);
    fftw_execute(p);
    for (size_t k = 0; k < M; k++)
        lam[k] = creal(buf[k]);
    fftw_destroy_plan(p);
    return SF_SUCCESS;
}

/* Row ky of the 2-D eigenvalues into row[px], before clamping: the outer
 * product of the 1-D sets (separable kernel), from the 1-D spectra
 * (separable-sum kernel), else a copy of f->lam's row.  No path keeps an
 * M-sized array but the last. */
static void eig_row(const sf_field *f, size_t ky, double *row)
{
    size_t px = f->info.px;
    if (f->info.separable)
        for (size_t kx = 0; kx < px; kx++)
            row[kx] = f->lx[kx] * f->ly[ky];
    else if (f->lam)
        memcpy(row, f->lam + px * ky, px * sizeof *row);
    else
        sep_eig_row(f, ky, row);
}

/* A sampling amplitude sqrt(lambda+/M) (invM = 1/M), lambda clamped at
 * zero (the nearest PSD circulant in the Frobenius norm). */
static inline double amp_of(double lambda, double invM)
{
    return sqrt((lambda < 0.0 ? 0.0 : lambda) * invM);
}

/* The sampling amplitudes for the periods in f->info (the stored half,
 * kx <= px/2, for a real sampler; none for a separable kernel: its draw
 * makes them from the 1-D eigenvalues, so a plan stores and first-touches
 * no M-sized array but the FFT's), with the eigenvalues' extremes and the
 * count clamped at zero, row by row: no M-sized eigenvalue array on the
 * separable paths. */
static int amp_fill(sf_field *f)
{
    size_t px = f->info.px, py = f->info.py, hx = f->spec.sample_real ? px / 2 + 1 : px;
    int keep = !f->info.separable;
    free(f->amp);
    free(f->arow);
    f->amp = keep ? sf_malloc(hx * py * sizeof *f->amp) : NULL;
    f->arow = keep ? NULL : sf_malloc(px * sizeof *f->arow);
    double *row = sf_malloc(px * sizeof *row);
    if (!(keep ? f->amp : f->arow) || !row) {
        free(row);
        return SF_ENOMEM;
    }
    double invM = 1.0 / ((double)px * (double)py);
    size_t nc = 0;
    for (size_t ky = 0; ky < py; ky++) {
        double mn, mx;
        eig_row(f, ky, row);
        min_max(row, px, &mn, &mx);
        f->info.lambda_min = ky ? nan_min(f->info.lambda_min, mn) : mn;
        f->info.lambda_max = ky ? nan_max(f->info.lambda_max, mx) : mx;
        for (size_t kx = 0; kx < px; kx++) {
            nc += row[kx] < 0.0;
            if (keep && kx < hx)
                f->amp[kx + hx * ky] = amp_of(row[kx], invM);
        }
    }
    free(row);
    f->info.n_clamped = nc;
    return SF_SUCCESS;
}

/* The 2-D eigenvalues' extremes for the periods in f->info: the
 * separable-sum kernel's from its 1-D spectra with the amplitudes
 * (amp_fill: one pass), any other kernel's from the 2-D FFT of its first
 * row, kept in f->lam. */
static int eig_bounds(sf_field *f, double *mn, double *mx)
{
    size_t px = f->info.px, py = f->info.py;
    if (f->spec.sep_terms > 0) {
        int rc = sep_tables(f, px, py);
        if (!rc)
            rc = amp_fill(f);
        *mn = f->info.lambda_min;
        *mx = f->info.lambda_max;
        return rc;
    }
    free(f->lam);
    f->lam = sf_malloc(px * py * sizeof *f->lam);
    if (!f->lam)
        return SF_ENOMEM;
    int rc = eig_2d(f, px, py, f->lam);
    if (rc)
        return rc;
    min_max(f->lam, px * py, mn, mx);
    return SF_SUCCESS;
}

/* The shortest period that embeds a kernel vanishing (to round-off)
 * beyond `support` [m] along an axis of m points at spacing d: lags k <= m-1
 * must see rho(k d) in the first row, so wherever min(k, P - k) != k both
 * lags must lie beyond the support: P >= 2 S and P >= m - 1 + S, S the
 * support in samples.  No longer than the usual minimal period 2 (m - 1).
 * Exactness is not assumed: finish_plan measures cov_error on every lag. */
static size_t support_period(size_t m, double d, double support)
{
    size_t P = min_period(m);
    if (!(support > 0) || m <= 1)
        return P;
    double S = ceil(support / d) + 1;
    double q = fmax(2 * S, (double)(m - 1) + S);
    return q < (double)P ? (size_t)q : P;
}

static int build_general(sf_field *f)
{
    const sf_field_spec *s = &f->spec;
    size_t pxm = support_period(s->m, s->dx, s->support), pym = support_period(s->n, s->dy, s->support);
    size_t px = nice_size(pxm), py = nice_size(pym);
    size_t capx = (size_t)ceil(s->pad_cap * (double)pxm);
    size_t capy = (size_t)ceil(s->pad_cap * (double)pym);
    double mn = 0.0, mx = 0.0;
    int tries = 0;
    for (;;) {
        if (px > s->max_points / py)
            return SF_ETOOBIG;
        double prev = mx > 0 ? -mn / mx : 0;
        f->info.px = px;
        f->info.py = py;
        int rc = eig_bounds(f, &mn, &mx);
        if (rc)
            return rc;
        if (mn >= -s->eig_rel_tol * mx || s->no_padding)
            break;
        /* An indefinite kernel (e.g. a pre-corrected Nataf correlation) has
         * negatives that padding cannot remove: stop once a step no longer
         * halves the most negative eigenvalue, rather than pad to the cap. */
        if (tries++ > 0 && -mn / mx > 0.5 * prev)
            break;
        size_t nx = s->m > 1 ? nice_size(px + px / 4) : 1;
        size_t ny = s->n > 1 ? nice_size(py + py / 4) : 1;
        if ((nx > capx && s->m > 1) || (ny > capy && s->n > 1)
            || nx > s->max_points / ny)
            break;
        px = nx;
        py = ny;
    }
    f->info.px = px;
    f->info.py = py;
    f->info.separable = 0;
    f->info.truncated = mn < -s->eig_rel_tol * mx;
    f->M = px * py;
    return SF_SUCCESS;
}

/* The amplitudes (unless the padding loop made them for these periods)
 * and the sampling FFT's array: M complex values, or the half spectrum a
 * real sampler transforms in place (its real output in rows of 2 hx). */
static int finish_plan(sf_field *f)
{
    size_t px = f->info.px, py = f->info.py;
    int rc = f->spec.sep_terms == 0 ? amp_fill(f) : SF_SUCCESS;   /* the separable-sum path has them from eig_bounds */
    if (!rc)
        rc = work_for(f, f->spec.sample_real ? (px / 2 + 1) * py : px * py);
    if (rc)
        return rc;
    f->info.cov_error = NAN;   /* until measure_cov */
    return SF_SUCCESS;
}

/* The plan's 2-D FFT over f->work: complex to complex with `sign`, or
 * for a real sampler half spectrum to real, in place (the c2r direction is
 * FFTW_BACKWARD; the eigenvalues are even, so the sign changes nothing). */
static fftw_plan plan_2d(sf_field *f, int sign, unsigned flags)
{
    int px = (int)f->info.px, py = (int)f->info.py;
    if (f->spec.sample_real)
        return SF_FALLIBLE(fftw_plan_dft_c2r_2d(py, px, f->work, (double *)f->work, flags));
    return SF_FALLIBLE(fftw_plan_dft_2d(py, px, f->work, f->work, sign, flags));
}

/* The real output of the last transform at embedding point (i, j). */
static double produced(const sf_field *f, size_t i, size_t j)
{
    if (f->spec.sample_real)
        return ((const double *)f->work)[i + 2 * (f->info.px / 2 + 1) * j];
    return creal(f->work[i + f->info.px * j]);
}

/* The covariance the plan produces on the grid lags, by one inverse FFT of
 * the clamped eigenvalues in the work array, and its largest distance to
 * the target (info.cov_error). */
static int measure_cov(sf_field *f)
{
    const sf_field_spec *s = &f->spec;
    size_t px = f->info.px, py = f->info.py, M = f->M, hx = s->sample_real ? px / 2 + 1 : px;
    double invM = 1.0 / (double)M;
    double *cov = sf_malloc(s->m * s->n * sizeof *cov), *row = sf_malloc(px * sizeof *row);
    fftw_plan p = NULL;
    if (cov && row)
        p = plan_2d(f, FFTW_BACKWARD, FFTW_ESTIMATE);
    if (!p) {
        free(cov);
        free(row);
        return SF_ENOMEM;
    }
    for (size_t ky = 0; ky < py; ky++) {   /* the clamped eigenvalues (the stored half of a real sampler) */
        eig_row(f, ky, row);
        for (size_t kx = 0; kx < hx; kx++)
            f->work[kx + hx * ky] = row[kx] < 0.0 ? 0.0 : row[kx];
    }
    free(row);
    fftw_execute(p);
    fftw_destroy_plan(p);
    double err = 0.0;
    /* a separable-sum kernel's target at the true lags (i dx, j dy), i < m,
     * j < n, from 1-D tables: with a short-support period (px < 2 (m - 1))
     * a lag beyond px/2 is not in the first row, and the error of the
     * embedding there (the wrapped tail) must be measured, not assumed */
    double *ttx = NULL, *tty = NULL;
    size_t T = s->sep_terms > 0 ? (size_t)s->sep_terms : 0;
    if (T) {
        ttx = sf_malloc(T * s->m * sizeof *ttx);
        tty = sf_malloc(T * s->n * sizeof *tty);
        if (!ttx || !tty) {
            free(ttx);
            free(tty);
            free(cov);
            return SF_ENOMEM;
        }
        for (size_t t = 0; t < T; t++) {
            for (size_t i = 0; i < s->m; i++)
                ttx[i + s->m * t] = s->sep_fn((int)t, (double)i * s->dx, s->sep_params);
            for (size_t j = 0; j < s->n; j++)
                tty[j + s->n * t] = s->sep_fn((int)t, (double)j * s->dy, s->sep_params);
        }
    }
    for (size_t j = 0; j < s->n; j++)
        for (size_t i = 0; i < s->m; i++) {
            double v = produced(f, i % px, j % py) * invM;
            cov[i + s->m * j] = v;
            double tg = 0;
            if (T)
                for (size_t t = T; t-- > 0;)   /* kernel_at's order: smallest terms first */
                    tg += ttx[i + s->m * t] * tty[j + s->n * t];
            else
                tg = kernel_at(s, (double)i * s->dx, (double)j * s->dy);
            double e = fabs(v - tg);
            err = nan_max(err, e);
        }
    free(ttx);
    free(tty);
    f->cov = cov;
    f->info.cov_error = err;
    return SF_SUCCESS;
}

int sf_field_measure_covariance(sf_field *f)
{
    if (!f)
        return SF_EINVAL;
    return f->cov ? SF_SUCCESS : measure_cov(f);
}

static int spec_valid(const sf_field_spec *s)
{
    return s->m >= 1 && s->n >= 1 && isfinite(s->dx) && s->dx > 0.0
        && isfinite(s->dy) && s->dy > 0.0
        && (s->kernel || (s->sep_terms > 0 && s->sep_fn) || (isfinite(s->l) && s->l > 0.0))
        && !(s->sep_terms > 0 && !s->sep_fn)   /* sep_terms is read before kernel and l: a term needs its factor */
        && !(s->sample_real && s->sep_terms <= 0)   /* exactly even eigenvalues: sep_tables */
        && isfinite(s->eig_rel_tol) && s->eig_rel_tol >= 0.0
        && isfinite(s->pad_cap) && s->pad_cap >= 1.0 && s->max_points >= 1
        && s->m <= s->max_points && s->n <= s->max_points;
}

int sf_field_alloc(const sf_field_spec *spec, sf_field **out)
{
    *out = NULL;
    if (!spec || !spec_valid(spec))
        return SF_EINVAL;
    sf_field *f = sf_calloc(1, sizeof *f);
    if (!f)
        return SF_ENOMEM;
    f->spec = *spec;
    f->info.px_min = min_period(spec->m);
    f->info.py_min = min_period(spec->n);
    int rc = spec->kernel || spec->sep_terms > 0 ? build_general(f) : build_separable(f);
    if (!rc)
        rc = finish_plan(f);
    if (!rc && !spec->defer_covariance)
        rc = measure_cov(f);
    if (!rc) {
        /* FFTW_ESTIMATE: the same plan in every process (docs/design.md sec. 8).
         * FFTW_MEASURE overwrites work while timing: nothing in it is
         * needed any more (measure_cov has extracted the covariance, and
         * a deferred one refills it). */
        f->plan = plan_2d(f, FFTW_FORWARD, spec->measure ? FFTW_MEASURE : FFTW_ESTIMATE);
        if (!f->plan)
            rc = SF_ENOMEM;
    }
    if (rc) {
        sf_field_free(f);
        return rc;
    }
    *out = f;
    return f->info.truncated ? SF_ETRUNC : SF_SUCCESS;
}

void sf_field_free(sf_field *f)
{
    if (!f)
        return;
    if (f->plan)
        fftw_destroy_plan(f->plan);
    fftw_free(f->work);
    free(f->lx);
    free(f->ly);
    free(f->lam);
    free(f->amp);
    free(f->arow);
    free(f->cov);
    free(f->kept);
    free(f->tx);
    free(f->ty);
    free(f->sx);
    free(f->sy);
    free(f);
}

const sf_field_info *sf_field_get_info(const sf_field *f)
{
    return &f->info;
}

/* A real sampler's draw (Hermitian noise on the stored half spectrum,
 * then the c2r FFT): X = sum_k sqrt(lambda_k/M) xi_k e^{2 pi i j.k/M}
 * over the whole spectrum with xi_{-k} = conj(xi_k) is real, and with
 * E|xi_k|^2 = 1, E xi_k^2 = 0 (xi_k = (a + ib)/sqrt 2) off the
 * self-conjugate points (xi_k = a there) its covariance is the
 * circulant's sum_k lambda_k/M e^{2 pi i (j - j').k/M}: exact, because
 * the eigenvalues are exactly even (sep_tables).  The columns kx = 0 and
 * kx = px/2 hold both k and -k: their rows ky > py/2 are the conjugates of
 * the rows py - ky drawn before them.  M normals, one real field. */
static void draw_real(sf_field *f, gsl_rng *rng)
{
    size_t px = f->info.px, py = f->info.py, hx = px / 2 + 1;
    const double *amp = f->amp;
    fftw_complex *w = f->work;
    for (size_t ky = 0; ky < py; ky++) {
        size_t my = ky ? py - ky : 0;   /* the mirror row */
        for (size_t kx = 0; kx < hx; kx++) {
            size_t k = kx + hx * ky;
            int own_mirror = kx == 0 || 2 * kx == px;   /* -k is in the stored half too */
            if (own_mirror && my == ky) {
                w[k] = amp[k] * gsl_ran_gaussian_ziggurat(rng, 1.0);
            } else if (own_mirror && my < ky) {
                w[k] = conj(w[kx + hx * my]);
            } else {
                double a = gsl_ran_gaussian_ziggurat(rng, 1.0);
                double b = gsl_ran_gaussian_ziggurat(rng, 1.0);
                double c = amp[k] * M_SQRT1_2;
                w[k] = c * a + I * (c * b);
            }
        }
    }
    fftw_execute(f->plan);
}

/* Complex noise times the amplitudes, then the FFT: Re and Im are two
 * fields.  A separable kernel's amplitudes are made here a row at a time
 * from its 1-D eigenvalues (eig_row's product, amp_of: amp_fill's bits;
 * a loop the compiler vectorises, so about as fast as reading them). */
static void draw_and_transform(sf_field *f, gsl_rng *rng)
{
    size_t px = f->info.px, py = f->info.py;
    double invM = 1.0 / ((double)px * (double)py);
    fftw_complex *w = f->work;
    for (size_t ky = 0; ky < py; ky++) {
        const double *amp = f->amp ? f->amp + px * ky : f->arow;
        if (!f->amp) {
            const double *restrict lx = f->lx;
            double *restrict ar = f->arow, ly = f->ly[ky];
            for (size_t kx = 0; kx < px; kx++)
                ar[kx] = amp_of(lx[kx] * ly, invM);
        }
        for (size_t kx = 0; kx < px; kx++) {
            double a = gsl_ran_gaussian_ziggurat(rng, 1.0);
            double b = gsl_ran_gaussian_ziggurat(rng, 1.0);
            w[kx + px * ky] = amp[kx] * a + I * (amp[kx] * b);
        }
    }
    fftw_execute(f->plan);
}

/* The grid's part of the last FFT: Re into re, Im into im (im may be NULL:
 * not extracted; a real sampler has none). */
static void extract(const sf_field *f, double *re, double *im)
{
    size_t m = f->spec.m, n = f->spec.n, px = f->info.px;
    for (size_t j = 0; j < n; j++) {
        const fftw_complex *row = f->work + px * j;
        double *r = re + m * j;
        if (f->spec.sample_real) {
            memcpy(r, (const double *)f->work + 2 * (px / 2 + 1) * j, m * sizeof *r);
            continue;
        }
        for (size_t i = 0; i < m; i++)
            r[i] = creal(row[i]);
        if (im) {
            double *q = im + m * j;
            for (size_t i = 0; i < m; i++)
                q[i] = cimag(row[i]);
        }
    }
}

void sf_field_discard(sf_field *f)
{
    f->have_kept = 0;
}

int sf_field_sample_pair(sf_field *f, gsl_rng *rng, double *re, double *im)
{
    if (!f || !rng || !re || !im || re == im || f->spec.sample_real)
        return SF_EINVAL;
    draw_and_transform(f, rng);
    extract(f, re, im);
    f->have_kept = 0;
    return SF_SUCCESS;
}

int sf_field_sample(sf_field *f, gsl_rng *rng, double *out)
{
    if (!f || !rng || !out || f->spec.sample_real)
        return SF_EINVAL;
    size_t mn = f->spec.m * f->spec.n;
    if (f->have_kept) {
        memcpy(out, f->kept, mn * sizeof *out);
        f->have_kept = 0;
        return SF_SUCCESS;
    }
    if (!f->kept && !(f->kept = sf_malloc(mn * sizeof *f->kept)))   /* on first use: sf_field_sample_fresh needs none */
        return SF_ENOMEM;
    draw_and_transform(f, rng);
    extract(f, out, f->kept);
    f->have_kept = 1;
    return SF_SUCCESS;
}

int sf_field_sample_fresh(sf_field *f, gsl_rng *rng, double *out)
{
    if (!f || !rng || !out)
        return SF_EINVAL;
    if (f->spec.sample_real)
        draw_real(f, rng);
    else
        draw_and_transform(f, rng);
    extract(f, out, NULL);
    f->have_kept = 0;
    return SF_SUCCESS;
}

int sf_field_covariance(const sf_field *f, double *cov)
{
    if (!f || !cov || !f->cov)
        return SF_EINVAL;
    memcpy(cov, f->cov, f->spec.m * f->spec.n * sizeof *cov);
    return SF_SUCCESS;
}

double sf_field_target(const sf_field *f, double hx, double hy)
{
    return kernel_at(&f->spec, hx, hy);
}

int sf_field_first_row(const sf_field *f, double *row)
{
    if (!f || !row)
        return SF_EINVAL;
    for (size_t j = 0; j < f->info.py; j++)
        for (size_t i = 0; i < f->info.px; i++)
            row[i + f->info.px * j] = first_row_at(f, f->info.px, f->info.py, i, j);
    return SF_SUCCESS;
}

int sf_field_eigenvalues(const sf_field *f, double *lambda)
{
    if (!f || !lambda)
        return SF_EINVAL;
    for (size_t ky = 0; ky < f->info.py; ky++)
        eig_row(f, ky, lambda + f->info.px * ky);
    return SF_SUCCESS;
}

int sf_field_wisdom_import(const char *path)
{
    if (access(path, F_OK) != 0)
        return SF_SUCCESS;
    return fftw_import_wisdom_from_filename(path) ? SF_SUCCESS : SF_EIO;
}

int sf_field_wisdom_export(const char *path)
{
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.tmp%ld", path, (long)getpid()) >= (int)sizeof tmp)
        return SF_EIO;
    if (!fftw_export_wisdom_to_filename(tmp) || rename(tmp, path) != 0) {
        unlink(tmp);
        return SF_EIO;
    }
    return SF_SUCCESS;
}
