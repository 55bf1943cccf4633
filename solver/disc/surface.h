/* slipfield: the static limit surface (paper Eqs. 9-11) as a plan.
 *
 * For a disc centred over belt point (xb, yb), the plan stores the static
 * COF at every quadrature cell once (one interpolation per cell); each
 * evaluation of the surface is then a pass over the cells, no field access.
 * Directions (theta, psi) are those of Eq. 9: a dimensionless twist
 * (xdot*, ydot*, phidot*) = (cos theta cos psi, cos theta sin psi, sin theta)
 * with lengths in units of R.  Points are dimensionless (Eq. 11):
 * Q* = (F*x, F*y, T*) = (Fx/N, Fy/N, T/(N R)), the maximum-power wrench of
 * that twist (the friction wrench on the disc is -N Q*).
 *
 * Stick uses only the T* = 0 section.  The paper approximates it by the
 * theta = 0 curve and that by a circle of radius mu_bar (the disc-averaged
 * static COF); sf_surface_section() gives the exact section: for each psi
 * the theta at which T* = 0 (T* increases monotonically with theta),
 * located with GSL's Brent solver.
 */
#ifndef SF_SURFACE_H
#define SF_SURFACE_H
#ifdef __cplusplus
extern "C" {
#endif

#include "contact.h"

typedef struct sf_surface sf_surface;

int sf_surface_alloc(const sf_contact *c, double xb, double yb, sf_surface **out);
void sf_surface_free(sf_surface *s);

/* Move a plan made by sf_surface_alloc(c, ...) to centre (xb, yb) of the
 * same contact c: only the static COF per cell is looked up again (the
 * same arithmetic as sf_surface_alloc, so the same bits); no allocation. */
void sf_surface_recentre(sf_surface *s, const sf_contact *c, double xb, double yb);

/* Eq. 11 at (theta, psi) [rad]: q = (F*x, F*y, T*), dimensionless. */
void sf_surface_point(const sf_surface *s, double theta, double psi, double q[3]);

/* Disc-averaged static COF mu_bar (dimensionless): the paper's equatorial
 * circle radius. */
double sf_surface_mean_cof(const sf_surface *s);

/* The exact T* = 0 section at twist azimuth psi: *theta with T* = 0 to
 * |dtheta| <= 1e-13 rad, and the point q (q[2] ~ 0). SF_EMAXITER if Brent
 * does not converge. */
int sf_surface_section(const sf_surface *s, double psi, double *theta, double q[3]);

/* Radius of the exact T* = 0 section along the force direction alpha [rad]
 * (dimensionless, in units of N); *psi_out (may be NULL) is the twist
 * azimuth that produces it. */
int sf_surface_section_radius(const sf_surface *s, double alpha, double *rho, double *psi_out);

/* Stick admissibility of a planar stick force (Fx, Fy) [N] with T = 0 at
 * centre (xb, yb) of contact c: exact = 0 uses the paper's equatorial
 * circle (radius mean COF * N), exact = 1 the true T = 0 section of the
 * limit surface.  *margin > 0 inside (stick holds), < 0 outside; in
 * newtons: the section's radius along the direction of F minus |F|.
 * (Named sf_contact_* for its callers; it lives here because stick
 * admissibility belongs to the limit surface.) */
int sf_contact_stick_margin(const sf_contact *c, double xb, double yb,
                            double Fx, double Fy, int exact, double *margin);

/* The exact (T = 0 section) margin on a surface the caller keeps, re-centred
 * at (xb, yb) of c (no allocation: the oscillator's stick test, many calls
 * a run).  *margin is NaN when it cannot be computed (SF_EINVAL: F not
 * finite); SF_EMAXITER from the section's root finder. */
int sf_surface_stick_margin(sf_surface *s, const sf_contact *c, double xb, double yb, double Fx, double Fy,
                            double *margin);

#ifdef __cplusplus
}
#endif
#endif
