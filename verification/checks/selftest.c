/* Checks that misbehave on purpose, to prove the runner's isolation (a
 * crash, an abort or a hang in one case is that case's failure; the rest
 * still run): tests/isolation/, run by `make test`.  They refuse to run
 * unless SF_SELFTEST=1, so no catalogue case can use them by mistake. */
#include "checks.h"
#include "sf_error.h"

#include <gsl/gsl_rng.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

static int armed(sf_result *r)
{
    const char *e = getenv("SF_SELFTEST");
    if (e && e[0] == '1')
        return 1;
    sf_note(r, "selftest checks run only with SF_SELFTEST=1");
    return 0;
}

static int chk_abort(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    abort();
}

static int chk_segv(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    raise(SIGSEGV);
    return SF_EFAIL;
}

static int chk_hang(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    for (;;)
        pause();
}

static int chk_spin(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    for (volatile unsigned long k = 0;; k++)
        ;
    return SF_EFAIL;
}

static int chk_pass(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    sf_check_abs(r, "1 + 1", 1.0 + 1.0, 2.0, 0);
    const double x[2] = { 0, 1 }, y[2] = { 2, 1.0 + 1.0 };
    sf_plot *p = sf_result_plot(r, "sum", "1 + 1", "operand index (dimensionless)",
                                "value (dimensionless)");
    sf_plot_series(p, "1 + 1", SF_STYLE_POINTS, 2, x, y);
    return SF_SUCCESS;
}

/* a row but no plot: the runner must call it an ERROR */
static int chk_noplot(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    sf_check_abs(r, "1 + 1", 1.0 + 1.0, 2.0, 0);
    return SF_SUCCESS;
}

/* a passing row and two misdrawn plots: gnuplot warns about the first
 * (a flat series on a log axis: "empty y range"), the second has nothing
 * to draw on its log axis.  The runner must call it a FAIL naming both. */
static int chk_badplot(const sf_case *c, sf_result *r)
{
    (void)c;
    if (!armed(r))
        return SF_EINVAL;
    sf_check_abs(r, "1 + 1", 1.0 + 1.0, 2.0, 0);
    const double x[2] = { 1, 2 }, flat[2] = { 2, 2 }, nonpos[2] = { -1, 0 };
    sf_plot *p = sf_result_plot(r, "flat_log", "a flat series on a log axis", "x [-]", "y [-]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "flat", SF_STYLE_LINES, 2, x, flat);
    p = sf_result_plot(r, "nothing_to_draw", "no positive value on a log axis", "x [-]", "y [-]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "non-positive", SF_STYLE_LINES, 2, x, nonpos);
    return SF_SUCCESS;
}

/* A uniform draw from the case's seed, plotted; the false-alarm budget's
 * tests (tests/budget) gate it as a p-value (the replication of a suspect
 * p) or under a deterministic row, u >= tolerance (a tolerance on
 * seed-dependent data: `replicate`). */
static int uniform_draw(const sf_case *c, sf_result *r, int as_p)
{
    if (!armed(r))
        return SF_EINVAL;
    gsl_rng *g = sf_case_rng(c);
    double u = gsl_rng_uniform_pos(g);
    gsl_rng_free(g);
    if (as_p)
        sf_check_pvalue(r, "a uniform draw as a p-value", u, c->spec.alpha, 1);
    else
        sf_check_ge(r, "a uniform draw", u, c->spec.tolerance);
    const double x[2] = { 0, 1 }, y[2] = { u, u };
    sf_plot *pl = sf_result_plot(r, as_p ? "p" : "u", "the draw", "draw index (dimensionless)",
                                 as_p ? "p (dimensionless)" : "u (dimensionless)");
    sf_plot_series(pl, as_p ? "p" : "u", SF_STYLE_LINES, 2, x, y);
    return SF_SUCCESS;
}

static int chk_uniform_p(const sf_case *c, sf_result *r) { return uniform_draw(c, r, 1); }
static int chk_uniform_ge(const sf_case *c, sf_result *r) { return uniform_draw(c, r, 0); }

const sf_check_def sf_checks_selftest[] = {
    { "selftest_abort", chk_abort, "calls abort() (isolation test)" },
    { "selftest_segv", chk_segv, "raises SIGSEGV (isolation test)" },
    { "selftest_hang", chk_hang, "never returns (time-out test)" },
    { "selftest_spin", chk_spin, "spins without end (CPU-time limit test)" },
    { "selftest_pass", chk_pass, "passes (isolation test)" },
    { "selftest_uniform_p", chk_uniform_p, "a uniform draw as a p-value (false-alarm budget test)" },
    { "selftest_uniform_ge", chk_uniform_ge, "a uniform draw under a deterministic row (false-alarm budget test)" },
    { "selftest_noplot", chk_noplot, "a row but no plot: an ERROR (isolation test)" },
    { "selftest_badplot", chk_badplot, "a passing row, two misdrawn plots: a FAIL (isolation test)" },
    { NULL, NULL, NULL }
};
