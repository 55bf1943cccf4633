/* Unit tests: results.json (margins, the JSON of a case, non-finite values,
 * escaping), the drift rules (verification/results.c, drift.c) and the
 * plot renderer's reading of gnuplot's messages (result.c). */
#include "test_util.h"
#include "drift.h"
#include "report.h"
#include "result.h"
#include "results.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <jansson.h>

static void results_row_margins(void **state)
{
    (void)state;
    sf_result *r = sf_result_alloc();
    sf_check_abs(r, "abs", 1.5, 1.0, 1.0);       /* 0.5 of 1 */
    sf_check_rel(r, "rel", 10.3, 10.0, 0.1);     /* 0.3 of 1.0 */
    sf_check_le(r, "le", 0.95, 1.0);             /* 0.95: near the edge */
    sf_check_le(r, "le negative value", -3, 1.0); /* far below: 0 */
    sf_check_le(r, "le negative bound", -5, -1);  /* passes, 1/5 of the way */
    sf_check_ge(r, "ge", 4, 2);                  /* 2/4 */
    sf_check_ge(r, "ge negative bound", -0.5, -1); /* passes: half the allowance */
    sf_check_ge(r, "ge fails", -2, -1);           /* fails: 2 */
    sf_check_pvalue(r, "test", 0.02, 0.01, 100); /* alpha / p = 0.5 */
    sf_check_true(r, "holds", 1, "yes");
    const double want[] = { 0.5, 0.3, 0.95, 0, 0.2, 0.5, 0.5, 2, 0.5 };
    for (size_t i = 0; i < 9; i++) {
        assert_close(sf_row_margin(sf_result_row(r, i)), want[i], 1e-12);
        /* above 1 exactly when the row fails */
        assert_int_equal(sf_row_margin(sf_result_row(r, i)) <= 1, sf_result_row(r, i)->pass);
    }
    assert_true(isnan(sf_row_margin(sf_result_row(r, 9))));
    assert_string_equal(sf_row_kind_name(sf_result_row(r, 8)->test), "statistical");
    assert_string_equal(sf_row_kind_name(sf_result_row(r, 9)->test), "boolean");
    assert_string_equal(sf_row_test_name(sf_result_row(r, 6)->test), "ge");
    size_t at;
    assert_close(sf_result_margin(r, &at), 2, 0);
    assert_int_equal(at, 7);
    sf_result_free(r);

    /* a NaN measured value: NaN margin, and the case's margin is +inf */
    r = sf_result_alloc();
    sf_check_le(r, "ok", 0.1, 1);
    sf_check_abs(r, "nan", NAN, 0, 1);
    assert_true(isnan(sf_row_margin(sf_result_row(r, 1))));
    assert_true(isinf(sf_result_margin(r, &at)));
    assert_int_equal(at, 1);
    sf_result_free(r);
    /* only boolean rows: no margin */
    r = sf_result_alloc();
    sf_check_true(r, "holds", 1, NULL);
    assert_true(isnan(sf_result_margin(r, NULL)));
    sf_result_free(r);
}

/* Near the edge: a count at its bound ("13 of 13 >= 13": margin 1 by
 * construction), a count against 0 and an exact equality say nothing of
 * how near a case is to failing and are left out of its margin; the same
 * rows failing, and a real margin, count. */
static void results_fixed_margins(void **state)
{
    (void)state;
    sf_result *r = sf_result_alloc();
    sf_check_ge(r, "releases before the circle's (all of them)", 13, 13);   /* 1, cannot move */
    sf_check_le(r, "realisations excluded", 0, 0);                        /* 0, cannot move */
    sf_check_abs(r, "bits that differ", 0, 0, 0);                        /* exact equality */
    sf_check_le(r, "error", 0.5, 1);                                     /* a real margin */
    assert_true(sf_row_margin_fixed(sf_result_row(r, 0)));
    assert_true(sf_row_margin_fixed(sf_result_row(r, 1)));
    assert_true(sf_row_margin_fixed(sf_result_row(r, 2)));
    assert_false(sf_row_margin_fixed(sf_result_row(r, 3)));
    assert_close(sf_row_margin(sf_result_row(r, 0)), 1, 0);   /* the row's own margin is unchanged */
    size_t at;
    assert_close(sf_result_margin(r, &at), 0.5, 0);
    assert_int_equal(at, 3);
    /* a count above its bound, or a non-whole value at it, is a margin */
    sf_check_ge(r, "instants exercised", 21, 20);
    sf_check_le(r, "residual", 0.25, 0.25);
    assert_false(sf_row_margin_fixed(sf_result_row(r, 4)));
    assert_false(sf_row_margin_fixed(sf_result_row(r, 5)));
    assert_close(sf_result_margin(r, &at), 1, 0);
    assert_int_equal(at, 5);
    sf_result_free(r);
    /* only such rows: no margin, not near the edge */
    r = sf_result_alloc();
    sf_check_ge(r, "realisations with a PV_F formed", 1000, 1000);
    assert_true(isnan(sf_result_margin(r, NULL)));
    /* failing, they count */
    sf_check_ge(r, "releases (all of them)", 12, 13);
    sf_check_abs(r, "bits that differ", 1, 0, 0);
    assert_false(sf_row_margin_fixed(sf_result_row(r, 1)));
    assert_false(sf_row_margin_fixed(sf_result_row(r, 2)));
    assert_true(isinf(sf_result_margin(r, &at)));
    assert_int_equal(at, 2);
    sf_result_free(r);
}

static void results_case_json(void **state)
{
    (void)state;
    char dir[] = "/tmp/sf-results-test.XXXXXX";
    assert_non_null(mkdtemp(dir));
    sf_result *r = sf_result_alloc();
    sf_check_abs(r, "quote \" backslash \\ newline \n tab \t", 1.0 / 3.0, 0.25, 0.1);
    sf_check_le(r, "nan measured", NAN, 1e-12);
    sf_check_rel(r, "inf measured", INFINITY, 1, 0.1);
    sf_check_pvalue(r, "bad bytes \xff\xfe", 0.5, 1e-3, 4000);
    sf_check_true(r, "holds", 1, "fine");
    sf_outcome o;
    memset(&o, 0, sizeof o);
    snprintf(o.id, sizeof o.id, "fam/name");
    snprintf(o.family, sizeof o.family, "fam");
    snprintf(o.key, sizeof o.key, "key");
    o.verdict = SF_VERDICT_FAIL;
    o.seed = 4294967295UL;
    o.seconds = 0.25;
    char err[256];
    assert_int_equal(sf_results_case_write(dir, NULL, r, &o, err, sizeof err), 0);
    char path[300];
    snprintf(path, sizeof path, "%s/result.json", dir);
    json_error_t je;
    json_t *j = json_load_file(path, 0, &je);
    assert_non_null(j);
    assert_string_equal(json_string_value(json_object_get(j, "verdict")), "fail");
    assert_int_equal(json_integer_value(json_object_get(j, "seed")), 4294967295LL);
    json_t *rows = json_object_get(j, "rows");
    assert_int_equal(json_array_size(rows), 5);
    json_t *r0 = json_array_get(rows, 0);
    assert_string_equal(json_string_value(json_object_get(r0, "quantity")),
                        "quote \" backslash \\ newline \n tab \t");
    /* 17 digits: the double reads back to the same bits */
    assert_true(json_real_value(json_object_get(r0, "measured")) == 1.0 / 3.0);
    assert_true(json_real_value(json_object_get(r0, "tolerance")) == 0.1);
    assert_null(json_object_get(r0, "nonfinite"));
    json_t *r1 = json_array_get(rows, 1);
    assert_true(json_is_null(json_object_get(r1, "measured")));
    assert_string_equal(json_string_value(json_object_get(json_object_get(r1, "nonfinite"), "measured")), "nan");
    assert_true(json_is_null(json_object_get(r1, "expected")));   /* a bound row: none */
    assert_null(json_object_get(json_object_get(r1, "nonfinite"), "expected"));
    assert_false(json_is_true(json_object_get(r1, "pass")));
    json_t *r2 = json_array_get(rows, 2);
    assert_string_equal(json_string_value(json_object_get(json_object_get(r2, "nonfinite"), "measured")), "inf");
    json_t *r3 = json_array_get(rows, 3);
    assert_string_equal(json_string_value(json_object_get(r3, "quantity")), "bad bytes ?? (n = 4000): p-value");
    assert_string_equal(json_string_value(json_object_get(r3, "kind")), "statistical");
    assert_int_equal(json_integer_value(json_object_get(r3, "n")), 4000);
    assert_true(json_real_value(json_object_get(r3, "alpha")) == 1e-3);
    assert_true(json_is_null(json_object_get(json_array_get(rows, 4), "margin")));
    /* the case's margin is +inf (the NaN row): null plus the flag */
    assert_true(json_is_null(json_object_get(j, "margin")));
    assert_string_equal(json_string_value(json_object_get(json_object_get(j, "nonfinite"), "margin")), "inf");
    json_decref(j);
    sf_result_free(r);
    unlink(path);
    rmdir(dir);
}

static void drift_rules(void **state)
{
    (void)state;
    /* exact: 10 units of round-off of the values compared */
    assert_false(sf_drift_exact_moved(1.0, 1.0, 1.0));
    assert_false(sf_drift_exact_moved(1.0, 1.0 + 8 * DBL_EPSILON, 1.0));
    assert_true(sf_drift_exact_moved(1.0, 1.0 + 16 * DBL_EPSILON, 1.0));
    assert_true(sf_drift_exact_moved(100.0, 100.0 + 1e-12, NAN));
    assert_false(sf_drift_exact_moved(100.0, 100.0 + 1e-13, NAN));
    /* an error metric at round-off level: the round-off of its O(1) operands */
    assert_false(sf_drift_exact_moved(3e-16, 6e-16, 0));
    assert_false(sf_drift_exact_moved(1.8e-15, 1.9e-15, NAN));
    assert_true(sf_drift_exact_moved(3e-16, 3e-15, 0));
    assert_true(sf_drift_exact_moved(3.0e-10, 3.1e-10, NAN));   /* an error that grew */
    assert_false(sf_drift_exact_moved(1e6, 1e6 + 1e-9, 1e6));   /* the scale is the values' */
    assert_true(sf_drift_exact_moved(1e6, 1e6 + 1e-8, 1e6));
    assert_true(sf_drift_exact_moved(1.0, NAN, 1.0));
    assert_false(sf_drift_exact_moved(NAN, NAN, 1.0));
    assert_false(sf_drift_exact_moved(INFINITY, INFINITY, 1.0));
    assert_true(sf_drift_exact_moved(INFINITY, -INFINITY, 1.0));
    /* statistical: |dz| > 2 sqrt 2 */
    assert_false(sf_drift_pvalue_moved(0.5, 0.5));
    assert_false(sf_drift_pvalue_moved(0.5, 0.05));    /* z 0 -> 1.64 */
    assert_true(sf_drift_pvalue_moved(0.5, 1e-3));     /* z 0 -> 3.09 */
    assert_false(sf_drift_pvalue_moved(1.0, 0.9));
    assert_false(sf_drift_pvalue_moved(0.0, 1e-300));
    assert_true(sf_drift_pvalue_moved(0.3, NAN));
    /* a chaotic case's exact row: round-off amplified, 1e-6 of the scale */
    assert_false(sf_drift_chaotic_moved(0.2, 0.2 + 1e-8, NAN));    /* PV_x moved by round-off */
    assert_true(sf_drift_chaotic_moved(0.2, 0.2 * 1.05, NAN));     /* by a 5% defect */
    assert_true(sf_drift_chaotic_moved(1.0, NAN, 1.0));
    assert_true(sf_drift_chaotic_family("dynamics"));
    assert_false(sf_drift_chaotic_family("field"));
    /* a p-value from the same draws: the exact rows' null, not |dz| > 2 sqrt 2 */
    assert_false(sf_drift_pvalue_coupled_moved(0.7755, 0.7755, 0));
    assert_true(sf_drift_pvalue_coupled_moved(0.7755, 0.7761, 1));  /* |dz| = 0.002: independent draws would not flag it */
    assert_false(sf_drift_pvalue_coupled_moved(0.7755, 0.7755 * (1 + 1e-8), 1));
    assert_true(sf_drift_pvalue_coupled_moved(0.7755, 0.7755 * (1 + 1e-8), 0));
    /* run time: more than 2x and more than 0.5 s */
    assert_false(sf_drift_time_grew(0.01, 0.1));
    assert_false(sf_drift_time_grew(1.0, 1.9));
    assert_true(sf_drift_time_grew(1.0, 2.1));
    assert_false(sf_drift_time_grew(10.0, 15.0));
}

/* gnuplot runs for real: a clean plot, a warning (a failing row naming
 * the plot and quoting gnuplot, not the echoed command) and an error (no
 * output folder: -1, the plot named). */
static void results_render_plots(void **state)
{
    (void)state;
    char dir[] = "/tmp/sf-plot-XXXXXX", err[400], path[600];
    assert_non_null(mkdtemp(dir));
    const double x[] = { 1, 2, 3 }, y[] = { 1, 4, 9 }, flat[] = { 2, 2, 2 };
    sf_result *r = sf_result_alloc();
    sf_plot_series(sf_result_plot(r, "clean", "clean", "x [m]", "y [m]"), "y", SF_STYLE_LINES, 3, x, y);
    sf_plot *p = sf_result_plot(r, "flat_log", "flat", "x [m]", "y [m]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "flat", SF_STYLE_LINES, 3, x, flat);
    assert_int_equal(sf_result_render_plots(r, dir, err, sizeof err), 1);
    assert_non_null(strstr(err, "plot flat_log: Warning: empty y range"));
    assert_int_equal(sf_result_nrows(r), 1);
    assert_false(sf_result_row(r, 0)->pass);
    for (size_t i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "%s/%s.png", dir, i ? "flat_log" : "clean");
        assert_int_equal(access(path, R_OK), 0);
        unlink(path);
    }
    rmdir(dir);
    sf_result_free(r);

    r = sf_result_alloc();
    sf_plot_series(sf_result_plot(r, "lost", "lost", "x [m]", "y [m]"), "y", SF_STYLE_LINES, 3, x, y);
    assert_int_equal(sf_result_render_plots(r, "/nonexistent/sf-plot", err, sizeof err), -1);
    assert_non_null(strstr(err, "gnuplot failed (status 1) on plot lost: line "));
    assert_non_null(strstr(err, "cannot open file"));
    assert_null(strstr(err, "set output"));
    sf_result_free(r);
}

/* A log x axis spans the data, not whole decades: l/R 0.25 and 1 once
 * drew from 0.1 (validation/quick-claims-lr).  gnuplot runs the plot's
 * own script and prints the x range it drew. */
static void results_plot_log_range(void **state)
{
    (void)state;
    char dir[] = "/tmp/sf-plot-XXXXXX", path[600], why[200], cmd[700];
    assert_non_null(mkdtemp(dir));
    const double x[] = { 0.25, 1 }, y[] = { 1.1, 1.3 }, lo[] = { 1.05, 1.2 }, hi[] = { 1.15, 1.4 };
    sf_result *r = sf_result_alloc();
    sf_plot *p = sf_result_plot(r, "lr", "lr", "l/R [-]", "ratio [-]");
    sf_plot_log(p, 1, 0);
    sf_plot_series(p, "mean", SF_STYLE_LINES, 2, x, y);
    sf_plot_errorbars(p, "interval", 2, x, y, lo, hi);
    snprintf(path, sizeof path, "%s/script.gp", dir);
    FILE *g = fopen(path, "w");
    assert_non_null(g);
    char png[600];
    snprintf(png, sizeof png, "%s/lr.png", dir);
    sf_plot_write_script(g, p, png, why, sizeof why);
    fprintf(g, "set print '-'\nprint sprintf('%%.6g %%.6g', GPVAL_X_MIN, GPVAL_X_MAX)\n");
    fclose(g);
    assert_string_equal(why, "");
    snprintf(cmd, sizeof cmd, "gnuplot '%s' 2>/dev/null", path);
    FILE *o = popen(cmd, "r");
    assert_non_null(o);
    double xmin = NAN, xmax = NAN;
    assert_int_equal(fscanf(o, "%lf %lf", &xmin, &xmax), 2);
    assert_int_equal(pclose(o), 0);
    /* within 10% of the data's ends (log scale: 0.23 .. 1.06), not 0.1 */
    assert_true(xmin > 0.2 && xmin < 0.25);
    assert_true(xmax > 1 && xmax < 1.1);
    /* a range of 600 decades (stress/wrench-extremes): gnuplot runs (no
     * "inf" in the script: the range is computed in logs) */
    const double xw[] = { 1e-300, 1e300 }, yw[] = { 1, 0.5 };
    sf_plot *pw = sf_result_plot(r, "wide", "wide", "eps [-]", "f [-]");
    sf_plot_log(pw, 1, 0);
    sf_plot_series(pw, "f", SF_STYLE_LINES, 2, xw, yw);
    g = fopen(path, "w");
    assert_non_null(g);
    sf_plot_write_script(g, pw, png, why, sizeof why);
    fclose(g);
    snprintf(cmd, sizeof cmd, "gnuplot '%s' 2>/dev/null", path);
    assert_int_equal(system(cmd), 0);
    unlink(png);
    unlink(path);
    rmdir(dir);
    sf_result_free(r);
}

/* Row labels are kept whole: the longest in the catalogue (montecarlo/
 * mlmc-boxes-levels, once cut at 159 characters after "(bits; the") and
 * one as long as SF_LABEL_LEN allows, also through a p-value's label. */
static void results_long_labels(void **state)
{
    (void)state;
    static const char longest[] = "level 1's first fine and coarse values and level 0's first pair mean (3 QoIs each) "
                                  "that differ from this check's runs on the fields of their streams (bits; the same "
                                  "operations)";
    char most[SF_LABEL_LEN], test[SF_LABEL_LEN], want[SF_LABEL_LEN + 32];
    memset(most, 'q', sizeof most - 1);
    most[sizeof most - 1] = '\0';
    memset(test, 't', 300);
    test[300] = '\0';
    sf_result *r = sf_result_alloc();
    sf_check_le(r, longest, 0, 0);
    sf_check_abs(r, most, 1, 1, 0);
    sf_check_pvalue(r, test, 0.5, 0.01, 1000);
    sf_result_sample(r, longest, 10, 0);
    assert_string_equal(sf_result_row(r, 0)->quantity, longest);
    assert_string_equal(sf_result_row(r, 1)->quantity, most);
    snprintf(want, sizeof want, "%s (n = 1000): p-value", test);
    assert_string_equal(sf_result_row(r, 2)->quantity, want);
    assert_string_equal(sf_result_sample_at(r, 0)->what, longest);
    sf_result_free(r);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(results_row_margins),
        cmocka_unit_test(results_fixed_margins),
        cmocka_unit_test(results_case_json),
        cmocka_unit_test(drift_rules),
        cmocka_unit_test(results_render_plots),
        cmocka_unit_test(results_long_labels),
        cmocka_unit_test(results_plot_log_range),
    };
    return cmocka_run_group_tests_name("results", tests, NULL, NULL);
}
