/* Unit tests: the tiled field generator (tiles.h) and the sliding COF
 * window (cof.h, cof_generator = tiles). */
#include "test_util.h"
#include "cof.h"
#include "scene.h"
#include "sf_error.h"
#include "tiles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_rng.h>

/* SplitMix64 from state 0: the reference implementation's first outputs
 * are 0xe220a8397b1dcdaf, 0x6e789e6aa1b965f4 (Vigna's splitmix64.c). */
static void splitmix_reference(void **state)
{
    (void)state;
    gsl_rng *r = gsl_rng_alloc(sf_rng_splitmix64);
    gsl_rng_set(r, 0);
    assert_int_equal(gsl_rng_get(r), 0xe220a839UL);
    assert_int_equal(gsl_rng_get(r), 0x6e789e6aUL);
    assert_int_equal(gsl_rng_max(r), 0xffffffffUL);
    double u = gsl_rng_uniform(r);
    assert_true(u >= 0 && u < 1);
    gsl_rng_free(r);
}

/* Unit variance and Eq. 2 at small lags; zero past the kernel's reach. */
static void produced_covariance(void **state)
{
    (void)state;
    sf_tiles_spec sp = { 8, 0.0125, 0.025, 0.1, 0, 0 };
    sf_tiles *t;
    assert_int_equal(sf_tiles_alloc(&sp, &t), SF_SUCCESS);
    assert_close(sf_tiles_covariance(t, 0, 0), 1.0, 1e-15);
    for (long p = 0; p < 40; p++)
        assert_close(sf_tiles_covariance(t, p, 3), exp(-(p * 0.0125 * p * 0.0125 + 0.075 * 0.075) / 0.01), 1e-15);
    size_t K;
    sf_tiles_weights(t, 0, &K);
    assert_int_equal(K, (size_t)ceil(6 * 0.1 / sqrt(2.0) / 0.0125));
    assert_true(sf_tiles_covariance(t, (long)(2 * K + 1), 0) == 0);
    sf_tiles_free(t);
    sf_tiles_spec bad = { 8, 0, 0.025, 0.1, 0, 0 };
    assert_int_equal(sf_tiles_alloc(&bad, &t), SF_EINVAL);
}

/* Random access: any chunking, any order, a fresh generator: same bits;
 * another key: another field. */
static void random_access(void **state)
{
    (void)state;
    sf_tiles_spec sp = { 21, 0.02, 0.02, 0.1, 0, 16 };
    sf_tiles *a, *b;
    assert_int_equal(sf_tiles_alloc(&sp, &a), SF_SUCCESS);
    assert_int_equal(sf_tiles_alloc(&sp, &b), SF_SUCCESS);
    size_t m = 300;
    double *g = malloc(m * 21 * sizeof *g), *h = malloc(m * 21 * sizeof *h);
    sf_tiles_set_key(a, 42);
    sf_tiles_set_key(b, 42);
    assert_int_equal(sf_tiles_fill(a, -150, m, g, m), SF_SUCCESS);
    for (size_t c = m; c > 0; c -= 7) {   /* chunks of 7 from the end */
        size_t lo = c >= 7 ? c - 7 : 0;
        assert_int_equal(sf_tiles_fill(b, -150 + (long)lo, c - lo, h + lo, m), SF_SUCCESS);
        if (lo == 0)
            break;
    }
    assert_memory_equal(g, h, m * 21 * sizeof *g);
    sf_tiles_set_key(b, 43);
    sf_tiles_fill(b, -150, m, h, m);
    assert_true(memcmp(g, h, m * 21 * sizeof *g) != 0);
    free(g);
    free(h);
    sf_tiles_free(a);
    sf_tiles_free(b);
}

/* auto: the circulant where the strip is small (existing bits), tiles
 * above 2^20 strip points (Table 1's l = 0.1 m below, l = 0.05 m
 * above); precorrect needs the circulant. */
static void generator_choice(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    sf_cof_plan *p;
    char err[256] = "";
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_CIRCULANT);
    assert_true(sf_cof_plan_get_info(p)->strip_points <= (double)SF_COF_AUTO_POINTS);
    sf_cof_plan_free(p);
    s.l = 0.064;   /* 1.05e6 strip points: the last l (in mm) on the circulant */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_CIRCULANT);
    sf_cof_plan_free(p);
    s.l = 0.063;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_TILES);
    sf_cof_plan_free(p);
    s.l = 0.05;   /* l/R = 0.1: 1.7e6 strip points */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_TILES);
    assert_true(sf_cof_plan_get_info(p)->strip_points > (double)SF_COF_AUTO_POINTS);
    sf_cof_plan_free(p);
    s.precorrect = 1;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_CIRCULANT);
    sf_cof_plan_free(p);
    s.cof_generator = SF_COFGEN_TILES;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "precorrect"));
}

/* The window: follows left and right, holds what it is asked for, and a
 * value at a belt point is the same whenever the window holds it (to the
 * last bits only at lattice nodes: between them the bilinear weights come
 * from (x - x0)/dx, which rounds differently for another origin x0). */
static void window_follow(void **state)
{
    (void)state;
    sf_scene s;
    sf_test_tiled_scene(&s);
    sf_cof_plan *p;
    sf_cof *c;
    char err[256] = "";
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_true(sf_cof_window_margin(c) > 0);
    assert_true(sf_cof_covers(c, 0, 0, s.R));
    double v0 = sf_cof_eval(c, 0.123, 0.01), v1;
    assert_true(v0 > 0);
    assert_int_equal(sf_cof_follow(c, -5.7, -4.9), SF_SUCCESS);
    assert_true(sf_cof_covers(c, -5.3, 0, 0.4));
    assert_int_equal(sf_cof_slides(c), 1);
    v1 = sf_cof_eval(c, -5.3, 0.02);
    assert_int_equal(sf_cof_follow(c, -5.5, -4.9), SF_SUCCESS);   /* held: no slide */
    assert_int_equal(sf_cof_slides(c), 1);
    assert_int_equal(sf_cof_follow(c, -0.2, 0.2), SF_SUCCESS);    /* back: a slide towards +x */
    assert_close(sf_cof_eval(c, 0.123, 0.01), v0, 1e-14 * v0);
    assert_int_equal(sf_cof_follow(c, -5.4, -5.2), SF_SUCCESS);
    assert_close(sf_cof_eval(c, -5.3, 0.02), v1, 1e-14 * v1);
    assert_int_equal(sf_cof_follow(c, -5.4, -5.39 + 10), SF_ETOOBIG); /* wider than the window */
    assert_int_equal(sf_cof_follow(c, NAN, 0), SF_EINVAL);
    assert_int_equal(sf_cof_outside(c), 0);
    assert_true(sf_cof_max(c) >= v0 && sf_cof_max(c) >= v1);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    gsl_rng_free(rng);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(splitmix_reference),
        cmocka_unit_test(produced_covariance),
        cmocka_unit_test(random_access),
        cmocka_unit_test(generator_choice),
        cmocka_unit_test(window_follow),
    };
    return cmocka_run_group_tests_name("tiles", tests, NULL, NULL);
}
