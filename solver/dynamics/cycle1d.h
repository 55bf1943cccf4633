/* slipfield: the 1-D stick-slip cycle of Eqs. 3-4 in closed form
 * (docs/design.md sec. 4.7), ideal (eps_lambda = 0) and with the threshold's own
 * effect: slip starts at relative speed delta = eps_lambda omega_n R
 * (Eq. 14) and ends when it falls back to delta, on the same harmonic arcs.
 *
 * x_s = mu_s m g / k, x_e = mu_k m g / k, d = x_s - x_e, omega = sqrt(k/m),
 * A = sqrt(d^2 + ((v_b - delta)/omega)^2); stick lasts 2 d / v_b; slip
 * lasts (pi + 2 atan((v_b - delta)/(omega d)))/omega; PV_x = 2 A;
 * PV_F = 2 (mu_s - mu_k) m g.  From rest at the origin the first slip is
 * x = x_e (1 - cos omega t) until xdot = v_b - delta, then stick to x_s.
 */
#ifndef SF_CYCLE1D_H
#define SF_CYCLE1D_H
#ifdef __cplusplus
extern "C" {
#endif

#include "scene.h"

typedef struct {
    double xs, xe, d, omega, delta, A;   /* [m], [m], [m], [1/s], [m/s], [m] */
    double t_stick, t_slip, period;       /* [s] */
    double pv_x, pv_F, stick_fraction;    /* [m], [N], [-] */
    double t_first_stick, x_first_stick;  /* first slip-to-stick from rest [s], [m] */
    double t_first_slip;                  /* first stick-to-slip [s] */
} sf_cycle1d;

/* mu_s = the scene's mu_mean, mu_k = mu_k_ratio mu_s; eps = the threshold
 * to account for (0: ideal).  SF_EINVAL when the 1-D model has no
 * stick-slip cycle (v_b - delta >= x_e omega: the first slip never slows
 * to the belt speed). */
int sf_cycle1d_init(sf_cycle1d *c, const sf_scene *s, double eps);

/* Time of the n-th transition from rest (n = 0: first stick onset, 1: the
 * slip onset after it, ...). */
double sf_cycle1d_transition(const sf_cycle1d *c, unsigned n);

/* Stick time [s] inside [t0, t1] of the motion from rest (the paper's
 * t_sk over that window, Sec. 3.1): the stick spans between transitions
 * 2j and 2j + 1, clipped to the window. */
double sf_cycle1d_stick_time(const sf_cycle1d *c, double t0, double t1);

#ifdef __cplusplus
}
#endif
#endif
