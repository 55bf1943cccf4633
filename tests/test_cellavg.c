/* The cell-averaged COF (solver/cellavg.h): limits of the box terms, the
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
    assert_true(sf_numplan_err_cell(s.l / s.R, s.mu_std / s.mu_mean, n) <= 0.75 * s.qoi_tol);
    assert_true(n == SF_PLAN_CELLAVG_CELLS ||
                sf_numplan_err_cell(s.l / s.R, s.mu_std / s.mu_mean, n - 1) > 0.75 * s.qoi_tol);
    assert_close(box, 2 * s.R / (double)n, 1e-15);
    s.l = 0.0158;   /* l/R = 0.0316: more cells */
    assert_int_equal(sf_numplan_cell_average(&s, &n, &box), 1);
    assert_true(n > SF_PLAN_CELLAVG_CELLS && n <= SF_PLAN_CELLAVG_MAX_CELLS);
    assert_true(sf_numplan_err_cell(s.l / s.R, s.mu_std / s.mu_mean, n) <= 0.75 * s.qoi_tol);
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
    const sf_field *f = sf_cof_plan_cell_field(p);
    assert_non_null(f);
    const sf_field_info *fi = sf_field_get_info(f);
    assert_true(fi->cov_error < 1e-13);
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

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_limits),
        cmocka_unit_test(plan_choice),
        cmocka_unit_test(effective_field),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
