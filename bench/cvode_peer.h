/* SUNDIALS CVODE (6.x API) with root-finding as a benchmark-only peer of
 * the stick-slip integrator, 1-D (dof = 1, constant COF) and
 * 3-DOF (any COF, the field included).  Only the benchmark links it:
 * everything here exists when bench_config.h says SF_HAVE_CVODE.
 *
 * The model is not copied: the peer holds a plan of the solver
 * (sf_osc_alloc) and calls its exported pieces (oscillator.h), so it
 * differs from solver/dynamics/oscillator.c in the integrator and the event
 * location only:
 *  - start at rest at the origin; slip if the switching function
 *    sf_osc_g_stick is >= 0 at t = 0, else stick from t = 0 (Eq. 12,
 *    sf_osc_stick_onset);
 *  - slip: sf_osc_slip_rhs (Eqs. 3-5 with the plan's wrench: Eq. 4, the
 *    Contensou closed form or the quadrature of Eqs. 7-8 on the field)
 *    integrated by CVODE: BDF with a dense direct solver (1-D: the exact
 *    Jacobian, the model being linear in slip; 3-DOF: CVODE's
 *    difference-quotient Jacobian), or Adams with the fixed-point
 *    nonlinear solver.  1-D: CVODE's vector is (x, vx), the other
 *    components held at 0; 3-DOF: the solver's whole state vector,
 *    friction work included;
 *  - slip -> stick: sf_osc_g_stick located by CVODE's root-finding on its
 *    interpolant, decreasing crossings only (that is the solver's "arm
 *    after the function leaves zero" rule: the function starts each slip
 *    at zero and rises); then Eq. 12 (sf_osc_stick_onset);
 *  - stick: exact motion with the belt (sf_osc_stick_move) for
 *    sf_osc_stick_duration (the closed-form exit, or the exact section);
 *  - stick -> slip: Eq. 14 (sf_osc_slip_onset), then CVodeReInit.
 * Tolerances: rtol, and atol = rtol times the solver's error-control
 * scales (sf_osc_scales), component by component.
 * Samples x(i sample_dt) for Eq. 15 on the solver's grid (i = 0 ...
 * floor(T / sample_dt), each taken in the phase whose interval (t0, t1]
 * holds it): CVODE's dense output (CVodeGetDky) in slip, the exact linear
 * motion in stick. */
#ifndef SF_CVODE_PEER_H
#define SF_CVODE_PEER_H

#include <stddef.h>
#include "bench.h"
#include "cof.h"
#include "scene.h"

#if SF_HAVE_CVODE

enum { SF_CVPEER_BDF = 0, SF_CVPEER_ADAMS = 1 };

typedef struct sf_cvpeer sf_cvpeer;

typedef struct {
    size_t ntrans;          /* transitions in [0, T] */
    double *trans_t;        /* their times [s] */
    int *trans_kind;        /* SF_OSC_STICK_ONSET or SF_OSC_SLIP_ONSET */
    size_t nsamples;        /* x(i sample_dt), as sf_osc_result's (when asked) */
    double *x_samples, sample_dt;
    long steps, fevals, gevals, jevals, err_fails, nl_fails;   /* summed over the slip phases; fevals
                                                                   include the Jacobian's difference quotients */
} sf_cvpeer_result;

/* A CVODE plan for the scene s with the COF cof (kept by pointer): the
 * solver's plan, context, vectors, solver memory, linear or nonlinear
 * solver and root function are created here, not in the timed run.
 * Returns 0, or nonzero with the reason in err. */
int sf_cvpeer_alloc(const sf_scene *s, const sf_cof *cof, int method, double rtol, sf_cvpeer **out, char *err,
                    size_t errlen);
void sf_cvpeer_free(sf_cvpeer *p);

/* Run [0, T] (CVodeReInit after every transition); sample_dt > 0 also
 * fills r->x_samples. */
int sf_cvpeer_run(sf_cvpeer *p, double sample_dt, sf_cvpeer_result *r, char *err, size_t errlen);
void sf_cvpeer_result_free(sf_cvpeer_result *r);

#endif
#endif
