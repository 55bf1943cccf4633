/* slipfield: the event-driven stick-slip integrators, Eqs. 3-6 and 12-14
 * (oscillator.h): the slip equations, the stick and slip onsets and the
 * run that accumulates the QoIs and the Eq. 15 error. */
#include "oscillator.h"
#include "contact.h"
#include "numplan.h"
#include "surface.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

/* state layout (oscillator.h; the 1-D model uses the same vector with y,
 * phi frozen), short names */
enum {
    X = SF_OSC_X, Y = SF_OSC_Y, P = SF_OSC_PHI, VX = SF_OSC_VX, VY = SF_OSC_VY, W = SF_OSC_W, WK = SF_OSC_WORK,
    NSTATE = SF_OSC_NSTATE
};

struct sf_osc {
    sf_scene s;              /* cells, rtol: as the plan resolved them */
    sf_numplan plan;         /* the numerical settings and why (numplan.h) */
    const sf_cof *cof;
    sf_contact *ct;          /* NULL: spatially constant COF, closed forms */
    int dof3;
    double mu;               /* the constant static COF (constant case) */
    double N, J, wn, delta;  /* m g [N], m R^2/2 [kg m^2], sqrt(k/m) [1/s], eps wn R [m/s] */
    double sc[NSTATE];       /* the error control's scales (sf_osc_scales) */
    gsl_odeiv2_system sys;
    gsl_odeiv2_step *step, *bstep;
    gsl_odeiv2_control *con;
    gsl_odeiv2_evolve *ev;
    gsl_root_fsolver *root;  /* Brent, for event location */
    sf_surface *stick_sf;    /* exact-section stick tests: one limit surface,
                                re-centred per test (made by sf_osc_alloc) */
    unsigned long wrench_evals;
    /* the last wrench evaluated and its arguments' bits (wrench()) */
    struct wrench_memo {
        int valid;
        unsigned long slides;
        double key[6], q[3];
    } memo;
    sf_osc_source_fn src;    /* manufactured source (sf_osc_set_source), or NULL */
    void *src_ctx;
};

static void wrench_eval(sf_osc *o, double t, const double *y, double q[3]);

/* Kinetic friction wrench on the disc at time t, state y.  A step asks
 * for it three times at its end (GSL's dydt_out, the next step's dydt_in,
 * the step's own record): the last evaluation is kept and reused when the
 * arguments it depends on (t, x, y, vx, vy, w) have the same bits and the
 * COF window has not moved since (a slide may change the last bits of a
 * look-up: cof.h), so the same bits at a third of the cost per step.
 * wrench_evals counts the evaluations made. */
static void wrench(sf_osc *o, double t, const double *y, double q[3])
{
    const double key[6] = { t, y[X], y[Y], y[VX], y[VY], y[W] };
    unsigned long slides = sf_cof_slides(o->cof);
    if (o->memo.valid && o->memo.slides == slides && !memcmp(key, o->memo.key, sizeof key)) {
        memcpy(q, o->memo.q, sizeof o->memo.q);
        return;
    }
    wrench_eval(o, t, y, q);
    o->wrench_evals++;
    memcpy(o->memo.key, key, sizeof key);
    memcpy(o->memo.q, q, sizeof o->memo.q);
    o->memo.slides = slides;
    o->memo.valid = 1;
}

static void wrench_eval(sf_osc *o, double t, const double *y, double q[3])
{
    const sf_scene *s = &o->s;
    double u = y[VX] - s->v_b, v = y[VY], w = y[W], muk = s->mu_k_ratio * o->mu;
    q[0] = q[1] = q[2] = 0;
    if (!o->dof3) {   /* Eq. 4 */
        q[0] = u > 0 ? -muk * o->N : (u < 0 ? muk * o->N : 0);
        return;
    }
    if (o->ct) {
        sf_contact_wrench(o->ct, y[X] - s->v_b * t, y[Y], u, v, w, s->mu_k_ratio, q);
        return;
    }
    double U = hypot(u, v), f, tt;
    if (U == 0 && w == 0)
        return;
    sf_contensou(w == 0 ? INFINITY : U / (fabs(w) * s->R), &f, &tt);
    if (U > 0) {
        q[0] = -muk * o->N * f * (u / U);
        q[1] = -muk * o->N * f * (v / U);
    }
    if (w != 0)
        q[2] = -muk * o->N * s->R * tt * (w > 0 ? 1 : -1);
}

void sf_osc_slip_rhs(sf_osc *o, double t, const double *y, double *f, double q[3])
{
    const sf_scene *s = &o->s;
    double qq[3];
    if (!q)
        q = qq;
    wrench(o, t, y, q);
    f[X] = y[VX];
    f[Y] = y[VY];
    f[P] = y[W];
    f[VX] = (-s->k * y[X] + q[0]) / s->m;
    f[VY] = (-s->k * y[Y] + q[1]) / s->m;
    f[W] = q[2] / o->J;
    f[WK] = q[0] * y[VX] + q[1] * y[VY] + q[2] * y[W];
    if (o->src) {   /* a manufactured source (code verification only): added to rows x, y, phi
                       of Eq. 5 after the model's own terms, which stay as they are */
        double S[3];
        o->src(o->src_ctx, t, S);
        f[VX] += S[0] / s->m;
        f[VY] += S[1] / s->m;
        f[W] += S[2] / o->J;
    }
}

void sf_osc_set_source(sf_osc *o, sf_osc_source_fn fn, void *ctx)
{
    o->src = fn;
    o->src_ctx = ctx;
}

int sf_osc_slip_integrate(sf_osc *o, double t0, const double *y0, double t1, double h, double *y1)
{
    if (!(t1 > t0) || !(h > 0) || !isfinite(t1 - t0) || (t1 - t0) / h > 1e8)
        return SF_EINVAL;
    /* equal steps that land on t1 exactly: the error at t1 is then the
     * stepper's alone, not that of a short last step */
    unsigned long n = (unsigned long)ceil((t1 - t0) / h * (1 - 1e-12));
    double hh = (t1 - t0) / (double)n, y[NSTATE], yerr[NSTATE];
    memcpy(y, y0, sizeof y);
    gsl_odeiv2_step_reset(o->bstep);   /* bstep: the event search's, so a run's stepper state is untouched */
    for (unsigned long i = 0; i < n; i++) {
        gsl_odeiv2_step_apply(o->bstep, t0 + (double)i * hh, hh, y, yerr, NULL, NULL, &o->sys);
        for (int j = 0; j < NSTATE; j++)
            if (!isfinite(y[j]))
                return SF_EFAIL;
    }
    memcpy(y1, y, sizeof y);
    return SF_SUCCESS;
}

static int rhs(double t, const double *y, double *f, void *params)
{
    sf_osc_slip_rhs(params, t, y, f, NULL);
    return GSL_SUCCESS;
}

/* The oscillator of scene s on cof with numerical plan np (NULL: made
 * here from s, as sf_plan_make would). */
static int osc_alloc(const sf_scene *s, const sf_numplan *np, const sf_cof *cof, sf_osc **out, char *err,
                     size_t errlen)
{
    *out = NULL;
    int constant = sf_cof_get_kind(cof) != SF_COF_FIELD;
    if (s->dof == SF_DOF_1 && !constant)
        return sf_seterr(err, errlen, SF_EINVAL, "dof = 1 needs a spatially constant COF (cof = uniform or variable)");
    if (s->dof == SF_DOF_1 && (s->y0 != 0 || s->phi0 != 0 || s->vy0 != 0 || s->w0 != 0))
        return sf_seterr(err, errlen, SF_EINVAL, "dof = 1 moves along x only: y0, phi0, vy0 and w0 must be 0");
    /* a constant COF has closed forms (Eq. 4, Contensou): no quadrature,
     * unless the scene asks for the full computation (shortcuts = false) */
    int quadrature = !constant || (s->dof == SF_DOF_3 && !s->shortcuts);
    sf_numplan own;
    if (!np) {
        int rc0 = sf_numplan_make(s, quadrature, &own, err, errlen);
        if (rc0)
            return rc0;
        np = &own;
    } else if (np->quadrature != quadrature)
        return sf_seterr(err, errlen, SF_EINVAL, "the plan %s a quadrature but the COF (%s) %s one",
                         np->quadrature ? "runs" : "skips", constant ? "constant" : "a field",
                         quadrature ? "needs" : "needs no");
    sf_osc *o = sf_calloc(1, sizeof *o);
    if (!o)
        return SF_ENOMEM;
    o->s = *s;
    o->plan = *np;
    o->cof = cof;
    o->dof3 = s->dof == SF_DOF_3;
    o->mu = constant ? sf_cof_eval(cof, 0, 0) : NAN;
    o->N = s->m * s->g;
    o->J = 0.5 * s->m * s->R * s->R;
    o->wn = sqrt(s->k / s->m);
    o->delta = s->eps_lambda * o->wn * s->R;
    o->s.cells = o->plan.cells ? o->plan.cells : s->cells;
    o->s.rtol = o->plan.rtol;
    o->s.layout = o->plan.layout;
    /* cell averages (cellavg.h): the COF's boxes must be the quadrature's cells */
    double box = constant ? 0 : sf_cof_box(cof);
    if (quadrature && (o->plan.cell_average != (box > 0) ||
                       (box > 0 && fabs(box - 2 * s->R / (double)o->s.cells) > 1e-9 * box))) {
        int ca = o->plan.cell_average;
        size_t nc = o->s.cells;
        free(o);
        return sf_seterr(err, errlen, SF_EINVAL,
                         "the COF holds %s (box %g m) but the plan runs cof_model = %s with %zu cells per diameter",
                         box > 0 ? "cell averages" : "point values", box, ca ? "cell_average" : "point", nc);
    }
    if (quadrature) {
        sf_contact_spec spec = { s->R, o->N, (sf_layout)o->s.layout, o->s.cells };
        int rc = sf_contact_alloc(&spec, cof, &o->ct);
        if (rc) {
            free(o);
            return sf_seterr(err, errlen, rc, "cannot set up the contact quadrature");
        }
    }
    /* the stepper: the plan's (numplan.c says why) */
    const gsl_odeiv2_step_type *T = o->plan.integrator == SF_INTEG_RK4     ? gsl_odeiv2_step_rk4
                                    : o->plan.integrator == SF_INTEG_RKCK ? gsl_odeiv2_step_rkck
                                                                          : gsl_odeiv2_step_rk8pd;
    o->sys = (gsl_odeiv2_system){ rhs, NULL, NSTATE, o };
    o->step = SF_FALLIBLE(gsl_odeiv2_step_alloc(T, NSTATE));
    o->bstep = SF_FALLIBLE(gsl_odeiv2_step_alloc(T, NSTATE));
    /* error control in the problem's own scales: a displacement x_s =
     * mu m g / k, its speed x_s omega_n, angles x_s / R, energy mu m g x_s;
     * an absolute tolerance in SI units would be meaningless for a stick
     * distance of a micrometre or of a metre */
    double xs = fmax((s->mu_mean + s->mu_std) * o->N / s->k, 1e-300);
    double sc[NSTATE] = { xs, xs, xs / s->R, xs * o->wn, xs * o->wn, xs * o->wn / s->R,
                          (s->mu_mean + s->mu_std) * o->N * xs };
    memcpy(o->sc, sc, sizeof sc);
    o->con = SF_FALLIBLE(gsl_odeiv2_control_scaled_new(o->s.rtol, o->s.rtol, 1.0, 0.0, sc, NSTATE));
    o->ev = SF_FALLIBLE(gsl_odeiv2_evolve_alloc(NSTATE));
    o->root = SF_FALLIBLE(gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
    int surf_rc = o->ct && s->exact_section ? sf_surface_alloc(o->ct, 0, 0, &o->stick_sf) : SF_SUCCESS;
    if (!o->step || !o->bstep || !o->con || !o->ev || !o->root || surf_rc) {
        sf_osc_free(o);
        return SF_ENOMEM;
    }
    *out = o;
    return SF_SUCCESS;
}

int sf_osc_alloc(const sf_scene *s, const sf_cof *cof, sf_osc **out, char *err, size_t errlen)
{
    return osc_alloc(s, NULL, cof, out, err, errlen);
}

int sf_osc_alloc_plan(const sf_scene *s, const sf_plan *pl, const sf_cof *cof, sf_osc **out, char *err,
                      size_t errlen)
{
    return osc_alloc(s, &pl->num, cof, out, err, errlen);
}

void sf_osc_free(sf_osc *o)
{
    if (!o)
        return;
    sf_contact_free(o->ct);
    if (o->step) gsl_odeiv2_step_free(o->step);
    if (o->bstep) gsl_odeiv2_step_free(o->bstep);
    if (o->con) gsl_odeiv2_control_free(o->con);
    if (o->ev) gsl_odeiv2_evolve_free(o->ev);
    if (o->root) gsl_root_fsolver_free(o->root);
    sf_surface_free(o->stick_sf);
    free(o);
}

void sf_osc_describe(const sf_osc *o, FILE *f)
{
    const sf_scene *s = &o->s;
    fprintf(f, "model: %s\n", o->dof3 ? "3-DOF disc (x, y, phi), Eq. 5" : "1-D oscillator, Eqs. 3-4");
    if (o->ct)
        fprintf(f, "slip wrench: %s quadrature, %zu cells, %s (Eqs. 7-8)\n",
                s->layout == SF_LAYOUT_POLAR ? "polar" : "Cartesian", sf_contact_ncells(o->ct),
                isnan(o->mu) ? (o->plan.cell_average ? "cell-averaged COF interpolated from the effective strip field"
                                                     : "COF interpolated from the strip field")
                             : "constant COF (shortcuts = false)");
    else
        fprintf(f, "slip wrench: closed form (constant COF %.6g: %s), no quadrature\n", o->mu,
                o->dof3 ? "Contensou elliptic integrals" : "Eq. 4");
    fprintf(f, "stick: exact motion with the belt, no quadrature; break test on the %s\n",
            s->exact_section ? "exact T = 0 section (bisection, bracketed by the circle's exit time)"
                             : "equatorial circle (closed-form exit time)");
    if (s->integrator == SF_INTEG_RK4)
        fprintf(f, "stepper: GSL rk4, fixed dt = %g s\n", s->dt);
    else
        fprintf(f, "stepper: GSL %s with error control at rtol = %g%s\n", gsl_odeiv2_step_name(o->step), s->rtol,
                s->integrator == SF_INTEG_ADAPTIVE ? (o->ct ? " (adaptive: the wrench is a quadrature, fewer stages pay)"
                                                            : " (adaptive: the wrench is a closed form, high order pays)")
                                                   : "");
    fprintf(f, "events: stick onsets by Brent (GSL) on single trial steps, to max(%g s, 8 ulp(t)); x extrema on the "
               "step's quintic interpolant, one trial step; velocity jump of Eq. 14 %s\n", SF_OSC_TIME_TOL,
            s->velocity_jump ? "on" : "off");
}

void sf_osc_explain(const sf_osc *o, FILE *f)
{
    sf_osc_describe(o, f);
    sf_numplan_explain(&o->plan, f);   /* the plan's own record of its choices */
}

const sf_numplan *sf_osc_get_plan(const sf_osc *o) { return &o->plan; }

size_t sf_osc_ncells(const sf_osc *o) { return o->ct ? sf_contact_ncells(o->ct) : 0; }

void sf_osc_scales(const sf_osc *o, double sc[SF_OSC_NSTATE])
{
    memcpy(sc, o->sc, sizeof o->sc);
}

static double lambda_of(const sf_osc *o, const double *y)
{
    double r = o->wn * o->s.R;
    return hypot(hypot((y[VX] - o->s.v_b) / r, y[VY] / r), y[W] / o->wn);
}

/* Stick admissibility margin [N] of the stick wrench (k x, k y) at the
 * belt point under the disc at time t (> 0 admissible); NaN when the exact
 * section could not be found (its root finder's failure). */
static double stick_margin(const sf_osc *o, double t, const double *y)
{
    const sf_scene *s = &o->s;
    double F = s->k * hypot(y[X], y[Y]), xb = y[X] - s->v_b * t, m;
    if (!o->ct)
        return o->mu * o->N - F;
    /* the exact section's surface is the oscillator's workspace (re-centred
     * here), not part of its observable state */
    int rc = s->exact_section
                 ? sf_surface_stick_margin(o->stick_sf, o->ct, xb, y[Y], s->k * y[X], s->k * y[Y], &m)
                 : sf_contact_stick_margin(o->ct, xb, y[Y], s->k * y[X], s->k * y[Y], 0, &m);
    return rc ? NAN : m;
}

/* Slip-to-stick switching function: < 0 when lambda < eps and stick is
 * admissible. Mixed units are fine: only its sign is used.  NaN when the
 * stick margin is (sf_osc_run fails with the time). */
double sf_osc_g_stick(const sf_osc *o, double t, const double *y)
{
    double c = lambda_of(o, y) - o->s.eps_lambda;
    if (c >= 0)   /* the sign is already decided: skip the (costly) margin */
        return c;
    double m = -stick_margin(o, t, y) / o->N;
    return isnan(m) ? NAN : fmax(c, m);   /* fmax would drop the NaN, and lambda alone would decide */
}

/* One step of the same stepper from (t0, y0) over h into yo; f0 =
 * f(t0, y0) (the slip right-hand side) is the step's first stage, the
 * same for every trial step from (t0, y0): the steppers take it as given
 * (dydt_in) instead of evaluating it again, with the same bits. */
static void advance(sf_osc *o, double t0, const double *y0, const double *f0, double h, double *yo)
{
    double yerr[NSTATE];
    memcpy(yo, y0, sizeof(double) * NSTATE);
    gsl_odeiv2_step_reset(o->bstep);
    gsl_odeiv2_step_apply(o->bstep, t0, h, yo, yerr, f0, NULL, &o->sys);
}

/* An event search keeps its last EV_KEEP trial steps (it takes about 8):
 * the ends of its final bracket are points it has tried, so looking at
 * them again needs no new trial step (one kept no longer is made again,
 * with the same bits). */
enum { EV_KEEP = 16 };

/* The stick event along a trial step of length h from (t0, y0): < 0 where
 * it holds, > 0 before it (sf_osc_g_stick). */
typedef struct {
    sf_osc *o;
    double t0;
    const double *y0;
    double f0[NSTATE];   /* f(t0, y0) */
    unsigned long *count;
    size_t n;            /* trials made; kept: trial n in slot n mod EV_KEEP */
    double h[EV_KEEP], v[EV_KEEP], y[EV_KEEP][NSTATE];   /* length (0: empty slot), event value, state */
} ev_par;

static double ev_fn(const ev_par *e, double h, const double *ym)
{
    return sf_osc_g_stick(e->o, e->t0 + h, ym);
}

static double ev_state(ev_par *e, double h, double *ym)
{
    if (h == 0) {   /* Brent's left end: the step's start, no trial step */
        memcpy(ym, e->y0, sizeof(double) * NSTATE);
        return ev_fn(e, h, ym);
    }
    for (size_t i = 0; i < EV_KEEP; i++)
        if (e->h[i] == h) {   /* tried before: the same state and value */
            memcpy(ym, e->y[i], sizeof(double) * NSTATE);
            return e->v[i];
        }
    advance(e->o, e->t0, e->y0, e->f0, h, ym);
    (*e->count)++;
    double v = ev_fn(e, h, ym);
    size_t k = e->n++ % EV_KEEP;
    e->h[k] = h;
    e->v[k] = v;
    memcpy(e->y[k], ym, sizeof(double) * NSTATE);
    return v;
}

static double ev_value(double h, void *p)
{
    double ym[NSTATE];
    return ev_state(p, h, ym);
}

/* The event time tolerance at t1: max(1e-12 s, 8 ulp(t1)). */
static double ev_tol(double t1) { return fmax(SF_OSC_TIME_TOL, 8 * DBL_EPSILON * fabs(t1)); }

/* The first stick time in (t0, t1] to ev_tol, given that stick does not
 * hold at t0 and holds at t1: GSL's Brent solver on the event function of
 * single steps of the same stepper from the step's start (superlinear where
 * bisection gains one bit per trial step), returning the bracket end where
 * it holds, and its state in ye. */
static double locate_stick(sf_osc *o, double t0, const double *y0, double t1, double *ye, unsigned long *count)
{
    double lo = 0, hi = t1 - t0, tol = ev_tol(t1);
    ev_par par = { .o = o, .t0 = t0, .y0 = y0, .count = count, .n = 0 };   /* slots empty */
    sf_osc_slip_rhs(o, t0, y0, par.f0, NULL);
    gsl_function F = { ev_value, &par };
    if (hi - lo > tol && gsl_root_fsolver_set(o->root, &F, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < 200; it++) {
            gsl_root_fsolver_iterate(o->root);
            lo = gsl_root_fsolver_x_lower(o->root);
            hi = gsl_root_fsolver_x_upper(o->root);
            if (gsl_root_test_interval(lo, hi, tol, 0) == GSL_SUCCESS)
                break;
        }
        double yl[NSTATE];
        if (!(ev_state(&par, hi, ye) < 0) && ev_state(&par, lo, yl) < 0) {
            hi = lo;   /* the bracket is oriented the other way */
            memcpy(ye, yl, sizeof yl);
        }
        return t0 + hi;
    }
    advance(o, t0, y0, par.f0, hi, ye);
    return t0 + hi;
}

/* The velocity of the step's quintic Hermite interpolant of x (sample()'s,
 * differentiated) at s in [0, 1]: v0 at 0 and v1 at 1 exactly. */
typedef struct {
    double dx, h, v0, a0, a1, v1;   /* dx = (x1 - x0) / h */
} hermite_v;

static double hermite_vel(double s, void *p)
{
    const hermite_v *c = p;
    double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
    return (30 * s2 - 60 * s3 + 30 * s4) * c->dx + (1 - 18 * s2 + 32 * s3 - 15 * s4) * c->v0 +
           (s - 4.5 * s2 + 6 * s3 - 2.5 * s4) * c->h * c->a0 + (1.5 * s2 - 4 * s3 + 2.5 * s4) * c->h * c->a1 +
           (-12 * s2 + 28 * s3 - 15 * s4) * c->v1;
}

/* The root of F in [lo, hi] (a sign change) to tol in the bracket's
 * width: GSL's Brent solver, its last estimate. */
static double brent_root(gsl_root_fsolver *root, gsl_function *F, double lo, double hi, double tol)
{
    double s = 0.5 * (lo + hi);
    (void)gsl_root_fsolver_set(root, F, lo, hi);
    for (int it = 0; it < 200; it++) {
        gsl_root_fsolver_iterate(root);
        s = gsl_root_fsolver_root(root);
        lo = gsl_root_fsolver_x_lower(root);
        hi = gsl_root_fsolver_x_upper(root);
        if (gsl_root_test_interval(lo, hi, tol, 0) == GSL_SUCCESS)
            break;
    }
    return s;
}

/* An extremum of x inside the slip step (t0, t1] (vx changes sign; p0, p1:
 * x, vx, ax at its ends; f0 = f(t0, y0)): the root of the interpolant's
 * velocity (GSL's Brent, to ev_tol), then one trial step of the stepper
 * from (t0, y0) to it for the state ye.  Slip is smooth there (the
 * relative speed is about v_b), so the interpolant's velocity errs by
 * O(h^5) and the root by that over |ax|; x, flat at its extremum, errs by
 * its square, the friction force by its rate times it: far below the
 * stepper's own error, at one trial step where a search on trial steps
 * takes about seven. */
static double locate_extremum(sf_osc *o, double t0, const double *y0, const double *f0, const double p0[3], double t1,
                              const double p1[3], double *ye, unsigned long *count)
{
    double h = t1 - t0;
    hermite_v c = { (p1[0] - p0[0]) / h, h, p0[1], p0[2], p1[2], p1[1] };
    gsl_function F = { hermite_vel, &c };
    double s = brent_root(o->root, &F, 0, 1, ev_tol(t1) / h);   /* a valid bracket: v0 v1 < 0, exactly the ends' values */
    advance(o, t0, y0, f0, s * h, ye);
    (*count)++;
    return t0 + s * h;
}

/* The friction force's x component along a slip step: F = m ax + k x (the
 * x row of Eq. 5), taken on the step's quintic Hermite interpolant of x
 * (sample()'s, in power form: X(s) = sum c_j s^j, s in [0, 1]), a quintic
 * in s whose value and rate are exact at the ends. */
typedef struct {
    double c[6], m_h2, k;   /* m_h2 = m / h^2 */
} force_poly;

static void force_poly_make(force_poly *f, double h, const double p0[3], const double p1[3], double m, double k)
{
    double h2 = h * h, d = p1[0] - p0[0] - h * p0[1] - 0.5 * h2 * p0[2], e = h * (p1[1] - p0[1]) - h2 * p0[2],
           g = h2 * (p1[2] - p0[2]);
    f->c[0] = p0[0];
    f->c[1] = h * p0[1];
    f->c[2] = 0.5 * h2 * p0[2];
    f->c[3] = 10 * d - 4 * e + 0.5 * g;
    f->c[4] = -15 * d + 7 * e - g;
    f->c[5] = 6 * d - 3 * e + 0.5 * g;
    f->m_h2 = m / h2;
    f->k = k;
}

static double force_val(double s, const force_poly *f)
{
    const double *c = f->c;
    double X = c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * (c[4] + s * c[5]))));
    double X2 = 2 * c[2] + s * (6 * c[3] + s * (12 * c[4] + s * 20 * c[5]));
    return f->k * X + f->m_h2 * X2;
}

static double force_rate(double s, void *p)
{
    const force_poly *f = p;
    const double *c = f->c;
    double X1 = c[1] + s * (2 * c[2] + s * (3 * c[3] + s * (4 * c[4] + s * 5 * c[5])));
    double X3 = 6 * c[3] + s * (24 * c[4] + s * 60 * c[5]);
    return f->k * X1 + f->m_h2 * X3;
}

/* The disc's slip speed scale, |U| + |w| R [m/s].  Within FORCE_MIN_SLIP
 * stick thresholds (eps wn R) of stick the slip direction, and with it F,
 * turns within a step, and the steps are short: F's extrema are sought
 * only in steps that slip faster at both ends. */
enum { FORCE_MIN_SLIP = 10 };

static double slip_speed(const sf_osc *o, const double *y)
{
    return hypot(y[VX] - o->s.v_b, y[VY]) + fabs(y[W]) * o->s.R;
}

/* The interior extrema of F in a slip step (0 < s < 1), ascending, at most
 * FORCE_SUB of them: a sign change of the interpolant's rate between
 * FORCE_SUB + 1 equally spaced points, refined by GSL's Brent to tol (in
 * s).  Two extrema within 1/FORCE_SUB of a step are a wiggle far below
 * the step's error, and missed. */
enum { FORCE_SUB = 8 };

static size_t force_extrema(gsl_root_fsolver *root, force_poly *f, double tol, double s_out[FORCE_SUB])
{
    size_t n = 0;
    gsl_function F = { force_rate, f };
    double a = 0, ra = force_rate(0, f);
    for (int j = 1; j <= FORCE_SUB; j++) {
        double b = (double)j / FORCE_SUB, rb = force_rate(b, f);
        if (ra * rb < 0)
            s_out[n++] = brent_root(root, &F, a, b, tol);
        a = b;
        ra = rb;
    }
    return n;
}

/* f(t0, y0), the slip right-hand side at a step's start, evaluated once
 * for the step's trial steps and only when one is made. */
static void step_start_rhs(sf_osc *o, double t0, const double *y0, double *f0, int *have)
{
    if (!*have)
        sf_osc_slip_rhs(o, t0, y0, f0, NULL);
    *have = 1;
}

/* Time to the stick break from (t0, y) with the belt patch fixed. */
double sf_osc_stick_duration(sf_osc *o, double t0, const double *y)
{
    const sf_scene *s = &o->s;
    double xb = y[X] - s->v_b * t0, yb = y[Y];
    double mu_bar = o->ct ? sf_contact_mean_cof(o->ct, xb, yb) : o->mu;
    double rmax = mu_bar * o->N / s->k;
    if (y[Y] * y[Y] >= rmax * rmax)
        return 0;
    double xe = sqrt(rmax * rmax - y[Y] * y[Y]);
    if (y[X] >= xe)
        return 0;
    double tau = (xe - y[X]) / s->v_b;   /* the circle's exit: closed form */
    if (!s->exact_section || !o->ct)
        return tau;
    /* exact section: rho(alpha) <= mu_bar, so the exit lies in [0, tau] */
    sf_surface *sf = o->stick_sf;
    sf_surface_recentre(sf, o->ct, xb, yb);
    double lo = 0, hi = tau;
    for (int it = 0; it < 200 && hi - lo > fmax(SF_OSC_TIME_TOL, 8 * DBL_EPSILON * (t0 + tau)); it++) {
        double mid = 0.5 * (lo + hi), x = y[X] + s->v_b * mid, rho;
        sf_surface_section_radius(sf, atan2(y[Y], x), &rho, NULL);
        if (rho * o->N - s->k * hypot(x, y[Y]) > 0)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

void sf_osc_stick_move(const sf_osc *o, double *y, double dt)
{
    const sf_scene *s = &o->s;
    double x0 = y[X];
    y[WK] += s->k * s->v_b * (x0 * dt + 0.5 * s->v_b * dt * dt);   /* = k (x1^2 - x0^2)/2 */
    y[X] = x0 + s->v_b * dt;
}

double sf_osc_stick_onset(const sf_osc *o, double *y)
{
    const sf_scene *s = &o->s;
    double dE = 0.5 * s->m * (s->v_b * s->v_b - y[VX] * y[VX] - y[VY] * y[VY]) - 0.5 * o->J * y[W] * y[W];
    y[VX] = s->v_b;   /* Eq. 12: the disc moves with the belt, */
    y[VY] = 0;        /* no lateral motion */
    y[W] = 0;         /* and no spin in stick */
    return dE;
}

double sf_osc_slip_onset(const sf_osc *o, double *y)
{
    const sf_scene *s = &o->s;
    if (!s->velocity_jump)
        return 0;
    double psi = atan2(s->k * y[Y], s->k * y[X]);   /* the direction of the stick wrench */
    y[VX] = s->v_b - o->delta * cos(psi);
    y[VY] = o->dof3 ? -o->delta * sin(psi) : 0;
    y[W] = 0;
    return 0.5 * s->m * (y[VX] * y[VX] + y[VY] * y[VY] - s->v_b * s->v_b);
}

/* ---- online QoIs */

typedef struct {
    sf_osc_result *r;
    double t_skip;
    /* the open stick cycle (since the last stick onset) */
    int open;
    double t0, xmin, xmax, Fmin, Fmax, stick;
    size_t cap_t, cap_c, cap_b, cap_o;
    double stick_total, cycle_total;
    /* the open oscillation (since the last maximum of x at or after t_skip) */
    int oopen;
    double ot0, oxmin, oxmax, oFmin, oFmax, ostick;
} acc;

/* Make room for element n in each of na parallel arrays of capacity *cap
 * (element size sz). */
static int grow(size_t n, size_t *cap, size_t sz, void **arrs[], size_t na)
{
    if (n < *cap)
        return 0;
    size_t c = *cap ? 2 * *cap : 64;
    for (size_t i = 0; i < na; i++) {
        void *q = sf_realloc(*arrs[i], c * sz);
        if (!q)
            return -1;
        *arrs[i] = q;
    }
    *cap = c;
    return 0;
}

static void note(acc *a, double x, double F)
{
    if (a->open) {
        a->xmin = fmin(a->xmin, x);
        a->xmax = fmax(a->xmax, x);
        a->Fmin = fmin(a->Fmin, F);
        a->Fmax = fmax(a->Fmax, F);
    }
    if (a->oopen) {
        a->oxmin = fmin(a->oxmin, x);
        a->oxmax = fmax(a->oxmax, x);
        a->oFmin = fmin(a->oFmin, F);
        a->oFmax = fmax(a->oFmax, F);
    }
}

/* Would F widen the open cycle's or the open oscillation's force range
 * by more than margin? */
static int widens(const acc *a, double F, double margin)
{
    return (a->open && (F < a->Fmin - margin || F > a->Fmax + margin)) ||
           (a->oopen && (F < a->oFmin - margin || F > a->oFmax + margin));
}

/* A stick span [t0, t1]: its part inside the window [t_skip, T] (the
 * paper's T_sk) and the open cycle's and oscillation's stick time. */
static void stick_span(acc *a, double t0, double t1)
{
    if (a->open)
        a->stick += t1 - t0;
    if (a->oopen)
        a->ostick += t1 - t0;
    a->r->stick_time += fmax(0, t1 - fmax(t0, a->t_skip));
}

/* A maximum of x at t (after note() saw it): it closes the open
 * oscillation, stick or not, and opens the next one. */
static int x_maximum(acc *a, double t, double x, double F)
{
    if (t < a->t_skip)
        return SF_SUCCESS;
    sf_osc_result *r = a->r;
    if (a->oopen) {   /* close the open oscillation */
        void **os[] = { (void **)&r->osc_t, (void **)&r->osc_pv_x, (void **)&r->osc_pv_F, (void **)&r->osc_stick };
        if (grow(r->nosc, &a->cap_o, sizeof(double), os, 4))
            return SF_ENOMEM;
        r->osc_t[r->nosc] = a->ot0;
        r->osc_pv_x[r->nosc] = a->oxmax - a->oxmin;
        r->osc_pv_F[r->nosc] = a->oFmax - a->oFmin;
        r->osc_stick[r->nosc] = a->ostick;
        r->nosc++;
    }
    a->oopen = 1;
    a->ot0 = t;
    a->oxmin = a->oxmax = x;
    a->oFmin = a->oFmax = F;
    a->ostick = 0;
    return SF_SUCCESS;
}

static int transition(acc *a, int kind, double t, double x, double kx)
{
    sf_osc_result *r = a->r;
    size_t ck = a->cap_t;
    void **tr[] = { (void **)&r->trans_t, (void **)&r->trans_x };
    void **kd[] = { (void **)&r->trans_kind };
    if (grow(r->ntrans, &a->cap_t, sizeof(double), tr, 2) || grow(r->ntrans, &ck, sizeof(int), kd, 1))
        return SF_ENOMEM;
    r->trans_t[r->ntrans] = t;
    r->trans_x[r->ntrans] = x;
    r->trans_kind[r->ntrans] = kind;
    r->ntrans++;
    if (kind != SF_OSC_STICK_ONSET)
        return SF_SUCCESS;
    if (t >= a->t_skip) {
        void **b[] = { (void **)&r->bif };
        if (grow(r->nbif, &a->cap_b, sizeof(double), b, 1))
            return SF_ENOMEM;
        r->bif[r->nbif++] = x;
    }
    if (a->open) {
        void **cy[] = { (void **)&r->cycle_pv_x, (void **)&r->cycle_pv_F, (void **)&r->cycle_stick,
                        (void **)&r->cycle_period };
        if (grow(r->ncycles, &a->cap_c, sizeof(double), cy, 4))
            return SF_ENOMEM;
        r->cycle_pv_x[r->ncycles] = a->xmax - a->xmin;
        r->cycle_pv_F[r->ncycles] = a->Fmax - a->Fmin;
        r->cycle_stick[r->ncycles] = a->stick;
        r->cycle_period[r->ncycles] = t - a->t0;
        a->stick_total += a->stick;
        a->cycle_total += t - a->t0;
        r->ncycles++;
    }
    a->open = t >= a->t_skip;
    a->t0 = t;
    a->xmin = a->xmax = x;
    a->Fmin = a->Fmax = kx;
    a->stick = 0;
    return SF_SUCCESS;
}

/* Uniform x samples in (t0, t1]: quintic Hermite from position, velocity
 * and acceleration at the step's ends (error O(h^6): ~1e-7 m for a 0.3 s
 * rk8pd step on the Table 1 arcs, where a cubic would give 4e-5 m); exact
 * in stick (a = 0, v = v_b). */
static void sample(sf_osc_result *r, size_t *next, double t0, const double p0[3], double t1, const double p1[3])
{
    double h = t1 - t0;
    while (*next < r->nsamples && (double)*next * r->sample_dt <= t1) {
        double tk = (double)*next * r->sample_dt, s = h > 0 ? (tk - t0) / h : 1;
        double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
        r->x_samples[*next] = (1 - 10 * s3 + 15 * s4 - 6 * s5) * p0[0] + (s - 6 * s3 + 8 * s4 - 3 * s5) * h * p0[1] +
                              (0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5) * h * h * p0[2] +
                              (0.5 * s3 - s4 + 0.5 * s5) * h * h * p1[2] + (-4 * s3 + 7 * s4 - 3 * s5) * h * p1[1] +
                              (10 * s3 - 15 * s4 + 6 * s5) * p1[0];
        (*next)++;
    }
}

static double energy(const sf_osc *o, const double *y)
{
    const sf_scene *s = &o->s;
    return 0.5 * s->m * (y[VX] * y[VX] + y[VY] * y[VY]) + 0.5 * o->J * y[W] * y[W] +
           0.5 * s->k * (y[X] * y[X] + y[Y] * y[Y]);
}

static void emit(sf_osc *o, sf_osc_row_fn row, void *ctx, double t, const double *y, const double *q, int stick)
{
    if (!row)
        return;
    sf_osc_row r = { t, y[X], y[Y], y[P], y[VX], y[VY], y[W], q[0], q[1], q[2], stick };
    (void)o;
    row(ctx, &r);
}

/* Extremes of the accepted path, and whether its contact patch stayed
 * on the COF strip (checked at step ends and x extrema). */
static void track(const sf_osc *o, double t, sf_osc_result *r, const double *y)
{
    r->x_min = fmin(r->x_min, y[X]);
    r->x_max = fmax(r->x_max, y[X]);
    r->y_absmax = fmax(r->y_absmax, fabs(y[Y]));
    r->off_strip += !sf_cof_covers(o->cof, y[X] - o->s.v_b * t, y[Y], o->s.R);
}

/* A tiled COF (sf_cof_follow) holds a window of the belt: before every
 * step (stick or slip) it is made to hold the disc's footprint plus a
 * margin M on each side, and the step is capped so that no stage of it
 * (accepted or rejected) can move the disc by M/2 or more on the belt.
 * Why the cap suffices: on the belt the centre moves at the relative
 * velocity (vx - v_b, vy), of size u at the step's start; its
 * acceleration is (spring + friction)/m, bounded while the disc stays
 * within M of its start by a = (k (|r| + 2 M) + mu_max m g) / m, mu_max
 * the largest COF the window holds (the friction force is at most
 * mu_max m g).  A Runge-Kutta stage's position is x0 + h sum_j a_ij v_j,
 * its stage velocities v_j = v0 + h sum_l a_jl acc_l, so with sum_j a_ij
 * = c_i <= 1 its displacement is at most h u + C a h^2, C = max_i sum_j
 * |a_ij| sum_l |a_jl|: 4.39 for Cash-Karp (row 5: 2.5 x 0.2 + 70/27 x 0.3
 * + 35/27 x 2.4), 0.5 for RK4; for rk8pd (13 stages) we take 45, ten
 * times Cash-Karp's, without a derivation.  h u + C a h^2 <= M/2 gives
 * the cap; a step is also capped at M / v_b.  Stick phases move the disc
 * with the belt (its belt point is fixed); events are located inside the
 * step.  Checked, not trusted: sf_cof_outside() counts every look-up off
 * the window, rejected stages included (cases/dynamics/tiles-small-l). */
static int follow(sf_osc *o, double t, const double *y, double *hcap)
{
    double M = sf_cof_window_margin(o->cof);
    *hcap = INFINITY;
    if (!(M > 0))
        return SF_SUCCESS;
    const sf_scene *s = &o->s;
    double xb = y[X] - s->v_b * t;
    int rc = sf_cof_follow(o->cof, xb - s->R - M, xb + s->R + M);
    if (rc)
        return rc;
    double C = o->step->type == gsl_odeiv2_step_rk8pd ? 45 : 4.5;
    double u = hypot(y[VX] - s->v_b, y[VY]);
    double a = (s->k * (hypot(y[X], y[Y]) + 2 * M) + sf_cof_max(o->cof) * o->N) / s->m;
    *hcap = fmin((sqrt(u * u + 2 * C * a * M) - u) / (2 * C * a), M / s->v_b);   /* h u + C a h^2 = M/2 */
    return SF_SUCCESS;
}

/* One slip step of the stepper from (*t, y), capped at hcap [s] (the COF
 * window's reach) and at T: fixed dt for RK4, else the error-controlled
 * step (*h: the next trial step). */
static int slip_step(sf_osc *o, double *t, double *y, double hcap, double *h, char *err, size_t errlen)
{
    const sf_scene *s = &o->s;
    if (s->integrator == SF_INTEG_RK4) {
        double hh = fmin(s->dt, s->T - *t), yerr[NSTATE];
        int last = s->T - *t <= s->dt;
        if (hcap < hh) {
            hh = hcap;
            last = 0;
        }
        gsl_odeiv2_step_apply(o->step, *t, hh, y, yerr, NULL, NULL, &o->sys);
        *t = last ? s->T : *t + hh;
        return SF_SUCCESS;
    }
    int st = gsl_odeiv2_evolve_apply(o->ev, o->con, o->step, &o->sys, t, fmin(s->T, *t + hcap), h, y);
    if (st != GSL_SUCCESS)
        return sf_seterr(err, errlen, SF_EFAIL, "the adaptive stepper failed (step size underflow)");
    return SF_SUCCESS;
}

/* The QoIs: means over the oscillations and over the complete cycles
 * (NAN when there is none), T_sk over the window (NAN when it is empty),
 * and the scene's choice of them. */
static double mean_of(const double *v, size_t n)
{
    double sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += v[i];
    return n ? sum / (double)n : NAN;
}

static void qoi_means(sf_osc_result *res, const acc *a, const sf_scene *s)
{
    res->osc_pv_x_mean = mean_of(res->osc_pv_x, res->nosc);
    res->osc_pv_F_mean = mean_of(res->osc_pv_F, res->nosc);
    res->win_stick_fraction = s->T > s->t_skip ? res->stick_time / (s->T - s->t_skip) : NAN;
    res->cyc_pv_x = mean_of(res->cycle_pv_x, res->ncycles);
    res->cyc_pv_F = mean_of(res->cycle_pv_F, res->ncycles);
    res->cyc_stick_fraction = res->ncycles ? a->stick_total / a->cycle_total : NAN;
    res->period = res->ncycles ? a->cycle_total / (double)res->ncycles : NAN;
    int paper = s->qoi_def == SF_QOI_PAPER;
    res->pv_x = paper ? res->osc_pv_x_mean : res->cyc_pv_x;
    res->pv_F = paper ? res->osc_pv_F_mean : res->cyc_pv_F;
    res->stick_fraction = paper ? res->win_stick_fraction : res->cyc_stick_fraction;
}

/* One run's state, shared by sf_osc_run's phases: the start, a stick
 * phase, a slip step, the end. */
typedef struct {
    sf_osc *o;
    sf_osc_row_fn row;
    void *ctx;
    sf_osc_result *res;
    acc a;
    size_t next;             /* the next x sample */
    double t, y[NSTATE], q[3], h, jumps;
    double hcap;             /* the COF window's step cap [s] */
    double pa[3];            /* x, vx, ax at the last step end */
    double E0;               /* energy at the start */
    int stick, armed;
    char *err;
    size_t errlen;
} run_state;

/* The result's arrays, the initial state (stick from the start inside the
 * stick set), the first sample and row. */
static int run_start(run_state *r, double sample_dt)
{
    sf_osc *o = r->o;
    sf_osc_result *res = r->res;
    const sf_scene *s = &o->s;
    memset(res, 0, sizeof *res);
    res->held_cell = -1;
    res->held_slip = NAN;
    res->x_min = INFINITY;
    res->x_max = -INFINITY;
    r->a = (acc){ .r = res, .t_skip = s->t_skip };
    r->next = 0;
    if (sample_dt > 0) {
        res->sample_dt = sample_dt;
        res->nsamples = (size_t)floor(s->T / sample_dt) + 1;
        res->x_samples = sf_calloc(res->nsamples, sizeof *res->x_samples);
        if (!res->x_samples)
            return SF_ENOMEM;
    }
    o->wrench_evals = 0;
    o->memo.valid = 0;
    /* the scene's initial state (x0 ... w0; default rest at the origin;
     * the 1-D model keeps y, phi, vy, w at 0: sf_osc_alloc refuses others) */
    double *y = r->y;
    const double y_init[NSTATE] = { s->x0, s->y0, s->phi0, s->vx0, s->vy0, s->w0, 0 };
    memcpy(y, y_init, sizeof y_init);
    r->t = 0;
    r->h = s->dt;
    r->jumps = 0;
    r->E0 = energy(o, y);   /* 0 from rest at the origin */
    double g0 = sf_osc_g_stick(o, 0, y);
    /* armed from the start unless the run starts on the threshold */
    r->stick = g0 < 0;
    r->armed = g0 > 0;
    int rc;
    gsl_odeiv2_evolve_reset(o->ev);
    if (r->stick) {   /* relative speed below eps_lambda omega_n R inside the stick set: stick from the start (Eq. 12) */
        /* sf_osc_stick_onset's jump, its energy in the product order of
         * the first release (from rest: bits of jump_energy kept) */
        r->jumps += 0.5 * s->m * s->v_b * s->v_b -
                    (0.5 * s->m * (y[VX] * y[VX] + y[VY] * y[VY]) + 0.5 * o->J * y[W] * y[W]);
        y[VX] = s->v_b;
        y[VY] = y[W] = 0;
        if ((rc = transition(&r->a, SF_OSC_STICK_ONSET, 0, y[X], s->k * y[X])))
            return rc;
    }
    if ((rc = follow(o, 0, y, &r->hcap)))
        return sf_seterr(r->err, r->errlen, rc, "the COF window cannot follow the disc");
    wrench(o, 0, y, r->q);
    double pa[3] = { y[X], y[VX], r->stick ? 0 : (-s->k * y[X] + r->q[0]) / s->m };
    memcpy(r->pa, pa, sizeof pa);
    sample(res, &r->next, 0, r->pa, 0, r->pa);
    emit(o, r->row, r->ctx, 0, y, r->stick ? (double[3]){ s->k * y[X], s->k * y[Y], 0 } : r->q, r->stick);
    return SF_SUCCESS;
}

/* A stick phase to its break (Eq. 14) or to T, then the release. */
static int run_stick(run_state *r)
{
    sf_osc *o = r->o;
    const sf_scene *s = &o->s;
    double *y = r->y, t = r->t;
    double tau = sf_osc_stick_duration(o, t, y), t1 = fmin(t + tau, s->T), x0 = y[X];
    sf_osc_stick_move(o, y, t1 - t);
    double x1 = y[X];
    double kq0[3] = { s->k * x0, s->k * y[Y], 0 }, kq1[3] = { s->k * x1, s->k * y[Y], 0 };
    note(&r->a, x0, kq0[0]);
    note(&r->a, x1, kq1[0]);
    stick_span(&r->a, t, t1);
    double p0[3] = { x0, s->v_b, 0 }, p1[3] = { x1, s->v_b, 0 };
    sample(r->res, &r->next, t, p0, t1, p1);
    r->t = t = t1;
    track(o, t, r->res, y);
    emit(o, r->row, r->ctx, t, y, kq1, 1);
    if (t >= s->T)
        return SF_SUCCESS;
    /* break: Eq. 14 */
    int rc = transition(&r->a, SF_OSC_SLIP_ONSET, t, y[X], kq1[0]);
    if (rc)
        return rc;
    r->jumps += sf_osc_slip_onset(o, y);
    r->stick = 0;
    r->armed = 0;
    r->h = s->dt;   /* each slip phase starts from dt */
    r->res->rejected += o->ev->failed_steps;   /* the reset clears the evolve's count */
    gsl_odeiv2_evolve_reset(o->ev);
    gsl_odeiv2_step_reset(o->step);
    wrench(o, t, y, r->q);
    r->pa[0] = y[X];
    r->pa[1] = y[VX];
    r->pa[2] = (-s->k * y[X] + r->q[0]) / s->m;
    note(&r->a, y[X], r->q[0]);
    emit(o, r->row, r->ctx, t, y, r->q, 0);
    return SF_SUCCESS;
}

/* The quadrature cell that slips slowest at y: its index (-1 without a
 * quadrature) and its slip speed over the disc's, |v_p| / (|U| + |w| R),
 * in *ratio (NaN without slip). */
static long slowest_cell(const sf_osc *o, const double *y, double *ratio)
{
    double u = y[VX] - o->s.v_b, v = y[VY], w = y[W], scale = slip_speed(o, y);
    *ratio = NAN;
    if (!o->ct)
        return -1;
    const double *rx, *ry, *wt;
    sf_contact_cells(o->ct, &rx, &ry, &wt);
    long best = -1;
    double vmin = INFINITY;
    for (size_t i = 0; i < sf_contact_ncells(o->ct); i++) {
        double vp = hypot(u - w * ry[i], v + w * rx[i]);
        if (vp < vmin) {
            vmin = vp;
            best = (long)i;
        }
    }
    *ratio = vmin / scale;
    return best;
}

/* The step budget (max_steps) is spent at t: record the slowest cell and
 * say why the steps were short when a cell holds the centre of rotation. */
static int budget_spent(const sf_osc *o, double t, double h, const double *y, sf_osc_result *res, char *err,
                        size_t errlen)
{
    res->held_cell = slowest_cell(o, y, &res->held_slip);
    char why[200] = "";
    if (res->held_cell >= 0) {
        const double *rx, *ry, *wt;
        sf_contact_cells(o->ct, &rx, &ry, &wt);
        size_t i = (size_t)res->held_cell;
        snprintf(why, sizeof why, "; cell %ld at (%.4g, %.4g) m, COF %.3g, slips at %.2g of the disc's speed%s",
                 res->held_cell, rx[i], ry[i], sf_cof_eval(o->cof, y[X] - o->s.v_b * t + rx[i], y[Y] + ry[i]), res->held_slip,
                 res->held_slip < SF_OSC_HELD_SLIP ? ": it holds the centre of rotation (a sliding mode)" : "");
    }
    return sf_seterr(err, errlen, SF_EMAXITER, "step budget (max_steps = %zu) spent at t = %.9g s, last step %.3g s%s",
                     o->s.max_steps, t, h, why);
}

/* One slip step: the stepper, the stick event inside it (Eq. 12) and an
 * x extremum inside it. */
static int run_slip(run_state *r)
{
    sf_osc *o = r->o;
    sf_osc_result *res = r->res;
    const sf_scene *s = &o->s;
    double *y = r->y, *q = r->q;
    double t0 = r->t, y0[NSTATE];
    memcpy(y0, y, sizeof y0);
    int rc = slip_step(o, &r->t, y, r->hcap, &r->h, r->err, r->errlen);
    if (rc)
        return rc;
    res->steps++;
    for (int i = 0; i < NSTATE; i++)
        if (!isfinite(y[i])) {
            rc = sf_seterr(r->err, r->errlen, SF_EFAIL, "non-finite state at t = %.9g s (slip)", r->t);
        }
    if (rc)
        return rc;
    if (res->steps > s->max_steps)
        return budget_spent(o, r->t, r->t - t0, y, res, r->err, r->errlen);
    double g1 = sf_osc_g_stick(o, r->t, y);
    if (isnan(g1))
        return sf_seterr(r->err, r->errlen, SF_EFAIL, "the exact T = 0 section of the limit surface was not found "
                                                      "at t = %.9g s (the stick test)", r->t);
    int to_stick = r->armed && g1 < 0;
    double ye[NSTATE], te = r->t;
    if (to_stick) {
        te = locate_stick(o, t0, y0, r->t, ye, &res->event_trials);
        r->t = te;
        memcpy(y, ye, sizeof ye);
    }
    double t = r->t;
    wrench(o, t, y, q);   /* the step's end (GSL's last evaluation unless the step was cut at stick) */
    double p1[3] = { y[X], y[VX], (-s->k * y[X] + q[0]) / s->m }, h = t - t0;
    /* Interior extrema of the friction force: PV_F is the continuous
     * force's peak-to-valley (Sec. 3.1), and a step's ends alone miss an
     * extremum inside it by about |F''| h^2 / 8, an error that falls only
     * as rtol^0.4.  Located on the interpolant (O(h^4)), F is taken from a
     * trial step to it, where it can widen an open range. */
    force_poly fp;
    double sf[FORCE_SUB], f0[NSTATE], margin = 0;
    size_t nf = 0, kf = 0;
    int have_f0 = 0;
    struct wrench_memo end = o->memo;   /* the end's wrench, asked for again by the next step */
    if (t >= r->a.t_skip && h > 0 && slip_speed(o, y0) > FORCE_MIN_SLIP * o->delta &&
        slip_speed(o, y) > FORCE_MIN_SLIP * o->delta) {
        force_poly_make(&fp, h, r->pa, p1, s->m, s->k);
        nf = force_extrema(o->root, &fp, ev_tol(t) / h, sf);
        /* a widening within the stepper's tolerance is not worth a trial
         * step, nor one within the interpolant's round-off (m x'' from
         * differences of x over h^2: large in the short steps of a sliding
         * mode) */
        margin = fmax(s->rtol * fmax(fabs(q[0]), fabs(s->m * r->pa[2] + s->k * r->pa[0])),
                      64 * DBL_EPSILON * s->m * (fabs(r->pa[0]) + fabs(p1[0]) + s->R) / (h * h));
    }
    double tx = INFINITY, yx[NSTATE], qx[3];
    if (y0[VX] * y[VX] < 0) {   /* an extremum of x inside the step */
        step_start_rhs(o, t0, y0, f0, &have_f0);
        tx = locate_extremum(o, t0, y0, f0, r->pa, t, p1, yx, &res->event_trials);
        wrench(o, tx, yx, qx);   /* at the extremum's own time: the belt has moved on by t */
    }
    for (int before_x = 1; before_x >= 0; before_x--) {
        for (; kf < nf && (!before_x || t0 + sf[kf] * h < tx); kf++) {
            if (!widens(&r->a, force_val(sf[kf], &fp), margin))
                continue;
            step_start_rhs(o, t0, y0, f0, &have_f0);
            double yf[NSTATE], qf[3];
            advance(o, t0, y0, f0, sf[kf] * h, yf);
            res->event_trials++;
            wrench(o, t0 + sf[kf] * h, yf, qf);
            note(&r->a, yf[X], qf[0]);
        }
        if (before_x && isfinite(tx)) {
            note(&r->a, yx[X], qx[0]);
            track(o, tx, res, yx);
            if (y0[VX] > 0 && (rc = x_maximum(&r->a, tx, yx[X], qx[0]))) {
                o->memo = end;
                return rc;
            }
        }
    }
    o->memo = end;
    sample(res, &r->next, t0, r->pa, t, p1);
    memcpy(r->pa, p1, sizeof r->pa);
    note(&r->a, y[X], q[0]);
    track(o, t, res, y);
    emit(o, r->row, r->ctx, t, y, q, 0);
    if (!to_stick) {
        if (g1 > 0)
            r->armed = 1;
        return SF_SUCCESS;
    }
    /* slip -> stick: Eq. 12 */
    r->jumps += sf_osc_stick_onset(o, y);
    r->stick = 1;
    if ((rc = transition(&r->a, SF_OSC_STICK_ONSET, t, y[X], s->k * y[X])))
        return rc;
    emit(o, r->row, r->ctx, t, y, (double[3]){ s->k * y[X], s->k * y[Y], 0 }, 1);
    return SF_SUCCESS;
}

/* Energy balance, step counts, the strip check and the QoIs. */
static int run_end(run_state *r, int rc)
{
    sf_osc *o = r->o;
    sf_osc_result *res = r->res;
    const double *y = r->y;
    res->friction_work = y[WK];
    res->jump_energy = r->jumps;
    res->energy_change = energy(o, y) - r->E0;
    res->energy_residual = res->energy_change - res->friction_work - res->jump_energy;
    res->rejected += o->ev->failed_steps;   /* the last slip phase's (earlier ones: run_stick) */
    res->wrench_evals = o->wrench_evals;
    if (!rc && res->off_strip)
        rc = sf_seterr(r->err, r->errlen, SF_EFAIL, "the disc left the belt strip of the COF field: raise strip_halfwidth");
    qoi_means(res, &r->a, &o->s);
    return rc;
}

int sf_osc_run(sf_osc *o, sf_osc_row_fn row, void *ctx, double sample_dt, sf_osc_result *res,
               char *err, size_t errlen)
{
    run_state r = { .o = o, .row = row, .ctx = ctx, .res = res, .err = err, .errlen = errlen };
    int rc = run_start(&r, sample_dt);
    if (rc)
        return rc;
    while (r.t < o->s.T && rc == SF_SUCCESS) {
        if ((rc = follow(o, r.t, r.y, &r.hcap))) {
            rc = sf_seterr(err, errlen, rc, "the COF window cannot follow the disc");
            break;
        }
        rc = r.stick ? run_stick(&r) : run_slip(&r);
    }
    return run_end(&r, rc);
}

void sf_osc_result_free(sf_osc_result *r)
{
    if (!r)
        return;
    free(r->trans_t);
    free(r->trans_x);
    free(r->trans_kind);
    free(r->cycle_pv_x);
    free(r->cycle_pv_F);
    free(r->cycle_stick);
    free(r->cycle_period);
    free(r->osc_t);
    free(r->osc_pv_x);
    free(r->osc_pv_F);
    free(r->osc_stick);
    free(r->bif);
    free(r->x_samples);
    memset(r, 0, sizeof *r);
}

double sf_osc_error_eq15(const sf_osc_result *a, const sf_osc_result *ref)
{
    size_t n = a->nsamples < ref->nsamples ? a->nsamples : ref->nsamples;
    if (!n || a->sample_dt != ref->sample_dt)
        return NAN;
    double e = 0;
    for (size_t i = 1; i < n; i++) {
        double d = a->x_samples[i] - ref->x_samples[i];
        e += d * d * a->sample_dt;
    }
    return e;
}
