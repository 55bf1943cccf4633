/* Unit tests: the lognormal (Nataf) parameter map and distortion. */
#include "test_util.h"
#include "lognormal.h"
#include "sf_error.h"

static void parameters(void **state)
{
    (void)state;
    sf_lognormal ln;
    assert_int_equal(sf_lognormal_init(&ln, 0.5, 0.1), SF_SUCCESS);
    assert_close(ln.cv, 0.2, 1e-15);
    assert_close(ln.sigma_g, sqrt(log(1.04)), 1e-15);
    assert_close(ln.mu_g, log(0.5) - 0.5 * log(1.04), 1e-15);
    /* E[H] = exp(mu_g + sigma_g^2/2), Var = (e^{s^2} - 1) E^2 */
    assert_close(exp(ln.mu_g + 0.5 * ln.sigma_g * ln.sigma_g), 0.5, 1e-15);
    assert_close(sqrt(expm1(ln.sigma_g * ln.sigma_g)) * 0.5, 0.1, 1e-14);
    assert_close(sf_lognormal_map(&ln, 0.0), exp(ln.mu_g), 1e-15);
    assert_close(sf_lognormal_cdf(&ln, exp(ln.mu_g)), 0.5, 1e-14);
}

static void invalid(void **state)
{
    (void)state;
    sf_lognormal ln;
    assert_int_equal(sf_lognormal_init(&ln, 0.0, 0.1), SF_EINVAL);
    assert_int_equal(sf_lognormal_init(&ln, -1.0, 0.1), SF_EINVAL);
    assert_int_equal(sf_lognormal_init(&ln, 0.5, -0.1), SF_EINVAL);
    assert_int_equal(sf_lognormal_init(&ln, NAN, 0.1), SF_EINVAL);
    assert_int_equal(sf_lognormal_init(&ln, 0.5, INFINITY), SF_EINVAL);
}

static void distortion(void **state)
{
    (void)state;
    sf_lognormal ln;
    sf_lognormal_init(&ln, 0.5, 0.5);
    assert_close(sf_lognormal_rho_h(&ln, 1.0), 1.0, 1e-15);
    assert_close(sf_lognormal_rho_h(&ln, 0.0), 0.0, 1e-15);
    double s2 = log(2.0);
    assert_close(sf_lognormal_rho_h(&ln, 0.5), (exp(0.5 * s2) - 1) / (exp(s2) - 1), 1e-15);
    for (double r = -1; r <= 1.0001; r += 0.125)
        assert_close(sf_lognormal_rho_g(&ln, sf_lognormal_rho_h(&ln, r)), r, 1e-14);
    assert_true(sf_lognormal_rho_h(&ln, 0.5) < 0.5);   /* distortion lowers correlation */
    sf_lognormal_init(&ln, 0.5, 0.0);                   /* std 0: identity, no 0/0 */
    assert_close(sf_lognormal_rho_h(&ln, 0.3), 0.3, 0);
    assert_close(sf_lognormal_rho_g(&ln, 0.3), 0.3, 0);
    sf_lognormal_init(&ln, 0.5, 1e-9);                  /* tiny CV: still accurate */
    assert_close(sf_lognormal_rho_h(&ln, 0.3), 0.3, 1e-9);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(parameters),
        cmocka_unit_test(invalid),
        cmocka_unit_test(distortion),
    };
    return cmocka_run_group_tests_name("lognormal", tests, NULL, NULL);
}
