/* The statistical tests the checks gate on (stats.h), the NaN-propagating
 * max and min, and the test-only NaN poison. */
#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sort.h>

double sf_ks_pvalue(double n_eff, double D)
{
    double sn = sqrt(n_eff);
    double lam = (sn + 0.12 + 0.11 / sn) * D;
    if (lam < 0.2)
        return 1.0;
    /* Q_KS(lam) = 2 sum_{k>=1} (-1)^(k-1) exp(-2 k^2 lam^2) */
    double sum = 0.0, sign = 1.0;
    for (int k = 1; k <= 100; k++) {
        double t = sign * exp(-2.0 * k * k * lam * lam);
        sum += t;
        if (fabs(t) < 1e-16 * fabs(sum))
            break;
        sign = -sign;
    }
    double p = 2.0 * sum;
    return p < 0 ? 0 : (p > 1 ? 1 : p);
}

/* A NaN in a sample has no place in a sorted order (gsl_sort and the
 * merge below would silently step over it): the test is then NaN. */
static int any_nan(const double *x, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (isnan(x[i]))
            return 1;
    return 0;
}

double sf_ks_test(double *x, size_t n, sf_cdf_fn cdf, void *params, double *D)
{
    if (any_nan(x, n)) {
        if (D) *D = NAN;
        return NAN;
    }
    gsl_sort(x, 1, n);
    double d = 0.0;
    for (size_t i = 0; i < n; i++) {
        double F = cdf(x[i], params);
        double lo = F - (double)i / (double)n, hi = (double)(i + 1) / (double)n - F;
        d = sf_max(d, sf_max(lo, hi));
    }
    if (D) *D = d;
    return sf_ks_pvalue((double)n, d);
}

double sf_ks2_test(double *a, size_t na, double *b, size_t nb, double *D)
{
    if (any_nan(a, na) || any_nan(b, nb)) {
        if (D) *D = NAN;
        return NAN;
    }
    gsl_sort(a, 1, na);
    gsl_sort(b, 1, nb);
    size_t i = 0, j = 0;
    double d = 0.0;
    while (i < na && j < nb) {
        double v = a[i] < b[j] ? a[i] : b[j];
        while (i < na && a[i] <= v) i++;
        while (j < nb && b[j] <= v) j++;
        double diff = fabs((double)i / (double)na - (double)j / (double)nb);
        d = sf_max(d, diff);
    }
    if (D) *D = d;
    return sf_ks_pvalue((double)na * (double)nb / (double)(na + nb), d);
}

typedef struct {
    double v;
    int from_a;
} mwu_item;

static int mwu_cmp(const void *x, const void *y)
{
    double u = ((const mwu_item *)x)->v, w = ((const mwu_item *)y)->v;
    return (u > w) - (u < w);
}

double sf_mwu_greater_p(const double *a, size_t na, const double *b, size_t nb)
{
    if (na < 2 || nb < 2 || any_nan(a, na) || any_nan(b, nb))
        return NAN;
    size_t n = na + nb;
    mwu_item *it = malloc(n * sizeof *it);
    if (!it)
        return NAN;
    for (size_t i = 0; i < na; i++)
        it[i] = (mwu_item){ a[i], 1 };
    for (size_t j = 0; j < nb; j++)
        it[na + j] = (mwu_item){ b[j], 0 };
    qsort(it, n, sizeof *it, mwu_cmp);
    double ra = 0, ties = 0;   /* a's rank sum (mid-ranks), sum of t^3 - t over tied groups */
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && it[j].v == it[i].v)
            j++;
        double mid = 0.5 * (double)(i + 1 + j), t = (double)(j - i);
        for (size_t k = i; k < j; k++)
            ra += it[k].from_a ? mid : 0;
        ties += t * t * t - t;
        i = j;
    }
    free(it);
    double fa = (double)na, fb = (double)nb, fn = (double)n;
    double u = ra - fa * (fa + 1) / 2;
    double var = fa * fb / 12 * ((fn + 1) - ties / (fn * (fn - 1)));
    if (!(var > 0))
        return u > fa * fb / 2 ? 0 : 1;
    return gsl_cdf_ugaussian_Q((u - fa * fb / 2 - 0.5) / sqrt(var));
}

double sf_z_pvalue(double z)
{
    return 2.0 * gsl_cdf_ugaussian_Q(fabs(z));
}

double sf_interval_null_p(double est, double se, double margin, double df)
{
    if (!(se > 0))
        return fabs(est) <= margin ? 1 : 0;
    return sf_min(1, gsl_cdf_tdist_Q((fabs(est) - margin) / se, df) + gsl_cdf_tdist_Q((fabs(est) + margin) / se, df));
}

double sf_chisq_pvalue(double x, double nu)
{
    return gsl_cdf_chisq_Q(x, nu);
}

double sf_var_pvalue(double s2, double sigma2, size_t n, int mean_known)
{
    double nu = (double)(mean_known ? n : n - 1);
    double x = nu * s2 / sigma2;
    double lo = gsl_cdf_chisq_P(x, nu), hi = gsl_cdf_chisq_Q(x, nu);
    double p = 2.0 * (lo < hi ? lo : hi);
    return p > 1 ? 1 : p;
}

double sf_rms_le_pvalue(const double *e, size_t n, double b)
{
    if (n < 2)
        return 0;
    double m = 0, v = 0;
    for (size_t i = 0; i < n; i++)
        m += e[i] * e[i] / (double)n;
    for (size_t i = 0; i < n; i++)
        v += (e[i] * e[i] - m) * (e[i] * e[i] - m) / (double)(n - 1);
    double se = sqrt(v / (double)n);
    if (!isfinite(m) || !isfinite(se))
        return 0;
    return se > 0 ? gsl_cdf_tdist_Q((m - b * b) / se, (double)n - 1) : (m <= b * b ? 1 : 0);
}

double sf_cdf_normal(double x, void *params)
{
    (void)params;
    return gsl_cdf_ugaussian_P(x);
}

/* ---- NaN-propagating aggregation and its test-only poison ---- */

static long poison_k = -1, poison_seen = 0;
static int poison_hit = 0;

void sf_poison_set(long k)
{
    poison_k = k;
    poison_seen = 0;
    poison_hit = 0;
}

int sf_poison_hit(void) { return poison_hit; }

/* The value that enters an aggregation: NaN when it is the poisoned one. */
static double pass_value(double a)
{
    if (poison_k < 0)
        return a;
    if (poison_seen++ == poison_k) {
        poison_hit = 1;
        return NAN;
    }
    return a;
}

void sf_poison_array(double *x, size_t n)
{
    if (poison_k < 0 || !x)
        return;
    if (poison_k >= poison_seen && poison_k - poison_seen < (long)n) {
        x[poison_k - poison_seen] = NAN;
        poison_hit = 1;
    }
    poison_seen += (long)n;
}

double sf_max(double a, double b)
{
    if (isnan(a) || isnan(b))
        return NAN;
    return pass_value(a > b ? a : b);
}

double sf_min(double a, double b)
{
    if (isnan(a) || isnan(b))
        return NAN;
    return pass_value(a < b ? a : b);
}

double sf_cov_pvalue(unsigned x, unsigned R, double clo, double chi)
{
    double pl = gsl_cdf_binomial_P(x, clo, R), ph = x ? gsl_cdf_binomial_Q(x - 1, chi, R) : 1;
    return fmin(1, 2 * fmin(pl, ph));
}

void sf_cov_region(unsigned R, double clo, double chi, double alpha, unsigned *lo, unsigned *hi)
{
    unsigned l = 0, h = R;
    while (l < R && gsl_cdf_binomial_P(l, clo, R) < alpha / 2)
        l++;
    while (h > 0 && gsl_cdf_binomial_Q(h - 1, chi, R) < alpha / 2)
        h--;
    *lo = l;
    *hi = h;
}

double sf_cov_reject(unsigned R, unsigned lo, unsigned hi, double c)
{
    double below = lo ? gsl_cdf_binomial_P(lo - 1, c, R) : 0, above = hi < R ? gsl_cdf_binomial_Q(hi, c, R) : 0;
    return below + above;
}

static double beta_inv(double P, double a, double b)
{
    double x = gsl_cdf_beta_Pinv(P, a, b);
    if (isfinite(x))
        return x;
    double lo = 0, hi = 1;
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi);
        *(gsl_cdf_beta_P(mid, a, b) < P ? &lo : &hi) = mid;
    }
    return 0.5 * (lo + hi);
}

void sf_clopper_pearson(double k, double n, double *lo, double *hi)
{
    *lo = k > 0 ? beta_inv(0.025, k, n - k + 1) : 0;
    *hi = k < n ? beta_inv(0.975, k + 1, n - k) : 1;
}
