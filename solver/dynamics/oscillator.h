/* slipfield: the event-driven stick-slip integrators (paper Eqs. 3-6 and
 * 12-14), 1-D deterministic and 3-DOF stochastic, as a plan.
 *
 * State (ground frame, SI): x, y [m], phi [rad], vx, vy [m/s], w [rad/s].
 * The disc starts from the scene's x0, y0, phi0, vx0, vy0, w0 (default:
 * rest at the origin), in stick when that state passes the slip-to-stick
 * test (lambda < eps_lambda and the stick wrench admissible; then Eq. 12
 * sets the velocities to (v_b, 0, 0)), else in slip; the belt moves at
 * v_b along +x;
 * the belt point under the centre is (x - v_b t, y).
 *
 * Slip: m x'' = -k x + Fx, m y'' = -k y + Fy, J phi'' = T (J = m R^2/2),
 * (Fx, Fy, T) the kinetic friction wrench on the disc (contact.h; for a
 * spatially constant COF the exact Contensou closed form, no quadrature;
 * 1-D: Fx = -mu_k m g sign(vx - v_b)).  Integrated with gsl_odeiv2 under
 * an error control at `rtol`: `adaptive` takes rk8pd when the wrench is a
 * closed form and Cash-Karp 4(5) when it is a quadrature (fewer stages per
 * step pay when each costs a pass over the cells: make bench), or forced
 * (`rk8pd`, `rkck`); or classical RK4 at a fixed step `dt`.
 * Stick: the disc moves with the belt; exact motion, no quadrature.  The
 * stick wrench is (k x, k y, 0) (Eq. 6) and stick holds while it is inside
 * the T = 0 section of the limit surface at the (fixed) belt point: the
 * equatorial circle of radius mu_bar m g by default, whose exit time is a
 * closed form, or the exact section (`exact_section`), bracketed by that
 * time and located by bisection (sf_osc_stick_duration: the margin is a
 * pass over the cells per trial, and bisection halves [0, tau] to
 * SF_OSC_TIME_TOL in a bounded number of them).
 * Slip -> stick: lambda = |(vx - v_b, vy)/(omega_n R), w/omega_n| (Sec.
 * 2.4) falls below eps_lambda AND the stick wrench is admissible; located
 * by GSL's Brent solver on single steps of the same stepper from the step's
 * start, to SF_OSC_TIME_TOL; then Eq. 12 (velocities (v_b, 0, 0)).
 * Stick -> slip: Eq. 14 with the jump magnitude eps_lambda omega_n R in
 * m/s (lambda = eps_lambda just after it; the paper's Eq. 14 writes
 * eps_lambda, a dimensionless number, as a speed).  With
 * velocity_jump = false the jump of Eq. 14 is skipped (Eq. 12 is the stick
 * kinematics itself and always holds).
 *
 * Quantities of interest are accumulated online (no history needed), over
 * the window [t_skip, T] of a run that starts from the scene's initial
 * state (default: rest at the origin; t_skip default 10 s).  Two sets of
 * definitions, both always computed:
 *  - the paper's (Sec. 3.1; `qoi_def = paper`, the default): stick
 *    fraction T_sk = the sum of the stick spans inside [t_skip, T] /
 *    (T - t_skip); an oscillation runs from one maximum of x (vx changes
 *    sign from + to -, located as an event to SF_OSC_TIME_TOL) to the
 *    next, both at or after t_skip, whether or not the disc sticks in
 *    between (a disc sliding on still oscillates); PV_x = max - min of x
 *    and PV_F = max - min of Fx over each oscillation, averaged over the
 *    run's oscillations (NaN only when the window holds none);
 *  - complete stick cycles (`qoi_def = cycles`): a cycle runs from a stick
 *    onset to the next, onset at or after t_skip; PV_x and PV_F per cycle,
 *    stick fraction = stick time / time of the complete cycles (NaN when
 *    the window holds no complete cycle).
 * In a periodic stick-slip motion both give the same PVs (each
 * oscillation holds one stick phase and its break), and the stick
 * fractions differ by the window's partial cycles.  Also: x at every
 * slip-to-stick instant after t_skip (bifurcation samples), and the energy
 * balance E(t) - E(0) = W_friction + sum of the jumps' kinetic-energy
 * changes.
 */
#ifndef SF_OSCILLATOR_H
#define SF_OSCILLATOR_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include "cof.h"
#include "numplan.h"
#include "scene.h"

/* Event times are located to max(1e-12 s, 8 ulp(t)). */
#define SF_OSC_TIME_TOL 1e-12
/* A cell whose slip speed is below this share of the disc's holds the
 * centre of rotation (sf_osc_run: SF_EMAXITER).  A cell at distance d from
 * the pole slips at about d / R of the disc's speed, so a pole that no cell
 * holds lies within 1e-4 R of some cell with probability ~ cells x 1e-8;
 * a pivot that is ending lets its cell slip faster and faster at the same
 * ~1e-8 s steps (measured 2.6e-7, 4.3e-7, 1.2e-6, 3.3e-6 of the disc's
 * speed 0.3, 0.6, 0.9, 1.0 million steps into one pivot, which ended at
 * 1.04 million), so a stop anywhere in it is held. */
#define SF_OSC_HELD_SLIP 1e-4

typedef struct sf_osc sf_osc;

typedef struct {
    double t, x, y, phi, vx, vy, w;  /* SI */
    double Fx, Fy, T;                /* friction wrench on the disc [N, N m] */
    int stick;                       /* 1 stick, 0 slip */
} sf_osc_row;

/* Called for every accepted step end and event (history). */
typedef void (*sf_osc_row_fn)(void *ctx, const sf_osc_row *row);

enum { SF_OSC_STICK_ONSET = 0, SF_OSC_SLIP_ONSET = 1 };

typedef struct {
    /* transitions, all of [0, T] */
    size_t ntrans;
    double *trans_t, *trans_x;
    int *trans_kind;
    /* the QoIs under the scene's qoi_def: the osc_ / win_ values (paper)
     * or the cyc_ values (cycles) */
    double pv_x, pv_F, stick_fraction;
    /* the paper's: oscillations (maximum of x to the next) inside
     * [t_skip, T], their start time, PVs and stick time; the stick time
     * inside the window and T_sk = stick_time / (T - t_skip) */
    size_t nosc;
    double *osc_t, *osc_pv_x, *osc_pv_F, *osc_stick;
    double osc_pv_x_mean, osc_pv_F_mean, stick_time, win_stick_fraction;
    /* complete stick cycles after t_skip */
    size_t ncycles;
    double *cycle_pv_x, *cycle_pv_F, *cycle_stick, *cycle_period;
    double cyc_pv_x, cyc_pv_F, cyc_stick_fraction, period;   /* means over the cycles */
    /* x at slip-to-stick instants after t_skip */
    size_t nbif;
    double *bif;
    /* uniform samples of x (when asked), x(i * sample_dt) */
    size_t nsamples;
    double *x_samples, sample_dt;
    /* energy: E(T) - E(0) - W - J, and its parts [J] */
    double energy_change, friction_work, jump_energy, energy_residual;
    /* cost */
    /* rejected: attempts the error control refused, over all slip phases;
     * event_trials: trial steps of the (Brent) event search; wrench_evals:
     * wrench evaluations made (a repeat of the last one's arguments is
     * reused, not made again) */
    unsigned long steps, rejected, event_trials, wrench_evals;
    unsigned long off_strip;     /* accepted states whose contact patch left the COF strip */
    /* on SF_EMAXITER (the scene's max_steps spent): the quadrature cell
     * that slips slowest at the stop and its slip speed over the disc's,
     * |v_p| / (|U| + |w| R) (about 0: the cell holds the centre of
     * rotation); -1 and NaN otherwise, and without a quadrature */
    long held_cell;
    double held_slip;
    double x_min, x_max, y_absmax;
} sf_osc_result;

/* The plan for a scene and a drawn COF (kept by pointer, not copied).
 * SF_EINVAL with the reason in err for an inconsistent scene (e.g. dof = 1
 * with a field COF). */
int sf_osc_alloc(const sf_scene *s, const sf_cof *cof, sf_osc **out, char *err, size_t errlen);
/* The same on the run's plan pl (sf_plan_make(s), numplan.h: the
 * quadrature, stepper and rtol it chose; cof drawn from its COF plan):
 * nothing is re-planned.  SF_EINVAL also for a COF that does not match
 * the plan (a constant COF where the plan runs a quadrature, or the
 * reverse; point values where it runs cell averages). */
int sf_osc_alloc_plan(const sf_scene *s, const sf_plan *pl, const sf_cof *cof, sf_osc **out, char *err,
                      size_t errlen);
void sf_osc_free(sf_osc *o);

/* What the oscillator set up, one line each (model, slip wrench, stick
 * test, stepper, events: for --explain, after the plan's record). */
void sf_osc_describe(const sf_osc *o, FILE *f);
/* The same, ending with the numerical plan's record (numplan.h). */
void sf_osc_explain(const sf_osc *o, FILE *f);

/* The numerical plan the run uses: cells, rtol, stepper, predicted
 * errors, warnings (numplan.h; decided in sf_osc_alloc from qoi_tol and
 * the explicit keys). */
const sf_numplan *sf_osc_get_plan(const sf_osc *o);
/* The cells of its slip-wrench quadrature (0 without one): with
 * sf_osc_result.wrench_evals, the work of a run in cell evaluations. */
size_t sf_osc_ncells(const sf_osc *o);

/* Run [0, T].  row (may be NULL) receives the history; sample_dt > 0
 * also fills res->x_samples.  Returns SF_SUCCESS, SF_EFAIL (non-finite
 * state; reason in err) or SF_EMAXITER (more than the scene's max_steps
 * slip steps: res then holds the run up to its stop, energy balance
 * included, and res->held_cell says whether a quadrature cell held the
 * centre of rotation.  Such a cell, of a COF many times the mean, makes
 * a sliding mode of the point quadrature: its kinetic force flips with
 * its slip direction, and the error-controlled stepper crosses the flip
 * in steps of about rtol x_s omega_n m / (2 |its force|), ~1e-8 s at
 * rtol = 1e-10). */
int sf_osc_run(sf_osc *o, sf_osc_row_fn row, void *ctx, double sample_dt, sf_osc_result *res,
               char *err, size_t errlen);
void sf_osc_result_free(sf_osc_result *r);

/* Eq. 15: sum (x_i - x_ref,i)^2 dt over common uniform samples [m^2 s]. */
double sf_osc_error_eq15(const sf_osc_result *a, const sf_osc_result *ref);

/* ---- The model's pieces, for peers.
 * A benchmark peer that integrates the same model with another ODE code
 * (bench/cvode_peer.h: SUNDIALS CVODE) calls these on a plan of
 * sf_osc_alloc instead of keeping its own copies of the physics: they are
 * the very functions sf_osc_run calls, so a peer differs from the solver
 * in its integrator and its event location only.  They leave the plan's
 * GSL steppers alone (a peer allocates a plan of its own and never runs
 * it); the wrench counts into the plan's wrench evaluations.
 *
 * The state vector (ground frame, SI): the 1-D model uses the same vector
 * with y, phi, vy, w staying 0.  SF_OSC_WORK is the friction work W(t)
 * (integral of the wrench's power) for the energy balance. */
enum { SF_OSC_X, SF_OSC_Y, SF_OSC_PHI, SF_OSC_VX, SF_OSC_VY, SF_OSC_W, SF_OSC_WORK, SF_OSC_NSTATE };

/* Slip right-hand side f = dy/dt at (t, y) (Eqs. 3-5 with the kinetic
 * wrench: Eq. 4, the Contensou closed form or the quadrature of Eqs. 7-8,
 * as the plan decided); q (may be NULL) receives the wrench (Fx, Fy, T). */
void sf_osc_slip_rhs(sf_osc *o, double t, const double *y, double *f, double q[3]);

/* ---- Code verification (manufactured solutions, cases/mms).
 *
 * An optional source term added to the slip equations: fn(ctx, t, S)
 * fills S = (S_x [N], S_y [N], S_phi [N m]), added to the right of rows
 * x, y, phi of Eq. 5 (m x'' = -k x + Fx + S_x, m y'' = -k y + Fy + S_y,
 * J phi'' = T + S_phi).  It is not friction: the work row and the wrench q
 * sf_osc_slip_rhs returns leave it out.  fn = NULL removes it; a plan
 * without a source computes exactly as before (same bits).  Read by
 * sf_osc_slip_integrate and by sf_osc_run in its slip phases (stick is
 * exact kinematics and never reads it): a manufactured solution through
 * events takes each slip arc's own source (cases/mms/events.md). */
typedef void (*sf_osc_source_fn)(void *ctx, double t, double S[3]);
void sf_osc_set_source(sf_osc *o, sf_osc_source_fn fn, void *ctx);

/* The slip equations alone (no events, no stick, no error control) from
 * y0 at t0 to t1 > t0 with n = ceil((t1 - t0)/h) equal fixed steps of
 * (t1 - t0)/n, by gsl_odeiv2_step_apply of the plan's stepper (rk4, rkck,
 * rk8pd; adaptive: the one it chose); y0, y1 hold SF_OSC_NSTATE values and
 * may alias.  For observed orders.  Returns SF_SUCCESS, SF_EINVAL (t1 <=
 * t0, h <= 0, more than 1e8 steps) or SF_EFAIL (non-finite state). */
int sf_osc_slip_integrate(sf_osc *o, double t0, const double *y0, double t1, double h, double *y1);

/* The error control's scale of each state component (the problem's own
 * scales: x_s = (mu_mean + mu_std) m g / k for lengths, x_s omega_n for
 * speeds, x_s / R and x_s omega_n / R for angle and spin,
 * (mu_mean + mu_std) m g x_s for the work): sf_osc_run's error control
 * asks rtol (|y_i| + sc[i]) of component i. */
void sf_osc_scales(const sf_osc *o, double sc[SF_OSC_NSTATE]);

/* Slip-to-stick switching function: lambda - eps_lambda while that is
 * >= 0, else max(lambda - eps_lambda, -margin / (m g)) with margin the stick
 * admissibility margin [N] of the stick wrench (k x, k y) at the belt
 * point under the disc at time t (exact_section: on the oscillator's own
 * limit surface, made by sf_osc_alloc and re-centred per call; NaN, and
 * sf_osc_run fails, if the section's root finder does).  Stick may start
 * where it is < 0; only its sign is meaningful.  The solver arms it after it has been > 0 in a
 * slip phase (it starts each slip phase at zero); a peer's root-finding on
 * decreasing crossings plays that role. */
double sf_osc_g_stick(const sf_osc *o, double t, const double *y);

/* Duration of the stick phase starting at (t, y) (>= 0): the belt patch
 * stays fixed, the disc moves with the belt, the break is the exit of the
 * stick wrench from the equatorial circle (closed form) or from the exact
 * T = 0 section (scene exact_section; o keeps one limit surface for it,
 * made with o and re-centred on each call: hence o is not const). */
double sf_osc_stick_duration(sf_osc *o, double t, const double *y);

/* Stick motion over dt (exact, no quadrature): x += v_b dt, and the stick
 * wrench's work into y[SF_OSC_WORK]. */
void sf_osc_stick_move(const sf_osc *o, double *y, double dt);

/* Eq. 12 at a slip-to-stick instant: velocities (v_b, 0, 0).  Returns the
 * kinetic-energy change of that jump [J]. */
double sf_osc_stick_onset(const sf_osc *o, double *y);

/* Eq. 14 at a stick-to-slip instant: the relative velocity jumps to
 * eps_lambda omega_n R opposite the stick wrench (k x, k y), spin 0; a
 * no-op with velocity_jump = false.  Returns the kinetic-energy change [J]. */
double sf_osc_slip_onset(const sf_osc *o, double *y);

#ifdef __cplusplus
}
#endif
#endif
