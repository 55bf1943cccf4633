/* Checks of the friction wrench over the disc (Eqs. 7-8).  Oracles: the
 * uniform-COF identities (|F| = mu N, T = (2/3) mu N R), an adaptive 2-D
 * GSL integral of the Contensou problem written here, the exact variance
 * of a disc average from the distance distribution of two points in a
 * disc, and exact symmetries. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "contact.h"
#include "cof.h"
#include "lnfield.h"
#include "lognormal.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_statistics_double.h>

static sf_contact *uniform_contact(const sf_scene *s, size_t cells, sf_cof **cof)
{
    sf_contact_spec spec = { s->R, s->m * s->g, (sf_layout)s->layout, cells };
    sf_contact *c = NULL;
    if (sf_cof_alloc_uniform(s->mu_mean, cof))
        return NULL;
    if (sf_contact_alloc(&spec, *cof, &c)) {
        sf_cof_free(*cof);
        return NULL;
    }
    return c;
}

static const char *layout_name(const sf_scene *s)
{
    return s->layout == SF_LAYOUT_POLAR ? "polar" : "cartesian";
}

/* Pure translation: |F| = mu N opposing the slip, T = 0 (Eq. 4 reduced). */
static int chk_pure_translation(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cof *cof;
    sf_contact *ct = uniform_contact(s, s->cells, &cof);
    if (!ct)
        return SF_EINVAL;
    double N = s->m * s->g, mu = s->mu_mean;
    size_t K = 16;
    double worst_mag = 0, worst_T = 0, worst_dir = 0;
    double *ang = check_alloc(K * sizeof *ang), *mag = check_alloc(K * sizeof *mag);
    for (size_t k = 0; k < K; k++) {
        double a = 2 * M_PI * (double)k / (double)K, U = 0.2;
        double u = U * cos(a), v = U * sin(a), q[3];
        if (sf_contact_wrench(ct, 0, 0, u, v, 0, 1.0, q)) { free(ang); free(mag); return SF_EFAIL; }
        double F = hypot(q[0], q[1]);
        worst_mag = sf_max(worst_mag, fabs(F - mu * N) / (mu * N));
        worst_T = sf_max(worst_T, fabs(q[2]) / (mu * N * s->R));
        /* opposing the slip: F . u_hat = -|F| */
        worst_dir = sf_max(worst_dir, fabs((q[0] * u + q[1] * v) / U + F) / (mu * N));
        ang[k] = a;
        mag[k] = F / (mu * N);
    }
    double q[3];
    sf_contact_wrench(ct, 0, 0, -s->v_b, 0, 0, s->mu_k_ratio, q);
    sf_check_rel(r, "Fx for the disc slower than the belt (u = -v_b), kinetic: Eq. 4 gives +mu_k m g [N]",
                 q[0], s->mu_k_ratio * mu * N, c->spec.tolerance);
    sf_check_le(r, "max | |F| - mu N | / (mu N) over 16 slip directions", worst_mag, c->spec.tolerance);
    sf_check_le(r, "max |T| / (mu N R) over 16 slip directions", worst_T, c->spec.tolerance);
    sf_check_le(r, "max |F . u_hat + |F|| / (mu N): force opposes slip", worst_dir, c->spec.tolerance);
    sf_note(r, "%s layout, %zu cells (%zu quadrature points).", layout_name(s), s->cells, sf_contact_ncells(ct));
    sf_plot *p = sf_result_plot(r, "force_magnitude", "Friction force in pure translation vs slip direction",
                                "slip direction [rad]", "|F| / (mu N) [-]");
    sf_plot_series(p, "quadrature", SF_STYLE_LINESPOINTS, K, ang, mag);
    sf_plot_hline(p, "exact: 1", 1.0);
    free(ang); free(mag);
    sf_contact_free(ct);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Pure spin: T = -(2/3) mu N R sign(w), F = 0. */
static int chk_pure_spin(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cof *cof;
    sf_contact *ct = uniform_contact(s, s->cells, &cof);
    if (!ct)
        return SF_EINVAL;
    double N = s->m * s->g, mu = s->mu_mean, q[3], q2[3];
    sf_contact_wrench(ct, 0, 0, 0, 0, 1.5, 1.0, q);
    sf_contact_wrench(ct, 0, 0, 0, 0, -0.3, 1.0, q2);
    sf_check_rel(r, "T for spin w = +1.5 rad/s: -(2/3) mu N R [N m]", q[2], -2.0 / 3.0 * mu * N * s->R, c->spec.tolerance);
    sf_check_rel(r, "T for spin w = -0.3 rad/s: +(2/3) mu N R [N m]", q2[2], 2.0 / 3.0 * mu * N * s->R, c->spec.tolerance);
    sf_check_le(r, "|F| / (mu N) in pure spin", hypot(q[0], q[1]) / (mu * N), c->spec.tolerance);
    sf_note(r, "%s layout, %zu cells.", layout_name(s), s->cells);
    double w[2] = { -0.3, 1.5 }, t[2] = { q2[2] / (mu * N * s->R), q[2] / (mu * N * s->R) };
    double ex[2] = { 2.0 / 3.0, -2.0 / 3.0 };
    sf_plot *p = sf_result_plot(r, "torque", "Torque in pure spin", "spin w [rad/s]", "T / (mu N R) [-]");
    sf_plot_series(p, "quadrature", SF_STYLE_POINTS, 2, w, t);
    sf_plot_series(p, "exact -(2/3) sign(w)", SF_STYLE_LINES, 2, w, ex);
    sf_contact_free(ct);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* ---- independent oracle: adaptive 2-D integral of the Contensou problem.
 * Unit disc, w = 1, centre slip eps along x: v_p = (eps - y, x).
 * f = |(1/pi) int v_hat dA|, t = |(1/pi) int (r x v_hat) dA|.  Polar
 * coordinates about the centre; the direction field jumps only at the pole
 * (r, phi) = (eps, pi/2): break points there for both integrals. */
typedef struct {
    double eps, r;
    int comp;   /* 0: x-force, 1: torque */
    gsl_integration_workspace *inner;
} cf_par;

static double cf_inner(double phi, void *p)
{
    const cf_par *q = p;
    double x = q->r * cos(phi), y = q->r * sin(phi);
    double vx = q->eps - y, vy = x, n = hypot(vx, vy);
    if (n == 0)
        return 0;
    double val = q->comp == 0 ? vx / n : (x * vy - y * vx) / n;
    return val * q->r;   /* polar area element r dr dphi */
}

static double cf_outer(double r, void *p)
{
    cf_par *q = p;
    q->r = r;
    gsl_function F = { cf_inner, q };
    double pts[3] = { -M_PI / 2, M_PI / 2, 3 * M_PI / 2 }, val, err;
    if (gsl_integration_qagp(&F, pts, 3, 1e-13, 1e-12, 2000, q->inner, &val, &err))
        return NAN;
    return val;
}

static int cf_oracle(double eps, double *f, double *t)
{
    gsl_integration_workspace *wo = gsl_integration_workspace_alloc(2000);
    gsl_integration_workspace *wi = gsl_integration_workspace_alloc(2000);
    double out[2];
    int st = 0;
    for (int comp = 0; comp < 2; comp++) {
        cf_par q = { eps, 0, comp, wi };
        gsl_function F = { cf_outer, &q };
        double val, err;
        if (eps > 0 && eps < 1) {
            double pts[3] = { 0, eps, 1 };
            st |= gsl_integration_qagp(&F, pts, 3, 1e-13, 1e-11, 2000, wo, &val, &err);
        } else {
            st |= gsl_integration_qags(&F, 0, 1, 1e-13, 1e-11, 2000, wo, &val, &err);
        }
        out[comp] = fabs(val) / M_PI;
    }
    gsl_integration_workspace_free(wo);
    gsl_integration_workspace_free(wi);
    *f = st ? NAN : out[0];
    *t = st ? NAN : out[1];
    return st;
}

/* f and t from two sources on one log-x plot. */
static void plot_ft(sf_result *r, const char *stem, const char *title, size_t K, const double *e,
                    const double *fe, const double *te, const char *other, const double *fo, const double *to)
{
    char lf[96], lt[96];
    sf_plot *p = sf_result_plot(r, stem, title, "eps = U / (|w| R) [-]", "f = |F|/(mu N), t = |T|/(mu N R) [-]");
    sf_plot_log(p, 1, 0);
    sf_plot_series(p, "f closed form", SF_STYLE_LINES, K, e, fe);
    sf_plot_series(p, "t closed form", SF_STYLE_LINES, K, e, te);
    snprintf(lf, sizeof lf, "f %s", other);
    snprintf(lt, sizeof lt, "t %s", other);
    sf_plot_series(p, lf, SF_STYLE_POINTS, K, e, fo);
    sf_plot_series(p, lt, SF_STYLE_POINTS, K, e, to);
}

/* Closed forms (elliptic integrals) vs the adaptive integral. */
static int chk_closed_form_oracle(const sf_case *c, sf_result *r)
{
    size_t K = c->spec.sweep.n;
    if (!K)
        return SF_EINVAL;
    double *e = check_alloc(K * sizeof *e), *f1 = check_alloc(K * sizeof *f1), *t1 = check_alloc(K * sizeof *t1);
    double *f2 = check_alloc(K * sizeof *f2), *t2 = check_alloc(K * sizeof *t2);
    double worst = 0;
    for (size_t k = 0; k < K; k++) {
        e[k] = c->spec.sweep.v[k];
        sf_contensou(e[k], &f1[k], &t1[k]);
        cf_oracle(e[k], &f2[k], &t2[k]);
        double d = sf_max(fabs(f1[k] - f2[k]), fabs(t1[k] - t2[k]));
        worst = sf_max(worst, d);
        sf_note(r, "eps = %-8g f: closed %.15f adaptive %.15f | t: closed %.15f adaptive %.15f", e[k],
                f1[k], f2[k], t1[k], t2[k]);
    }
    sf_check_le(r, "max |closed form - adaptive 2-D integral| over the eps sweep (f and t)", worst, c->spec.tolerance);
    double f0, t0, fi, ti, f1e, t1e;
    sf_contensou(0, &f0, &t0);
    sf_contensou(1, &f1e, &t1e);
    sf_contensou(1e6, &fi, &ti);
    sf_check_abs(r, "f(0) = 0", f0, 0, 1e-15);
    sf_check_abs(r, "t(0) = 2/3", t0, 2.0 / 3.0, 1e-15);
    sf_check_abs(r, "f(1) = 8/(3 pi)", f1e, 8 / (3 * M_PI), 1e-14);
    sf_check_abs(r, "t(1) = 8/(9 pi)", t1e, 8 / (9 * M_PI), 1e-14);
    sf_check_abs(r, "f(1e6) -> 1", fi, 1, 1e-11);
    sf_check_rel(r, "t(1e6) ~ 1/(4 eps)", ti, 1 / (4e6), 1e-5);
    plot_ft(r, "contensou", "Contensou coupling: closed forms vs adaptive integral", K, e, f1, t1,
            "adaptive 2-D (GSL)", f2, t2);
    free(e); free(f1); free(t1); free(f2); free(t2);
    return SF_SUCCESS;
}

/* The quadrature under combined sliding and spin vs the closed forms. */
static int chk_contensou_sweep(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K)
        return SF_EINVAL;
    sf_cof *cof;
    sf_contact *ct = uniform_contact(s, s->cells, &cof);
    if (!ct)
        return SF_EINVAL;
    double N = s->m * s->g, mu = s->mu_mean, w = 2.0;
    double *e = check_alloc(K * sizeof *e), *fq = check_alloc(K * sizeof *fq), *tq = check_alloc(K * sizeof *tq);
    double *fe = check_alloc(K * sizeof *fe), *te = check_alloc(K * sizeof *te);
    double worst = 0, worst_e = 0, worst_dir = 0;
    for (size_t k = 0; k < K; k++) {
        e[k] = c->spec.sweep.v[k];
        double U = e[k] * w * s->R, q[3];
        /* slip at 30 degrees to exercise both components */
        double ux = U * cos(M_PI / 6), uy = U * sin(M_PI / 6);
        sf_contact_wrench(ct, 0, 0, ux, uy, w, 1.0, q);
        fq[k] = hypot(q[0], q[1]) / (mu * N);
        tq[k] = fabs(q[2]) / (mu * N * s->R);
        sf_contensou(e[k], &fe[k], &te[k]);
        double d = sf_max(fabs(fq[k] - fe[k]), fabs(tq[k] - te[k]));
        if (!(d <= worst) && !isnan(worst)) worst_e = e[k];   /* a NaN is the worst */
        worst = sf_max(worst, d);
        if (U > 0)  /* force antiparallel to u, torque opposing w */
            worst_dir = sf_max(worst_dir, fabs((q[0] * ux + q[1] * uy) / U + hypot(q[0], q[1])) / (mu * N));
        if (q[2] * w > 0)
            worst_dir = INFINITY;
    }
    char t[160];
    snprintf(t, sizeof t, "max |quadrature - closed form| in f and t (worst at eps = %g)", worst_e);
    sf_check_le(r, t, worst, c->spec.tolerance);
    sf_check_le(r, "force antiparallel to the centre slip, torque opposing the spin", worst_dir, c->spec.tolerance);
    sf_note(r, "%s layout, %zu cells; spin w = %g rad/s, slip at 30 degrees to x.", layout_name(s), s->cells, w);
    plot_ft(r, "contensou_quadrature", "Combined sliding and spin: quadrature vs closed form", K, e, fe, te,
            "quadrature", fq, tq);
    free(e); free(fq); free(tq); free(fe); free(te);
    sf_contact_free(ct);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Observed order of the quadrature vs cell count, pole inside (eps = 0.5)
 * and outside (eps = 2) the disc; tolerance = the smallest order accepted
 * for the pole-inside case (the hard one). */
static int chk_convergence(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t K = c->spec.sweep.n;
    if (K < 3)
        return SF_EINVAL;
    double eps2[2] = { 0.5, 2.0 }, order[2];
    double N = s->m * s->g, mu = s->mu_mean, w = 2.0;
    double *x = check_alloc(K * sizeof *x), *err[2], *lx = check_alloc(K * sizeof *lx), *ly = check_alloc(K * sizeof *ly);
    double *pts = check_alloc(K * sizeof *pts);
    for (int a = 0; a < 2; a++)
        err[a] = check_alloc(K * sizeof(double));
    for (size_t k = 0; k < K; k++) {
        sf_cof *cof;
        sf_contact *ct = uniform_contact(s, (size_t)c->spec.sweep.v[k], &cof);
        if (!ct)
            return SF_EINVAL;
        x[k] = c->spec.sweep.v[k];
        pts[k] = (double)sf_contact_ncells(ct);
        for (int a = 0; a < 2; a++) {
            double fe, te, q[3];
            sf_contensou(eps2[a], &fe, &te);
            sf_contact_wrench(ct, 0, 0, eps2[a] * w * s->R * cos(0.3), eps2[a] * w * s->R * sin(0.3), w, 1.0, q);
            err[a][k] = sf_max(fabs(hypot(q[0], q[1]) / (mu * N) - fe), fabs(fabs(q[2]) / (mu * N * s->R) - te));
        }
        sf_contact_free(ct);
        sf_cof_free(cof);
    }
    /* least-squares slope of log err vs log(resolution) over the points
     * above the round-off floor (1e-12); an erratic pole-inside error makes
     * a fit over the whole sweep the steadier estimator.  A series that
     * reaches the floor within 3 points is spectral: its check is the floor. */
    const double floor_err = 1e-12;
    int spectral[2];
    for (int a = 0; a < 2; a++) {
        size_t n = 0;
        for (size_t k = 0; k < K; k++) {
            if (err[a][k] <= floor_err) continue;
            lx[n] = log(x[k]);
            ly[n] = log(err[a][k]);
            n++;
        }
        double c0, c1, cov00, cov01, cov11, sumsq;
        spectral[a] = n < 3;
        if (spectral[a] || gsl_fit_linear(lx, 1, ly, 1, n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq))
            order[a] = NAN;
        else
            order[a] = -c1;
    }
    sf_note(r, "| resolution | quadrature points | error, pole inside (eps = 0.5) | error, pole outside (eps = 2) |\n|---|---|---|---|");
    for (size_t k = 0; k < K; k++)
        sf_note(r, "| %g | %g | %.3e | %.3e |", x[k], pts[k], err[0][k], err[1][k]);
    sf_note(r, "\nObserved order (least-squares slope of log error vs log resolution, points above %g): pole "
               "inside %.2f, pole outside %.2f%s. Resolution is %s.\n", floor_err, order[0], order[1],
            spectral[1] ? " (reaches round-off within 3 resolutions: spectral)" : "",
            s->layout == SF_LAYOUT_POLAR ? "the number of rings" : "cells across the diameter");
    const char *name[2] = { "observed order, pole inside the disc (eps = 0.5)",
                            "observed order, pole outside the disc (eps = 2)" };
    for (int a = 0; a < 2; a++) {
        if (spectral[a])
            sf_check_le(r, a ? "pole outside: error at the finest resolution (spectral, round-off floor)"
                             : "pole inside: error at the finest resolution (round-off floor)",
                        err[a][K - 1], floor_err);
        else
            sf_check_ge(r, name[a], order[a], c->spec.tolerance);
    }
    sf_check_le(r, "error at the finest resolution, pole outside", err[1][K - 1], 1e-3);
    sf_plot *p = sf_result_plot(r, "convergence", "Quadrature error vs resolution (uniform COF)",
                                s->layout == SF_LAYOUT_POLAR ? "rings [-]" : "cells across the diameter [-]",
                                "max error in f and t [-]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "pole inside (eps = 0.5)", SF_STYLE_LINESPOINTS, K, x, err[0]);
    sf_plot_series(p, "pole outside (eps = 2)", SF_STYLE_LINESPOINTS, K, x, err[1]);
    double *ref = check_alloc(K * sizeof *ref);
    for (size_t k = 0; k < K; k++)
        ref[k] = err[0][0] * pow(x[k] / x[0], -c->spec.tolerance);
    sf_plot_series(p, "slope of the accepted order", SF_STYLE_LINES, K, x, ref);
    free(ref); free(x); free(lx); free(ly); free(pts); free(err[0]); free(err[1]);
    return SF_SUCCESS;
}

/* Central symmetry for a random field: wrench(-d) = -wrench(d). */
static int chk_central_symmetry(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    gsl_rng *rng = sf_case_rng(c);
    check_disc_field df = { 0 };
    double worst = 0, scale = s->mu_mean * s->m * s->g;
    size_t tested = 0;
    for (size_t real = 0; real < 4; real++) {
        sf_cof *cof = check_disc_cof(s, rng, &df);
        if (!cof) { gsl_rng_free(rng); return SF_EFAIL; }
        sf_contact_spec spec = { s->R, s->m * s->g, (sf_layout)s->layout, s->cells };
        sf_contact *ct;
        if (sf_contact_alloc(&spec, cof, &ct)) { sf_cof_free(cof); gsl_rng_free(rng); return SF_EFAIL; }
        for (int k = 0; k < 50; k++) {
            double u = gsl_ran_gaussian(rng, 0.3), v = gsl_ran_gaussian(rng, 0.3), w = gsl_ran_gaussian(rng, 1.0);
            double a[3], b[3];
            sf_contact_wrench(ct, 0.01 * k, -0.005 * k, u, v, w, 1.0, a);
            sf_contact_wrench(ct, 0.01 * k, -0.005 * k, -u, -v, -w, 1.0, b);
            for (int i = 0; i < 3; i++) {
                double d = fabs(a[i] + b[i]) / (i < 2 ? scale : scale * s->R);
                worst = sf_max(worst, d);
            }
            tested++;
        }
        sf_contact_free(ct);
        sf_cof_free(cof);
    }
    sf_check_le(r, "max |Q(d) + Q(-d)| / (mu N) over random fields and directions", worst, c->spec.tolerance);
    sf_note(r, "%zu direction pairs over 4 lognormal realisations (l = %g m, grid %zu x %zu).", tested, s->l,
            df.gs.nx, df.gs.ny);
    double x[2] = { 0, 1 }, y[2] = { worst > 0 ? worst : 1e-17, worst > 0 ? worst : 1e-17 };
    sf_plot *p = sf_result_plot(r, "symmetry", "Central symmetry residual", "(single value) [-]", "max residual [-]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "measured", SF_STYLE_LINESPOINTS, 2, x, y);
    sf_plot_hline(p, "tolerance", c->spec.tolerance > 0 ? c->spec.tolerance : 1e-16);
    check_disc_field_free(&df);
    gsl_rng_free(rng);
    return SF_SUCCESS;
}

/* Density of the distance s between two uniform points of a disc of
 * radius R: p(s) = (4 s/(pi R^2)) (acos(q) - q sqrt(1 - q^2)), q = s/(2R). */
typedef struct { double R, l, sigma_g; int lognormal; } var_par;

static double var_integrand(double sd, void *p)
{
    const var_par *q = p;
    double x = sd / (2 * q->R);
    double dens = 4 * sd / (M_PI * q->R * q->R) * (acos(x) - x * sqrt(sf_max(0, 1 - x * x)));
    double rho = exp(-sd * sd / (q->l * q->l));
    if (q->lognormal) {
        double s2 = q->sigma_g * q->sigma_g;
        rho = expm1(s2 * rho) / expm1(s2);
    }
    return dens * rho;
}

/* Wrench statistics in pure translation: |F| = N * (disc average of mu):
 * mean mu_mean N, variance N^2 sigma^2 int rho_H(s) p(s) ds. */
static int chk_wrench_statistics(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_scene gs = check_gen_scene(c);   /* the fields are drawn from the generator's scene */
    gsl_rng *rng = sf_case_rng(c);
    check_disc_field df = { 0 };
    size_t N = s->samples;
    double *F = check_alloc(N * sizeof *F), Nf = s->m * s->g;
    for (size_t k = 0; k < N; k++) {
        sf_cof *cof = check_disc_cof(&gs, rng, &df);
        if (!cof) { gsl_rng_free(rng); free(F); return SF_EFAIL; }
        sf_contact_spec spec = { s->R, Nf, (sf_layout)s->layout, s->cells };
        sf_contact *ct;
        if (sf_contact_alloc(&spec, cof, &ct)) { sf_cof_free(cof); return SF_EFAIL; }
        double q[3];
        sf_contact_wrench(ct, 0, 0, -s->v_b, 0, 0, 1.0, q);
        F[k] = hypot(q[0], q[1]);
        sf_contact_free(ct);
        sf_cof_free(cof);
    }
    sf_lognormal ln;
    sf_lognormal_init(&ln, s->mu_mean, s->mu_std);
    var_par vp = { s->R, s->l, ln.sigma_g, 1 };
    gsl_function G = { var_integrand, &vp };
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    double I, err;
    gsl_integration_qags(&G, 0, 2 * s->R, 1e-14, 1e-10, 1000, ws, &I, &err);
    vp.lognormal = 0;
    double Ig;
    gsl_integration_qags(&G, 0, 2 * s->R, 1e-14, 1e-10, 1000, ws, &Ig, &err);
    gsl_integration_workspace_free(ws);
    double mean_ex = s->mu_mean * Nf, var_ex = Nf * Nf * s->mu_std * s->mu_std * I;
    sf_result_data(r, "|F| per realisation", N, F);
    double m = 0, m2 = 0, m4 = 0;
    for (size_t k = 0; k < N; k++) m += F[k];
    m /= (double)N;
    for (size_t k = 0; k < N; k++) {
        double d = F[k] - m;
        m2 += d * d;
        m4 += d * d * d * d;
    }
    double var = m2 / (double)(N - 1);
    m4 /= (double)N;
    double zm = (m - mean_ex) / sqrt(var / (double)N);
    double zv = (var - var_ex) / sqrt(sf_max(m4 - var * var, 1e-300) / (double)N);
    sf_check_pvalue(r, "mean |F| = mu_mean N (z test)", sf_z_pvalue(zm), c->spec.alpha / 2, N);
    sf_check_pvalue(r, "var |F| = N^2 sigma^2 int rho_H p ds (z test, sample kurtosis)", sf_z_pvalue(zv), c->spec.alpha / 2, N);
    sf_note(r, "Exact: mean %.6g N, std %.6g N (variance factor of the disc average %.5g with the distorted "
               "correlation, %.5g with the Gaussian one). Sample: mean %.6g N, std %.6g N over %zu realisations. "
               "Grid spacing %.4g m (l/%g); bilinear interpolation lowers the variance between nodes by a "
               "fraction of order (h/l)^2.", mean_ex, sqrt(var_ex), I, Ig, m, sqrt(var), N, df.gs.dx, s->l / df.gs.dx);
    /* histogram vs normal approximation */
    size_t B = 30;
    double lo = m - 4 * sqrt(var), hi = m + 4 * sqrt(var), bw = (hi - lo) / (double)B;
    double *bx = check_alloc(B * sizeof *bx), *by = check_alloc(B * sizeof *by), *bn = check_alloc(B * sizeof *bn);
    for (size_t b = 0; b < B; b++) {
        bx[b] = lo + (b + 0.5) * bw;
        bn[b] = gsl_ran_gaussian_pdf(bx[b] - mean_ex, sqrt(var_ex));
    }
    for (size_t k = 0; k < N; k++) {
        long b = (long)floor((F[k] - lo) / bw);
        if (b >= 0 && b < (long)B) by[b] += 1.0 / ((double)N * bw);
    }
    sf_plot *p = sf_result_plot(r, "force_distribution", "Friction force over realisations (pure translation)",
                                "|F| [N]", "density [1/N]");
    sf_plot_series(p, "sample histogram", SF_STYLE_STEPS, B, bx, by);
    sf_plot_series(p, "normal with the exact mean and variance", SF_STYLE_LINES, B, bx, bn);
    free(bx); free(by); free(bn); free(F);
    check_disc_field_free(&df);
    gsl_rng_free(rng);
    return SF_SUCCESS;
}


/* Exact mean-square error of bilinear interpolation of a unit-variance
 * field with correlation exp(-r^2/l^2) from nodes of spacing H, averaged
 * over an s x s lattice of points in a cell (the fine nodes); and the mean
 * variance of the interpolant itself (variance lost = 1 - that). */
static void interp_exact(double H, double l, size_t s, double *mse, double *var_mid)
{
    double cx[4] = { 0, H, 0, H }, cy[4] = { 0, 0, H, H }, acc = 0;
    for (size_t a = 0; a < s; a++)
        for (size_t b = 0; b < s; b++) {
            double tx = (double)a / (double)s, ty = (double)b / (double)s;
            double w[4] = { (1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty };
            double px = tx * H, py = ty * H, e = 1, vv = 0;
            for (int k = 0; k < 4; k++) {
                e -= 2 * w[k] * ref_sq_exp(px - cx[k], py - cy[k], l);
                for (int j = 0; j < 4; j++)
                    vv += w[k] * w[j] * ref_sq_exp(cx[k] - cx[j], cy[k] - cy[j], l);
            }
            acc += e + vv;
        }
    *mse = acc / (double)(s * s);
    double vm = 0;   /* cell centre: weights 1/4 */
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 4; j++)
            vm += 0.0625 * ref_sq_exp(cx[k] - cx[j], cy[k] - cy[j], l);
    *var_mid = vm;
}

/* Interpolation error of the COF grid vs grid spacing: bilinear
 * interpolation (sf_cof_eval) from coarse subgrids of one fine Gaussian
 * field, against the exact mean-square error from the covariance; the
 * exact error must fall at order 2 in H (MSE at order 4). */
static int chk_interpolation(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t K = c->spec.sweep.n, N = s->samples, m = s->nx;
    if (K < 2)
        return SF_EINVAL;
    sf_field *f;
    sf_field_spec spec;
    sf_scene gs = check_gen_scene(c);   /* the field is drawn from the generator's scene */
    sf_field_spec_default(&spec, m, m, s->dx, s->dx, gs.l);
    if (!sf_usable(sf_field_alloc(&spec, &f)))
        return SF_EFAIL;
    gsl_rng *rng = sf_case_rng(c);
    double *g = check_alloc(m * m * sizeof *g), *h = check_alloc(K * sizeof *h);
    double *ex = check_alloc(K * sizeof *ex), *vm = check_alloc(K * sizeof *vm);
    double *mean = check_alloc(K * sizeof *mean), *sd = check_alloc(K * sizeof *sd);
    double *per = check_alloc(N * K * sizeof *per);
    for (size_t q = 0; q < N; q++) {
        check_field_sample(c, f, rng, g, m * m);
        for (size_t k = 0; k < K; k++) {
            size_t st = (size_t)c->spec.sweep.v[k], mc = (m - 1) / st + 1;
            double *cg = check_alloc(mc * mc * sizeof *cg);
            for (size_t j = 0; j < mc; j++)
                for (size_t i = 0; i < mc; i++)
                    cg[i + mc * j] = g[i * st + m * (j * st)];
            sf_cof *cof;
            sf_cof_alloc_grid(mc, mc, 0, 0, s->dx * (double)st, s->dx * (double)st, cg, &cof);
            size_t lim = (mc - 1) * st, cnt = 0;
            double acc = 0;
            for (size_t j = 0; j < lim; j++)
                for (size_t i = 0; i < lim; i++) {
                    double e = sf_cof_eval(cof, (double)i * s->dx, (double)j * s->dx) - g[i + m * j];
                    acc += e * e;
                    cnt++;
                }
            per[q * K + k] = acc / (double)cnt;
            sf_cof_free(cof);
            free(cg);
        }
    }
    sf_result_data(r, "mean-square interpolation error per field and spacing", N * K, per);
    double worstp = 1;
    for (size_t k = 0; k < K; k++) {
        size_t st = (size_t)c->spec.sweep.v[k];
        h[k] = s->dx * (double)st;
        interp_exact(h[k], s->l, st, &ex[k], &vm[k]);
        mean[k] = gsl_stats_mean(per + k, K, N);
        sd[k] = gsl_stats_sd(per + k, K, N);
        double z = (mean[k] - ex[k]) / (sd[k] / sqrt((double)N));
        worstp = sf_min(worstp, sf_z_pvalue(z));
    }
    /* observed order of the exact RMS error over the sweep */
    double *lx = check_alloc(K * sizeof *lx), *ly = check_alloc(K * sizeof *ly), c0, c1, c00, c01, c11, ss;
    for (size_t k = 0; k < K; k++) {
        lx[k] = log(h[k]);
        ly[k] = 0.5 * log(ex[k]);
    }
    gsl_fit_linear(lx, 1, ly, 1, K, &c0, &c1, &c00, &c01, &c11, &ss);
    sf_check_pvalue(r, "sample MSE = exact MSE from the covariance, worst z test over the spacings (Bonferroni)",
                    sf_min(1, worstp * (double)K), c->spec.alpha, N);
    sf_check_abs(r, "observed order of the RMS interpolation error in H (exact: 2)", c1, 2.0, c->spec.tolerance);
    sf_note(r, "| H [m] | H/l | exact RMS error | sample RMS error | interpolant variance at cell centre |\n|---|---|---|---|---|");
    for (size_t k = 0; k < K; k++)
        sf_note(r, "| %.4g | %.3g | %.3e | %.3e | %.5f |", h[k], h[k] / s->l, sqrt(ex[k]), sqrt(mean[k]), vm[k]);
    double mse_q, vm_q;
    interp_exact(s->l / 4, s->l, 1, &mse_q, &vm_q);
    double var_loss_quarter = 1 - vm_q;
    sf_note(r, "\n**What interpolation does to the variance.** Between nodes the bilinear interpolant is a "
               "weighted average of correlated values, so its variance is below 1: at the cell centre it is "
               "the last column (about 1 - (H/l)^2/2 for small H/l). The COF seen by the disc is therefore "
               "slightly smoother and less variable than the target field between nodes; the strip grid uses "
               "H <= l/4, where the centre variance loss is %.2g%% of the variance.\n",
            100 * var_loss_quarter);
    sf_plot *p = sf_result_plot(r, "interp_error", "Bilinear interpolation error of the field vs node spacing",
                                "node spacing H / l [-]", "RMS error [std of the field]");
    sf_plot_log(p, 1, 1);
    double *hx = check_alloc(K * sizeof *hx), *re = check_alloc(K * sizeof *re), *rs = check_alloc(K * sizeof *rs);
    double *lo = check_alloc(K * sizeof *lo), *hi = check_alloc(K * sizeof *hi);
    for (size_t k = 0; k < K; k++) {
        hx[k] = h[k] / s->l;
        re[k] = sqrt(ex[k]);
        rs[k] = sqrt(mean[k]);
        double half = 3.29 * sd[k] / sqrt((double)N);   /* 99.9% band */
        lo[k] = sqrt(sf_max(ex[k] - half, 1e-300));
        hi[k] = sqrt(ex[k] + half);
    }
    sf_plot_band(p, "99.9% band of the sample mean", K, hx, lo, hi);
    sf_plot_series(p, "exact (covariance)", SF_STYLE_LINES, K, hx, re);
    sf_plot_series(p, "sampled", SF_STYLE_POINTS, K, hx, rs);
    free(hx); free(re); free(rs); free(lo); free(hi); free(lx); free(ly);
    free(g); free(h); free(ex); free(vm); free(mean); free(sd); free(per);
    sf_field_free(f);
    gsl_rng_free(rng);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_contact[] = {
    { "contact_pure_translation", chk_pure_translation, "uniform COF: |F| = mu N opposing slip, T = 0" },
    { "contact_pure_spin", chk_pure_spin, "uniform COF: T = -(2/3) mu N R sign(w), F = 0" },
    { "contact_closed_form_oracle", chk_closed_form_oracle, "Contensou closed forms vs adaptive GSL 2-D integral" },
    { "contact_contensou_sweep", chk_contensou_sweep, "quadrature vs closed forms over the spin ratio" },
    { "contact_convergence", chk_convergence, "observed quadrature order vs cells (log-log)" },
    { "contact_central_symmetry", chk_central_symmetry, "Q(-d) = -Q(d) for random fields" },
    { "contact_interpolation", chk_interpolation, "bilinear COF interpolation error vs spacing, exact from the covariance" },
    { "contact_wrench_statistics", chk_wrench_statistics, "mean and variance of F over realisations vs exact" },
    { NULL, NULL, NULL }
};
