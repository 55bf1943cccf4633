/* slipfield: lognormal marginals by the Nataf map (paper Sec. 2.2).
 *
 * H = exp(mu_g + sigma_g G), G standard normal, with
 *   sigma_g^2 = ln(1 + CV^2),  mu_g = ln(mean) - sigma_g^2/2,  CV = std/mean,
 * so that E[H] = mean and sd[H] = std exactly.
 * Correlation distortion (Gaussian rho_G -> lognormal rho_H):
 *   rho_H = (exp(sigma_g^2 rho_G) - 1) / (exp(sigma_g^2) - 1)
 * and its inverse rho_G = ln(1 + rho_H (exp(sigma_g^2) - 1)) / sigma_g^2.
 */
#ifndef SF_LOGNORMAL_H
#define SF_LOGNORMAL_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double mean, std, cv;   /* target moments of H (same units as H) */
    double mu_g, sigma_g;   /* parameters of ln H (dimensionless) */
} sf_lognormal;

/* SF_EINVAL unless mean > 0, std >= 0 and both finite. */
int sf_lognormal_init(sf_lognormal *ln, double mean, double std);

/* H for a standard normal value g. */
double sf_lognormal_map(const sf_lognormal *ln, double g);

/* Apply the map in place to n values. */
void sf_lognormal_map_array(const sf_lognormal *ln, double *v, unsigned long n);

double sf_lognormal_cdf(const sf_lognormal *ln, double h);

/* Correlation distortion and its inverse; both are the identity when
 * std = 0 (the limit sigma_g -> 0). Defined for rho in [-1, 1]. */
double sf_lognormal_rho_h(const sf_lognormal *ln, double rho_g);
double sf_lognormal_rho_g(const sf_lognormal *ln, double rho_h);

#ifdef __cplusplus
}
#endif
#endif
