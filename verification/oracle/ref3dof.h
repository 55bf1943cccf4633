/* slipfield verification: a second, independent implementation of the
 * 3-DOF stick-slip model (paper Secs. 2.3-2.4, Eqs. 5-14), the oracle of
 * the code-to-code cases (cases/dynamics/ref3dof-*).
 *
 * Written from the paper's equations; it shares no code with solver/ beyond
 * reading the scene and the COF's nodal values (sf_cof_grid_view, or
 * sf_cof_eval at one point for a spatially constant COF).  What it does
 * its own way, on purpose different from the solver:
 *  - wrench (Eqs. 7-8): Gauss-Legendre in radius (GSL glfixed) x trapezoid
 *    in angle over the disc, always a quadrature (the solver takes the
 *    Contensou closed form for a constant COF and polar/Cartesian cells
 *    for a field), its own bilinear interpolation of the nodal values;
 *  - lambda (Eq. 9) and the stick test on the equatorial circle of radius
 *    mu_bar m g (Eqs. 10-11, as the paper), mu_bar its own disc average
 *    (the same Gauss-Legendre x trapezoid rule);
 *  - the jumps of Eq. 12 (velocities (v_b, 0, 0)) and Eq. 14 (relative
 *    velocity eps_lambda omega_n R opposite the stick force (k x, k y));
 *  - classical RK4 written out at a fixed step dt (or, on given nodes,
 *    with its own step-doubling error control: ref3dof_alloc_nodes),
 *    shortened near the stick threshold to m V / (mu_k,max m g) (V the
 *    relative speed:
 *    the damping time of friction on the slip direction, which makes the
 *    slip equations stiff as V -> 0) (the solver: GSL's adaptive
 *    rkck/rk8pd with Brent event search); events by bisection on
 *    the event predicate over single RK4 steps from the step's start; the
 *    stick phase as exact belt motion with its break found by bisection
 *    on k |(x, y)| - mu_bar m g (the solver uses a closed form).
 * Same conventions as solver/disc/contact.h: the wrench acts ON the disc and
 * opposes local slip; ground frame; belt point (x - v_b t, y).
 * QoIs with the definitions of solver/dynamics/oscillator.h (a cycle from a stick
 * onset to the next, complete cycles with onset >= t_skip), computed here
 * by their own code; and the paper's (Sec. 3.1, `qoi_def = paper`), also
 * by their own code: the stick time is each stick span clipped to
 * [t_skip, T] at both ends, an oscillation runs from a maximum of x (vx
 * from + to -, bisected on the RK4 step) at or after t_skip to the next,
 * and one still open at T is not one.
 */
#ifndef SF_ORACLE_REF3DOF_H
#define SF_ORACLE_REF3DOF_H

#include <stddef.h>
#include "cof.h"
#include "scene.h"

typedef struct ref3dof ref3dof;

enum { REF_X, REF_Y, REF_PHI, REF_VX, REF_VY, REF_W, REF_N };
enum { REF_STICK_ONSET = 0, REF_SLIP_ONSET = 1 };

typedef struct {
    double t;
    int kind;               /* REF_STICK_ONSET or REF_SLIP_ONSET */
    double pre[REF_N];      /* state just before the jump (Eq. 12 or 14) */
    double post[REF_N];     /* state just after it */
} ref3dof_event;

typedef struct {
    size_t nev;
    ref3dof_event *ev;
    size_t ncycles;
    double *cycle_pv_x, *cycle_pv_F, *cycle_stick;
    double pv_x, pv_F, stick_fraction;   /* means over the complete cycles (NAN if none) */
    /* the paper's: oscillations (maximum of x to the next, both inside
     * [t_skip, T]), their mean PV_x and PV_F (NAN if none); the stick time
     * inside [t_skip, T] and T_sk = that / (T - t_skip) (NAN for an empty
     * window) */
    size_t nosc;
    double osc_pv_x, osc_pv_F, stick_time, win_stick_fraction;
    size_t nsamples;
    double sample_dt, *x_samples;        /* x(i sample_dt) when asked */
    double end[REF_N];
    unsigned long steps, bisections;
} ref3dof_result;

/* The oracle for scene s (m, k, v_b, R, g, mu_k_ratio, eps_lambda, T,
 * t_skip, x0 ... w0) and COF cof (kept by pointer): RK4 step dt [s], nr
 * Gauss-Legendre radii and na trapezoid angles.  Refuses (SF_EINVAL)
 * dof = 1 and velocity_jump = false (this oracle models Eq. 5 with both
 * jumps only), and a tiled COF (cof_generator = tiles, or auto on a large
 * strip: a window whose contents change as runs slide it; the oracle
 * reads one fixed grid). */
int ref3dof_alloc(const sf_scene *s, const sf_cof *cof, double dt, size_t nr, size_t na, ref3dof **out);
/* The same oracle on a given rule: n nodes at offsets (rx, ry) [m] from
 * the disc's centre with weights w (any scale: normalised here), used for
 * both the wrench and the disc average.  Given the solver's own cells
 * (sf_contact_cells), both codes integrate the same discrete wrench: the
 * COF at the same points, summed with the same weights, each by its own
 * code; what remains different is the time integration, the events, the
 * jumps and the rest of Eqs. 5-14 as each writes them.  tol > 0: RK4
 * with step doubling (its own error control, Richardson on a step against
 * two half steps) at tolerance tol in the scales of the stick distance
 * mu_max m g / k, dt the largest step; 0: fixed steps dt as
 * ref3dof_alloc.  The wrench on points is only piecewise smooth in the
 * state (kinks where a point crosses a grid line of the COF, a jump where
 * the slip field's pole crosses a point): fixed steps converge there at
 * order 1-2 with an error whose sign changes from one dt to the next, the
 * controlled step keeps the error about proportional to tol. */
int ref3dof_alloc_nodes(const sf_scene *s, const sf_cof *cof, double dt, double tol, size_t n, const double *rx,
                        const double *ry, const double *w, ref3dof **out);
void ref3dof_free(ref3dof *o);

/* Integrate [0, T]; sample_dt > 0 also fills x_samples.  SF_EFAIL on a
 * non-finite state. */
int ref3dof_run(ref3dof *o, double sample_dt, ref3dof_result *res);
void ref3dof_result_free(ref3dof_result *r);

/* The kinetic friction wrench {Fx [N], Fy [N], T [N m]} on the disc at
 * time t in state s (ground frame): Eqs. 7-8 by this oracle's quadrature. */
void ref3dof_wrench(const ref3dof *o, double t, const double s[REF_N], double out[3]);

/* The disc-averaged static COF at belt point (xb, yb) by this oracle's
 * rule: the radius of its stick test's circle over m g (Eqs. 10-11). */
double ref3dof_mean_cof(const ref3dof *o, double xb, double yb);

/* Eq. 15 written out: sum_i (a_i - b_i)^2 dt over the first n samples
 * (i >= 1: the common start x(0) carries no error) [m^2 s]. */
double ref3dof_eq15(const double *a, const double *b, size_t n, double dt);

#endif
