/* Unit tests: scene parsing (good and bad input), defaults, case reading. */
#include "test_util.h"
#include "scene.h"
#include "sf_error.h"
#include "case.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* A case's scene block: the solver's keys and the case's (check,
 * sweep, ...), one parser. */
static int parse(sf_scene *s, const char *text, char *err)
{
    sf_case_spec v;
    sf_scene_default(s);
    sf_case_spec_default(&v);
    return sf_case_scene_parse(s, &v, text, "t.scene", 1, err, 256);
}

static void scene_defaults_are_table1(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    assert_close(s.m, 10, 0);
    assert_close(s.k, 30, 0);
    assert_close(s.v_b, 0.2, 0);
    assert_close(s.R, 0.5, 0);
    assert_close(s.l, 0.1, 0);
    assert_close(s.mu_mean, 0.5, 0);
    assert_close(s.mu_std, 0.1, 0);
    assert_close(s.mu_k_ratio, 0.9, 0);
    assert_close(s.g, 9.81, 0);
    assert_close(s.T, 100, 0);
    assert_close(s.eps_lambda, 1e-3, 0);
    assert_int_equal(sf_scene_was_set(&s, "l"), 0);
    sf_case_spec v;
    sf_case_spec_default(&v);
    assert_int_equal(v.tier, SF_TIER_QUICK);
    assert_int_equal(v.vv, SF_VV_CODE);
    assert_close(v.alpha, 1e-3, 0);
}

static void scene_good_input(void **state)
{
    (void)state;
    sf_scene s;
    sf_case_spec v;
    char err[256];
    sf_scene_default(&s);
    sf_case_spec_default(&v);
    /* a case's scene block: the solver's keys and the case's, one parser */
    assert_int_equal(sf_case_scene_parse(&s, &v, "# comment\n  l = 0.25   # trailing\n\nnx=7\ncof = uniform\n"
                               "no_padding = yes\nsweep = 1, 2.5 ,3e-2\nseed = 18446744073709551615\n"
                               "check = field_exact_covariance\n", "t.scene", 1, err, sizeof err), SF_SUCCESS);
    assert_close(s.l, 0.25, 0);
    assert_int_equal(s.nx, 7);
    assert_int_equal(s.cof, 0);
    assert_int_equal(s.no_padding, 1);
    assert_int_equal(v.sweep.n, 3);
    assert_close(v.sweep.v[2], 0.03, 1e-15);
    assert_true(s.seed == 18446744073709551615UL);
    assert_string_equal(v.check, "field_exact_covariance");
    assert_int_equal(sf_scene_was_set(&s, "l"), 1);
    assert_int_equal(sf_scene_was_set(&s, "check"), 0);   /* not a solver key */
    /* the solver alone knows nothing of checks */
    sf_scene_default(&s);
    assert_int_equal(sf_scene_parse(&s, "check = field_exact_covariance\n", "t.scene", 1, err, 256), SF_EPARSE);
    assert_non_null(strstr(err, "t.scene:1: unknown key 'check'"));
}

static void expect_error(const char *text, const char *fragment)
{
    sf_scene s;
    char err[256] = "";
    assert_int_equal(parse(&s, text, err), SF_EPARSE);
    if (!strstr(err, fragment)) {
        print_error("error '%s' does not contain '%s'\n", err, fragment);
        fail();
    }
}

static void scene_bad_input(void **state)
{
    (void)state;
    expect_error("l = -1\n", "t.scene:1: key 'l': must be > 0");
    expect_error("\n\nfoo = 1\n", "t.scene:3: unknown key 'foo'");
    expect_error("l = nan\n", "key 'l': expected a finite number");
    expect_error("l = inf\n", "key 'l': expected a finite number");
    expect_error("l =\n", "key 'l': missing value");
    expect_error("l = 0.1\nl = 0.2\n", "t.scene:2: key 'l': set twice");
    expect_error("l 0.1\n", "expected 'key = value'");
    expect_error("= 3\n", "missing key");
    expect_error("l = 1e999\n", "expected a finite number");
    expect_error("nx = -3\n", "non-negative whole number");
    expect_error("nx = 2.5\n", "non-negative whole number");
    expect_error("nx = 0\n", "key 'nx': must be >= 1");
    expect_error("cof = random\n", "expected one of uniform|variable|field");
    expect_error("no_padding = maybe\n", "expected true or false");
    expect_error("sweep = 1,,2\n", "item 2 is not a finite number");
    expect_error("sweep = 1,2,\n", "trailing comma");
    expect_error("check = a b\n", "only letters");
    expect_error("mu_k_ratio = 1.5\n", "must be > 0 and <= 1");
    expect_error("l = 0.1\x01\n", "non-printable");
    expect_error("seed = -1\n", "non-negative whole number");
}

static void scene_huge_line(void **state)
{
    (void)state;
    size_t n = 1u << 20;
    char *big = malloc(n + 16);
    memcpy(big, "l = ", 4);
    memset(big + 4, '1', n);
    strcpy(big + 4 + n, "\n");
    sf_scene s;
    char err[256];
    assert_int_equal(parse(&s, big, err), SF_EPARSE);
    free(big);
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void case_reader(void **state)
{
    (void)state;
    char dir[] = "/tmp/sf_case_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char fam[600], path[700];
    snprintf(fam, sizeof fam, "%s/fam", dir);
    assert_int_equal(mkdir(fam, 0777), 0);
    snprintf(path, sizeof path, "%s/good-case.md", fam);
    write_file(path, "# Title here\n\nProse.\n\n```scene\ncheck = field_exact_covariance\ntolerance = 1e-12\n```\nAfter.\n");
    sf_case c;
    char err[512];
    assert_int_equal(sf_case_read(&c, path, err, sizeof err), SF_SUCCESS);
    assert_string_equal(c.id, "fam/good-case");
    assert_string_equal(c.title, "Title here");
    assert_int_equal(c.scene_line, 6);
    sf_case_free(&c);

    snprintf(path, sizeof path, "%s/bad.md", fam);
    write_file(path, "# T\n```scene\ncheck = field_exact_covariance\nl = -2\ntolerance = 1\n```\n");
    assert_int_equal(sf_case_read(&c, path, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "bad.md:4: key 'l'"));
    sf_case_free(&c);

    write_file(path, "# T\n```scene\ncheck = field_exact_covariance\ntolerance = 1\n");
    assert_int_equal(sf_case_read(&c, path, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "unterminated"));
    sf_case_free(&c);

    write_file(path, "# T\n```scene\ncheck = no_such_check\ntolerance = 1\n```\n");
    assert_int_equal(sf_case_read(&c, path, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "unknown check"));
    sf_case_free(&c);

    write_file(path, "# T\n```scene\ncheck = field_exact_covariance\n```\n");
    assert_int_equal(sf_case_read(&c, path, err, sizeof err), SF_EPARSE);
    assert_non_null(strstr(err, "neither 'tolerance' nor 'alpha'"));
    sf_case_free(&c);

    snprintf(path, sizeof path, "%s/Bad Name.md", fam);
    write_file(path, "# T\n");
    assert_int_equal(sf_case_read(&c, path, err, sizeof err), SF_EPARSE);
    sf_case_free(&c);
    char cmd[800];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    assert_int_equal(system(cmd), 0);
}

/* Power alternatives: parsed strictly, applied to a copy of the scene
 * (the generator's), generator-only quantities default to the null. */
static void power_alternative(void **state)
{
    (void)state;
    sf_alt a;
    char err[256];
    assert_int_equal(sf_alt_parse("mu_std*1.05", &a, err, sizeof err), SF_SUCCESS);
    sf_scene s;
    sf_scene_default(&s);
    sf_alt_apply(&a, &s);
    assert_close(s.mu_std, 0.105, 1e-15);
    assert_close(s.l, 0.1, 0);
    assert_close(sf_alt_field_std(&a), 1, 0);
    assert_int_equal(sf_alt_parse("re_im_corr+0.1", &a, err, sizeof err), SF_SUCCESS);
    assert_close(sf_alt_re_im_corr(&a), 0.1, 0);
    assert_int_equal(sf_alt_parse("field_std*1.05", &a, err, sizeof err), SF_SUCCESS);
    assert_close(sf_alt_field_std(&a), 1.05, 0);
    const char *bad[] = { "mu_std", "seed*2", "l*x", "l*-1", "re_im_corr+1.5", "*2", "mu_std*nan" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_int_equal(sf_alt_parse(bad[i], &a, err, sizeof err), SF_EPARSE);
    /* a case naming a power_alt must be statistical (alpha) and valid */
    sf_case c;
    const char *ok = "# t\n```scene\ncheck = field_pointwise_moments\nalpha = 1e-3\npower_alt = field_std*1.05\n```\n";
    const char *noalpha = "# t\n```scene\ncheck = field_pointwise_moments\ntolerance = 1\npower_alt = l*1.1\n```\n";
    const char *unknown = "# t\n```scene\ncheck = field_pointwise_moments\nalpha = 1e-3\npower_alt = nx*2\n```\n";
    assert_int_equal(sf_case_parse(&c, "cases/field/t.md", ok, strlen(ok), err, sizeof err), SF_SUCCESS);
    assert_string_equal(c.alternative, "");   /* a normal run draws under the null */
    sf_case_free(&c);
    assert_int_equal(sf_case_parse(&c, "cases/field/t.md", noalpha, strlen(noalpha), err, sizeof err), SF_EPARSE);
    sf_case_free(&c);
    assert_int_equal(sf_case_parse(&c, "cases/field/t.md", unknown, strlen(unknown), err, sizeof err), SF_EPARSE);
    sf_case_free(&c);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scene_defaults_are_table1),
        cmocka_unit_test(scene_good_input),
        cmocka_unit_test(scene_bad_input),
        cmocka_unit_test(scene_huge_line),
        cmocka_unit_test(case_reader),
        cmocka_unit_test(power_alternative),
    };
    return cmocka_run_group_tests_name("scene", tests, NULL, NULL);
}
