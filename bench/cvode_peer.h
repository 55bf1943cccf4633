/* SUNDIALS CVODE (6.x API) with root-finding as a benchmark-only peer of
 * the 1-D stick-slip integrator (issue 6).  Only the benchmark links it:
 * everything here exists when bench_config.h says SF_HAVE_CVODE.
 *
 * The model is the one of solver/oscillator.c for dof = 1 and a spatially
 * constant COF, transition for transition:
 *  - start at rest at the origin; slip if lambda(0) > eps_lambda, else
 *    stick from t = 0 (Eq. 12);
 *  - slip: m x'' = -k x + Fx, Fx = -mu_k m g sign(vx - v_b) (Eqs. 3-4),
 *    integrated by CVODE (BDF with a dense direct solver and the exact
 *    Jacobian, or Adams with the fixed-point nonlinear solver);
 *  - slip -> stick: the same switching function as the solver, lambda -
 *    eps_lambda while >= 0, else max(lambda - eps_lambda, -margin / (m g))
 *    with margin = mu m g - k |x| (stick admissible), located by CVODE's
 *    root-finding on its interpolant (decreasing crossings only: that is
 *    the solver's "arm after the function leaves zero" rule, since the
 *    function starts each slip at zero and rises); then Eq. 12, vx = v_b;
 *  - stick: exact motion with the belt, break at the closed-form exit of
 *    the equatorial circle k |x| = mu m g, tau = (mu m g / k - x) / v_b;
 *  - stick -> slip: Eq. 14, vx = v_b - eps_lambda omega_n R, then
 *    CVodeReInit from the new state.
 * Absolute tolerances in the problem's scales, as the solver's error
 * control: atol = rtol x_s for x and rtol x_s omega_n for vx, x_s the
 * static excursion mu m g / k. */
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
    long steps, fevals, gevals, jevals, err_fails, nl_fails;   /* summed over the slip phases */
} sf_cvpeer_result;

/* A CVODE plan for the 1-D scene s (dof = 1) with the constant COF cof:
 * context, vectors, solver memory, linear or nonlinear solver and root
 * function are created here, not in the timed run.  Returns 0, or nonzero
 * with the reason in err. */
int sf_cvpeer_alloc(const sf_scene *s, const sf_cof *cof, int method, double rtol, sf_cvpeer **out, char *err,
                    size_t errlen);
void sf_cvpeer_free(sf_cvpeer *p);

/* Run [0, T] (CVodeReInit at t = 0 and after every transition). */
int sf_cvpeer_run(sf_cvpeer *p, sf_cvpeer_result *r, char *err, size_t errlen);
void sf_cvpeer_result_free(sf_cvpeer_result *r);

#endif
#endif
