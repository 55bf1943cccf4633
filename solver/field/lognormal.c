/* slipfield: lognormal marginals by the Nataf map of Sec. 2.2
 * (lognormal.h) and the correlation distortion between the Gaussian and
 * the lognormal field. */
#include "lognormal.h"
#include "sf_error.h"

#include <math.h>
#include <gsl/gsl_cdf.h>

int sf_lognormal_init(sf_lognormal *ln, double mean, double std)
{
    if (!(isfinite(mean) && isfinite(std)) || mean <= 0.0 || std < 0.0)
        return SF_EINVAL;
    ln->mean = mean;
    ln->std = std;
    ln->cv = std / mean;
    /* log1p keeps sigma_g accurate for small CV */
    double s2 = log1p(ln->cv * ln->cv);
    ln->sigma_g = sqrt(s2);
    ln->mu_g = log(mean) - 0.5 * s2;
    return SF_SUCCESS;
}

double sf_lognormal_map(const sf_lognormal *ln, double g)
{
    return exp(ln->mu_g + ln->sigma_g * g);
}

void sf_lognormal_map_array(const sf_lognormal *ln, double *v, unsigned long n)
{
    for (unsigned long i = 0; i < n; i++)
        v[i] = exp(ln->mu_g + ln->sigma_g * v[i]);
}

double sf_lognormal_cdf(const sf_lognormal *ln, double h)
{
    if (ln->sigma_g == 0.0)
        return h < ln->mean ? 0.0 : 1.0;
    return gsl_cdf_lognormal_P(h, ln->mu_g, ln->sigma_g);
}

double sf_lognormal_rho_h(const sf_lognormal *ln, double rho_g)
{
    double s2 = ln->sigma_g * ln->sigma_g;
    if (s2 == 0.0)
        return rho_g;
    /* expm1 avoids cancellation: rho_H = expm1(s2 rho_G) / expm1(s2) */
    return expm1(s2 * rho_g) / expm1(s2);
}

double sf_lognormal_rho_g(const sf_lognormal *ln, double rho_h)
{
    double s2 = ln->sigma_g * ln->sigma_g;
    if (s2 == 0.0)
        return rho_h;
    return log1p(rho_h * expm1(s2)) / s2;
}
