/* Checks of the 1-D deterministic oscillator (Eqs. 3-4) and of the 3-DOF
 * integrator with a spatially constant COF, against the closed-form cycle
 * (solver/dynamics/cycle1d.h: ideal and with the eps_lambda threshold's own effect)
 * and exact invariants (energy balance, symmetry). */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "cycle1d.h"
#include "cof.h"
#include "oscillator.h"
#include "sf_error.h"

#include <math.h>
#include <gsl/gsl_math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_math.h>

/* max |t_i - closed form| over all transitions, and the index of the worst */
static double transition_error(const sf_osc_result *res, const sf_cycle1d *cf, size_t *worst)
{
    double e = 0;
    *worst = 0;
    for (size_t i = 0; i < res->ntrans; i++) {
        double d = fabs(res->trans_t[i] - sf_cycle1d_transition(cf, (unsigned)i));
        if (!(d <= e) && !isnan(e))
            *worst = i;   /* the first NaN is the worst */
        e = sf_max(e, d); /* not `if (!(d <= e)) e = d`: a later finite d would replace a NaN */
    }
    return e;
}

/* The simulated cycle vs the eps-corrected closed form: PV_x, PV_F, stick
 * fraction, period, stick and slip durations, and every transition time. */
static int chk_cycle(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cycle1d cf, ideal;
    if (sf_cycle1d_init(&cf, s, s->eps_lambda) || sf_cycle1d_init(&ideal, s, 0))
        return SF_EINVAL;
    sf_osc_result res;
    check_hist h = { .every = 1 };
    if (check_osc_run(s, NULL, NULL, 0, &res, check_hist_row, &h, r))
        return SF_EFAIL;
    size_t worst;
    double te = transition_error(&res, &cf, &worst), tol = c->spec.tolerance;
    double stick = 0;
    for (size_t i = 0; i < res.ncycles; i++)
        stick += res.cycle_stick[i];
    stick /= (double)res.ncycles;
    sf_check_rel(r, "PV_x per complete cycle [m]", res.cyc_pv_x, cf.pv_x, tol);
    sf_check_rel(r, "PV_F per complete cycle [N]", res.cyc_pv_F, cf.pv_F, tol);
    sf_check_rel(r, "stick fraction of the complete cycles [-]", res.cyc_stick_fraction, cf.stick_fraction, tol);
    /* the paper's definitions (Sec. 3.1): each oscillation (maximum of x
     * to the next) holds one whole stick-slip cycle, so its PVs are the
     * cycle's; T_sk over [t_skip, T] counts the window's partial stick
     * spans, from the closed form's transition times */
    double tsk = sf_cycle1d_stick_time(&cf, s->t_skip, s->T);
    sf_check_rel(r, "PV_x per oscillation [m] (paper)", res.osc_pv_x_mean, cf.pv_x, tol);
    sf_check_rel(r, "PV_F per oscillation [N] (paper)", res.osc_pv_F_mean, cf.pv_F, tol);
    sf_check_rel(r, "stick time inside [t_skip, T] [s] (paper's t_sk)", res.stick_time, tsk, tol);
    sf_check_rel(r, "T_sk = t_sk / (T - t_skip) [-] (paper)", res.win_stick_fraction, tsk / (s->T - s->t_skip), tol);
    sf_check_rel(r, "period [s]", res.period, cf.period, tol);
    sf_check_rel(r, "stick duration [s]", stick, cf.t_stick, tol);
    sf_check_rel(r, "slip duration [s]", res.period - stick, cf.t_slip, tol);
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "max |transition time - closed form| over %zu transitions [s] (worst: #%zu)", res.ntrans, worst);
    sf_check_le(r, q, te, tol * cf.period);
    unsigned nexp = 0;
    while (sf_cycle1d_transition(&cf, nexp) <= s->T)
        nexp++;
    sf_check_abs(r, "number of transitions in [0, T]", (double)res.ntrans, (double)nexp, 0);
    sf_note(r, "%s model, %s; eps_lambda = %g, so slip starts and ends at relative speed delta = eps omega_n R = "
               "%.4g m/s. Closed form with that delta: PV_x = %.9f m, period %.9f s; the ideal cycle (delta = 0) "
               "has PV_x = %.9f m, period %.9f s: the threshold moves PV_x by %.2e relative, which is why the "
               "comparison is with the corrected form. %lu steps, %lu event trial steps.",
            s->dof == SF_DOF_1 ? "1-D" : "3-DOF (constant COF, Contensou closed-form wrench)",
            s->integrator == SF_INTEG_RK4 ? "fixed-step RK4" : "adaptive rk8pd", s->eps_lambda, cf.delta, cf.pv_x,
            cf.period, ideal.pv_x, ideal.period, cf.pv_x / ideal.pv_x - 1, res.steps, res.event_trials);
    sf_note(r, "Over the window [%g, %g] s: %zu oscillations, %zu complete cycles; T_sk = %.9f against the cycle's "
               "stick fraction %.9f (the window's partial cycles: %.2e relative).", s->t_skip, s->T, res.nosc,
            res.ncycles, res.win_stick_fraction, cf.stick_fraction, res.win_stick_fraction / cf.stick_fraction - 1);
    sf_plot *p = sf_result_plot(r, "displacement", "Displacement of the disc (1-D stick-slip cycle)", "t [s]", "x [m]");
    sf_plot_series(p, "x(t), simulated", SF_STYLE_LINES, h.n, h.t, h.x);
    sf_plot_hline(p, "x_s = mu_s m g / k", cf.xs);
    double *idx = check_alloc((res.ntrans + 1) * sizeof *idx), *err = check_alloc((res.ntrans + 1) * sizeof *err);
    for (size_t i = 0; i < res.ntrans; i++) {
        idx[i] = (double)i;
        err[i] = sf_max(fabs(res.trans_t[i] - sf_cycle1d_transition(&cf, (unsigned)i)), 1e-16);
    }
    sf_plot *p2 = sf_result_plot(r, "transition_error", "Transition times vs the closed form", "transition index [-]",
                                 "|t - t_exact| [s]");
    sf_plot_log(p2, 0, 1);
    sf_plot_series(p2, "simulated", SF_STYLE_POINTS, res.ntrans, idx, err);
    sf_plot_hline(p2, "tolerance (tol x period)", tol * cf.period);
    free(idx);
    free(err);
    check_hist_free(&h);
    sf_osc_result_free(&res);
    return SF_SUCCESS;
}

/* A disc that never sticks (v_b - delta above x_e omega: the first slip
 * from rest never slows to the belt) still oscillates, and the paper's
 * PV counts each oscillation: x = x_e (1 - cos omega t) exactly (Fx =
 * mu_k m g throughout), maxima 2 x_e at t = (2 j + 1) pi / omega, so
 * every oscillation has PV_x = 2 x_e and PV_F = 0, their number is the
 * maxima inside [t_skip, T] less one, and T_sk = 0.  Run with the scene's
 * dof and with the other (3-DOF: the Contensou wrench without spin is the
 * same force). */
static int chk_slide_on(const sf_case *c, sf_result *r)
{
    const double tol = c->spec.tolerance;
    for (int dof = 0; dof < 2; dof++) {
        sf_scene s = c->scene;
        s.dof = dof ? SF_DOF_3 : SF_DOF_1;
        double N = s.m * s.g, om = sqrt(s.k / s.m), xe = s.mu_k_ratio * s.mu_mean * N / s.k;
        double vr = s.v_b - check_jump_speed(&s);
        char q[SF_LABEL_LEN];
        snprintf(q, sizeof q, "%s: slide-on scene (v_b - delta > x_e omega)", dof ? "3-DOF" : "1-D");
        sf_check_true(r, q, vr > xe * om, "v_b - delta vs x_e omega");
        sf_osc_result res;
        check_hist h = { .every = 1 };
        if (check_osc_run(&s, NULL, NULL, 0, &res, check_hist_row, &h, r))
            return SF_EFAIL;
        if (!dof) {
            sf_plot *p = sf_result_plot(r, "slide_on", "A disc sliding on (1-D): x(t) oscillates without sticking",
                                        "t [s]", "x [m]");
            sf_plot_series(p, "x(t), simulated", SF_STYLE_LINES, h.n, h.t, h.x);
            sf_plot_hline(p, "2 x_e (each maximum)", 2 * xe);
        }
        check_hist_free(&h);
        long j0 = (long)ceil((s.t_skip * om / M_PI - 1) / 2), j1 = (long)floor((s.T * om / M_PI - 1) / 2);
        double nexp = (double)(j1 - j0);   /* maxima j0 .. j1 bound j1 - j0 oscillations */
        const char *tag = dof ? "3-DOF" : "1-D";
        snprintf(q, sizeof q, "%s: oscillations inside [t_skip, T] (maxima of x less one)", tag);
        sf_check_abs(r, q, (double)res.nosc, nexp, 0);
        snprintf(q, sizeof q, "%s: PV_x per oscillation = 2 x_e [m]", tag);
        sf_check_rel(r, q, res.pv_x, 2 * xe, tol);
        snprintf(q, sizeof q, "%s: PV_F per oscillation = 0 [N] (abs., tol x mu_k m g)", tag);
        sf_check_abs(r, q, res.pv_F, 0, tol * s.mu_k_ratio * s.mu_mean * N);
        snprintf(q, sizeof q, "%s: T_sk = 0 (no stick)", tag);
        sf_check_abs(r, q, res.stick_fraction, 0, 0);
        sf_note(r, "%s: %zu oscillations, PV_x = %.12f m (2 x_e = %.12f m), PV_F = %.3e N, %zu transitions.", tag,
                res.nosc, res.pv_x, 2 * xe, res.pv_F, res.ntrans);
        sf_osc_result_free(&res);
    }
    return SF_SUCCESS;
}

/* The threshold's effect on the cycle is first order in eps_lambda: PV_x
 * and the slip duration vs the ideal closed form, observed order 1, and
 * each deviation equal to the corrected closed form's prediction. */
static int chk_eps_order(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (K < 3)
        return SF_EINVAL;
    double *e = check_alloc(K * sizeof *e), *dp = check_alloc(K * sizeof *dp), *ds = check_alloc(K * sizeof *ds);
    double *pp = check_alloc(K * sizeof *pp), worst_pred = 0;
    sf_note(r, "| eps_lambda | PV_x - ideal [m] | predicted | slip - ideal [s] | predicted |\n|---|---|---|---|---|");
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        s.eps_lambda = c->spec.sweep.v[k];
        sf_cycle1d cf, ideal;
        if (sf_cycle1d_init(&cf, &s, s.eps_lambda) || sf_cycle1d_init(&ideal, &s, 0))
            return SF_EINVAL;
        sf_osc_result res;
        if (check_osc_run(&s, NULL, NULL, 0, &res, NULL, NULL, r))
            return SF_EFAIL;
        double stick = 0;
        for (size_t i = 0; i < res.ncycles; i++)
            stick += res.cycle_stick[i];
        stick /= (double)res.ncycles;
        e[k] = s.eps_lambda;
        dp[k] = fabs(res.pv_x - ideal.pv_x);
        ds[k] = fabs(res.period - stick - ideal.t_slip);
        pp[k] = fabs(cf.pv_x - ideal.pv_x);
        worst_pred = sf_max(worst_pred, sf_max(fabs((res.pv_x - ideal.pv_x) - (cf.pv_x - ideal.pv_x)) / pp[k],
                                           fabs((res.period - stick - ideal.t_slip) - (cf.t_slip - ideal.t_slip)) /
                                               fabs(cf.t_slip - ideal.t_slip)));
        sf_note(r, "| %g | %.6e | %.6e | %.6e | %.6e |", e[k], res.pv_x - ideal.pv_x, cf.pv_x - ideal.pv_x,
                res.period - stick - ideal.t_slip, cf.t_slip - ideal.t_slip);
        sf_osc_result_free(&res);
    }
    double op = check_loglog_slope(e, dp, K), os = check_loglog_slope(e, ds, K);
    sf_check_abs(r, "observed order of the PV_x deviation in eps_lambda", op, 1, c->spec.tolerance);
    sf_check_abs(r, "observed order of the slip-duration deviation in eps_lambda", os, 1, c->spec.tolerance);
    sf_check_le(r, "max relative gap between each deviation and the corrected closed form's prediction",
                worst_pred, 1e-3);
    sf_plot *p = sf_result_plot(r, "eps_order", "Deviation from the ideal cycle vs the threshold",
                                "eps_lambda [-]", "|deviation| [m or s]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "PV_x, simulated [m]", SF_STYLE_POINTS, K, e, dp);
    sf_plot_series(p, "PV_x, corrected closed form [m]", SF_STYLE_LINES, K, e, pp);
    sf_plot_series(p, "slip duration, simulated [s]", SF_STYLE_LINESPOINTS, K, e, ds);
    free(e); free(dp); free(ds); free(pp);
    return SF_SUCCESS;
}

/* Observed order of the time stepper: max transition-time error vs the
 * corrected closed form over the sweep of dt (rk4) or rtol (adaptive). */
static int chk_step_order(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (K < 3)
        return SF_EINVAL;
    int rk4 = s0->integrator == SF_INTEG_RK4;
    double *h = check_alloc(K * sizeof *h), *err = check_alloc(K * sizeof *err), *cost = check_alloc(K * sizeof *cost);
    sf_cycle1d cf;
    if (sf_cycle1d_init(&cf, s0, s0->eps_lambda))
        return SF_EINVAL;
    sf_note(r, "| %s | max transition-time error [s] | PV_x rel. error | steps |\n|---|---|---|---|", rk4 ? "dt [s]" : "rtol");
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        if (rk4)
            s.dt = c->spec.sweep.v[k];
        else
            s.rtol = c->spec.sweep.v[k];
        sf_osc_result res;
        if (check_osc_run(&s, NULL, NULL, 0, &res, NULL, NULL, r))
            return SF_EFAIL;
        size_t w;
        h[k] = c->spec.sweep.v[k];
        err[k] = transition_error(&res, &cf, &w);
        cost[k] = (double)res.steps;
        sf_note(r, "| %g | %.3e | %.3e | %lu |", h[k], err[k], res.pv_x / cf.pv_x - 1, res.steps);
        sf_osc_result_free(&res);
    }
    double ord = check_loglog_slope(h, err, K);
    sf_check_ge(r, rk4 ? "observed order of RK4 in dt (transition times)" : "observed order of the error in rtol",
                ord, c->spec.tolerance);
    sf_note(r, "\nObserved order %.3f (least squares over the sweep). Expected: %s.\n", ord,
            rk4 ? "4 for classical RK4 (the events are located with the same stepper, so they inherit its order)"
                : "about 1: the error control keeps the local error near rtol, and the global error follows it");
    sf_plot *p = sf_result_plot(r, "step_order", rk4 ? "Transition-time error vs step (RK4)" : "Transition-time error vs rtol (rk8pd)",
                                rk4 ? "dt [s]" : "rtol [-]", "max |t - t_exact| [s]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "measured", SF_STYLE_LINESPOINTS, K, h, err);
    double *ref = check_alloc(K * sizeof *ref);
    for (size_t k = 0; k < K; k++)
        ref[k] = err[0] * pow(h[k] / h[0], c->spec.tolerance);
    sf_plot_series(p, "slope of the accepted order", SF_STYLE_LINES, K, h, ref);
    free(ref); free(h); free(err); free(cost);
    return SF_SUCCESS;
}

/* The 3-DOF integrator with a constant COF reduces to the 1-D model: the
 * closed-form path exactly (same transitions bit for bit, y = phi = 0), the
 * quadrature path (a constant field on a grid) to the quadrature's
 * round-off. */
static int chk_3dof_reduces(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    sf_scene s1 = *s0, s3 = *s0;
    s1.dof = SF_DOF_1;
    s3.dof = SF_DOF_3;
    sf_osc_result a, b, q;
    check_hist hb = { .every = 1 }, hq = { .every = 1 };
    double dt = 1e-2;
    if (check_osc_run(&s1, NULL, NULL, dt, &a, NULL, NULL, r) || check_osc_run(&s3, NULL, NULL, dt, &b, check_hist_row, &hb, r))
        return SF_EFAIL;
    /* the same constant COF as a 3 x 3 grid: the quadrature path */
    double g[9];
    for (int i = 0; i < 9; i++)
        g[i] = s0->mu_mean;
    sf_cof *grid;
    sf_cof_alloc_grid(3, 3, -1e3, -1e3, 1e3, 1e3, g, &grid);
    if (check_osc_run(&s3, NULL, grid, dt, &q, check_hist_row, &hq, r))
        return SF_EFAIL;
    double dtr = 0, dq = 0, dqx = 0;
    for (size_t i = 0; i < a.ntrans && i < b.ntrans; i++)
        dtr = sf_max(dtr, fabs(a.trans_t[i] - b.trans_t[i]));
    for (size_t i = 0; i < a.ntrans && i < q.ntrans; i++) {
        dq = sf_max(dq, fabs(a.trans_t[i] - q.trans_t[i]));
        dqx = sf_max(dqx, fabs(a.trans_x[i] - q.trans_x[i]));
    }
    sf_check_abs(r, "closed-form path: transitions (3-DOF vs 1-D count)", (double)b.ntrans, (double)a.ntrans, 0);
    sf_check_le(r, "closed-form path: max |t_3DOF - t_1D| over transitions [s]", dtr, 0);
    sf_check_le(r, "closed-form path: max |y| [m] and |phi| [rad]", sf_max(hb.y_absmax, hb.phi_absmax), 0);
    sf_check_abs(r, "quadrature path: transitions (3-DOF vs 1-D count)", (double)q.ntrans, (double)a.ntrans, 0);
    sf_check_le(r, "quadrature path: max |t_3DOF - t_1D| over transitions [s]", dq, c->spec.tolerance);
    sf_check_le(r, "quadrature path: max |x_3DOF - x_1D| at the transitions [m]", dqx, c->spec.tolerance);
    sf_check_le(r, "quadrature path: max |y| [m]", hq.y_absmax, 1e-10);
    sf_check_le(r, "quadrature path: max |phi| [rad]", hq.phi_absmax, 1e-10);
    sf_note(r, "The closed-form path (Contensou forms with zero spin) must give the 1-D model bit for bit. The "
               "quadrature path sums cells whose torque cancels only to round-off (~1e-16 relative), so y and "
               "phi leave zero at that level and the equations' stability keeps them there; x agrees to the "
               "solver's tolerance. Max |y| %.2e m, |phi| %.2e rad.", hq.y_absmax, hq.phi_absmax);
    sf_plot *p = sf_result_plot(r, "y_phi", "Out-of-plane motion of the 3-DOF model with a constant COF", "t [s]",
                                "|y| [m], |phi| [rad]");
    sf_plot_log(p, 0, 1);
    double *ay = check_alloc(hq.n * sizeof *ay), *ap = check_alloc(hq.n * sizeof *ap);
    for (size_t i = 0; i < hq.n; i++) {
        ay[i] = sf_max(fabs(hq.y[i]), 1e-20);
        ap[i] = sf_max(fabs(hq.phi[i]), 1e-20);
    }
    sf_plot_series(p, "|y|, quadrature path", SF_STYLE_LINES, hq.n, hq.t, ay);
    sf_plot_series(p, "|phi|, quadrature path", SF_STYLE_LINES, hq.n, hq.t, ap);
    free(ay); free(ap);
    sf_cof_free(grid);
    check_hist_free(&hb);
    check_hist_free(&hq);
    sf_osc_result_free(&a);
    sf_osc_result_free(&b);
    sf_osc_result_free(&q);
    return SF_SUCCESS;
}

/* Energy balance: E(T) - E(0) = friction work + the jumps' kinetic-energy
 * changes (stick work k v_b int x dt in closed form, slip work integrated
 * with the motion). A friction sign error or a missing term breaks it at
 * O(1) relative. */
static int chk_energy(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    gsl_rng *rng = sf_case_rng(c);
    sf_osc_result res;
    check_hist h = { .every = 1 };
    int rc = check_osc_run(s, rng, NULL, 0, &res, check_hist_row, &h, r);
    gsl_rng_free(rng);
    if (rc)
        return SF_EFAIL;
    double scale = fabs(res.friction_work) + fabs(res.energy_change);
    sf_check_le(r, "|E(T) - E(0) - W_friction - jumps| / (|W| + |dE|)", fabs(res.energy_residual) / scale, c->spec.tolerance);
    sf_note(r, "E(T) - E(0) = %.9g J; friction work %.9g J (stick phases in closed form, slip integrated); jumps "
               "(Eqs. 12, 14) %.3e J; residual %.3e J. The friction work is the negative of the dissipated energy "
               "in slip and positive in stick (the belt drags the disc against the spring).",
            res.energy_change, res.friction_work, res.jump_energy, res.energy_residual);
    double *e = check_alloc(h.n * sizeof *e);
    for (size_t i = 0; i < h.n; i++)
        e[i] = 0.5 * s->m * h.vx[i] * h.vx[i] + 0.5 * s->k * (h.x[i] * h.x[i] + h.y[i] * h.y[i]);
    sf_plot *p = sf_result_plot(r, "energy", "Mechanical energy (translation) over the run", "t [s]", "E [J]");
    sf_plot_series(p, "m vx^2/2 + k (x^2 + y^2)/2", SF_STYLE_LINES, h.n, h.t, e);
    free(e);
    check_hist_free(&h);
    sf_osc_result_free(&res);
    return SF_SUCCESS;
}

/* ---- The window's edges against the closed-form timeline.
 *
 * Started in stick at the limit cycle's stick onset (x0 = x_e - d, vx0 =
 * v_b: the stick set holds it at t = 0), the run is the limit cycle from
 * t = 0 with no transient, and every phase boundary is a closed form (the
 * checks' own ref_cycle, common.c): with P = t_st + t_sl,
 *   stick j:  [j P, j P + t_st],
 *   slip j:   [j P + t_st, (j + 1) P],
 *   maximum of x in slip j at j P + t_st + theta_m / omega, theta_m =
 *   atan(v_r / (omega d)) (x - x_e = d cos th + (v_r / omega) sin th after
 *   the break), where x = x_e + A; the minimum pi / omega later.
 * The paper's QoIs over [t_skip, T] follow by counting: the stick time is
 * the sum of |stick j intersected with [t_skip, T]| (a cut phase counts its
 * part); an oscillation runs from one maximum at or after t_skip to the
 * next at or before T, so there are (maxima in [t_skip, T]) - 1 of them,
 * and each holds one whole cycle: PV_x = 2 A, PV_F = 2 k d. */
typedef struct {
    double P, tst, tmax;   /* period, stick duration, a maximum's time after the stick onset [s] */
} edge_timeline;

static double edge_stick_time(const edge_timeline *e, double t0, double t1)
{
    double sum = 0;
    for (long j = 0; (double)j * e->P <= t1; j++) {
        double a = fmax((double)j * e->P, t0), b = fmin((double)j * e->P + e->tst, t1);
        if (b > a)
            sum += b - a;
    }
    return sum;
}

static long edge_maxima(const edge_timeline *e, double t0, double t1)
{
    long n = 0;
    for (long j = 0; (double)j * e->P + e->tmax <= t1; j++)
        n += (double)j * e->P + e->tmax >= t0;
    return n;
}

/* Phase boundaries (stick onsets, breaks) strictly inside (t0, t1). */
static long edge_boundaries(const edge_timeline *e, double t0, double t1)
{
    long n = 0;
    for (long j = 0; (double)j * e->P <= t1; j++) {
        double b[2] = { (double)j * e->P, (double)j * e->P + e->tst };
        for (int i = 0; i < 2; i++)
            n += b[i] > t0 && b[i] < t1;
    }
    return n;
}

/* Three windows, each with one edge inside a phase the definitions must
 * cut, the other edge where no rule is at stake; run with dof 1 and 3
 * (uniform COF: the 3-DOF model is the 1-D one). */
static int chk_window_edges(const sf_case *c, sf_result *r)
{
    ref_cycle1d cy;
    if (ref_cycle(&c->scene, c->scene.mu_mean, &cy))
        return SF_EINVAL;
    const double tol = c->spec.tolerance;
    const sf_scene *s0 = &c->scene;
    double P = cy.t_stick + cy.t_slip, thm = atan2(cy.vr, cy.omega * cy.d);
    edge_timeline e = { P, cy.t_stick, cy.t_stick + thm / cy.omega };
    double tdown = cy.t_stick + 0.5 * cy.t_slip;   /* mid-slip, after the maximum, before the minimum */
    double tup = cy.t_stick + 0.5 * thm / cy.omega; /* slip, after the break, before the maximum */
    struct {
        const char *name;
        double t_skip, T;
    } w[3] = {
        { "T mid-stick (half of stick 8 inside)", 2 * P + tdown, 8 * P + 0.5 * cy.t_stick },
        { "t_skip mid-stick (the last 0.6 of stick 2 inside)", 2 * P + 0.4 * cy.t_stick, 8 * P + tup },
        { "T mid-slip (cuts oscillation 8 between its maximum and minimum)", 2 * P + tdown, 8 * P + tdown },
    };
    sf_note(r, "Closed-form cycle (ref_cycle, eps_lambda = %g): x_s = %.12g m, x_e = %.12g m, d = %.12g m, omega = "
               "%.12g 1/s, v_r = v_b - eps omega R = %.12g m/s; stick %.12g s, slip %.12g s, period %.12g s; "
               "maximum of x %.12g s after each stick onset; PV_x = 2 A = %.12g m, PV_F = 2 k d = %.12g N. The run "
               "starts in stick at x0 = x_e - d = %.12g m, vx0 = v_b: the limit cycle from t = 0.\n\n"
               "| window | t_skip [s] | T [s] | stick time [s] | T_sk | oscillations | boundaries inside |\n"
               "|---|---|---|---|---|---|---|",
            s0->eps_lambda, cy.xs, cy.xe, cy.d, cy.omega, cy.vr, cy.t_stick, cy.t_slip, P, e.tmax, cy.pv_x, cy.pv_F,
            cy.xe - cy.d);
    double exp_t[3], exp_sf[3];
    long exp_n[3], nb[3];
    for (int i = 0; i < 3; i++) {
        exp_t[i] = edge_stick_time(&e, w[i].t_skip, w[i].T);
        exp_sf[i] = exp_t[i] / (w[i].T - w[i].t_skip);
        exp_n[i] = edge_maxima(&e, w[i].t_skip, w[i].T) - 1;
        nb[i] = edge_boundaries(&e, w[i].t_skip, w[i].T);
        sf_note(r, "| %s | %.12g | %.12g | %.12g | %.12g | %ld | %ld |", w[i].name, w[i].t_skip, w[i].T, exp_t[i],
                exp_sf[i], exp_n[i], nb[i]);
    }
    sf_plot *p = NULL;
    for (int dof = 1; dof <= 3; dof += 2)
        for (int i = 0; i < 3; i++) {
            sf_scene s = *s0;
            s.dof = dof == 1 ? SF_DOF_1 : SF_DOF_3;
            s.cof = SF_COF_UNIFORM;
            s.qoi_def = SF_QOI_PAPER;
            s.x0 = cy.xe - cy.d;
            s.vx0 = s.v_b;
            s.t_skip = w[i].t_skip;
            s.T = w[i].T;
            sf_osc_result res;
            check_hist h = { .every = 1 };
            if (check_osc_run(&s, NULL, NULL, 0, &res, check_hist_row, &h, r))
                return SF_EFAIL;
            if (dof == 1) {   /* x(t) up to each window's T, with its edges */
                if (!p)
                    p = sf_result_plot(r, "window_edges", "x(t) of the 1-D runs and the windows' edges", "t [s]",
                                       "x [m]");
                char lab[160];
                snprintf(lab, sizeof lab, "x(t), run to T of window %d", i + 1);
                sf_plot_series(p, lab, SF_STYLE_LINES, h.n, h.t, h.x);
                double ex[2][2] = { { s.t_skip, s.t_skip }, { s.T, s.T } };
                double ey[2] = { cy.xe - 1.2 * cy.pv_x / 2, cy.xe + 1.2 * cy.pv_x / 2 };
                snprintf(lab, sizeof lab, "window %d: t_skip", i + 1);
                sf_plot_series(p, lab, SF_STYLE_LINES, 2, ex[0], ey);
                snprintf(lab, sizeof lab, "window %d: T", i + 1);
                sf_plot_series(p, lab, SF_STYLE_LINES, 2, ex[1], ey);
            }
            check_hist_free(&h);
            char q[240];
            const char *tag = dof == 1 ? "1-D" : "3-DOF";
            /* each boundary inside the window is off by at most tol x
             * period (cases/deterministic/cycle-adaptive's bound on the
             * transition times); the window's own edges are exact */
            double at = (double)nb[i] * tol * P;
            snprintf(q, sizeof q, "%s, %s: stick time inside [t_skip, T] [s] (abs. tol: %ld boundaries x tol x period)",
                     tag, w[i].name, nb[i]);
            sf_check_abs(r, q, res.stick_time, exp_t[i], at);
            snprintf(q, sizeof q, "%s, %s: T_sk (paper) [-]", tag, w[i].name);
            sf_check_abs(r, q, res.stick_fraction, exp_sf[i], at / (s.T - s.t_skip));
            snprintf(q, sizeof q, "%s, %s: oscillations (maximum to maximum inside the window)", tag, w[i].name);
            sf_check_abs(r, q, (double)res.nosc, (double)exp_n[i], 0);
            snprintf(q, sizeof q, "%s, %s: PV_x (paper) [m]", tag, w[i].name);
            sf_check_rel(r, q, res.pv_x, cy.pv_x, tol);
            snprintf(q, sizeof q, "%s, %s: PV_F (paper) [N]", tag, w[i].name);
            sf_check_rel(r, q, res.pv_F, cy.pv_F, tol);
            sf_note(r, "%s, %s: stick time %.12g s (exact %.12g), T_sk %.12g (exact %.12g), %zu oscillations, PV_x "
                       "%.12g m, PV_F %.12g N.", tag, w[i].name, res.stick_time, exp_t[i], res.stick_fraction,
                    exp_sf[i], res.nosc, res.pv_x, res.pv_F);
            sf_osc_result_free(&res);
        }
    return SF_SUCCESS;
}

const sf_check_def sf_checks_deterministic[] = {
    { "det_cycle", chk_cycle, "1-D cycle vs the eps-corrected closed form: PV, durations, transition times" },
    { "det_slide_on", chk_slide_on, "a disc that never sticks: PV per oscillation 2 x_e, T_sk = 0 (the paper's definitions)" },
    { "det_eps_order", chk_eps_order, "the threshold's effect is first order in eps_lambda, as predicted" },
    { "det_step_order", chk_step_order, "observed order of the stepper (dt for RK4, rtol for rk8pd)" },
    { "det_3dof_reduces", chk_3dof_reduces, "3-DOF with a constant COF equals the 1-D model" },
    { "det_window_edges", chk_window_edges,
      "the paper's QoIs at a window that cuts a stick or a slip phase, against the closed-form timeline" },
    { "det_energy", chk_energy, "energy balance: dE = friction work + jumps" },
    { NULL, NULL, NULL }
};
