/* The plan's skip decisions (docs/design.md sec. 1.2): each shortcut
 * against the full computation it replaces (scene key shortcuts = false),
 * on a grid of scenes at the shortcut's boundary.
 *  - plan_shortcut_boundary: one random variable instead of a field when
 *    the strip is short against l, and closed forms instead of a field and
 *    quadrature when mu_std = 0.  The two runs are coupled: the shortcut
 *    gets the value of the full run's field where the disc starts.
 *  - plan_history_skip: a summary-only run (no history) gives the same
 *    bits as a run that records every step and samples x.
 *  - plan_reuse: a plan reused across realisations draws the same bits as
 *    a fresh plan per realisation.
 *  - plan_qoi_tol: the accuracy-driven numerical plan (numplan.h) meets
 *    the scene's qoi_tol across l/R. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "cof.h"
#include "montecarlo.h"
#include "oscillator.h"
#include "sf_error.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NQ = 3 };
static const char *const qname[NQ] = { "PV_x", "PV_F", "stick fraction" };

static void qois(const sf_osc_result *res, double *q)
{
    q[0] = res->pv_x;
    q[1] = res->pv_F;
    q[2] = res->stick_fraction;
}

/* Largest relative deviation from mu0 of the COF over the belt region the
 * disc covered in run a (a 401 x 41 lattice over the bounding rectangle
 * of the contact patches: belt x in [x_min - v_b T - R, x_max + R], |y| up
 * to y_absmax + R). */
static double cof_spread(const sf_cof *cof, const sf_scene *s, const sf_osc_result *a, double mu0)
{
    double x0 = a->x_min - s->v_b * s->T - s->R, x1 = a->x_max + s->R, y1 = a->y_absmax + s->R, d = 0;
    for (int j = 0; j <= 40; j++)
        for (int i = 0; i <= 400; i++) {
            double mu = sf_cof_eval(cof, x0 + (x1 - x0) * i / 400.0, -y1 + 2 * y1 * j / 40.0);
            d = sf_max(d, fabs(mu - mu0) / mu0);
        }
    return d;
}

/* One scene of the boundary grid: the full run (shortcuts off) and the
 * coupled shortcut run.  Fills dq[NQ] (relative differences), *delta
 * (COF spread) and *taken (the plan's decision with shortcuts on). */
static int boundary_point(const sf_scene *s, sf_result *r, double *dq, double *delta, int *taken, double *e2)
{
    char err[256] = "";
    sf_cof_plan *p;
    int rc = sf_cof_plan_alloc(s, &p, err, sizeof err);
    if (rc) {
        sf_note(r, "**Plan failed:** %s", err);
        return rc;
    }
    const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
    *taken = in->shortcut;
    *e2 = (in->strip_diag / s->l) * (in->strip_diag / s->l);
    sf_cof_plan_free(p);
    sf_scene full = *s;
    full.shortcuts = 0;
    if ((rc = sf_cof_plan_alloc(&full, &p, err, sizeof err))) {
        sf_note(r, "**Full plan failed:** %s", err);
        return rc;
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, s->seed);
    sf_cof *field = NULL, *one = NULL;
    rc = sf_cof_plan_draw(p, rng, &field);
    gsl_rng_free(rng);
    double mu0 = rc ? NAN : sf_cof_eval(field, 0, 0);   /* where the disc starts */
    sf_cof_plan_free(p);
    if (!rc)
        rc = sf_cof_alloc_uniform(mu0, &one);
    sf_osc_result a, b;
    double qa[NQ], qb[NQ];
    if (!rc && !(rc = check_osc_run(&full, NULL, field, 0, &a, NULL, NULL, r))) {
        qois(&a, qa);
        *delta = cof_spread(field, &full, &a, mu0);
        sf_osc_result_free(&a);
        if (!(rc = check_osc_run(s, NULL, one, 0, &b, NULL, NULL, r))) {
            qois(&b, qb);
            sf_osc_result_free(&b);
            for (int q = 0; q < NQ; q++)
                dq[q] = fabs(qa[q] - qb[q]) / fabs(qb[q]);
        }
    }
    sf_cof_free(field);
    sf_cof_free(one);
    return rc;
}

/* Shortcut vs full computation over the sweep.  Two rows per QoI and
 * scene: the coupled difference within 2 delta + 100 rtol (every scene:
 * each QoI moves at most in proportion to the COF, so a COF within
 * (1 +- delta) of mu0 moves it by at most ~delta; the factor 2 covers the
 * within-cycle spread, whose sensitivity is 1/(1 - mu_k/mu_s)); and, where
 * the plan takes the shortcut, within the case's tolerance (its promise). */
static int chk_shortcut_boundary(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param)
        return SF_EINVAL;
    double floor_ = 100 * s0->rtol;
    double *x = check_alloc(K * sizeof *x), *dmax = check_alloc(K * sizeof *dmax);
    double *dl = check_alloc(K * sizeof *dl);
    size_t n_taken = 0, n_full = 0;
    sf_note(r, "Coupled runs: the full computation (shortcuts = false: a lognormal field, polar quadrature) "
               "and the shortcut the plan would take, given the COF value mu0 of the full run's field where the "
               "disc starts. delta is the largest relative deviation of that field from mu0 over the belt region the disc covered.\n\n"
               "| %s | (E/l)^2 | plan (shortcuts on) | delta | dPV_x | dPV_F | d stick fraction |\n"
               "|---|---|---|---|---|---|---|", c->spec.sweep_param);
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        if (sf_sweep_set(&s, c->spec.sweep_param, c->spec.sweep.v[k], err, sizeof err)) {
            sf_note(r, "**Bad sweep value:** %s", err);
            return SF_EINVAL;
        }
        double dq[NQ] = { NAN, NAN, NAN }, delta = NAN, e2 = NAN;
        int taken = 0;
        int rc = boundary_point(&s, r, dq, &delta, &taken, &e2);
        if (rc)
            return SF_EFAIL;
        n_taken += taken;
        n_full += !taken;
        sf_note(r, "| %g | %.3g | %s | %.3g | %.3g | %.3g | %.3g |", c->spec.sweep.v[k], e2,
                taken ? (s.mu_std == 0 ? "uniform (closed forms)" : "one variable") : "field", delta, dq[0], dq[1],
                dq[2]);
        x[k] = c->spec.sweep.v[k];
        dmax[k] = sf_max(sf_max(dq[0], dq[1]), sf_max(dq[2], 1e-17));
        dl[k] = 2 * delta + floor_;
        for (int q = 0; q < NQ; q++) {
            char t[160];
            snprintf(t, sizeof t, "%s = %g: |d%s| within 2 delta + 100 rtol", c->spec.sweep_param, x[k], qname[q]);
            sf_check_le(r, t, dq[q], 2 * delta + floor_);
            if (taken) {
                snprintf(t, sizeof t, "%s = %g (shortcut taken): |d%s| within the tolerance", c->spec.sweep_param, x[k],
                         qname[q]);
                sf_check_le(r, t, dq[q], c->spec.tolerance);
            }
        }
    }
    char found[96];
    snprintf(found, sizeof found, "%zu scenes with the shortcut, %zu without", n_taken, n_full);
    sf_check_true(r, "the grid straddles the plan's decision (at least one scene each side)", n_taken && n_full,
                  found);
    int logx = 1;
    for (size_t k = 0; k < K; k++)
        logx &= x[k] > 0;
    sf_plot *p = sf_result_plot(r, "shortcut_boundary", "Shortcut vs full computation (coupled runs)",
                                !strcmp(c->spec.sweep_param, "l_over_R") ? "l/R [-]" : "mu_std [-]",
                                "relative QoI difference [-]");
    sf_plot_log(p, logx, 1);
    sf_plot_series(p, "largest |dQ|/Q of PV_x, PV_F, stick fraction", SF_STYLE_LINESPOINTS, K, x, dmax);
    sf_plot_series(p, "bound 2 delta + 100 rtol", SF_STYLE_LINESPOINTS, K, x, dl);
    sf_plot_hline(p, "tolerance where the shortcut is taken", c->spec.tolerance);
    free(x);
    free(dmax);
    free(dl);
    return SF_SUCCESS;
}

/* Summary-only vs full history: the history is an observer. */
typedef struct { size_t n; } row_count;
static void count_row(void *ctx, const sf_osc_row *row)
{
    (void)row;
    ((row_count *)ctx)->n++;
}

static int chk_history_skip(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cof *cof = check_case_cof(c, s, r);
    int rc;
    if (!cof)
        return SF_EINVAL;
    sf_osc_result full, sum;
    row_count rows = { 0 };
    if ((rc = check_osc_run(s, NULL, cof, 1e-3, &full, count_row, &rows, r))) {
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    if ((rc = check_osc_run(s, NULL, cof, 0, &sum, NULL, NULL, r))) {
        sf_osc_result_free(&full);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    sf_note(r, "The full-history run streamed %zu rows and kept %zu samples of x (every 1e-3 s, %.2f MB); the "
               "summary-only run kept none. Differences below are exact (bits): the history is an observer, so "
               "any difference is a defect.", rows.n, full.nsamples, 8e-6 * (double)full.nsamples);
    double a[8] = { full.pv_x, full.pv_F, full.stick_fraction, full.period, full.x_min, full.x_max,
                    full.energy_residual, (double)full.steps },
           b[8] = { sum.pv_x, sum.pv_F, sum.stick_fraction, sum.period, sum.x_min, sum.x_max, sum.energy_residual,
                    (double)sum.steps };
    const char *nm[8] = { "PV_x [m]", "PV_F [N]", "stick fraction [-]", "period [s]", "x_min [m]", "x_max [m]",
                          "energy residual [J]", "accepted steps" };
    for (int i = 0; i < 8; i++) {
        char t[160];
        if (isfinite(a[i]) && isfinite(b[i])) {
            snprintf(t, sizeof t, "%s: summary-only minus full history", nm[i]);
            sf_check_abs(r, t, b[i], a[i], 0);
            continue;
        }
        /* a QoI the window does not define (the period with fewer than two
         * complete cycles on a slow field): the claim is that both runs say
         * so, with the same bits; a NaN is not data to difference */
        snprintf(t, sizeof t, "%s: undefined in both runs, identical bits", nm[i]);
        sf_check_true(r, t, isnan(a[i]) && isnan(b[i]) && !memcmp(&a[i], &b[i], sizeof a[i]),
                      isnan(a[i]) && isnan(b[i]) ? "NaN in both (not defined in the window)"
                                                 : "defined in one run only");
    }
    size_t same = full.ntrans == sum.ntrans;
    for (size_t i = 0; same && i < full.ntrans; i++)
        same = full.trans_t[i] == sum.trans_t[i];
    char found[96];
    snprintf(found, sizeof found, "%zu and %zu transitions", full.ntrans, sum.ntrans);
    sf_check_true(r, "every transition time identical", (int)same, found);
    sf_check_true(r, "the full run recorded a history", rows.n > 0 && full.nsamples > 0, "rows and samples");
    sf_plot *pl = sf_result_plot(r, "history_skip", "Stick-slip transitions: full-history run and summary-only run",
                                 "time t [s]", "x at a transition [m]");
    sf_plot_series(pl, "full history", SF_STYLE_LINES, full.ntrans, full.trans_t, full.trans_x);
    sf_plot_series(pl, "summary only", SF_STYLE_POINTS, sum.ntrans, sum.trans_t, sum.trans_x);
    sf_osc_result_free(&full);
    sf_osc_result_free(&sum);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* A plan reused over realisations vs a fresh plan per realisation. */
static int chk_reuse(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    size_t n = s->samples;
    char err[256] = "";
    sf_cof_plan *kept;
    int rc = sf_cof_plan_alloc(s, &kept, err, sizeof err);
    if (rc) {
        sf_note(r, "**Plan failed:** %s", err);
        return rc;
    }
    const sf_cof_plan_info *in = sf_cof_plan_get_info(kept);
    if (in->kind != SF_COF_FIELD) {
        sf_cof_plan_free(kept);
        sf_note(r, "The scene must plan a field.");
        return SF_EINVAL;
    }
    size_t differ = 0, points = 0;
    /* for the plot: realisation 0 along the strip's centre line, both ways */
    double *pxb = check_alloc(3 * in->nx * sizeof *pxb), *pa = pxb + in->nx, *pb = pxb + 2 * in->nx;
    for (size_t i = 0; i < n && !rc; i++) {
        gsl_rng *g1 = gsl_rng_alloc(gsl_rng_mt19937), *g2 = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(g1, sf_mc_seed(s->seed, i));
        gsl_rng_set(g2, sf_mc_seed(s->seed, i));
        sf_cof_plan *fresh = NULL;
        sf_cof *a = NULL, *b = NULL;
        rc = sf_cof_plan_draw(kept, g1, &a);
        if (!rc)
            rc = sf_cof_plan_alloc(s, &fresh, err, sizeof err);
        if (!rc)
            rc = sf_cof_plan_draw(fresh, g2, &b);
        for (size_t j = 0; !rc && j < in->ny; j++)
            for (size_t k = 0; k < in->nx; k++) {
                double xb = in->x0 + (double)k * in->dx, yb = in->y0 + (double)j * in->dy;
                double va = sf_cof_eval(a, xb, yb), vb = sf_cof_eval(b, xb, yb);
                differ += va != vb;
                points++;
                if (i == 0 && j == in->ny / 2) {
                    pxb[k] = xb;
                    pa[k] = va;
                    pb[k] = vb;
                }
            }
        sf_cof_free(a);
        sf_cof_free(b);
        sf_cof_plan_free(fresh);
        gsl_rng_free(g1);
        gsl_rng_free(g2);
    }
    size_t nx = in->nx;
    sf_cof_plan_free(kept);
    if (rc) {
        free(pxb);
        return rc;
    }
    sf_plot *pl = sf_result_plot(r, "plan_reuse", "Realisation 0 on the strip's centre line: reused and fresh plan",
                                 "belt coordinate x_b [m]", "COF [dimensionless]");
    sf_plot_series(pl, "reused plan", SF_STYLE_LINES, nx, pxb, pa);
    sf_plot_series(pl, "fresh plan", SF_STYLE_POINTS, nx, pxb, pb);
    free(pxb);
    sf_note(r, "%zu realisations of a %zu x %zu strip field (one FFTW plan, FFTW_ESTIMATE) drawn by one plan in "
               "turn and each by a fresh plan, with realisation i's own stream (sf_mc_seed): the plan is reused "
               "across realisations only if that changes nothing.", n, in->nx, in->ny);
    sf_check_abs(r, "grid values that differ (reused vs fresh plan)", (double)differ, 0, 0);
    sf_check_true(r, "values compared", points > 0, "strip grid points");
    return SF_SUCCESS;
}

/* Solution verification of the accuracy-driven plan (numplan.h; docs/design.md sec. 6):
 * at each l/R of the sweep, `samples` realisations run at the plan's own
 * settings for the scene's qoi_tol (cells and rtol unset: the plan
 * chooses) and again at 4x its rings and rtol / 100 on the same field
 * (the reference).  The achieved error of a realisation is the largest
 * relative difference of PV_x, PV_F and stick fraction; the check: its RMS
 * over the realisations at or below qoi_tol at every l/R (and the
 * prediction the plan printed is noted beside it; each field's error is
 * listed after the table).  Where the plan needs no
 * quadrature (the strip is one random variable at large l/R) the reference
 * differs in rtol only.  The reference is the same code at a finer
 * setting: this verifies the plan's error control, not the model. */
static int chk_qoi_tol(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, n = s0->samples;
    if (!K || strcmp(c->spec.sweep_param, "l_over_R") || s0->cells || s0->rtol > 0 || !n) {
        sf_note(r, "The scene must sweep l_over_R and leave cells and rtol to the plan (unset).");
        return SF_EINVAL;
    }
    double *x = check_alloc(K * sizeof *x), *ach = check_alloc(K * sizeof *ach);
    double *worst = check_alloc(K * sizeof *worst), *pred = check_alloc(K * sizeof *pred);
    double *es = check_alloc(K * n * sizeof *es);   /* each l/R's per-realisation errors */
    sf_note(r, "Each realisation at the plan's settings for qoi_tol = %g against 4x its rings and rtol / 100 on the "
               "same field; %zu realisations per l/R (streams sf_mc_seed(seed, i)); error: the largest relative "
               "difference of PV_x, PV_F and stick fraction.\n\n| l/R | cells (plan) | rtol (plan) | predicted | "
               "achieved (RMS) | worst realisation | reference cells, rtol |\n|---|---|---|---|---|---|---|",
               s0->qoi_tol, n);
    int rc = SF_SUCCESS;
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        if (sf_sweep_set(&s, "l_over_R", c->spec.sweep.v[k], err, sizeof err)) {
            sf_note(r, "**Bad sweep value:** %s", err);
            return SF_EINVAL;
        }
        sf_cof_plan *cp;
        if ((rc = sf_cof_plan_alloc(&s, &cp, err, sizeof err))) {
            sf_note(r, "**Cannot plan the COF at l/R = %g:** %s", c->spec.sweep.v[k], err);
            break;
        }
        double e2 = 0, ew = 0;
        sf_numplan np = { 0 };
        sf_scene ref = s;
        /* a field with no complete cycle in T at either setting has no QoI
         * to compare (a long stick or slip phase: about 2% of the fields at
         * l/R = 0.5, T = 30 s): the next stream replaces it, up to 4n draws.
         * So does a field on which the two settings count different events
         * (check_qoi_shape: an oscillation or a stick at the window's edge
         * at one setting only, e.g. seed 672499010 at l/R = 0.5; a maximum
         * of x grazing vx = 0 in a long slip): the per-realisation QoI
         * jumps there whatever the accuracy; such fields are counted and
         * reported with the size of each jump. */
        size_t used = 0, none = 0, edge = 0;
        char jumps[128] = "";   /* the first few jumps' gaps */
        for (size_t i = 0; used < n && i < 4 * n && !rc; i++) {
            sf_cof *cof = NULL;
            rc = check_draw(cp, s.seed, i, &cof);
            sf_osc *o = NULL;
            if (!rc && !(rc = sf_osc_alloc(&s, cof, &o, err, sizeof err))) {
                np = *sf_osc_get_plan(o);
                sf_osc_free(o);
            }
            ref.cells = np.quadrature ? 4 * np.cells : 0;
            ref.rtol = np.rtol / 100;
            double e = 0;
            int differ = 0;
            if (!rc && !(rc = check_qoi_gap(&s, cof, &ref, cof, &e, &differ, r))) {
                if (isnan(e))
                    none++;
                else if (differ) {   /* by the runs' event structures (common.h): an infinite gap otherwise fails */
                    if (edge++ < 8 && strlen(jumps) < sizeof jumps - 16)
                        snprintf(jumps + strlen(jumps), sizeof jumps - strlen(jumps), " %.3g", e);
                } else {
                    e2 += e * e / (double)n;
                    ew = sf_max(ew, e);
                    es[k * n + used++] = e;
                }
            }
            sf_cof_free(cof);
        }
        sf_cof_plan_free(cp);
        if (rc)
            break;
        check_replaced_notes(r, "l/R", c->spec.sweep.v[k], none, edge, jumps);
        char t[160];
        check_fields_row(r, "l/R", c->spec.sweep.v[k], used, n);
        x[k] = c->spec.sweep.v[k];
        ach[k] = fmax(sqrt(e2), 1e-17);
        worst[k] = fmax(ew, 1e-17);
        pred[k] = np.err_total;
        char cells[32];
        snprintf(cells, sizeof cells, np.quadrature ? "%zu" : "none (closed form)", np.cells);
        sf_note(r, "| %g | %s | %.3g | %.2g | %.2g | %.2g | %zu, %.3g |", x[k], cells, np.rtol, pred[k], ach[k],
                worst[k], ref.cells, ref.rtol);
        /* what --explain promises, the same at every seed (the plan does not draw) */
        snprintf(t, sizeof t, "l/R = %g: the plan's predicted error <= qoi_tol", x[k]);
        sf_check_le(r, t, pred[k], s0->qoi_tol);
        snprintf(t, sizeof t, "l/R = %g: RMS QoI error at the plan's settings (requested qoi_tol)", x[k]);
        sf_check_le(r, t, ach[k], s0->qoi_tol);
    }
    if (!rc)
        check_list_errors(r, "l/R", K, x, n, es);
    if (!rc) {
        sf_plot *p = sf_result_plot(r, "qoi_tol", "Accuracy plan: achieved QoI error vs l/R", "l/R [-]",
                                    "relative QoI error [-]");
        sf_plot_log(p, 1, 1);
        sf_plot_series(p, "achieved (RMS over realisations)", SF_STYLE_LINESPOINTS, K, x, ach);
        sf_plot_series(p, "worst realisation", SF_STYLE_POINTS, K, x, worst);
        sf_plot_series(p, "predicted by the plan", SF_STYLE_LINESPOINTS, K, x, pred);
        sf_plot_hline(p, "requested qoi_tol", s0->qoi_tol);
    }
    free(x);
    free(ach);
    free(worst);
    free(pred);
    free(es);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

const sf_check_def sf_checks_plan[] = {
    { "plan_shortcut_boundary", chk_shortcut_boundary, "a plan shortcut vs the full computation at its boundary" },
    { "plan_history_skip", chk_history_skip, "summary-only run vs full history: identical bits" },
    { "plan_reuse", chk_reuse, "plan reused across realisations vs a fresh plan: identical bits" },
    { "plan_qoi_tol", chk_qoi_tol, "the accuracy plan's settings meet qoi_tol against 4x rings, rtol / 100" },
    { NULL, NULL, NULL }
};
