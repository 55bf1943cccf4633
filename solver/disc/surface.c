/* slipfield: the static limit surface of Eqs. 9-11 as a plan (surface.h):
 * the COF at each quadrature cell stored once, the surface's points and
 * sections, and the stick margin of a state against it. */
#include "surface.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>

struct sf_surface {
    size_t n;
    double *px, *py;   /* cell offsets / R (dimensionless) */
    double *a;         /* mu_s(cell) x weight / N (dimensionless; sums to mu_bar) */
    double mu_bar;
    /* Brent workspaces, made with the plan: the section's (theta at T* = 0)
     * and the radius's around it (psi at a force direction), so that no
     * evaluation allocates (the oscillator's stick test calls them often).
     * Scratch, not state: reset by every gsl_root_fsolver_set. */
    gsl_root_fsolver *inner, *outer;
};

int sf_surface_alloc(const sf_contact *c, double xb, double yb, sf_surface **out)
{
    *out = NULL;
    sf_surface *s = sf_calloc(1, sizeof *s);
    if (!s)
        return SF_ENOMEM;
    s->n = sf_contact_ncells(c);
    s->px = sf_malloc(s->n * sizeof *s->px);
    s->py = sf_malloc(s->n * sizeof *s->py);
    s->a = sf_malloc(s->n * sizeof *s->a);
    s->inner = SF_FALLIBLE(gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
    s->outer = SF_FALLIBLE(gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
    if (!s->px || !s->py || !s->a || !s->inner || !s->outer) {
        sf_surface_free(s);
        return SF_ENOMEM;
    }
    const double *rx, *ry, *wt;
    sf_contact_cells(c, &rx, &ry, &wt);
    double R = sf_contact_radius(c);
    for (size_t i = 0; i < s->n; i++) {
        s->px[i] = rx[i] / R;
        s->py[i] = ry[i] / R;
    }
    sf_surface_recentre(s, c, xb, yb);
    *out = s;
    return SF_SUCCESS;
}

void sf_surface_recentre(sf_surface *s, const sf_contact *c, double xb, double yb)
{
    const double *rx, *ry, *wt;
    sf_contact_cells(c, &rx, &ry, &wt);
    const sf_cof *cof = sf_contact_get_cof(c);
    double N = sf_contact_normal_force(c);
    s->mu_bar = 0;
    for (size_t i = 0; i < s->n; i++) {
        s->a[i] = wt[i] / N * sf_cof_eval(cof, xb + rx[i], yb + ry[i]);
        s->mu_bar += s->a[i];
    }
}

void sf_surface_free(sf_surface *s)
{
    if (!s)
        return;
    free(s->px);
    free(s->py);
    free(s->a);
    if (s->inner)
        gsl_root_fsolver_free(s->inner);
    if (s->outer)
        gsl_root_fsolver_free(s->outer);
    free(s);
}

double sf_surface_mean_cof(const sf_surface *s) { return s->mu_bar; }

void sf_surface_point(const sf_surface *s, double theta, double psi, double q[3])
{
    double u = cos(theta) * cos(psi), v = cos(theta) * sin(psi), w = sin(theta);
    double fx = 0, fy = 0, t = 0;
    for (size_t i = 0; i < s->n; i++) {
        double vx = u - w * s->py[i], vy = v + w * s->px[i], m = hypot(vx, vy);
        if (m == 0)
            continue;
        double b = s->a[i] / m;
        fx += b * vx;
        fy += b * vy;
        t += b * (s->px[i] * vy - s->py[i] * vx);
    }
    q[0] = fx;
    q[1] = fy;
    q[2] = t;
}

typedef struct { const sf_surface *s; double psi; double alpha; } root_par;

static double torque_at(double theta, void *p)
{
    const root_par *r = p;
    double q[3];
    sf_surface_point(r->s, theta, r->psi, q);
    return q[2];
}

/* Brent on [lo, hi] (a sign change is required) with the workspace rs. */
static int brent(gsl_root_fsolver *rs, gsl_function *F, double lo, double hi, double tol, double *x)
{
    *x = NAN;   /* no root: the callers' results are NaN, never uninitialised */
    if (gsl_root_fsolver_set(rs, F, lo, hi))
        return SF_EFAIL;
    int status = GSL_CONTINUE;
    for (int it = 0; it < 200 && status == GSL_CONTINUE; it++) {
        gsl_root_fsolver_iterate(rs);
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(rs), gsl_root_fsolver_x_upper(rs), tol, 0);
    }
    *x = gsl_root_fsolver_root(rs);
    return status == GSL_SUCCESS ? SF_SUCCESS : SF_EMAXITER;
}

int sf_surface_section(const sf_surface *s, double psi, double *theta, double q[3])
{
    root_par p = { s, psi, 0 };
    gsl_function F = { torque_at, &p };
    /* T*(-pi/2) = -sum a |p| < 0 < T*(pi/2) whenever mu_bar > 0 */
    double lo = -M_PI / 2, hi = M_PI / 2;
    if (s->mu_bar <= 0) {
        *theta = 0;
        q[0] = q[1] = q[2] = 0;
        return SF_SUCCESS;
    }
    int rc = brent(s->inner, &F, lo, hi, 1e-13, theta);
    sf_surface_point(s, *theta, psi, q);
    return rc;
}

static double wrap(double a)
{
    return remainder(a, 2 * M_PI);
}

/* Force direction of the section point at psi, minus the target alpha. */
static double alpha_gap(double psi, void *p)
{
    root_par *r = p;
    double th, q[3];
    sf_surface_section(r->s, psi, &th, q);   /* no allocation; a root short of 1e-13 still points the force */
    return wrap(atan2(q[1], q[0]) - r->alpha);
}

int sf_surface_section_radius(const sf_surface *s, double alpha, double *rho, double *psi_out)
{
    root_par p = { s, 0, alpha };
    gsl_function F = { alpha_gap, &p };
    *rho = NAN;
    if (s->mu_bar <= 0) {
        *rho = 0;
        if (psi_out)
            *psi_out = alpha;
        return SF_SUCCESS;
    }
    /* alpha(psi) stays close to psi: widen a bracket around alpha until the
     * wrapped gap changes sign (it must within half a turn). */
    double h = 0.05, lo, hi, glo, ghi;
    for (;;) {
        lo = alpha - h;
        hi = alpha + h;
        glo = alpha_gap(lo, &p);
        ghi = alpha_gap(hi, &p);
        if (glo <= 0 && ghi >= 0)
            break;
        h *= 2;
        if (h > M_PI / 2)
            return SF_EFAIL;
    }
    double psi = glo == 0 ? lo : (ghi == 0 ? hi : 0);
    int rc = SF_SUCCESS;
    if (glo != 0 && ghi != 0)
        rc = brent(s->outer, &F, lo, hi, 1e-13, &psi);
    double th, q[3];
    int rc2 = sf_surface_section(s, psi, &th, q);
    *rho = hypot(q[0], q[1]);
    if (psi_out)
        *psi_out = psi;
    return rc ? rc : rc2;
}

int sf_surface_stick_margin(sf_surface *s, const sf_contact *c, double xb, double yb, double Fx, double Fy,
                            double *margin)
{
    double N = sf_contact_normal_force(c), F = hypot(Fx, Fy), rho;
    *margin = NAN;   /* never uninitialised */
    if (!isfinite(F))
        return SF_EINVAL;
    sf_surface_recentre(s, c, xb, yb);
    int rc = sf_surface_section_radius(s, F > 0 ? atan2(Fy, Fx) : 0, &rho, NULL);
    *margin = rho * N - F;
    return rc;
}

int sf_contact_stick_margin(const sf_contact *c, double xb, double yb,
                            double Fx, double Fy, int exact, double *margin)
{
    double N = sf_contact_normal_force(c), F = hypot(Fx, Fy);
    *margin = NAN;
    if (!isfinite(F))
        return SF_EINVAL;
    if (!exact) {
        *margin = sf_contact_mean_cof(c, xb, yb) * N - F;
        return SF_SUCCESS;
    }
    sf_surface *s;
    int rc = sf_surface_alloc(c, xb, yb, &s);
    if (rc)
        return rc;
    rc = sf_surface_stick_margin(s, c, xb, yb, Fx, Fy, margin);
    sf_surface_free(s);
    return rc;
}
