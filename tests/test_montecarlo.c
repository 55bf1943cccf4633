/* Unit tests: Monte Carlo driver: counter-based seeds, bit-identical
 * results for any thread count, checkpoint and resume; the sweep's
 * aggregation and the summary it prints. */
#include "test_util.h"
#include "montecarlo.h"
#include "sweep.h"
#include "mcstop.h"
#include "antithetic.h"
#include "mlmc.h"
#include "lognormal.h"
#include "scene.h"
#include "cof.h"
#include <stdint.h>
#include "sf_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_statistics_double.h>

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
    /* sf_mc_stream: MT19937 at sf_mc_seed(seed, i), whatever it held before */
    gsl_rng *a = gsl_rng_alloc(gsl_rng_mt19937), *b = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(a, sf_mc_seed(1, 5));
    gsl_rng_get(b);
    sf_mc_stream(b, 1, 5);
    for (int k = 0; k < 10; k++)
        assert_int_equal(gsl_rng_get(a), gsl_rng_get(b));
    gsl_rng_free(a);
    gsl_rng_free(b);
}

/* The stream sf_mc_run gives realisation i is sf_mc_stream(seed, i): a
 * realisation re-run alone (slipfield run --realisation) has its bits. */
static void stream_of_realisation(void **state)
{
    (void)state;
    size_t n = 9;
    double *a = malloc(2 * n * sizeof *a), one[2];
    sf_mc_ops ops = { NULL, NULL, realise };
    sf_mc_spec s = { n, 2, 42, 2, NULL, 0, 0, NULL };
    assert_int_equal(sf_mc_run(&s, &ops, NULL, a, NULL, NULL, 0), SF_SUCCESS);
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    for (size_t i = 0; i < n; i++) {
        sf_mc_stream(r, 42, i);
        realise(NULL, i, r, one);
        assert_memory_equal(one, a + 2 * i, sizeof one);
    }
    gsl_rng_free(r);
    free(a);
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

/* sf_mc_stage_lines: off a terminal, a labelled run prints the time of
 * its first tenth and a line when done; nothing unlabelled, switched off,
 * or for the done line of a run that failed. */
static void stage_lines(void **state)
{
    (void)state;
    char path[] = "/tmp/sf-mc-stage-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    size_t n = 20;
    double *out = malloc(2 * n * sizeof *out);
    sf_mc_ops ops = { NULL, NULL, realise }, bad = { NULL, NULL, fail_at_7 };
    sf_mc_spec s = { n, 2, 42, 1, NULL, 0, 0, "lab" };
    fflush(stderr);
    int saved = dup(2);
    assert_true(saved >= 0 && dup2(fd, 2) == 2);
    int r1 = sf_mc_run(&s, &ops, NULL, out, NULL, NULL, 0);   /* off: nothing */
    sf_mc_stage_lines(1);
    s.label = NULL;
    int r2 = sf_mc_run(&s, &ops, NULL, out, NULL, NULL, 0);   /* unlabelled: nothing */
    s.label = "lab";
    int r3 = sf_mc_run(&s, &ops, NULL, out, NULL, NULL, 0);
    int r4 = sf_mc_run(&s, &bad, NULL, out, NULL, NULL, 0);   /* the first line only */
    sf_mc_stage_lines(0);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    assert_int_equal(r1, SF_SUCCESS);
    assert_int_equal(r2, SF_SUCCESS);
    assert_int_equal(r3, SF_SUCCESS);
    assert_int_equal(r4, SF_EFAIL);
    char text[1000] = { 0 };
    assert_true(lseek(fd, 0, SEEK_SET) == 0);
    ssize_t len = read(fd, text, sizeof text - 1);
    close(fd);
    unlink(path);
    assert_true(len > 0);
    const char *a = strstr(text, "lab: the first 2 of 20 runs took ");
    assert_non_null(a);
    const char *b = strstr(a + 1, "lab: 20 runs done in ");
    assert_non_null(b);
    const char *c = strstr(b + 1, "lab: the first 2 of 20 runs took ");
    assert_non_null(c);
    assert_null(strstr(c + 1, "runs done"));
    assert_ptr_equal(a, text);   /* nothing before: not from the runs switched off or unlabelled */
    free(out);
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

/* The summary row's field named `col` (header of the same table). */
static double summary_field(const char *text, const char *col)
{
    char *t = strdup(text), *save1, *save2;
    char *head = strtok_r(t, "\n", &save1), *row = strtok_r(NULL, "\n", &save1);
    double v = NAN;
    char *h = strtok_r(head, "\t", &save2);
    char *cells[128];
    size_t nc = 0;
    for (char *c = strtok_r(row, "\t", &save1); c && nc < 128; c = strtok_r(NULL, "\t", &save1))
        cells[nc++] = c;
    for (size_t k = 0; h && k < nc; k++, h = strtok_r(NULL, "\t", &save2))
        if (!strcmp(h, col))
            v = strtod(cells[k], NULL);
    free(t);
    return v;
}

/* 16 realisations, 8 of them without a stick fraction (NaN) and one
 * without a PV_x (+Inf): every count and statistic the summary prints
 * is that of the finite values (the summary once said n = 16 over 8). */
/* The diagnostics (header and one row) that `sweep --diagnostics` writes for p. */
static char *diag_text(const char *param, double value, const sf_sweep_point *p)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    sf_sweep_diagnostics_header(f);
    sf_sweep_diagnostics_row(f, param, value, p);
    fclose(f);
    return text;
}

/* The summary that `sweep --summary` writes for p: wide (header and one
 * row, with or without the work column) or long (header and 3 rows). */
static char *sum_text(const char *param, double value, const sf_sweep_point *p, int work, int lng)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (lng) {
        sf_sweep_summary_long_header(f);
        sf_sweep_summary_long_rows(f, param, value, p);
    } else {
        sf_sweep_summary_header(f, work);
        sf_sweep_summary_row(f, param, value, p, work);
    }
    fclose(f);
    return text;
}

/* p's summary (wide, with the work column when work) states ratio q's
 * answer a: its estimate, se, interval, u_num, n and work to the bit,
 * and the same numbers in the long form's row of q */
static void assert_summary_states(const sf_sweep_point *p, int q, const sf_sweep_answer *a, int work)
{
    static const char *const qn[SF_SWEEP_NQ] = { "pv_x", "pv_F", "stick_fraction" };
    char *text = sum_text("l_over_R", 2, p, work, 0), nm[64];
    snprintf(nm, sizeof nm, "%s_ratio_estimate[-]", qn[q]);
    assert_true(summary_field(text, nm) == a->estimate);
    snprintf(nm, sizeof nm, "%s_ratio_se[-]", qn[q]);
    assert_true(summary_field(text, nm) == a->se);
    snprintf(nm, sizeof nm, "%s_ratio_ci95_lo[-]", qn[q]);
    assert_true(summary_field(text, nm) == a->ci_lo);
    snprintf(nm, sizeof nm, "%s_ratio_ci95_hi[-]", qn[q]);
    assert_true(summary_field(text, nm) == a->ci_hi);
    assert_true(summary_field(text, "n") == (double)a->n);
    char w[32];
    snprintf(w, sizeof w, "%.6g", a->work);
    assert_true(work ? summary_field(text, "work") == strtod(w, NULL) : isnan(summary_field(text, "work")));
    assert_true(!work == !strstr(text, "\twork\t"));
    free(text);
    text = sum_text("l_over_R", 2, p, 0, 1);
    char row[400], u[32];
    snprintf(u, sizeof u, "%.3g", a->u_num);
    snprintf(row, sizeof row, "l_over_R\t2\t%s_ratio\t%.17g\t%.17g\t%.17g\t%.17g\t%s\t%zu\t%s\t%s\t-\n", qn[q],
             a->estimate, a->se, a->ci_lo, a->ci_hi, u, a->n, sf_sweep_estimator_name(a->estimator),
             sf_mcstop_reason(a->stop));
    assert_non_null(strstr(text, row));
    assert_non_null(strstr(text, "param\tvalue\tqoi\testimate\tse\tci_lo\tci_hi\tu_num\tn\testimator\tstop\tunit\n"));
    size_t lines = 0;
    for (const char *c = text; *c; c++)
        lines += *c == '\n';
    assert_int_equal(lines, 1 + SF_SWEEP_NQ);
    free(text);
}

static void summary_counts_finite_values(void **state)
{
    (void)state;
    sf_sweep_point p = { .det = { 2, 4, 0.5 }, .n = 16 };
    p.qoi = calloc(16 * SF_SWEEP_NQ, sizeof *p.qoi);
    p.ratio = calloc(16 * SF_SWEEP_NQ, sizeof *p.ratio);
    double sf[8];
    size_t m = 0;
    for (size_t i = 0; i < 16; i++) {
        p.qoi[3 * i] = i == 4 ? INFINITY : 1.5 + 0.01 * (double)(i * i % 7);
        p.qoi[3 * i + 1] = 4 + 0.3 * sin((double)i);
        p.qoi[3 * i + 2] = i % 2 ? NAN : 0.3 + 0.02 * (double)i;
        if (!(i % 2))
            sf[m++] = p.qoi[3 * i + 2];
    }
    assert_int_equal(sf_sweep_point_stats(&p), SF_SUCCESS);
    char *text = diag_text("v_b", 0.6, &p);
    assert_true(summary_field(text, "n") == 16);
    assert_true(summary_field(text, "stick_fraction_n_used") == 8);
    assert_true(summary_field(text, "stick_fraction_n_excluded") == 8);
    assert_true(summary_field(text, "pv_x_n_used") == 15);
    assert_true(summary_field(text, "pv_x_n_excluded") == 1);
    assert_true(summary_field(text, "pv_F_n_used") == 16);
    assert_int_equal(p.n_valid, 7);
    double mean = gsl_stats_mean(sf, 1, 8), sd = gsl_stats_sd(sf, 1, 8), se = sd / sqrt(8.0);
    assert_true(summary_field(text, "stick_fraction_mean[-]") == mean);
    assert_true(summary_field(text, "stick_fraction_std[-]") == sd);
    assert_true(summary_field(text, "stick_fraction_se[-]") == se);
    /* t_{0.975, 7} = 2.36462425159278 (tables) */
    assert_true(fabs(summary_field(text, "stick_fraction_ci95_hi[-]") - (mean + 2.36462425159278 * se)) <= 1e-14);
    assert_true(summary_field(text, "stick_fraction_ratio_mean[-]") == gsl_stats_mean(p.ratio + 2, 6, 8));
    assert_true(isnan(summary_field(text, "no_such_column")));
    assert_non_null(strstr(text, "\nv_b\t0.6\t16\t"));   /* the value as given, not 0.59999999999999998 */
    free(text);
    /* the summary: plain's answer is the ratio mean and its Student interval; no work, no u_num (not estimated) */
    p.stop = SF_MCSTOP_FIXED;
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_answer a;
        assert_int_equal(sf_sweep_estimate(&p, q, &a), SF_SUCCESS);
        assert_true(a.estimator == SF_EST_PLAIN && a.estimate == p.rstat[q].mean && a.se == p.rstat[q].se);
        assert_true(a.ci_lo == p.rstat[q].ci_lo && a.ci_hi == p.rstat[q].ci_hi && a.n == 16);
        assert_true(isnan(a.u_num) && isnan(a.work) && a.stop == SF_MCSTOP_FIXED);
        assert_summary_states(&p, q, &a, 0);
    }
    text = sum_text("v_b", 0.6, &p, 0, 0);
    assert_true(!strncmp(text, "param\tvalue\tpv_x_ratio_estimate[-]\tpv_x_ratio_se[-]\tpv_x_ratio_ci95_lo[-]\t"
                               "pv_x_ratio_ci95_hi[-]\tpv_x_ratio_u_num[-]\tpv_F_ratio_estimate[-]", 128));
    assert_non_null(strstr(text, "\tstick_fraction_ratio_u_num[-]\tn\testimator\tstop\nv_b\t0.6\t"));
    assert_non_null(strstr(text, "\t16\tplain\tfixed\n"));
    free(text);
    text = sum_text("v_b", 0.6, &p, 1, 0);   /* a work column asked of a point without work: nan */
    assert_non_null(strstr(text, "\tn\twork\testimator\tstop\n") && strstr(text, "\t16\tnan\tplain\tfixed\n"));
    free(text);
    /* u_num in ratio units where estimated */
    p.num[SF_SWEEP_PVF] = (sf_sweep_num){ .n_sub = 4, .n_used = 4, .u_mean = 0.5 };
    sf_sweep_answer an;
    assert_int_equal(sf_sweep_estimate(&p, SF_SWEEP_PVF, &an), SF_SUCCESS);
    assert_true(an.u_num == 0.5 / p.det[SF_SWEEP_PVF]);
    /* no such ratio, no such estimator: a NaN answer */
    assert_int_equal(sf_sweep_estimate(&p, -1, &an), SF_EINVAL);
    assert_true(isnan(an.estimate) && isnan(an.u_num));
    assert_int_equal(sf_sweep_estimate(&p, SF_SWEEP_NQ, &an), SF_EINVAL);
    p.estimator = 99;
    assert_int_equal(sf_sweep_estimate(&p, 0, &an), SF_EINVAL);
    assert_true(isnan(an.estimate) && isnan(an.se) && isnan(an.ci_lo) && an.n == 16);
    text = sum_text("v_b", 0.6, &p, 0, 0);
    assert_non_null(strstr(text, "\nv_b\t0.6\tnan\tnan\tnan\tnan\tnan\t") && strstr(text, "\tunknown\tfixed\n"));
    free(text);
    p.estimator = SF_EST_PLAIN;
    /* the estimators that record their work */
    assert_true(!sf_sweep_estimator_work(SF_EST_PLAIN) && !sf_sweep_estimator_work(SF_EST_CV) &&
                !sf_sweep_estimator_work(SF_EST_TARGET) && sf_sweep_estimator_work(SF_EST_MLMC) &&
                sf_sweep_estimator_work(SF_EST_MLMC_BOXES) && sf_sweep_estimator_work(SF_EST_MLMC_SUB) &&
                sf_sweep_estimator_work(SF_EST_ANTITHETIC));
    /* one value: a mean, no spread; none: nothing */
    sf_sweep_stat st;
    double one[2] = { 3, NAN };
    assert_int_equal(sf_sweep_stat_of(one, 1, 2, &st), SF_SUCCESS);
    assert_true(st.n_used == 1 && st.n_excluded == 1 && st.mean == 3 && isnan(st.std) && isnan(st.ci_lo));
    assert_int_equal(sf_sweep_stat_of(one + 1, 1, 1, &st), SF_SUCCESS);
    assert_true(st.n_used == 0 && isnan(st.mean));
    sf_sweep_point_free(&p);
}

/* ---- the two-stage design (mcstop.h) */

static void stein_pieces(void **state)
{
    (void)state;
    assert_string_equal(sf_mcstop_reason(SF_MCSTOP_FIXED), "fixed");
    assert_string_equal(sf_mcstop_reason(SF_MCSTOP_TARGET), "target");
    assert_string_equal(sf_mcstop_reason(SF_MCSTOP_CAP), "cap");
    assert_int_equal(sf_mcstop_size(1, 0.1), 100);
    assert_int_equal(sf_mcstop_size(1.05, 0.1), 111);   /* ceil(110.25) */
    assert_int_equal(sf_mcstop_size(0, 0.1), 1);
    assert_true(sf_mcstop_size(NAN, 0.1) == SIZE_MAX);
    assert_true(sf_mcstop_size(1e300, 1e-300) == SIZE_MAX);
    /* t_{0.975, 9} = 2.262157162798205 (tables) */
    assert_true(fabs(sf_mcstop_halfwidth(2, 10, 100, 0.95) - 2.262157162798205 * 2 / 10) < 1e-14);
    assert_true(isnan(sf_mcstop_halfwidth(2, 1, 100, 0.95)));
    assert_true(isnan(sf_mcstop_halfwidth(2, 10, 0, 0.95)));
    /* the interval: the pilot's spread, every value's mean; NaN left out */
    double x[12] = { 1, 3, NAN, 5, 7, 2, 2, 2, 2, 2, 2, 2 }, lo, hi;
    assert_int_equal(sf_mcstop_interval(x, 1, 5, 12, 0.95, &lo, &hi), SF_SUCCESS);
    double mean = 30.0 / 11, s0 = sqrt(20.0 / 3), hw = sf_mcstop_halfwidth(s0, 4, 11, 0.95);
    assert_true(fabs(0.5 * (lo + hi) - mean) < 1e-14 && fabs(0.5 * (hi - lo) - hw) < 1e-14);
    /* decisions: no target asks for the pilot only; a pilot without two
       finite values, or a target beyond the cap, stops at the cap */
    double pilot[8] = { 1, NAN, 2, NAN, 3, 5, 4, NAN };   /* 4 x 2 */
    double none[2] = { 0, NAN }, t1[2] = { 0.1, 0 }, t2[2] = { 0, 0.1 }, t3[2] = { 10, 0 };
    size_t n;
    int why;
    sf_mcstop_spec st = { 4, 1000, none };
    assert_int_equal(sf_mcstop_decide(&st, 2, pilot, &n, &why), SF_SUCCESS);
    assert_true(n == 4 && why == SF_MCSTOP_TARGET);
    st.target_se = t1;   /* sd of 1..4 = sqrt(5/3): ceil(166.67) */
    assert_int_equal(sf_mcstop_decide(&st, 2, pilot, &n, &why), SF_SUCCESS);
    assert_true(n == 167 && why == SF_MCSTOP_TARGET);
    st.n_max = 100;
    assert_int_equal(sf_mcstop_decide(&st, 2, pilot, &n, &why), SF_SUCCESS);
    assert_true(n == 100 && why == SF_MCSTOP_CAP);
    st.target_se = t2;   /* one finite value */
    assert_int_equal(sf_mcstop_decide(&st, 2, pilot, &n, &why), SF_SUCCESS);
    assert_true(n == 100 && why == SF_MCSTOP_CAP);
    st.target_se = t3;   /* met by the pilot: the floor */
    assert_int_equal(sf_mcstop_decide(&st, 2, pilot, &n, &why), SF_SUCCESS);
    assert_true(n == 4 && why == SF_MCSTOP_TARGET);
}

static void stein_runs(void **state)
{
    (void)state;
    double *a = malloc(200 * 2 * sizeof *a), *b = malloc(200 * 2 * sizeof *b), *c = malloc(200 * 2 * sizeof *c);
    double target[2] = { 1.0, 0 };   /* sd of a sum of 50 normals ~ 7: N ~ 50 */
    sf_mcstop_spec st = { 10, 200, target };
    sf_mc_ops ops = { NULL, NULL, realise };
    sf_mc_spec s = { 0, 2, 42, 1, NULL, 0, 0, NULL };
    size_t na, nb, nc, before;
    int wa, wb, wc;
    char err[200];
    assert_int_equal(sf_mcstop_run(&s, &st, &ops, NULL, a, &na, &wa, NULL, err, sizeof err), SF_SUCCESS);
    assert_true(na > 10 && na < 200 && wa == SF_MCSTOP_TARGET);
    s.threads = 2;   /* the same N and bits on two threads */
    assert_int_equal(sf_mcstop_run(&s, &st, &ops, NULL, b, &nb, &wb, NULL, err, sizeof err), SF_SUCCESS);
    assert_true(nb == na && wb == wa);
    assert_memory_equal(a, b, 2 * na * sizeof *a);
    /* with a checkpoint: a resumed run takes every realisation from it */
    char ck[64];
    snprintf(ck, sizeof ck, "/tmp/sf-test-stein-%ld.ck", (long)getpid());
    s.checkpoint = ck;
    assert_int_equal(sf_mcstop_run(&s, &st, &ops, NULL, c, &nc, &wc, &before, err, sizeof err), SF_SUCCESS);
    assert_true(nc == na && before == 0);
    s.resume = 1;
    int calls = 0;
    assert_int_equal(sf_mcstop_run(&s, &st, &ops, &calls, c, &nc, &wc, &before, err, sizeof err), SF_SUCCESS);
    assert_true(nc == na && before == na && calls == 0);
    assert_memory_equal(a, c, 2 * na * sizeof *a);
    unlink(ck);
    /* a range past n is clipped to n; an empty one (first > upto) runs nothing */
    sf_mc_spec r = { 12, 2, 42, 1, NULL, 0, 0, NULL };
    calls = 0;
    assert_int_equal(sf_mc_run_range(&r, 10, 50, &ops, &calls, c, &before, err, sizeof err), SF_SUCCESS);
    assert_int_equal(calls, 2);
    assert_memory_equal(a + 20, c + 20, 4 * sizeof *a);
    calls = 0;
    assert_int_equal(sf_mc_run_range(&r, 9, 5, &ops, &calls, c, &before, err, sizeof err), SF_SUCCESS);
    assert_int_equal(calls, 0);
    /* a realisation's error stops the run; a bad spec is refused */
    sf_mc_ops bad = { NULL, NULL, fail_at_7 };
    s.checkpoint = NULL;
    s.resume = 0;
    assert_int_equal(sf_mcstop_run(&s, &st, &bad, NULL, a, &na, &wa, NULL, err, sizeof err), SF_EFAIL);
    st.n_pilot = 1;
    assert_int_equal(sf_mcstop_run(&s, &st, &ops, NULL, a, &na, &wa, NULL, err, sizeof err), SF_EINVAL);
    st.n_pilot = 300;
    assert_int_equal(sf_mcstop_run(&s, &st, &ops, NULL, a, &na, &wa, NULL, err, sizeof err), SF_EINVAL);
    free(a);
    free(b);
    free(c);
}

static void stein_sweep(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_VARIABLE;
    s.T = 14;
    s.t_skip = 4;
    sf_sweep_point a, b;
    char err[200];
    assert_int_equal(sf_sweep_run_target(&s, 0.05, 4, 30, 1, NULL, 0, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run_target(&s, 0.05, 4, 30, 2, NULL, 0, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_true(a.n == b.n && a.n >= 4 && a.n_pilot == 4 && a.stop != SF_MCSTOP_FIXED);
    assert_memory_equal(a.qoi, b.qoi, a.n * SF_SWEEP_NQ * sizeof *a.qoi);
    for (int q = 0; q < SF_SWEEP_NQ; q++)   /* Stein's interval is not the Student one */
        assert_true(a.rci_lo[q] < a.rstat[q].mean && a.rstat[q].mean < a.rci_hi[q] && a.rci_lo[q] != a.rstat[q].ci_lo);
    char *text = diag_text("v_b", 0.2, &a);
    assert_true(summary_field(text, "n_pilot") == 4);
    assert_true(summary_field(text, "pv_F_ratio_ci95_lo[-]") == a.rci_lo[SF_SWEEP_PVF]);
    assert_non_null(strstr(text, a.stop == SF_MCSTOP_CAP ? "\tcap\t4\t" : "\ttarget\t4\t"));
    free(text);
    /* the summary: the ratio mean, its se, and the interval the two stages guarantee (Stein's) */
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_answer e;
        assert_int_equal(sf_sweep_estimate(&a, q, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_TARGET && e.estimate == a.rstat[q].mean && e.se == a.rstat[q].se);
        assert_true(e.ci_lo == a.rci_lo[q] && e.ci_hi == a.rci_hi[q] && e.n == a.n && e.stop == a.stop);
        assert_summary_states(&a, q, &e, 0);
    }
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
    assert_int_equal(sf_sweep_run_target(&s, 0, 4, 30, 1, NULL, 0, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_target(&s, 0.1, 1, 30, 1, NULL, 0, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_target(&s, 0.1, 40, 30, 1, NULL, 0, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_target(&s, NAN, 4, 30, 1, NULL, 0, NULL, &a, err, sizeof err), SF_EINVAL);
}

/* ---- the control variate */

/* `sweep --tuples`' rows of a point (sf_sweep_write_tuples): the header,
 * then `want` rows, each with its 11 columns and finite values where the
 * estimator has them (cost row, level0, level1 / pair / cv / row). */
static void assert_tuples(const sf_sweep_point *p, size_t want, const char *level)
{
    FILE *f = tmpfile();
    assert_non_null(f);
    sf_sweep_tuples_header(f);
    sf_sweep_write_tuples(f, "l_over_R", 0.5, p);
    rewind(f);
    char line[2048];
    size_t rows = 0, lv = 0;
    while (fgets(line, sizeof line, f)) {
        size_t tabs = 0;
        for (const char *c = line; *c; c++)
            tabs += *c == '\t';
        assert_int_equal(tabs, 10);
        rows++;
        lv += strstr(line, level) != NULL;
    }
    fclose(f);
    assert_int_equal(rows, want + 1);
    assert_true(lv > 0);
}

static void cv_estimator(void **state)
{
    (void)state;
    size_t n = 50;
    sf_sweep_point p = { .det = { 1, 2, 4 }, .n = n, .cv_known = 0.5 };
    p.qoi = calloc(n * SF_SWEEP_NQ, sizeof *p.qoi);
    p.ratio = calloc(n * SF_SWEEP_NQ, sizeof *p.ratio);
    p.companion = calloc(n, sizeof *p.companion);
    for (size_t i = 0; i < n; i++) {   /* ratio = 1.5 + 3 (C - 0.5) + a wiggle; C NaN once */
        double c = 0.5 + 0.1 * cos(1.7 * (double)i), e = 0.01 * sin(2.9 * (double)i);
        p.companion[i] = i == 7 ? NAN : c;
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            p.qoi[i * SF_SWEEP_NQ + q] = p.det[q] * (1.5 + 3 * (c - 0.5) + e);
    }
    assert_int_equal(sf_sweep_point_stats(&p), SF_SUCCESS);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        assert_int_equal(p.cv[q].m, n - 1);
        assert_true(fabs(p.cv[q].beta - 3) < 0.05 && fabs(p.cv[q].mean - 1.5) < 3 * p.cv[q].se);
        assert_true(p.cv[q].ci_lo < p.cv[q].mean && p.cv[q].mean < p.cv[q].ci_hi);
        assert_true(p.cv[q].vrf > 50);   /* the wiggle is 1/30 of C's part */
    }
    char *text = diag_text("l_over_R", 100, &p);
    assert_true(summary_field(text, "pv_F_cv_ratio_mean[-]") == p.cv[SF_SWEEP_PVF].mean);
    assert_true(summary_field(text, "stick_fraction_cv_vrf[-]") == p.cv[SF_SWEEP_SF].vrf);
    free(text);
    /* the summary: the regression estimate; without a companion (every C NaN, or none held) plain's */
    p.estimator = SF_EST_CV;
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_answer e;
        assert_int_equal(sf_sweep_estimate(&p, q, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_CV && e.estimate == p.cv[q].mean && e.se == p.cv[q].se);
        assert_true(e.ci_lo == p.cv[q].ci_lo && e.ci_hi == p.cv[q].ci_hi && e.n == n && isnan(e.work));
        assert_summary_states(&p, q, &e, 0);
    }
    {
        double *c = p.companion;
        sf_sweep_answer e;
        p.companion = calloc(n, sizeof *p.companion);
        for (size_t i = 0; i < n; i++)
            p.companion[i] = NAN;
        assert_int_equal(sf_sweep_point_stats(&p), SF_SUCCESS);
        assert_int_equal(sf_sweep_estimate(&p, SF_SWEEP_PVF, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_PLAIN && e.estimate == p.rstat[SF_SWEEP_PVF].mean && isfinite(e.estimate));
        assert_true(e.ci_lo == p.rstat[SF_SWEEP_PVF].ci_lo && isnan(p.cv[SF_SWEEP_PVF].mean));
        text = sum_text("l_over_R", 100, &p, 0, 0);
        assert_non_null(strstr(text, "\tplain\tfixed\n"));
        free(text);
        free(p.companion);
        p.companion = NULL;
        assert_int_equal(sf_sweep_estimate(&p, SF_SWEEP_PVF, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_PLAIN && e.estimate == p.rstat[SF_SWEEP_PVF].mean);
        p.companion = c;
        assert_int_equal(sf_sweep_point_stats(&p), SF_SUCCESS);
    }
    p.n = 2;   /* too few for a line with a residual */
    assert_int_equal(sf_sweep_point_stats(&p), SF_SUCCESS);
    assert_true(isnan(p.cv[0].mean) && isnan(p.cv[0].vrf));
    sf_sweep_point_free(&p);
    assert_null(p.companion);
    /* the companion: the COF itself when uniform; none for a window of tiles */
    sf_scene s;
    sf_scene_default(&s);
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(0.37, &u), SF_SUCCESS);
    assert_true(fabs(sf_sweep_companion(u, &s) - 0.37) < 1e-13);
    sf_cof_free(u);
    s.l = 0.05;
    s.strip_halfwidth = 0.05;
    s.cof_generator = SF_COFGEN_TILES;
    sf_cof_plan *pl;
    char err[200];
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    assert_int_equal(sf_cof_plan_alloc(&s, &pl, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_draw(pl, rng, &u), SF_SUCCESS);
    assert_true(isnan(sf_sweep_companion(u, &s)));
    sf_cof_free(u);
    sf_cof_plan_free(pl);
    gsl_rng_free(rng);
    /* a sweep with it: the same bits on two threads, C near mu_mean */
    sf_scene_default(&s);
    s.T = 14;
    s.t_skip = 4;
    s.l = 5;
    sf_sweep_point a, b;
    assert_int_equal(sf_sweep_run_cv(&s, 6, 1, NULL, 0, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run_cv(&s, 6, 2, NULL, 0, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_memory_equal(a.companion, b.companion, 6 * sizeof *a.companion);
    assert_memory_equal(a.qoi, b.qoi, 6 * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_true(fabs(a.companion[0] - 0.5) < 0.5 && a.cv_known == s.mu_mean && isfinite(a.cv[0].mean));
    assert_tuples(&a, 6, "\tcv\t");   /* one row per realisation, its companion beside it */
    free(a.companion);
    a.companion = NULL;
    assert_tuples(&a, 6, "\trow\t");  /* a plain point: the ratios alone */
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
}

/* Where the stages stopped (mlmc.h: sf_mlmc_stage), no level asks for
 * more: the sizes recomputed from the point's final variances and costs
 * are within its counts (derived levels: level 0's variance is its own). */
static void assert_stages_done(const sf_sweep_point *a, size_t n_plain, size_t n_pilot)
{
    double v0[SF_SWEEP_NQ], v1[SF_SWEEP_NQ], vf[SF_SWEEP_NQ];
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        v0[q] = a->ml.q[q].var[0];
        v1[q] = a->ml.q[q].var[1];
        vf[q] = a->ml.q[q].var_fine;
    }
    size_t t0, t1;
    sf_mlmc_sizes(v0, v1, vf, SF_SWEEP_NQ, a->ml.cost[0], a->ml.cost[1], n_plain, n_pilot, &t0, &t1);
    assert_true(t0 <= a->ml.n[0] && t1 <= a->ml.n[1]);
}

/* The tuples of a paired point as `sweep --tuples` writes them (ratios,
 * det = 1), replayed through the pure stage rule and interval functions,
 * give the point's own sizes and intervals bit for bit: they are what the
 * sweep runs (cases/montecarlo/coverage-estimators.md replays them). */
static void assert_anti_replay(const sf_sweep_point *p, size_t n_plain, size_t n_pilot)
{
    static const double one[SF_SWEEP_NQ] = { 1, 1, 1 };
    double *t = malloc(p->n * 2 * SF_SWEEP_NQ * sizeof *t);
    assert_non_null(t);
    for (size_t i = 0; i < p->n; i++)
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            t[i * 2 * SF_SWEEP_NQ + q] = p->ratio[i * SF_SWEEP_NQ + q];
            t[i * 2 * SF_SWEEP_NQ + SF_SWEEP_NQ + q] = p->anti.qoi_anti[i * SF_SWEEP_NQ + q] / p->det[q];
        }
    assert_tuples(p, p->n + 1, "\tpair\t");
    size_t n = n_pilot, g;
    int capped;
    while (1) {   /* every stage uses a prefix of the final pairs */
        assert_int_equal(sf_anti_stage(t, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, n, n_pilot, n_plain, NULL, &g, &capped),
                         SF_SUCCESS);
        if (g == n)
            break;
        assert_true(g > n && g <= p->n);
        n = g;
    }
    assert_int_equal(n, p->n);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_anti e;
        assert_int_equal(sf_anti_interval(t, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, q, n, &e), SF_SUCCESS);
        assert_true(e.m == p->anti.q[q].m && e.mean == p->anti.q[q].mean && e.se == p->anti.q[q].se);
        assert_true(e.ci_lo == p->anti.q[q].ci_lo && e.ci_hi == p->anti.q[q].ci_hi);
    }
    free(t);
}

/* The same for two levels: the interval bit for bit, and the final stage
 * decision (taken at the point's own sizes and costs) is to stop. */
static void assert_mlmc_replay(const sf_sweep_point *p, size_t n_plain, size_t n_pilot, int boxes)
{
    static const double one[SF_SWEEP_NQ] = { 1, 1, 1 };
    size_t n1 = p->ml.n[1], n0 = p->ml.n[0], g0, g1;
    assert_tuples(p, 1 + n0 + n1, "\tlevel0\t");
    double *t = malloc(n1 * 2 * SF_SWEEP_NQ * sizeof *t), *l0 = malloc(n0 * SF_SWEEP_NQ * sizeof *l0);
    assert_true(t && l0);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        for (size_t i = 0; i < n1; i++) {
            t[i * 2 * SF_SWEEP_NQ + q] = p->ratio[i * SF_SWEEP_NQ + q];
            t[i * 2 * SF_SWEEP_NQ + SF_SWEEP_NQ + q] = p->ml.coarse1[i * SF_SWEEP_NQ + q] / p->det[q];
        }
        for (size_t i = 0; i < n0; i++)
            l0[i * SF_SWEEP_NQ + q] = p->ml.coarse0[i * SF_SWEEP_NQ + q] / p->det[q];
    }
    int capped;
    assert_int_equal(sf_mlmc_next(t, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, n1, l0, SF_SWEEP_NQ, n0, one, p->ml.cost[0],
                                  p->ml.cost[1], n_pilot, n_plain, NULL, &g0, &g1, &capped),
                     SF_SUCCESS);
    assert_true(g0 == n0 && g1 == n1);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_ml e;
        assert_int_equal(sf_mlmc_interval(t, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, n1, l0, SF_SWEEP_NQ, n0, one, q, boxes, &e),
                         SF_SUCCESS);
        assert_true(e.m[0] == p->ml.q[q].m[0] && e.m[1] == p->ml.q[q].m[1] && e.mean == p->ml.q[q].mean);
        assert_true(e.se == p->ml.q[q].se && e.df == p->ml.q[q].df);
        assert_true(e.ci_lo == p->ml.q[q].ci_lo && e.ci_hi == p->ml.q[q].ci_hi);
    }
    free(t);
    free(l0);
}

/* The two-level estimator: Giles' sizes, the coarse plan, and a point
 * (the same bits on two threads; level 1's fine values are plain Monte
 * Carlo's; its summary columns). */
static void mlmc_estimator(void **state)
{
    (void)state;
    /* sizes: V1 = 0 leaves level 1 at the pilot and level 0 at
       n_plain V0 / Vf; no usable ratio: the floors; caps hold */
    double v0[3] = { 1, 1, NAN }, v1[3] = { 0, 0, 1 }, vf[3] = { 1, 0, 1 };
    size_t n0, n1;
    sf_mlmc_sizes(v0, v1, vf, 3, 1, 4, 100, 10, &n0, &n1);
    assert_true(n0 == 100 && n1 == 10);
    double w0[1] = { 1 }, w1[1] = { 1 }, wf[1] = { 1 };
    sf_mlmc_sizes(w0, w1, wf, 1, 1, 1, 100, 10, &n0, &n1);   /* 2 x 100 each, capped */
    assert_true(n0 == 200 && n1 == 100);
    sf_mlmc_sizes(w0, w1, wf, 0, 1, 1, 100, 10, &n0, &n1);
    assert_true(n0 == 10 && n1 == 10);
    w1[0] = 100;
    sf_mlmc_sizes(w0, w1, wf, 1, 1, 1, 100, 10, &n0, &n1);   /* level 0 over its cap */
    assert_true(n0 == 400 && n1 == 100);
    /* stages: at most doubled, never shrunk, the want itself once within 2x */
    assert_int_equal(sf_mlmc_stage(10, 48), 20);
    assert_int_equal(sf_mlmc_stage(10, 20), 20);
    assert_int_equal(sf_mlmc_stage(10, 19), 19);
    assert_int_equal(sf_mlmc_stage(10, 21), 20);
    assert_int_equal(sf_mlmc_stage(10, 10), 10);
    assert_int_equal(sf_mlmc_stage(10, 3), 10);
    /* the coarse plan: half the rings (at least 2), rtol raised; cell
       averages keep their cells (the field's boxes) */
    sf_plan f = { 0 }, c;
    f.num.quadrature = 1;
    f.num.cells = 25;
    f.num.rtol = 1e-8;
    sf_mlmc_coarse_plan(&f, &c);
    assert_true(c.num.cells == 13 && c.num.rtol == SF_MLMC_RTOL);
    f.num.cells = 3;
    f.num.rtol = 1e-3;
    sf_mlmc_coarse_plan(&f, &c);
    assert_true(c.num.cells == 2 && c.num.rtol == 1e-3);
    f.num.cell_average = 1;
    f.num.cells = 59;
    sf_mlmc_coarse_plan(&f, &c);
    assert_int_equal(c.num.cells, 59);
    sf_cof_plan_info in = { .kind = SF_COF_VARIABLE };
    assert_true(sf_mlmc_draw_work(&in) == 0);
    in = (sf_cof_plan_info){ .kind = SF_COF_FIELD, .nx = 10, .ny = 10, .box = 0.01 };
    assert_true(sf_mlmc_draw_work(&in) == 100 * SF_MLMC_DRAW_WORK_CELL);
    in.box = 0;
    assert_true(sf_mlmc_draw_work(&in) == 100 * SF_MLMC_DRAW_WORK_POINT);
    /* a point */
    sf_scene s;
    sf_scene_default(&s);
    s.T = 14;
    s.t_skip = 4;
    s.l = 0.5;
    char err[200];
    sf_sweep_point a, b, p;
    assert_int_equal(sf_sweep_run_mlmc(&s, 8, 1, 1, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_mlmc(&s, 3, 4, 1, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_mlmc(&s, 8, 3, 1, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run_mlmc(&s, 8, 3, 2, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run(&s, a.n, 1, NULL, 0, NULL, &p, err, sizeof err), SF_SUCCESS);
    assert_true(a.ml.n[1] == a.n && a.n >= 3 && a.ml.n[0] >= 3);
    assert_memory_equal(a.qoi, b.qoi, a.n * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.qoi, p.qoi, a.n * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.ml.q, b.ml.q, sizeof a.ml.q);
    assert_true(a.ml.n[0] == b.ml.n[0] && a.ml.work == b.ml.work);
    assert_memory_equal(a.ml.coarse0, b.ml.coarse0, a.ml.n[0] * SF_SWEEP_NQ * sizeof *a.ml.coarse0);
    assert_memory_equal(a.ml.coarse1, b.ml.coarse1, a.n * SF_SWEEP_NQ * sizeof *a.ml.coarse1);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const sf_sweep_ml *e = &a.ml.q[q];
        assert_true(isfinite(e->mean) && e->se > 0 && e->ci_lo < e->mean && e->mean < e->ci_hi && e->vrf > 0);
        assert_true(e->var[1] < e->var_fine);   /* one field: the difference varies less than the fine value */
    }
    assert_true(a.ml.cost[0] < a.ml.cost_fine && a.ml.cost_fine < a.ml.cost[1]);
    assert_mlmc_replay(&a, 8, 3, 0);
    char *text = diag_text("l_over_R", 1, &a);
    assert_true(summary_field(text, "pv_F_ml_ratio_mean[-]") == a.ml.q[SF_SWEEP_PVF].mean);
    assert_true(summary_field(text, "ml_n0") == (double)a.ml.n[0]);
    free(text);
    /* the summary: the two-level estimate, n = both levels' samples, the work */
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_answer e;
        assert_int_equal(sf_sweep_estimate(&a, q, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_MLMC && e.estimate == a.ml.q[q].mean && e.se == a.ml.q[q].se);
        assert_true(e.ci_lo == a.ml.q[q].ci_lo && e.ci_hi == a.ml.q[q].ci_hi && e.estimate != a.rstat[q].mean);
        assert_true(e.n == a.ml.n[0] + a.ml.n[1] && e.work == a.ml.work && e.stop == SF_MCSTOP_FIXED);
        assert_summary_states(&a, q, &e, 1);
    }
    text = diag_text("l_over_R", 1, &p);   /* without it: nan */
    assert_true(isnan(summary_field(text, "stick_fraction_ml_vrf[-]")) && isnan(summary_field(text, "ml_cost0")));
    free(text);
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
    sf_sweep_point_free(&p);
    /* a uniform COF: every realisation the same, no variance at either
       level: the estimate stands, its interval has no degrees of freedom */
    s.cof = SF_COF_UNIFORM;
    assert_int_equal(sf_sweep_run_mlmc(&s, 4, 2, 1, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_true(a.ml.n[0] == 2 && a.ml.n[1] == 2 && isfinite(a.ml.q[0].mean) && isnan(a.ml.q[0].df));
    sf_sweep_point_free(&a);
    s.T = 10.5;   /* no deterministic reference: refused before any realisation */
    assert_int_not_equal(sf_sweep_run_mlmc(&s, 4, 2, 1, NULL, &a, err, sizeof err), SF_SUCCESS);
    sf_sweep_point_free(&a);
}

/* Antithetic pairs: the size rule, the antithetic COF of each kind, and
 * a point (the same bits on two threads; the G members are plain Monte
 * Carlo's; its summary columns). */
static void anti_estimator(void **state)
{
    (void)state;
    /* sizes: Var(pair mean) / (Var Q / n_plain), floored at the pilot and
       capped at n_plain; an unusable ratio sets none */
    double vp[3] = { 0.25, 0.01, NAN }, vf[3] = { 1, 1, 1 };
    assert_int_equal(sf_anti_size(vp, vf, 3, 100, 10), 25);
    vp[0] = 2;
    assert_int_equal(sf_anti_size(vp, vf, 3, 100, 10), 100);
    assert_int_equal(sf_anti_size(vp, vf, 0, 100, 10), 10);
    vf[0] = 0;
    vp[1] = 0.05;
    assert_int_equal(sf_anti_size(vp, vf, 2, 100, 10), 10);
    /* the antithetic COF: uniform itself, one variable exp(2 mu_g) / mu,
       a grid node by node; a COF of another kind is refused */
    sf_scene s;
    sf_scene_default(&s);
    sf_lognormal ln;
    sf_lognormal_init(&ln, s.mu_mean, s.mu_std);
    sf_cof_plan *pl;
    sf_cof *c, *a;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    s.cof = SF_COF_VARIABLE;
    assert_int_equal(sf_cof_plan_alloc(&s, &pl, NULL, 0), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_draw(pl, rng, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(pl, c, &a), SF_SUCCESS);
    assert_int_equal(sf_cof_get_kind(a), SF_COF_VARIABLE);
    assert_true(fabs(log(sf_cof_eval(c, 0, 0)) + log(sf_cof_eval(a, 0, 0)) - 2 * ln.mu_g) < 1e-14);
    sf_cof_free(a);
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(0.3, &u), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(pl, u, &a), SF_EINVAL);   /* another kind */
    assert_null(a);
    sf_cof_plan_free(pl);
    s.cof = SF_COF_UNIFORM;
    assert_int_equal(sf_cof_plan_alloc(&s, &pl, NULL, 0), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(pl, u, &a), SF_SUCCESS);
    assert_true(sf_cof_eval(a, 1, 1) == 0.3);
    sf_cof_free(a);
    assert_int_equal(sf_cof_plan_antithetic(pl, c, &a), SF_EINVAL);   /* a variable to a uniform plan */
    sf_cof_plan_free(pl);
    sf_cof_free(c);
    s.cof = SF_COF_FIELD;
    s.l = 0.5;
    s.T = 14;
    s.t_skip = 4;
    assert_int_equal(sf_cof_plan_alloc(&s, &pl, NULL, 0), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(pl, u, &a), SF_EINVAL);
    assert_int_equal(sf_cof_plan_draw(pl, rng, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_set_box(c, 0.01), SF_SUCCESS);   /* cell averages to a point-value plan */
    assert_int_equal(sf_cof_plan_antithetic(pl, c, &a), SF_EINVAL);
    assert_int_equal(sf_cof_set_box(c, 0), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(pl, c, &a), SF_SUCCESS);
    size_t m, n;
    const double *x, *y;
    assert_int_equal(sf_cof_grid_view(c, &m, &n, NULL, NULL, NULL, NULL, &x), SF_SUCCESS);
    assert_int_equal(sf_cof_grid_view(a, NULL, NULL, NULL, NULL, NULL, NULL, &y), SF_SUCCESS);
    for (size_t k = 0; k < m * n; k++)
        assert_true(fabs(log(x[k]) + log(y[k]) - 2 * ln.mu_g) < 1e-13);
    sf_cof_free(a);
    sf_cof_free(c);
    sf_cof_free(u);
    sf_cof_plan_free(pl);
    gsl_rng_free(rng);
    /* a point */
    char err[200];
    sf_sweep_point p, b, q;
    assert_int_equal(sf_sweep_run_antithetic(&s, 8, 1, 1, NULL, &p, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_antithetic(&s, 3, 4, 1, NULL, &p, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_antithetic(&s, 40, 3, 1, NULL, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run_antithetic(&s, 40, 3, 2, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run(&s, p.n, 1, NULL, 0, NULL, &q, err, sizeof err), SF_SUCCESS);
    assert_true(p.anti.n == p.n && p.n >= 3 && p.n <= 40);
    assert_memory_equal(p.qoi, b.qoi, p.n * SF_SWEEP_NQ * sizeof *p.qoi);
    assert_memory_equal(p.qoi, q.qoi, p.n * SF_SWEEP_NQ * sizeof *p.qoi);
    assert_memory_equal(p.anti.qoi_anti, b.anti.qoi_anti, p.n * SF_SWEEP_NQ * sizeof *p.qoi);
    assert_memory_equal(p.anti.q, b.anti.q, sizeof p.anti.q);
    assert_true(p.anti.cost > p.anti.cost_fine && p.anti.work == (double)p.n * p.anti.cost);
    assert_true(p.estimator == SF_EST_ANTITHETIC && q.estimator == SF_EST_PLAIN);
    double sp[SF_SWEEP_NQ], sq[SF_SWEEP_NQ];   /* the stages stopped: the size from the final pairs is within n */
    for (int k = 0; k < SF_SWEEP_NQ; k++) {
        sp[k] = p.anti.q[k].se * p.anti.q[k].se * (double)p.anti.q[k].m;
        sq[k] = p.anti.q[k].var_fine;
    }
    assert_true(sf_anti_size(sp, sq, SF_SWEEP_NQ, 40, 3) <= p.n);
    assert_anti_replay(&p, 40, 3);
    for (int k = 0; k < SF_SWEEP_NQ; k++) {
        const sf_sweep_anti *e = &p.anti.q[k];
        assert_true(isfinite(e->mean) && e->se > 0 && e->ci_lo < e->mean && e->mean < e->ci_hi && e->vrf > 0);
        assert_true(e->m > 2 ? e->rho >= -1 && e->rho <= 1 : isnan(e->rho));   /* a correlation needs 3 pairs */
    }
    char *text = diag_text("l_over_R", 1, &p);
    assert_true(summary_field(text, "pv_F_anti_ratio_mean[-]") == p.anti.q[SF_SWEEP_PVF].mean);
    assert_true(summary_field(text, "anti_n") == (double)p.anti.n);
    assert_true(summary_field(text, "pv_x_anti_n_used") == (double)p.anti.q[SF_SWEEP_PVX].m);
    free(text);
    /* the summary: the pairs' estimate, n = the pairs, the work */
    for (int k = 0; k < SF_SWEEP_NQ; k++) {
        sf_sweep_answer e;
        assert_int_equal(sf_sweep_estimate(&p, k, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_ANTITHETIC && e.estimate == p.anti.q[k].mean && e.se == p.anti.q[k].se);
        assert_true(e.ci_lo == p.anti.q[k].ci_lo && e.ci_hi == p.anti.q[k].ci_hi);
        assert_true(e.n == p.anti.n && e.work == p.anti.work);
        assert_summary_states(&p, k, &e, 1);
    }
    text = diag_text("l_over_R", 1, &q);   /* without it: nan */
    assert_true(isnan(summary_field(text, "stick_fraction_anti_vrf[-]")) && isnan(summary_field(text, "anti_cost")));
    free(text);
    sf_sweep_point_free(&p);
    sf_sweep_point_free(&b);
    sf_sweep_point_free(&q);
    s.T = 10.5;   /* no deterministic reference: refused before any realisation */
    assert_int_not_equal(sf_sweep_run_antithetic(&s, 4, 2, 1, NULL, &p, err, sizeof err), SF_SUCCESS);
    sf_sweep_point_free(&p);
}

/* Two levels on boxes of boxes: the box grid and means (cof.h), the
 * plans, and a point (the same bits on two threads). */
static void boxes_estimator(void **state)
{
    (void)state;
    /* the box grid: 4 x 4 boxes of a 20 x 17 cell-average strip from
       (1, 2) at spacing 0.5 (box 1.5): nodes (20 - 1 - 9) / 4 + 1 = 3 and
       (17 - 1 - 9) / 4 + 1 = 2, origin + 4.5 spacings, spacing 2 */
    sf_cof_plan_info in = { .kind = SF_COF_FIELD, .nx = 20, .ny = 17, .x0 = 1, .y0 = 2, .dx = 0.5, .dy = 0.5,
                            .box = 1.5 }, c;
    assert_int_equal(sf_cof_box_grid(&in, 4, &c), SF_SUCCESS);
    assert_true(c.nx == 3 && c.ny == 2 && c.x0 == 3.25 && c.y0 == 4.25 && c.dx == 2 && c.dy == 2 && c.box == 6);
    assert_int_equal(sf_cof_box_grid(&in, 1, &c), SF_EINVAL);
    in.ny = 10;   /* fewer than 3 (b - 1) + 2 nodes */
    assert_int_equal(sf_cof_box_grid(&in, 4, &c), SF_EINVAL);
    in.ny = 17;
    in.box = 0;   /* point values */
    assert_int_equal(sf_cof_box_grid(&in, 4, &c), SF_EINVAL);
    /* the means: node values i + 100 j, so a box mean is the mean index */
    double v[20 * 17];
    for (size_t j = 0; j < 17; j++)
        for (size_t i = 0; i < 20; i++)
            v[i + 20 * j] = (double)i + 100 * (double)j;
    sf_cof *f, *g;
    assert_int_equal(sf_cof_alloc_grid(20, 17, 1, 2, 0.5, 0.5, v, &f), SF_SUCCESS);
    assert_int_equal(sf_cof_box_means(f, 4, &g), SF_EINVAL);   /* not cell averages */
    assert_int_equal(sf_cof_set_box(f, 1.5), SF_SUCCESS);
    assert_int_equal(sf_cof_box_means(f, 4, &g), SF_SUCCESS);
    size_t m, n;
    double x0, dx;
    const double *u;
    assert_int_equal(sf_cof_grid_view(g, &m, &n, &x0, NULL, &dx, NULL, &u), SF_SUCCESS);
    assert_true(m == 3 && n == 2 && x0 == 3.25 && dx == 2 && sf_cof_box(g) == 6);
    /* node (I, J): fine columns 4 I + {0, 3, 6, 9}, rows 4 J + {0, 3, 6, 9} */
    for (size_t J = 0; J < n; J++)
        for (size_t I = 0; I < m; I++)
            assert_true(fabs(u[I + m * J] - ((double)(4 * I) + 4.5 + 100 * ((double)(4 * J) + 4.5))) < 1e-12);
    sf_cof_free(g);
    sf_cof_free(f);
    /* the plans: refused where the plan draws point values */
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    sf_plan fp, cp, dp;
    char err[200];
    assert_int_equal(sf_mlmc_box_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "cell averages"));
    assert_int_equal(sf_sweep_estimator_auto(&s), SF_EST_MLMC_SUB);   /* point values on the strip, l/R 0.2 */
    assert_string_equal(sf_sweep_estimator_name(SF_EST_ANTITHETIC), "antithetic");
    assert_string_equal(sf_sweep_estimator_name(-1), "unknown");
    assert_string_equal(sf_sweep_estimator_name(SF_EST_MLMC_SUB + 1), "unknown");
    s.l = 0.015;   /* l/R = 0.03: the plan's cell averages, 59 cells -> 60 */
    s.T = 14;
    s.t_skip = 4;
    assert_int_equal(sf_mlmc_box_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_SUCCESS);
    assert_true(fp.num.cells % SF_MLMC_BOX == 0 && cp.num.cells == fp.num.cells / SF_MLMC_BOX);
    assert_int_equal(sf_sweep_estimator_auto(&s), SF_EST_MLMC_BOXES);
    assert_true(fabs(dp.cof.box - SF_MLMC_BOX * fp.cof.box) < 1e-15 && cp.num.rtol == SF_MLMC_RTOL);
    /* a point, on one and two threads */
    sf_sweep_point a, b;
    assert_int_equal(sf_sweep_run_mlmc_boxes(&s, 40, 3, 1, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run_mlmc_boxes(&s, 40, 3, 2, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_true(a.ml.n[0] >= 3 && a.ml.n[1] >= 3 && a.ml.n[0] == b.ml.n[0] && a.ml.n[1] == b.ml.n[1]);
    assert_memory_equal(a.qoi, b.qoi, a.n * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.ml.coarse0, b.ml.coarse0, a.ml.n[0] * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.ml.q, b.ml.q, sizeof a.ml.q);
    assert_true(a.ml.cost[0] < a.ml.cost_fine && isfinite(a.ml.q[0].mean) && a.ml.q[0].se > 0);
    assert_int_equal(a.estimator, SF_EST_MLMC_BOXES);
    assert_stages_done(&a, 40, 3);
    assert_mlmc_replay(&a, 40, 3, 1);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {   /* the summary: the two-level estimate */
        sf_sweep_answer e;
        assert_int_equal(sf_sweep_estimate(&a, q, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_MLMC_BOXES && e.estimate == a.ml.q[q].mean && e.ci_hi == a.ml.q[q].ci_hi);
        assert_true(e.n == a.ml.n[0] + a.ml.n[1] && e.work == a.ml.work);
        assert_summary_states(&a, q, &e, 1);
    }
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
    assert_int_equal(sf_sweep_run_mlmc_boxes(&s, 8, 1, 1, NULL, &a, err, sizeof err), SF_EINVAL);
    sf_sweep_point_free(&a);
}

/* Two levels on every 2nd node: the grid and the subsample (cof.h), the
 * plans, the rule of `--estimator auto`, and a point (the same bits on
 * two threads; level 1's fine values are plain's). */
static void sub_estimator(void **state)
{
    (void)state;
    sf_cof_plan_info in = { .kind = SF_COF_FIELD, .nx = 9, .ny = 4, .x0 = 1, .y0 = 2, .dx = 0.5, .dy = 0.25 }, c;
    assert_int_equal(sf_cof_sub_grid(&in, 2, &c), SF_SUCCESS);
    assert_true(c.nx == 5 && c.ny == 2 && c.x0 == 1 && c.y0 == 2 && c.dx == 1 && c.dy == 0.5);
    assert_int_equal(sf_cof_sub_grid(&in, 1, &c), SF_EINVAL);
    assert_int_equal(sf_cof_sub_grid(&in, 4, &c), SF_EINVAL);   /* fewer than 2 coarse rows */
    in.box = 0.1;
    assert_int_equal(sf_cof_sub_grid(&in, 2, &c), SF_EINVAL);   /* cell averages */
    in.box = 0;
    in.generator = SF_COFGEN_TILES;
    assert_int_equal(sf_cof_sub_grid(&in, 2, &c), SF_EINVAL);
    double v[9 * 4];
    for (size_t k = 0; k < 36; k++)
        v[k] = (double)k;
    sf_cof *f, *g;
    assert_int_equal(sf_cof_alloc_grid(9, 4, 1, 2, 0.5, 0.25, v, &f), SF_SUCCESS);
    assert_int_equal(sf_cof_subsample(f, 2, &g), SF_SUCCESS);
    size_t m, n;
    const double *u;
    assert_int_equal(sf_cof_grid_view(g, &m, &n, NULL, NULL, NULL, NULL, &u), SF_SUCCESS);
    assert_true(m == 5 && n == 2 && u[0] == 0 && u[1] == 2 && u[4] == 8 && u[5] == 18 && u[9] == 26);
    sf_cof_free(g);
    assert_int_equal(sf_cof_subsample(f, 4, &g), SF_EINVAL);
    assert_int_equal(sf_cof_set_box(f, 0.1), SF_SUCCESS);
    assert_int_equal(sf_cof_subsample(f, 2, &g), SF_EINVAL);   /* cell averages */
    sf_cof_free(f);
    /* the plans and the rule */
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    s.T = 14;
    s.t_skip = 4;
    sf_plan fp, cp, dp;
    char err[200];
    assert_int_equal(sf_mlmc_sub_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_SUCCESS);
    assert_true(dp.cof.dx == 2 * fp.cof.dx && cp.cof.nx == dp.cof.nx && cp.num.rtol == SF_MLMC_RTOL);
    s.l = 10 * s.R;
    assert_int_equal(sf_sweep_estimator_auto(&s), SF_EST_ANTITHETIC);   /* l/R >= 5 */
    s.l = s.R;
    assert_int_equal(sf_sweep_estimator_auto(&s), SF_EST_MLMC);   /* 0.5 <= l/R < 5 */
    s.l = 0.05 * s.R;
    s.cof_generator = SF_COFGEN_TILES;
    s.cof_model = SF_COFMODEL_POINT;
    assert_int_equal(sf_mlmc_sub_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_EINVAL);   /* tiles */
    assert_int_equal(sf_sweep_estimator_auto(&s), SF_EST_ANTITHETIC);
    s.cof = SF_COF_VARIABLE;
    assert_int_equal(sf_mlmc_sub_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_estimator_auto(&s), SF_EST_ANTITHETIC);
    /* a point */
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    s.l = s.R;
    s.T = 14;
    s.t_skip = 4;
    sf_sweep_point a, b, p;
    assert_int_equal(sf_sweep_run_mlmc_sub(&s, 40, 3, 1, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run_mlmc_sub(&s, 40, 3, 2, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_sweep_run(&s, a.n, 1, NULL, 0, NULL, &p, err, sizeof err), SF_SUCCESS);
    assert_true(a.estimator == SF_EST_MLMC_SUB && a.ml.n[0] == b.ml.n[0] && a.ml.n[1] == b.ml.n[1]);
    assert_memory_equal(a.qoi, b.qoi, a.n * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.qoi, p.qoi, a.n * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.ml.coarse0, b.ml.coarse0, a.ml.n[0] * SF_SWEEP_NQ * sizeof *a.qoi);
    assert_memory_equal(a.ml.q, b.ml.q, sizeof a.ml.q);
    assert_string_equal(sf_sweep_estimator_name(a.estimator), "mlmc-sub");
    assert_stages_done(&a, 40, 3);
    assert_mlmc_replay(&a, 40, 3, 1);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {   /* the summary: the two-level estimate */
        sf_sweep_answer e;
        assert_int_equal(sf_sweep_estimate(&a, q, &e), SF_SUCCESS);
        assert_true(e.estimator == SF_EST_MLMC_SUB && e.estimate == a.ml.q[q].mean && e.ci_lo == a.ml.q[q].ci_lo);
        assert_true(e.n == a.ml.n[0] + a.ml.n[1] && e.work == a.ml.work);
        assert_summary_states(&a, q, &e, 1);
    }
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
    sf_sweep_point_free(&p);
}

/* The estimators at a target standard error (sf_sweep_run_estimator_se):
 * refusals; a point that meets its targets says so, and its standard
 * errors are within them (the sizes' rule: the final variances over the
 * final sizes); a tighter target takes more; one beyond the cap says
 * cap. */
static void estimator_targets(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    s.l = s.R;
    s.T = 14;
    s.t_skip = 4;
    char err[200];
    sf_sweep_point a, b;
    double none[SF_SWEEP_NQ] = { NAN, NAN, NAN }, neg[SF_SWEEP_NQ] = { 0.01, -1, NAN };
    double tse[SF_SWEEP_NQ] = { 0.1, 0.1, 0.1 }, tight[SF_SWEEP_NQ] = { 0.06, 0.06, 0.06 };
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, none, 3, 40, 1, NULL, &a, err, sizeof err),
                     SF_EINVAL);
    assert_non_null(strstr(err, "no ratio has a target"));
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_MLMC, NULL, 3, 40, 1, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, neg, 3, 40, 1, NULL, &a, err, sizeof err),
                     SF_EINVAL);
    assert_non_null(strstr(err, "finite and > 0"));
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_CV, tse, 3, 40, 1, NULL, &a, err, sizeof err), SF_EINVAL);
    assert_non_null(strstr(err, "control-variate"));
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, tse, 3, 60, 1, NULL, &a, err, sizeof err),
                     SF_SUCCESS);
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, tight, 3, 60, 2, NULL, &b, err, sizeof err),
                     SF_SUCCESS);
    assert_true(a.stop == SF_MCSTOP_TARGET && b.stop == SF_MCSTOP_TARGET && b.n > a.n);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        assert_true(a.anti.q[q].se <= tse[q] && b.anti.q[q].se <= tight[q]);
    sf_sweep_point_free(&a);
    sf_sweep_point_free(&b);
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_MLMC_SUB, tse, 3, 60, 1, NULL, &a, err, sizeof err),
                     SF_SUCCESS);
    assert_true(a.stop == SF_MCSTOP_TARGET && a.estimator == SF_EST_MLMC_SUB);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        assert_true(a.ml.q[q].se <= tse[q]);
    sf_sweep_point_free(&a);
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_MLMC, tight, 3, 4, 1, NULL, &a, err, sizeof err),
                     SF_SUCCESS);
    assert_true(a.stop == SF_MCSTOP_CAP && a.estimator == SF_EST_MLMC && a.ml.n[1] <= 4);
    sf_sweep_point_free(&a);
    double inf[SF_SWEEP_NQ] = { INFINITY, 0.1, 0.1 };
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_MLMC, inf, 3, 40, 1, NULL, &a, err, sizeof err), SF_EINVAL);
    /* the sizes' rule: a ratio with a target not finite and > 0, or a
       variance not finite and >= 0, asks for none */
    double t5[5] = { 0, INFINITY, 0.01, 0.01, 0.01 }, v05[5] = { 1, 1, -1, 1, INFINITY }, v15[5] = { 1, 1, 1, -1, 1 };
    double m0, m1;
    sf_mlmc_want(v05, v15, t5, 5, 1, 1, &m0, &m1);
    assert_true(m0 == 0 && m1 == 0);
    sf_mlmc_want(v15, v15, t5 + 2, 1, 1, 1, &m0, &m1);   /* V0 = V1 = 1, C = 1, target 0.01 */
    assert_true(m0 == 200 && m1 == 200);
    double vp4[4] = { 1, 1, -1, INFINITY };
    assert_true(sf_anti_want(vp4, t5, 4) == 0 && sf_anti_want(vp4, t5 + 2, 1) == 100);
    /* one variable per realisation, T = 14 s: some pairs form no PV_x; a
       ratio whose spread is not known asks for the cap */
    s.cof = SF_COF_VARIABLE;
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, tse, 3, 3, 1, NULL, &a, err, sizeof err),
                     SF_SUCCESS);
    assert_true(a.stop == SF_MCSTOP_CAP && a.n == 3);
    sf_sweep_point_free(&a);
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, tse, 3, 40, 1, NULL, &a, err, sizeof err),
                     SF_SUCCESS);
    assert_true(a.n > 3);
    sf_sweep_point_free(&a);
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_MLMC, tse, 3, 3, 1, NULL, &a, err, sizeof err), SF_SUCCESS);
    assert_true(a.ml.n[1] == 3);
    sf_sweep_point_free(&a);
    /* boxes of boxes at a target (l/R = 0.03: the plan's cell averages) */
    s.cof = SF_COF_FIELD;
    s.l = 0.015;
    assert_int_equal(sf_sweep_run_estimator_se(&s, SF_EST_MLMC_BOXES, tse, 3, 8, 1, NULL, &a, err, sizeof err),
                     SF_SUCCESS);
    assert_true(a.estimator == SF_EST_MLMC_BOXES && a.stop != SF_MCSTOP_FIXED);
    sf_sweep_point_free(&a);
}

/* The refusals of the derived fields and the antithetic (cof.h) and of
 * the derived levels' plans (mlmc.h), branch by branch. */
static void derived_refusals(void **state)
{
    (void)state;
    sf_cof_plan_info in = { .kind = SF_COF_FIELD, .nx = 20, .ny = 17, .dx = 0.5, .dy = 0.5, .box = 1.5 }, c;
    sf_cof_plan_info bad = in;
    bad.kind = SF_COF_UNIFORM;
    assert_int_equal(sf_cof_box_grid(&bad, 4, &c), SF_EINVAL);
    assert_int_equal(sf_cof_sub_grid(&bad, 2, &c), SF_EINVAL);
    bad = in;
    bad.generator = SF_COFGEN_TILES;
    assert_int_equal(sf_cof_box_grid(&bad, 4, &c), SF_EINVAL);
    bad = in;
    bad.dx = 0;
    assert_int_equal(sf_cof_box_grid(&bad, 4, &c), SF_EINVAL);
    bad = in;
    bad.nx = 10;
    assert_int_equal(sf_cof_box_grid(&bad, 4, &c), SF_EINVAL);
    bad.box = 0;
    bad.nx = 2;
    assert_int_equal(sf_cof_sub_grid(&bad, 2, &c), SF_EINVAL);   /* fewer than k + 1 nodes in x */
    sf_cof *u, *g, *a;
    assert_int_equal(sf_cof_alloc_uniform(0.3, &u), SF_SUCCESS);
    assert_int_equal(sf_cof_box_means(u, 4, &g), SF_EINVAL);
    assert_int_equal(sf_cof_subsample(u, 2, &g), SF_EINVAL);
    double v[4] = { 1, 2, 3, 4 };
    sf_cof *f;
    assert_int_equal(sf_cof_alloc_grid(2, 2, 0, 0, 1, 1, v, &f), SF_SUCCESS);
    assert_int_equal(sf_cof_subsample(f, 1, &g), SF_EINVAL);   /* k < 2 */
    assert_int_equal(sf_cof_subsample(f, 2, &g), SF_EINVAL);   /* fewer than k + 1 nodes */
    assert_int_equal(sf_cof_set_box(f, 1), SF_SUCCESS);
    assert_int_equal(sf_cof_box_means(f, 4, &g), SF_EINVAL);   /* too few nodes for 4 x 4 boxes */
    /* a tiled window: no derived field, and its antithetic is refused by a strip plan */
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    s.T = 14;
    s.t_skip = 4;
    s.l = 0.05 * s.R;
    s.cof_model = SF_COFMODEL_POINT;
    s.cof_generator = SF_COFGEN_TILES;
    sf_cof_plan *tp, *sp;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    sf_cof *w;
    assert_int_equal(sf_cof_plan_alloc(&s, &tp, NULL, 0), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_draw(tp, rng, &w), SF_SUCCESS);
    assert_int_equal(sf_cof_subsample(w, 2, &g), SF_EINVAL);
    assert_int_equal(sf_cof_box_means(w, 2, &g), SF_EINVAL);
    s.l = s.R;
    s.cof_generator = SF_COFGEN_CIRCULANT;
    assert_int_equal(sf_cof_plan_alloc(&s, &sp, NULL, 0), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(sp, w, &a), SF_EINVAL);   /* a window to a strip plan */
    assert_int_equal(sf_cof_plan_antithetic(sp, NULL, &a), SF_EINVAL);
    sf_cof *grid;
    assert_int_equal(sf_cof_plan_draw(sp, rng, &grid), SF_SUCCESS);
    assert_int_equal(sf_cof_plan_antithetic(tp, grid, &a), SF_EINVAL);   /* a strip to a tiles plan */
    assert_int_equal(sf_cof_plan_antithetic(sp, u, &a), SF_EINVAL);   /* a uniform COF to a field plan */
    sf_cof_free(grid);
    sf_cof_free(w);
    sf_cof_plan_free(tp);
    sf_cof_plan_free(sp);
    gsl_rng_free(rng);
    sf_cof_free(f);
    sf_cof_free(u);
    /* the plans: a cell-average scene refuses every 2nd node, a tiled one both */
    sf_plan fp, cp, dp;
    char err[200];
    s.l = 0.015;
    s.cof_model = SF_COFMODEL_AUTO;
    assert_int_equal(sf_mlmc_sub_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_EINVAL);
    s.l = 0.05 * s.R;
    s.cof_model = SF_COFMODEL_POINT;
    s.cof_generator = SF_COFGEN_TILES;
    assert_int_equal(sf_mlmc_sub_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_EINVAL);
    assert_int_equal(sf_mlmc_box_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_EINVAL);
    s.T = -1;   /* no plan at all */
    assert_int_not_equal(sf_mlmc_sub_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_SUCCESS);
    assert_int_not_equal(sf_mlmc_box_plans(&s, &fp, &cp, &dp, err, sizeof err), SF_SUCCESS);
    sf_sweep_point p;
    s.T = 14;
    assert_int_equal(sf_sweep_run_mlmc_sub(&s, 4, 2, 1, NULL, &p, err, sizeof err), SF_EINVAL);
    sf_sweep_point_free(&p);
    s.cof_generator = SF_COFGEN_CIRCULANT;
    s.l = s.R;
    s.R = -1;   /* a scene no plan is made for */
    assert_int_not_equal(sf_sweep_run_antithetic(&s, 4, 2, 1, NULL, &p, err, sizeof err), SF_SUCCESS);
    sf_sweep_point_free(&p);
}

static void shortest_text(void **state)
{
    (void)state;
    char b[32];
    const double x[] = { 0.1, 0.2, 1, 20, 1e6, 1e20, 1e-300, 0.30000000000000004, 2.0 / 3, -7.25 };
    const char *want[] = { "0.1", "0.2", "1", "20", "1000000", "1e+20", "1e-300", "0.30000000000000004", NULL, "-7.25" };
    for (size_t i = 0; i < sizeof x / sizeof *x; i++) {
        sf_sweep_fmt(b, sizeof b, x[i]);
        assert_true(strtod(b, NULL) == x[i]);
        if (want[i])
            assert_string_equal(b, want[i]);
    }
}

/* The pure stage rules' edges: a target whose ratio has no finite spread
 * yet asks for the cap; one sample on a level has no variance. */
static void stage_edges(void **state)
{
    (void)state;
    static const double one[SF_SWEEP_NQ] = { 1, 1, 1 };
    double v[8 * 2 * SF_SWEEP_NQ], l0[8 * SF_SWEEP_NQ], tse[SF_SWEEP_NQ] = { 0.01, 0.01, 0.01 };
    for (size_t i = 0; i < 8; i++)
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            v[i * 2 * SF_SWEEP_NQ + q] = 1 + 0.1 * (double)((i * 7 + (size_t)q) % 5);
            v[i * 2 * SF_SWEEP_NQ + SF_SWEEP_NQ + q] = 1 - 0.05 * (double)((i * 3 + (size_t)q) % 4);
            l0[i * SF_SWEEP_NQ + q] = 1 + 0.02 * (double)((i + (size_t)q) % 3);
        }
    for (size_t i = 0; i < 8; i++)   /* ratio 2 never finite: no spread to size it by */
        v[i * 2 * SF_SWEEP_NQ + 2] = NAN;
    size_t g, g0, g1;
    int capped = 0;
    assert_int_equal(sf_anti_stage(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, 8, 4, 40, tse, &g, &capped), SF_SUCCESS);
    assert_true(capped && g > 8);
    capped = 0;
    assert_int_equal(sf_mlmc_next(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, 8, l0, SF_SWEEP_NQ, 8, one, 1, 2, 4, 40, tse, &g0,
                                  &g1, &capped), SF_SUCCESS);
    assert_true(capped && g1 > 8);
    /* no pairs yet: no interval (NaN), sizes from the pilot */
    sf_sweep_anti ea;
    sf_sweep_ml em;
    assert_int_equal(sf_anti_interval(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, 0, 0, &ea), SF_SUCCESS);
    assert_true(isnan(ea.ci_lo));
    assert_int_equal(sf_anti_stage(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, one, 0, 4, 40, NULL, &g, &capped), SF_SUCCESS);
    assert_int_equal(sf_mlmc_next(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, 8, l0, SF_SWEEP_NQ, 0, one, 1, 2, 4, 40, NULL, &g0,
                                  &g1, &capped), SF_SUCCESS);
    assert_int_equal(sf_mlmc_interval(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, 8, l0, SF_SWEEP_NQ, 0, one, 0, 0, &em),
                     SF_SUCCESS);
    /* one sample a level: no variance, no size from it */
    assert_int_equal(sf_mlmc_next(v, 2 * SF_SWEEP_NQ, SF_SWEEP_NQ, 1, l0, SF_SWEEP_NQ, 1, one, 1, 2, 1, 40, NULL, &g0,
                                  &g1, &capped), SF_SUCCESS);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(seeds),
        cmocka_unit_test(thread_count_invariance),
        cmocka_unit_test(stream_of_realisation),
        cmocka_unit_test(stage_lines),
        cmocka_unit_test(checkpoint_resume),
        cmocka_unit_test(summary_counts_finite_values),
        cmocka_unit_test(shortest_text),
        cmocka_unit_test(stein_pieces),
        cmocka_unit_test(stein_runs),
        cmocka_unit_test(stein_sweep),
        cmocka_unit_test(cv_estimator),
        cmocka_unit_test(mlmc_estimator),
        cmocka_unit_test(anti_estimator),
        cmocka_unit_test(boxes_estimator),
        cmocka_unit_test(sub_estimator),
        cmocka_unit_test(derived_refusals),
        cmocka_unit_test(estimator_targets),
        cmocka_unit_test(stage_edges),
    };
    return cmocka_run_group_tests_name("montecarlo", tests, NULL, NULL);
}
