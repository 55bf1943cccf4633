/* Unit tests: the white noise fixed in belt coordinates (noise.h), the
 * plan's belt-noise branches (numplan.c: sf_plan_cof,
 * sf_numplan_cell_average, sf_plan_explain), the belt-noise window and
 * point (cof.c: belt_noise, x_off, sf_cof_plan_point) and the tiles' other
 * noise source (tiles.c: sf_tiles_set_noise, sf_tiles_noise_rows). */
#include "test_util.h"
#include "cof.h"
#include "lognormal.h"
#include "noise.h"
#include "numplan.h"
#include "scene.h"
#include "sf_error.h"
#include "tiles.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_rng.h>

#define SQRT2 1.4142135623730951

/* Columns i0 .. i0 + n - 1 of z (nr rows each) into out[(i - i0) nr + r]:
 * each column copied before the next call (sf_noise_column's pointer is
 * valid until then). */
static void columns(sf_noise *z, long i0, size_t n, size_t nr, double *out)
{
    for (size_t c = 0; c < n; c++)
        memcpy(out + c * nr, sf_noise_column(z, i0 + (long)c), nr * sizeof *out);
}

/* ---- sf_noise_level, sf_noise_alloc */

static void noise_level(void **state)
{
    (void)state;
    int L = -7;
    double h = -7;
    const double bad[] = { 0, -1, NAN, INFINITY, -INFINITY, 8 * SQRT2 * SF_NOISE_H0 * 1.001, 1e300,
                           1e-11 /* below level 48's range (2.06e-11, 4.12e-11] */, 1e-300, 5e-324 };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        assert_int_equal(sf_noise_level(bad[k], &L, &h), SF_EINVAL);
        assert_int_equal(L, -7);   /* outputs untouched */
        assert_true(h == -7);
    }
    const double ok[] = { 1e-3, 0.005, 0.05, 0.1, 0.25, 1, 3.7, 500, 1000, 11585 /* just below 8 sqrt2 H0 */,
                          3e-11 /* level 48 */, 0.0884, 0.0885 };
    for (size_t k = 0; k < sizeof ok / sizeof *ok; k++) {
        double l = ok[k];
        assert_int_equal(sf_noise_level(l, &L, &h), SF_SUCCESS);
        assert_true(L >= 0 && L <= SF_NOISE_MAX_LEVEL);
        assert_true(h == ldexp(SF_NOISE_H0, -L));   /* exactly a dyadic cell side */
        assert_true(l / (8 * SQRT2) <= h && h < l / (4 * SQRT2));
        assert_true(l / h > 4 * SQRT2 && l / h <= 8 * SQRT2 * (1 + 1e-15));
    }
    assert_int_equal(sf_noise_level(11585, &L, &h), SF_SUCCESS);
    assert_int_equal(L, 0);
    assert_true(h == SF_NOISE_H0);
    assert_int_equal(sf_noise_level(3e-11, &L, &h), SF_SUCCESS);
    assert_int_equal(L, SF_NOISE_MAX_LEVEL);
    assert_int_equal(sf_noise_level(0.1, &L, &h), SF_SUCCESS);   /* l/h = 6.4 */
    assert_int_equal(L, 16);
    assert_true(h == 0.015625);
    /* a switch of level where l / (8 sqrt 2) crosses a cell side: h doubles */
    double h1, h2;
    int L1, L2;
    double lsw = 8 * SQRT2 * ldexp(SF_NOISE_H0, -10);
    assert_int_equal(sf_noise_level(lsw * (1 - 1e-9), &L1, &h1), SF_SUCCESS);
    assert_int_equal(sf_noise_level(lsw * (1 + 1e-9), &L2, &h2), SF_SUCCESS);
    assert_int_equal(L1, 10);   /* l / h = 8 sqrt 2 - : level 10, h = 1 m */
    assert_int_equal(L2, 9);    /* l / h = 4 sqrt 2 + : level 9, h = 2 m */
    assert_true(h1 == 1);
    assert_true(h2 == 2 * h1);
    /* at the switch itself l / h = 8 sqrt 2: the closed end, the finer level */
    assert_int_equal(sf_noise_level(lsw, &L1, &h1), SF_SUCCESS);
    assert_int_equal(L1, 10);
    assert_true(h1 == 1);
    assert_int_equal(sf_noise_level(8 * SQRT2 * SF_NOISE_H0, &L1, &h1), SF_SUCCESS);   /* the largest l */
    assert_int_equal(L1, 0);
    assert_int_equal(sf_noise_level(8 * SQRT2 * SF_NOISE_H0 * (1 + 1e-15), &L1, &h1), SF_EINVAL);
}

static void noise_alloc_refusals(void **state)
{
    (void)state;
    sf_noise *z = (sf_noise *)1;
    assert_int_equal(sf_noise_alloc(3, 0, 0, &z), SF_EINVAL);
    assert_null(z);
    z = (sf_noise *)1;
    assert_int_equal(sf_noise_alloc(-1, 0, 4, &z), SF_EINVAL);
    assert_null(z);
    z = (sf_noise *)1;
    assert_int_equal(sf_noise_alloc(SF_NOISE_MAX_LEVEL + 1, 0, 4, &z), SF_EINVAL);
    assert_null(z);
    assert_int_equal(sf_noise_alloc(SF_NOISE_MAX_LEVEL, -3, 1, &z), SF_SUCCESS);   /* the deepest, one row */
    sf_noise_set_key(z, 5);
    double v = sf_noise_column(z, -1)[0];
    assert_true(isfinite(v));
    sf_noise_free(z);
    sf_noise_free(NULL);
}

/* ---- one white noise across levels */

/* Level L over rows [r0, r0 + n), columns [i0, i0 + nc), against level
 * L + d over the children's rows and columns: each cell is 2^-d times the
 * sum of its 4^d descendants (W(cell) / h_L = sum W(child) / h_L, and a
 * child's value is W(child) / h_(L+d)).  The finer level's columns are
 * read backwards (another order through its cache). */
static void check_levels(uint64_t key, int L, int d, long r0, size_t n, long i0, size_t nc)
{
    sf_noise *a, *b;
    size_t f = (size_t)1 << d, fn = f * n, fc = f * nc;
    assert_int_equal(sf_noise_alloc(L, r0, n, &a), SF_SUCCESS);
    assert_int_equal(sf_noise_alloc(L + d, (long)f * r0, fn, &b), SF_SUCCESS);
    sf_noise_set_key(a, key);
    sf_noise_set_key(b, key);
    double *pa = malloc(nc * n * sizeof *pa), *pb = malloc(fc * fn * sizeof *pb);
    assert_non_null(pa);
    assert_non_null(pb);
    columns(a, i0, nc, n, pa);
    for (size_t c = fc; c-- > 0;)
        memcpy(pb + c * fn, sf_noise_column(b, (long)f * i0 + (long)c), fn * sizeof *pb);
    double ss = 0;
    for (size_t c = 0; c < nc; c++)
        for (size_t r = 0; r < n; r++) {
            double s = 0;
            for (size_t u = 0; u < f; u++)
                for (size_t v = 0; v < f; v++)
                    s += pb[(f * c + u) * fn + f * r + v];
            double p = pa[c * n + r];
            if (!(fabs(p - s / (double)f) <= 1e-12)) {
                print_error("level %d cell (%ld, %ld) = %.17g, its level-%d descendants give %.17g\n", L,
                            i0 + (long)c, r0 + (long)r, p, L + d, s / (double)f);
                fail();
            }
            ss += p * p;
        }
    assert_true(ss > 0.25 * (double)(nc * n));   /* not a zero noise */
    free(pa);
    free(pb);
    sf_noise_free(a);
    sf_noise_free(b);
}

static void one_noise_across_levels(void **state)
{
    (void)state;
    /* negative rows and columns (floor division), across block boundaries
     * (columns around -64, 0 and 64 at level L, around -128 .. 128 at L + 1) */
    check_levels(0x1234abcdULL, 5, 1, -7, 12, -65, 136);
    check_levels(0x1234abcdULL, 5, 2, -7, 12, -65, 136);   /* two levels apart */
    check_levels(99, 0, 1, -3, 6, -70, 141);               /* the root */
    check_levels(99, 1, 1, 3, 5, 60, 10);                  /* positive rows, odd r0 */
    check_levels(7, 20, 1, -1000001, 9, -129, 3);          /* far from the origin */
    check_levels(7, SF_NOISE_MAX_LEVEL - 1, 1, 1000, 5, -3, 7);   /* the deepest levels */
}

/* ---- random access, the cache, the key */

static void noise_random_access(void **state)
{
    (void)state;
    const int L = 10;
    const long r0 = -5;
    const size_t nr = 25;
    sf_noise *a, *b;
    assert_int_equal(sf_noise_alloc(L, r0, nr, &a), SF_SUCCESS);
    assert_int_equal(sf_noise_alloc(L, r0, nr, &b), SF_SUCCESS);
    sf_noise_set_key(a, 42);
    sf_noise_set_key(b, 42);
    double first[25], again[25], other[25], k2[25];
    const long i = 3;
    memcpy(first, sf_noise_column(a, i), sizeof first);
    /* columns a root block apart (64 2^L columns): a block of their own at
     * every level, 12 of them, so every level's 3 slots are evicted */
    long far = 64L << L;
    for (long m = 1; m <= 6; m++) {
        assert_true(isfinite(sf_noise_column(b, i + m * far)[0]));
        assert_true(isfinite(sf_noise_column(b, i - m * far)[0]));
    }
    memcpy(again, sf_noise_column(b, i), sizeof again);   /* first requested after the others */
    assert_memory_equal(first, again, sizeof first);
    for (long m = 1; m <= 6; m++) {
        assert_true(isfinite(sf_noise_column(a, i + m * far)[0]));
        assert_true(isfinite(sf_noise_column(a, i - 2 * m * far - 1)[0]));
    }
    memcpy(again, sf_noise_column(a, i), sizeof again);   /* again, after the evictions */
    assert_memory_equal(first, again, sizeof first);
    memcpy(again, sf_noise_column(a, i), sizeof again);   /* again, from the cache */
    assert_memory_equal(first, again, sizeof first);
    /* the neighbouring column in the same block: another column */
    memcpy(other, sf_noise_column(a, i + 1), sizeof other);
    assert_true(memcmp(first, other, sizeof first) != 0);
    /* another key, another noise; set_key drops what was cached */
    sf_noise_set_key(a, 43);
    memcpy(k2, sf_noise_column(a, i), sizeof k2);
    assert_true(memcmp(first, k2, sizeof first) != 0);
    sf_noise_set_key(b, 43);
    sf_noise_column(b, i + 700);
    memcpy(again, sf_noise_column(b, i), sizeof again);
    assert_memory_equal(k2, again, sizeof k2);
    sf_noise_set_key(a, 42);
    memcpy(again, sf_noise_column(a, i), sizeof again);
    assert_memory_equal(first, again, sizeof first);
    /* a noise over other rows holds the same cells where the rows overlap */
    sf_noise *c;
    assert_int_equal(sf_noise_alloc(L, r0 + 7, 3, &c), SF_SUCCESS);
    sf_noise_set_key(c, 42);
    assert_memory_equal(sf_noise_column(c, i), first + 7, 3 * sizeof *first);
    sf_noise_free(c);
    /* key 0 is a noise too (not a zero one) */
    sf_noise_set_key(a, 0);
    double s2 = 0;
    for (size_t r = 0; r < nr; r++)
        s2 += sf_noise_column(a, i)[r] * sf_noise_column(a, i)[r];
    assert_true(s2 > 0);
    sf_noise_free(a);
    sf_noise_free(b);
}

/* ---- moments */

static void moments_at(int L, long r0, size_t nr, long i0, size_t nc, uint64_t key)
{
    sf_noise *z;
    assert_int_equal(sf_noise_alloc(L, r0, nr, &z), SF_SUCCESS);
    sf_noise_set_key(z, key);
    double *v = malloc(nc * nr * sizeof *v);
    assert_non_null(v);
    columns(z, i0, nc, nr, v);
    double n = (double)(nc * nr), s = 0, s2 = 0, cx = 0, cy = 0;
    for (size_t c = 0; c < nc; c++)
        for (size_t r = 0; r < nr; r++) {
            double x = v[c * nr + r];
            s += x;
            s2 += x * x;
            if (c + 1 < nc)
                cx += x * v[(c + 1) * nr + r];
            if (r + 1 < nr)
                cy += x * v[c * nr + r + 1];
        }
    double mean = s / n, var = s2 / n - mean * mean;
    double nx = (double)((nc - 1) * nr), ny = (double)(nc * (nr - 1));
    double rx = (cx / nx - mean * mean) / var, ry = (cy / ny - mean * mean) / var;
    print_message("level %d, %.0f cells: mean %.4g, variance %.5g, lag-1 correlation x %.4g, y %.4g\n", L, n, mean,
                  var, rx, ry);
    assert_true(fabs(mean) < 5 / sqrt(n));
    assert_true(fabs(var - 1) < 5 * sqrt(2 / n));
    assert_true(fabs(rx) < 5 / sqrt(nx));
    assert_true(fabs(ry) < 5 / sqrt(ny));
    free(v);
    sf_noise_free(z);
}

/* Cells of the same indices (i, j) at levels L and L + 1 (other places
 * of the belt, whose draws are keyed by another level) are independent:
 * the mean of their product within 5 / sqrt(n) of 0. */
static void levels_independent(int L, long r0, size_t nr, long i0, size_t nc, uint64_t key)
{
    sf_noise *a, *b;
    assert_int_equal(sf_noise_alloc(L, r0, nr, &a), SF_SUCCESS);
    assert_int_equal(sf_noise_alloc(L + 1, r0, nr, &b), SF_SUCCESS);
    sf_noise_set_key(a, key);
    sf_noise_set_key(b, key);
    double *va = malloc(nc * nr * sizeof *va), *vb = malloc(nc * nr * sizeof *vb);
    assert_non_null(va);
    assert_non_null(vb);
    columns(a, i0, nc, nr, va);
    columns(b, i0, nc, nr, vb);
    double n = (double)(nc * nr), c = 0;
    for (size_t k = 0; k < nc * nr; k++)
        c += va[k] * vb[k];
    print_message("levels %d and %d, %.0f cells of the same indices: mean product %.4g\n", L, L + 1, n, c / n);
    assert_true(fabs(c / n) < 5 / sqrt(n));
    free(va);
    free(vb);
    sf_noise_free(a);
    sf_noise_free(b);
}

static void moments(void **state)
{
    (void)state;
    moments_at(8, 0, 400, 0, 500, 2026);            /* 2e5 cells */
    moments_at(13, -201, 400, -250, 500, 77);       /* negative rows and columns, odd start */
    moments_at(0, -100, 200, -100, 200, 3);         /* the root: cells drawn alone */
    moments_at(1, -100, 200, -100, 200, 3);         /* its children */
    levels_independent(0, 1, 200, 1, 200, 11);
    levels_independent(8, 0, 400, 0, 500, 2026);
}

/* ---- the tiles' other noise source */

typedef struct {
    size_t nr;
    double buf[256];
    long calls;
} const_noise;

static const double *ones(void *ctx, long i)
{
    (void)i;
    const_noise *c = ctx;
    c->calls++;
    return c->buf;
}

static void tiles_noise_source(void **state)
{
    (void)state;
    sf_tiles_spec sp = { 5, 0.02, 0.02, 0.1, 0, 16 };
    sf_tiles *t, *u;
    assert_int_equal(sf_tiles_alloc(&sp, &t), SF_SUCCESS);
    assert_int_equal(sf_tiles_alloc(&sp, &u), SF_SUCCESS);
    size_t ky, kx, nr = sf_tiles_noise_rows(t, &ky);
    const double *wx = sf_tiles_weights(t, 0, &kx), *wy = sf_tiles_weights(t, 1, &ky);
    assert_int_equal(nr, 16 + 2 * ky);   /* ny rounded up to 16, Ky each side */
    assert_true(nr <= 256);
    const_noise cn = { nr, { 0 }, 0 };
    for (size_t r = 0; r < nr; r++)
        cn.buf[r] = 1;
    sf_tiles_set_key(t, 9);
    sf_tiles_set_key(u, 9);
    double own[5 * 7], g[5 * 7];
    assert_int_equal(sf_tiles_fill(t, -3, 7, own, 7), SF_SUCCESS);
    sf_tiles_set_noise(t, ones, &cn);
    assert_int_equal(sf_tiles_fill(t, -3, 7, g, 7), SF_SUCCESS);
    assert_true(cn.calls >= 7 + 2 * (long)kx);
    double sx = 0, sy = 0;
    for (size_t a = 0; a < 2 * kx + 1; a++)
        sx += wx[a];
    for (size_t b = 0; b < 2 * ky + 1; b++)
        sy += wy[b];
    for (size_t k = 0; k < 35; k++)   /* a constant noise: G = (sum wx) (sum wy) everywhere */
        assert_close(g[k], sx * sy, 1e-13);
    sf_tiles_set_noise(t, NULL, NULL);   /* back to the tiles' own: the same bits as before */
    assert_int_equal(sf_tiles_fill(t, -3, 7, g, 7), SF_SUCCESS);
    assert_memory_equal(g, own, sizeof g);
    assert_int_equal(sf_tiles_fill(u, -3, 7, g, 7), SF_SUCCESS);
    assert_memory_equal(g, own, sizeof g);
    sf_tiles_free(t);
    sf_tiles_free(u);
}

/* ---- the plan */

/* A field scene on the belt noise; l/R = 1/5, Table 1 otherwise. */
static void belt_scene(sf_scene *s, double l)
{
    sf_scene_default(s);
    s->cof = SF_COF_FIELD;
    s->cof_generator = SF_COFGEN_BELT_NOISE;
    s->l = l;
    s->T = 5;
    s->strip_halfwidth = 0.05;
}

/* The plan's lattice: dx = dy = the level's h, y0 a cell centre
 * -(J + 1/2) h with ny = 2 J + 2 rows and (J + 1/2) h the smallest such
 * half-width that holds W = W0 + 2 h. */
static void check_belt_plan(const sf_scene *s, const sf_plan *p)
{
    int L;
    double h, B0, W0;
    assert_int_equal(sf_noise_level(s->l, &L, &h), SF_SUCCESS);
    const sf_cof_plan_info *in = &p->cof;
    assert_int_equal(in->kind, SF_COF_FIELD);
    assert_int_equal(in->shortcut, 0);
    assert_int_equal(in->belt_noise, 1);
    assert_int_equal(in->noise_level, L);
    assert_int_equal(in->generator, SF_COFGEN_TILES);
    assert_int_equal(p->cof_model, SF_PLAN_MODEL_POINT);
    assert_true(in->dx == h && in->dy == h);
    double J = -in->y0 / h - 0.5;
    assert_true(J >= 0 && J == floor(J));
    assert_int_equal(in->ny, (size_t)(2 * J + 2));
    sf_plan_strip_bounds(s, &B0, &W0);
    double W = W0 + 2 * h;
    assert_true((J + 0.5) * h >= W && (J - 0.5) * h < W);
    assert_true(in->margin >= 2 * h && in->margin >= s->R / 4);
    /* the window: the disc's footprint, the margins and the slack R, with
     * two columns to spare */
    assert_true((double)(in->nx - 1) * h >= 3 * s->R + 3 * in->margin + 2 * h);
}

/* what sf_plan_explain prints for (p, s), into out */
static void explain_text(const sf_plan *p, const sf_scene *s, char *out, size_t cap)
{
    FILE *f = tmpfile();
    assert_non_null(f);
    sf_plan_explain(p, s, f);
    rewind(f);
    size_t len = fread(out, 1, cap - 1, f);
    out[len] = '\0';
    fclose(f);
}

static void plan_branches(void **state)
{
    (void)state;
    sf_scene s;
    sf_plan p;
    char err[256] = "";
    const double ls[] = { 0.005, 0.05, 0.1, 1, 500, 1000 };
    for (size_t k = 0; k < sizeof ls / sizeof *ls; k++) {
        belt_scene(&s, ls[k]);
        if (ls[k] < 0.01) {   /* a small disc: a small window */
            s.R = 0.02;
            s.strip_halfwidth = 0.01;
        }
        assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
        check_belt_plan(&s, &p);
    }
    /* l = 5000 m on a short belt and a stiff spring (E = 1.7 m):
     * (E/l)^2 = 1.2e-7 takes the one-variable shortcut, but not on the
     * belt noise */
    belt_scene(&s, 5000);
    s.T = 1;
    s.k = 3000;
    sf_scene t = s;
    t.cof_generator = SF_COFGEN_AUTO;
    assert_int_equal(sf_plan_cof(&t, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cof.kind, SF_COF_VARIABLE);
    assert_int_equal(p.cof.shortcut, 1);
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    check_belt_plan(&s, &p);
    /* mu_std = 0: the uniform shortcut, belt noise or not */
    s.mu_std = 0;
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cof.kind, SF_COF_VARIABLE);
    assert_int_equal(p.cof.shortcut, 1);
    assert_int_equal(p.cof.belt_noise, 0);
    /* shortcuts = false: the field even at mu_std = 0 */
    s.shortcuts = 0;
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(p.cof.kind, SF_COF_FIELD);
    assert_int_equal(p.cof.belt_noise, 1);
    /* cell averages: the box averages of the belt noise's own field, one
     * level coarser, box centres at most box/3 apart */
    belt_scene(&s, 0.1);
    s.cof_model = SF_COFMODEL_CELL;
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    int lv;
    double hl;
    assert_int_equal(sf_noise_level(s.l, &lv, &hl), SF_SUCCESS);
    assert_int_equal(p.cof.belt_noise, 1);
    assert_int_equal(p.cof.generator, SF_COFGEN_TILES);
    assert_int_equal(p.cof.noise_level, lv - 1);
    assert_true(p.cof.box > 0 && p.cof.box_step >= 1);
    assert_true(p.cof.dx <= p.cof.box / 3 || p.cof.box_step == 1);
    assert_close(p.cof.dx, 2 * hl * (double)p.cof.box_step, 1e-15);
    sf_cof_plan *cp;
    assert_int_equal(sf_cof_plan_alloc(&s, &cp, err, sizeof err), SF_SUCCESS);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *w, *a;
    assert_int_equal(sf_cof_plan_draw(cp, g, &w), SF_SUCCESS);
    assert_close(sf_cof_box(w), p.cof.box, 0);
    assert_int_equal(sf_cof_plan_antithetic(cp, w, &a), SF_SUCCESS);
    assert_true(sf_cof_key(a) == sf_cof_key(w));
    double mu;
    assert_int_equal(sf_cof_plan_point(cp, g, 0, 0, &mu), SF_EINVAL);   /* point values: the point model's */
    sf_cof_free(w);
    sf_cof_free(a);
    gsl_rng_free(g);
    sf_cof_plan_free(cp);
    s.cof_model = SF_COFMODEL_POINT;
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    check_belt_plan(&s, &p);
    /* precorrect: the tiles make Eq. 2 only */
    s.cof_model = SF_COFMODEL_AUTO;
    s.precorrect = 1;
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "precorrect"));
    /* l above the root level's range */
    belt_scene(&s, 8 * SQRT2 * SF_NOISE_H0 * 1.01);
    err[0] = '\0';
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "belt_noise"));
    assert_non_null(strstr(err, "outside the noise's levels"));
    s.l = 1e-12;   /* below the deepest level's */
    err[0] = '\0';
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "belt_noise"));
    /* cof_model = auto at l/R = 0.01: cell averages on the circulant and
     * on the belt noise (its box averages), the same cells; point values
     * when the scene asks for them */
    sf_scene_default(&s);
    s.l = 0.005;
    s.T = 2;
    s.t_skip = 0;
    s.strip_halfwidth = 0.01;
    size_t cells = 0, bcells = 0;
    double box = -1, bbox = -1;
    assert_int_equal(sf_numplan_cell_average(&s, &cells, &box), 1);
    s.cof_generator = SF_COFGEN_BELT_NOISE;
    assert_int_equal(sf_numplan_cell_average(&s, &bcells, &bbox), 1);
    assert_int_equal(bcells, cells);
    assert_true(bbox == box);
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_true(p.cof.box == box && p.cof.belt_noise == 1 && p.cof.box_step >= 1);
    {   /* what run --explain says of it */
        sf_plan full;
        char out[16384];
        assert_int_equal(sf_plan_make(&s, &full, err, sizeof err), SF_SUCCESS);
        explain_text(&full, &s, out, sizeof out);
        assert_non_null(strstr(out, "cell-averaged lognormal field (cof_model = auto"));
        assert_non_null(strstr(out, "on the white noise of the belt"));
        s.cof_model = SF_COFMODEL_CELL;
        assert_int_equal(sf_plan_make(&s, &full, err, sizeof err), SF_SUCCESS);
        explain_text(&full, &s, out, sizeof out);
        assert_non_null(strstr(out, "(cof_model = cell_average) on the white noise"));
        /* the Nataf precorrection has no box average of its own here */
        s.precorrect = 1;
        assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_EINVAL);
        assert_non_null(strstr(err, "precorrect is not supported"));
        s.precorrect = 0;
        s.cof_model = SF_COFMODEL_AUTO;
    }
    s.cof_model = SF_COFMODEL_POINT;
    assert_int_equal(sf_numplan_cell_average(&s, NULL, NULL), 0);
    assert_int_equal(sf_plan_cof(&s, &p, err, sizeof err), SF_SUCCESS);
    check_belt_plan(&s, &p);
    assert_true(p.cof.box == 0);
}

static void plan_explain(void **state)
{
    (void)state;
    sf_scene s;
    sf_plan p;
    char err[256] = "";
    belt_scene(&s, 1);
    s.T = 2;
    assert_int_equal(sf_plan_make(&s, &p, err, sizeof err), SF_SUCCESS);
    char out[16384];
    explain_text(&p, &s, out, sizeof out);
    char *line = strstr(out, "COF: ");
    assert_non_null(line);
    char *eol = strchr(line, '\n');
    assert_non_null(eol);
    *eol = '\0';
    assert_non_null(strstr(line, "belt_noise"));
    assert_non_null(strstr(line, "noise level 13"));   /* l = 1 m: h = 1/8 m */
    assert_non_null(strstr(line, "cells of 0.125 m (l/8)"));
}

/* ---- the window and the point */

typedef struct {
    double l, R, shw;
} pscene;

static void point_scene(sf_scene *s, const pscene *q)
{
    belt_scene(s, q->l);
    s->R = q->R;
    s->strip_halfwidth = q->shw;
    s->T = 2;
}

/* G at lattice node (i, j) from the noise itself: sum_a sum_b wx(a) wy(b)
 * z(i - a, j - b) (tiles.h), lattice column i at x = (i + 1/2) h, row j at
 * y = (j + 1/2) h. */
static double g_from_noise(uint64_t key, int L, double h, double l, long i, long j)
{
    sf_tiles_spec ts = { 2, h, h, l, 0, 0 };
    sf_tiles *t;
    assert_int_equal(sf_tiles_alloc(&ts, &t), SF_SUCCESS);
    size_t kx, ky;
    const double *wx = sf_tiles_weights(t, 0, &kx), *wy = sf_tiles_weights(t, 1, &ky);
    sf_noise *z;
    size_t nr = 2 * ky + 1;
    assert_int_equal(sf_noise_alloc(L, j - (long)ky, nr, &z), SF_SUCCESS);
    sf_noise_set_key(z, key);
    double g = 0;
    for (long a = -(long)kx; a <= (long)kx; a++) {
        const double *col = sf_noise_column(z, i - a);   /* rows j - Ky .. j + Ky */
        double y = 0;
        for (long b = -(long)ky; b <= (long)ky; b++)
            y += wy[b + (long)ky] * col[(long)ky - b];
        g += wx[a + (long)kx] * y;
    }
    sf_noise_free(z);
    sf_tiles_free(t);
    return g;
}

static uint64_t key_of_seed(unsigned long seed)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, seed);
    uint64_t key = (uint64_t)gsl_rng_get(r) << 32;
    key ^= (uint64_t)gsl_rng_get(r);
    gsl_rng_free(r);
    return key;
}

static void point_refusals(void **state)
{
    (void)state;
    sf_scene s;
    pscene q = { 0.1, 0.5, 0.05 };
    point_scene(&s, &q);
    sf_cof_plan *p;
    char err[256] = "";
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double mu = -3;
    assert_int_equal(sf_cof_plan_point(p, NULL, 0, 0, &mu), SF_EINVAL);
    assert_int_equal(sf_cof_plan_point(p, rng, NAN, 0, &mu), SF_EINVAL);
    assert_int_equal(sf_cof_plan_point(p, rng, INFINITY, 0, &mu), SF_EINVAL);
    assert_int_equal(sf_cof_plan_point(p, rng, 0, NAN, &mu), SF_EINVAL);
    assert_int_equal(sf_cof_plan_point(p, rng, 0, -INFINITY, &mu), SF_EINVAL);
    assert_int_equal(sf_cof_plan_point(p, rng, 1e20, 0, &mu), SF_EINVAL);   /* off the lattice's range */
    assert_int_equal(sf_cof_plan_point(p, rng, 0, -1e20, &mu), SF_EINVAL);
    assert_true(mu == -3);
    assert_int_equal(sf_cof_plan_point(p, rng, 0, 0, &mu), SF_SUCCESS);
    assert_true(mu > 0 && isfinite(mu));
    sf_cof_plan_free(p);
    /* another generator: tiles (the same window, its own noise) */
    s.cof_generator = SF_COFGEN_TILES;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    mu = -3;
    assert_int_equal(sf_cof_plan_point(p, rng, 0, 0, &mu), SF_EINVAL);
    sf_cof_plan_free(p);
    s.cof_generator = SF_COFGEN_CIRCULANT;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_point(p, rng, 0, 0, &mu), SF_EINVAL);
    sf_cof_plan_free(p);
    s.cof = SF_COF_UNIFORM;
    assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_point(p, rng, 0, 0, &mu), SF_EINVAL);
    sf_cof_plan_free(p);
    assert_true(mu == -3);
    gsl_rng_free(rng);
}

/* sf_cof_plan_point against the drawn window followed to the point (the
 * same key from the same rng state), at belt points near and far; the
 * window's nodes against the convolution of the noise itself. */
static void point_agrees(void **state)
{
    (void)state;
    const pscene qs[] = { { 0.005, 0.02, 0.01 }, { 0.1, 0.5, 0.05 }, { 1, 0.5, 0.05 }, { 500, 0.5, 0.05 } };
    const double pts[][2] = { { 0, 0 }, { -0.0123, 0.0071 }, { 0.0137, -0.0189 }, { -0.25, 0.02 }, { -3.3, -0.0111 } };
    for (size_t k = 0; k < sizeof qs / sizeof *qs; k++) {
        sf_scene s;
        point_scene(&s, &qs[k]);
        sf_cof_plan *p;
        char err[256] = "";
        assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
        const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
        assert_int_equal(in->belt_noise, 1);
        double h = in->dx;
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        for (size_t q = 0; q < sizeof pts / sizeof *pts; q++) {
            double sc = qs[k].R > 0.1 ? 10 : 1;   /* the small disc: points within its strip */
            double xb = sc * pts[q][0], yb = sc * pts[q][1];
            unsigned long seed = 100 + 7 * q + k;
            gsl_rng_set(rng, seed);
            sf_cof *c;
            assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
            assert_int_equal(sf_cof_follow(c, xb - 0.1 * qs[k].R, xb + 0.1 * qs[k].R), SF_SUCCESS);
            double want = sf_cof_eval(c, xb, yb);
            assert_int_equal(sf_cof_outside(c), 0);
            gsl_rng_set(rng, seed);
            double mu = -1;
            assert_int_equal(sf_cof_plan_point(p, rng, xb, yb, &mu), SF_SUCCESS);
            assert_close(mu, want, 1e-12);
            /* the window's lattice: cell centres; a node from the noise */
            size_t m, n;
            double x0, y0;
            const double *g;
            assert_int_equal(sf_cof_grid_view(c, &m, &n, &x0, &y0, NULL, NULL, &g), SF_SUCCESS);
            double ci = x0 / h - 0.5, cj = y0 / h - 0.5;
            assert_close(ci, round(ci), 1e-9);
            assert_close(cj, round(cj), 1e-9);
            size_t gc = (size_t)floor((xb - x0) / h), gr = (size_t)floor((yb - y0) / h);
            assert_true(gc + 1 < m && gr + 1 < n);
            double gn = g_from_noise(key_of_seed(seed), in->noise_level, h, s.l, lround(ci) + (long)gc,
                                     lround(cj) + (long)gr);
            sf_lognormal ln;
            assert_int_equal(sf_lognormal_init(&ln, s.mu_mean, s.mu_std), SF_SUCCESS);
            assert_close(g[gc + m * gr], sf_lognormal_map(&ln, gn), 1e-12);
            /* at the node itself the point is the node (to the weights' last bits) */
            double xn = x0 + (double)gc * h, yn = y0 + (double)gr * h;
            gsl_rng_set(rng, seed);
            assert_int_equal(sf_cof_plan_point(p, rng, xn, yn, &mu), SF_SUCCESS);
            assert_close(mu, g[gc + m * gr], 1e-12);
            sf_cof_free(c);
        }
        gsl_rng_free(rng);
        sf_cof_plan_free(p);
    }
}

/* The same field whatever v_b and the COF's marginal: at a lattice node
 * (where the point is the node's value, no interpolation) and one key,
 * G = (ln mu - mu_g) / sigma_g is the same for another v_b, mean or CV. */
static void point_same_noise(void **state)
{
    (void)state;
    sf_scene s;
    pscene q = { 0.1, 0.5, 0.05 };
    point_scene(&s, &q);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    char err[256] = "";
    double g[3];
    for (int k = 0; k < 3; k++) {
        sf_scene t = s;
        if (k == 1) {
            t.v_b = 0.5;
            t.mu_mean = 0.3;
        }
        if (k == 2) {
            t.mu_std = 0.2;
            t.T = 40;
        }
        sf_cof_plan *p;
        assert_int_equal(sf_cof_plan_alloc(&t, &p, err, sizeof err), SF_SUCCESS);
        gsl_rng_set(rng, 5);
        double mu;
        double h = sf_cof_plan_get_info(p)->dx;
        assert_true(h == 0.015625);
        assert_int_equal(sf_cof_plan_point(p, rng, (-24 + 0.5) * h, (1 + 0.5) * h, &mu), SF_SUCCESS);
        sf_lognormal ln;
        assert_int_equal(sf_lognormal_init(&ln, t.mu_mean, t.mu_std), SF_SUCCESS);
        g[k] = (log(mu) - ln.mu_g) / ln.sigma_g;
        sf_cof_plan_free(p);
    }
    assert_close(g[1], g[0], 1e-12);
    assert_close(g[2], g[0], 1e-12);
    assert_true(fabs(g[0]) > 1e-3);
    gsl_rng_free(rng);
}

static void antithetic(void **state)
{
    (void)state;
    const pscene qs[] = { { 0.1, 0.5, 0.05 }, { 500, 0.5, 0.05 } };
    for (size_t k = 0; k < 2; k++) {
        sf_scene s;
        point_scene(&s, &qs[k]);
        sf_cof_plan *p;
        char err[256] = "";
        assert_int_equal(sf_cof_plan_alloc(&s, &p, err, sizeof err), SF_SUCCESS);
        if (k == 1)
            sf_cof_plan_keep_columns(p, 1);
        sf_lognormal ln;
        assert_int_equal(sf_lognormal_init(&ln, s.mu_mean, s.mu_std), SF_SUCCESS);
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        sf_cof *c, *a;
        assert_int_equal(sf_cof_plan_draw(p, rng, &c), SF_SUCCESS);
        assert_int_equal(sf_cof_plan_antithetic(p, c, &a), SF_SUCCESS);
        for (int pass = 0; pass < 2; pass++) {
            size_t m, n, ma, na;
            double x0, y0, xa, ya;
            const double *g, *ga;
            assert_int_equal(sf_cof_grid_view(c, &m, &n, &x0, &y0, NULL, NULL, &g), SF_SUCCESS);
            assert_int_equal(sf_cof_grid_view(a, &ma, &na, &xa, &ya, NULL, NULL, &ga), SF_SUCCESS);
            assert_int_equal(m, ma);
            assert_int_equal(n, na);
            assert_true(x0 == xa && y0 == ya);
            int differ = 0;
            for (size_t node = 0; node < m * n; node += 1 + m * n / 97) {
                assert_close(log(ga[node]) - ln.mu_g, -(log(g[node]) - ln.mu_g), 1e-12);
                differ |= ga[node] != g[node];
            }
            assert_true(differ);
            /* far along the belt: both windows slide (the partner copies or makes again) */
            double xf = -4 * qs[k].R - 0.37;
            assert_int_equal(sf_cof_follow(c, xf - qs[k].R, xf + qs[k].R), SF_SUCCESS);
            assert_int_equal(sf_cof_follow(a, xf - qs[k].R, xf + qs[k].R), SF_SUCCESS);
        }
        sf_cof_free(a);
        sf_cof_free(c);
        gsl_rng_free(rng);
        sf_cof_plan_free(p);
    }
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(noise_level),
        cmocka_unit_test(noise_alloc_refusals),
        cmocka_unit_test(one_noise_across_levels),
        cmocka_unit_test(noise_random_access),
        cmocka_unit_test(moments),
        cmocka_unit_test(tiles_noise_source),
        cmocka_unit_test(plan_branches),
        cmocka_unit_test(plan_explain),
        cmocka_unit_test(point_refusals),
        cmocka_unit_test(point_agrees),
        cmocka_unit_test(point_same_noise),
        cmocka_unit_test(antithetic),
    };
    return cmocka_run_group_tests_name("noise", tests, NULL, NULL);
}
