/* Unit tests: allocation failure, SQLite style (solver/base/sf_alloc.h).  This
 * program links a solver built with -DSF_FAULT_INJECTION (Makefile: the
 * plain test links build/fi/, the sanitised one build/san/, make coverage
 * build/cov/).  For each public call that allocates, the walk fails its
 * k-th allocation, k = 0, 1, 2, ..., until a run sees no failure, and
 * checks at every k that the call returns SF_ENOMEM and hands out no
 * object (the out pointer is NULL); the sanitised build and valgrind
 * (scripts/valgrind.sh) check that nothing leaks on any of these paths.
 * The run without a failure must give the result of a run with injection
 * off (same bits), so a recovered failure cannot leave stale state. */
/* the fault hooks (sf_alloc.h): declared only for a fault-injection build */
#define SF_FAULT_INJECTION 1
#include "test_util.h"
#include "cellavg.h"
#include "cof.h"
#include "contact.h"
#include "field.h"
#include "lnfield.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "qoi.h"
#include "scene.h"
#include "sf_alloc.h"
#include "sensitivity.h"
#include "sf_error.h"
#include "sobol.h"
#include "surface.h"
#include "sweep.h"
#include "mcstop.h"
#include "noise.h"
#include "tiles.h"
#include "antithetic.h"
#include "mlmc.h"
#include "unum.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <gsl/gsl_rng.h>

/* One attempt of a call: returns its code; on failure it has checked that
 * nothing escaped, on success it has checked the result and freed it. */
typedef int attempt_fn(void *ctx);

/* Fail allocation k = 0, 1, ... of f(ctx) until a run completes without a
 * failure; every failed run must return SF_ENOMEM (or `also`, a code the
 * call documents for a failed allocation deeper down; 0: none).  Returns
 * the number of allocations the call makes. */
static long walk(const char *what, attempt_fn *f, void *ctx, int ok, int also)
{
    /* SF_WALK_PART=i/n: fail only the allocations k = i mod n (one of n
     * processes that share a long walk: scripts/valgrind.sh) */
    long part = 0, parts = 1, walked = 0;
    const char *wp = getenv("SF_WALK_PART");
    if (wp && (sscanf(wp, "%ld/%ld", &part, &parts) != 2 || parts < 1 || part < 0 || part >= parts)) {
        print_error("SF_WALK_PART=%s: expected i/n with 0 <= i < n\n", wp);
        fail();
    }
    for (long k = part;; k += parts) {
        sf_fault_arm(k);
        int rc = f(ctx);
        int fired = sf_fault_fired();
        long n = sf_fault_count();
        sf_fault_arm(-1);
        if (!fired) {
            if (rc != ok) {
                print_error("%s: %ld allocations, no failure injected, returned %d (expected %d)\n", what, n, rc, ok);
                fail();
            }
            if (parts > 1)
                print_message("%s: %ld of %ld allocation-failure paths walked (part %ld of %ld)\n", what, walked, n,
                              part, parts);
            else
                print_message("%s: %ld allocation-failure paths walked\n", what, n);
            return n;   /* the allocations of a run without a failure: k, when every k is walked */
        }
        walked++;
        if (rc != SF_ENOMEM && !(also && rc == also)) {
            print_error("%s: allocation %ld of %ld failed, returned %d (%s), expected SF_ENOMEM\n", what, k, n, rc,
                        sf_strerror(rc));
            fail();
        }
    }
}

static void scene_small(sf_scene *s)
{
    sf_scene_default(s);
    s->T = 6;
    s->t_skip = 1;
    s->l = 0.25;
    s->strip_halfwidth = 0.05;
    s->cells = 6;
    s->rtol = 1e-6;
}

/* cof_model = cell_average (cellavg.h), chosen by auto at l/R = 0.01 on
 * a short belt and a narrow strip: the effective field's separable-sum
 * embedding is ~1e5 points, cheap enough to plan once per allocation */
static void scene_cellavg(sf_scene *s)
{
    sf_scene_default(s);
    s->l = 0.005;
    s->T = 2;
    s->t_skip = 0;
    s->strip_halfwidth = 0.01;
    s->rtol = 1e-6;
}

/* ---- COF */

static int cof_uniform(void *ctx)
{
    (void)ctx;
    sf_cof *c = (sf_cof *)1;
    int rc = sf_cof_alloc_uniform(0.3, &c);
    if (rc) {
        assert_null(c);
        return rc;
    }
    assert_close(sf_cof_eval(c, 1, 2), 0.3, 0);
    sf_cof_free(c);
    return rc;
}

static int cof_grid(void *ctx)
{
    (void)ctx;
    double g[6] = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 };
    sf_cof *c = (sf_cof *)1;
    int rc = sf_cof_alloc_grid(3, 2, 0, 0, 1, 1, g, &c);
    if (rc) {
        assert_null(c);
        return rc;
    }
    assert_close(sf_cof_eval(c, 1, 1), 0.5, 1e-15);
    sf_cof_free(c);
    return rc;
}

static void cof_allocs(void **state)
{
    (void)state;
    assert_int_equal(walk("sf_cof_alloc_uniform", cof_uniform, NULL, SF_SUCCESS, 0), 1);
    assert_int_equal(walk("sf_cof_alloc_grid", cof_grid, NULL, SF_SUCCESS, 0), 2);
}

/* A plan and one draw from it; the draw's first values recorded in ref
 * (the run without a failure must give the same). */
typedef struct {
    sf_scene s;
    double ref[4];
    int have_ref;
} plan_ctx;

static int plan_and_draw(void *ctx)
{
    plan_ctx *c = ctx;
    sf_cof_plan *p = (sf_cof_plan *)1;
    char err[256] = "";
    int rc = sf_cof_plan_alloc(&c->s, &p, err, sizeof err);
    if (rc) {
        assert_null(p);
        return rc;
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 7);
    sf_cof *cof = (sf_cof *)1;
    rc = sf_cof_plan_draw(p, rng, &cof);
    gsl_rng_free(rng);
    sf_cof_plan_free(p);
    if (rc) {
        assert_null(cof);
        return rc;
    }
    double v[4] = { sf_cof_eval(cof, 0, 0), sf_cof_eval(cof, -0.3, 0.01), sf_cof_eval(cof, -1.1, -0.02),
                    sf_cof_max(cof) };
    if (c->have_ref)
        assert_memory_equal(v, c->ref, sizeof v);
    memcpy(c->ref, v, sizeof v);
    c->have_ref = 1;
    sf_cof_free(cof);
    return rc;
}

static void cof_plans(void **state)
{
    (void)state;
    plan_ctx c = { 0 };
    scene_small(&c.s);
    c.s.cof_generator = SF_COFGEN_CIRCULANT;
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);   /* the reference: injection off */
    assert_true(walk("plan + draw (circulant strip)", plan_and_draw, &c, SF_SUCCESS, 0) > 10);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);
    c.s.cof_generator = SF_COFGEN_TILES;
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);
    assert_true(walk("plan + draw (tiled window)", plan_and_draw, &c, SF_SUCCESS, 0) > 5);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);
    c.s.precorrect = 1;   /* the general (non-separable) embedding */
    c.s.cof_generator = SF_COFGEN_CIRCULANT;
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);
    assert_true(walk("plan + draw (pre-corrected, general embedding)", plan_and_draw, &c, SF_SUCCESS, 0) > 5);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);
    c.s.cof = SF_COF_VARIABLE;
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);
    assert_int_equal(walk("plan + draw (variable)", plan_and_draw, &c, SF_SUCCESS, 0), 2);
    memset(&c, 0, sizeof c);
    scene_cellavg(&c.s);
    assert_int_equal(sf_numplan_cell_average(&c.s, NULL, NULL), 1);
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);
    assert_true(walk("plan + draw (cell averages, separable-sum embedding)", plan_and_draw, &c, SF_SUCCESS, 0) > 10);
}

static int from_scene(void *ctx)
{
    sf_cof *cof = (sf_cof *)1;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    int rc = sf_cof_from_scene(ctx, rng, &cof);
    gsl_rng_free(rng);
    if (rc)
        assert_null(cof);
    sf_cof_free(cof);
    return rc;
}

/* A window that slides asks for a larger column buffer (tiles.c) */
static int window_slide(void *ctx)
{
    sf_cof_plan *p;
    int rc = sf_cof_plan_alloc(ctx, &p, NULL, 0);
    if (rc)
        return rc;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *cof;
    rc = sf_cof_plan_draw(p, rng, &cof);
    gsl_rng_free(rng);
    sf_cof_plan_free(p);
    if (rc)
        return rc;
    double mu = sf_cof_eval(cof, -0.4, 0);
    rc = sf_cof_follow(cof, -60, -59);   /* far: the whole window made again */
    if (!rc) {
        assert_int_equal(sf_cof_follow(cof, -0.6, 0.6), SF_SUCCESS);
        assert_close(sf_cof_eval(cof, -0.4, 0), mu, 1e-14);
    }
    sf_cof_free(cof);
    return rc;
}

/* An antithetic pair of windows that share kept columns
 * (sf_cof_plan_keep_columns): the store's allocation and each growth
 * fail with SF_ENOMEM, and the partner's values are then -G's */
static int window_pair_kept(void *ctx)
{
    sf_cof_plan *p;
    int rc = sf_cof_plan_alloc(ctx, &p, NULL, 0);
    if (rc)
        return rc;
    sf_cof_plan_keep_columns(p, 1);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *g = NULL, *a = NULL;
    rc = sf_cof_plan_draw(p, rng, &g);
    gsl_rng_free(rng);
    if (!rc)
        rc = sf_cof_follow(g, 20, 21);   /* far: the store grows */
    if (!rc)
        rc = sf_cof_plan_antithetic(p, g, &a);
    for (int k = 0; !rc && k < 2; k++)   /* the partner copies, then makes */
        rc = sf_cof_follow(a, 20 + 15 * k, 21 + 15 * k);
    if (!rc && !(sf_cof_columns_made(a) > 0 && sf_cof_columns_made(a) < sf_cof_columns_made(g)))
        rc = SF_EINVAL;
    sf_cof_free(g);
    sf_cof_free(a);
    sf_cof_plan_free(p);
    return rc;
}

static void cof_more(void **state)
{
    (void)state;
    sf_scene s;
    scene_small(&s);
    s.cof_generator = SF_COFGEN_CIRCULANT;
    walk("sf_cof_from_scene", from_scene, &s, SF_SUCCESS, 0);
    s.cof_generator = SF_COFGEN_TILES;
    s.T = 400;   /* a strip of 80 m: the window follows */
    walk("tiled window slides", window_slide, &s, SF_SUCCESS, 0);
    walk("tiled antithetic pair, kept columns", window_pair_kept, &s, SF_SUCCESS, 0);
}

/* ---- the belt noise (noise.h, cof_generator = belt_noise) */

typedef struct {
    double ref[12];
    int have_ref;
} noise_ctx;

/* its allocations: the struct, the rng, 3 block columns per level */
static int noise_alloc(void *ctx)
{
    noise_ctx *c = ctx;
    sf_noise *z = (sf_noise *)1;
    int rc = sf_noise_alloc(3, -2, 12, &z);
    if (rc) {
        assert_null(z);
        return rc;
    }
    sf_noise_set_key(z, 42);
    double v[12];
    memcpy(v, sf_noise_column(z, -65), sizeof v);
    if (c->have_ref)
        assert_memory_equal(v, c->ref, sizeof v);
    memcpy(c->ref, v, sizeof v);
    c->have_ref = 1;
    sf_noise_free(z);
    return rc;
}

/* sf_cof_plan_point: a plan, then the point's own tiles and noise */
static int belt_point(void *ctx)
{
    plan_ctx *c = ctx;
    sf_cof_plan *p;
    int rc = sf_cof_plan_alloc(&c->s, &p, NULL, 0);
    if (rc)
        return rc;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 7);
    double mu = -1;
    rc = sf_cof_plan_point(p, rng, -0.3, 0.01, &mu);
    gsl_rng_free(rng);
    sf_cof_plan_free(p);
    if (rc) {
        assert_true(mu == -1);
        return rc;
    }
    if (c->have_ref)
        assert_memory_equal(&mu, c->ref, sizeof mu);
    c->ref[0] = mu;
    c->have_ref = 1;
    return rc;
}

/* a belt-noise window, its antithetic partner, both slid far */
static int belt_pair(void *ctx)
{
    sf_cof_plan *p;
    int rc = sf_cof_plan_alloc(ctx, &p, NULL, 0);
    if (rc)
        return rc;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *g = NULL, *a = (sf_cof *)1;
    rc = sf_cof_plan_draw(p, rng, &g);
    gsl_rng_free(rng);
    if (!rc) {
        rc = sf_cof_plan_antithetic(p, g, &a);
        if (rc)
            assert_null(a);
    } else {
        assert_null(g);
        a = NULL;
    }
    for (int k = 0; !rc && k < 2; k++)
        rc = sf_cof_follow(k ? a : g, -20, -19);   /* far: the whole window made again */
    sf_cof_free(g);
    sf_cof_free(a);
    sf_cof_plan_free(p);
    return rc;
}

static void belt_noise(void **state)
{
    (void)state;
    noise_ctx n = { .have_ref = 0 };
    assert_int_equal(noise_alloc(&n), SF_SUCCESS);
    assert_int_equal(walk("sf_noise_alloc", noise_alloc, &n, SF_SUCCESS, 0), 2 + 3 * (3 + 1));
    plan_ctx c = { 0 };
    scene_small(&c.s);
    c.s.cof_generator = SF_COFGEN_BELT_NOISE;
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);
    /* the plan, the window, its tiles, the noise (2 + 3 (L + 1) at l =
     * 0.25 m: level 15), the grid, the tiles' column buffer */
    assert_true(walk("plan + draw (belt-noise window)", plan_and_draw, &c, SF_SUCCESS, 0) > 2 + 3 * 16);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);
    c.s.cof_generator = SF_COFGEN_BELT_NOISE;
    assert_int_equal(belt_point(&c), SF_SUCCESS);
    assert_true(walk("plan + sf_cof_plan_point (belt noise)", belt_point, &c, SF_SUCCESS, 0) > 2 + 3 * 16);
    walk("belt-noise window + antithetic, slid", belt_pair, &c.s, SF_SUCCESS, 0);
    /* box averages on the belt noise (cellavg.h: l/R = 0.01, the plan's
     * cell averages): the filter's weights, its row buffers */
    memset(&c, 0, sizeof c);
    scene_cellavg(&c.s);
    c.s.cof_generator = SF_COFGEN_BELT_NOISE;
    assert_int_equal(plan_and_draw(&c), SF_SUCCESS);
    assert_true(walk("plan + draw (box averages on belt noise)", plan_and_draw, &c, SF_SUCCESS, 0) > 5);
    /* (its slide is walked for the point model above: under valgrind a
     * slid box-average walk takes over 8 min) */
}

/* ---- the estimators' pure stage rules and intervals (antithetic.h, mlmc.h) */

static double stage_v[8 * 2 * SF_SWEEP_NQ], stage_l0[8 * SF_SWEEP_NQ];

static int anti_pure(void *ctx)
{
    (void)ctx;
    static const double one[SF_SWEEP_NQ] = { 1, 1, 1 };
    size_t g;
    int capped;
    sf_sweep_anti e;
    int rc = sf_anti_stage(stage_v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, 8, 4, 40, NULL, &g, &capped);
    return rc ? rc : sf_anti_interval(stage_v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, 0, 8, &e);
}

static int mlmc_pure(void *ctx)
{
    (void)ctx;
    static const double one[SF_SWEEP_NQ] = { 1, 1, 1 };
    size_t g0, g1;
    int capped;
    sf_sweep_ml e;
    int rc = sf_mlmc_next(stage_v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, 8, stage_l0, SF_SWEEP_NQ, 8, one, 1, 2, 4, 40, NULL,
                          &g0, &g1, &capped);
    return rc ? rc : sf_mlmc_interval(stage_v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, 8, stage_l0, SF_SWEEP_NQ, 8, one, 0, 0,
                                      &e);
}

static void estimator_rules(void **state)
{
    (void)state;
    for (size_t i = 0; i < 8; i++)
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            stage_v[i * 2 * SF_SWEEP_NQ + q] = 1 + 0.1 * (double)((i * 7 + (size_t)q) % 5);
            stage_v[i * 2 * SF_SWEEP_NQ + SF_SWEEP_NQ + q] = 1 - 0.05 * (double)((i * 3 + (size_t)q) % 4);
            stage_l0[i * SF_SWEEP_NQ + q] = 1 + 0.02 * (double)((i + (size_t)q) % 3);
        }
    assert_true(walk("sf_anti_stage + sf_anti_interval", anti_pure, NULL, SF_SUCCESS, 0) >= 2);
    assert_true(walk("sf_mlmc_next + sf_mlmc_interval", mlmc_pure, NULL, SF_SUCCESS, 0) >= 2);
}

/* ---- fields, tiles */

static double exp_kernel(double r, void *p)
{
    (void)p;
    return exp(-r / 0.3);
}

static int field(void *ctx)
{
    const sf_field_spec *sp = ctx;
    sf_field *f = (sf_field *)1;
    int rc = sf_field_alloc(sp, &f);
    if (!sf_usable(rc)) {
        assert_null(f);
        return rc;
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double *v = malloc(sp->m * sp->n * sizeof *v);
    int rs = sf_field_sample(f, rng, v);   /* allocates the kept field on first use */
    free(v);
    gsl_rng_free(rng);
    sf_field_free(f);
    return rs ? rs : rc;
}

/* A field and one sample from a fixed seed, compared with the run
 * without a failure (a recovered failure leaves no stale table). */
typedef struct {
    sf_field_spec sp;
    double ref[3];
    int have_ref;
} field_ctx;

static int field_bits(void *ctx)
{
    field_ctx *c = ctx;
    sf_field *f = (sf_field *)1;
    int rc = sf_field_alloc(&c->sp, &f);
    if (!sf_usable(rc)) {
        assert_null(f);
        return rc;
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 5);
    size_t mn = c->sp.m * c->sp.n;
    double *v = malloc(mn * sizeof *v);
    int rs = sf_field_sample(f, rng, v);   /* allocates the kept field on first use */
    if (rs) {
        free(v);
        gsl_rng_free(rng);
        sf_field_free(f);
        return rs;
    }
    double r[3] = { v[0], v[mn / 2], sf_field_get_info(f)->cov_error };
    if (c->have_ref)
        assert_memory_equal(r, c->ref, sizeof r);
    memcpy(c->ref, r, sizeof r);
    c->have_ref = 1;
    free(v);
    gsl_rng_free(rng);
    sf_field_free(f);
    return rc;
}

/* The same plan with its covariance deferred: sf_field_sample_fresh gives
 * field_bits' sample, and sf_field_measure_covariance its cov_error, bit
 * for bit (run after field_bits has set the reference). */
static int field_deferred(void *ctx)
{
    field_ctx *c = ctx;
    sf_field_spec sp = c->sp;
    sp.defer_covariance = 1;
    sf_field *f = (sf_field *)1;
    int rc = sf_field_alloc(&sp, &f);
    if (!sf_usable(rc)) {
        assert_null(f);
        return rc;
    }
    assert_true(isnan(sf_field_get_info(f)->cov_error));
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 5);
    size_t mn = sp.m * sp.n;
    double *v = malloc(mn * sizeof *v);
    assert_int_equal(sf_field_sample_fresh(f, rng, v), SF_SUCCESS);
    int rm = sf_field_measure_covariance(f);
    if (!rm) {
        double r[3] = { v[0], v[mn / 2], sf_field_get_info(f)->cov_error };
        assert_memory_equal(r, c->ref, sizeof r);
    }
    free(v);
    gsl_rng_free(rng);
    sf_field_free(f);
    return rm;
}

static int lnfield(void *ctx)
{
    sf_lnfield *f = (sf_lnfield *)1;
    int rc = sf_lnfield_alloc(ctx, &f);
    if (!sf_usable(rc)) {
        assert_null(f);
        return rc;
    }
    const sf_scene *s = ctx;
    double *cof = malloc(s->nx * s->ny * sizeof *cof);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    int rs = sf_lnfield_sample(f, rng, NULL, cof);   /* its scratch and the kept field, on first use */
    gsl_rng_free(rng);
    free(cof);
    sf_lnfield_free(f);
    return rs ? rs : rc;
}

static int tiles(void *ctx)
{
    (void)ctx;
    sf_tiles_spec sp = { 21, 0.02, 0.02, 0.1, 0, 16 };
    sf_tiles *t = (sf_tiles *)1;
    int rc = sf_tiles_alloc(&sp, &t);
    if (rc) {
        assert_null(t);
        return rc;
    }
    sf_tiles_set_key(t, 42);
    double *g = malloc(300 * 21 * sizeof *g);
    rc = sf_tiles_fill(t, -20, 300, g, 300);   /* grows the column buffer */
    free(g);
    sf_tiles_free(t);
    return rc;
}

static void fields(void **state)
{
    (void)state;
    sf_field_spec sp;
    sf_field_spec_default(&sp, 24, 16, 0.05, 0.05, 0.2);
    assert_true(walk("sf_field_alloc (separable)", field, &sp, SF_SUCCESS, 0) > 5);
    sp.kernel = exp_kernel;
    walk("sf_field_alloc (general kernel)", field, &sp, SF_SUCCESS, 0);
    sf_field_spec_default(&sp, 64, 8, 0.05, 0.05, 1.0);
    sp.pad_cap = 1.5;   /* truncated: SF_ETRUNC, usable */
    walk("sf_field_alloc (padding cap)", field, &sp, SF_ETRUNC, 0);
    /* the cell-averaged COF's kernel: a separable sum with a short support
     * (1-D tables per period, the target at the true lags) */
    sf_cellavg ca;
    double box = 0.03125;   /* 32 cells on a disc of radius 0.5 m */
    assert_int_equal(sf_cellavg_init(&ca, 0.5, 0.1, 0.005, box), SF_SUCCESS);
    field_ctx fc = { .have_ref = 0 };
    sf_field_spec_default(&fc.sp, 120, 40, box / 3, box / 3, 0.005);
    fc.sp.sep_terms = ca.nterms;
    fc.sp.sep_fn = sf_cellavg_septerm;
    fc.sp.sep_params = &ca;
    fc.sp.support = sf_cellavg_support(&ca);
    assert_int_equal(field_bits(&fc), SF_SUCCESS);
    assert_true(walk("sf_field_alloc (separable-sum kernel, short support)", field_bits, &fc, SF_SUCCESS, 0) > 5);
    assert_true(walk("sf_field_alloc (deferred covariance) + measure", field_deferred, &fc, SF_SUCCESS, 0) > 5);
    sf_scene s;
    scene_small(&s);
    s.nx = 16;
    s.ny = 12;
    s.dx = s.dy = 0.05;
    walk("sf_lnfield_alloc", lnfield, &s, SF_SUCCESS, 0);
    walk("sf_tiles_alloc + fill", tiles, NULL, SF_SUCCESS, 0);
}

/* ---- contact, surface */

typedef struct {
    sf_contact_spec spec;
    sf_cof *cof;
} contact_ctx;

static int contact(void *ctx)
{
    contact_ctx *c = ctx;
    sf_contact *ct = (sf_contact *)1;
    int rc = sf_contact_alloc(&c->spec, c->cof, &ct);
    if (rc) {
        assert_null(ct);
        return rc;
    }
    double q[3];
    assert_int_equal(sf_contact_wrench(ct, 0, 0, 0.1, 0, 0, 1, q), SF_SUCCESS);
    sf_contact_free(ct);
    return rc;
}

static int surface(void *ctx)
{
    contact_ctx *c = ctx;
    sf_contact *ct;
    int rc = sf_contact_alloc(&c->spec, c->cof, &ct);
    if (rc)
        return rc;
    sf_surface *s = (sf_surface *)1;
    rc = sf_surface_alloc(ct, 0, 0, &s);
    if (rc) {
        assert_null(s);
    } else {
        double rho, psi;
        rc = sf_surface_section_radius(s, 0.3, &rho, &psi);   /* Brent: a GSL solver */
        sf_surface_free(s);
    }
    double m;
    if (!rc)
        rc = sf_contact_stick_margin(ct, 0, 0, 1, 2, 1, &m);
    sf_contact_free(ct);
    return rc;
}

static void contacts(void **state)
{
    (void)state;
    contact_ctx c = { { 0.5, 9.81, SF_LAYOUT_POLAR, 6 }, NULL };
    assert_int_equal(sf_cof_alloc_uniform(0.3, &c.cof), SF_SUCCESS);
    assert_int_equal(walk("sf_contact_alloc (polar)", contact, &c, SF_SUCCESS, 0), 8);
    c.spec.layout = SF_LAYOUT_CARTESIAN;
    assert_int_equal(walk("sf_contact_alloc (Cartesian)", contact, &c, SF_SUCCESS, 0), 4);
    c.spec.layout = SF_LAYOUT_POLAR;
    walk("sf_surface_alloc, section, stick margin", surface, &c, SF_SUCCESS, 0);
    sf_cof_free(c.cof);
}

/* ---- the oscillator, Monte Carlo, sweep */

typedef struct {
    sf_scene s;
    double ref[3];
    int have_ref;
    int planned;   /* 1: on the plan made first (sf_plan_make, sf_cof_plan_build, sf_osc_alloc_plan) */
} osc_ctx;

/* The COF of the plan made first (numplan.h: sf_plan_make, which
 * allocates nothing; the COF plan built from it): one draw */
static int planned_cof(const sf_scene *s, sf_plan *pl, gsl_rng *rng, sf_cof **cof)
{
    assert_int_equal(sf_plan_make(s, pl, NULL, 0), SF_SUCCESS);
    sf_cof_plan *p = (sf_cof_plan *)1;
    int rc = sf_cof_plan_build(s, pl, &p, NULL, 0);
    if (rc) {
        assert_null(p);
        return rc;
    }
    rc = sf_cof_plan_draw(p, rng, cof);
    sf_cof_plan_free(p);
    return rc;
}

/* c->planned: the same run on the plan made first, the oscillator on it
 * (the same values as the old entry points': c->ref) */
static int osc(void *ctx)
{
    osc_ctx *c = ctx;
    sf_cof *cof;
    sf_plan pl;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 3);
    int rc = c->planned ? planned_cof(&c->s, &pl, rng, &cof) : sf_cof_from_scene(&c->s, rng, &cof);
    gsl_rng_free(rng);
    if (rc)
        return rc;
    sf_osc *o = (sf_osc *)1;
    char err[256] = "";
    rc = c->planned ? sf_osc_alloc_plan(&c->s, &pl, cof, &o, err, sizeof err)
                    : sf_osc_alloc(&c->s, cof, &o, err, sizeof err);
    if (rc) {
        assert_null(o);
        sf_cof_free(cof);
        return rc;
    }
    sf_osc_result r;
    rc = sf_osc_run(o, NULL, NULL, 0.05, &r, err, sizeof err);
    if (!rc) {
        double v[3] = { r.pv_x, r.pv_F, (double)r.ntrans };
        if (c->have_ref)
            assert_memory_equal(v, c->ref, sizeof v);
        memcpy(c->ref, v, sizeof v);
        c->have_ref = 1;
    }
    sf_osc_result_free(&r);   /* also after a failed run */
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc;
}

static void oscillator(void **state)
{
    (void)state;
    osc_ctx c = { 0 };
    scene_small(&c.s);
    c.s.T = 150;   /* > 64 transitions: the result arrays grow */
    c.s.t_skip = 0;
    c.s.cof = SF_COF_UNIFORM;
    assert_int_equal(osc(&c), SF_SUCCESS);
    assert_true(c.ref[2] > 64);
    assert_true(walk("oscillator, 1-D closed form", osc, &c, SF_SUCCESS, 0) > 10);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);
    c.s.dof = SF_DOF_3;
    c.s.cof_generator = SF_COFGEN_CIRCULANT;
    assert_int_equal(osc(&c), SF_SUCCESS);
    assert_true(walk("oscillator, 3-DOF on a field", osc, &c, SF_SUCCESS, 0) > 20);
    c.planned = 1;   /* the old entry points' bits (c.ref) */
    assert_int_equal(osc(&c), SF_SUCCESS);
    assert_true(walk("oscillator, 3-DOF on a field, on the plan made first", osc, &c, SF_SUCCESS, 0) > 20);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);   /* the exact T = 0 section: its surface is made with the oscillator */
    c.s.dof = SF_DOF_3;
    c.s.cof_generator = SF_COFGEN_CIRCULANT;
    c.s.exact_section = 1;
    assert_int_equal(osc(&c), SF_SUCCESS);
    assert_true(walk("oscillator, 3-DOF on a field, exact section", osc, &c, SF_SUCCESS, 0) > 20);
    memset(&c, 0, sizeof c);
    scene_small(&c.s);
    c.s.dof = SF_DOF_3;
    c.s.cof_generator = SF_COFGEN_TILES;
    assert_int_equal(osc(&c), SF_SUCCESS);
    walk("oscillator, 3-DOF on a tiled window", osc, &c, SF_SUCCESS, 0);
    memset(&c, 0, sizeof c);
    scene_cellavg(&c.s);   /* the Cartesian quadrature on cell averages */
    assert_int_equal(sf_numplan_cell_average(&c.s, NULL, NULL), 1);
    assert_int_equal(osc(&c), SF_SUCCESS);
    assert_true(walk("oscillator, 3-DOF on cell averages", osc, &c, SF_SUCCESS, 0) > 20);
    c.planned = 1;
    assert_int_equal(osc(&c), SF_SUCCESS);
    assert_true(walk("oscillator, 3-DOF on cell averages, on the plan made first", osc, &c, SF_SUCCESS, 0) > 20);
}

static void *ws_alloc(void *ctx)
{
    (void)ctx;
    return sf_malloc(16);   /* a workspace that can fail like the solver's */
}

static int realise(void *ws, size_t i, gsl_rng *rng, double *out)
{
    (void)ws;
    out[0] = (double)i + gsl_rng_uniform(rng);
    return SF_SUCCESS;
}

static int mc(void *ctx)
{
    double out[5];
    sf_mc_ops ops = { ws_alloc, free, realise };
    sf_mc_spec sp = { 5, 1, 11, 1, ctx, 0, 0x5f, NULL };
    int rc = sf_mc_run(&sp, &ops, NULL, out, NULL, NULL, 0);
    if (!rc)
        assert_true(out[4] >= 4 && out[4] < 5);
    return rc;
}

static void montecarlo(void **state)
{
    (void)state;
    char ck[64];
    snprintf(ck, sizeof ck, "/tmp/sf-faults-%ld.ck", (long)getpid());
    walk("sf_mc_run", mc, NULL, SF_SUCCESS, 0);
    walk("sf_mc_run, checkpoint", mc, ck, SF_SUCCESS, 0);
    unlink(ck);
}

static int sweep(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run(ctx, 2, 1, NULL, 0, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_int_equal(pt.n_valid, 2);
    else if (rc != SF_ENOMEM)
        print_message("sweep: %s\n", err);
    sf_sweep_point_free(&pt);
    return rc;
}

static int sweep2(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run_target(ctx, 1e-6, 2, 3, 1, NULL, 0, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_true(pt.n == 3 && pt.stop == SF_MCSTOP_CAP);
    sf_sweep_point_free(&pt);
    return rc;
}

static int sweep_cv(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run_cv(ctx, 3, 1, NULL, 0, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_true(pt.companion && isfinite(pt.cv[0].mean));
    sf_sweep_point_free(&pt);
    return rc;
}

static int sweep_mlmc(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run_mlmc(ctx, 2, 2, 1, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_true(pt.ml.n[1] >= 2 && isfinite(pt.ml.q[0].mean));
    sf_sweep_point_free(&pt);
    return rc;
}

static int sweep_anti(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run_antithetic(ctx, 2, 2, 1, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_true(pt.anti.n == 2 && isfinite(pt.anti.q[0].mean));
    sf_sweep_point_free(&pt);
    return rc;
}

static int sweep_boxes(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run_mlmc_boxes(ctx, 2, 2, 1, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_true(pt.ml.n[1] >= 2 && isfinite(pt.ml.q[0].mean));
    sf_sweep_point_free(&pt);
    return rc;
}

static int sweep_sub(void *ctx)
{
    sf_sweep_point pt;
    char err[256] = "";
    int rc = sf_sweep_run_mlmc_sub(ctx, 2, 2, 1, NULL, &pt, err, sizeof err);
    if (!rc)
        assert_true(pt.ml.n[1] >= 2 && isfinite(pt.ml.q[0].mean));
    sf_sweep_point_free(&pt);
    return rc;
}

/* a small field scene for the sweep's walks */
static void scene_sweep(sf_scene *s)
{
    scene_small(s);
    s->T = 20;
    s->t_skip = 2;
    s->cof_generator = SF_COFGEN_CIRCULANT;
}

static void sweeps(void **state)
{
    (void)state;
    sf_scene s;
    scene_sweep(&s);
    assert_true(walk("sf_sweep_run", sweep, &s, SF_SUCCESS, 0) > 20);
    assert_true(walk("sf_sweep_run_target", sweep2, &s, SF_SUCCESS, 0) > 20);
    assert_true(walk("sf_sweep_run_cv", sweep_cv, &s, SF_SUCCESS, 0) > 20);
}

/* The walks of the estimators on pairs (antithetic, two levels on a
 * derived coarse field): ~1250 failing runs, a test of their own that
 * scripts/valgrind.sh leaves to make test's AddressSanitizer build (its
 * leak checker runs each path; under memcheck they would take ~18 min
 * of the CI machine). */
static void sweeps_mlmc_derived(void **state)
{
    (void)state;
    sf_scene s;
    scene_sweep(&s);
    assert_true(walk("sf_sweep_run_antithetic", sweep_anti, &s, SF_SUCCESS, 0) > 20);
    assert_true(walk("sf_sweep_run_mlmc_sub", sweep_sub, &s, SF_SUCCESS, 0) > 20);
    scene_sweep(&s);   /* boxes of boxes need cell averages: few, for a short walk */
    s.cof_model = SF_COFMODEL_CELL;
    s.cells = 8;
    s.l = 0.05;
    s.T = 14;
    s.t_skip = 4;
    assert_true(walk("sf_sweep_run_mlmc_boxes", sweep_boxes, &s, SF_SUCCESS, 0) > 20);
}

/* the two-level sweep's walk: a test of its own, the longest (about half
 * of the program's time), so scripts/valgrind.sh can run it beside the
 * rest (SF_TEST_ONLY / SF_TEST_SKIP, main below) */
static void sweeps_mlmc(void **state)
{
    (void)state;
    sf_scene s;
    scene_sweep(&s);
    assert_true(walk("sf_sweep_run_mlmc", sweep_mlmc, &s, SF_SUCCESS, 0) > 20);
}

/* the numerical error of a sweep point's means: a point computed once,
 * then the companions of its subset walked */
typedef struct {
    const sf_scene *s;
    sf_sweep_point *p;
} unum_ctx;

static int unum_sweep(void *ctx)
{
    unum_ctx *c = ctx;
    char err[256] = "";
    int rc = sf_unum_sweep(c->s, c->p, 1, err, sizeof err);
    if (!rc)
        assert_true(c->p->num[0].n_sub == 2 && c->p->num[0].n_used == 2 && isfinite(c->p->num[0].u_mean));
    else
        assert_true(c->p->num[0].n_sub == 0);   /* left unestimated */
    return rc;
}

static void unum_sweeps(void **state)
{
    (void)state;
    sf_scene s;
    scene_sweep(&s);
    sf_sweep_point pt;
    char err[256] = "";
    assert_int_equal(sf_sweep_run(&s, 2, 1, NULL, 0, NULL, &pt, err, sizeof err), SF_SUCCESS);
    unum_ctx c = { &s, &pt };
    assert_true(walk("sf_unum_sweep", unum_sweep, &c, SF_SUCCESS, 0) > 10);
    sf_sweep_point_free(&pt);
}

/* ---- Sobol' indices */

static int sobol_design(void *ctx)
{
    (void)ctx;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    sf_sobol_design *D = (sf_sobol_design *)1;
    int rc = sf_sobol_design_alloc(4, 2, g, &D);
    gsl_rng_free(g);
    if (rc)
        assert_null(D);
    sf_sobol_design_free(D);
    return rc;
}

static int sobol_estimate(void *ctx)
{
    const sf_sobol_design *D = ctx;
    double y[16];
    for (int e = 0; e < 16; e++)
        y[e] = sin(e);
    sf_sobol_result r;
    return sf_sobol_estimate(D, y, 1, 5, 0.9, 1, &r, NULL);
}

static int sobol_rank(void *ctx)
{
    (void)ctx;
    double x[24], y[12];
    for (int j = 0; j < 24; j++)
        x[j] = sin(3 * j);
    for (int j = 0; j < 12; j++)
        y[j] = x[2 * j] + cos(j);
    sf_sobol_rank_result r;
    int rc = sf_sobol_rank_s1(12, 2, x, 2, y, 1, 5, 0.9, 1, &r);
    if (!rc)
        assert_true(isfinite(r.idx[1].se));
    return rc;
}

static int sens(void *ctx)
{
    sf_sens_ranges r;
    sf_sens_ranges_default(&r);
    r.lo[SF_SENS_LOGLR] = 2;   /* one COF value per run: cheap runs */
    r.hi[SF_SENS_LOGLR] = 2.1;
    sf_sens *S = (sf_sens *)1;
    char err[300];
    int rc = sf_sens_run(ctx, &r, 2, 4, 0.9, 1, NULL, &S, err, sizeof err);
    if (rc)
        assert_null(S);
    sf_sens_free(S);
    return rc;
}

static void sobol(void **state)
{
    (void)state;
    assert_int_equal(walk("sf_sobol_design_alloc", sobol_design, NULL, SF_SUCCESS, 0), 3);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    sf_sobol_design *D;
    assert_int_equal(sf_sobol_design_alloc(4, 2, g, &D), SF_SUCCESS);
    gsl_rng_free(g);
    assert_int_equal(walk("sf_sobol_estimate", sobol_estimate, D, SF_SUCCESS, 0), 5);
    assert_int_equal(walk("sf_sobol_rank_s1", sobol_rank, NULL, SF_SUCCESS, 0), 8);
    sf_sobol_design_free(D);
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    s.T = 60;
    s.t_skip = 1;
    /* the study's own allocations and its first runs' (a full walk would
     * repeat the 14 runs some 1500 times: each run's own allocations are
     * walked by the oscillator's and the plan's walks above) */
    for (long k = 0; k < 40; k++) {
        sf_fault_arm(k);
        int rc = sens(&s);
        assert_true(sf_fault_fired());
        assert_int_equal(rc, SF_ENOMEM);
    }
    sf_fault_arm(-1);
    assert_int_equal(sens(&s), SF_SUCCESS);
}

/* ---- the periodogram, text files */

static int periodogram(void *ctx)
{
    (void)ctx;
    double x[16], f[9], p[9];
    for (int i = 0; i < 16; i++)
        x[i] = sin(i);
    return sf_periodogram(x, 16, 0.1, f, p);
}

static int read_text(void *ctx)
{
    char *t = (char *)1;
    size_t n;
    int rc = sf_read_text(ctx, "scene", &t, &n, NULL, 0);
    if (rc)
        assert_null(t);
    free(t);
    return rc;
}

static void misc(void **state)
{
    (void)state;
    assert_int_equal(walk("sf_periodogram", periodogram, NULL, SF_SUCCESS, 0), 3);
    char path[64];
    snprintf(path, sizeof path, "/tmp/sf-faults-%ld.scene", (long)getpid());
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("T = 3\n", f);
    fclose(f);
    assert_int_equal(walk("sf_read_text", read_text, path, SF_SUCCESS, 0), 1);
    unlink(path);
}

int main(void)
{
    sf_init();
    /* a subset, by CMocka's name patterns: scripts/valgrind.sh splits the
     * walks over two processes */
    const char *only = getenv("SF_TEST_ONLY"), *skip = getenv("SF_TEST_SKIP");
    if (only)
        cmocka_set_test_filter(only);
    if (skip)
        cmocka_set_skip_filter(skip);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cof_allocs),
        cmocka_unit_test(cof_plans),
        cmocka_unit_test(cof_more),
        cmocka_unit_test(belt_noise),
        cmocka_unit_test(estimator_rules),
        cmocka_unit_test(fields),
        cmocka_unit_test(contacts),
        cmocka_unit_test(oscillator),
        cmocka_unit_test(montecarlo),
        cmocka_unit_test(sweeps),
        cmocka_unit_test(sweeps_mlmc),
        cmocka_unit_test(sweeps_mlmc_derived),
        cmocka_unit_test(unum_sweeps),
        cmocka_unit_test(sobol),
        cmocka_unit_test(misc),
    };
    return cmocka_run_group_tests_name("faults", tests, NULL, NULL);
}
