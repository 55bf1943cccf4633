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
#include <gsl/gsl_randist.h>

struct sf_field {
    sf_field_spec spec;
    sf_field_info info;
    size_t M;
    double *lx, *ly;        /* raw 1-D eigenvalues (separable path) */
    double *lam;            /* raw 2-D eigenvalues, before clamping */
    double *amp;            /* sqrt(max(lambda, 0)/M), length M */
    double *cov;            /* produced covariance at grid lags, m*n */
    fftw_complex *work;
    fftw_plan plan;
    double *kept;           /* second field of the last FFT */
    int have_kept;
    double *tx, *ty;        /* separable-sum kernel: sep_fn(t, min(i, px-i) dx) at tx[i + px t] (ty alike) */
    size_t tpx, tpy;        /* the periods the tables were made for */
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

/* 1-D eigenvalues of the squared-exponential circulant of period P. */
static int eig_1d(size_t P, double d, double l, double *lam)
{
    fftw_complex *buf = SF_FALLIBLE(fftw_alloc_complex(P));
    if (!buf)
        return SF_ENOMEM;
    fftw_plan p = SF_FALLIBLE(fftw_plan_dft_1d((int)P, buf, buf, FFTW_FORWARD, FFTW_ESTIMATE));
    if (!p) {
        fftw_free(buf);
        return SF_ENOMEM;
    }
    for (size_t j = 0; j < P; j++) {
        size_t jj = j < P - j ? j : P - j;
        buf[j] = sq_exp((double)jj * d, l);
    }
    fftw_execute(p);
    for (size_t k = 0; k < P; k++)
        lam[k] = creal(buf[k]);
    fftw_destroy_plan(p);
    fftw_free(buf);
    return SF_SUCCESS;
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
    f->M = px * py;
    f->lam = sf_malloc(f->M * sizeof *f->lam);
    if (!f->lam)
        return SF_ENOMEM;
    for (size_t j = 0; j < py; j++)
        for (size_t i = 0; i < px; i++)
            f->lam[i + px * j] = f->lx[i] * f->ly[j];
    return SF_SUCCESS;
}

/* The separable-sum kernel's 1-D tables for periods (px, py): each
 * factor once per lag, so the M entries of the first row cost
 * sep_terms multiply-adds each (the same sum, in the same order, as
 * kernel_at). */
static int sep_tables(sf_field *f, size_t px, size_t py)
{
    const sf_field_spec *s = &f->spec;
    size_t T = (size_t)s->sep_terms;
    free(f->tx);
    free(f->ty);
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
    return SF_SUCCESS;
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

/* General (non-separable) kernel: 2-D first row, 2-D FFT, pad both axes. */
static int eig_2d(sf_field *f, size_t px, size_t py, double *lam)
{
    size_t M = px * py;
    if (f->spec.sep_terms > 0) {
        int rc = sep_tables(f, px, py);
        if (rc)
            return rc;
    }
    fftw_complex *buf = SF_FALLIBLE(fftw_alloc_complex(M));
    if (!buf)
        return SF_ENOMEM;
    fftw_plan p = SF_FALLIBLE(fftw_plan_dft_2d((int)py, (int)px, buf, buf, FFTW_FORWARD, FFTW_ESTIMATE));
    if (!p) {
        fftw_free(buf);
        return SF_ENOMEM;
    }
    for (size_t j = 0; j < py; j++)
        for (size_t i = 0; i < px; i++)
            buf[i + px * j] = first_row_at(f, px, py, i, j);
    fftw_execute(p);
    for (size_t k = 0; k < M; k++)
        lam[k] = creal(buf[k]);
    fftw_destroy_plan(p);
    fftw_free(buf);
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
        free(f->lam);
        f->lam = sf_malloc(px * py * sizeof *f->lam);
        if (!f->lam)
            return SF_ENOMEM;
        int rc = eig_2d(f, px, py, f->lam);
        if (rc)
            return rc;
        double prev = mx > 0 ? -mn / mx : 0;
        min_max(f->lam, px * py, &mn, &mx);
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

/* Clamp the 2-D eigenvalues at zero (the nearest PSD circulant in the
 * Frobenius norm), set the sampling amplitudes sqrt(lambda+/M), and compute
 * the covariance this produces on the grid lags by one inverse FFT (done in
 * the work array before the sampling plan exists). */
static int finish_plan(sf_field *f)
{
    const sf_field_spec *s = &f->spec;
    size_t px = f->info.px, py = f->info.py, M = f->M;
    f->amp = sf_malloc(M * sizeof *f->amp);
    f->cov = sf_malloc(s->m * s->n * sizeof *f->cov);
    f->work = SF_FALLIBLE(fftw_alloc_complex(M));
    if (!f->amp || !f->cov || !f->work)
        return SF_ENOMEM;
    double mn, mx, invM = 1.0 / (double)M;
    min_max(f->lam, M, &mn, &mx);
    f->info.lambda_min = mn;
    f->info.lambda_max = mx;
    size_t nc = 0;
    for (size_t k = 0; k < M; k++) {
        double l = f->lam[k];
        if (l < 0.0) { l = 0.0; nc++; }
        f->amp[k] = sqrt(l * invM);
        f->work[k] = l;
    }
    f->info.n_clamped = nc;
    fftw_plan p = SF_FALLIBLE(fftw_plan_dft_2d((int)py, (int)px, f->work, f->work, FFTW_BACKWARD, FFTW_ESTIMATE));
    if (!p)
        return SF_ENOMEM;
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
            double v = creal(f->work[(i % px) + px * (j % py)]) * invM;
            f->cov[i + s->m * j] = v;
            double tg = 0;
            if (T)
                for (size_t t = T; t-- > 0;)   /* kernel_at's order: smallest terms first */
                    tg += ttx[i + s->m * t] * tty[j + s->n * t];
            else
                tg = kernel_at(s, (double)i * s->dx, (double)j * s->dy);
            double e = fabs(v - tg);
            err = nan_max(err, e);
        }
    f->info.cov_error = err;
    free(ttx);
    free(tty);
    return SF_SUCCESS;
}

static int spec_valid(const sf_field_spec *s)
{
    return s->m >= 1 && s->n >= 1 && isfinite(s->dx) && s->dx > 0.0
        && isfinite(s->dy) && s->dy > 0.0
        && (s->kernel || (s->sep_terms > 0 && s->sep_fn) || (isfinite(s->l) && s->l > 0.0))
        && !(s->sep_terms > 0 && !s->sep_fn)   /* sep_terms is read before kernel and l: a term needs its factor */
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
    if (!rc) {
        f->kept = sf_malloc(spec->m * spec->n * sizeof *f->kept);
        if (!f->kept)
            rc = SF_ENOMEM;
    }
    if (!rc) {
        /* FFTW_ESTIMATE: the same plan in every process (DESIGN sec. 8).
         * FFTW_MEASURE overwrites work while timing: nothing in it is
         * needed any more (finish_plan has extracted the covariance). */
        f->plan = SF_FALLIBLE(fftw_plan_dft_2d((int)f->info.py, (int)f->info.px, f->work, f->work, FFTW_FORWARD,
                                               spec->measure ? FFTW_MEASURE : FFTW_ESTIMATE));
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
    free(f->cov);
    free(f->kept);
    free(f->tx);
    free(f->ty);
    free(f);
}

const sf_field_info *sf_field_get_info(const sf_field *f)
{
    return &f->info;
}

static void draw_and_transform(sf_field *f, gsl_rng *rng)
{
    const double *amp = f->amp;
    fftw_complex *w = f->work;
    for (size_t k = 0; k < f->M; k++) {
        double a = gsl_ran_gaussian_ziggurat(rng, 1.0);
        double b = gsl_ran_gaussian_ziggurat(rng, 1.0);
        w[k] = amp[k] * a + I * (amp[k] * b);
    }
    fftw_execute(f->plan);
}

static void extract(const sf_field *f, double *re, double *im)
{
    size_t m = f->spec.m, n = f->spec.n, px = f->info.px;
    for (size_t j = 0; j < n; j++) {
        const fftw_complex *row = f->work + px * j;
        double *r = re + m * j, *q = im + m * j;
        for (size_t i = 0; i < m; i++) {
            r[i] = creal(row[i]);
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
    if (!f || !rng || !re || !im || re == im)
        return SF_EINVAL;
    draw_and_transform(f, rng);
    extract(f, re, im);
    f->have_kept = 0;
    return SF_SUCCESS;
}

int sf_field_sample(sf_field *f, gsl_rng *rng, double *out)
{
    if (!f || !rng || !out)
        return SF_EINVAL;
    size_t mn = f->spec.m * f->spec.n;
    if (f->have_kept) {
        memcpy(out, f->kept, mn * sizeof *out);
        f->have_kept = 0;
        return SF_SUCCESS;
    }
    draw_and_transform(f, rng);
    extract(f, out, f->kept);
    f->have_kept = 1;
    return SF_SUCCESS;
}

int sf_field_covariance(const sf_field *f, double *cov)
{
    if (!f || !cov)
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
    memcpy(lambda, f->lam, f->M * sizeof *lambda);
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
