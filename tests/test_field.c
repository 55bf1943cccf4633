/* Unit tests: circulant-embedding field plan. */
#include "test_util.h"
#include "field.h"
#include "sf_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <string.h>
#include <gsl/gsl_math.h>

static sf_field *plan(size_t m, size_t n, double dx, double dy, double l, int *rc)
{
    sf_field_spec s;
    sf_field_spec_default(&s, m, n, dx, dy, l);
    sf_field *f = NULL;
    *rc = sf_field_alloc(&s, &f);
    return f;
}

static int only_small_primes(size_t p)
{
    while (p % 2 == 0 && p > 1) p /= 2;
    while (p % 3 == 0 && p > 1) p /= 3;
    while (p % 5 == 0 && p > 1) p /= 5;
    while (p % 7 == 0 && p > 1) p /= 7;
    return p == 1;
}

static void first_row_is_the_embedded_toeplitz(void **state)
{
    (void)state;
    int rc;
    sf_field *f = plan(7, 5, 0.1, 0.2, 0.15, &rc);
    assert_int_equal(rc, SF_SUCCESS);
    const sf_field_info *in = sf_field_get_info(f);
    assert_true(in->px >= 2 * (7 - 1) && in->py >= 2 * (5 - 1));
    assert_true(only_small_primes(in->px) && only_small_primes(in->py));
    double *row = malloc(in->px * in->py * sizeof *row);
    sf_field_first_row(f, row);
    assert_close(row[0], 1.0, 0);
    for (size_t j = 0; j < in->py; j++)
        for (size_t i = 0; i < in->px; i++) {
            size_t ii = (in->px - i) % in->px, jj = (in->py - j) % in->py;
            assert_close(row[i + in->px * j], row[ii + in->px * jj], 0);   /* even */
            if (i < 7 && j < 5)   /* the grid lags: Eq. 2 itself */
                assert_close(row[i + in->px * j], exp(-(pow(i * 0.1, 2) + pow(j * 0.2, 2)) / (0.15 * 0.15)), 1e-15);
        }
    free(row);
    sf_field_free(f);
}

static void fft_eigenvalues_match_direct_dft(void **state)
{
    (void)state;
    int rc;
    sf_field *f = plan(3, 4, 0.3, 0.2, 0.25, &rc);
    const sf_field_info *in = sf_field_get_info(f);
    size_t px = in->px, py = in->py, M = px * py;
    double *row = malloc(M * sizeof *row), *lam = malloc(M * sizeof *lam);
    sf_field_first_row(f, row);
    sf_field_eigenvalues(f, lam);
    for (size_t ky = 0; ky < py; ky++)
        for (size_t kx = 0; kx < px; kx++) {
            double s = 0;
            for (size_t j = 0; j < py; j++)
                for (size_t i = 0; i < px; i++)
                    s += row[i + px * j] * cos(2 * M_PI * ((double)(kx * i) / px + (double)(ky * j) / py));
            assert_close(lam[kx + px * ky], s, 1e-13);
        }
    free(row);
    free(lam);
    sf_field_free(f);
}

static void padding_and_cap(void **state)
{
    (void)state;
    int rc;
    sf_field *f = plan(16, 16, 0.05, 0.05, 0.4, &rc);   /* l/domain = 0.53 */
    assert_int_equal(rc, SF_SUCCESS);
    const sf_field_info *in = sf_field_get_info(f);
    assert_true(in->px > in->px_min);
    assert_true(in->cov_error < 1e-10);
    assert_int_equal(in->truncated, 0);
    sf_field_free(f);

    sf_field_spec s;
    sf_field_spec_default(&s, 16, 16, 0.05, 0.05, 0.4);
    s.pad_cap = 1;
    assert_int_equal(sf_field_alloc(&s, &f), SF_ETRUNC);
    assert_non_null(f);
    assert_int_equal(sf_field_get_info(f)->truncated, 1);
    assert_true(sf_field_get_info(f)->cov_error > 1e-6);
    sf_field_free(f);
}

static void invalid_specs(void **state)
{
    (void)state;
    sf_field_spec s;
    sf_field *f = (sf_field *)1;
    sf_field_spec_default(&s, 8, 8, 0.1, 0.1, -1);
    assert_int_equal(sf_field_alloc(&s, &f), SF_EINVAL);
    assert_null(f);
    sf_field_spec_default(&s, 8, 8, NAN, 0.1, 1);
    assert_int_equal(sf_field_alloc(&s, &f), SF_EINVAL);
    sf_field_spec_default(&s, 0, 8, 0.1, 0.1, 1);
    assert_int_equal(sf_field_alloc(&s, &f), SF_EINVAL);
    sf_field_spec_default(&s, 8, 8, 0.1, 0.1, 1);
    s.pad_cap = 0.5;
    assert_int_equal(sf_field_alloc(&s, &f), SF_EINVAL);
    sf_field_spec_default(&s, 100000, 100000, 0.1, 0.1, 0.1);
    assert_int_equal(sf_field_alloc(&s, &f), SF_ETOOBIG);   /* over max_points: refused, not out of memory */
    assert_int_equal(sf_field_sample(NULL, NULL, NULL), SF_EINVAL);
}

static void sampling_is_deterministic_and_pairs_match(void **state)
{
    (void)state;
    int rc;
    sf_field *f = plan(9, 6, 0.05, 0.05, 0.1, &rc);
    size_t n = 54;
    double a[54], b[54], re[54], im[54];
    gsl_rng *r1 = gsl_rng_alloc(gsl_rng_mt19937), *r2 = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r1, 42);
    gsl_rng_set(r2, 42);
    sf_field_sample(f, r1, a);       /* real part of FFT 1 */
    sf_field_sample(f, r1, b);       /* kept imaginary part, no new draw */
    sf_field_sample_pair(f, r2, re, im);
    assert_memory_equal(a, re, n * sizeof(double));
    assert_memory_equal(b, im, n * sizeof(double));
    assert_true(gsl_rng_get(r1) == gsl_rng_get(r2));   /* same draws consumed */
    /* a fresh draw is discard + sample, bit for bit, whatever was kept */
    gsl_rng_set(r1, 7);
    gsl_rng_set(r2, 7);
    sf_field_sample(f, r1, a);   /* keeps a second field ... */
    sf_field_discard(f);         /* ... that discard forgets */
    sf_field_sample(f, r1, a);
    sf_field_sample_fresh(f, r2, re);   /* the same stream position: one FFT's draws earlier */
    sf_field_sample_fresh(f, r2, re);
    assert_memory_equal(a, re, n * sizeof(double));
    gsl_rng_free(r1);
    gsl_rng_free(r2);
    sf_field_free(f);
}

static void single_point(void **state)
{
    (void)state;
    int rc;
    sf_field *f = plan(1, 1, 1, 1, 1, &rc);
    assert_int_equal(rc, SF_SUCCESS);
    double c;
    sf_field_covariance(f, &c);
    assert_close(c, 1.0, 1e-15);
    sf_field_free(f);
}

static double gauss_kernel(double r, void *p)
{
    double l = *(double *)p;
    return exp(-r * r / (l * l));
}

/* The squared-exponential kernel of length *l on an m x n grid, by the
 * separable path (*a, SF_SUCCESS) and as a general kernel (*b, rc_b). */
static void both_paths(size_t m, size_t n, double dx, double dy, double *l, int rc_b, sf_field **a, sf_field **b)
{
    sf_field_spec s;
    sf_field_spec_default(&s, m, n, dx, dy, *l);
    assert_int_equal(sf_field_alloc(&s, a), SF_SUCCESS);
    s.kernel = gauss_kernel;
    s.kernel_params = l;
    assert_int_equal(sf_field_alloc(&s, b), rc_b);
}

static void general_path_matches_separable(void **state)
{
    (void)state;
    double l = 0.12;
    sf_field *a, *b;
    both_paths(10, 7, 0.03, 0.04, &l, SF_SUCCESS, &a, &b);
    assert_int_equal(sf_field_get_info(a)->separable, 1);
    assert_int_equal(sf_field_get_info(b)->separable, 0);
    double ca[70], cb[70];
    sf_field_covariance(a, ca);
    sf_field_covariance(b, cb);
    for (int i = 0; i < 70; i++)
        assert_close(ca[i], cb[i], 1e-12);
    sf_field_free(a);
    sf_field_free(b);
}

/* A general kernel whose embedding must grow (l long against the grid):
 * the eigenvalue FFT runs in the sampler's work array, which each larger
 * period replaces; the covariance and the periods are the separable
 * path's, and a draw is finite. */
static void general_path_pads_like_separable(void **state)
{
    (void)state;
    double l = 0.6;
    sf_field *a, *b;
    both_paths(12, 6, 0.05, 0.05, &l, SF_ETRUNC, &a, &b);   /* usable: its eigenvalues' floor not quite reached */
    const sf_field_info *ia = sf_field_get_info(a), *ib = sf_field_get_info(b);
    assert_true(ib->px > 24 || ib->py > 10);   /* the padding loop ran: past the first periods (22, 10 made nice) */
    double ca[72], cb[72], g[72];
    sf_field_covariance(a, ca);
    sf_field_covariance(b, cb);
    for (int i = 0; i < 72; i++)
        assert_close(ca[i], cb[i], 1e-9 + 2 * fmax(ib->cov_error, ia->cov_error));
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    assert_int_equal(sf_field_sample_fresh(b, r, g), SF_SUCCESS);
    for (int i = 0; i < 72; i++)
        assert_true(isfinite(g[i]));
    gsl_rng_free(r);
    sf_field_free(a);
    sf_field_free(b);
}

/* Wisdom: missing file = nothing to import; garbage = SF_EIO; a saved
 * file imports; an unwritable path fails cleanly and leaves no file. */
static void wisdom_round_trip(void **state)
{
    (void)state;
    char path[64];
    snprintf(path, sizeof path, "/tmp/sf-wisdom-%ld", (long)getpid());
    unlink(path);
    assert_int_equal(sf_field_wisdom_import(path), SF_SUCCESS);
    sf_field_spec spec;
    sf_field_spec_default(&spec, 16, 8, 0.1, 0.1, 0.2);
    spec.measure = 1;
    sf_field *f;
    assert_int_equal(sf_field_alloc(&spec, &f), SF_SUCCESS);
    sf_field_free(f);
    assert_int_equal(sf_field_wisdom_export(path), SF_SUCCESS);
    assert_int_equal(sf_field_wisdom_import(path), SF_SUCCESS);
    FILE *g = fopen(path, "w");
    assert_non_null(g);
    fputs("not wisdom\n", g);
    fclose(g);
    assert_int_equal(sf_field_wisdom_import(path), SF_EIO);
    unlink(path);
    assert_int_equal(sf_field_wisdom_export("/nonexistent-dir/w"), SF_EIO);
    assert_int_equal(access("/nonexistent-dir/w", F_OK), -1);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(first_row_is_the_embedded_toeplitz),
        cmocka_unit_test(fft_eigenvalues_match_direct_dft),
        cmocka_unit_test(padding_and_cap),
        cmocka_unit_test(invalid_specs),
        cmocka_unit_test(sampling_is_deterministic_and_pairs_match),
        cmocka_unit_test(single_point),
        cmocka_unit_test(general_path_matches_separable),
        cmocka_unit_test(general_path_pads_like_separable),
        cmocka_unit_test(wisdom_round_trip),
    };
    return cmocka_run_group_tests_name("field", tests, NULL, NULL);
}
