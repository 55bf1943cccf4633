/* slipfield: Sobol' indices by pick-freeze, for any model of d inputs.
 *
 * Two independent sample matrices A and B (n rows, d columns, uniform on
 * [0, 1)^d) and, for each input i, A_B^(i): A with column i taken from B.
 * The model is evaluated at n (d + 2) points; evaluation e = k n + j is row
 * j of block k (0: A, 1: B, 2 + i: A_B^(i)).  With V the variance of the
 * 2n values f(A), f(B):
 *
 *   first order (Saltelli et al. 2010)  S_i  = mean_j (f(B)_j - f0) (f(A_B^i)_j - f(A)_j) / V
 *   total (Jansen 1999)                 S_Ti = mean_j (f(A)_j - f(A_B^i)_j)^2 / (2 V)
 *
 * f0 the mean of those 2n values.  Saltelli's estimator is the same in
 * expectation for any shift of f, but its variance grows with f0^2 / V:
 * for a QoI ratio near 1 with a spread of 0.1 that is a factor of 100.
 * Centring removes it at a bias of order V / n (f0 shares two of the 2n
 * values with each row's difference).
 *
 * Confidence intervals by the bootstrap over rows (percentile intervals;
 * every block of a row is resampled together, so the correlation between
 * the numerators and V is kept): the estimators are ratios of means whose
 * delta-method variance needs the joint covariance of d + 1 means, and
 * at the small n a simulator affords the percentile interval also follows
 * the skew of a ratio.  The resampling stream is MT19937 seeded from the
 * caller's seed: the intervals are reproducible bit for bit.
 *
 * A row with a non-finite value in any of its d + 2 evaluations is
 * excluded (counted, never used), so the indices stay paired estimates.
 */
#ifndef SF_SOBOL_H
#define SF_SOBOL_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <gsl/gsl_rng.h>

#define SF_SOBOL_MAXD 32   /* inputs at most */

typedef struct {
    size_t n, d;     /* rows, inputs */
    double *a, *b;   /* n x d each, row-major, uniform on [0, 1) */
} sf_sobol_design;

/* A and B from rng (A's n d values first, then B's).  SF_EINVAL for n < 2,
 * d = 0 or d > SF_SOBOL_MAXD, SF_ETOOBIG when n (d + 2) overflows. */
int sf_sobol_design_alloc(size_t n, size_t d, gsl_rng *rng, sf_sobol_design **out);
void sf_sobol_design_free(sf_sobol_design *D);

/* n (d + 2), the model evaluations the design asks for. */
size_t sf_sobol_nevals(const sf_sobol_design *D);

/* u[0..d): the point of evaluation e (e < sf_sobol_nevals). */
void sf_sobol_point(const sf_sobol_design *D, size_t e, double *u);

/* Whose row column i of evaluation e is: j when it is A's row j, n + j
 * when B's.  A model input that is not a number (a random stream, a field
 * realisation) is keyed by this: evaluations that share it share the input. */
size_t sf_sobol_source_row(const sf_sobol_design *D, size_t e, size_t i);

typedef struct {
    double s1, st;                  /* the estimates */
    double s1_lo, s1_hi, st_lo, st_hi;   /* bootstrap percentile interval at the level asked */
    double s1_se, st_se;            /* bootstrap standard deviations */
} sf_sobol_index;

typedef struct {
    size_t n_used, n_excluded;      /* rows */
    double mean, var;               /* of f over A and B (var: n - 1 divisor over the 2 n_used values) */
    size_t nboot, nboot_used;       /* resamples asked for, and those with V > 0 (the intervals') */
    double level;
    sf_sobol_index idx[SF_SOBOL_MAXD];
} sf_sobol_result;

/* The indices of one output: y[e stride] is f at evaluation e.  nboot
 * bootstrap resamples (0: no interval, NAN ends) at level in (0, 1).
 * boot (NULL: not wanted) receives the resamples, nboot x 2d: row b holds
 * S_1..S_d then S_T1..S_Td of resample b, for b < res->nboot_used (a
 * statistic of several indices, e.g. a difference, has its interval from
 * these paired rows).
 * SF_EINVAL for a bad level or fewer than 2 usable rows; SF_EFAIL when
 * V is 0 (a constant output has no indices); SF_ENOMEM. */
int sf_sobol_estimate(const sf_sobol_design *D, const double *y, size_t stride, size_t nboot, double level,
                      unsigned long seed, sf_sobol_result *res, double *boot);

#ifdef __cplusplus
}
#endif
#endif
