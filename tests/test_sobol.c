/* Unit tests: the pick-freeze design and estimators (sobol.h) and the
 * sensitivity study of the QoI ratios (sensitivity.h): the design's
 * blocks, exact zeros of the estimators, a linear model's known indices,
 * the bootstrap's intervals, excluded rows, every refusal, and a small
 * study bit-identical on 1 and 2 threads. */
#include "test_util.h"
#include "sobol.h"
#include "sensitivity.h"
#include "sf_error.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

static sf_sobol_design *design(size_t n, size_t d, unsigned long seed)
{
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, seed);
    sf_sobol_design *D;
    assert_int_equal(sf_sobol_design_alloc(n, d, g, &D), SF_SUCCESS);
    gsl_rng_free(g);
    return D;
}

/* f = sum c_i u_i over every evaluation, stride 1 */
static double *linear(const sf_sobol_design *D, const double *c)
{
    size_t ne = sf_sobol_nevals(D);
    double *y = malloc(ne * sizeof *y), u[SF_SOBOL_MAXD];
    for (size_t e = 0; e < ne; e++) {
        sf_sobol_point(D, e, u);
        y[e] = 0;
        for (size_t i = 0; i < D->d; i++)
            y[e] += c[i] * u[i];
    }
    return y;
}

static void blocks(void **state)
{
    (void)state;
    sf_sobol_design *D = design(5, 3, 7);
    assert_int_equal(sf_sobol_nevals(D), 25);
    double u[3];
    for (size_t e = 0; e < 25; e++) {
        size_t k = e / 5, j = e % 5;
        sf_sobol_point(D, e, u);
        for (size_t i = 0; i < 3; i++) {
            int from_b = k == 1 || k == 2 + i;
            assert_true(u[i] == (from_b ? D->b : D->a)[j * 3 + i]);
            assert_true(u[i] >= 0 && u[i] < 1);
            assert_int_equal(sf_sobol_source_row(D, e, i), from_b ? 5 + j : j);
        }
    }
    sf_sobol_design_free(D);
    sf_sobol_design_free(NULL);
}

static void refusals(void **state)
{
    (void)state;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    sf_sobol_design *D = (sf_sobol_design *)1;
    assert_int_equal(sf_sobol_design_alloc(1, 2, g, &D), SF_EINVAL);
    assert_null(D);
    assert_int_equal(sf_sobol_design_alloc(4, 0, g, &D), SF_EINVAL);
    assert_int_equal(sf_sobol_design_alloc(4, SF_SOBOL_MAXD + 1, g, &D), SF_EINVAL);
    assert_int_equal(sf_sobol_design_alloc(SIZE_MAX / 4, 3, g, &D), SF_ETOOBIG);
    gsl_rng_free(g);
    D = design(8, 2, 1);
    double y[32];
    sf_sobol_result r;
    for (int e = 0; e < 32; e++)
        y[e] = 2.5;
    assert_int_equal(sf_sobol_estimate(D, y, 1, 10, 0.95, 1, &r, NULL), SF_EFAIL);   /* constant: no V */
    assert_int_equal(sf_sobol_estimate(D, y, 1, 10, 1.0, 1, &r, NULL), SF_EINVAL);
    assert_int_equal(sf_sobol_estimate(D, y, 1, 10, NAN, 1, &r, NULL), SF_EINVAL);
    for (int j = 0; j < 7; j++)   /* rows 0..6 excluded: one row left */
        y[2 * 8 + j] = NAN;
    assert_int_equal(sf_sobol_estimate(D, y, 1, 10, 0.95, 1, &r, NULL), SF_EINVAL);
    assert_int_equal(r.n_used, 1);
    assert_int_equal(r.n_excluded, 7);
    sf_sobol_design_free(D);
}

/* f = c0 u0: the other input's indices are exactly 0, and S_T0 is the
 * Jansen sum itself */
static void exact_zeros(void **state)
{
    (void)state;
    sf_sobol_design *D = design(50, 2, 3);
    const double c[2] = { 3, 0 };
    double *y = linear(D, c);
    sf_sobol_result r;
    assert_int_equal(sf_sobol_estimate(D, y, 1, 0, 0.9, 1, &r, NULL), SF_SUCCESS);
    assert_true(r.idx[1].s1 == 0 && r.idx[1].st == 0);
    assert_true(isnan(r.idx[0].s1_lo) && isnan(r.idx[0].st_hi) && isnan(r.idx[0].s1_se));
    double t = 0;
    for (size_t j = 0; j < 50; j++)
        t += (y[j] - y[100 + j]) * (y[j] - y[100 + j]);
    assert_close(r.idx[0].st, t / 100 / r.var, 1e-14);
    assert_int_equal(r.n_used, 50);
    free(y);
    sf_sobol_design_free(D);
}

/* f = sum c_i u_i: S_i = S_Ti = c_i^2 / sum c^2; bootstrap intervals
 * around the estimates; a row with a NaN is excluded; every index on a
 * strided column */
static void linear_model(void **state)
{
    (void)state;
    const size_t n = 4000;
    sf_sobol_design *D = design(n, 3, 11);
    const double c[3] = { 1, 2, 0.5 }, cc = 1 + 4 + 0.25;
    double *y1 = linear(D, c), *y = malloc(2 * sf_sobol_nevals(D) * sizeof *y);
    for (size_t e = 0; e < sf_sobol_nevals(D); e++) {
        y[2 * e] = y1[e];
        y[2 * e + 1] = -1;
    }
    y[2 * (3 * n + 5)] = NAN;   /* row 5 of A_B^(1) */
    sf_sobol_result r, r2;
    double *boot = malloc(200 * 6 * sizeof *boot), col[200];
    assert_int_equal(sf_sobol_estimate(D, y, 2, 200, 0.95, 9, &r, boot), SF_SUCCESS);
    assert_int_equal(r.nboot_used, 200);
    for (int b = 0; b < 200; b++)   /* the paired resamples give the intervals: S_T2's */
        col[b] = boot[b * 6 + 3 + 2];
    gsl_sort(col, 1, 200);
    assert_true(gsl_stats_quantile_from_sorted_data(col, 1, 200, 0.025) == r.idx[2].st_lo);
    free(boot);
    assert_int_equal(r.n_used, n - 1);
    assert_int_equal(r.n_excluded, 1);
    assert_int_equal(r.nboot, 200);
    for (int i = 0; i < 3; i++) {
        const sf_sobol_index *x = &r.idx[i];
        assert_true(fabs(x->s1 - c[i] * c[i] / cc) < 5 * x->s1_se);
        assert_true(fabs(x->st - c[i] * c[i] / cc) < 5 * x->st_se);
        assert_true(x->s1_lo <= x->s1 && x->s1 <= x->s1_hi);
        assert_true(x->st_lo <= x->st && x->st <= x->st_hi);
        assert_true(x->s1_se > 0 && x->st_se > 0 && x->s1_se < 0.03 && x->st_se < 0.03);
    }
    /* same seed, same bits; another seed, other intervals, same estimates */
    assert_int_equal(sf_sobol_estimate(D, y, 2, 200, 0.95, 9, &r2, NULL), SF_SUCCESS);
    assert_memory_equal(&r, &r2, sizeof r);
    assert_int_equal(sf_sobol_estimate(D, y, 2, 200, 0.95, 10, &r2, NULL), SF_SUCCESS);
    assert_true(r2.idx[0].s1 == r.idx[0].s1 && r2.idx[0].s1_lo != r.idx[0].s1_lo);
    free(y);
    free(y1);
    sf_sobol_design_free(D);
}

/* Some blocks only: input i's indices from A, B and A_B^(i) are the full
 * estimate's bit for bit, the others NAN; a NaN in a block left out
 * excludes no row; an empty bit set is refused. */
static void some_blocks(void **state)
{
    (void)state;
    const size_t n = 300;
    sf_sobol_design *D = design(n, 3, 12);
    const double c[3] = { 1, 2, 0.5 };
    double *y = linear(D, c);
    sf_sobol_result all, some;
    assert_int_equal(sf_sobol_estimate(D, y, 1, 100, 0.9, 4, &all, NULL), SF_SUCCESS);
    for (size_t j = 0; j < n; j++)   /* A_B^(0) and A_B^(2) not run */
        y[2 * n + j] = y[4 * n + j] = NAN;
    for (size_t e = 0; e < sf_sobol_nevals(D); e++)
        assert_int_equal(sf_sobol_in_blocks(D, 1UL << 1, e), e < 2 * n || (e >= 3 * n && e < 4 * n));
    assert_int_equal(sf_sobol_estimate_some(D, 1UL << 1, y, 1, 100, 0.9, 4, &some, NULL), SF_SUCCESS);
    assert_int_equal(some.n_used, n);
    assert_memory_equal(&some.idx[1], &all.idx[1], sizeof all.idx[1]);
    assert_true(some.mean == all.mean && some.var == all.var);
    assert_true(isnan(some.idx[0].st) && isnan(some.idx[2].s1) && isnan(some.idx[2].st_hi) && isnan(some.idx[0].st_se));
    assert_int_equal(sf_sobol_estimate(D, y, 1, 100, 0.9, 4, &all, NULL), SF_EINVAL);   /* every row has a NaN */
    assert_int_equal(sf_sobol_estimate_some(D, 1UL << 3, y, 1, 100, 0.9, 4, &some, NULL), SF_EINVAL);   /* no input */
    free(y);
    sf_sobol_design_free(D);
}

/* Two rows, one whose A and B values are equal: a resample that draws it
 * twice has V = 0 and is left out of the intervals. */
static void degenerate_resamples(void **state)
{
    (void)state;
    sf_sobol_design *D = design(2, 1, 5);
    double y[6] = { 1, 4, 1, 0, 2, 3 };   /* A: 1 4, B: 1 0, A_B: 2 3 */
    sf_sobol_result r;
    assert_int_equal(sf_sobol_estimate(D, y, 1, 50, 0.95, 3, &r, NULL), SF_SUCCESS);
    assert_true(isfinite(r.idx[0].s1_lo) && r.idx[0].s1_lo <= r.idx[0].s1_hi);
    /* nboot = 1: fewer than 2 resamples, no interval */
    assert_int_equal(sf_sobol_estimate(D, y, 1, 1, 0.95, 3, &r, NULL), SF_SUCCESS);
    assert_true(isnan(r.idx[0].st_lo));
    sf_sobol_design_free(D);
}

/* ---- the rank-based (given-data) first-order estimator */

/* Ishigami's three analytic first-order indices (a = 7, b = 0.1) */
static void ishigami_s1(double *s)
{
    double p4 = pow(M_PI, 4), v1 = 0.5 * pow(1 + 0.1 * p4 / 5, 2), v2 = 49.0 / 8;
    double v = v1 + v2 + 0.01 * p4 * p4 * (1.0 / 18 - 1.0 / 50);
    s[0] = v1 / v;
    s[1] = v2 / v;
    s[2] = 0;
}

/* n rows of the Ishigami function, x uniform on [-pi, pi]^3, row-major */
static void ishigami_rows(size_t n, unsigned long seed, double *x, double *y)
{
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, seed);
    for (size_t j = 0; j < n; j++) {
        double *u = x + 3 * j;
        for (int i = 0; i < 3; i++)
            u[i] = M_PI * (2 * gsl_rng_uniform(g) - 1);
        y[j] = sin(u[0]) + 7 * pow(sin(u[1]), 2) + 0.1 * pow(u[2], 4) * sin(u[0]);
    }
    gsl_rng_free(g);
}

/* 2^16 rows: each index within 4 se of the analytic value (a two-sided
 * 6e-5 each at a fixed seed), S3 (y's mean does not depend on x3) within
 * its se's reach of 0; the interval is s1 -/+ z se; the se is of the size
 * the 300-replication study of the case measured (0.0304 at 1024 rows:
 * 0.0038 at 2^16 by the 1/sqrt(n) law). */
static void rank_ishigami(void **state)
{
    (void)state;
    const size_t n = 1u << 16;
    double *x = malloc(3 * n * sizeof *x), *y = malloc(n * sizeof *y), ex[3];
    ishigami_rows(n, 2026, x, y);
    ishigami_s1(ex);
    sf_sobol_rank_result r;
    assert_int_equal(sf_sobol_rank_s1(n, 3, x, 3, y, 1, 100, 0.95, 5, &r), SF_SUCCESS);
    assert_int_equal(r.n_used, n);
    assert_int_equal(r.groups, 40);   /* floor(cbrt(65536)) */
    assert_int_equal(r.nsplit_used, 100);
    for (int i = 0; i < 3; i++) {
        const sf_sobol_rank_index *o = &r.idx[i];
        if (!(fabs(o->s1 - ex[i]) < 4 * o->se))
            fail_msg("S%d = %.5f, analytic %.5f, se %.5f", i + 1, o->s1, ex[i], o->se);
        assert_true(o->se > 0.002 && o->se < 0.008);
        assert_close((o->hi - o->lo) / (2 * o->se), 1.959963984540054, 1e-12);
        assert_close(0.5 * (o->hi + o->lo), o->s1, 1e-14);
    }
    free(x);
    free(y);
}

/* y = sum c_i x_i, x_i uniform of width w_i: S_i = c_i^2 w_i^2 / sum.
 * The inputs are columns 0..2 of a 4-column matrix, y column 0 of 2;
 * a row with a NaN y and one with an infinite x are excluded; input 3
 * (c = 0) has S ~ 0 within its se; one input alone, as a column, has the
 * index and se of the joint call (the same splits for every input). */
static void rank_linear(void **state)
{
    (void)state;
    const size_t n = 4000;
    const double c[3] = { 1, 2, 0 }, w[3] = { 1, 0.75, 3 };
    double *x = malloc(4 * n * sizeof *x), *y = malloc(2 * n * sizeof *y), ex[3], sum = 0;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, 17);
    for (size_t j = 0; j < n; j++) {
        y[2 * j] = 0;
        y[2 * j + 1] = NAN;   /* another output: never read */
        for (int i = 0; i < 3; i++) {
            x[4 * j + i] = w[i] * gsl_rng_uniform(g);
            y[2 * j] += c[i] * x[4 * j + i];
        }
        x[4 * j + 3] = NAN;   /* a column past d: never read */
    }
    gsl_rng_free(g);
    for (int i = 0; i < 3; i++)
        sum += c[i] * c[i] * w[i] * w[i];
    for (int i = 0; i < 3; i++)
        ex[i] = c[i] * c[i] * w[i] * w[i] / sum;
    y[2 * 7] = NAN;
    x[4 * 11 + 1] = INFINITY;
    sf_sobol_rank_result r, r2;
    assert_int_equal(sf_sobol_rank_s1(n, 3, x, 4, y, 2, 50, 0.9, 3, &r), SF_SUCCESS);
    assert_int_equal(r.n_used, n - 2);
    assert_int_equal(r.n_excluded, 2);
    assert_int_equal(r.nsplit, 50);
    assert_true(r.level == 0.9);
    for (int i = 0; i < 3; i++) {
        const sf_sobol_rank_index *o = &r.idx[i];
        if (!(fabs(o->s1 - ex[i]) < 4 * o->se))
            fail_msg("S%d = %.5f, exact %.5f, se %.5f", i + 1, o->s1, ex[i], o->se);
        assert_true(o->se > 0 && o->se < 0.03);
        assert_true(o->lo < o->s1 && o->s1 < o->hi);
    }
    /* same seed, same bits; another seed, the same estimates, another se */
    assert_int_equal(sf_sobol_rank_s1(n, 3, x, 4, y, 2, 50, 0.9, 3, &r2), SF_SUCCESS);
    assert_memory_equal(&r, &r2, sizeof r);
    assert_int_equal(sf_sobol_rank_s1(n, 3, x, 4, y, 2, 50, 0.9, 4, &r2), SF_SUCCESS);
    assert_true(r2.idx[1].s1 == r.idx[1].s1 && r2.idx[1].se != r.idx[1].se);
    /* input 1 alone: the column x + 1 with the matrix's stride */
    assert_int_equal(sf_sobol_rank_s1(n, 1, x + 1, 4, y, 2, 50, 0.9, 3, &r2), SF_SUCCESS);
    assert_int_equal(r2.n_excluded, 2);
    assert_true(r2.idx[0].s1 == r.idx[1].s1 && r2.idx[0].se == r.idx[1].se);
    free(x);
    free(y);
}

/* Ties: x = 1, 0, 1, 0, 1, 0 orders the rows 1 3 5 0 2 4 (by x, then by
 * row); the estimate is that order's wrapped sum, to rounding. */
static void rank_ties(void **state)
{
    (void)state;
    const double x[6] = { 1, 0, 1, 0, 1, 0 }, y[6] = { 0.3, -1.2, 2.5, 0.7, -0.4, 1.9 };
    const int ord[6] = { 1, 3, 5, 0, 2, 4 };
    double mean = 0, v = 0, c = 0;
    for (int j = 0; j < 6; j++)
        mean += y[j] / 6;
    for (int j = 0; j < 6; j++)
        v += (y[j] - mean) * (y[j] - mean) / 6;
    for (int k = 0; k < 6; k++)
        c += (y[ord[k]] - mean) * (y[ord[(k + 1) % 6]] - mean) / 6;
    sf_sobol_rank_result r;
    assert_int_equal(sf_sobol_rank_s1(6, 1, x, 1, y, 1, 10, 0.95, 1, &r), SF_SUCCESS);
    assert_close(r.idx[0].s1, c / v, 1e-14);
    assert_close(r.mean, mean, 1e-15);
    assert_close(r.var, v, 1e-14);
    assert_int_equal(r.groups, 2);   /* cbrt(6) < 2: 2 groups of 3 */
    assert_true(isfinite(r.idx[0].se));
}

/* Splits whose groups have no variance, and too few rows for a split */
static void rank_degenerate(void **state)
{
    (void)state;
    double x[27], y[27] = { 0 };
    for (int j = 0; j < 27; j++)
        x[j] = (j * 7) % 27;
    sf_sobol_rank_result r;
    /* one non-zero y: one of the 2 groups is always constant, no se */
    y[3] = 1;
    assert_int_equal(sf_sobol_rank_s1(4, 1, x, 1, y, 1, 20, 0.95, 1, &r), SF_SUCCESS);
    assert_int_equal(r.groups, 2);
    assert_int_equal(r.nsplit_used, 0);
    assert_true(isfinite(r.idx[0].s1) && isnan(r.idx[0].se) && isnan(r.idx[0].lo) && isnan(r.idx[0].hi));
    /* two non-zero y in 3 groups: a split is used only when they fall in
     * different groups */
    y[5] = 2;
    assert_int_equal(sf_sobol_rank_s1(27, 1, x, 1, y, 1, 40, 0.95, 1, &r), SF_SUCCESS);
    assert_int_equal(r.groups, 3);
    assert_true(r.nsplit_used > 0 && r.nsplit_used < 40);
    assert_true(r.idx[0].se < 1e-12);   /* a spike among 9 equal rows: -1/8 in either group */
    /* 3 rows: an estimate, no split of 2 groups of 2 */
    assert_int_equal(sf_sobol_rank_s1(3, 1, x, 1, y + 3, 1, 20, 0.95, 1, &r), SF_SUCCESS);
    assert_int_equal(r.groups, 0);
    assert_int_equal(r.nsplit_used, 0);
    assert_true(isfinite(r.idx[0].s1) && isnan(r.idx[0].se));
    /* nsplit = 0: no se asked for */
    assert_int_equal(sf_sobol_rank_s1(27, 1, x, 1, y, 1, 0, 0.95, 1, &r), SF_SUCCESS);
    assert_int_equal(r.groups, 3);
    assert_true(isnan(r.idx[0].se));
}

static void rank_refusals(void **state)
{
    (void)state;
    double x[16], y[8];
    for (int j = 0; j < 16; j++)
        x[j] = sin(j);
    for (int j = 0; j < 8; j++)
        y[j] = cos(j);
    sf_sobol_rank_result r;
    assert_int_equal(sf_sobol_rank_s1(2, 1, x, 1, y, 1, 10, 0.95, 1, &r), SF_EINVAL);   /* n < 3 */
    assert_int_equal(sf_sobol_rank_s1(8, 1, x, 1, y, 1, 10, 0, 1, &r), SF_EINVAL);
    assert_int_equal(sf_sobol_rank_s1(8, 1, x, 1, y, 1, 10, 1, 1, &r), SF_EINVAL);
    assert_int_equal(sf_sobol_rank_s1(8, 1, x, 1, y, 1, 10, NAN, 1, &r), SF_EINVAL);
    assert_int_equal(sf_sobol_rank_s1(8, 0, x, 1, y, 1, 10, 0.95, 1, &r), SF_EINVAL);
    assert_int_equal(sf_sobol_rank_s1(8, SF_SOBOL_MAXD + 1, x, SF_SOBOL_MAXD + 1, y, 1, 10, 0.95, 1, &r), SF_EINVAL);
    assert_int_equal(sf_sobol_rank_s1(8, 2, x, 1, y, 1, 10, 0.95, 1, &r), SF_EINVAL);   /* xstride < d */
    /* every row non-finite (y in some, x in the others) */
    double yn[8], xn[16];
    memcpy(xn, x, sizeof x);
    for (int j = 0; j < 8; j++) {
        yn[j] = j % 2 ? NAN : y[j];
        if (j % 2 == 0)
            xn[2 * j + 1] = -INFINITY;
    }
    assert_int_equal(sf_sobol_rank_s1(8, 2, xn, 2, yn, 1, 10, 0.95, 1, &r), SF_EINVAL);
    assert_int_equal(r.n_used, 0);
    assert_int_equal(r.n_excluded, 8);
    /* two usable rows of 8 */
    yn[1] = yn[3] = 1;
    assert_int_equal(sf_sobol_rank_s1(8, 2, xn, 2, yn, 1, 10, 0.95, 1, &r), SF_EINVAL);
    assert_int_equal(r.n_used, 2);
    /* a constant output has no index */
    for (int j = 0; j < 8; j++)
        yn[j] = 4.25;
    assert_int_equal(sf_sobol_rank_s1(8, 2, x, 2, yn, 1, 10, 0.95, 1, &r), SF_EFAIL);
    assert_true(r.var == 0 && r.n_used == 8);
}

/* ---- the study */

static void small_scene(sf_scene *s)
{
    sf_scene_default(s);
    s->cof = SF_COF_FIELD;
    s->T = 20;
    s->t_skip = 2;
    s->strip_halfwidth = 0.05;
    s->cells = 6;
    s->rtol = 1e-6;
}

static void narrow(sf_sens_ranges *r)
{
    const double lo[SF_SENS_NPAR] = { -0.3, 0.15, 0.2, 0.45 }, hi[SF_SENS_NPAR] = { -0.2, 0.25, 0.25, 0.55 };
    memcpy(r->lo, lo, sizeof lo);
    memcpy(r->hi, hi, sizeof hi);
}

static void ranges(void **state)
{
    (void)state;
    sf_sens_ranges r;
    char err[200];
    sf_sens_ranges_default(&r);
    assert_int_equal(sf_sens_ranges_check(&r, err, sizeof err), SF_SUCCESS);
    assert_true(r.lo[SF_SENS_LOGLR] == -2 && r.hi[SF_SENS_LOGLR] == 3 && r.hi[SF_SENS_VB] == 0.6);
    r.lo[SF_SENS_LOGLR] = -5;   /* log10 l/R may be negative */
    assert_int_equal(sf_sens_ranges_check(&r, err, sizeof err), SF_SUCCESS);
    r.lo[SF_SENS_CV] = 0.4;
    assert_int_equal(sf_sens_ranges_check(&r, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "cv"));
    r.lo[SF_SENS_CV] = 0.1;
    r.hi[SF_SENS_MU] = INFINITY;
    assert_int_equal(sf_sens_ranges_check(&r, err, sizeof err), SF_EINVAL);
    r.hi[SF_SENS_MU] = 1;
    r.lo[SF_SENS_MU] = NAN;
    assert_int_equal(sf_sens_ranges_check(&r, err, sizeof err), SF_EINVAL);
    r.lo[SF_SENS_MU] = 0;
    assert_int_equal(sf_sens_ranges_check(&r, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "positive"));
    assert_string_equal(sf_sens_input_name(SF_SENS_FIELD), "field");
    assert_string_equal(sf_sens_input_name(SF_SENS_LOGLR), "log10_l_over_R");
    assert_string_equal(sf_sens_input_name(-1), "?");
    assert_string_equal(sf_sens_input_name(SF_SENS_D), "?");
    /* the scene of a point */
    sf_sens_ranges_default(&r);
    sf_scene b, s;
    sf_scene_default(&b);
    double u[SF_SENS_D] = { 0.6, 0.5, 0, 1, 0.3 }, x[SF_SENS_NPAR];
    sf_sens_scene(&b, &r, u, &s, x);
    assert_close(s.l / s.R, 10.0, 1e-14);
    assert_close(s.mu_std / s.mu_mean, 0.2, 1e-14);
    assert_true(s.v_b == 0.1 && s.mu_mean == 1 && x[SF_SENS_LOGLR] == 1 && x[SF_SENS_MU] == 1);
}

static void study_refusals(void **state)
{
    (void)state;
    sf_scene s;
    sf_sens_ranges r;
    sf_sens *S = (sf_sens *)1;
    char err[300];
    small_scene(&s);
    narrow(&r);
    r.hi[SF_SENS_VB] = 0.1;
    assert_int_equal(sf_sens_run(&s, &r, 2, 0, 0.95, 1, NULL, &S, err, sizeof err), SF_EINVAL);
    assert_null(S);
    narrow(&r);
    s.cof = SF_COF_VARIABLE;
    assert_int_equal(sf_sens_run(&s, &r, 2, 0, 0.95, 1, NULL, &S, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "cof = field"));
    s.cof = SF_COF_FIELD;
    assert_int_equal(sf_sens_run(&s, &r, 1, 0, 0.95, 1, NULL, &S, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sens_run(&s, &r, 2, 0, 0, 1, NULL, &S, err, sizeof err), SF_EINVAL);
    /* a window without an oscillation: the deterministic reference fails */
    s.T = 1.5;
    assert_int_equal(sf_sens_run(&s, &r, 2, 0, 0.95, 1, NULL, &S, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "raise T"));
    assert_null(S);
    /* per-cycle QoIs on a short window: NaN ratios, every row excluded */
    small_scene(&s);
    s.qoi_def = SF_QOI_CYCLES;
    s.T = 4;
    s.t_skip = 3;
    int rc = sf_sens_run(&s, &r, 2, 0, 0.95, 1, NULL, &S, err, sizeof err);
    if (rc != SF_EINVAL)   /* (the reference itself may have no cycle: the same refusal) */
        fail_msg("per-cycle run: %d %s", rc, err);
    assert_null(S);
    sf_sens_free(NULL);
}

static char *text_of(void (*w)(FILE *, const sf_sens *), const sf_sens *S)
{
    char *t = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&t, &n);
    w(f, S);
    fclose(f);
    return t;
}

static void study_threads(void **state)
{
    (void)state;
    sf_scene s;
    sf_sens_ranges r;
    sf_sens *S1, *S2;
    char err[300] = "";
    small_scene(&s);
    narrow(&r);
    int rc = sf_sens_run(&s, &r, 3, 20, 0.9, 1, NULL, &S1, err, sizeof err);
    if (rc)
        fail_msg("%d: %s", rc, err);
    assert_int_equal(sf_sens_run(&s, &r, 3, 20, 0.9, 2, NULL, &S2, err, sizeof err), SF_SUCCESS);
    size_t ne = sf_sobol_nevals(S1->D);
    assert_int_equal(ne, 21);
    assert_memory_equal(S1->y, S2->y, ne * 2 * SF_SWEEP_NQ * sizeof *S1->y);
    assert_memory_equal(S1->res, S2->res, sizeof S1->res);
    /* the field input: A_B^(field) is A's parameters with B's field */
    for (size_t j = 0; j < 3; j++) {
        size_t e = (2 + SF_SENS_FIELD) * 3 + j;
        assert_memory_equal(S1->x + e * SF_SENS_NPAR, S1->x + j * SF_SENS_NPAR, SF_SENS_NPAR * sizeof(double));
        assert_true(S1->y[e * 2 * SF_SWEEP_NQ] != S1->y[j * 2 * SF_SWEEP_NQ]);
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            assert_true(S1->y[j * 2 * SF_SWEEP_NQ + q] > 0);
    }
    /* the study's A and B blocks as given data, the call sobol.h shows */
    sf_sobol_rank_result rr;
    assert_int_equal(sf_sobol_rank_s1(2 * 3, SF_SENS_NPAR, S1->x, SF_SENS_NPAR, S1->y + 1, 2 * SF_SWEEP_NQ, 20, 0.9,
                                      1, &rr), SF_SUCCESS);
    assert_true(rr.n_used == 6 && rr.groups == 2 && fabs(rr.idx[SF_SENS_LOGLR].s1) <= 1);
    char *a = text_of(sf_sens_write_indices, S1), *b = text_of(sf_sens_write_evals, S1);
    assert_non_null(strstr(a, "qoi\tinput\tS1\tS1_ci90_lo"));
    assert_non_null(strstr(a, "stick_fraction_ratio\tfield\t"));
    assert_non_null(strstr(b, "\nAB_field\t2\t5\t"));
    assert_non_null(strstr(b, "\nB\t0\t3\t"));
    free(a);
    free(b);
    sf_sens_free(S2);
    /* one input's blocks: its indices and runs are the full study's, the blocks left out not run */
    sf_sens *S3;
    assert_int_equal(sf_sens_run_some(&s, &r, 3, 1UL << SF_SENS_VB, 20, 0.9, 2, NULL, &S3, err, sizeof err),
                     SF_SUCCESS);
    for (size_t e = 0; e < ne; e++) {
        int run = e < 6 || e / 3 == 2 + SF_SENS_VB;
        for (int q = 0; q < 2 * SF_SWEEP_NQ; q++) {
            double v = S3->y[e * 2 * SF_SWEEP_NQ + q];
            assert_true(run ? v == S1->y[e * 2 * SF_SWEEP_NQ + q] : isnan(v));
        }
    }
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        assert_memory_equal(&S3->res[q].idx[SF_SENS_VB], &S1->res[q].idx[SF_SENS_VB], sizeof(sf_sobol_index));
        assert_true(isnan(S3->res[q].idx[SF_SENS_CV].st) && isnan(S3->res[q].idx[SF_SENS_FIELD].s1));
    }
    b = text_of(sf_sens_write_evals, S3);
    assert_non_null(strstr(b, "\nAB_v_b\t2\t2\t"));
    assert_null(strstr(b, "AB_cv"));
    free(b);
    assert_int_equal(sf_sens_run_some(&s, &r, 3, 1UL << SF_SENS_D, 20, 0.9, 2, NULL, &S2, err, sizeof err),
                     SF_EINVAL);
    assert_null(S2);
    sf_sens_free(S1);
    sf_sens_free(S3);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(blocks),
        cmocka_unit_test(refusals),
        cmocka_unit_test(exact_zeros),
        cmocka_unit_test(linear_model),
        cmocka_unit_test(degenerate_resamples),
        cmocka_unit_test(some_blocks),
        cmocka_unit_test(rank_ishigami),
        cmocka_unit_test(rank_linear),
        cmocka_unit_test(rank_ties),
        cmocka_unit_test(rank_degenerate),
        cmocka_unit_test(rank_refusals),
        cmocka_unit_test(ranges),
        cmocka_unit_test(study_refusals),
        cmocka_unit_test(study_threads),
    };
    return cmocka_run_group_tests_name("sobol", tests, NULL, NULL);
}
