/* slipfield: homogeneous Gaussian random fields on a regular 2-D grid by
 * circulant embedding (paper Appendix A; Dietrich & Newsam 1997).
 *
 * Plan once, sample many (FFTW idiom): sf_field_alloc() sizes the
 * embedding, pads it until its eigenvalues are non-negative to a relative
 * round-off floor (or a cap is reached), computes the eigenvalues with FFTW
 * and plans the sampling FFT.  sf_field_sample() then costs one complex FFT
 * of the embedding size per *two* independent fields (real and imaginary
 * parts), plus the normal draws.
 *
 * Grid layout everywhere: value at (x_i, y_j) = (i dx, j dy) is out[i + m*j],
 * i = 0..m-1 (x fastest), j = 0..n-1.
 *
 * Correlation: R(r) = exp(-r^2/l^2) (Eq. 2) by default.  That kernel is
 * separable, R(dx,dy) = exp(-dx^2/l^2) exp(-dy^2/l^2), so the 2-D circulant
 * eigenvalues are the outer product of two 1-D sets: padding is decided per
 * axis at the cost of two 1-D FFTs.  A user kernel rho(r) (e.g. the
 * pre-corrected Gaussian correlation of a lognormal field) takes the general
 * 2-D path.
 */
#ifndef SF_FIELD_H
#define SF_FIELD_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <gsl/gsl_rng.h>

/* Isotropic correlation rho(r), r >= 0 in metres, rho(0) = 1. */
typedef double (*sf_kernel_fn)(double r, void *params);

/* One factor of an anisotropic correlation that is a sum of separable
 * terms, rho(hx, hy) = sum_t f(t, hx) f(t, hy), t < sep_terms (the
 * cell-averaged COF of cellavg.h): the factor of term t at lag d [m]. */
typedef double (*sf_septerm_fn)(int term, double d, void *params);

typedef struct {
    size_t m, n;          /* grid points along x and y (>= 1 each) */
    double dx, dy;        /* grid spacings [m] (> 0) */
    double l;             /* correlation length l [m] of Eq. 2 (> 0) */
    sf_kernel_fn kernel;  /* NULL: squared exponential exp(-r^2/l^2) */
    void *kernel_params;
    int sep_terms;        /* > 0: rho = sum of separable terms sep_fn (kernel and l unused);
                             the general 2-D path, its first row from 1-D tables */
    sf_septerm_fn sep_fn;
    void *sep_params;
    double support;       /* > 0 (general path): rho is zero to round-off at lags beyond this [m]
                             along either axis, so a period of m - 1 + support/dx suffices
                             (instead of 2 (m - 1)); cov_error measures what it gives */
    double eig_rel_tol;   /* accept lambda_min >= -tol*lambda_max; 0 -> 1e-12 */
    double pad_cap;       /* max embedding period per axis as a multiple of
                             the minimal one; 0 -> 16 */
    size_t max_points;    /* cap on the embedding size M; 0 -> 2^25 */
    int no_padding;       /* 1: minimal embedding only (truncate if needed) */
    int defer_covariance; /* 1: sf_field_alloc does not compute the produced
                             covariance (an inverse FFT of the embedding and a
                             pass over the grid, about a third of planning a
                             large strip): info->cov_error is NaN and
                             sf_field_covariance refuses until
                             sf_field_measure_covariance.  For plans that only
                             sample (the COF plan of a run); verification
                             measures.  0: computed at planning. */
    int sample_real;      /* 1 (separable-sum kernels): one field per FFT, from
                             Hermitian noise by a real (c2r) FFT: half the
                             normals and about half the transform of a pair,
                             for plans whose draws are each a function of
                             their stream alone (sf_field_sample_fresh only;
                             sf_field_sample and _pair refuse).  Same
                             covariance, exactly: the eigenvalues are made
                             exactly even.  0: complex FFT, two fields each. */
    int measure;          /* 1: plan the sampling FFT with FFTW_MEASURE (up to ~3x
                             faster on large power-of-two embeddings, make bench);
                             the plan it times its way to, and so the last bits of
                             a sample, may differ between processes unless they
                             import the same wisdom (sf_field_wisdom_*).  0:
                             FFTW_ESTIMATE, the same plan everywhere. */
} sf_field_spec;

typedef struct {
    size_t px, py;          /* embedding periods per axis; M = px*py */
    size_t px_min, py_min;  /* minimal embedding periods (2(m-1), 2(n-1)) */
    int separable;          /* 1 when the outer-product path was used */
    int truncated;          /* 1 when the cap was hit and negatives clamped */
    size_t n_clamped;       /* 2-D eigenvalues clamped to zero (round-off or truncation) */
    double lambda_max;      /* largest 2-D eigenvalue */
    double lambda_min;      /* smallest 2-D eigenvalue before clamping */
    double cov_error;       /* max |C_produced - Sigma| over the grid lags:
                               exact, computed from the clamped eigenvalues
                               (NaN while deferred: defer_covariance) */
} sf_field_info;

typedef struct sf_field sf_field;

/* Fill a spec with defaults for an m x n grid (tolerances, caps). */
void sf_field_spec_default(sf_field_spec *spec, size_t m, size_t n,
                           double dx, double dy, double l);

/* Returns SF_SUCCESS, or SF_ETRUNC when the padding cap was reached: the plan
 * is still usable (negative eigenvalues clamped, error in info->cov_error;
 * test with sf_usable()).  SF_EINVAL / SF_ENOMEM / SF_ETOOBIG (embedding
 * over spec->max_points) leave *out = NULL. */
int sf_field_alloc(const sf_field_spec *spec, sf_field **out);
void sf_field_free(sf_field *f);

const sf_field_info *sf_field_get_info(const sf_field *f);

/* Draw one standard Gaussian field (mean 0, variance 1, correlation R) into
 * out[m*n].  Each FFT yields two independent fields; the second is kept and
 * returned by the next call, so consecutive calls cost half an FFT each.
 * The stream is a deterministic function of the rng state. */
int sf_field_sample(sf_field *f, gsl_rng *rng, double *out);

/* Forget the kept second field, so the next sample is a function of the
 * rng state alone (Monte Carlo with per-realisation streams). */
void sf_field_discard(sf_field *f);

/* One field as a function of the rng state alone: the same values as
 * sf_field_discard then sf_field_sample, without copying (or keeping) the
 * FFT's second field; a real sampler's one field (spec.sample_real).
 * Discards any kept field. */
int sf_field_sample_fresh(sf_field *f, gsl_rng *rng, double *out);

/* Draw both fields of one FFT at once into distinct arrays re, im of m*n.
 * Discards any kept field. */
int sf_field_sample_pair(sf_field *f, gsl_rng *rng, double *re, double *im);

/* The covariance the generator actually produces, no sampling:
 * cov[i + m*j] = Cov(G(0,0), G(i dx, j dy)), i < m, j < n.  By symmetry of
 * the embedding this also gives the lags (-i, j), (i, -j), (-i, -j).
 * SF_EINVAL for a plan whose covariance is deferred and not yet measured. */
int sf_field_covariance(const sf_field *f, double *cov);

/* Compute a deferred plan's produced covariance and info->cov_error (the
 * same values sf_field_alloc computes without defer_covariance); nothing to
 * do when they are there.  It plans an inverse FFT: call it where plans
 * are made (not while another thread samples this plan).  SF_ENOMEM. */
int sf_field_measure_covariance(sf_field *f);

/* The target correlation at lag (i dx, j dy) (Sigma's entries). */
double sf_field_target(const sf_field *f, double hx, double hy);

/* The first row of the block-circulant embedding (Appendix A, step 2):
 * row[i + px*j] = rho(min(i, px-i) dx, min(j, py-j) dy); length px*py. */
int sf_field_first_row(const sf_field *f, double *row);

/* FFTW wisdom (plans found by FFTW_MEASURE) from and to a file, so that
 * processes importing the same file make the same plans.  Import: SF_EIO
 * when the file exists but is unreadable or not wisdom (a missing file is
 * SF_SUCCESS: nothing to import).  Export: written to a temporary name
 * and renamed, so a killed run leaves the old file whole. */
int sf_field_wisdom_import(const char *path);
int sf_field_wisdom_export(const char *path);

/* The 2-D embedding eigenvalues (length px*py, index kx + px*ky), before
 * clamping.  Exposed for verification (FFT vs direct DFT). */
int sf_field_eigenvalues(const sf_field *f, double *lambda);

#ifdef __cplusplus
}
#endif
#endif
