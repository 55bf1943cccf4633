/* Unit tests: the high-level calls (model.h): a model from text, from a
 * file and its refusals; keys set as scene lines; realisation i equal to
 * row i of a sweep to the bit; the workspace's cache; the refusals of a
 * solve. */
#include "test_util.h"
#include "model.h"
#include "montecarlo.h"
#include "sf_error.h"
#include "sweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SHORT "cof = field\nl = 0.5\nT = 20\nt_skip = 10\n"

static void from_text_and_file(void **state)
{
    (void)state;
    char err[300];
    sf_model *m = (sf_model *)1;
    assert_int_equal(sf_model_new(NULL, &m, err, sizeof err), SF_SUCCESS);
    sf_scene d;
    sf_scene_default(&d);
    assert_close(sf_model_scene(m)->l, d.l, 0);   /* Table 1 */
    sf_model_free(m);
    assert_int_equal(sf_model_new("", &m, err, sizeof err), SF_SUCCESS);
    sf_model_free(m);
    m = (sf_model *)1;
    assert_int_equal(sf_model_new("l = -1\n", &m, err, sizeof err), SF_EPARSE);
    assert_null(m);
    assert_non_null(strstr(err, "scene:1"));
    assert_int_equal(sf_model_load("/nonexistent/x.scene", &m, err, sizeof err), SF_EIO);
    assert_null(m);
    FILE *f = fopen("test_model.scene", "w");
    assert_non_null(f);
    fputs(SHORT, f);
    fclose(f);
    assert_int_equal(sf_model_load("test_model.scene", &m, err, sizeof err), SF_SUCCESS);
    assert_close(sf_model_scene(m)->l, 0.5, 0);
    sf_model_free(m);
    remove("test_model.scene");
    sf_model_free(NULL);
    sf_model_ws_free(NULL);
}

static void set_keys(void **state)
{
    (void)state;
    char err[300];
    sf_model *m;
    assert_int_equal(sf_model_new(SHORT, &m, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_model_set(m, "v_b", "0.3", err, sizeof err), SF_SUCCESS);
    assert_close(sf_model_scene(m)->v_b, 0.3, 0);
    assert_int_equal(sf_model_set(m, "cof", "uniform", err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_model_scene(m)->cof, 0);
    assert_int_equal(sf_model_set(m, "l_over_R", "2", err, sizeof err), SF_SUCCESS);
    assert_close(sf_model_scene(m)->l, 2 * sf_model_scene(m)->R, 0);
    /* refusals leave the scene as it was */
    assert_int_equal(sf_model_set(m, "v_b", "-1", err, sizeof err), SF_EPARSE);
    assert_close(sf_model_scene(m)->v_b, 0.3, 0);
    assert_int_equal(sf_model_set(m, "nokey", "1", err, sizeof err), SF_EPARSE);
    assert_int_equal(sf_model_set(m, "l_over_R", "x", err, sizeof err), SF_EPARSE);
    assert_int_equal(sf_model_set(m, "l_over_R", "", err, sizeof err), SF_EPARSE);
    assert_int_equal(sf_model_set(m, "v_b", "0.2\nl = 3", err, sizeof err), SF_EPARSE);   /* one line only */
    assert_int_equal(sf_model_set(m, "v_b = 1 #", "0.2", err, sizeof err), SF_EPARSE);
    char big[600];
    memset(big, '1', sizeof big - 1);
    big[sizeof big - 1] = 0;
    assert_int_equal(sf_model_set(m, "v_b", big, err, sizeof err), SF_EPARSE);
    sf_model_free(m);
}

/* realisation i is row i of a plain sweep, to the bit; twice the same */
static void run_is_sweep_row(void **state)
{
    (void)state;
    char err[300];
    sf_model *m;
    assert_int_equal(sf_model_new(SHORT, &m, err, sizeof err), SF_SUCCESS);
    sf_sweep_point p;
    assert_int_equal(sf_sweep_run(sf_model_scene(m), 3, 1, NULL, 0, NULL, &p, err, sizeof err), SF_SUCCESS);
    for (size_t i = 0; i < 3; i++) {
        double out[SF_MODEL_NOUT], again[SF_MODEL_NOUT];
        assert_int_equal(sf_model_run(m, i, i == 0, out, err, sizeof err), SF_SUCCESS);
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            assert_memory_equal(&out[q], &p.qoi[i * SF_SWEEP_NQ + q], sizeof(double));
            assert_close(out[SF_MODEL_RATIO + q], p.ratio[i * SF_SWEEP_NQ + q], 1e-15);
            assert_true(i == 0 ? isfinite(out[SF_MODEL_U + q]) && out[SF_MODEL_U + q] >= 0
                               : isnan(out[SF_MODEL_U + q]));
        }
        assert_int_equal(sf_model_run(m, i, i == 0, again, err, sizeof err), SF_SUCCESS);   /* the cache's reuse */
        assert_memory_equal(out, again, sizeof out);
    }
    sf_sweep_point_free(&p);
    sf_model_free(m);
}

static void solve_refusals(void **state)
{
    (void)state;
    char err[300];
    sf_model *m;
    assert_int_equal(sf_model_new(SHORT, &m, err, sizeof err), SF_SUCCESS);
    double out[SF_MODEL_NOUT];
    assert_int_equal(sf_model_set(m, "T", "5", err, sizeof err), SF_SUCCESS);   /* T below t_skip */
    assert_int_equal(sf_model_run(m, 0, 1, out, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "t_skip"));
    assert_true(isnan(out[0]));
    /* a reference without an oscillation in the window: the run's values stand, no ratio */
    assert_int_equal(sf_model_set(m, "T", "10.5", err, sizeof err), SF_SUCCESS);
    int rc = sf_model_run(m, 0, 0, out, err, sizeof err);
    assert_int_equal(rc, SF_EINVAL);
    assert_true(isnan(out[SF_MODEL_RATIO]));
    /* a plan that cannot be made */
    assert_int_equal(sf_model_set(m, "T", "20", err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_model_set(m, "qoi_tol", "0.9", err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_model_set(m, "cof_model", "cell_average", err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_model_set(m, "precorrect", "true", err, sizeof err), SF_SUCCESS);   /* cell averages refuse it */
    assert_int_equal(sf_model_run(m, 0, 0, out, err, sizeof err), SF_EINVAL);
    sf_model_free(m);
}

static void estimators_by_name(void **state)
{
    (void)state;
    int by = -1;
    assert_int_equal(sf_model_estimator(NULL, &by), SF_SUCCESS);
    assert_int_equal(by, SF_MODEL_PLAIN);
    assert_int_equal(sf_model_estimator("mlmc-sub", &by), SF_SUCCESS);
    assert_int_equal(by, SF_MODEL_MLMC_SUB);
    assert_int_equal(sf_model_estimator("auto", &by), SF_SUCCESS);
    assert_int_equal(by, SF_MODEL_AUTO);
    assert_int_equal(sf_model_estimator("mlmc2", &by), SF_EINVAL);
    char err[300];
    sf_model_spec sp = { SF_MODEL_PLAIN, 8, 0, NAN, 0, 1, NULL, 0, NULL };
    assert_int_equal(sf_model_spec_check(&sp, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sp.pilot, 0);
    sp.by = 9;
    assert_int_equal(sf_model_spec_check(&sp, err, sizeof err), SF_EINVAL);
    sp.by = SF_MODEL_PLAIN;
    sp.target_se = -1;
    assert_int_equal(sf_model_spec_check(&sp, err, sizeof err), SF_EINVAL);
    sp.target_se = 0.01;
    assert_int_equal(sf_model_spec_check(&sp, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sp.pilot, 8);   /* min(n, 20) */
    sp.control_variate = 1;
    assert_int_equal(sf_model_spec_check(&sp, err, sizeof err), SF_EINVAL);
    sf_model_spec q = { SF_MODEL_MLMC, 40, 0, NAN, 1, 1, NULL, 0, NULL };
    assert_int_equal(sf_model_spec_check(&q, err, sizeof err), SF_EINVAL);   /* paired + control variate */
    q.control_variate = 0;
    q.resume = 1;
    assert_int_equal(sf_model_spec_check(&q, err, sizeof err), SF_EINVAL);
    q.resume = 0;
    assert_int_equal(sf_model_spec_check(&q, err, sizeof err), SF_SUCCESS);
    assert_int_equal(q.pilot, 10);
    q.pilot = 50;
    assert_int_equal(sf_model_spec_check(&q, err, sizeof err), SF_EINVAL);   /* above n */
    q.pilot = 1;
    assert_int_equal(sf_model_spec_check(&q, err, sizeof err), SF_EINVAL);
    sf_model_spec r = { SF_MODEL_PLAIN, 8, 4, NAN, 0, 1, NULL, 0, NULL };
    assert_int_equal(sf_model_spec_check(&r, err, sizeof err), SF_EINVAL);   /* a pilot with plain */
}

/* each estimator's point through the one dispatch: its answer's estimator */
static void points_by_spec(void **state)
{
    (void)state;
    static const struct {
        int by;
        double l, target;
        int cv, est;
    } t[] = {
        { SF_MODEL_PLAIN, 0.5, NAN, 0, SF_EST_PLAIN },
        { SF_MODEL_PLAIN, 0.5, NAN, 1, SF_EST_CV },
        { SF_MODEL_PLAIN, 0.5, 0.05, 0, SF_EST_TARGET },
        { SF_MODEL_MLMC, 0.5, NAN, 0, SF_EST_MLMC },
        { SF_MODEL_MLMC, 0.5, 0.05, 0, SF_EST_MLMC },
        { SF_MODEL_MLMC_SUB, 0.2, NAN, 0, SF_EST_MLMC_SUB },
        { SF_MODEL_MLMC_BOXES, 0.015, NAN, 0, SF_EST_MLMC_BOXES },
        { SF_MODEL_ANTITHETIC, 0.5, NAN, 0, SF_EST_ANTITHETIC },
        { SF_MODEL_AUTO, 0.5, NAN, 0, SF_EST_MLMC },
        { SF_MODEL_AUTO, 0.015, NAN, 0, SF_EST_MLMC_BOXES },
        { SF_MODEL_AUTO, 0.2, NAN, 0, SF_EST_MLMC_SUB },
        { SF_MODEL_AUTO, 5, NAN, 0, SF_EST_ANTITHETIC },
    };
    char err[300];
    for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
        sf_scene s;
        sf_scene_default(&s);
        s.cof = SF_COF_FIELD;
        s.l = t[k].l;
        s.T = 20;
        s.t_skip = 10;
        s.strip_halfwidth = 0.05;
        sf_model_spec sp = { t[k].by, 6, t[k].by == SF_MODEL_PLAIN && isnan(t[k].target) ? 0 : 3, t[k].target,
                             t[k].cv, 1, NULL, 0, NULL };
        assert_int_equal(sf_model_spec_check(&sp, err, sizeof err), SF_SUCCESS);
        sf_sweep_point p;
        int rc = sf_model_point(&s, &sp, k == 0, &p, err, sizeof err);
        if (rc)
            print_error("case %zu: %s\n", k, err);
        assert_int_equal(rc, SF_SUCCESS);
        assert_int_equal(p.estimator, t[k].est);
        sf_sweep_answer a;
        assert_int_equal(sf_sweep_estimate(&p, 0, &a), SF_SUCCESS);
        assert_true(isfinite(a.estimate));
        if (k == 0)
            assert_true(isfinite(a.u_num));
        sf_sweep_point_free(&p);
    }
}

static void sweep_handle(void **state)
{
    (void)state;
    char err[300];
    sf_model *m;
    assert_int_equal(sf_model_new(SHORT "strip_halfwidth = 0.05\n", &m, err, sizeof err), SF_SUCCESS);
    sf_model_spec sp = { SF_MODEL_PLAIN, 4, 0, NAN, 0, 1, NULL, 0, NULL };
    const double v[2] = { 1, 2 };
    sf_model_sweep *w = (sf_model_sweep *)1;
    assert_int_equal(sf_model_sweep_run(m, "l_over_R", v, 2, &sp, &w, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_model_sweep_points(w), 2);
    double f[6], tab[2 * 3 * 6];
    const char *e, *st, *names[2 * 3 * 2];
    assert_int_equal(sf_model_sweep_answer(w, 1, 2, f, &e, &st), SF_SUCCESS);
    assert_string_equal(e, "plain");
    assert_true(f[2] <= f[0] && f[0] <= f[3] && f[5] == 4);
    assert_int_equal(sf_model_sweep_table(w, tab, names), SF_SUCCESS);
    assert_memory_equal(tab + (1 * 3 + 2) * 6, f, sizeof f);
    assert_string_equal(names[2 * (1 * 3 + 2) + 1], st);
    assert_int_equal(sf_model_sweep_answer(w, 2, 0, f, &e, &st), SF_EINVAL);
    assert_int_equal(sf_model_sweep_answer(w, 0, 3, f, &e, &st), SF_EINVAL);
    assert_int_equal(sf_model_sweep_answer(w, 0, -1, f, &e, &st), SF_EINVAL);
    sf_model_sweep_free(w);
    sf_model_sweep_free(NULL);
    /* refusals: the spec, no values, a parameter, a point that fails */
    sp.target_se = -1;
    assert_int_equal(sf_model_sweep_run(m, "l_over_R", v, 2, &sp, &w, err, sizeof err), SF_EINVAL);
    assert_null(w);
    sp.target_se = NAN;
    assert_int_equal(sf_model_sweep_run(m, "l_over_R", v, 0, &sp, &w, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_model_sweep_run(m, "nokey", v, 2, &sp, &w, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "nokey"));
    const double tv[1] = { 5 };   /* T below t_skip: the reference refuses */
    assert_int_equal(sf_model_sweep_run(m, "T", tv, 1, &sp, &w, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "T = 5"));
    sf_model_free(m);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(from_text_and_file),
        cmocka_unit_test(set_keys),
        cmocka_unit_test(run_is_sweep_row),
        cmocka_unit_test(solve_refusals),
        cmocka_unit_test(estimators_by_name),
        cmocka_unit_test(points_by_spec),
        cmocka_unit_test(sweep_handle),
    };
    return cmocka_run_group_tests_name("model", tests, NULL, NULL);
}
