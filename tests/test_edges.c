/* Solver paths no case exercises (coverage of solver/ by make test + the
 * quick tier, `make coverage`): error messages, the scene key table (units for
 * axis labels, `help scene`), the plan's account of itself (`run
 * --explain`), its refusals and warnings, sweep-parameter edges, and the
 * stick break on the exact T = 0 section. */
#include "test_util.h"
#include "cof.h"
#include "numplan.h"
#include "oscillator.h"
#include "scene.h"
#include "sf_error.h"
#include "sweep.h"
#include "sf_version.h"

#include <stdlib.h>
#include <gsl/gsl_rng.h>
#include <string.h>

/* every error code has its own message; an unknown code says so */
static void strerror_codes(void **state)
{
    (void)state;
    const int codes[] = { SF_SUCCESS, SF_EINVAL, SF_ENOMEM, SF_ETRUNC, SF_ETOOBIG, SF_EIO, SF_EPARSE, SF_EFAIL, SF_EMAXITER };
    const size_t n = sizeof codes / sizeof codes[0];
    for (size_t i = 0; i < n; i++) {
        const char *m = sf_strerror(codes[i]);
        assert_non_null(m);
        assert_true(strlen(m) > 0);
        assert_string_not_equal(m, "unknown error");
        for (size_t j = 0; j < i; j++)
            assert_string_not_equal(m, sf_strerror(codes[j]));
    }
    assert_string_equal(sf_strerror(-12345), "unknown error");
}

static void key_units(void **state)
{
    (void)state;
    assert_string_equal(sf_scene_key_unit("v_b"), "m/s");
    assert_string_equal(sf_scene_key_unit("k"), "N/m");
    assert_string_equal(sf_scene_key_unit("mu_mean"), "1");
    assert_string_equal(sf_scene_key_unit("l_over_R"), "1");
    assert_null(sf_scene_key_unit("no_such_key"));
    assert_null(sf_scene_key_unit(NULL));
}

/* the text of a FILE * writer, NUL-terminated (caller frees) */
static char *text_of(void (*fn)(const void *, FILE *), const void *arg)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_non_null(f);
    fn(arg, f);
    fclose(f);
    return buf;
}

static void print_keys_fn(const void *arg, FILE *f) { (void)arg; sf_scene_print_keys(f); }

/* `help scene`: one line per key with unit, default and range or choices */
static void key_table(void **state)
{
    (void)state;
    char *t = text_of(print_keys_fn, NULL);
    assert_non_null(strstr(t, "unit"));
    assert_non_null(strstr(t, "v_b"));
    assert_non_null(strstr(t, "m/s"));
    assert_non_null(strstr(t, "polar|cartesian"));   /* an enum's choices */
    free(t);
}

static void explain_fn(const void *arg, FILE *f) { sf_osc_explain(arg, f); }

/* the account of one oscillator, for a scene changed by `edit` */
static char *explain(void (*edit)(sf_scene *))
{
    sf_scene s;
    sf_scene_default(&s);
    s.T = 1;
    s.t_skip = 0;
    edit(&s);
    sf_cof *cof;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &cof), SF_SUCCESS);
    sf_osc *o;
    char err[256] = "";
    int rc = sf_osc_alloc(&s, cof, &o, err, sizeof err);
    if (rc)
        print_error("sf_osc_alloc: %s\n", err);
    assert_int_equal(rc, SF_SUCCESS);
    char *t = text_of(explain_fn, o);
    sf_osc_free(o);
    sf_cof_free(cof);
    return t;
}

static void e_default(sf_scene *s) { (void)s; }
static void e_one_dof(sf_scene *s) { s->dof = SF_DOF_1; }
static void e_quadrature_rk4(sf_scene *s)
{
    s->shortcuts = 0;            /* constant COF through the quadrature */
    s->integrator = SF_INTEG_RK4;
    s->dt = 1e-3;
    s->cells = 8;
    s->exact_section = 1;
    s->velocity_jump = 0;
}
static void e_rkck(sf_scene *s)
{
    s->shortcuts = 0;
    s->integrator = SF_INTEG_RKCK;
    s->rtol = 1e-6;
    s->cells = 8;
}

static void explain_variants(void **state)
{
    (void)state;
    char *t = explain(e_default);
    assert_non_null(strstr(t, "3-DOF"));
    assert_non_null(strstr(t, "closed form"));
    assert_non_null(strstr(t, "accuracy plan"));
    free(t);
    t = explain(e_one_dof);
    assert_non_null(strstr(t, "1-D oscillator"));
    assert_non_null(strstr(t, "Eq. 4"));
    free(t);
    t = explain(e_quadrature_rk4);
    assert_non_null(strstr(t, "quadrature"));
    assert_non_null(strstr(t, "constant COF"));
    assert_non_null(strstr(t, "rk4"));
    assert_non_null(strstr(t, "exact T = 0 section"));
    assert_non_null(strstr(t, "set by the scene"));
    free(t);
    t = explain(e_rkck);
    assert_non_null(strstr(t, "rtol = 1e-06"));
    assert_non_null(strstr(t, "predicted QoI error"));
    free(t);
}

/* the plan's refusals and warnings: qoi_tol outside (0, 1); cells set
 * coarser than l; a qoi_tol the ring cap cannot meet */
static void plan_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    sf_numplan p;
    char err[256] = "";
    s.qoi_tol = 0;
    assert_int_equal(sf_numplan_make(&s, 1, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "qoi_tol"));
    s.qoi_tol = 1;
    assert_int_equal(sf_numplan_make(&s, 1, &p, NULL, 0), SF_EINVAL);
    sf_scene_default(&s);
    s.cells = 4;
    s.l = 0.01 * s.R;   /* cells of R/4, far coarser than l */
    assert_int_equal(sf_numplan_make(&s, 1, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cells_from, SF_PLAN_SCENE);
    assert_non_null(strstr(p.warning, "does not resolve"));
    sf_scene_default(&s);
    s.qoi_tol = 1e-9;   /* more rings than the cap */
    s.l = 0.3 * s.R;
    assert_int_equal(sf_numplan_make(&s, 1, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cells, SF_PLAN_MAX_RINGS);
    assert_non_null(strstr(p.warning, "capped"));
}

/* The predicted error (err_pred): the design-fitted bound inside its box
 * (point model, the plan's own polar rings, rkck and rtol, l/R 0.1-1,
 * qoi_tol 1e-3-1e-2), the budget err_total everywhere else; NaN for rk4;
 * what --explain says in each case. */
static char *numplan_text(const sf_numplan *p)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    sf_numplan_explain(p, f);
    fclose(f);
    return text;
}

static void plan_prediction_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_numplan p;
    char err[256] = "", *text;
    sf_scene_default(&s);
    s.cof_model = SF_COFMODEL_POINT;
    s.l = 0.3 * s.R;
    s.qoi_tol = 3e-3;
    assert_int_equal(sf_numplan_make(&s, 1, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.pred_fitted, 1);
    double cv = s.mu_std / s.mu_mean;
    sf_numplan_pred_model m;   /* the constants' values: cases/plan/errmodel-fit.md refits them from their data */
    sf_numplan_pred_model_get(&m);
    assert_close(p.err_pred, p.err_total * m.factor * pow(0.3, -m.lr_exp) * exp(m.cv_coef * cv + m.mu_coef * s.mu_mean),
                 1e-12);
    assert_true(p.err_pred < p.err_total);
    text = numplan_text(&p);
    assert_non_null(strstr(text, "95% of realisations below it"));
    assert_non_null(strstr(text, "plan: not bounded: a jump of a realisation's QoIs"));
    free(text);
    /* outside the box, one departure at a time: the budget */
    for (int k = 0; k < 11; k++) {
        sf_scene t = s;
        int quadrature = k != 0;
        if (k == 1)
            t.cof_model = SF_COFMODEL_CELL;
        if (k == 2)
            t.layout = 1;   /* Cartesian (contact.h) */
        if (k == 3)
            t.cells = 40;
        if (k == 4)
            t.rtol = 1e-9;
        if (k == 5)
            t.integrator = SF_INTEG_RK8PD;
        if (k == 6)
            t.l = 0.05 * t.R;
        if (k == 7)
            t.l = 2 * t.R;
        if (k == 8)
            t.qoi_tol = 1e-4;
        if (k == 9)
            t.qoi_tol = 2e-2;
        if (k == 10)
            t.integrator = SF_INTEG_RK4;
        assert_int_equal(sf_numplan_make(&t, quadrature, &p, err, sizeof err), SF_SUCCESS);
        assert_int_equal(p.pred_fitted, 0);
        if (k == 10) {
            assert_true(isnan(p.err_pred));
            continue;
        }
        assert_true(p.err_pred == p.err_total);
        text = numplan_text(&p);
        assert_non_null(strstr(text, "predicted QoI error"));
        assert_non_null(strstr(text, "the budget: outside the design"));
        free(text);
    }
}

/* ---- The plan made first (numplan.h: sf_plan) */

typedef struct {
    const sf_plan *p;
    const sf_scene *s;
} plan_arg;

static void plan_explain_fn(const void *arg, FILE *f)
{
    const plan_arg *a = arg;
    sf_plan_explain(a->p, a->s, f);
}

/* the plan of s (it must plan) and its record, which must contain want */
static void plan_says(const sf_scene *s, int model, const char *want)
{
    sf_plan p;
    char err[256] = "";
    int rc = sf_plan_make(s, &p, err, sizeof err);
    if (rc)
        print_error("sf_plan_make: %s\n", err);
    assert_int_equal(rc, SF_SUCCESS);
    assert_int_equal(p.cof_model, model);
    plan_arg a = { &p, s };
    char *t = text_of(plan_explain_fn, &a);
    if (!strstr(t, want))
        print_error("wanted '%s' in:\n%s", want, t);
    assert_non_null(strstr(t, want));
    assert_non_null(strstr(t, "accuracy plan"));   /* the numerical part, in the same record */
    free(t);
}

/* every kind of COF the plan chooses, said by its record; what it skips */
static void plan_records(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.T = 5;
    s.cof = SF_COF_UNIFORM;
    plan_says(&s, SF_PLAN_MODEL_UNIFORM, "COF: uniform");
    plan_says(&s, SF_PLAN_MODEL_UNIFORM, "its equatorial circle");
    plan_says(&s, SF_PLAN_MODEL_UNIFORM, "history: streamed");
    s.exact_section = 1;
    s.history = 0;
    plan_says(&s, SF_PLAN_MODEL_UNIFORM, "the exact section, by bisection");
    plan_says(&s, SF_PLAN_MODEL_UNIFORM, "history: none");
    sf_scene_default(&s);
    s.cof = SF_COF_VARIABLE;
    plan_says(&s, SF_PLAN_MODEL_VARIABLE, "one lognormal random variable per realisation");
    s.cof = SF_COF_FIELD;
    s.mu_std = 0;
    plan_says(&s, SF_PLAN_MODEL_VARIABLE, "mu_std = 0, i.e. uniform");
    sf_scene_default(&s);
    s.l = 1e6;   /* the strip is a point against l: one variable */
    plan_says(&s, SF_PLAN_MODEL_VARIABLE, "one random variable, no field");
    sf_scene_default(&s);
    s.T = 5;
    s.l = 0.1;
    plan_says(&s, SF_PLAN_MODEL_POINT, "cof_generator = auto: strip at or below 2^" SF_STR(SF_COF_AUTO_LOG2) " points");
    s.cof_generator = SF_COFGEN_CIRCULANT;
    plan_says(&s, SF_PLAN_MODEL_POINT, "circulant embedding (cof_generator = circulant)");
    s.cof_generator = SF_COFGEN_TILES;
    plan_says(&s, SF_PLAN_MODEL_POINT, "tiles of white noise (cof_generator = tiles)");
    sf_scene_default(&s);   /* a strip far above the cap: the tiles, by auto */
    s.l = 0.005;
    s.T = 100;
    s.strip_halfwidth = 0.1;
    s.cof_model = SF_COFMODEL_POINT;
    plan_says(&s, SF_PLAN_MODEL_POINT, "strip above 2^" SF_STR(SF_COF_AUTO_LOG2) " points");
    plan_says(&s, SF_PLAN_MODEL_POINT, "(above the cap of 2^24)");
    s.T = 20;   /* a strip the cell averages take: auto chooses them */
    s.cof_model = SF_COFMODEL_AUTO;
    plan_says(&s, SF_PLAN_MODEL_CELL_AVERAGE, "cof_model = auto: the plan's choice");
    s.cof_model = SF_COFMODEL_CELL;
    plan_says(&s, SF_PLAN_MODEL_CELL_AVERAGE, "cof_model = cell_average)");
}

/* the plan's refusals; builders given a plan of another scene refuse it;
 * the builders on the plan give the bits of the old entry points */
static void plan_builders(void **state)
{
    (void)state;
    sf_scene s;
    sf_plan p;
    char err[256] = "";
    sf_scene_default(&s);
    s.mu_mean = -1;   /* no lognormal marginal */
    assert_int_equal(sf_plan_make(&s, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "marginal"));
    sf_scene_default(&s);
    s.qoi_tol = 0;   /* the numerical part refuses */
    assert_int_equal(sf_plan_make(&s, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "qoi_tol"));
    /* a COF plan built on another scene's plan */
    sf_scene_default(&s);
    s.l = 0.005;
    s.T = 2;
    s.t_skip = 0;
    s.strip_halfwidth = 0.01;
    assert_int_equal(sf_plan_make(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cof_model, SF_PLAN_MODEL_CELL_AVERAGE);
    sf_scene o = s;
    o.mu_mean = -1;
    sf_cof_plan *cp = (sf_cof_plan *)1;
    assert_int_equal(sf_cof_plan_build(&o, &p, &cp, err, sizeof err), SF_EINVAL);
    assert_null(cp);
    o = s;
    o.l = -1;
    assert_int_equal(sf_cof_plan_build(&o, &p, &cp, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "cell-average"));
    /* the oscillator refuses a COF the plan did not plan for */
    sf_scene u = s;
    u.cof = SF_COF_UNIFORM;
    sf_plan pu;
    assert_int_equal(sf_plan_make(&u, &pu, err, sizeof err), SF_SUCCESS);
    assert_int_equal(pu.num.quadrature, 0);
    double g[16] = { 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5 };
    sf_cof *grid;
    assert_int_equal(sf_cof_alloc_grid(4, 4, -2, -2, 1.3, 1.3, g, &grid), SF_SUCCESS);
    sf_osc *osc = (sf_osc *)1;
    assert_int_equal(sf_osc_alloc_plan(&u, &pu, grid, &osc, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "skips a quadrature"));
    sf_cof_free(grid);
    /* a field scene two ways: the old entry points (each plans for
     * itself) and the plan made first, the same seed: the same bits */
    sf_scene_default(&s);
    s.T = 4;
    s.t_skip = 0;
    s.l = 0.1;
    s.strip_halfwidth = 0.05;
    double v[2][4];
    for (int way = 0; way < 2; way++) {
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(rng, 11);
        sf_cof *cof;
        sf_osc *x;
        if (way == 0) {
            assert_int_equal(sf_cof_from_scene(&s, rng, &cof), SF_SUCCESS);
            assert_int_equal(sf_osc_alloc(&s, cof, &x, err, sizeof err), SF_SUCCESS);
        } else {
            assert_int_equal(sf_plan_make(&s, &p, err, sizeof err), SF_SUCCESS);
            assert_int_equal(sf_cof_plan_build(&s, &p, &cp, err, sizeof err), SF_SUCCESS);
            assert_int_equal(sf_cof_plan_draw(cp, rng, &cof), SF_SUCCESS);
            sf_cof_plan_free(cp);
            assert_int_equal(sf_osc_alloc_plan(&s, &p, cof, &x, err, sizeof err), SF_SUCCESS);
            assert_memory_equal(sf_osc_get_plan(x), &p.num, sizeof p.num);
        }
        gsl_rng_free(rng);
        sf_osc_result r;
        assert_int_equal(sf_osc_run(x, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
        double w[4] = { r.pv_x, r.pv_F, r.stick_fraction, (double)r.steps };
        memcpy(v[way], w, sizeof w);
        sf_osc_result_free(&r);
        sf_osc_free(x);
        sf_cof_free(cof);
    }
    assert_true(v[0][3] > 10);
    assert_memory_equal(v[0], v[1], sizeof v[0]);
}

/* sweep parameters: l_over_R must be positive and finite; mu_mean keeps
 * the CV (Fig. 13); an unknown key is refused with the parser's reason */
static void sweep_set_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    char err[256] = "";
    assert_int_equal(sf_sweep_set(&s, "l_over_R", 0, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "l_over_R"));
    assert_int_equal(sf_sweep_set(&s, "l_over_R", INFINITY, err, sizeof err), SF_EPARSE);
    assert_int_equal(sf_sweep_set(&s, "l_over_R", 2, err, sizeof err), SF_SUCCESS);
    assert_close(s.l, 2 * s.R, 1e-15);
    double cv = s.mu_std / s.mu_mean;
    assert_int_equal(sf_sweep_set(&s, "mu_mean", 0.8, err, sizeof err), SF_SUCCESS);
    assert_close(s.mu_mean, 0.8, 1e-15);
    assert_close(s.mu_std / s.mu_mean, cv, 1e-15);
    assert_int_not_equal(sf_sweep_set(&s, "no_such_key", 1, err, sizeof err), SF_SUCCESS);
    assert_non_null(strstr(err, "unknown parameter 'no_such_key'"));
    /* the swept value overrides a value the scene file set (not "set twice"),
       value after value */
    sf_scene_default(&s);
    assert_int_equal(sf_scene_parse(&s, "T = 30\n", "t.scene", 1, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_set(&s, "T", 40, err, sizeof err), SF_SUCCESS);
    assert_close(s.T, 40, 0);
    assert_int_equal(sf_sweep_set(&s, "T", 50, err, sizeof err), SF_SUCCESS);
    assert_close(s.T, 50, 0);
    assert_true(sf_scene_was_set(&s, "T"));
}

/* the library's run-time version is the headers' */
static void version_agrees(void **state)
{
    (void)state;
    char v[32];
    snprintf(v, sizeof v, "%d.%d.%d", SF_VERSION_MAJOR, SF_VERSION_MINOR, SF_VERSION_PATCH);
    assert_string_equal(sf_version(), v);
    assert_string_equal(SF_VERSION_STRING, v);
}

/* Stick duration from rest at the origin, uniform COF through the
 * quadrature: on the equatorial circle it is the closed form
 * (mu N / k) / v_b; on the exact section (a uniform disc's T = 0 section
 * is that circle, up to the quadrature) it lies in (0, tau] and within 1 %
 * of it (8 rings).  Outside the stick set it is 0. */
static void stick_on_exact_section(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.shortcuts = 0;
    s.cells = 8;
    s.mu_std = 0;
    sf_cof *cof;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &cof), SF_SUCCESS);
    double y[SF_OSC_NSTATE] = { 0 }, tau = s.mu_mean * s.m * s.g / s.k / s.v_b;
    char err[256] = "";
    for (int exact = 0; exact <= 1; exact++) {
        s.exact_section = exact;
        sf_osc *o;
        assert_int_equal(sf_osc_alloc(&s, cof, &o, err, sizeof err), SF_SUCCESS);
        y[SF_OSC_X] = y[SF_OSC_Y] = 0;
        double d = sf_osc_stick_duration(o, 0, y);
        if (exact) {
            assert_true(d > 0 && d <= tau * (1 + 1e-9));
            assert_close(d, tau, 1e-2);
        } else {
            assert_close(d, tau, 1e-12);
        }
        y[SF_OSC_X] = 2 * s.mu_mean * s.m * s.g / s.k;   /* beyond the break */
        assert_true(sf_osc_stick_duration(o, 0, y) == 0);
        y[SF_OSC_X] = 0;
        y[SF_OSC_Y] = y[SF_OSC_X] + 2 * s.mu_mean * s.m * s.g / s.k;
        assert_true(sf_osc_stick_duration(o, 0, y) == 0);
        sf_osc_free(o);
    }
    sf_cof_free(cof);
}

/* A key table of the test's own (the scene's has no string or list key;
 * verification/case.c declares some the same way). */
typedef struct { char name[16]; sf_list xs; unsigned char set[2]; } own_keys;
static const sf_key own_table[] = {
    { "name", SF_KEY_STRING, offsetof(own_keys, name), sizeof(((own_keys *)0)->name), 0, 0, 0, 0, "", "", NULL, "a name" },
    { "xs", SF_KEY_LIST, offsetof(own_keys, xs), 0, 0, 0, 0, 0, "", "", NULL, "a list" },
};

/* the parser's length and count limits, enum names, and writing a list */
static void scene_parse_limits(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    own_keys o;
    memset(&o, 0, sizeof o);
    sf_keytab tabs[2] = { sf_scene_keytab(&s), { own_table, 2, &o, o.set } };
    sf_keys_default(&tabs[1]);
    char err[256] = "", text[4096];
    /* a seed is an integer of at most 31 characters */
    assert_int_equal(sf_scene_parse(&s, "seed = 1234567890123456789012345678901234567890\n", "t", 1, err, sizeof err),
                     SF_EPARSE);
    assert_non_null(strstr(err, "too long"));
    /* a string key longer than its buffer */
    int n = snprintf(text, sizeof text, "name = ");
    for (int i = 0; i < 30; i++)
        text[n++] = 'a';
    text[n++] = '\n';
    text[n] = '\0';
    assert_int_equal(sf_keys_parse(tabs, 2, text, "t", 1, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "longer than"));
    /* a list of more than SF_LIST_MAX values */
    n = snprintf(text, sizeof text, "xs = 1");
    for (int i = 0; i < SF_LIST_MAX; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, ", %d", i + 2);
    snprintf(text + n, sizeof text - (size_t)n, "\n");
    assert_int_equal(sf_keys_parse(tabs, 2, text, "t", 1, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "more than"));
    /* enum names: known, out of range, not an enum, unknown key */
    assert_string_equal(sf_scene_enum_name("layout", 1), "cartesian");
    assert_string_equal(sf_scene_enum_name("layout", 7), "?");
    assert_string_equal(sf_scene_enum_name("v_b", 0), "?");
    assert_string_equal(sf_scene_enum_name("no_such_key", 0), "?");
    /* a list written back as "a, b, c" */
    sf_scene_default(&s);
    sf_keys_default(&tabs[1]);
    assert_int_equal(sf_keys_parse(tabs, 2, "sweep = 1\n", "t", 1, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "t:1: unknown key 'sweep'"));   /* a case's key, not the solver's */
    assert_int_equal(sf_keys_parse(tabs, 2, "l = 0.2\nxs = 0.5, 2, 8\nname = a_b\n", "t", 1, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_keys_was_set(&tabs[1], "xs"), 1);
    assert_int_equal(sf_scene_was_set(&s, "l"), 1);
    assert_int_equal(sf_keys_parse(tabs, 2, "xs = 1\n", "t", 7, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "t:7: key 'xs': set twice"));
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_non_null(f);
    sf_keys_write(&tabs[1], f);
    sf_scene_write(&s, f);
    fclose(f);
    assert_non_null(strstr(buf, "xs = 0.5, 2, 8"));
    assert_non_null(strstr(buf, "name = a_b"));
    assert_non_null(strstr(buf, "layout = polar"));
    free(buf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(strerror_codes),
        cmocka_unit_test(key_units),
        cmocka_unit_test(key_table),
        cmocka_unit_test(explain_variants),
        cmocka_unit_test(plan_edges),
        cmocka_unit_test(plan_prediction_edges),
        cmocka_unit_test(plan_records),
        cmocka_unit_test(plan_builders),
        cmocka_unit_test(sweep_set_edges),
        cmocka_unit_test(version_agrees),
        cmocka_unit_test(stick_on_exact_section),
        cmocka_unit_test(scene_parse_limits),
    };
    return cmocka_run_group_tests_name("edges", tests, NULL, NULL);
}
