/* slipfield verification: statistical tests (GSL for distributions,
 * sorting and moments).  All p-values are upper-tail probabilities of the
 * test statistic under the null hypothesis. */
#ifndef SF_STATS_H
#define SF_STATS_H

#include <stddef.h>

typedef double (*sf_cdf_fn)(double x, void *params);

/* Kolmogorov distribution: P(sqrt(n_eff) D > ...) with Stephens' small-n
 * correction (accurate to ~1e-3 relative for n_eff >= 20). */
double sf_ks_pvalue(double n_eff, double D);

/* One-sample KS test of x[0..n) against cdf; sorts x in place. */
double sf_ks_test(double *x, size_t n, sf_cdf_fn cdf, void *params, double *D);

/* Two-sample KS test; sorts both arrays in place. */
double sf_ks2_test(double *a, size_t na, double *b, size_t nb, double *D);

/* One-sided Mann-Whitney U (Wilcoxon rank-sum) test that a's values tend
 * to exceed b's: U = the pairs (a_i, b_j) with a_i > b_j (a tie counts
 * 1/2), p = Q((U - na nb / 2 - 1/2) / sd), sd with the tie correction;
 * the normal approximation, good to about 1e-3 in p for na, nb >= 10.
 * A few extreme values move U by at most their count times the other
 * sample's size, so the test keeps its power under heavy tails.  NaN if a
 * value is not finite or a sample has fewer than 2.  Sorts neither
 * array (allocates their pooled ranks). */
double sf_mwu_greater_p(const double *a, size_t na, const double *b, size_t nb);

/* Two-sided normal p-value of a z statistic. */
double sf_z_pvalue(double z);

/* Upper tail of chi-square with nu degrees of freedom. */
double sf_chisq_pvalue(double x, double nu);

/* Two-sided p-value of the sample variance s2 of n iid normal values
 * against sigma2 (chi-square with n-1 dof, or n dof if mean_known). */
double sf_var_pvalue(double s2, double sigma2, size_t n, int mean_known);

/* The test of the interval null |theta| <= margin from an estimate est
 * with standard error se (Student t, df): p = Q_t((|est| - margin) / se)
 * + Q_t((|est| + margin) / se), exact for a normal estimate at the
 * boundary and conservative inside it; a small p shows |theta| > margin.
 * se = 0: 1 inside the margin, 0 outside. */
double sf_interval_null_p(double est, double se, double margin, double df);

/* One-sided test of H0 "the RMS of e[0..n) is at most b": Student's t on
 * the squares (n - 1 dof), p = Q_t((mean(e^2) - b^2) / se(e^2)).  For
 * right-skewed squares (heavy-tailed errors) the upper t test is
 * conservative: a large mean comes with a large sd.  A non-finite e or
 * n < 2 gives 0 (the case fails); zero spread: 1 if mean(e^2) <= b^2,
 * else 0. */
double sf_rms_le_pvalue(const double *e, size_t n, double b);

/* The two-sided exact binomial test of an interval procedure's coverage:
 * H0 "coverage in [clo, chi]" from x of R intervals covering.
 * sf_cov_pvalue: p = 2 min(P(X <= x | clo), P(X >= x | chi)), at most 1;
 * its size is at most alpha at every c in [clo, chi] (each tail is
 * largest at its own end of H0).  sf_cov_region: the counts [*lo, *hi]
 * whose p is at least alpha.  sf_cov_reject: the probability of a count
 * outside [lo, hi] at true coverage c (the power there, or the
 * false-alarm rate inside H0). */
double sf_cov_pvalue(unsigned x, unsigned R, double clo, double chi);
void sf_cov_region(unsigned R, double clo, double chi, double alpha, unsigned *lo, unsigned *hi);
double sf_cov_reject(unsigned R, unsigned lo, unsigned hi, double c);

/* The Clopper-Pearson 95% interval [*lo, *hi] of a rate from k of n.
 * gsl_cdf_beta_Pinv, by bisection on gsl_cdf_beta_P where it returns NaN
 * (GSL's inverse does not converge for some parameters in the thousands). */
void sf_clopper_pearson(double k, double n, double *lo, double *hi);

/* Standard normal CDF as an sf_cdf_fn. */
double sf_cdf_normal(double x, void *params);

/* NaN-propagating aggregation (docs/design.md sec. 7.6).  fmax/fmin and `if (x > m)`
 * silently drop a NaN, so a NaN at one lag, point or realisation would
 * vanish from a max and the case pass: every max/min a check aggregates
 * goes through these instead.  A NaN argument gives NaN; an Inf is kept
 * by the ordinary comparison. */
double sf_max(double a, double b);
double sf_min(double a, double b);

/* Test-only fault injection (tests/test_nonfinite.c): with
 * sf_poison_set(k), k >= 0, the k-th value (0-based, counted from the
 * call) that passes through the aggregation -- a value sf_max/sf_min
 * returns (one each) or an element handed to sf_result_data (n each) --
 * is replaced by a NaN, as a defect at that lag, point or realisation
 * would put it there.  sf_poison_set(-1) turns it off
 * (the default: the helpers then only count).  sf_poison_hit() says
 * whether the poisoned value was reached. */
void sf_poison_set(long k);
int sf_poison_hit(void);
/* Used by sf_result_data: poison x[0..n) if the k-th value is among them. */
void sf_poison_array(double *x, size_t n);

#endif
