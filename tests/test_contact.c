/* Unit tests: the COF seen by the disc, the friction wrench, the
 * Contensou closed forms and the limit-surface plan. */
#include "test_util.h"
#include "cof.h"
#include "numplan.h"
#include "contact.h"
#include "surface.h"
#include "scene.h"
#include "sf_error.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

/* Bilinear interpolation reproduces a bilinear function exactly, and
 * points outside the grid are clamped and counted. */
static void cof_bilinear(void **state)
{
    (void)state;
    size_t m = 5, n = 4;
    double g[20];
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < m; i++) {
            double x = 1.0 + 0.5 * (double)i, y = -2.0 + 0.25 * (double)j;
            g[i + m * j] = 1 + 2 * x - 3 * y + 0.5 * x * y;
        }
    sf_cof *c;
    assert_int_equal(sf_cof_alloc_grid(m, n, 1.0, -2.0, 0.5, 0.25, g, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_get_kind(c), SF_COF_FIELD);
    double x = 1.37, y = -1.61;
    assert_close(sf_cof_eval(c, x, y), 1 + 2 * x - 3 * y + 0.5 * x * y, 1e-14);
    assert_close(sf_cof_eval(c, 3.0, -1.25), g[4 + m * 3], 1e-15);   /* last node */
    assert_int_equal(sf_cof_outside(c), 0);
    assert_close(sf_cof_eval(c, 100, -1.61), sf_cof_eval(c, 3.0, -1.61), 1e-15);
    assert_close(sf_cof_eval(c, 1.37, -100), sf_cof_eval(c, 1.37, -2.0), 1e-15);
    (void)sf_cof_eval(c, NAN, 0);
    assert_int_equal(sf_cof_outside(c), 3);
    /* the read-only view gives back the grid as allocated (values copied) */
    size_t vm = 0, vn = 0;
    double vx0 = 0, vy0 = 0, vdx = 0, vdy = 0;
    const double *mu = NULL;
    assert_int_equal(sf_cof_grid_view(c, &vm, &vn, &vx0, &vy0, &vdx, &vdy, &mu), SF_SUCCESS);
    assert_int_equal(vm, m);
    assert_int_equal(vn, n);
    assert_close(vx0, 1.0, 0);
    assert_close(vy0, -2.0, 0);
    assert_close(vdx, 0.5, 0);
    assert_close(vdy, 0.25, 0);
    assert_non_null(mu);
    assert_true(mu != g);
    for (size_t k = 0; k < m * n; k++)
        assert_close(mu[k], g[k], 0);
    assert_int_equal(sf_cof_grid_view(c, NULL, NULL, NULL, NULL, NULL, NULL, NULL), SF_SUCCESS);
    sf_cof_free(c);
    /* no grid behind a uniform COF */
    assert_int_equal(sf_cof_alloc_uniform(0.5, &c), SF_SUCCESS);
    vm = 7;
    assert_int_equal(sf_cof_grid_view(c, &vm, &vn, &vx0, &vy0, &vdx, &vdy, &mu), SF_EINVAL);
    assert_int_equal(vm, 7);
    sf_cof_free(c);
}

static void cof_invalid(void **state)
{
    (void)state;
    sf_cof *c = (sf_cof *)1;
    double g[4] = { 1, 1, 1, 1 };
    assert_int_equal(sf_cof_alloc_uniform(-0.1, &c), SF_EINVAL);
    assert_null(c);
    assert_int_equal(sf_cof_alloc_uniform(NAN, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(1, 2, 0, 0, 1, 1, g, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(2, 2, 0, 0, 0, 1, g, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(2, 2, 0, 0, 1, 1, NULL, &c), SF_EINVAL);
    sf_cof_free(NULL);
}

/* The plan decides what a scene needs: nothing for a uniform COF, one
 * draw for a random variable, a strip field sized from l, v_b T and the
 * spring excursion bound; an oversized strip is refused with a reason. */
static void cof_plan(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof_plan *p;
    sf_cof *c;
    char err[256] = "";
    s.cof = SF_COF_UNIFORM;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_close(sf_cof_eval(c, 3, 4), s.mu_mean, 0);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    s.cof = SF_COF_VARIABLE;
    assert_int_equal(sf_cof_from_scene(&s, rng, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_get_kind(c), SF_COF_VARIABLE);
    assert_true(sf_cof_eval(c, 0, 0) > 0 && sf_cof_eval(c, 0, 0) != s.mu_mean);
    sf_cof_free(c);
    s.cof = SF_COF_FIELD;
    s.T = 10;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
    double B = s.R + 2 * (s.mu_mean + 4 * s.mu_std) * s.m * s.g / s.k + 2 * in->dx;
    assert_close(in->bound, B, 1e-15);
    assert_close(in->dx, s.l / 8, 1e-15);
    assert_true(in->x0 <= -s.v_b * s.T - B + 1e-12);
    assert_true(in->x0 + in->dx * (double)(in->nx - 1) >= B - 1e-12);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_true(sf_cof_eval(c, -1.0, 0.3) > 0);
    assert_int_equal(sf_cof_outside(c), 0);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    s.strip_halfwidth = 0.2;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_close(sf_cof_plan_get_info(p)->y0, -(0.2 + s.R + 2 * s.l / 8), 1e-15);
    sf_cof_plan_free(p);
    s.l = 1e-3;   /* a 1e-3 m field over a 30 m strip: point values refused */
    s.cof_model = SF_COFMODEL_POINT;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_ETOOBIG);
    assert_non_null(strstr(err, "grid points"));
    s.cof_model = SF_COFMODEL_AUTO;   /* the plan's choice there: cell averages (numplan.h) */
    size_t nc = 0;
    assert_int_equal(sf_numplan_cell_average(&s, &nc, NULL), 1);
    assert_true(nc >= SF_PLAN_CELLAVG_CELLS && nc <= SF_PLAN_CELLAVG_MAX_CELLS);
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_close(sf_cof_plan_get_info(p)->box, 2 * s.R / (double)nc, 1e-15);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_close(sf_cof_box(c), 2 * s.R / (double)nc, 1e-15);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    s.l = 1e5;    /* a 1e5 m correlation length over a 15 m strip: one variable */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->kind, SF_COF_VARIABLE);
    assert_int_equal(sf_cof_plan_get_info(p)->shortcut, 1);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_get_kind(c), SF_COF_VARIABLE);
    sf_cof_free(c);
    double E = sf_cof_plan_get_info(p)->strip_diag;
    assert_true((E / s.l) * (E / s.l) <= SF_COF_SHORTCUT_E2);
    sf_cof_plan_free(p);
    s.shortcuts = 0;   /* the same scene in full: a (tiny) strip field */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->kind, SF_COF_FIELD);
    assert_int_equal(sf_cof_plan_get_info(p)->shortcut, 0);
    assert_close(sf_cof_plan_get_info(p)->strip_diag, E, 0);
    sf_cof_plan_free(p);
    s.shortcuts = 1;
    s.l = 0.1;
    s.mu_std = 0;      /* no spread: uniform unless computed in full */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->shortcut, 1);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_close(sf_cof_eval(c, 0, 0), s.mu_mean, 0);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    s.shortcuts = 0;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->kind, SF_COF_FIELD);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_close(sf_cof_eval(c, -1.0, 0.3), s.mu_mean, 1e-15);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    gsl_rng_free(rng);
}

/* The closed forms at their special points, continuity across the branch
 * points eps = 1 and eps = 2, monotonicity, and the asymptote. */
static void contensou(void **state)
{
    (void)state;
    double f, t, f2, t2;
    sf_contensou(0, &f, &t);
    assert_close(f, 0, 0);
    assert_close(t, 2.0 / 3.0, 1e-16);
    sf_contensou(1, &f, &t);
    assert_close(f, 8 / (3 * M_PI), 1e-15);
    assert_close(t, 8 / (9 * M_PI), 1e-15);
    sf_contensou(1 - 1e-12, &f2, &t2);
    assert_close(f2, f, 1e-10);
    assert_close(t2, t, 1e-10);
    sf_contensou(1 + 1e-12, &f2, &t2);
    assert_close(f2, f, 1e-10);
    assert_close(t2, t, 1e-10);
    sf_contensou(2 - 1e-13, &f, &t);
    sf_contensou(2, &f2, &t2);
    assert_close(t2, t, 1e-12);
    sf_contensou(-0.5, &f, &t);
    sf_contensou(0.5, &f2, &t2);
    assert_close(f, f2, 0);
    sf_contensou(1e8, &f, &t);
    assert_close(f, 1, 1e-14);
    assert_close(t * 4e8, 1, 1e-10);
    sf_contensou(INFINITY, &f, &t);
    assert_close(f, 1, 0);
    double fp = 0, tp = 1;
    for (double e = 0.01; e < 50; e *= 1.3) {
        sf_contensou(e, &f, &t);
        assert_true(f > fp && t < tp);
        fp = f;
        tp = t;
    }
}

/* The fast wrench loop: the scaled speeds make the wrench a
 * function of the slip direction field only, so scaling (u, v, w) by a
 * power of two gives the same bits (no overflow at 2^900, no underflow at
 * 2^-1000); it agrees with the cell-by-cell hypot loop written here from
 * the public quadrature; a cell on the pole (Cartesian, odd cells, pure
 * spin) adds nothing instead of a NaN; clamped look-ups are counted. */
static void reference_wrench(const sf_contact *c, double xb, double yb, double u, double v, double w, double q[3])
{
    const double *rx, *ry, *wt;
    sf_contact_cells(c, &rx, &ry, &wt);
    q[0] = q[1] = q[2] = 0;
    for (size_t i = 0; i < sf_contact_ncells(c); i++) {
        double vx = u - w * ry[i], vy = v + w * rx[i], sp = hypot(vx, vy);
        if (sp == 0)
            continue;
        double a = wt[i] * sf_cof_eval(sf_contact_get_cof(c), xb + rx[i], yb + ry[i]);
        q[0] -= a * vx / sp;
        q[1] -= a * vy / sp;
        q[2] -= a * (rx[i] * vy - ry[i] * vx) / sp;
    }
}

/* The fast loop's bits, written out scalar: cell i into lane i mod 8 with
 * the scaled speeds (u, v, w) 2^-e of sf_contact_wrench, the COF from
 * sf_cof_eval (on the grid the same bits as the loop's inlined look-up),
 * 1/sqrt, the lanes summed in order.  Every copy of the loop (the AVX-512
 * one with its look-up by pairs on machines that have it, the portable one
 * elsewhere and in the coverage build) must give exactly these bits. */
static void lanes_wrench(const sf_contact *c, double xb, double yb, double u, double v, double w, double q[3])
{
    const double *rx, *ry, *wt;
    sf_contact_cells(c, &rx, &ry, &wt);
    int e = INT_MIN;
    if (u != 0)
        e = ilogb(u) + 1;
    if (v != 0 && ilogb(v) + 1 > e)
        e = ilogb(v) + 1;
    if (w != 0 && ilogb(w) + ilogb(sf_contact_radius(c)) + 2 > e)
        e = ilogb(w) + ilogb(sf_contact_radius(c)) + 2;
    double us = ldexp(u, -e), vs = ldexp(v, -e), ws = ldexp(w, -e), f[3][8] = { { 0 } };
    for (size_t i = 0; i < sf_contact_ncells(c); i++) {
        double ax = us - ws * ry[i], ay = vs + ws * rx[i], s2 = ax * ax + ay * ay;
        double r = 1 / sqrt(s2), a = wt[i] * sf_cof_eval(sf_contact_get_cof(c), xb + rx[i], yb + ry[i]);
        double dx = ax * r, dy = ay * r;
        f[0][i % 8] -= a * dx;
        f[1][i % 8] -= a * dy;
        f[2][i % 8] -= a * (rx[i] * dy - ry[i] * dx);
    }
    for (int k = 0; k < 3; k++) {
        q[k] = 0;
        for (int l = 0; l < 8; l++)
            q[k] += f[k][l];
    }
}

static void wrench_fast_loop(void **state)
{
    (void)state;
    enum { M = 40 };
    double g[M * M];
    for (int j = 0; j < M; j++)
        for (int i = 0; i < M; i++)
            g[i + M * j] = 0.5 + 0.1 * sin(0.7 * i) * cos(0.4 * j);
    sf_cof *cof;
    assert_int_equal(sf_cof_alloc_grid(M, M, -1, -1, 2.0 / (M - 1), 2.0 / (M - 1), g, &cof), SF_SUCCESS);
    sf_contact_spec spec = { 0.5, 98.1, SF_LAYOUT_POLAR, 13 };
    sf_contact *c;
    assert_int_equal(sf_contact_alloc(&spec, cof, &c), SF_SUCCESS);
    double q[3], r[3], k[3];
    const double mv[][3] = { { -0.2, 0.05, 0.3 }, { 0.1, 0, -2 }, { 0, 0, 1 }, { 1e-3, -2e-3, 0 } };
    for (size_t t = 0; t < sizeof mv / sizeof mv[0]; t++) {
        double u = mv[t][0], v = mv[t][1], w = mv[t][2];
        sf_contact_wrench(c, 0.1, -0.05, u, v, w, 1, q);
        reference_wrench(c, 0.1, -0.05, u, v, w, r);
        for (int i = 0; i < 3; i++)
            assert_close(q[i], r[i], 1e-12 * 98.1);
        lanes_wrench(c, 0.1, -0.05, u, v, w, r);
        for (int i = 0; i < 3; i++)
            assert_true(q[i] == r[i]);   /* the same bits */
        const int ex[] = { -1000, -500, 500, 900 };
        for (int e = 0; e < 4; e++) {
            sf_contact_wrench(c, 0.1, -0.05, ldexp(u, ex[e]), ldexp(v, ex[e]), ldexp(w, ex[e]), 1, k);
            for (int i = 0; i < 3; i++)
                assert_true(k[i] == q[i]);   /* the same bits */
        }
    }
    assert_int_equal(sf_cof_outside(cof), 0);
    {   /* the disc-averaged COF: on the grid the same bits as the sum of sf_cof_eval, in its order;
           over the edge too (clamped look-ups, counted) */
        const double *rx, *ry, *wt;
        sf_contact_cells(c, &rx, &ry, &wt);
        const double at[][2] = { { 0.1, -0.05 }, { 0.9, 0 } };
        for (int a = 0; a < 2; a++) {
            double sum = 0;
            for (size_t i = 0; i < sf_contact_ncells(c); i++)
                sum += wt[i] * sf_cof_eval(cof, at[a][0] + rx[i], at[a][1] + ry[i]);
            unsigned long out0 = sf_cof_outside(cof);
            assert_true(sf_contact_mean_cof(c, at[a][0], at[a][1]) == sum / 98.1);
            assert_true(a ? sf_cof_outside(cof) > out0 : sf_cof_outside(cof) == 0);
        }
    }
    sf_contact_wrench(c, 0.9, 0, -0.2, 0, 0.3, 1, q);   /* the disc hangs over the grid's edge */
    assert_true(sf_cof_outside(cof) > 0);
    reference_wrench(c, 0.9, 0, -0.2, 0, 0.3, r);
    for (int i = 0; i < 3; i++)
        assert_close(q[i], r[i], 1e-12 * 98.1);
    sf_contact_free(c);
    /* a cell on the pole: Cartesian, 9 cells across (one at the centre), pure spin */
    sf_contact_spec cs = { 0.5, 98.1, SF_LAYOUT_CARTESIAN, 9 };
    assert_int_equal(sf_contact_alloc(&cs, cof, &c), SF_SUCCESS);
    sf_contact_wrench(c, 0, 0, 0, 0, 1.5, 1, q);
    reference_wrench(c, 0, 0, 0, 0, 1.5, r);
    for (int i = 0; i < 3; i++) {
        assert_true(isfinite(q[i]));
        assert_close(q[i], r[i], 1e-12 * 98.1);
    }
    sf_contact_free(c);
    sf_cof_free(cof);
}

static void wrench_and_margins(void **state)
{
    (void)state;
    sf_cof *cof;
    sf_cof_alloc_uniform(0.4, &cof);
    sf_contact *c = (sf_contact *)1;
    sf_contact_spec bad = { -1, 10, SF_LAYOUT_POLAR, 8 };
    assert_int_equal(sf_contact_alloc(&bad, cof, &c), SF_EINVAL);
    assert_null(c);
    bad.R = 0.5;
    bad.cells = 0;
    assert_int_equal(sf_contact_alloc(&bad, cof, &c), SF_EINVAL);
    sf_contact_spec spec = { 0.5, 10, SF_LAYOUT_POLAR, 8 };
    assert_int_equal(sf_contact_alloc(&spec, cof, &c), SF_SUCCESS);
    double q[3];
    assert_int_equal(sf_contact_wrench(c, 0, 0, NAN, 0, 0, 1, q), SF_EINVAL);
    assert_int_equal(sf_contact_wrench(c, 0, 0, 0, 0, 0, 1, q), SF_SUCCESS);   /* no slip: no force */
    assert_close(q[0], 0, 0);
    assert_close(q[2], 0, 0);
    sf_contact_wrench(c, 0, 0, -0.3, 0, 0, 0.9, q);
    assert_close(q[0], 0.9 * 0.4 * 10, 1e-14);
    assert_close(sf_contact_mean_cof(c, 5, 5), 0.4, 0);
    double m0, m1;
    assert_int_equal(sf_contact_stick_margin(c, 0, 0, 1.0, 2.0, 0, &m0), SF_SUCCESS);
    assert_int_equal(sf_contact_stick_margin(c, 0, 0, 1.0, 2.0, 1, &m1), SF_SUCCESS);
    assert_close(m0, 4 - hypot(1, 2), 1e-14);
    assert_close(m1, m0, 1e-12);   /* uniform: the section is the circle */
    assert_int_equal(sf_contact_stick_margin(c, 0, 0, INFINITY, 0, 0, &m0), SF_EINVAL);
    assert_int_equal(sf_contact_stick_margin(c, 0, 0, INFINITY, 0, 1, &m0), SF_EINVAL);
    assert_true(isnan(m0));
    sf_surface *s;
    assert_int_equal(sf_surface_alloc(c, 0, 0, &s), SF_SUCCESS);
    /* on a surface the caller keeps: the same margin as a fresh one's */
    assert_int_equal(sf_surface_stick_margin(s, c, 0, 0, 1.0, 2.0, &m0), SF_SUCCESS);
    assert_close(m0, m1, 0);
    assert_int_equal(sf_surface_stick_margin(s, c, 0, 0, NAN, 2.0, &m0), SF_EINVAL);
    assert_true(isnan(m0));
    double th, p[3];
    assert_int_equal(sf_surface_section(s, 0.7, &th, p), SF_SUCCESS);
    assert_close(th, 0, 1e-12);
    assert_close(hypot(p[0], p[1]), 0.4, 1e-13);
    sf_surface_free(s);
    sf_contact_free(c);
    /* zero COF: the surface degenerates to the origin without failing */
    sf_cof_free(cof);
    sf_cof_alloc_uniform(0, &cof);
    sf_contact_alloc(&spec, cof, &c);
    sf_surface_alloc(c, 0, 0, &s);
    double rho;
    assert_int_equal(sf_surface_section_radius(s, 1.0, &rho, NULL), SF_SUCCESS);
    assert_close(rho, 0, 0);
    assert_int_equal(sf_surface_section(s, 1.0, &th, p), SF_SUCCESS);
    sf_surface_free(s);
    sf_contact_free(c);
    sf_cof_free(cof);
}

/* On a field with a linear COF gradient, the exact section lies inside
 * the equatorial circle and the margins order accordingly. */
static void section_inside_circle(void **state)
{
    (void)state;
    double g[9];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++)
            g[i + 3 * j] = 0.5 + 0.2 * (i - 1);
    sf_cof *cof;
    sf_cof_alloc_grid(3, 3, -1, -1, 1, 1, g, &cof);
    sf_contact_spec spec = { 0.5, 10, SF_LAYOUT_POLAR, 16 };
    sf_contact *c;
    sf_contact_alloc(&spec, cof, &c);
    double m0, m1;
    sf_contact_stick_margin(c, 0, 0, 0.0, 3.0, 0, &m0);
    sf_contact_stick_margin(c, 0, 0, 0.0, 3.0, 1, &m1);
    assert_close(m0, 2.0, 1e-12);
    assert_true(m1 < m0 && m1 > 0);
    sf_contact_free(c);
    sf_cof_free(cof);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cof_bilinear),
        cmocka_unit_test(cof_invalid),
        cmocka_unit_test(cof_plan),
        cmocka_unit_test(contensou),
        cmocka_unit_test(wrench_and_margins),
        cmocka_unit_test(wrench_fast_loop),
        cmocka_unit_test(section_inside_circle),
    };
    return cmocka_run_group_tests_name("contact", tests, NULL, NULL);
}
