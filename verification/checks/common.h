/* Helpers shared by the check families. */
#ifndef SF_CHECKS_COMMON_H
#define SF_CHECKS_COMMON_H

#include <math.h>
#include "../case.h"
#include "../result.h"
#include "field.h"

/* The oracle's own Eq. 2, written independently of the solver. */
double ref_sq_exp(double hx, double hy, double l);

/* The oracle's own Contensou closed forms (DESIGN.md sec. 5), written from
 * the formulas with GSL's complete elliptic integrals of modulus k
 * (gsl_sf_ellint_Kcomp, Ecomp) and sharing no code with sf_contensou:
 * a uniformly pressed disc of radius R under uniform COF mu, centre slip U
 * and spin w, eps = U/(|w| R) >= 0 (INFINITY: no spin): |F| = mu N f(eps),
 * |T| = mu N R t(eps).  The eps > 1 torque bracket cancels like eps^-4:
 * about 1e-16 eps^4 relative error, so keep eps below ~100. */
void ref_contensou(double eps, double *f, double *t);

/* max that keeps a NaN (fmax drops it): a NaN in a check's data must
 * reach the row and fail it. */
static inline double check_nanmax(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : (a > b ? a : b);
}

/* Build the Gaussian field plan a case's scene asks for; note the
 * embedding facts in the findings.  Returns SF_SUCCESS or SF_ETRUNC (plan
 * usable) or an error (plan NULL). */
int check_field_plan(const sf_case *c, sf_result *r, sf_field **out);

/* Allocate or die (exit 3): checks run in their own process. */
void *check_alloc(size_t n);

/* Direct (no FFT) circulant eigenvalues of the squared-exponential
 * embedding of period (px, py) for spacings dx, dy: the oracle for the
 * FFT path.  lam has px*py entries, index kx + px*ky. O((px py)^2)/sep. */
void ref_eigenvalues(size_t px, size_t py, double dx, double dy, double l, double *lam);

/* Covariance at grid lags (i < m, j < n) produced by clamped eigenvalues,
 * by a direct inverse DFT. */
void ref_produced_cov(const double *lam, size_t px, size_t py, size_t m, size_t n, double *cov);

/* A lognormal COF (or a uniform one when cof = uniform or mu_std = 0) on
 * a square grid covering a disc of radius R centred at the origin.  Grid
 * spacing l/8 (bilinear RMS error ~ 7e-3 std, cases/contact/interpolation)
 * and at least 4 nodes across the disc, so a long l gets a coarse grid
 * instead of an embedding it cannot pad.  The Gaussian plan is made on the
 * first call and kept in *st; a truncated embedding is refused (NULL). */
#include "cof.h"
#include "lnfield.h"
typedef struct { sf_lnfield *lf; sf_scene gs; } check_disc_field;
sf_cof *check_disc_cof(const sf_scene *s, gsl_rng *rng, check_disc_field *st);
void check_disc_field_free(check_disc_field *st);

/* Run the oscillator for a scene: the COF drawn from the scene's plan with
 * rng (NULL for a constant COF), or the given cof.  On failure the reason
 * is noted in r and an error returned. */
#include "oscillator.h"
/* A history collector for sf_osc_run (every row, or one in `every`). */
typedef struct {
    size_t n, cap, every, seen;
    double *t, *x, *y, *phi, *vx, *Fx;
    int *stick;
    double y_absmax, phi_absmax;
} check_hist;
void check_hist_row(void *ctx, const sf_osc_row *row);
void check_hist_free(check_hist *h);

/* One COF realisation of the scene from the case's stream (kept across
 * runs that must share it); NULL with the reason noted when the plan is
 * refused. */
sf_cof *check_case_cof(const sf_case *c, const sf_scene *s, sf_result *r);

int check_osc_run(const sf_scene *s, gsl_rng *rng, const sf_cof *cof, double sample_dt, sf_osc_result *res,
                  sf_osc_row_fn row, void *ctx, sf_result *r);

#endif
