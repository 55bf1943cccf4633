/* Manufactured solutions (MMS) for the 3-DOF slip equations (Eq. 5 with
 * the wrench of Eqs. 7-8): code verification of the solver's slip
 * right-hand side and of its three steppers (docs/design.md sec. 7.3).
 *
 * A smooth trajectory q*(t) = (x*, y*, phi*)(t) is chosen inside one slip
 * phase, with the disc's instantaneous pole outside the disc at all times
 * (|u| > |w| R, u the centre's slip velocity), so that the slip direction
 * field over the disc is smooth (docs/design.md sec. 4.5, quadrature).  This
 * check computes the source
 *     S(t) = M q*'' + K q* - Q(q*, q*')
 * WITH ITS OWN CODE from the paper: M = diag(m, m, J), J = m R^2/2, K =
 * diag(k, k, 0) (Eq. 5); Q = -(F_sx, F_sy, T_s) with F_s, T_s the integrals
 * of Eq. 8 (friction on the disc opposes the local slip, solver/disc/contact.h),
 * by its own product rule (Gauss-Legendre in r, GSL glfixed, x the
 * trapezoid rule in angle, spectral for a smooth periodic integrand) and,
 * for a gridded COF, its own bilinear look-up of the grid values
 * (sf_cof_grid_view).  Nothing of the solver's wrench (Contensou closed
 * forms, sf_contact_* cells, sf_cof_eval) is used to build S.  The solver
 * then integrates M q'' + K q = Q + S from q*(0) with fixed steps
 * (sf_osc_slip_integrate, the source through sf_osc_set_source); its error
 * against q*(T) falls at the stepper's order until it meets the floor set
 * by the difference between the solver's wrench and this one. */
#include "checks.h"
#include "../stats.h"
#include "common.h"
#include "cof.h"
#include "oscillator.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

/* ---- the manufactured trajectory: a sum of sines per coordinate,
 * q*(t) = c + sum a_i sin(om_i t + ph_i).  With the belt at v_b = 1 m/s
 * and R = 0.5 m (pinned by the cases): |x*'| <= 0.2 m/s, so the centre
 * slips backwards at 0.8..1.2 m/s; |y*'| <= 0.12 m/s; |phi*'| <= 0.52
 * rad/s, so |w| R <= 0.26 m/s < 0.8 m/s <= |u|: the pole stays at least
 * 3 R from the centre. */
typedef struct {
    double c, a[2], om[2], ph[2];
} traj1;

static const traj1 TRAJ[3] = {
    { 0.05, { 0.08, 0.02 }, { 2.0, 3.1 }, { 0.0, 0.7 } },    /* x [m] */
    { 0.0, { 0.06, 0.02 }, { 1.5, 2.3 }, { 0.3, 1.1 } },     /* y [m] */
    { 0.1, { 0.30, 0.08 }, { 1.3, 2.7 }, { 0.5, -0.4 } },    /* phi [rad] */
};

/* value, first and second derivative of coordinate i at t */
static void traj_eval(int i, double t, double d[3])
{
    const traj1 *q = &TRAJ[i];
    d[0] = q->c;
    d[1] = d[2] = 0;
    for (int j = 0; j < 2; j++) {
        double s = sin(q->om[j] * t + q->ph[j]), c = cos(q->om[j] * t + q->ph[j]);
        d[0] += q->a[j] * s;
        d[1] += q->a[j] * q->om[j] * c;
        d[2] -= q->a[j] * q->om[j] * q->om[j] * s;
    }
}

/* the solver's state vector at q*(t) (friction work 0) */
static void traj_state(double t, double *y)
{
    double d[3][3];
    for (int i = 0; i < 3; i++)
        traj_eval(i, t, d[i]);
    memset(y, 0, SF_OSC_NSTATE * sizeof *y);
    y[SF_OSC_X] = d[0][0];
    y[SF_OSC_Y] = d[1][0];
    y[SF_OSC_PHI] = d[2][0];
    y[SF_OSC_VX] = d[0][1];
    y[SF_OSC_VY] = d[1][1];
    y[SF_OSC_W] = d[2][1];
}

/* ---- the manufactured field COF: a bilinear function of the belt
 * coordinates sampled on a grid, mu_s = mu_mean (1 + GX (xb - XC) + GY yb
 * + GXY (xb - XC) yb).  Bilinear interpolation reproduces it exactly, so
 * the interpolated COF the solver sees is smooth along the path (a generic
 * field's interpolant has kinks on the grid lines, which would make the
 * right-hand side only piecewise smooth in t and hide every stepper's
 * order): the right-hand side stays smooth and the orders are
 * observable, while the COF still varies along x, y and both together. */
#define GX 0.1     /* 1/m */
#define GY 0.3     /* 1/m */
#define GXY 0.1    /* 1/m^2 */
#define GRID_H 0.05   /* grid spacing [m] */

typedef struct {
    /* scene */
    double m, k, R, N, J, v_b, muk_ratio, mu;
    /* COF: uniform (grid NULL) or grid values */
    size_t gm, gn;
    double gx0, gy0, gdx, gdy;
    const double *grid;
    /* quadrature: nr Gauss-Legendre radii x na angles, as nodes (x, y)
     * [m] from the centre and weights dS = r dr dtheta [m^2] */
    size_t nr, na;
    double *x, *y, *dS;
    unsigned long evals;
    /* the manufactured trajectory: the sines above (NULL) or the
     * stick-slip one of mms_events */
    const struct evtraj *ev;
} mms_ref;

static void ev_eval(const struct evtraj *e, double t, double d[3][3]);

/* value, first and second derivative of x*, y*, phi* at t */
static void traj_at(const mms_ref *q, double t, double d[3][3])
{
    if (q->ev) {
        ev_eval(q->ev, t, d);
        return;
    }
    for (int i = 0; i < 3; i++)
        traj_eval(i, t, d[i]);
}

static void ref_quad(mms_ref *q, size_t nr, size_t na)
{
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(nr);
    if (!gl)
        exit(SF_EXIT_INTERNAL);
    free(q->x);
    free(q->y);
    free(q->dS);
    q->x = check_alloc(nr * na * sizeof *q->x);
    q->y = check_alloc(nr * na * sizeof *q->y);
    q->dS = check_alloc(nr * na * sizeof *q->dS);
    double dth = 2 * M_PI / (double)na;
    for (size_t j = 0; j < nr; j++) {
        double r, w;
        gsl_integration_glfixed_point(0, q->R, j, &r, &w, gl);
        for (size_t a = 0; a < na; a++) {
            double th = ((double)a + 0.5) * dth;
            q->x[j * na + a] = r * cos(th);
            q->y[j * na + a] = r * sin(th);
            q->dS[j * na + a] = w * r * dth;   /* dS = r dr dtheta */
        }
    }
    gsl_integration_glfixed_table_free(gl);
    q->nr = nr;
    q->na = na;
}

static void ref_quad_free(mms_ref *q)
{
    free(q->x);
    free(q->y);
    free(q->dS);
    q->x = q->y = q->dS = NULL;
}

/* mu_s at belt point (xb, yb): the uniform value, or this check's own
 * bilinear look-up of the grid values (clamped cells; the grid covers the
 * path with margin, so no clamping happens on it) */
static double ref_mu(const mms_ref *q, double xb, double yb)
{
    if (!q->grid)
        return q->mu;
    double sx = (xb - q->gx0) / q->gdx, sy = (yb - q->gy0) / q->gdy;
    double fi = floor(sx), fj = floor(sy);
    fi = fmin(fmax(fi, 0), (double)q->gm - 2);
    fj = fmin(fmax(fj, 0), (double)q->gn - 2);
    size_t i = (size_t)fi, j = (size_t)fj;
    double tx = sx - fi, ty = sy - fj;
    const double *g = q->grid;
    return (1 - tx) * (1 - ty) * g[i + q->gm * j] + tx * (1 - ty) * g[i + 1 + q->gm * j] +
           (1 - tx) * ty * g[i + q->gm * (j + 1)] + tx * ty * g[i + 1 + q->gm * (j + 1)];
}

/* Eq. 8 as printed: F_s = (F_sx, F_sy) and T_s (along the slip) at belt
 * point (xb, yb) of the centre, xd = xdot, yd = ydot, pd = phidot;
 * P = m g / (pi R^2) (Eq. 7), H_k = mu_k_ratio H_s (Eq. 1). */
static void ref_eq8(mms_ref *q, double xb, double yb, double xd, double yd, double pd, double Fs[3])
{
    double P = q->N / (M_PI * q->R * q->R), u = xd - q->v_b;
    double fx = 0, fy = 0, ts = 0;
    q->evals++;
    for (size_t i = 0; i < q->nr * q->na; i++) {
        double x = q->x[i], y = q->y[i];
        double den = sqrt((u - pd * y) * (u - pd * y) + (yd + pd * x) * (yd + pd * x));
        double H = q->muk_ratio * ref_mu(q, xb + x, yb + y), a = P * H * q->dS[i] / den;
        fx += a * (u - pd * y);
        fy += a * (yd + pd * x);
        ts += a * (pd * (x * x + y * y) + x * yd - y * u);
    }
    Fs[0] = fx;
    Fs[1] = fy;
    Fs[2] = ts;
}

/* Q(q*, q*') at t: the wrench on the disc, -(F_sx, F_sy, T_s) */
static void ref_Q(mms_ref *q, double t, double Q[3])
{
    double d[3][3], Fs[3];
    traj_at(q, t, d);
    ref_eq8(q, d[0][0] - q->v_b * t, d[1][0], d[0][1], d[1][1], d[2][1], Fs);
    for (int i = 0; i < 3; i++)
        Q[i] = -Fs[i];
}

/* S = M q*'' + K q* - Q (Eq. 5 with the source on the right) */
static void ref_source(void *ctx, double t, double S[3])
{
    mms_ref *q = ctx;
    double d[3][3], Q[3];
    traj_at(q, t, d);
    ref_Q(q, t, Q);
    S[0] = q->m * d[0][2] + q->k * d[0][0] - Q[0];
    S[1] = q->m * d[1][2] + q->k * d[1][0] - Q[1];
    S[2] = q->J * d[2][2] - Q[2];
}

/* the error at T in metres: positions, R x angle, and speeds / omega_n */
static double state_error(const mms_ref *q, const double *y, const double *ys, double comp[6])
{
    double wn = sqrt(q->k / q->m), e = 0;
    comp[0] = fabs(y[SF_OSC_X] - ys[SF_OSC_X]);
    comp[1] = fabs(y[SF_OSC_Y] - ys[SF_OSC_Y]);
    comp[2] = q->R * fabs(y[SF_OSC_PHI] - ys[SF_OSC_PHI]);
    comp[3] = fabs(y[SF_OSC_VX] - ys[SF_OSC_VX]) / wn;
    comp[4] = fabs(y[SF_OSC_VY] - ys[SF_OSC_VY]) / wn;
    comp[5] = q->R * fabs(y[SF_OSC_W] - ys[SF_OSC_W]) / wn;
    for (int i = 0; i < 6; i++)
        e = isnan(comp[i]) || isnan(e) ? NAN : fmax(e, comp[i]);
    return e;
}

/* the reference's own quadrature resolution (rings x angles) and the
 * doubled one its floor is measured against */
#define REF_NR 16
#define REF_NA 48
#define NFLOOR 61
/* the step at which rk8pd's truncation error (~1e-18 m) is far below
 * round-off: its error there is the floor of the error measure [s] */
#define FLOOR_H 0.025

/* Observed-order band [p - ORDER_BELOW, p + ORDER_ABOVE] (dimensionless):
 * measured on these cases rk4 3.95-4.0 and rkck 5.0-5.3 (the coarse steps
 * still carry the next term), rk8pd 8.6-8.9 over h = 0.25..0.075 s (its
 * local slopes fall towards 8 as h shrinks: 8.9, 8.6, 8.3 measured down to
 * the round-off floor at h = 0.05 s).  A defect in a row of Eq. 5 leaves an
 * O(h^0) error: slope near 0. */
#define ORDER_BELOW 0.3
#define ORDER_ABOVE 1.0
/* the solver's wrench against the reference along the path (relative):
 * both are converged to round-off of sums of ~10^3 terms (measured
 * 3-5e-15); 1e-12 leaves a margin of ~200 and is still far below the 5%
 * a defect in a term makes */
#define WRENCH_TOL 1e-12
static int chk_mms_slip(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (s->dof != SF_DOF_3 || c->spec.sweep.n < 3 || c->spec.sweep2.n < 3 || !(s->T > 0) || !(c->spec.tolerance > 0)) {
        sf_note(r, "mms_slip needs dof = 3, T > 0, tolerance > 0, sweep (steps of rk4 and rkck, >= 3) and sweep2 "
                   "(steps of rk8pd, >= 3).");
        return SF_EINVAL;
    }
    mms_ref q = { .m = s->m, .k = s->k, .R = s->R, .N = s->m * s->g, .J = 0.5 * s->m * s->R * s->R,
                  .v_b = s->v_b, .muk_ratio = s->mu_k_ratio, .mu = s->mu_mean };
    /* the COF: built here (not drawn from the scene's plan) */
    sf_cof *cof = NULL;
    int field = s->cof == SF_COF_FIELD, rc;
    if (field) {
        /* cover the belt strip the disc visits, with a margin of 4 cells */
        double xlo = -s->v_b * s->T - s->R - 0.2 - 4 * GRID_H, xhi = s->R + 0.2 + 4 * GRID_H;
        double ylo = -s->R - 0.2 - 4 * GRID_H;
        size_t gm = (size_t)ceil((xhi - xlo) / GRID_H) + 1, gn = (size_t)ceil(-2 * ylo / GRID_H) + 1;
        double xc = 0.5 * (xlo + xhi);
        double *g = check_alloc(gm * gn * sizeof *g);
        for (size_t j = 0; j < gn; j++)
            for (size_t i = 0; i < gm; i++) {
                double xb = xlo + (double)i * GRID_H - xc, yb = ylo + (double)j * GRID_H;
                g[i + gm * j] = s->mu_mean * (1 + GX * xb + GY * yb + GXY * xb * yb);
            }
        rc = sf_cof_alloc_grid(gm, gn, xlo, ylo, GRID_H, GRID_H, g, &cof);
        free(g);
        if (!rc && sf_cof_grid_view(cof, &q.gm, &q.gn, &q.gx0, &q.gy0, &q.gdx, &q.gdy, &q.grid))
            rc = SF_EFAIL;
    } else {
        rc = sf_cof_alloc_uniform(s->mu_mean, &cof);
    }
    if (rc) {
        sf_note(r, "could not build the manufactured COF");
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    double mu_lo = INFINITY, mu_hi = -INFINITY;
    if (field)
        for (size_t i = 0; i < q.gm * q.gn; i++) {
            mu_lo = sf_min(mu_lo, q.grid[i]);
            mu_hi = sf_max(mu_hi, q.grid[i]);
        }

    /* ---- floors: the reference quadrature against its doubled self, and
     * the solver's wrench against the reference, along q*(t) */
    static const int steppers[3] = { SF_INTEG_RK4, SF_INTEG_RKCK, SF_INTEG_RK8PD };
    static const char *names[3] = { "rk4", "rkck", "rk8pd" };
    static const double order[3] = { 4, 5, 8 };
    sf_scene s0 = *s;
    s0.integrator = SF_INTEG_RK4;
    sf_osc *o0 = NULL;
    char err[256] = "";
    if (sf_osc_alloc(&s0, cof, &o0, err, sizeof err)) {
        sf_note(r, "sf_osc_alloc: %s", err);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    double selfd = 0, solvd = 0, Fmag = 0, Tmag = 0, Fy_max = 0, eps_min = INFINITY;
    double tf[NFLOOR], dsol[NFLOOR], dself[NFLOOR];
    mms_ref q2 = q;
    q2.x = q2.y = q2.dS = NULL;
    ref_quad(&q2, 2 * REF_NR, 2 * REF_NA);
    ref_quad(&q, REF_NR, REF_NA);
    double fs = s->mu_mean * q.N, ts = fs * s->R;   /* force and torque scales [N], [N m] */
    for (int i = 0; i < NFLOOR; i++) {
        double t = s->T * i / (NFLOOR - 1), Q1[3], Q2[3], y[SF_OSC_NSTATE], f[SF_OSC_NSTATE], qs[3];
        ref_Q(&q, t, Q1);
        ref_Q(&q2, t, Q2);
        traj_state(t, y);
        sf_osc_slip_rhs(o0, t, y, f, qs);
        tf[i] = t;
        dself[i] = sf_max(sf_max(fabs(Q1[0] - Q2[0]), fabs(Q1[1] - Q2[1])) / fs, fabs(Q1[2] - Q2[2]) / ts);
        dsol[i] = sf_max(sf_max(fabs(qs[0] - Q2[0]), fabs(qs[1] - Q2[1])) / fs, fabs(qs[2] - Q2[2]) / ts);
        selfd = isnan(selfd) || isnan(dself[i]) ? NAN : fmax(selfd, dself[i]);   /* NaN sticks: it fails the row */
        solvd = isnan(solvd) || isnan(dsol[i]) ? NAN : fmax(solvd, dsol[i]);
        Fmag = sf_max(Fmag, hypot(Q2[0], Q2[1]));
        Tmag = sf_max(Tmag, fabs(Q2[2]));
        Fy_max = sf_max(Fy_max, fabs(Q2[1]) / fs);
        double u = hypot(y[SF_OSC_VX] - s->v_b, y[SF_OSC_VY]);
        double e = u / (fabs(y[SF_OSC_W]) * s->R);
        eps_min = isnan(eps_min) || isnan(e) ? NAN : fmin(eps_min, e);
    }
    ref_quad_free(&q2);
    sf_osc_free(o0);
    /* how a wrench difference d [N] propagates to the state at T: the
     * disturbance d/m integrated twice, (T^2/2) d/m, a bound for the
     * order of magnitude (the springs only rotate it) */
    double prop = 0.5 * s->T * s->T * solvd * fs / s->m;

    /* ---- observed orders */
    double ystar0[SF_OSC_NSTATE], ystarT[SF_OSC_NSTATE];
    traj_state(0, ystar0);
    traj_state(s->T, ystarT);
    sf_plot *p = sf_result_plot(r, "mms_order", "MMS: error at T against the manufactured solution",
                                "fixed step h [s]", "error at T [m] (x, y, R phi, v/omega_n)");
    sf_plot_log(p, 1, 1);
    double floor_meas = NAN, finest_min = INFINITY;
    for (int k = 0; k < 3; k++) {
        const sf_list *hl = steppers[k] == SF_INTEG_RK8PD ? &c->spec.sweep2 : &c->spec.sweep;
        sf_scene sk = *s;
        sk.integrator = steppers[k];
        sf_osc *o = NULL;
        if (sf_osc_alloc(&sk, cof, &o, err, sizeof err)) {
            sf_note(r, "sf_osc_alloc (%s): %s", names[k], err);
            ref_quad_free(&q);
            sf_cof_free(cof);
            return SF_EFAIL;
        }
        sf_osc_set_source(o, ref_source, &q);
        double hs[SF_LIST_MAX], es[SF_LIST_MAX], comp[6], worst[6] = { 0 };
        q.evals = 0;
        for (size_t i = 0; i < hl->n; i++) {
            double y1[SF_OSC_NSTATE];
            hs[i] = hl->v[i];
            if (sf_osc_slip_integrate(o, 0, ystar0, s->T, hs[i], y1)) {
                es[i] = NAN;
            } else {
                es[i] = state_error(&q, y1, ystarT, comp);
            }
            if (i + 1 == hl->n)
                memcpy(worst, comp, sizeof worst);
        }
        if (steppers[k] == SF_INTEG_RK8PD) {   /* the round-off floor: rk8pd's truncation error there is ~1e-18 m */
            double y1[SF_OSC_NSTATE], cf[6];
            floor_meas = sf_osc_slip_integrate(o, 0, ystar0, s->T, FLOOR_H, y1) ? NAN : state_error(&q, y1, ystarT, cf);
        }
        sf_osc_free(o);
        size_t n = hl->n;
        finest_min = isnan(finest_min) || isnan(es[n - 1]) ? NAN : fmin(finest_min, es[n - 1]);
        double slope = check_loglog_slope(hs, es, n), last = log(es[n - 2] / es[n - 1]) / log(hs[n - 2] / hs[n - 1]);
        char qn[160], line[1024];
        snprintf(qn, sizeof qn, "%s: observed order (least squares, h = %g..%g s), not below %g - %g", names[k],
                 hs[0], hs[n - 1], order[k], ORDER_BELOW);
        sf_check_ge(r, qn, slope, order[k] - ORDER_BELOW);
        snprintf(qn, sizeof qn, "%s: observed order, not above %g + %g (pre-asymptotic margin)", names[k], order[k],
                 ORDER_ABOVE);
        sf_check_le(r, qn, slope, order[k] + ORDER_ABOVE);
        snprintf(qn, sizeof qn, "%s: error at T at the finest step h = %g s [m]", names[k], hs[n - 1]);
        sf_check_le(r, qn, es[n - 1], c->spec.tolerance);
        int len = snprintf(line, sizeof line, "%s: errors at T [m] for h [s] =", names[k]);
        for (size_t i = 0; i < n && len > 0 && (size_t)len < sizeof line; i++)
            len += snprintf(line + len, sizeof line - (size_t)len, "%s %g: %.3e", i ? "," : "", hs[i], es[i]);
        sf_note(r, "%s; least-squares order %.3f, last pair %.3f; finest-step error by component (x, y, R phi, "
                   "vx/wn, vy/wn, R w/wn) %.1e %.1e %.1e %.1e %.1e %.1e m; %lu source evaluations.\n\n",
                line, slope, last, worst[0], worst[1], worst[2], worst[3], worst[4], worst[5], q.evals);
        char lab[64];
        snprintf(lab, sizeof lab, "%s (order %.2f)", names[k], slope);
        sf_plot_series(p, lab, SF_STYLE_LINESPOINTS, hl->n, hs, es);
    }
    sf_plot_hline(p, "bound from the wrench difference, (T^2/2) d/m (round-off: incoherent, pessimistic)",
                  fmax(prop, 1e-17));
    sf_plot_hline(p, "measured floor: rk8pd at h = 0.025 s", fmax(floor_meas, 1e-17));
    sf_plot_hline(p, "tolerance on the finest-step error", c->spec.tolerance);
    /* every point of the fits must stand well above the floor, or the
     * fitted slope is the floor's, not the stepper's */
    sf_check_ge(r, "min over steppers of finest-step error / measured floor (rk8pd at h = 0.025 s)",
                finest_min / floor_meas, 10);
    sf_note(r, "Measured floor: rk8pd at h = %g s leaves %.2e m at T (round-off); the bound from the wrench difference "
               "is %.1e m. The smallest finest-step error above is %.2e m, %.0f times the measured floor.\n\n",
            FLOOR_H, floor_meas, prop, finest_min, finest_min / floor_meas);

    /* the floors as rows: the solver's wrench must agree with the
     * reference along the path (an independent check of Eqs. 7-8 in its
     * own right), and the reference must be converged far below that */
    sf_check_le(r, "max |solver wrench - reference| along q*(t) / (mu N, mu N R)", solvd, WRENCH_TOL);
    sf_check_le(r, "reference quadrature: max |(16 x 48) - (32 x 96)| / (mu N, mu N R)", selfd, WRENCH_TOL);
    sf_check_ge(r, "min over the path of |u| / (|w| R) (pole outside the disc)", eps_min, 1.5);
    sf_check_ge(r, "max over the path of |F_y| / (mu N) (the lateral row matters)", Fy_max, 0.05);
    sf_check_ge(r, "max over the path of |T| / (mu N R) (the spin row matters)", Tmag / ts, 0.05);
    sf_note(r, "COF: %s. Wrench along q*(t) (%d times): max |F| = %.3g N, max |T| = %.3g N m; the pole stays "
               "at >= %.2f R from the centre. Reference quadrature %d x %d (Gauss-Legendre in r x trapezoid in "
               "angle) against %d x %d: max difference %.2e (relative to mu N, mu N R). Solver's wrench (%s) "
               "against the reference: max %.2e, i.e. d = %.2e N, which the equations carry to at most about "
               "(T^2/2) d/m = %.1e m at T: the floor under every error above.\n",
            field ? "a bilinear function of the belt coordinates on a grid (exact under bilinear interpolation)"
                  : "uniform (the solver takes the Contensou closed form)",
            NFLOOR, Fmag, Tmag, eps_min, REF_NR, REF_NA, 2 * REF_NR, 2 * REF_NA, selfd,
            field ? "polar cells of sf_contact" : "Contensou closed form", solvd, solvd * fs, prop);
    if (field)
        sf_note(r, "Grid %zu x %zu at %g m, mu_s from %.3f to %.3f.\n", q.gm, q.gn, q.gdx, mu_lo, mu_hi);
    sf_plot *pf = sf_result_plot(r, "mms_floor", "Wrench along q*(t): solver and reference quadrature", "t [s]",
                                 "max relative difference (dimensionless)");
    sf_plot_log(pf, 0, 1);
    for (int i = 0; i < NFLOOR; i++) {
        dsol[i] = fmax(dsol[i], 1e-18);
        dself[i] = fmax(dself[i], 1e-18);
    }
    sf_plot_series(pf, "solver vs reference", SF_STYLE_LINESPOINTS, NFLOOR, tf, dsol);
    sf_plot_series(pf, "reference vs its doubled self", SF_STYLE_LINESPOINTS, NFLOOR, tf, dself);
    ref_quad_free(&q);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* ---- Manufactured stick-slip (mms_events): sf_osc_run itself, events
 * and all, against a trajectory that slips, sticks and slips again.
 *
 * Arc A, slip on [0, t1], s = t1 - t: u = xdot - v_b = -delta cos a (1 + c s),
 * ydot = -delta (sin a (1 + c s) + e s^2), phidot = wa s,
 * delta = eps_lambda omega_n R; lambda^2 >= eps^2 (1 + c s)^2, so lambda
 * falls through eps_lambda exactly once, at t1, transversally (slope
 * -eps c), with the stick wrench k (x1, y1) inside the circle of radius
 * mu m g: the slip-to-stick event is t1, by construction.  Eq. 12 there.
 * Stick on [t1, t2]: x = x1 + v_b (t - t1), y = y1, phi = phi1 (exact
 * kinematics) until k |(x, y)| = mu m g, the equatorial circle:
 * t2 = t1 + (sqrt(rmax^2 - y1^2) - x1) / v_b, rmax = mu m g / k.
 * Eq. 14 at t2: relative velocity delta (cos psi, sin psi) backwards,
 * psi = atan2(y1, x2), spin 0.
 * Arc C, slip on [t2, T], sg = t - t2: u = -delta cos psi (1 + c2 sg),
 * ydot = -delta (sin psi (1 + c2 sg) + e2 sg^2), phidot = wc sg: it starts
 * from Eq. 14's state exactly and lambda grows (no second stick).
 * Positions are the integrals (polynomials).  The source of each arc is
 * M q*'' + K q* - Q(q*, q*') with this file's Eq. 8 quadrature; the run
 * takes arc A's for t < (t1 + t2)/2 and arc C's after (stick ignores it).
 * The disc's pole stays outside it (|w| R < |u|), so the quadrature is
 * spectral, as for mms_slip. */
struct evtraj {
    double v_b, delta, t1, t2, x1, y1, phi1, x2;
    double ca, sa, c, e, wa;     /* arc A */
    double cp, sp, c2, e2, wc;   /* arc C */
};

static void ev_eval(const struct evtraj *v, double t, double d[3][3])
{
    double D = v->delta;
    if (t < 0.5 * (v->t1 + v->t2)) {
        double s = v->t1 - t;
        d[0][0] = v->x1 - v->v_b * s + D * v->ca * (s + 0.5 * v->c * s * s);
        d[0][1] = v->v_b - D * v->ca * (1 + v->c * s);
        d[0][2] = D * v->ca * v->c;
        d[1][0] = v->y1 + D * (v->sa * (s + 0.5 * v->c * s * s) + v->e * s * s * s / 3);
        d[1][1] = -D * (v->sa * (1 + v->c * s) + v->e * s * s);
        d[1][2] = D * (v->sa * v->c + 2 * v->e * s);
        d[2][0] = v->phi1 - 0.5 * v->wa * s * s;
        d[2][1] = v->wa * s;
        d[2][2] = -v->wa;
    } else {
        double g = t - v->t2;
        d[0][0] = v->x2 + v->v_b * g - D * v->cp * (g + 0.5 * v->c2 * g * g);
        d[0][1] = v->v_b - D * v->cp * (1 + v->c2 * g);
        d[0][2] = -D * v->cp * v->c2;
        d[1][0] = v->y1 - D * (v->sp * (g + 0.5 * v->c2 * g * g) + v->e2 * g * g * g / 3);
        d[1][1] = -D * (v->sp * (1 + v->c2 * g) + v->e2 * g * g);
        d[1][2] = -D * (v->sp * v->c2 + 2 * v->e2 * g);
        d[2][0] = v->phi1 + 0.5 * v->wc * g * g;
        d[2][1] = v->wc * g;
        d[2][2] = v->wc;
    }
}

/* the trajectory's shape: A: a = 0.5 rad, c = 1.5 1/s, e = 0.8 1/s^2
 * (in units of delta), wa = 0.15 rad/s^2; C: c2 = 1 1/s, e2 = 0.5 1/s^2,
 * wc = 0.1 rad/s^2; the stick onset at t1 = 1.2 s at (x1, y1, phi1) =
 * (-0.8 m, 0.3 m, 0.1 rad) */
#define EV_T1 1.2
#define EV_X1 (-0.8)
#define EV_Y1 0.3

/* one run of sf_osc_run from q*(0): the state at T (its last history
 * row) and the transitions */
typedef struct {
    double y[SF_OSC_NSTATE], tend, t1, t2;
    size_t ntrans;
    int kinds_ok;
    unsigned long steps, trials;
} ev_run;

static void ev_last_row(void *ctx, const sf_osc_row *row)
{
    ev_run *r = ctx;
    const double y[SF_OSC_NSTATE] = { row->x, row->y, row->phi, row->vx, row->vy, row->w, 0 };
    memcpy(r->y, y, sizeof y);
    r->tend = row->t;
}

static int ev_solve(const sf_scene *s, const sf_cof *cof, mms_ref *q, int integ, double dt, double rtol, ev_run *out,
                    char *err, size_t errlen)
{
    sf_scene sk = *s;
    double d[3][3];
    traj_at(q, 0, d);
    sk.integrator = integ;
    sk.dt = dt;
    sk.rtol = rtol;
    sk.x0 = d[0][0];
    sk.y0 = d[1][0];
    sk.phi0 = d[2][0];
    sk.vx0 = d[0][1];
    sk.vy0 = d[1][1];
    sk.w0 = d[2][1];
    sk.t_skip = 0;
    sf_osc *o = NULL;
    sf_osc_result res;
    int rc = sf_osc_alloc(&sk, cof, &o, err, errlen);
    if (rc)
        return rc;
    sf_osc_set_source(o, ref_source, q);
    rc = sf_osc_run(o, ev_last_row, out, 0, &res, err, errlen);
    sf_osc_free(o);
    if (!rc) {
        out->ntrans = res.ntrans;
        out->kinds_ok = res.ntrans == 2 && res.trans_kind[0] == SF_OSC_STICK_ONSET &&
                        res.trans_kind[1] == SF_OSC_SLIP_ONSET;
        out->t1 = res.ntrans > 0 ? res.trans_t[0] : NAN;
        out->t2 = res.ntrans > 1 ? res.trans_t[1] : NAN;
        out->steps = res.steps;
        out->trials = res.event_trials;
    }
    sf_osc_result_free(&res);
    return rc;
}

/* errors of one run against the manufactured solution: the state at T
 * (state_error's measure, m), the two event times [s] */
static void ev_errors(const mms_ref *q, const ev_run *u, const double *ystarT, double T, double e[3])
{
    double comp[6];
    e[0] = u->tend == T ? state_error(q, u->y, ystarT, comp) : NAN;
    e[1] = fabs(u->t1 - q->ev->t1);
    e[2] = fabs(u->t2 - q->ev->t2);
}

static const char *EV_NAMES[3] = { "state at T [m]", "stick onset t1 [s]", "break t2 [s]" };

/* Observed orders.  rk4 (fixed dt): [4 - ORDER_BELOW, 4 + ORDER_ABOVE] as
 * for mms_slip, for the state and for both event times (an event time's
 * error is the state's error at it over the event function's slope).
 * Adaptive (error against rtol): the error control holds the local error
 * of the propagated solution to about rtol per unit step, so the global
 * error is proportional to rtol: slope 1; measured 0.88-0.99 on this case
 * (rk8pd's event times wobble: 2-4 steps per arc land differently from
 * one rtol to the next), hence EV_RTOL_BAND around 1.  A
 * defect in an event (a jump 5% off, a wrong stick radius) leaves an
 * O(1) error: slope near 0. */
#define EV_RTOL_BAND 0.25
/* the event times must stand this far above the event location's own
 * tolerance (SF_OSC_TIME_TOL) in every fitted point, or the fit measures
 * the root finder, not the stepper */
#define EV_FLOOR_RATIO 10

static int chk_mms_events(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (s->dof != SF_DOF_3 || s->cof != SF_COF_UNIFORM || !s->velocity_jump || s->exact_section ||
        c->spec.sweep.n < 3 || c->spec.sweep2.n < 3 || !(c->spec.tolerance > 0)) {
        sf_note(r, "mms_events needs dof = 3, cof = uniform, velocity_jump = true, exact_section = false, "
                   "tolerance > 0, sweep (rk4 steps, >= 3) and sweep2 (rtols of rkck and rk8pd, >= 3).");
        return SF_EINVAL;
    }
    mms_ref q = { .m = s->m, .k = s->k, .R = s->R, .N = s->m * s->g, .J = 0.5 * s->m * s->R * s->R,
                  .v_b = s->v_b, .muk_ratio = s->mu_k_ratio, .mu = s->mu_mean };
    /* the events in closed form */
    double wn = sqrt(s->k / s->m), rmax = s->mu_mean * q.N / s->k;
    struct evtraj ev = { .v_b = s->v_b, .delta = check_jump_speed(s), .t1 = EV_T1, .x1 = EV_X1,
                         .y1 = EV_Y1, .phi1 = 0.1, .ca = cos(0.5), .sa = sin(0.5), .c = 1.5, .e = 0.8,
                         .wa = 0.15, .c2 = 1, .e2 = 0.5, .wc = 0.1 };
    if (!(hypot(EV_X1, EV_Y1) < rmax)) {
        sf_note(r, "the stick onset (%g, %g) m lies outside the stick circle of radius mu m g / k = %g m", EV_X1,
                EV_Y1, rmax);
        return SF_EINVAL;
    }
    ev.x2 = sqrt(rmax * rmax - EV_Y1 * EV_Y1);
    ev.t2 = EV_T1 + (ev.x2 - EV_X1) / s->v_b;
    ev.cp = ev.x2 / rmax;
    ev.sp = EV_Y1 / rmax;
    if (!(s->T > ev.t2 + 0.5)) {
        sf_note(r, "T must exceed the break t2 = %.6g s by 0.5 s (a slip arc after it)", ev.t2);
        return SF_EINVAL;
    }
    q.ev = &ev;
    sf_cof *cof = NULL;
    char err[256] = "";
    if (sf_cof_alloc_uniform(s->mu_mean, &cof)) {
        sf_note(r, "could not build the uniform COF");
        return SF_EFAIL;
    }
    ref_quad(&q, REF_NR, REF_NA);

    /* ---- the path's own conditions and the wrench floor, along both
     * slip arcs: lambda above eps_lambda inside them (one event each
     * way), the pole outside the disc, solver's wrench = reference */
    sf_scene s0 = *s;
    s0.integrator = SF_INTEG_RK4;
    sf_osc *o0 = NULL;
    if (sf_osc_alloc(&s0, cof, &o0, err, sizeof err)) {
        sf_note(r, "sf_osc_alloc: %s", err);
        ref_quad_free(&q);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    double lam_min = INFINITY, eps_min = INFINITY, solvd = 0, fs = s->mu_mean * q.N, ts = fs * s->R;
    for (int i = 0; i < NFLOOR; i++) {
        /* arc A on [0, t1), arc C on (t2, T]: interior points */
        double t = i < NFLOOR / 2 ? ev.t1 * (i + 0.5) / (NFLOOR / 2)
                                  : ev.t2 + (s->T - ev.t2) * (i - NFLOOR / 2 + 0.5) / (NFLOOR - NFLOOR / 2);
        double d[3][3], y[SF_OSC_NSTATE] = { 0 }, f[SF_OSC_NSTATE], qs[3], Q[3];
        traj_at(&q, t, d);
        for (int j = 0; j < 3; j++) {
            y[j] = d[j][0];
            y[SF_OSC_VX + j] = d[j][1];
        }
        double u = hypot(y[SF_OSC_VX] - s->v_b, y[SF_OSC_VY]);
        double lam = hypot(u / (wn * s->R), y[SF_OSC_W] / wn);
        double gap = (lam - s->eps_lambda) / (s->eps_lambda * fabs(i < NFLOOR / 2 ? ev.t1 - t : t - ev.t2));
        lam_min = isnan(lam_min) || isnan(gap) ? NAN : fmin(lam_min, gap);
        double e = y[SF_OSC_W] == 0 ? INFINITY : u / (fabs(y[SF_OSC_W]) * s->R);
        eps_min = isnan(eps_min) || isnan(e) ? NAN : fmin(eps_min, e);
        ref_Q(&q, t, Q);
        sf_osc_slip_rhs(o0, t, y, f, qs);
        double dd = sf_max(sf_max(fabs(qs[0] - Q[0]), fabs(qs[1] - Q[1])) / fs, fabs(qs[2] - Q[2]) / ts);
        solvd = isnan(solvd) || isnan(dd) ? NAN : fmax(solvd, dd);
    }
    sf_osc_free(o0);

    /* ---- the runs */
    double ystarT[SF_OSC_NSTATE], yc[3][3];
    traj_at(&q, s->T, yc);
    memset(ystarT, 0, sizeof ystarT);
    for (int j = 0; j < 3; j++) {
        ystarT[j] = yc[j][0];
        ystarT[SF_OSC_VX + j] = yc[j][1];
    }
    static const int integ[3] = { SF_INTEG_RK4, SF_INTEG_RKCK, SF_INTEG_RK8PD };
    static const char *names[3] = { "rk4", "rkck", "rk8pd" };
    int bad_events = 0, failed = 0;
    double tmin = INFINITY, finest = 0;
    for (int k = 0; k < 3; k++) {
        const sf_list *L = k == 0 ? &c->spec.sweep : &c->spec.sweep2;
        size_t n = L->n;
        double xs[SF_LIST_MAX], es[3][SF_LIST_MAX];
        unsigned long steps = 0, trials = 0;
        for (size_t i = 0; i < n; i++) {
            ev_run u = { .tend = NAN };
            xs[i] = L->v[i];
            int rc = ev_solve(s, cof, &q, integ[k], k == 0 ? xs[i] : s->dt, k == 0 ? s->rtol : xs[i], &u, err,
                              sizeof err);
            if (rc) {
                sf_note(r, "%s at %g: sf_osc_run failed: %s\n\n", names[k], xs[i], err);
                failed++;
                u.t1 = u.t2 = u.tend = NAN;
            }
            bad_events += !rc && !u.kinds_ok;
            double e3[3];
            ev_errors(&q, &u, ystarT, s->T, e3);
            for (int j = 0; j < 3; j++)
                es[j][i] = e3[j];
            tmin = isnan(tmin) || isnan(e3[1]) || isnan(e3[2]) ? NAN : fmin(tmin, fmin(e3[1], e3[2]));
            steps += u.steps;
            trials += u.trials;
        }
        for (int j = 0; j < 3; j++)
            finest = isnan(finest) || isnan(es[j][n - 1]) ? NAN : fmax(finest, es[j][n - 1]);
        char title[160], qn[200], line[1200];
        snprintf(title, sizeof title, "MMS through events: %s", names[k]);
        sf_plot *p = sf_result_plot(r, k == 0 ? "mms_events_rk4" : k == 1 ? "mms_events_rkck" : "mms_events_rk8pd",
                                    title, k == 0 ? "fixed step dt [s]" : "rtol", "error (state at T [m], times [s])");
        sf_plot_log(p, 1, 1);
        for (int j = 0; j < 3; j++) {
            double slope = check_loglog_slope(xs, es[j], n), want = k == 0 ? 4 : 1;
            double lo = k == 0 ? want - ORDER_BELOW : want - EV_RTOL_BAND;
            double hi = k == 0 ? want + ORDER_ABOVE : want + EV_RTOL_BAND;
            snprintf(qn, sizeof qn, "%s: observed order of the %s error against %s (%g..%g), not below", names[k],
                     EV_NAMES[j], k == 0 ? "dt" : "rtol", xs[0], xs[n - 1]);
            sf_check_ge(r, qn, slope, lo);
            snprintf(qn, sizeof qn, "%s: observed order of the %s error, not above", names[k], EV_NAMES[j]);
            sf_check_le(r, qn, slope, hi);
            int len = snprintf(line, sizeof line, "%s, %s errors for %s =", names[k], EV_NAMES[j],
                               k == 0 ? "dt [s]" : "rtol");
            for (size_t i = 0; i < n && len > 0 && (size_t)len < sizeof line; i++)
                len += snprintf(line + len, sizeof line - (size_t)len, "%s %g: %.3e", i ? "," : "", xs[i], es[j][i]);
            sf_note(r, "%s; order %.3f.\n\n", line, slope);
            char lab[80];
            snprintf(lab, sizeof lab, "%s (order %.2f)", EV_NAMES[j], slope);
            sf_plot_series(p, lab, SF_STYLE_LINESPOINTS, n, xs, es[j]);
        }
        sf_plot_hline(p, "event location tolerance (1e-12 s)", SF_OSC_TIME_TOL);
        sf_note(r, "%s: %lu accepted slip steps, %lu event trial steps over the %zu runs.\n\n", names[k], steps,
                trials, n);
    }
    sf_check_le(r, "runs that failed", failed, 0);
    sf_check_le(r, "runs whose transitions are not exactly (stick onset, break)", bad_events, 0);
    sf_check_le(r, "largest finest-level error (state at T [m], event times [s])", finest, c->spec.tolerance);
    sf_check_ge(r, "min event-time error in the fits / event location tolerance (SF_OSC_TIME_TOL)",
                tmin / SF_OSC_TIME_TOL, EV_FLOOR_RATIO);
    sf_check_ge(r, "min over the slip arcs of (lambda - eps_lambda) / (eps_lambda |t - t_event|) (one crossing)",
                lam_min, 0.5);
    sf_check_ge(r, "min over the slip arcs of |u| / (|w| R) (pole outside the disc)", eps_min, 1.5);
    sf_check_le(r, "max |solver wrench - reference| along the slip arcs / (mu N, mu N R)", solvd, WRENCH_TOL);
    sf_note(r, "Manufactured events (closed form): stick onset t1 = %.6g s at (%g, %g) m; Eq. 12; stick until "
               "k |(x, y)| = mu m g, rmax = %.6g m: break t2 = t1 + (sqrt(rmax^2 - y1^2) - x1)/v_b = %.9g s; "
               "Eq. 14 jump of delta = eps_lambda omega_n R = %.6g m/s at psi = %.4f rad; slip to T = %g s. "
               "Smallest event-time error in the fits: %.2e s.\n",
            ev.t1, EV_X1, EV_Y1, rmax, ev.t2, ev.delta, atan2(EV_Y1, ev.x2), s->T, tmin);
    ref_quad_free(&q);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_mms[] = {
    { "mms_slip", chk_mms_slip, "manufactured solution of the 3-DOF slip equations: observed order of every stepper" },
    { "mms_events", chk_mms_events,
      "manufactured stick-slip solution through sf_osc_run (Eqs. 12, 14, event location): observed orders" },
    { NULL, NULL, NULL }
};
