/* Unit tests: Monte Carlo driver: counter-based seeds, bit-identical
 * results for any thread count, checkpoint and resume. */
#include "test_util.h"
#include "montecarlo.h"
#include "sf_error.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <gsl/gsl_randist.h>

/* A realisation: a few draws, so the whole stream matters. */
static int realise(void *ws, size_t i, gsl_rng *rng, double *out)
{
    int *calls = ws;
    (void)i;
    double s = 0;
    for (int k = 0; k < 50; k++)
        s += gsl_ran_gaussian(rng, 1.0);
    out[0] = s;
    out[1] = gsl_rng_uniform(rng);
    if (calls) {
#pragma omp atomic
        (*calls)++;
    }
    return SF_SUCCESS;
}

static int fail_at_7(void *ws, size_t i, gsl_rng *rng, double *out)
{
    if (i == 7)
        return SF_EFAIL;
    return realise(ws, i, rng, out);
}

static void seeds(void **state)
{
    (void)state;
    assert_int_equal(sf_mc_seed(1, 5), sf_mc_seed(1, 5));
    assert_true(sf_mc_seed(1, 5) != sf_mc_seed(1, 6));
    assert_true(sf_mc_seed(1, 5) != sf_mc_seed(2, 5));
    assert_true(sf_mc_hash("a", 1, 0) != sf_mc_hash("b", 1, 0));
}

static void thread_count_invariance(void **state)
{
    (void)state;
    size_t n = 64;
    double *a = malloc(2 * n * sizeof *a), *b = malloc(2 * n * sizeof *b);
    sf_mc_ops ops = { NULL, NULL, realise };
    sf_mc_spec s = { n, 2, 42, 1, NULL, 0, 0, NULL };
    assert_int_equal(sf_mc_run(&s, &ops, NULL, a, NULL, NULL, 0), SF_SUCCESS);
    s.threads = 2;
    assert_int_equal(sf_mc_run(&s, &ops, NULL, b, NULL, NULL, 0), SF_SUCCESS);
    assert_memory_equal(a, b, 2 * n * sizeof *a);
    /* a realisation's values do not depend on n either */
    s.n = 10;
    assert_int_equal(sf_mc_run(&s, &ops, NULL, b, NULL, NULL, 0), SF_SUCCESS);
    assert_memory_equal(a, b, 2 * 10 * sizeof *a);
    free(a);
    free(b);
}

static void checkpoint_resume(void **state)
{
    (void)state;
    char path[] = "/tmp/sf-mc-test-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    unlink(path);
    size_t n = 20, before = 99;
    double *ref = malloc(2 * n * sizeof *ref), *out = calloc(2 * n, sizeof *out);
    sf_mc_ops ops = { NULL, NULL, realise };
    sf_mc_spec s = { n, 2, 7, 2, NULL, 0, 0xabc, NULL };
    sf_mc_run(&s, &ops, NULL, ref, NULL, NULL, 0);
    /* a run that fails at realisation 7 leaves the others checkpointed */
    s.checkpoint = path;
    sf_mc_ops bad = { NULL, NULL, fail_at_7 };
    s.threads = 1;
    assert_int_equal(sf_mc_run(&s, &bad, NULL, out, NULL, NULL, 0), SF_EFAIL);
    /* tear the last line as a kill mid-write would */
    FILE *f = fopen(path, "a");
    fputs("8 0x1p+0", f);
    fclose(f);
    int calls = 0;
    memset(out, 0, 2 * n * sizeof *out);
    s.resume = 1;
    assert_int_equal(sf_mc_run(&s, &ops, &calls, out, &before, NULL, 0), SF_SUCCESS);
    assert_int_equal(before, 7);   /* 0..6 done before the failure */
    assert_int_equal(calls, (int)(n - 7));
    assert_memory_equal(out, ref, 2 * n * sizeof *out);
    /* resuming a complete run redoes nothing */
    calls = 0;
    assert_int_equal(sf_mc_run(&s, &ops, &calls, out, &before, NULL, 0), SF_SUCCESS);
    assert_int_equal(calls, 0);
    assert_int_equal(before, n);
    /* a checkpoint of other work is refused with a reason */
    char err[256] = "";
    s.key = 0xdef;
    assert_int_equal(sf_mc_run(&s, &ops, NULL, out, NULL, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "other work"));
    f = fopen(path, "w");
    fputs("garbage\n", f);
    fclose(f);
    assert_int_equal(sf_mc_run(&s, &ops, NULL, out, NULL, err, sizeof err), SF_EINVAL);
    unlink(path);
    s.checkpoint = "/nonexistent-dir/x";
    s.resume = 0;
    assert_int_equal(sf_mc_run(&s, &ops, NULL, out, NULL, err, sizeof err), SF_EIO);
    free(ref);
    free(out);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(seeds),
        cmocka_unit_test(thread_count_invariance),
        cmocka_unit_test(checkpoint_resume),
    };
    return cmocka_run_group_tests_name("montecarlo", tests, NULL, NULL);
}
