/* The cell-averaged COF (solver/field/cellavg.h): limits of the box terms, the
 * plan's choice, the effective field's embedding, and the oscillator's
 * refusal of a COF whose boxes are not its cells. */
#include "test_util.h"
#include "cellavg.h"
#include "cof.h"
#include "contact.h"
#include "field.h"
#include "numplan.h"
#include "oscillator.h"
#include "scene.h"
#include "sf_error.h"

#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

static void box_limits(void **state)
{
    (void)state;
    sf_cellavg c;
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0.01, 1e-6), SF_SUCCESS);
    /* a box much smaller than l: the point covariance exp(-n d^2/l^2) */
    for (int n = 1; n <= 3; n++)
        for (double d = 0; d < 0.03; d += 0.0037)
            assert_close(sf_cellavg_box1(&c, n, d), exp(-n * d * d / 1e-4), 1e-6);
    /* a box much larger than l: the triangle (1 - |d|/h) sqrt(pi) l / (sqrt(n) h) */
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0.01, 1.0), SF_SUCCESS);
    for (double d = 0; d < 0.9; d += 0.1)
        assert_close(sf_cellavg_box1(&c, 2, d), M_SQRTPI * 0.01 / sqrt(2.0) * (1 - d), 1e-3);
    /* even in d; the erf and erfc branches meet at d = h */
    assert_close(sf_cellavg_box1(&c, 1, -0.3), sf_cellavg_box1(&c, 1, 0.3), 1e-15);
    assert_close(sf_cellavg_box1(&c, 1, 1 - 1e-12), sf_cellavg_box1(&c, 1, 1 + 1e-12), 1e-9);
    /* the series: Cov(0) of the point field is mubar^2 (exp(sG^2) - 1) =
     * std^2; a box of l/100 lowers it by ~(h/l)^2/6 (and the closed form
     * carries ~1e-16 (l/h)^2 of round-off: cellavg.h) */
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0.01, 1e-4), SF_SUCCESS);
    assert_close(sf_cellavg_var(&c), 0.01, 1e-4);
    assert_true(sf_cellavg_var(&c) < 0.01);
    assert_close(sf_cellavg_corr(0, 0, &c), 1, 1e-15);
    assert_true(sf_cellavg_support(&c) > 0);
    assert_int_equal(sf_cellavg_init(&c, 0, 0.1, 0.01, 1), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0.01, NAN), SF_EINVAL);
}

static void plan_choice(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    size_t n = 0;
    double box = 0;
    s.l = 0.005;   /* l/R = 0.01: cell averages, the fewest cells whose predicted error is within 3/4 qoi_tol */
    assert_int_equal(sf_numplan_cell_average(&s, &n, &box), 1);
    assert_true(n >= SF_PLAN_CELLAVG_CELLS && n <= SF_PLAN_CELLAVG_MAX_CELLS);
    assert_true(sf_numplan_err_cell(&s, n) <= 0.75 * s.qoi_tol);
    assert_true(n == SF_PLAN_CELLAVG_CELLS ||
                sf_numplan_err_cell(&s, n - 1) > 0.75 * s.qoi_tol);
    assert_close(box, 2 * s.R / (double)n, 1e-15);
    s.l = 0.0158;   /* l/R = 0.0316: more cells */
    assert_int_equal(sf_numplan_cell_average(&s, &n, &box), 1);
    assert_true(n > SF_PLAN_CELLAVG_CELLS && n <= SF_PLAN_CELLAVG_MAX_CELLS);
    assert_true(sf_numplan_err_cell(&s, n) <= 0.75 * s.qoi_tol);
    /* the belt-speed number and the CV scale err_cell from their knees on (numplan.c): Table 1 sits below both */
    sf_scene t = s;
    double e1 = sf_numplan_err_cell(&t, 40);
    assert_true(sf_numplan_belt_number(&t) < 0.08);
    t.v_b = 0.4 / sqrt(3.0) * 0.5 * 9.81 * 0.4;   /* beta = 0.16: twice the knee */
    assert_close(sf_numplan_belt_number(&t), 0.16, 1e-12);
    assert_close(sf_numplan_err_cell(&t, 40), 2 * e1, 1e-12);
    t = s;
    t.mu_std = 0.4;   /* CV 0.8: 4x the CV, 4^1.3 the error */
    assert_close(sf_numplan_err_cell(&t, 40), e1 * pow(4.0, 1.3), 1e-12);
    t.mu_std = 0.025;   /* CV 0.05: linear below the knee */
    assert_close(sf_numplan_err_cell(&t, 40), e1 / 4, 1e-12);
    s.T = 2000;   /* the effective strip over [0, T] above 2^22 points: the point model's tiles */
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
    s.T = 100;
    s.l = 0.05;   /* l/R = 0.1: point values, whatever the tolerance */
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
    s.l = 0.005;
    s.shortcuts = 0;   /* the full computation */
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
    s.shortcuts = 1;
    s.cells = 40;   /* cells set: they are the point model's */
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
    s.cof_model = SF_COFMODEL_CELL;   /* explicit: cells per diameter */
    assert_int_equal(sf_numplan_cell_average(&s, &n, NULL), 1);
    assert_int_equal(n, 40);
    s.cof_model = SF_COFMODEL_POINT;
    s.cells = 0;
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
    s.cof_model = SF_COFMODEL_AUTO;
    s.cof = SF_COF_UNIFORM;
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
}

static void effective_field(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.l = 0.005;
    s.T = 5;
    s.strip_halfwidth = 0.01;
    sf_cof_plan *p;
    char err[256] = "";
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
    size_t nc = 0;
    assert_int_equal(sf_numplan_cell_average(&s, &nc, NULL), 1);   /* the plan's cells per diameter */
    assert_close(in->box, 2 * s.R / (double)nc, 1e-15);
    assert_close(in->dx, in->box / 3, 1e-15);
    sf_field *f = sf_cof_plan_cell_field(p);
    assert_non_null(f);
    const sf_field_info *fi = sf_field_get_info(f);
    assert_true(isnan(fi->cov_error));   /* deferred: a run only samples */
    double *cv = malloc(in->nx * in->ny * sizeof *cv);
    assert_non_null(cv);
    assert_int_equal(sf_field_covariance(f, cv), SF_EINVAL);
    assert_int_equal(sf_field_measure_covariance(f), SF_SUCCESS);
    assert_int_equal(sf_field_measure_covariance(f), SF_SUCCESS);   /* once */
    assert_true(fi->cov_error < 1e-13);
    assert_int_equal(sf_field_covariance(f, cv), SF_SUCCESS);
    assert_close(cv[0], 1, 1e-13);
    free(cv);
    assert_true(fi->px < 2 * (in->nx - 1));   /* the short-support period */
    assert_close(sf_field_target(f, 0, 0), 1, 1e-15);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *c;
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_close(sf_cof_box(c), in->box, 0);
    /* the oscillator runs the matching Cartesian quadrature ... */
    sf_osc *o;
    assert_int_equal(sf_osc_alloc(&s, c, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_get_plan(o)->cell_average, 1);
    assert_int_equal(sf_osc_get_plan(o)->layout, SF_LAYOUT_CARTESIAN);
    FILE *fp = tmpfile();   /* --explain names the cell-averaged COF */
    assert_non_null(fp);
    sf_osc_explain(o, fp);
    rewind(fp);
    char out[8192];
    size_t len = fread(out, 1, sizeof out - 1, fp);
    out[len] = '\0';
    fclose(fp);
    assert_non_null(strstr(out, "Cartesian quadrature"));
    assert_non_null(strstr(out, "cell-averaged COF interpolated from the effective strip field"));
    sf_osc_free(o);
    /* ... and refuses a COF whose boxes are not its cells, or point values */
    sf_scene s2 = s;
    s2.cof_model = SF_COFMODEL_CELL;
    s2.cells = 40;
    assert_int_equal(sf_osc_alloc(&s2, c, &o, err, sizeof err), SF_EINVAL);
    s2.cof_model = SF_COFMODEL_POINT;
    s2.cells = 0;
    assert_int_equal(sf_osc_alloc(&s2, c, &o, err, sizeof err), SF_EINVAL);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    /* precorrect is refused with cell averages set explicitly */
    s.cof_model = SF_COFMODEL_CELL;
    s.precorrect = 1;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_EINVAL);
    gsl_rng_free(rng);
}

/* sf_cellavg_init refuses each argument that is not a positive finite
 * number (std: non-negative); std = 0 has no series (a constant COF); a
 * huge CV keeps 64 terms, whose sum is still the point variance std^2 for
 * a box much smaller than l (the terms peak near n = sG^2 and the 64th is
 * ~1e-15 of the peak at CV = 1e4: the cap costs nothing there). */
/* The belt noise's box filter (sf_cellavg_cubic_weights): n = 2E + 1
 * weights, E = floor(beta/2) + 2, symmetric, summing to 1, the box
 * average of x^2 exact (the cubic interpolant); refusals. */
static void cubic_weights(void **state)
{
    assert_int_equal(sf_cellavg_cubic_weights(0, NULL, 0), 0);      /* no box */
    assert_int_equal(sf_cellavg_cubic_weights(NAN, NULL, 0), 0);
    assert_int_equal(sf_cellavg_cubic_weights(2e6, NULL, 0), 0);    /* a filter of millions of taps refused */
    (void)state;
    const double betas[] = { 0.5, 1, 2.83, 4.3, 8.678, 17.4, 40 };
    for (size_t k = 0; k < sizeof betas / sizeof betas[0]; k++) {
        double b = betas[k], w[64];
        size_t n = sf_cellavg_cubic_weights(b, NULL, 0), E = (size_t)floor(b / 2) + 2;
        assert_int_equal(n, 2 * E + 1);
        assert_int_equal(sf_cellavg_cubic_weights(b, w, 64), n);
        double s0 = 0, s2 = 0;
        for (size_t i = 0; i < n; i++) {
            double x = (double)i - (double)E;
            s0 += w[i];
            s2 += w[i] * x * x;
            assert_close(w[i], w[n - 1 - i], 1e-15);
        }
        assert_close(s0, 1, 1e-14);
        assert_close(s2, b * b / 12, 1e-13);
    }
    double w[4];
    assert_int_equal(sf_cellavg_cubic_weights(10, w, 4), 0);   /* cap too small */
    assert_int_equal(sf_cellavg_cubic_weights(0, NULL, 0), 0);
    assert_int_equal(sf_cellavg_cubic_weights(NAN, NULL, 0), 0);
}

static void cellavg_init_edges(void **state)
{
    (void)state;
    sf_cellavg c;
    assert_int_equal(sf_cellavg_init(&c, 0.5, -0.1, 0.01, 0.1), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0, 0.1), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0.01, 0), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, INFINITY, 0.1, 0.01, 0.1), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, INFINITY, 0.01, 0.1), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, INFINITY, 0.1), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0.1, 0.01, INFINITY), SF_EINVAL);
    assert_int_equal(sf_cellavg_init(&c, 0.5, 0, 0.01, 0.1), SF_SUCCESS);
    assert_int_equal(c.nterms, 0);
    assert_close(sf_cellavg_var(&c), 0, 0);
    assert_int_equal(sf_cellavg_init(&c, 1, 1e4, 0.01, 1e-8), SF_SUCCESS);
    assert_int_equal(c.nterms, 64);
    assert_close(sf_cellavg_var(&c), 1e8, 1e-6);
}

/* sf_cof_set_box marks a grid's values as cell averages; anything but a
 * grid, and a box that is not a finite non-negative length, is refused
 * (the COF is left as it was). */
static void cof_box_marks(void **state)
{
    (void)state;
    sf_cof *c;
    assert_int_equal(sf_cof_alloc_uniform(0.5, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_set_box(c, 0.1), SF_EINVAL);
    assert_close(sf_cof_box(c), 0, 0);
    sf_cof_free(c);
    double g[4] = { 0.4, 0.5, 0.6, 0.7 };
    assert_int_equal(sf_cof_alloc_grid(2, 2, 0, 0, 1, 1, g, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_set_box(c, -0.1), SF_EINVAL);
    assert_int_equal(sf_cof_set_box(c, NAN), SF_EINVAL);
    assert_int_equal(sf_cof_set_box(c, INFINITY), SF_EINVAL);
    assert_close(sf_cof_box(c), 0, 0);
    assert_int_equal(sf_cof_set_box(c, 0.1), SF_SUCCESS);
    assert_close(sf_cof_box(c), 0.1, 0);
    assert_int_equal(sf_cof_set_box(c, 0), SF_SUCCESS);   /* back to point values */
    assert_close(sf_cof_box(c), 0, 0);
    sf_cof_free(c);
}

/* the cell-average scene of effective_field: l/R = 0.01, a short belt */
static void scene_cellavg(sf_scene *s)
{
    sf_scene_default(s);
    s->l = 0.005;
    s->T = 5;
    s->strip_halfwidth = 0.01;
}

/* The cell-average plan's refusals, each before the field is made, and
 * its standard deviation (the series' Var(mu_h); 0 for a point plan). */
static void cellavg_plan_refusals(void **state)
{
    (void)state;
    sf_scene s;
    sf_cof_plan *p = (sf_cof_plan *)1;
    char err[256] = "";
    /* mu_std = 0 with cell averages set and no shortcut: nothing to average */
    scene_cellavg(&s);
    s.cof_model = SF_COFMODEL_CELL;
    s.mu_std = 0;
    s.shortcuts = 0;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_EINVAL);
    assert_null(p);
    assert_non_null(strstr(err, "mu_std > 0"));
    /* l = 0 (the scene parser refuses it; the API must too): no series */
    scene_cellavg(&s);
    s.cof_model = SF_COFMODEL_CELL;
    s.cells = 32;
    s.l = 0;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_EINVAL);
    assert_null(p);
    assert_non_null(strstr(err, "invalid cell-average model"));
    /* a belt of 2 km: the effective strip over 2^24 points, refused
     * before anything is allocated */
    scene_cellavg(&s);
    s.cof_model = SF_COFMODEL_CELL;
    s.cells = 56;
    s.T = 1e4;
    s.strip_halfwidth = 0;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_ETOOBIG);
    assert_null(p);
    assert_non_null(strstr(err, "cell-averaged belt strip"));
    /* the plan's std: sqrt(Var(mu_h)) of the same series; 0 for points */
    scene_cellavg(&s);
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    sf_cellavg ca;
    assert_int_equal(sf_cellavg_init(&ca, s.mu_mean, s.mu_std, s.l, sf_cof_plan_get_info(p)->box), SF_SUCCESS);
    assert_close(sf_cof_plan_cell_std(p), sqrt(sf_cellavg_var(&ca)), 0);
    assert_true(sf_cof_plan_cell_std(p) < s.mu_std);   /* averaging lowers the variance */
    sf_cof_plan_free(p);
    s.cof_model = SF_COFMODEL_POINT;
    s.l = 0.25;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_null(sf_cof_plan_cell_field(p));
    assert_close(sf_cof_plan_cell_std(p), 0, 0);
    sf_cof_plan_free(p);
    /* auto generator with precorrect but nothing to pre-correct (mu_std
     * = 0, no shortcut, so no cell averages either) on a strip over the
     * tiles' threshold: the tiles (only the window's size is planned) */
    scene_cellavg(&s);
    s.precorrect = 1;
    s.mu_std = 0;
    s.shortcuts = 0;
    s.strip_halfwidth = 0.5;
    s.T = 100;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_TILES);
    assert_null(sf_cof_plan_cell_field(p));
    sf_cof_plan_free(p);
}

/* The plan's cell-average branches: set explicitly where no count
 * suffices (the largest, with a warning), chosen on a constant COF (not:
 * nothing to average), the out pointers optional; and what --explain
 * prints for both origins. */
static void cellavg_plan_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.l = 0.25;   /* l/R = 0.5: the model's error is above qoi_tol at any count */
    s.cof_model = SF_COFMODEL_CELL;
    size_t n = 0;
    double box = 0;
    assert_int_equal(sf_numplan_cell_average(&s, &n, &box), 1);
    assert_int_equal(n, SF_PLAN_CELLAVG_MAX_CELLS);
    assert_close(box, 2 * s.R / (double)n, 1e-15);
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 1);
    sf_numplan pl;
    char err[256] = "", out[4096];
    assert_int_equal(sf_numplan_make(&s, 1, &pl, err, sizeof err), SF_SUCCESS);
    assert_int_equal(pl.cell_average, 1);
    assert_int_equal(pl.cof_model_from, SF_PLAN_SCENE);
    assert_int_equal(pl.cells_from, SF_PLAN_CHOSEN);
    assert_true(pl.err_quad > 0.75 * s.qoi_tol);
    assert_non_null(strstr(pl.warning, "cof_model = point resolves l"));
    FILE *f = tmpfile();
    assert_non_null(f);
    sf_numplan_explain(&pl, f);
    rewind(f);
    size_t len = fread(out, 1, sizeof out - 1, f);
    out[len] = '\0';
    fclose(f);
    assert_non_null(strstr(out, "cof_model = cell_average (set by the scene)"));
    char want[64];
    snprintf(want, sizeof want, "cells = %d per diameter (chosen for qoi_tol", SF_PLAN_CELLAVG_MAX_CELLS);
    assert_non_null(strstr(out, want));
    assert_non_null(strstr(out, "plan warning: cof_model = cell_average"));
    /* chosen by auto at l/R = 0.01, cells set by the scene (40) */
    s.l = 0.005;
    s.cof_model = SF_COFMODEL_AUTO;
    assert_int_equal(sf_numplan_make(&s, 1, &pl, err, sizeof err), SF_SUCCESS);
    assert_int_equal(pl.cof_model_from, SF_PLAN_CHOSEN);
    /* the fewest cells whose predicted error is within 3/4 of qoi_tol (59 at Table 1 since the model's floor) */
    assert_in_range(pl.cells, SF_PLAN_CELLAVG_CELLS, SF_PLAN_CELLAVG_MAX_CELLS);
    assert_true(sf_numplan_err_cell(&s, pl.cells) <= 0.75 * s.qoi_tol);
    if (pl.cells > SF_PLAN_CELLAVG_CELLS)
        assert_true(sf_numplan_err_cell(&s, pl.cells - 1) > 0.75 * s.qoi_tol);
    assert_string_equal(pl.warning, "");
    f = tmpfile();
    assert_non_null(f);
    sf_numplan_explain(&pl, f);
    rewind(f);
    len = fread(out, 1, sizeof out - 1, f);
    out[len] = '\0';
    fclose(f);
    assert_non_null(strstr(out, "cof_model = cell_average (chosen: l/R below 0.05"));
    /* auto on a field without spread: point values (nothing to average) */
    s.mu_std = 0;
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
}

/* The oscillator refuses point values where the plan runs cell averages
 * (the converse of effective_field's refusals), and explains a point
 * field's quadrature as such. */
static void osc_point_values_refused(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.l = 0.005;   /* auto: cell averages */
    double g[21 * 21];
    for (int i = 0; i < 21 * 21; i++)
        g[i] = 0.5 + 0.01 * (i % 7);
    sf_cof *c;
    assert_int_equal(sf_cof_alloc_grid(21, 21, -1, -1, 0.1, 0.1, g, &c), SF_SUCCESS);
    sf_osc *o = (sf_osc *)1;
    char err[256] = "";
    assert_int_equal(sf_osc_alloc(&s, c, &o, err, sizeof err), SF_EINVAL);
    assert_null(o);
    assert_non_null(strstr(err, "the COF holds point values (box 0 m) but the plan runs cof_model = cell_average"));
    s.cof_model = SF_COFMODEL_POINT;
    s.cells = 8;
    assert_int_equal(sf_osc_alloc(&s, c, &o, err, sizeof err), SF_SUCCESS);
    FILE *f = tmpfile();
    assert_non_null(f);
    sf_osc_explain(o, f);
    rewind(f);
    char out[8192];
    size_t len = fread(out, 1, sizeof out - 1, f);
    out[len] = '\0';
    fclose(f);
    assert_non_null(strstr(out, "COF interpolated from the strip field"));
    assert_null(strstr(out, "cell-averaged"));
    sf_osc_free(o);
    sf_cof_free(c);
}

/* The separable-sum kernel's embedding (field.h): a support longer than
 * the axis keeps the usual minimal period, an axis of one point has
 * period 1, and a term count without its factor function is refused
 * (it was dereferenced: the spec was accepted when l was valid). */
static void sep_sum_embedding(void **state)
{
    (void)state;
    sf_cellavg ca;
    double box = 0.03125, d = box / 3;
    assert_int_equal(sf_cellavg_init(&ca, 0.5, 0.1, 0.005, box), SF_SUCCESS);
    sf_field_spec sp;
    sf_field_spec_default(&sp, 10, 1, d, d, 0.005);
    sp.sep_terms = ca.nterms;
    sp.sep_fn = sf_cellavg_septerm;
    sp.sep_params = &ca;
    sp.support = sf_cellavg_support(&ca);   /* 0.076 m: 7 spacings, longer than the axis of 9 */
    sf_field *f;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_SUCCESS);
    const sf_field_info *fi = sf_field_get_info(f);
    assert_int_equal(fi->px, 18);   /* 2 (m - 1): the support does not shorten it */
    assert_int_equal(fi->py, 1);
    assert_true(fi->cov_error < 1e-13);
    sf_field_free(f);
    /* a longer axis: the short-support period (2 S with S = support/d + 1) */
    sp.m = 200;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_SUCCESS);
    fi = sf_field_get_info(f);
    assert_true(fi->px < 2 * 199);
    assert_true(fi->cov_error < 1e-13);
    sf_field_free(f);
    /* a 2-D grid: the eigenvalues from the 1-D spectra equal the direct
     * 2-D DFT of the first row to round-off (relative to lambda_max) */
    sp.m = 40;
    sp.n = 12;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_SUCCESS);
    fi = sf_field_get_info(f);
    size_t px = fi->px, py = fi->py, M = px * py;
    double *row = malloc(M * sizeof *row), *lam = malloc(M * sizeof *lam);
    assert_non_null(row);
    assert_non_null(lam);
    assert_int_equal(sf_field_first_row(f, row), SF_SUCCESS);
    assert_int_equal(sf_field_eigenvalues(f, lam), SF_SUCCESS);
    double worst = 0;
    for (size_t ky = 0; ky < py; ky++)
        for (size_t kx = 0; kx < px; kx++) {
            double d = 0;
            for (size_t j = 0; j < py; j++)
                for (size_t i = 0; i < px; i++)
                    d += row[i + px * j] * cos(2 * M_PI * ((double)(i * kx % px) / (double)px +
                                                           (double)(j * ky % py) / (double)py));
            worst = fmax(worst, fabs(d - lam[kx + px * ky]));
        }
    assert_true(worst <= 1e-13 * fi->lambda_max);
    for (size_t ky = 0; ky < py; ky++)   /* exactly even, bit for bit: the real sampler's draw needs it */
        for (size_t kx = 0; kx < px; kx++)
            assert_memory_equal(&lam[kx + px * ky], &lam[(px - kx) % px + px * ((py - ky) % py)], sizeof *lam);
    free(row);
    free(lam);
    sf_field_free(f);
    /* the real sampler: separable-sum kernels only; one field per draw */
    sf_field_spec rs = sp;
    rs.sample_real = 1;
    rs.sep_terms = 0;
    f = (sf_field *)1;
    assert_int_equal(sf_field_alloc(&rs, &f), SF_EINVAL);
    assert_null(f);
    rs.sep_terms = sp.sep_terms;
    rs.defer_covariance = 1;
    assert_int_equal(sf_field_alloc(&rs, &f), SF_SUCCESS);
    double *a = malloc(rs.m * rs.n * sizeof *a), *b = malloc(rs.m * rs.n * sizeof *b);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    assert_int_equal(sf_field_sample(f, rng, a), SF_EINVAL);
    assert_int_equal(sf_field_sample_pair(f, rng, a, b), SF_EINVAL);
    assert_int_equal(sf_field_sample_fresh(NULL, rng, a), SF_EINVAL);
    assert_int_equal(sf_field_sample_fresh(f, NULL, a), SF_EINVAL);
    assert_int_equal(sf_field_sample_fresh(f, rng, NULL), SF_EINVAL);
    assert_int_equal(sf_field_sample_fresh(f, rng, a), SF_SUCCESS);
    assert_int_equal(sf_field_measure_covariance(NULL), SF_EINVAL);
    assert_int_equal(sf_field_covariance(f, b), SF_EINVAL);   /* deferred */
    assert_int_equal(sf_field_measure_covariance(f), SF_SUCCESS);
    assert_true(sf_field_get_info(f)->cov_error < 1e-13);
    assert_int_equal(sf_field_covariance(f, b), SF_SUCCESS);
    assert_close(b[0], 1, 1e-13);
    gsl_rng_free(rng);
    free(a);
    free(b);
    sf_field_free(f);
    sp.sep_fn = NULL;
    f = (sf_field *)1;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_EINVAL);
    assert_null(f);
    sp.kernel = NULL;
    sp.l = NAN;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_EINVAL);
}

/* A plan whose embedding reached its padding cap says so (the run and
 * sweep commands warn on it); one at the default cap does not. */
static void plan_truncation(void **state)
{
    (void)state;
    sf_scene s;
    sf_cof_plan *p;
    char err[256] = "";
    sf_scene_default(&s);
    s.l = 50;   /* l/R = 100: a strip of a few l, an embedding that needs padding */
    s.T = 12;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_truncated(p), 0);
    sf_cof_plan_free(p);
    s.pad_cap = 1;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);   /* usable */
    assert_int_equal(sf_cof_plan_truncated(p), 1);
    sf_cof_plan_free(p);
    scene_cellavg(&s);   /* the cell-averaged strip's embedding, the same */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_truncated(p), 0);
    sf_cof_plan_free(p);
    s.cof_model = SF_COFMODEL_CELL;   /* forced at l = 2 m, over a strip shorter than l */
    s.cells = 12;
    s.l = 2;
    s.pad_cap = 1;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_non_null(sf_cof_plan_cell_field(p));
    assert_int_equal(sf_cof_plan_truncated(p), 1);
    sf_cof_plan_free(p);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_limits),
        cmocka_unit_test(plan_choice),
        cmocka_unit_test(effective_field),
        cmocka_unit_test(cubic_weights),
        cmocka_unit_test(cellavg_init_edges),
        cmocka_unit_test(cof_box_marks),
        cmocka_unit_test(cellavg_plan_refusals),
        cmocka_unit_test(cellavg_plan_edges),
        cmocka_unit_test(osc_point_values_refused),
        cmocka_unit_test(sep_sum_embedding),
        cmocka_unit_test(plan_truncation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
