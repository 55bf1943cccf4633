/* slipfield: a lognormal COF field = a Gaussian field plan (field.h) plus
 * the Nataf map (lognormal.h), built from a scene.  With `precorrect`, the
 * Gaussian field uses rho_G(r) = distortion^-1(exp(-r^2/l^2)) so that the
 * lognormal field itself has the target correlation of Eq. 2 (an option
 * the paper did without). */
#ifndef SF_LNFIELD_H
#define SF_LNFIELD_H
#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"
#include "lognormal.h"
#include "scene.h"

typedef struct sf_lnfield sf_lnfield;

/* The Gaussian field spec a scene asks for: nx x ny grid, dx, dy, l,
 * pad_cap, eig_tol, no_padding (squared-exponential kernel). */
void sf_field_spec_from_scene(const sf_scene *s, sf_field_spec *spec);

/* Grid nx x ny, spacing dx, dy; marginal (mu_mean, mu_std).  Returns
 * SF_SUCCESS or SF_ETRUNC (usable, truncated: sf_usable()), else an error
 * (SF_ETOOBIG: embedding over its cap) and *out = NULL. */
int sf_lnfield_alloc(const sf_scene *s, sf_lnfield **out);

/* The same, for a plan that only samples: the Gaussian plan's produced
 * covariance is deferred (field.h, defer_covariance). */
int sf_lnfield_alloc_sampler(const sf_scene *s, sf_lnfield **out);
void sf_lnfield_free(sf_lnfield *f);

sf_field *sf_lnfield_gaussian(sf_lnfield *f);
const sf_lognormal *sf_lnfield_marginal(const sf_lnfield *f);

/* One realisation: the Gaussian values (optional, may be NULL) and the
 * COF values cof[nx*ny] = exp(mu_g + sigma_g G). */
int sf_lnfield_sample(sf_lnfield *f, gsl_rng *rng, double *gauss, double *cof);

/* One realisation as a function of the rng state alone (field.h:
 * sf_field_sample_fresh): the values of sf_field_discard on the Gaussian
 * plan then sf_lnfield_sample, with no copy of the second field. */
int sf_lnfield_sample_fresh(sf_lnfield *f, gsl_rng *rng, double *cof);

#ifdef __cplusplus
}
#endif
#endif
