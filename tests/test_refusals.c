/* Unit tests: the solver's refusals and rarely taken branches that no case
 * and no other unit test reaches (coverage of solver/): invalid
 * arguments named by an error code, size caps, padding caps per axis, the
 * tiled window's partial slides, checkpoints of other work, the wrench's
 * hypot fallback on a field.  Each test asserts what the branch is for,
 * not merely that it runs. */
#include "test_util.h"
#include "cof.h"
#include "contact.h"
#include "cycle1d.h"
#include "field.h"
#include "lnfield.h"
#include "lognormal.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "qoi.h"
#include "scene.h"
#include "sf_error.h"
#include "surface.h"
#include "sweep.h"
#include "tiles.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

/* ---- COF */

static void cof_refusals(void **state)
{
    (void)state;
    sf_cof *c = (sf_cof *)1;
    assert_int_equal(sf_cof_alloc_uniform(NAN, &c), SF_EINVAL);
    assert_null(c);
    assert_int_equal(sf_cof_alloc_uniform(-0.1, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_uniform(INFINITY, &c), SF_EINVAL);
    double g[6] = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 };
    assert_int_equal(sf_cof_alloc_grid(1, 6, 0, 0, 1, 1, g, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(6, 1, 0, 0, 1, 1, g, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(3, 2, 0, 0, 0, 1, g, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(3, 2, 0, 0, 1, NAN, g, &c), SF_EINVAL);
    assert_int_equal(sf_cof_alloc_grid(3, 2, 0, 0, 1, 1, NULL, &c), SF_EINVAL);
    /* int indices (sf_cof_view): refused before anything is allocated */
    assert_int_equal(sf_cof_alloc_grid((size_t)INT_MAX / 3 + 1, 3, 0, 0, 1, 1, g, &c), SF_EINVAL);
    assert_null(c);
    assert_int_equal(sf_cof_alloc_grid(3, 2, 0, 0, 1, 1, g, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_points_held(c), 6);
    assert_int_equal(sf_cof_follow(c, -1, 1), SF_SUCCESS);   /* not a window: holds what it holds */
    assert_int_equal(sf_cof_columns_made(c), 0);
    /* covers: the disc must lie on the grid on every side */
    assert_true(sf_cof_covers(c, 1, 0.5, 0.5));
    assert_false(sf_cof_covers(c, 0.4, 0.5, 0.5));   /* off the -x edge */
    assert_false(sf_cof_covers(c, 1.6, 0.5, 0.5));   /* +x */
    assert_false(sf_cof_covers(c, 1, 0.4, 0.5));     /* -y */
    assert_false(sf_cof_covers(c, 1, 0.6, 0.5));     /* +y */
    sf_cof_free(c);
    assert_int_equal(sf_cof_alloc_uniform(0.3, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_points_held(c), 0);
    assert_int_equal(sf_cof_grid_view(c, NULL, NULL, NULL, NULL, NULL, NULL, NULL), SF_EINVAL);
    assert_int_equal(sf_cof_grid_view(NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL), SF_EINVAL);
    sf_cof_free(c);
    sf_cof_free(NULL);
    sf_cof_plan_free(NULL);
}

static void plan_refusals(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    sf_cof_plan *p = (sf_cof_plan *)1;
    char err[256] = "";
    s.mu_mean = 0;   /* no lognormal marginal */
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_EINVAL);
    assert_null(p);
    assert_non_null(strstr(err, "marginal"));
    /* the whole strip over 2^24 points: refused before anything is made */
    sf_scene_default(&s);
    s.cof_generator = SF_COFGEN_CIRCULANT;
    s.cof_model = SF_COFMODEL_POINT;   /* auto would average over cells here (l/R = 0.01) */
    s.l = 0.005;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_ETOOBIG);
    assert_null(p);
    assert_non_null(strstr(err, "belt strip needs"));
    /* a strip under 2^24 points whose embedding (about 4x) is over the
     * field's cap of 2^25: refused by the embedding, named as such */
    sf_scene_default(&s);
    s.cof_generator = SF_COFGEN_CIRCULANT;
    s.cof_model = SF_COFMODEL_POINT;
    s.l = 0.02;
    s.strip_halfwidth = 0.05;
    s.T = 350;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_ETOOBIG);
    assert_non_null(strstr(err, "circulant embedding"));
    /* strip_halfwidth = 0: the strip is as wide as the bound B */
    sf_scene_default(&s);
    s.strip_halfwidth = 0;
    s.T = 5;
    s.l = 0.5;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
    assert_close(in->y0, -in->bound, 1e-15);
    sf_cof_plan_free(p);
    /* tiles with precorrect are refused only when there is something to
     * pre-correct (mu_std > 0) */
    s.cof_generator = SF_COFGEN_TILES;
    s.precorrect = 1;
    s.mu_std = 0;
    s.shortcuts = 0;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_get_info(p)->generator, SF_COFGEN_TILES);
    sf_cof_plan_free(p);
    /* auto with precorrect keeps the circulant however large the strip
     * (here over the circulant's cap: refused as a strip, where the tiles
     * would have planned a window) */
    sf_scene_default(&s);
    s.precorrect = 1;
    s.l = 0.005;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_ETOOBIG);
    assert_non_null(strstr(err, "belt strip needs"));
    /* a uniform plan draws the mean and nothing from the generator */
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 1);
    unsigned long before = gsl_rng_get(rng);
    gsl_rng_set(rng, 1);
    sf_cof *c;
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_get_kind(c), SF_COF_UNIFORM);
    assert_close(sf_cof_eval(c, 3, 4), s.mu_mean, 0);
    assert_int_equal(gsl_rng_get(rng), before);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    gsl_rng_free(rng);
}

/* A plan of sf_test_tiled_scene and a generator for its draws */
static gsl_rng *tiled_plan(sf_cof_plan **p)
{
    sf_scene s;
    sf_test_tiled_scene(&s);
    assert_int_equal(sf_cof_plan_alloc(&s, p, NULL, 0), SF_SUCCESS);
    return gsl_rng_alloc(gsl_rng_mt19937);
}

/* An antithetic pair of tiled windows shares the columns the first made
 * (sf_cof_plan_keep_columns): the partner follows a path the first went
 * along and then beyond; its values are the same bits as a partner that
 * made every column itself, and it made only the columns off the first's
 * path. */
static void window_kept_columns(void **state)
{
    (void)state;
    sf_cof_plan *p;
    gsl_rng *rng = tiled_plan(&p);
    sf_cof *g[2], *a[2];
    for (int keep = 0; keep < 2; keep++) {
        gsl_rng_set(rng, 7);
        sf_cof_plan_keep_columns(p, keep);
        assert_int_equal(sf_cof_plan_draw(p, rng, &g[keep]), SF_SUCCESS);
        assert_int_equal(sf_cof_plan_antithetic(p, g[keep], &a[keep]), SF_SUCCESS);
    }
    double x0, dx, span;
    size_t m;
    assert_int_equal(sf_cof_grid_view(g[1], &m, NULL, &x0, NULL, &dx, NULL, NULL), SF_SUCCESS);
    span = dx * (double)(m - 1);
    for (int keep = 0; keep < 2; keep++)   /* the first window's path: 3 widths towards +x */
        for (int k = 1; k <= 12; k++)
            assert_int_equal(sf_cof_follow(g[keep], x0 + 0.25 * k * span, x0 + 0.25 * k * span + 0.5 * span),
                             SF_SUCCESS);
    size_t made_g = sf_cof_columns_made(g[1]);
    for (int k = 1; k <= 16; k++)   /* the partner's: the same, then a width beyond */
        for (int keep = 0; keep < 2; keep++) {
            assert_int_equal(sf_cof_follow(a[keep], x0 + 0.25 * k * span, x0 + 0.25 * k * span + 0.5 * span),
                             SF_SUCCESS);
            size_t mm, nn;
            const double *u, *v;
            assert_int_equal(sf_cof_grid_view(a[0], &mm, &nn, NULL, NULL, NULL, NULL, &u), SF_SUCCESS);
            assert_int_equal(sf_cof_grid_view(a[1], NULL, NULL, NULL, NULL, NULL, NULL, &v), SF_SUCCESS);
            if (keep)
                assert_memory_equal(u, v, mm * nn * sizeof *u);
        }
    size_t made_a = sf_cof_columns_made(a[1]);
    assert_true(made_a > 0 && made_a < made_g && made_a < sf_cof_columns_made(a[0]));
    /* jumps: the first window's jump to 50 m leaves a hole in the store,
     * where the partner makes its columns (25 m); a return into the hole
     * fills it, and the partner copies (37 m); a jump to 200 m would hold
     * more than 2^22 values: not kept, the partner makes them */
    size_t rows;
    assert_int_equal(sf_cof_grid_view(g[1], NULL, &rows, NULL, NULL, NULL, NULL, NULL), SF_SUCCESS);
    assert_true((double)rows * 200 / dx > 4194304.0 && (double)rows * 50 / dx < 4194304.0);
    const double jump[] = { 50, 25, 37, 37, 200, 200 };
    const int mover[] = { 0, 1, 0, 1, 0, 1 }, makes[] = { 0, 1, 0, 0, 0, 1 };
    for (int step = 0; step < 6; step++) {
        double x = x0 + jump[step];
        size_t before = sf_cof_columns_made(mover[step] ? a[1] : g[1]);
        for (int keep = 0; keep < 2; keep++)
            assert_int_equal(sf_cof_follow(mover[step] ? a[keep] : g[keep], x, x + 0.5 * span), SF_SUCCESS);
        if (!mover[step])
            continue;
        size_t mm, nn;
        const double *u, *v;
        assert_int_equal(sf_cof_grid_view(a[0], &mm, &nn, NULL, NULL, NULL, NULL, &u), SF_SUCCESS);
        assert_int_equal(sf_cof_grid_view(a[1], NULL, NULL, NULL, NULL, NULL, NULL, &v), SF_SUCCESS);
        assert_memory_equal(u, v, mm * nn * sizeof *u);
        assert_int_equal(sf_cof_columns_made(a[1]) > before, makes[step]);
    }
    for (int keep = 0; keep < 2; keep++) {
        sf_cof_free(g[keep]);   /* the partner keeps the shared columns alive */
        assert_int_equal(sf_cof_follow(a[keep], x0, x0 + 0.5 * span), SF_SUCCESS);
        sf_cof_free(a[keep]);
    }
    sf_cof_plan_free(p);
    gsl_rng_free(rng);
}

/* The tiled window slides by part of its width in either direction: the
 * columns both positions hold are moved, only the new ones are made, and
 * a lattice node keeps its value. */
static void window_partial_slides(void **state)
{
    (void)state;
    sf_cof_plan *p;
    gsl_rng *rng = tiled_plan(&p);
    sf_cof *c;
    assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
    size_t m, n;
    double x0, y0, dx, dy;
    const double *g;
    assert_int_equal(sf_cof_grid_view(c, &m, &n, &x0, &y0, &dx, &dy, &g), SF_SUCCESS);
    double xn = x0 + 20 * dx, yn = y0 + 3 * dy, v = sf_cof_eval(c, xn, yn);   /* a lattice node */
    size_t made = sf_cof_columns_made(c);
    double span = dx * (double)(m - 1);
    /* towards -x by 10 columns (xlo just below the window's start) */
    assert_int_equal(sf_cof_follow(c, x0 - 9.5 * dx, x0 - 9.5 * dx + 0.5 * span), SF_SUCCESS);
    assert_int_equal(sf_cof_slides(c), 1);
    size_t d1 = sf_cof_columns_made(c) - made;
    assert_true(d1 > 0 && d1 < m);
    assert_close(sf_cof_eval(c, xn, yn), v, 1e-14);
    /* back towards +x, past the start: the other partial slide */
    double x1;
    assert_int_equal(sf_cof_grid_view(c, NULL, NULL, &x1, NULL, NULL, NULL, NULL), SF_SUCCESS);
    made = sf_cof_columns_made(c);
    assert_int_equal(sf_cof_follow(c, x1 + span - 0.6 * span, x1 + span + 5.5 * dx), SF_SUCCESS);
    assert_int_equal(sf_cof_slides(c), 2);
    size_t d2 = sf_cof_columns_made(c) - made;
    assert_true(d2 > 0 && d2 < m);
    assert_close(sf_cof_eval(c, xn, yn), v, 1e-14);
    /* refusals: an empty or reversed range, non-finite ends, ends beyond
     * the lattice's reach */
    assert_int_equal(sf_cof_follow(c, 1, 0), SF_EINVAL);
    assert_int_equal(sf_cof_follow(c, 0, INFINITY), SF_EINVAL);
    assert_int_equal(sf_cof_follow(c, -INFINITY, 0), SF_EINVAL);
    assert_int_equal(sf_cof_follow(c, 1e20, 1e20), SF_EINVAL);
    sf_cof_free(c);
    sf_cof_plan_free(p);
    gsl_rng_free(rng);
}

/* ---- the circulant field */

static double nan_kernel(double r, void *p)
{
    (void)p;
    return r > 0.3 ? NAN : exp(-r * r);
}

static double gauss_kernel(double r, void *p)
{
    double l = *(const double *)p;
    return exp(-(r / l) * (r / l));
}

static void field_refusals(void **state)
{
    (void)state;
    sf_field_spec sp;
    sf_field *f = (sf_field *)1;
    assert_int_equal(sf_field_alloc(NULL, &f), SF_EINVAL);
    assert_null(f);
    /* each invalid setting alone */
    struct { const char *what; size_t m, n; double dx, dy, l, tol, cap; size_t maxp; } bad[] = {
        { "m = 0", 0, 8, 0.1, 0.1, 1, 1e-12, 16, 1 << 20 },
        { "n = 0", 8, 0, 0.1, 0.1, 1, 1e-12, 16, 1 << 20 },
        { "dx = NaN", 8, 8, NAN, 0.1, 1, 1e-12, 16, 1 << 20 },
        { "dx = 0", 8, 8, 0, 0.1, 1, 1e-12, 16, 1 << 20 },
        { "dy = Inf", 8, 8, 0.1, INFINITY, 1, 1e-12, 16, 1 << 20 },
        { "dy < 0", 8, 8, 0.1, -0.1, 1, 1e-12, 16, 1 << 20 },
        { "l = NaN", 8, 8, 0.1, 0.1, NAN, 1e-12, 16, 1 << 20 },
        { "l = 0", 8, 8, 0.1, 0.1, 0, 1e-12, 16, 1 << 20 },
        { "tol = Inf", 8, 8, 0.1, 0.1, 1, INFINITY, 16, 1 << 20 },
        { "tol < 0", 8, 8, 0.1, 0.1, 1, -1, 16, 1 << 20 },
        { "pad_cap = NaN", 8, 8, 0.1, 0.1, 1, 1e-12, NAN, 1 << 20 },
        { "pad_cap < 1", 8, 8, 0.1, 0.1, 1, 1e-12, 0.5, 1 << 20 },
        { "max_points = 0", 8, 8, 0.1, 0.1, 1, 1e-12, 16, 0 },
        { "m > max_points", 8, 4, 0.1, 0.1, 1, 1e-12, 16, 6 },
        { "n > max_points", 4, 8, 0.1, 0.1, 1, 1e-12, 16, 6 },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sf_field_spec_default(&sp, bad[i].m, bad[i].n, bad[i].dx, bad[i].dy, bad[i].l);
        sp.eig_rel_tol = bad[i].tol;
        sp.pad_cap = bad[i].cap;
        sp.max_points = bad[i].maxp;
        if (sf_field_alloc(&sp, &f) != SF_EINVAL) {
            print_error("%s: not refused\n", bad[i].what);
            fail();
        }
        assert_null(f);
    }
    /* the embedding over max_points: separable and general paths */
    sf_field_spec_default(&sp, 40, 40, 0.1, 0.1, 0.3);
    sp.max_points = 1000;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_ETOOBIG);
    assert_null(f);
    double l = 0.3;
    sp.kernel = gauss_kernel;
    sp.kernel_params = &l;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_ETOOBIG);
    sf_field_free(NULL);
}

static void field_args(void **state)
{
    (void)state;
    sf_field_spec sp;
    sf_field_spec_default(&sp, 8, 6, 0.1, 0.1, 0.2);
    sf_field *f;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_SUCCESS);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double a[48], b[48];
    assert_int_equal(sf_field_sample_pair(NULL, rng, a, b), SF_EINVAL);
    assert_int_equal(sf_field_sample_pair(f, NULL, a, b), SF_EINVAL);
    assert_int_equal(sf_field_sample_pair(f, rng, NULL, b), SF_EINVAL);
    assert_int_equal(sf_field_sample_pair(f, rng, a, NULL), SF_EINVAL);
    assert_int_equal(sf_field_sample_pair(f, rng, a, a), SF_EINVAL);   /* the two fields would overwrite */
    assert_int_equal(sf_field_sample(NULL, rng, a), SF_EINVAL);
    assert_int_equal(sf_field_sample(f, NULL, a), SF_EINVAL);
    assert_int_equal(sf_field_sample(f, rng, NULL), SF_EINVAL);
    assert_int_equal(sf_field_covariance(NULL, a), SF_EINVAL);
    assert_int_equal(sf_field_covariance(f, NULL), SF_EINVAL);
    assert_int_equal(sf_field_first_row(NULL, a), SF_EINVAL);
    assert_int_equal(sf_field_first_row(f, NULL), SF_EINVAL);
    assert_int_equal(sf_field_eigenvalues(NULL, a), SF_EINVAL);
    assert_int_equal(sf_field_eigenvalues(f, NULL), SF_EINVAL);
    /* the target covariance is Eq. 2 */
    assert_close(sf_field_target(f, 0.1, 0.2), exp(-(0.05) / 0.04), 1e-15);
    gsl_rng_free(rng);
    sf_field_free(f);
}

/* Truncation per axis: the padding cap hit along y only; no_padding
 * keeps the minimal period (separable and general); max_points stops the
 * padding; a general kernel on a single row pads along x only. */
static void field_padding(void **state)
{
    (void)state;
    sf_field_spec sp;
    sf_field *f;
    /* x: l/dx small (the minimal embedding is PSD); y: l/dy large */
    sf_field_spec_default(&sp, 8, 8, 1.0, 0.05, 0.5);
    sp.pad_cap = 1;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_ETRUNC);
    const sf_field_info *in = sf_field_get_info(f);
    assert_true(in->truncated);
    assert_int_equal(in->px, in->px_min);
    sf_field_free(f);
    /* no padding: the minimal period, truncated */
    sf_field_spec_default(&sp, 8, 8, 0.05, 0.05, 0.5);
    sp.no_padding = 1;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_ETRUNC);
    in = sf_field_get_info(f);
    assert_int_equal(in->px, in->px_min);
    assert_int_equal(in->py, in->py_min);
    sf_field_free(f);
    double l = 0.5;
    sp.kernel = gauss_kernel;
    sp.kernel_params = &l;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_ETRUNC);
    in = sf_field_get_info(f);
    assert_int_equal(in->px, in->px_min);
    assert_false(in->separable);
    sf_field_free(f);
    /* separable: padding stopped by max_points (below pad_cap) */
    sf_field_spec_default(&sp, 8, 1, 0.05, 0.05, 0.5);
    sp.max_points = 20;
    assert_int_equal(sf_field_alloc(&sp, &f), SF_ETRUNC);
    assert_true(sf_field_get_info(f)->px <= 20);
    sf_field_free(f);
    /* a general kernel on one row: only x is padded */
    sf_field_spec_default(&sp, 8, 1, 0.05, 0.05, 0.5);
    sp.kernel = gauss_kernel;
    sp.kernel_params = &l;
    assert_true(sf_usable(sf_field_alloc(&sp, &f)));
    in = sf_field_get_info(f);
    assert_int_equal(in->py, 1);
    assert_true(in->px > in->px_min);
    sf_field_free(f);
}

/* A NaN in the kernel is not dropped by the extremes (nan_max/nan_min):
 * it shows in lambda_min, lambda_max and cov_error. */
static void field_nan_kernel(void **state)
{
    (void)state;
    sf_field_spec sp;
    sf_field_spec_default(&sp, 6, 6, 0.1, 0.1, 1);
    sp.kernel = nan_kernel;
    sp.pad_cap = 1;
    sf_field *f;
    assert_true(sf_usable(sf_field_alloc(&sp, &f)));
    const sf_field_info *in = sf_field_get_info(f);
    assert_true(isnan(in->lambda_min));
    assert_true(isnan(in->lambda_max));
    assert_true(isnan(in->cov_error));
    sf_field_free(f);
}

static void wisdom_files(void **state)
{
    (void)state;
    char path[5000];
    memset(path, 'a', sizeof path - 1);
    path[0] = '/';
    path[sizeof path - 1] = '\0';
    assert_int_equal(sf_field_wisdom_export(path), SF_EIO);   /* longer than the temporary name's buffer */
    assert_int_equal(sf_field_wisdom_export("/nonexistent-dir-sf/w.wis"), SF_EIO);
    assert_int_equal(sf_field_wisdom_import("/nonexistent-dir-sf/w.wis"), SF_SUCCESS);   /* nothing to import */
    char bad[64];
    snprintf(bad, sizeof bad, "/tmp/sf-refusals-%ld.wis", (long)getpid());
    FILE *f = fopen(bad, "w");
    assert_non_null(f);
    fputs("not wisdom\n", f);
    fclose(f);
    assert_int_equal(sf_field_wisdom_import(bad), SF_EIO);
    unlink(bad);
}

static void lnfield_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.nx = 12;
    s.ny = 10;
    s.dx = s.dy = 0.05;
    sf_lnfield *f = (sf_lnfield *)1;
    s.mu_mean = -1;
    assert_int_equal(sf_lnfield_alloc(&s, &f), SF_EINVAL);
    assert_null(f);
    s.mu_mean = 0.3;
    s.mu_std = 0;
    s.precorrect = 1;   /* nothing to pre-correct: the plain kernel */
    assert_int_equal(sf_lnfield_alloc(&s, &f), SF_SUCCESS);
    assert_close(sf_lnfield_marginal(f)->mean, 0.3, 0);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double g[120], c[120];
    assert_int_equal(sf_lnfield_sample(f, rng, g, c), SF_SUCCESS);   /* the Gaussian field kept */
    for (int i = 0; i < 120; i++)
        assert_close(c[i], 0.3, 1e-15);   /* std 0: the mean everywhere */
    gsl_rng_free(rng);
    sf_lnfield_free(f);
    /* lognormal with std 0: a step CDF; the array map is the pointwise map */
    sf_lognormal ln;
    assert_int_equal(sf_lognormal_init(&ln, 0.3, 0), SF_SUCCESS);
    assert_close(sf_lognormal_cdf(&ln, 0.29), 0, 0);
    assert_close(sf_lognormal_cdf(&ln, 0.3), 1, 0);
    assert_int_equal(sf_lognormal_init(&ln, 0.3, 0.1), SF_SUCCESS);
    double v[3] = { -1, 0, 2 };
    sf_lognormal_map_array(&ln, v, 3);
    assert_close(v[0], sf_lognormal_map(&ln, -1), 0);
    assert_close(v[2], sf_lognormal_map(&ln, 2), 0);
}

/* ---- tiles */

static void tiles_refusals(void **state)
{
    (void)state;
    sf_tiles *t = (sf_tiles *)1;
    sf_tiles_spec bad[] = {
        { 0, 0.02, 0.02, 0.1, 0, 0 },  { 8, 0, 0.02, 0.1, 0, 0 },   { 8, 0.02, NAN, 0.1, 0, 0 },
        { 8, 0.02, 0.02, 0, 0, 0 },    { 8, 0.02, 0.02, INFINITY, 0, 0 }, { 8, 0.02, 0.02, 0.1, -1, 0 },
        { 8, 1e-6, 0.02, 1e3, 0, 0 },  /* a kernel of more than 10^6 taps */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(sf_tiles_alloc(&bad[i], &t), SF_EINVAL);
        assert_null(t);
    }
    assert_int_equal(sf_tiles_alloc(NULL, &t), SF_EINVAL);
    sf_tiles_spec sp = { 8, 0.02, 0.04, 0.1, 3, 32 };   /* kernel cut at 3 l/sqrt(2), 32-column tiles */
    assert_int_equal(sf_tiles_alloc(&sp, &t), SF_SUCCESS);
    assert_int_equal(sf_tiles_tile_cols(t), 32);
    size_t kx, ky;
    sf_tiles_weights(t, 0, &kx);
    const double *wy = sf_tiles_weights(t, 1, &ky);
    assert_int_equal(kx, (size_t)ceil(3 * 0.1 / sqrt(2.0) / 0.02));
    assert_int_equal(ky, (size_t)ceil(3 * 0.1 / sqrt(2.0) / 0.04));
    assert_true(wy[ky] > wy[0]);   /* peaked at lag 0 */
    assert_true(sf_tiles_covariance(t, 0, (long)(2 * ky + 1)) == 0);   /* beyond the y reach */
    double out[16 * 8];
    assert_int_equal(sf_tiles_fill(t, 0, 16, out, 15), SF_EINVAL);   /* ld < m */
    assert_int_equal(sf_tiles_fill(t, 0, 16, NULL, 16), SF_EINVAL);
    sf_tiles_free(t);
}

/* ---- contact, surface */

static void contact_refusals(void **state)
{
    (void)state;
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(0.3, &u), SF_SUCCESS);
    sf_contact *c = (sf_contact *)1;
    sf_contact_spec bad[] = {
        { 0, 9.81, SF_LAYOUT_POLAR, 8 },   { INFINITY, 9.81, SF_LAYOUT_POLAR, 8 }, { 0.5, -1, SF_LAYOUT_POLAR, 8 },
        { 0.5, INFINITY, SF_LAYOUT_POLAR, 8 }, { 0.5, 9.81, SF_LAYOUT_POLAR, 0 }, { 0.5, 9.81, SF_LAYOUT_POLAR, 100001 },
        { 0.5, 9.81, (sf_layout)7, 8 },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(sf_contact_alloc(&bad[i], u, &c), SF_EINVAL);
        assert_null(c);
    }
    assert_int_equal(sf_contact_alloc(NULL, u, &c), SF_EINVAL);
    assert_int_equal(sf_contact_alloc(&bad[0], NULL, &c), SF_EINVAL);
    sf_contact_spec sp = { 0.5, 9.81, SF_LAYOUT_POLAR, 8 };
    assert_int_equal(sf_contact_alloc(&sp, u, &c), SF_SUCCESS);
    double q[3] = { 1, 1, 1 };
    assert_int_equal(sf_contact_wrench(c, 0, 0, NAN, 0, 0, 1, q), SF_EINVAL);
    assert_int_equal(sf_contact_wrench(c, 0, 0, 0, INFINITY, 0, 1, q), SF_EINVAL);
    assert_int_equal(sf_contact_wrench(c, 0, 0, 0, 0, NAN, 1, q), SF_EINVAL);
    assert_int_equal(sf_contact_wrench(c, NAN, 0, 0, 0, 1, 1, q), SF_EINVAL);
    assert_int_equal(sf_contact_wrench(c, 0, INFINITY, 0, 0, 1, 1, q), SF_EINVAL);
    assert_int_equal(sf_contact_wrench(c, 0, 0, 0, 0, 0, 1, q), SF_SUCCESS);   /* at rest: no force */
    assert_true(q[0] == 0 && q[1] == 0 && q[2] == 0);
    sf_contact_free(c);
    sf_cof_free(u);
}

/* A Cartesian layout with an odd number of cells has a cell on the pole of
 * a pure spin: the fast loop hands the call to the hypot loop, which
 * skips that cell; on a constant grid it gives the uniform COF's bits. */
static void wrench_fallback_on_field(void **state)
{
    (void)state;
    double g[4] = { 0.3, 0.3, 0.3, 0.3 };
    sf_cof *u, *grid;
    assert_int_equal(sf_cof_alloc_uniform(0.3, &u), SF_SUCCESS);
    assert_int_equal(sf_cof_alloc_grid(2, 2, -1, -1, 2, 2, g, &grid), SF_SUCCESS);
    sf_contact_spec sp = { 0.5, 9.81, SF_LAYOUT_CARTESIAN, 5 };
    sf_contact *cu, *cg;
    assert_int_equal(sf_contact_alloc(&sp, u, &cu), SF_SUCCESS);
    assert_int_equal(sf_contact_alloc(&sp, grid, &cg), SF_SUCCESS);
    double qu[3], qg[3];
    assert_int_equal(sf_contact_wrench(cu, 0, 0, 0, 0, 2.0, 1, qu), SF_SUCCESS);
    assert_int_equal(sf_contact_wrench(cg, 0, 0, 0, 0, 2.0, 1, qg), SF_SUCCESS);
    assert_true(isfinite(qg[2]) && qg[2] < 0);   /* the torque opposes the spin */
    assert_memory_equal(qu, qg, sizeof qu);
    /* the surface's section on the pole of a pure spin skips that cell too */
    sf_surface *s;
    assert_int_equal(sf_surface_alloc(cg, 0, 0, &s), SF_SUCCESS);
    double q[3];
    sf_surface_point(s, 2 * atan(1.0), 0, q);   /* theta = pi/2: pure spin */
    assert_true(isfinite(q[2]) && q[2] > 0);
    sf_surface_free(s);
    /* the stick margin with no spring force: the radius at angle 0 */
    double m;
    assert_int_equal(sf_contact_stick_margin(cg, 0, 0, 0, 0, 1, &m), SF_SUCCESS);
    assert_true(m > 0 && m <= 0.3 * 9.81 * (1 + 1e-12));
    assert_int_equal(sf_contact_stick_margin(cg, 0, 0, NAN, 0, 1, &m), SF_EINVAL);
    sf_contact_free(cu);
    sf_contact_free(cg);
    sf_cof_free(u);
    sf_cof_free(grid);
}

/* A COF that jumps by 20x across the disc turns the section's force far
 * from the direction psi of the slip: the bracket around alpha is widened
 * until it holds the root, and the root's force points along alpha. */
static void surface_skewed_section(void **state)
{
    (void)state;
    double g[201 * 2];   /* mu = 0.001 for x < 0.2, 1 above (a step over 5 mm) */
    for (int i = 0; i < 201; i++)
        g[i] = g[i + 201] = -0.5 + 0.005 * i < 0.2 ? 0.001 : 1.0;
    sf_cof *c;
    assert_int_equal(sf_cof_alloc_grid(201, 2, -0.5, -1, 0.005, 2, g, &c), SF_SUCCESS);
    sf_contact_spec sp = { 0.5, 9.81, SF_LAYOUT_POLAR, 12 };
    sf_contact *ct;
    assert_int_equal(sf_contact_alloc(&sp, c, &ct), SF_SUCCESS);
    sf_surface *s;
    assert_int_equal(sf_surface_alloc(ct, 0, 0, &s), SF_SUCCESS);
    int widened = 0;
    for (int i = 0; i < 16; i++) {
        double alpha = -3.0 + 0.4 * i, rho, psi, th, q[3];
        assert_int_equal(sf_surface_section_radius(s, alpha, &rho, &psi), SF_SUCCESS);
        assert_int_equal(sf_surface_section(s, psi, &th, q), SF_SUCCESS);
        assert_close(remainder(atan2(q[1], q[0]) - alpha, 2 * M_PI), 0, 1e-9);
        assert_close(hypot(q[0], q[1]), rho, 1e-12);
        widened += fabs(remainder(psi - alpha, 2 * M_PI)) > 0.05;
    }
    assert_true(widened > 0);   /* some psi lies outside the first bracket */
    sf_surface_free(s);
    sf_contact_free(ct);
    sf_cof_free(c);
}

static void surface_zero_cof(void **state)
{
    (void)state;
    sf_cof *z;
    assert_int_equal(sf_cof_alloc_uniform(0, &z), SF_SUCCESS);
    sf_contact_spec sp = { 0.5, 9.81, SF_LAYOUT_POLAR, 6 };
    sf_contact *c;
    assert_int_equal(sf_contact_alloc(&sp, z, &c), SF_SUCCESS);
    sf_surface *s;
    assert_int_equal(sf_surface_alloc(c, 0, 0, &s), SF_SUCCESS);
    double rho = 1, psi = 0;
    assert_int_equal(sf_surface_section_radius(s, 0.7, &rho, &psi), SF_SUCCESS);
    assert_true(rho == 0 && psi == 0.7);   /* no friction: the surface is the origin */
    assert_int_equal(sf_surface_section_radius(s, 0.7, &rho, NULL), SF_SUCCESS);
    sf_surface_free(s);
    sf_contact_free(c);
    sf_cof_free(z);
}

/* ---- dynamics */

static void osc_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.dof = SF_DOF_1;
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &u), SF_SUCCESS);
    sf_osc *o = (sf_osc *)1;
    char err[256] = "";
    /* dof = 1 moves along x only: each of y0, phi0, vy0, w0 refused */
    double *keys[] = { &s.y0, &s.phi0, &s.vy0, &s.w0 };
    for (int i = 0; i < 4; i++) {
        *keys[i] = 0.01;
        assert_int_equal(sf_osc_alloc(&s, u, &o, err, sizeof err), SF_EINVAL);
        assert_null(o);
        *keys[i] = 0;
    }
    s.qoi_tol = 2;   /* the plan refuses */
    assert_int_equal(sf_osc_alloc(&s, u, &o, err, sizeof err), SF_EINVAL);
    assert_null(o);
    assert_non_null(strstr(err, "qoi_tol"));
    s.qoi_tol = 0.01;
    /* a 3-DOF disc on a constant COF computed in full (shortcuts off), on
     * a Cartesian layout: explain says so; the plan and scales are read */
    s.dof = SF_DOF_3;
    s.shortcuts = 0;
    s.layout = SF_LAYOUT_CARTESIAN;
    s.cells = 8;
    assert_int_equal(sf_osc_alloc(&s, u, &o, err, sizeof err), SF_SUCCESS);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    sf_osc_explain(o, f);
    fclose(f);
    assert_non_null(strstr(text, "Cartesian"));
    assert_non_null(strstr(text, "constant COF (shortcuts = false)"));
    free(text);
    assert_int_equal(sf_osc_get_plan(o)->cells, 8);
    double sc[SF_OSC_NSTATE];
    sf_osc_scales(o, sc);
    assert_true(sc[0] > 0 && sc[2] == sc[0] / s.R);
    /* slip_integrate refuses an empty or reversed interval, a step <= 0,
     * or more than 1e8 steps */
    double y0[SF_OSC_NSTATE] = { 0 }, y1[SF_OSC_NSTATE];
    assert_int_equal(sf_osc_slip_integrate(o, 1, y0, 1, 0.1, y1), SF_EINVAL);
    assert_int_equal(sf_osc_slip_integrate(o, 0, y0, 1, 0, y1), SF_EINVAL);
    assert_int_equal(sf_osc_slip_integrate(o, 0, y0, INFINITY, 0.1, y1), SF_EINVAL);
    assert_int_equal(sf_osc_slip_integrate(o, 0, y0, 1, 1e-9, y1), SF_EINVAL);
    sf_osc_free(o);
    /* the adaptive stepper on a closed form: explain names why */
    s.shortcuts = 1;
    s.integrator = SF_INTEG_ADAPTIVE;
    assert_int_equal(sf_osc_alloc(&s, u, &o, err, sizeof err), SF_SUCCESS);
    text = NULL;
    f = open_memstream(&text, &len);
    sf_osc_explain(o, f);
    fclose(f);
    assert_non_null(strstr(text, "closed form"));
    free(text);
    sf_osc_free(o);
    sf_cof_free(u);
}

typedef struct { size_t rows, stick; } rows_seen;

static void count_row(void *ctx, const sf_osc_row *r)
{
    rows_seen *c = ctx;
    c->rows++;
    c->stick += r->stick != 0;
}

/* Rows reach the callback; without the velocity jump the slip starts at
 * the belt speed; Eq. 15 needs the same sampling. */
static void osc_rows_no_jump(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.dof = SF_DOF_1;
    s.T = 20;
    s.t_skip = 2;
    s.velocity_jump = 0;
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &u), SF_SUCCESS);
    sf_osc *o;
    assert_int_equal(sf_osc_alloc(&s, u, &o, NULL, 0), SF_SUCCESS);
    rows_seen c = { 0, 0 };
    sf_osc_result r, r2;
    assert_int_equal(sf_osc_run(o, count_row, &c, 0.1, &r, NULL, 0), SF_SUCCESS);
    assert_true(c.rows > 10 && c.stick > 0 && c.stick < c.rows);
    assert_true(r.ncycles > 0);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0.05, &r2, NULL, 0), SF_SUCCESS);
    assert_true(isnan(sf_osc_error_eq15(&r, &r2)));   /* other sampling: no Eq. 15 error */
    sf_osc_result_free(&r2);
    assert_true(sf_osc_error_eq15(&r, &r) == 0);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(u);
}

/* A constant COF without quadrature: the exact T = 0 section is the
 * circle of radius mu N, so exact_section gives the same bits; Eq. 15
 * needs samples; explain names a field's interpolation. */
static void osc_closed_form_section(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.dof = SF_DOF_3;
    s.T = 20;
    s.t_skip = 2;
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &u), SF_SUCCESS);
    sf_osc_result r[2];
    for (int e = 0; e < 2; e++) {
        s.exact_section = e;
        sf_osc *o;
        assert_int_equal(sf_osc_alloc(&s, u, &o, NULL, 0), SF_SUCCESS);
        assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r[e], NULL, 0), SF_SUCCESS);
        sf_osc_free(o);
    }
    assert_true(r[0].ncycles > 0);
    assert_memory_equal(&r[0].pv_x, &r[1].pv_x, sizeof r[0].pv_x);
    assert_memory_equal(&r[0].stick_fraction, &r[1].stick_fraction, sizeof r[0].stick_fraction);
    assert_true(isnan(sf_osc_error_eq15(&r[0], &r[1])));   /* no samples (sample_dt 0) */
    sf_osc_result_free(&r[0]);
    sf_osc_result_free(&r[1]);
    sf_cof_free(u);
    /* a field: the quadrature interpolates the strip's COF */
    sf_scene_default(&s);
    s.T = 5;
    s.l = 0.5;
    s.strip_halfwidth = 0.05;
    s.cells = 6;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *cof;
    assert_int_equal(sf_cof_from_scene(&s, rng, &cof), SF_SUCCESS);
    sf_osc *o;
    assert_int_equal(sf_osc_alloc(&s, cof, &o, NULL, 0), SF_SUCCESS);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    sf_osc_explain(o, f);
    fclose(f);
    assert_non_null(strstr(text, "COF interpolated from the strip field"));
    free(text);
    sf_osc_free(o);
    sf_cof_free(cof);
    gsl_rng_free(rng);
}

/* RK4 on a tiled window: a fixed dt above the window's step cap is cut
 * to the cap (no look-up off the window). */
static void rk4_window_cap(void **state)
{
    (void)state;
    sf_scene s;
    sf_test_tiled_scene(&s);
    s.dof = SF_DOF_3;
    s.integrator = SF_INTEG_RK4;
    s.dt = 0.5;
    s.T = 8;
    s.t_skip = 0;
    s.cells = 6;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *cof;
    assert_int_equal(sf_cof_from_scene(&s, rng, &cof), SF_SUCCESS);
    sf_osc *o;
    char err[256] = "";
    assert_int_equal(sf_osc_alloc(&s, cof, &o, err, sizeof err), SF_SUCCESS);
    sf_osc_result r;
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
    assert_true(r.steps > (size_t)(s.T / s.dt));   /* capped below dt */
    assert_int_equal(sf_cof_outside(cof), 0);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(cof);
    gsl_rng_free(rng);
}

static void cycle1d_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    sf_cycle1d c;
    assert_int_equal(sf_cycle1d_init(&c, &s, 0), SF_SUCCESS);
    assert_close(sf_cycle1d_transition(&c, 0), c.t_first_stick, 0);   /* n = 0: the first stick */
    s.mu_k_ratio = 1;   /* no drop from static to kinetic friction: no stick-slip cycle */
    assert_int_equal(sf_cycle1d_init(&c, &s, 0), SF_EINVAL);
}

/* ---- Monte Carlo checkpoints */

static int realise(void *ws, size_t i, gsl_rng *rng, double *out)
{
    (void)ws;
    out[0] = (double)i;
    out[1] = gsl_rng_uniform(rng);
    return SF_SUCCESS;
}

static void checkpoint_refusals(void **state)
{
    (void)state;
    char ck[64], err[256];
    snprintf(ck, sizeof ck, "/tmp/sf-refusals-%ld.ck", (long)getpid());
    unlink(ck);
    double out[8], ref[8];
    sf_mc_ops ops = { NULL, NULL, realise };
    sf_mc_spec sp = { 4, 2, 5, 1, ck, 1, 0xabc, NULL };
    size_t before = 99;
    /* resume without a file: nothing to resume */
    assert_int_equal(sf_mc_run(&sp, &ops, NULL, ref, &before, err, sizeof err), SF_SUCCESS);
    assert_int_equal(before, 0);
    /* damaged lines are redone: a bad index, an index out of range, too
     * few values, a repeated line */
    FILE *f = fopen(ck, "w");
    assert_non_null(f);
    fprintf(f, "# slipfield checkpoint v1 n=4 nout=2 key=abc\n");
    fprintf(f, "x 1 2\n7 0x1p+0 0x1p+0\n1 0x1p+0\n2 %a %a\n2 %a %a\n", ref[4], ref[5], ref[4], ref[5]);
    fclose(f);
    memset(out, 0, sizeof out);
    assert_int_equal(sf_mc_run(&sp, &ops, NULL, out, &before, err, sizeof err), SF_SUCCESS);
    assert_int_equal(before, 1);
    assert_memory_equal(out, ref, sizeof ref);
    /* not a checkpoint; a checkpoint of other work */
    f = fopen(ck, "w");
    fputs("hello\n", f);
    fclose(f);
    assert_int_equal(sf_mc_run(&sp, &ops, NULL, out, NULL, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "not a slipfield checkpoint"));
    f = fopen(ck, "w");   /* empty */
    fclose(f);
    assert_int_equal(sf_mc_run(&sp, &ops, NULL, out, NULL, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "not a slipfield checkpoint"));
    const char *other[] = { "# slipfield checkpoint v1 n=4 nout=2 key=abd\n",
                            "# slipfield checkpoint v1 n=5 nout=2 key=abc\n",
                            "# slipfield checkpoint v1 n=4 nout=3 key=abc\n" };
    for (int i = 0; i < 3; i++) {   /* another key, size or output count */
        f = fopen(ck, "w");
        fputs(other[i], f);
        fclose(f);
        assert_int_equal(sf_mc_run(&sp, &ops, NULL, out, NULL, err, sizeof err), SF_EINVAL);
        assert_non_null(strstr(err, "other work"));
    }
    unlink(ck);
    /* the checkpoint cannot replace a directory */
    assert_int_equal(mkdir(ck, 0700), 0);
    sp.resume = 0;
    assert_int_equal(sf_mc_run(&sp, &ops, NULL, out, NULL, err, sizeof err), SF_EIO);
    char tmp[80];
    snprintf(tmp, sizeof tmp, "%s.tmp", ck);
    unlink(tmp);
    rmdir(ck);
    assert_true(sf_mc_hash("a", 1, 7) != sf_mc_hash("a", 1, 0));   /* a running hash */
}

/* ---- sweep, plan, periodogram */

static void sweep_no_cycle(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.T = 3;
    s.t_skip = 2;
    sf_sweep_point pt;
    char err[256] = "";
    assert_int_equal(sf_sweep_run(&s, 2, 1, NULL, 0, NULL, &pt, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "no oscillation or no stick in [t_skip, T]"));
    sf_sweep_point_free(&pt);
    s.qoi_def = SF_QOI_CYCLES;
    assert_int_equal(sf_sweep_run(&s, 2, 1, NULL, 0, NULL, &pt, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "no complete cycle"));
    sf_sweep_point_free(&pt);
}

static void seterr_zero_length(void **state)
{
    (void)state;
    char err[8] = "keep";
    assert_int_equal(sf_seterr(err, 0, SF_EIO, "%s", "overwritten"), SF_EIO);   /* n = 0: nothing written */
    assert_string_equal(err, "keep");
}

static void numplan_edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    sf_numplan p;
    char err[256] = "";
    /* a tight qoi_tol at small l/R: the rings are capped, and the plan
     * says so in its warning and its explanation */
    s.qoi_tol = 1e-6;
    s.l = 0.01;
    assert_int_equal(sf_numplan_make(&s, 1, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cells, SF_PLAN_MAX_RINGS);
    assert_true(p.warning[0] != '\0');
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    sf_numplan_explain(&p, f);
    fclose(f);
    assert_non_null(strstr(text, "plan warning"));
    free(text);
    /* Cartesian cells per diameter: cell size 2R / cells */
    sf_scene_default(&s);
    s.layout = SF_LAYOUT_CARTESIAN;
    s.cells = 20;
    assert_int_equal(sf_numplan_make(&s, 1, &p, err, sizeof err), SF_SUCCESS);
    assert_close(p.cell_size, 2 * s.R / 20, 1e-15);
}

static void periodogram_edges(void **state)
{
    (void)state;
    double x[7] = { 1, 2, 0, -1, 3, 1, 0 }, f[4], p[4];
    assert_int_equal(sf_periodogram(x, 1, 0.1, f, p), SF_EINVAL);
    assert_int_equal(sf_periodogram(x, 7, 0, f, p), SF_EINVAL);
    assert_int_equal(sf_periodogram(x, 7, NAN, f, p), SF_EINVAL);
    /* odd n: no Nyquist bin, every bin but 0 doubled (Parseval) */
    assert_int_equal(sf_periodogram(x, 7, 0.1, f, p), SF_SUCCESS);
    double mean = 0, var = 0, sum = 0;
    for (int i = 0; i < 7; i++)
        mean += x[i] / 7;
    for (int i = 0; i < 7; i++)
        var += (x[i] - mean) * (x[i] - mean) / 7;
    for (int k = 0; k < 4; k++)
        sum += p[k] / (7 * 0.1);
    assert_close(sum, var, 1e-12);
}

/* A draw needs a generator unless the COF is uniform: each kind of plan
 * refuses a NULL rng with SF_EINVAL and hands out nothing. */
static void draw_without_rng(void **state)
{
    (void)state;
    struct { int cof, gen; double l, T; } k[] = {
        { SF_COF_UNIFORM, SF_COFGEN_AUTO, 0.1, 2 },     /* draws nothing: accepted */
        { SF_COF_VARIABLE, SF_COFGEN_AUTO, 0.1, 2 },
        { SF_COF_FIELD, SF_COFGEN_CIRCULANT, 0.1, 2 },  /* the lognormal strip */
        { SF_COF_FIELD, SF_COFGEN_TILES, 0.1, 2 },
        { SF_COF_FIELD, SF_COFGEN_AUTO, 0.005, 2 },     /* auto: cell averages at l/R = 0.01 */
    };
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++) {
        sf_scene s;
        sf_scene_default(&s);
        s.cof = k[i].cof;
        s.cof_generator = k[i].gen;
        s.l = k[i].l;
        s.T = k[i].T;
        s.strip_halfwidth = 0.05;
        sf_cof_plan *p;
        char err[256] = "";
        assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
        sf_cof *c = (sf_cof *)1;
        int rc = sf_cof_plan_draw(p, NULL, &c);
        assert_int_equal(rc, i == 0 ? SF_SUCCESS : SF_EINVAL);
        if (i)
            assert_null(c);
        if (i == 4)
            assert_true(sf_cof_plan_get_info(p)->box > 0);
        sf_cof_free(c);
        sf_cof_plan_free(p);
    }
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cof_refusals),
        cmocka_unit_test(draw_without_rng),
        cmocka_unit_test(plan_refusals),
        cmocka_unit_test(window_partial_slides),
        cmocka_unit_test(window_kept_columns),
        cmocka_unit_test(field_refusals),
        cmocka_unit_test(field_args),
        cmocka_unit_test(field_padding),
        cmocka_unit_test(field_nan_kernel),
        cmocka_unit_test(wisdom_files),
        cmocka_unit_test(lnfield_edges),
        cmocka_unit_test(tiles_refusals),
        cmocka_unit_test(contact_refusals),
        cmocka_unit_test(wrench_fallback_on_field),
        cmocka_unit_test(surface_skewed_section),
        cmocka_unit_test(surface_zero_cof),
        cmocka_unit_test(osc_edges),
        cmocka_unit_test(osc_rows_no_jump),
        cmocka_unit_test(osc_closed_form_section),
        cmocka_unit_test(rk4_window_cap),
        cmocka_unit_test(cycle1d_edges),
        cmocka_unit_test(checkpoint_refusals),
        cmocka_unit_test(sweep_no_cycle),
        cmocka_unit_test(seterr_zero_length),
        cmocka_unit_test(numplan_edges),
        cmocka_unit_test(periodogram_edges),
    };
    return cmocka_run_group_tests_name("refusals", tests, NULL, NULL);
}
