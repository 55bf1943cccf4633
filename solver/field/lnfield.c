/* slipfield: a lognormal COF field from a scene (lnfield.h): the Gaussian
 * field plan (field.h) and the Nataf map (lognormal.h) together, with the
 * optional pre-corrected correlation. */
#include "lnfield.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sf_lnfield {
    sf_lognormal ln;
    double l;
    sf_field *g;
    double *tmp;
    size_t n;
};

/* Pre-corrected Gaussian correlation (inverse distortion of Eq. 2). */
static double precorrected(double r, void *params)
{
    const struct sf_lnfield *f = params;
    double q = r / f->l;
    return sf_lognormal_rho_g(&f->ln, exp(-q * q));
}

void sf_field_spec_from_scene(const sf_scene *s, sf_field_spec *spec)
{
    sf_field_spec_default(spec, s->nx, s->ny, s->dx, s->dy, s->l);
    spec->pad_cap = s->pad_cap;
    spec->eig_rel_tol = s->eig_tol;
    spec->no_padding = s->no_padding;
    spec->measure = s->fftw_planner;
}

static int lnfield_alloc(const sf_scene *s, int defer_covariance, sf_lnfield **out)
{
    *out = NULL;
    sf_lnfield *f = sf_calloc(1, sizeof *f);
    if (!f)
        return SF_ENOMEM;
    int rc = sf_lognormal_init(&f->ln, s->mu_mean, s->mu_std);
    if (rc) {
        free(f);
        return rc;
    }
    f->l = s->l;
    sf_field_spec spec;
    sf_field_spec_from_scene(s, &spec);
    spec.defer_covariance = defer_covariance;
    if (s->precorrect && s->mu_std > 0) {
        spec.kernel = precorrected;
        spec.kernel_params = f;
    }
    rc = sf_field_alloc(&spec, &f->g);
    if (!sf_usable(rc)) {
        free(f);
        return rc;
    }
    f->n = s->nx * s->ny;
    *out = f;
    return rc;
}

int sf_lnfield_alloc(const sf_scene *s, sf_lnfield **out) { return lnfield_alloc(s, 0, out); }
int sf_lnfield_alloc_sampler(const sf_scene *s, sf_lnfield **out) { return lnfield_alloc(s, 1, out); }

void sf_lnfield_free(sf_lnfield *f)
{
    if (!f)
        return;
    sf_field_free(f->g);
    free(f->tmp);
    free(f);
}

sf_field *sf_lnfield_gaussian(sf_lnfield *f) { return f->g; }
const sf_lognormal *sf_lnfield_marginal(const sf_lnfield *f) { return &f->ln; }

int sf_lnfield_sample(sf_lnfield *f, gsl_rng *rng, double *gauss, double *cof)
{
    if (!gauss && !f->tmp && !(f->tmp = sf_malloc(f->n * sizeof *f->tmp)))   /* on first use */
        return SF_ENOMEM;
    double *g = gauss ? gauss : f->tmp;
    int rc = sf_field_sample(f->g, rng, g);
    if (rc)
        return rc;
    for (size_t i = 0; i < f->n; i++)
        cof[i] = sf_lognormal_map(&f->ln, g[i]);
    return SF_SUCCESS;
}

int sf_lnfield_sample_fresh(sf_lnfield *f, gsl_rng *rng, double *cof)
{
    int rc = sf_field_sample_fresh(f->g, rng, cof);
    if (rc)
        return rc;
    for (size_t i = 0; i < f->n; i++)   /* the Nataf map in place */
        cof[i] = sf_lognormal_map(&f->ln, cof[i]);
    return SF_SUCCESS;
}
