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

/* Two-sided normal p-value of a z statistic. */
double sf_z_pvalue(double z);

/* Upper tail of chi-square with nu degrees of freedom. */
double sf_chisq_pvalue(double x, double nu);

/* Two-sided p-value of the sample variance s2 of n iid normal values
 * against sigma2 (chi-square with n-1 dof, or n dof if mean_known). */
double sf_var_pvalue(double s2, double sigma2, size_t n, int mean_known);

/* Standard normal CDF as an sf_cdf_fn. */
double sf_cdf_normal(double x, void *params);

#endif
