/* slipfield: friction wrench of the belt on the disc (Eqs. 7-8) and the
 * static limit surface (Eqs. 9-11).
 *
 * Conventions.  The disc (radius R, load N = m g, uniform pressure
 * P = N/(pi R^2)) has its centre over belt point (xb, yb).  The relative
 * velocity of the disc centre with respect to the belt is (u, v) =
 * (xdot - v_b, ydot) [m/s], the spin is w = phidot [rad/s].  A disc point
 * at offset (rx, ry) from the centre slips at v_p = (u - w ry, v + w rx).
 * The returned wrench is the one acting ON the disc, opposing local slip:
 *   F = -sum P mu(x_i) v_p/|v_p| dS_i,  T = -sum P mu(x_i) (r x v_p)/|v_p| dS_i
 * so that with a uniform COF the 3-DOF equations m xddot = -k x + F_x
 * reduce exactly to Eqs. 3-4 (F_x = +mu_k m g while the disc is slower than
 * the belt).  The paper's Eq. 5 writes Q_s = -[F, T] with the opposite
 * sign convention for F inside the integral; the physics is the same.
 */
#ifndef SF_CONTACT_H
#define SF_CONTACT_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include "cof.h"

typedef enum { SF_LAYOUT_POLAR = 0, SF_LAYOUT_CARTESIAN = 1 } sf_layout;

typedef struct {
    double R;             /* disc radius [m] */
    double normal_force;  /* N = m g [N] */
    sf_layout layout;
    size_t cells;         /* resolution: polar = rings (sectors grow with
                             radius so cells are near-square); cartesian =
                             cells across the diameter */
} sf_contact_spec;

typedef struct sf_contact sf_contact;

int sf_contact_alloc(const sf_contact_spec *spec, const sf_cof *cof, sf_contact **out);
void sf_contact_free(sf_contact *c);
size_t sf_contact_ncells(const sf_contact *c);

/* The quadrature itself (for the limit-surface plan): offsets [m] and
 * weights [N] (pressure x area; they sum to N). */
void sf_contact_cells(const sf_contact *c, const double **rx, const double **ry, const double **wt);
const sf_cof *sf_contact_get_cof(const sf_contact *c);
double sf_contact_radius(const sf_contact *c);
double sf_contact_normal_force(const sf_contact *c);

/* Friction wrench on the disc, out = {Fx [N], Fy [N], T [N m]}, with the
 * local COF ratio * mu_s (ratio = 1 static, 0.9 kinetic per Eq. 1). */
int sf_contact_wrench(const sf_contact *c, double xb, double yb,
                      double u, double v, double w, double ratio, double out[3]);

/* Disc-averaged static COF at centre (xb, yb) (equatorial radius of the
 * limit surface, dimensionless). */
double sf_contact_mean_cof(const sf_contact *c, double xb, double yb);

/* Uniform COF, uniform pressure closed forms (docs/design.md sec. 4.5, Contensou
 * coupling): eps = U/(|w| R); |F| = mu N f(eps), |T| = mu N R t(eps). */
void sf_contensou(double eps, double *f, double *t);

#ifdef __cplusplus
}
#endif
#endif
