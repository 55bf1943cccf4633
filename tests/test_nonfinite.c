/* Unit tests: a NaN in a check's data fails the case (docs/design.md
 * sec. 7.6).
 *
 * The harness side: a row whose measured value is NaN fails; NaN/Inf in a
 * plotted series or in an array given to sf_result_data is counted, and
 * sf_result_gate_nonfinite appends the failing row "non-finite values = 0".
 *
 * The data side: for one real case of EACH family the test-only poison of
 * verification/stats.h turns one aggregated value (the k-th value through
 * sf_max/sf_min/sf_result_data: one lag, point, cell, step or realisation)
 * into a NaN, as a defect would, and the case must then fail -- while the
 * same case without the poison passes (so the failure is the NaN's).  Cases
 * that are slow in the quick tier run here with a reduced scene (fewer
 * samples, shorter T, one sweep point): the data path is the same. */
#include "test_util.h"
#include "case.h"
#include "registry.h"
#include "result.h"
#include "stats.h"
#include "sf_error.h"

#include <string.h>
#include <gsl/gsl_cdf.h>

/* ---- harness ---- */

static void nan_row_fails(void **state)
{
    (void)state;
    sf_result *r = sf_result_alloc();
    assert_false(sf_check_abs(r, "a", NAN, 0, 1));
    assert_false(sf_check_rel(r, "b", NAN, 1, 1));
    assert_false(sf_check_le(r, "c", NAN, 1));
    assert_false(sf_check_ge(r, "d", NAN, 0));
    assert_false(sf_check_pvalue(r, "e", NAN, 1e-3, 10));
    assert_false(sf_check_le(r, "f", INFINITY, INFINITY) && sf_result_nonfinite(r) == 0);
    assert_int_equal(sf_result_nonfinite(r), 6);
    assert_false(sf_result_gate_nonfinite(r));
    sf_result_free(r);
}

static void clean_result_gets_passing_row(void **state)
{
    (void)state;
    sf_result *r = sf_result_alloc();
    double x[3] = { 1, 2, 3 };
    sf_check_le(r, "ok", 0.5, 1);
    sf_plot_series(sf_result_plot(r, "p", "t", "x [m]", "y [m]"), "s", SF_STYLE_LINES, 3, x, x);
    sf_result_data(r, "d", 3, x);
    assert_true(sf_result_gate_nonfinite(r));
    assert_int_equal(sf_result_nrows(r), 2);
    assert_true(sf_result_passed(r));
    sf_result_free(r);
}

static void nan_in_plot_or_data_fails(void **state)
{
    (void)state;
    double x[3] = { 1, 2, 3 }, y[3] = { 1, NAN, 3 }, z[3] = { 1, 2, INFINITY };
    sf_result *r = sf_result_alloc();
    sf_check_le(r, "ok", 0.5, 1);
    sf_plot_series(sf_result_plot(r, "p", "t", "x [m]", "y [m]"), "s", SF_STYLE_LINES, 3, x, y);
    assert_false(sf_result_gate_nonfinite(r));
    assert_false(sf_result_passed(r));
    sf_result_free(r);
    r = sf_result_alloc();
    sf_check_le(r, "ok", 0.5, 1);
    sf_result_data(r, "aggregated", 3, z);
    assert_false(sf_result_gate_nonfinite(r));
    sf_result_free(r);
}

static void helpers_propagate_nan(void **state)
{
    (void)state;
    assert_true(isnan(sf_max(NAN, 1)) && isnan(sf_max(1, NAN)));
    assert_true(isnan(sf_min(NAN, 1)) && isnan(sf_min(1, NAN)));
    assert_close(sf_max(1, 2), 2, 0);
    assert_close(sf_min(1, 2), 1, 0);
    assert_true(isinf(sf_max(1, INFINITY)));
    /* the poison: the 2nd value through the helpers becomes NaN */
    sf_poison_set(1);
    double m = 0;
    double v[4] = { 1, 2, 3, 4 };
    for (int i = 0; i < 4; i++)
        m = sf_max(m, v[i]);
    assert_true(sf_poison_hit());
    assert_true(isnan(m));
    sf_poison_set(5);                 /* element 1 of the 2nd array of 4 */
    double a[4] = { 1, 2, 3, 4 }, b[4] = { 1, 2, 3, 4 };
    sf_result *r = sf_result_alloc();
    sf_result_data(r, "a", 4, a);
    sf_result_data(r, "b", 4, b);
    sf_poison_set(-1);
    assert_true(isnan(b[1]) && !isnan(a[1]));
    assert_int_equal(sf_result_nonfinite(r), 1);
    sf_result_free(r);
}

static void ks_tests_are_nan_with_a_nan_sample(void **state)
{
    (void)state;
    double a[5] = { 0.1, -0.3, NAN, 0.7, 1.2 }, b[5] = { 0.2, 0.4, -0.1, 0.0, 0.5 }, D;
    assert_true(isnan(sf_ks2_test(a, 5, b, 5, &D)) && isnan(D));
    double c[5] = { 0.1, -0.3, NAN, 0.7, 1.2 };
    assert_true(isnan(sf_ks_test(c, 5, sf_cdf_normal, NULL, &D)) && isnan(D));
}

/* The RMS test refuses what it cannot judge (a NaN or Inf, one value)
 * and otherwise is Student's t on the squares: e^2 = 1, 4, 9 has mean
 * 14/3 and se 7/3, so against b = 2 t = (2/3) / (7/3) = 2/7 and
 * p = Q_t(t, 2); zero spread decides by the mean alone. */
/* The Mann-Whitney U test against scipy.stats.mannwhitneyu (asymptotic,
 * continuity-corrected, tie-corrected; two tied groups here): both
 * directions, and NaN for a NaN value or a sample of one */
static void mwu_test_matches_scipy(void **state)
{
    (void)state;
    const double a[] = { 0.31, 0.12, 0.5, 0.5, 0.77, 0.05, 0.9, 0.64, 0.33, 0.41, 0.28 };
    const double b[] = { 0.1, 0.2, 0.5, 0.02, 0.15, 0.3, 0.07, 0.22, 0.18, 0.11, 0.25, 0.09 };
    assert_close(sf_mwu_greater_p(a, 11, b, 12), 0.005283879110680374, 1e-12);
    assert_close(sf_mwu_greater_p(b, 12, a, 11), 0.9955813221165568, 1e-12);
    const double c[] = { 1, NAN };
    assert_true(isnan(sf_mwu_greater_p(a, 11, c, 2)));
    assert_true(isnan(sf_mwu_greater_p(a, 1, b, 12)));
    const double e[] = { 2, 2 }, f[] = { 2, 2, 2 };   /* all tied: no spread to rank */
    assert_true(sf_mwu_greater_p(e, 2, f, 3) == 1);
}

static void rms_test_refuses_nonfinite(void **state)
{
    (void)state;
    double a[3] = { 1, NAN, 2 }, b[3] = { 1, INFINITY, 2 }, c[3] = { 1, 2, 3 }, d[3] = { 2, 2, 2 };
    assert_true(sf_rms_le_pvalue(a, 3, 1) == 0);
    assert_true(sf_rms_le_pvalue(b, 3, 1) == 0);
    assert_true(sf_rms_le_pvalue(c, 1, 10) == 0);
    assert_true(fabs(sf_rms_le_pvalue(c, 3, 2) - gsl_cdf_tdist_Q(2.0 / 7, 2)) < 1e-14);
    assert_true(sf_rms_le_pvalue(d, 3, 2) == 1);
    assert_true(sf_rms_le_pvalue(d, 3, 1.9) == 0);
}

/* ---- one case per family ---- */

typedef struct {
    const char *path;   /* a quick-tier case file, or the id of `text` */
    const char *text;   /* a reduced scene (NULL: read path) */
} fam_case;

/* Run a case's check with the poison at k (-1: none) as the runner does.
 * Returns 1 pass, 0 fail (a check error counts as a failure); *hit says
 * whether the poisoned value was reached. */
static int run_case(const fam_case *fc, long k, int *hit)
{
    sf_case c;
    char err[512];
    int rc = fc->text ? sf_case_parse(&c, fc->path, fc->text, strlen(fc->text), err, sizeof err)
                      : sf_case_read(&c, fc->path, err, sizeof err);
    if (rc) {
        print_error("%s\n", err);
        fail();
    }
    const sf_check_def *d = sf_check_find(c.spec.check);
    assert_non_null(d);
    sf_result *r = sf_result_alloc();
    sf_poison_set(k);
    rc = d->fn(&c, r);
    *hit = sf_poison_hit();
    sf_poison_set(-1);
    int pass = 0;
    if (!rc && sf_result_nrows(r) > 0) {
        sf_result_gate_nonfinite(r);
        pass = sf_result_passed(r);
    }
    sf_result_free(r);
    sf_case_free(&c);
    return pass;
}

static void poisoned_case_fails(const fam_case *fc)
{
    int hit;
    if (!run_case(fc, -1, &hit)) {
        print_error("%s fails without a NaN: the test proves nothing\n", fc->path);
        fail();
    }
    /* the first aggregated value, and one further in (another lag, point
       or realisation) */
    const long ks[2] = { 0, 3 };
    for (int i = 0; i < 2; i++) {
        int pass = run_case(fc, ks[i], &hit);
        if (!hit) {
            print_error("%s: value %ld never passed through the aggregation helpers\n", fc->path, ks[i]);
            fail();
        }
        if (pass) {
            print_error("%s: a NaN at aggregated value %ld and the case still passes\n", fc->path, ks[i]);
            fail();
        }
    }
}

#define FAMILY_TEST(fam, ...)                                  \
    static void fam##_nan_fails(void **state)                  \
    {                                                          \
        (void)state;                                           \
        static const fam_case fc = { __VA_ARGS__ };            \
        poisoned_case_fails(&fc);                              \
    }

FAMILY_TEST(field, "cases/field/exact-covariance-minimal.md", NULL)
FAMILY_TEST(lognormal, "cases/lognormal/nataf-map-roundtrip.md", NULL)
FAMILY_TEST(contact, "cases/contact/contensou-sweep-polar.md", NULL)
FAMILY_TEST(surface, "cases/surface/equator-mean-cof.md", NULL)
FAMILY_TEST(stress, "cases/stress/threshold-range.md", NULL)
FAMILY_TEST(deterministic, "cases/deterministic/eps-first-order.md", NULL)
FAMILY_TEST(dynamics, "cases/dynamics/variable-limit.md", NULL)
FAMILY_TEST(limits, "cases/limits/test-large-lr.md",
            "# reduced limits_large_lr\n```scene\ncheck = limits_large_lr\ncof = field\nl = 500000\nqoi_def = cycles\n"
            "cells = 12\nrtol = 1e-9\nT = 20\nt_skip = 5\nsamples = 60\nalpha = 1e-3\n```\n")
FAMILY_TEST(validation, "cases/validation/test-fig16.md",
            "# reduced val_fig16\n```scene\ncheck = val_fig16\ncof = field\ncells = 12\nrtol = 1e-8\n"
            "T = 30\nt_skip = 10\nsweep_param = l_over_R\nsweep = 100\ntolerance = 1e-8\n```\n")
FAMILY_TEST(plan, "cases/plan/test-shortcut.md",
            "# reduced plan_shortcut_boundary\n```scene\ncheck = plan_shortcut_boundary\ncof = field\n"
            "T = 20\nt_skip = 5\ncells = 12\nsweep_param = l_over_R\nsweep = 200, 200000\n"
            "tolerance = 2.3e-3\n```\n")

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nan_row_fails),
        cmocka_unit_test(clean_result_gets_passing_row),
        cmocka_unit_test(nan_in_plot_or_data_fails),
        cmocka_unit_test(helpers_propagate_nan),
        cmocka_unit_test(ks_tests_are_nan_with_a_nan_sample),
        cmocka_unit_test(mwu_test_matches_scipy),
        cmocka_unit_test(rms_test_refuses_nonfinite),
        cmocka_unit_test(field_nan_fails),
        cmocka_unit_test(lognormal_nan_fails),
        cmocka_unit_test(contact_nan_fails),
        cmocka_unit_test(surface_nan_fails),
        cmocka_unit_test(stress_nan_fails),
        cmocka_unit_test(deterministic_nan_fails),
        cmocka_unit_test(dynamics_nan_fails),
        cmocka_unit_test(limits_nan_fails),
        cmocka_unit_test(validation_nan_fails),
        cmocka_unit_test(plan_nan_fails),
    };
    return cmocka_run_group_tests_name("nonfinite", tests, NULL, NULL);
}
