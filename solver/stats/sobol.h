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

/* ---- Some blocks only
 *
 * The indices of input i need blocks A, B and A_B^(i) alone: a study of a
 * few inputs' indices runs 3n evaluations for one input, not n (d + 2).
 * `inputs` is a bit set, bit i for A_B^(i) (SF_SOBOL_ALL: every block);
 * A and B are always in.  The design (A, B) is the full one's, so input
 * i's indices are those of the full study bit for bit, but for rows the
 * full study excludes for a non-finite value in a block left out here. */
#define SF_SOBOL_ALL (~0UL)

/* Whether evaluation e is in a block of `inputs`: block A, B or A_B^(i)
 * with bit i set. */
int sf_sobol_in_blocks(const sf_sobol_design *D, unsigned long inputs, size_t e);

/* sf_sobol_estimate over the blocks of `inputs` (y of the other blocks
 * is never read): a row is excluded for a non-finite value in those
 * blocks only, and the indices of an input left out are NAN (estimates,
 * intervals, resamples).  SF_EINVAL also when `inputs` has no bit below
 * d. */
int sf_sobol_estimate_some(const sf_sobol_design *D, unsigned long inputs, const double *y, size_t stride,
                           size_t nboot, double level, unsigned long seed, sf_sobol_result *res, double *boot);

/* ---- Given data: the rank-based first-order index
 *
 * From n plain Monte Carlo rows (x_j, y_j), x_j in R^d with independent
 * entries, no pick-freeze design: for each input i sort the rows by x_i
 * (ties by row index: an order that does not look at y, so tied rows stay
 * exchangeable), let N(j) be the row after j in that order, the last
 * wrapping to the first, and
 *
 *   S_i = ( (1/n) sum_j y_j y_N(j) - ybar^2 ) / ( (1/n) sum_j y_j^2 - ybar^2 )
 *
 * (Gamboa, Gremaud, Klein & Lagnoux 2022, "Global sensitivity analysis: a
 * novel generation of mighty estimators based on rank statistics",
 * Bernoulli 28(4), 2345-2374, sec. 3; Chatterjee 2021's construction with
 * y's values for its ranks).  The wrap makes N a permutation, so the
 * numerator is exactly (1/n) sum_j (y_j - ybar)(y_N(j) - ybar): computed
 * so, centred, it loses nothing to a large mean.  Consistent, one sort per
 * input, bias O(1/n) (ybar^2's Var(y)/n, the wrapped pair).
 *
 * Intervals: not the bootstrap.  A resample with replacement repeats
 * rows, and a repeated row is its own neighbour: about 1 - 1/e of the
 * pairs become y_j^2, which drags every resampled index towards 1 (the
 * n-out-of-n bootstrap of Chatterjee's coefficient is inconsistent: Lin &
 * Han 2024, Biometrika 111; Dalitz et al. 2024 measure its coverage near
 * 0, arXiv:2312.15496).  The paper's CLT variance (and its 2023 erratum)
 * needs conditional moments of y that would have to be estimated too.  So the standard error comes from random
 * splits, a subsampling method without replacement (no repeated rows):
 * the rows are dealt at random into K groups of about b = n/K rows, the
 * estimator is computed in each group (ranks within the group: the
 * global order restricted to it), and since sqrt(b) (S_b - S) and
 * sqrt(n) (S_n - S) have the same normal limit, Var(S_n) = Var(S_b) b/n
 * = s^2 / K with s^2 the variance of the K group estimates.  K =
 * floor(cbrt(n)) (at least 2, groups of at least 2 rows): b and K both
 * grow with n.  s^2 / K is averaged over nsplit independent splits (one
 * split's s^2 has only K - 1 degrees of freedom), and the interval is
 * S_n -/+ z se, z the normal quantile at the level.  The splits are drawn
 * from MT19937 seeded from seed, the same splits for every input:
 * reproducible bit for bit.
 *
 * A row with a non-finite y or a non-finite x_i (any i < d) is excluded
 * (counted, never used).
 */

typedef struct {
    double s1;          /* the estimate */
    double lo, hi;      /* s1 -/+ z se at the level asked (NAN: no se) */
    double se;          /* standard error from the random splits (NAN: none) */
} sf_sobol_rank_index;

typedef struct {
    size_t n_used, n_excluded;   /* rows */
    double mean, var;            /* of y over the used rows (var: the estimator's 1/n divisor) */
    size_t groups;               /* K, the groups of a split (0: too few rows for a se) */
    size_t nsplit, nsplit_used;  /* splits asked for, and those with 2 or more groups of V > 0 (the se's) */
    double level;
    sf_sobol_rank_index idx[SF_SOBOL_MAXD];
} sf_sobol_rank_result;

/* The rank-based first-order indices of y on the d inputs of n rows:
 * x[j xstride + i] is input i of row j (xstride >= d: the d inputs may be
 * the leading columns of a wider matrix), y[j ystride] its output.
 * nsplit random splits for the se (0: no se or interval, NAN), level in
 * (0, 1).  With fewer than 4 usable rows no split has two groups: groups
 * = 0, NAN se.
 * SF_EINVAL for d = 0 or d > SF_SOBOL_MAXD, xstride < d, a bad level, n <
 * 3 or fewer than 3 usable rows (res->n_used, n_excluded say how many);
 * SF_EFAIL when y is constant over the used rows (no index); SF_ENOMEM.
 *
 * The sensitivity study's runs as given data (sensitivity.h: S->x is
 * nevals x SF_SENS_NPAR parameters, S->y nevals x 2 SF_SWEEP_NQ outputs,
 * evaluation e = k n + j): blocks A and B (evaluations 0 .. 2n - 1) are
 * 2n independent draws of the parameters, so the indices of output q on
 * the SF_SENS_NPAR parameter columns are
 *
 *   sf_sobol_rank_s1(2 * n, SF_SENS_NPAR, S->x, SF_SENS_NPAR,
 *                    S->y + q, 2 * SF_SWEEP_NQ, 200, 0.95, seed, &res);
 *
 * (the A_B^(i) blocks repeat A's columns but for one: not independent
 * rows, leave them out).  Column i alone: x = S->x + i, d = 1, xstride =
 * SF_SENS_NPAR.  The field input has no column: its first-order index is
 * not given-data. */
int sf_sobol_rank_s1(size_t n, size_t d, const double *x, size_t xstride, const double *y, size_t ystride,
                     size_t nsplit, double level, unsigned long seed, sf_sobol_rank_result *res);

#ifdef __cplusplus
}
#endif
#endif
