/* The accuracy plan's promise on a space-filling design (solution
 * verification of numplan.c across the parameter box, not at one point).
 *
 * plan_design: N points of a Latin hypercube (one random permutation of
 * the N strata per dimension, a uniform jitter inside each stratum; GSL's
 * mt19937 seeded from the case seed) over
 *   l/R      (sweep: lo, hi; log)        CV = mu_std / mu_mean  0.05 - 1
 *   v_b      0.1 - 0.8 m/s               mu_mean                0.2 - 1
 *   T        20 - 100 s                  qoi_tol (sweep2: lo, hi; log)
 * one realisation per point (stream sf_mc_seed(seed, i)).  At each point:
 * the plan's own settings (level 0), then 2x its rings with rtol / 10
 * (level 1) and 3x its rings with rtol / 100 (level 2, the reference), on
 * the same field.  Per (point, QoI): achieved = |Q0 - Q2| / |Q2|, the
 * reference's own error estimate |Q1 - Q2| / |Q2|, the plan's predicted
 * error, and the run's a-posteriori u_num (unum.h) / |Q0|.  A pair whose
 * reference is not converged to the tolerance under test (|Q1 - Q2| >
 * qoi_tol: a realisation near a grazing stick, where the levels need not
 * converge monotonically) cannot decide the promise either way: it is
 * listed and left out of the gates, and must be at most a quarter of the
 * pairs (the decision does not look at level 0, the run under test).
 *
 * A per-realisation QoI is a mean over the complete cycles in [t_skip, T]:
 * where the levels disagree on the number of cycles (a cycle starting or
 * ending at the window's edge moves across it) the QoI jumps by a cycle's
 * share whatever the accuracy (and a run with a single maximum of x has
 * a cycle but no peak-to-valley: NaN); such a point is reported and kept
 * out of the per-realisation gate as undecidable (its promise is on the
 * statistic over realisations: the jump's probability, not its size,
 * shrinks with the error).
 *
 * plan_errmodel (below): the plan's predicted error against the stored
 * tables of this design at held-out seeds, without a solve. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "cof.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "sf_error.h"
#include "sweep.h"
#include "unum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

enum { NQ = 3, ND = 6, NLEV = 3 };
static const char *const qname[NQ] = { "PV_x", "PV_F", "stick fraction" };

/* The promise, as rates over design points (a point's error: the largest
 * relative error of its decided QoIs, the quantity the plan's models are
 * calibrated on, numplan.c): each is H0 of an exact one-sided binomial
 * test that rejects when the points over the line are too many. */
#define MISS_RATE 0.05     /* achieved > qoi_tol */
#define WILD_RATE 0.01     /* achieved > `tolerance` x qoi_tol */
#define UNDER_RATE 0.05    /* achieved > the plan's predicted error */
#define UNDECIDED_RATE 0.25   /* points that cannot decide (no cycle, a cycle at the edge, reference not converged) */
#define NTEST 4            /* the case's alpha split over the four tests (Bonferroni) */
#define MDE_POWER 0.99

/* P(X >= k), X ~ Bin(n, p) */
static double binom_upper(size_t k, double p, size_t n)
{
    return k == 0 ? 1 : k > n ? 0 : gsl_cdf_binomial_Q((unsigned)(k - 1), p, (unsigned)n);
}

/* The smallest count k whose P(X >= k | n, p0) is <= alpha: the test
 * rejects H0 "rate <= p0" at k or more (n + 1: it cannot reject at this n). */
static size_t binom_critical(size_t n, double p0, double alpha)
{
    size_t k = 0;
    while (k <= n && binom_upper(k, p0, n) > alpha)
        k++;
    return k;
}

/* The smallest rate the test detects with power MDE_POWER (bisection; NaN
 * when no rate can be rejected at this n) */
static double binom_mde(size_t n, double p0, size_t kcrit)
{
    if (kcrit > n)
        return NAN;
    double lo = p0, hi = 1;
    for (int it = 0; it < 60; it++) {
        double mid = 0.5 * (lo + hi);
        if (binom_upper(kcrit, mid, n) >= MDE_POWER)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/* One rate's test: the row (a p-value at alpha) and a line of findings
 * with the observed fraction, its Clopper-Pearson 95% interval, the
 * critical count and the minimum detectable rate. */
static void rate_test(sf_result *r, const char *what, size_t k, size_t n, double p0, double alpha)
{
    double p = binom_upper(k, p0, n);
    size_t kc = binom_critical(n, p0, alpha);
    double lo = k ? gsl_cdf_beta_Pinv(0.025, (double)k, (double)(n - k + 1)) : 0;
    double hi = k < n ? gsl_cdf_beta_Pinv(0.975, (double)(k + 1), (double)(n - k)) : 1;
    double mde = binom_mde(n, p0, kc);
    char t[200];
    snprintf(t, sizeof t, "exact binomial test of H0 'rate of %s <= %g': P(X >= %zu of %zu)", what, p0, k, n);
    sf_check_pvalue(r, t, p, alpha, n);
    if (isfinite(mde))
        sf_note(r, "- %s: %zu of %zu (%.3f, Clopper-Pearson 95%% [%.3f, %.3f]); H0 rate <= %g rejected at %zu or "
                   "more (alpha %.3g); minimum detectable rate at power %.2f: %.2f.",
                what, k, n, n ? (double)k / (double)n : 0, lo, hi, p0, kc, alpha, MDE_POWER, mde);
    else
        sf_note(r, "- %s: %zu of %zu (Clopper-Pearson 95%% [%.3f, %.3f]); at n = %zu no count rejects H0 rate "
                   "<= %g at alpha %.3g (power 0).", what, k, n, lo, hi, n, p0, alpha);
}

/* The prediction's sharpness (reported, not gated: outside the box its
 * fit covers the prediction is the budget, orders of magnitude above the
 * error at large l/R): the median of achieved / predicted over the
 * decided points with its distribution-free 95% interval (order
 * statistics, binomial(n, 1/2)). */
static void report_sharpness(sf_result *r, double *ratio, size_t n)
{
    if (n == 0)
        return;
    gsl_sort(ratio, 1, n);
    size_t j = 0;   /* the interval [x_(j), x_(n-1-j)] covers the median with >= 95% */
    while (j + 1 < n / 2 && gsl_cdf_binomial_P((unsigned)(j + 1), 0.5, (unsigned)n) <= 0.025)
        j++;
    double med = gsl_stats_median_from_sorted_data(ratio, 1, n);
    const char *fit = "the prediction's fit: 0.18 inside its box, numplan.c; the budget err_total outside it";
    if (gsl_cdf_binomial_P((unsigned)j, 0.5, (unsigned)n) <= 0.025)
        sf_note(r, "Sharpness (reported): median achieved / predicted over the %zu decided points %.3g, 95%% interval "
                   "[%.3g, %.3g] (%s).", n, med, ratio[j], ratio[n - 1 - j], fit);
    else
        sf_note(r, "Sharpness (reported): median achieved / predicted over the %zu decided points %.3g (%s).", n, med,
                fit);
}

/* N Latin-hypercube points in [0, 1)^ND, row-major (point i: u[ND i ..]) */
static void lhs(gsl_rng *g, size_t n, double *u)
{
    size_t *perm = check_alloc(n * sizeof *perm);
    for (int d = 0; d < ND; d++) {
        for (size_t i = 0; i < n; i++)
            perm[i] = i;
        gsl_ran_shuffle(g, perm, n, sizeof *perm);
        for (size_t i = 0; i < n; i++)
            u[ND * i + (size_t)d] = ((double)perm[i] + gsl_rng_uniform(g)) / (double)n;
    }
    free(perm);
}

static double lin(double u, double a, double b) { return a + u * (b - a); }
static double logmap(double u, double a, double b) { return exp(lin(u, log(a), log(b))); }

typedef struct {
    double q[NLEV][NQ];
    size_t cycles[NLEV];
    double u[NQ];          /* u_num / |Q0| */
    sf_numplan np;
    double cpu[NLEV], cpu_u;
    size_t ref_cells[2];   /* cell averages: the point references' rings (levels 1, 2); 0 otherwise */
} point_run;

static void qois(const sf_osc_result *res, double *q)
{
    q[0] = res->pv_x;
    q[1] = res->pv_F;
    q[2] = res->stick_fraction;
}

/* the three levels and the companion on one field */
/* level 0: the plan's run of scene s on cof (its plan in pr->np) and its
 * u_num companion */
static int run_level0(const sf_scene *s, const sf_cof *cof, point_run *pr, sf_result *r)
{
    char err[256] = "";
    sf_osc *o = NULL;
    sf_osc_result res;
    double t0 = check_cpu_seconds();
    int rc = sf_osc_alloc(s, cof, &o, err, sizeof err);
    if (!rc)
        rc = sf_osc_run(o, NULL, NULL, 0, &res, err, sizeof err);
    if (rc) {
        sf_note(r, "**The plan's run failed:** %s (%s).", err, sf_strerror(rc));
        sf_osc_free(o);
        return rc;
    }
    pr->np = *sf_osc_get_plan(o);
    sf_osc_free(o);
    pr->cpu[0] = check_cpu_seconds() - t0;
    qois(&res, pr->q[0]);
    pr->cycles[0] = res.ncycles;
    sf_unum u;
    t0 = check_cpu_seconds();
    rc = sf_unum_estimate(s, cof, &pr->np, &res, &u, err, sizeof err);
    pr->cpu_u = check_cpu_seconds() - t0;
    sf_osc_result_free(&res);
    if (rc) {
        sf_note(r, "**The companion solve failed:** %s (%s).", err, sf_strerror(rc));
        return rc;
    }
    for (int k = 0; k < NQ; k++)
        pr->u[k] = u.u[k] / fabs(pr->q[0][k]);
    return SF_SUCCESS;
}

static int run_point(const sf_scene *s, const sf_cof *cof, point_run *pr, sf_result *r)
{
    int rc = run_level0(s, cof, pr, r);
    sf_osc_result res;
    double t0;
    for (int l = 1; l < NLEV && !rc; l++) {
        sf_scene f = *s;
        f.cells = pr->np.quadrature ? (size_t)(l + 1) * pr->np.cells : 0;
        f.rtol = pr->np.rtol / (l == 1 ? 10 : 100);
        t0 = check_cpu_seconds();
        if (!(rc = check_osc_run(&f, NULL, cof, 0, &res, NULL, NULL, r))) {
            qois(&res, pr->q[l]);
            pr->cycles[l] = res.ncycles;
            sf_osc_result_free(&res);
        }
        pr->cpu[l] = check_cpu_seconds() - t0;
    }
    return rc;
}

/* A point where the plan takes the cell averages (l/R below about
 * 0.05): refining its cells would average the field over smaller boxes, a
 * different COF, so the levels are not the same run refined.  Level 0 is
 * the plan's run fed with the exact box averages of a fine point field
 * (check_cellavg_filter; its spacing l/8, the tiles); levels 1 and 2 are
 * the point model on that same field at REF_RINGS_C / (l/R) x 2/3 and
 * REF_RINGS_C / (l/R) rings (cells of 0.75 l and 0.5 l: cellavg-plan-qoi-
 * tol-small's references, 0.45-0.56 l, were converged to 2e-4) and
 * rtol / 10, rtol / 100.  The field is drawn afresh for each run (a tiled
 * window slides with the disc); the same stream gives the same field. */
#define REF_RINGS_C 2.0
static int run_point_cellavg(const sf_scene *s, const sf_numplan *pl, unsigned long seed, size_t i, point_run *pr,
                             double *t_draw, sf_result *r)
{
    char err[256] = "";
    sf_scene sc = *s, sp[NLEV];
    sc.cof_model = SF_COFMODEL_CELL;
    sc.cells = pl->cells;
    sc.rtol = pl->rtol;
    size_t n2 = (size_t)ceil(REF_RINGS_C / s->l * s->R);
    for (int l = 1; l < NLEV; l++) {
        sp[l] = *s;
        sp[l].cof_model = SF_COFMODEL_POINT;
        sp[l].cof_generator = SF_COFGEN_TILES;
        sp[l].cells = l == 1 ? (2 * n2 + 2) / 3 : n2;
        sp[l].rtol = pl->rtol / (l == 1 ? 10 : 100);
    }
    sf_cof_plan *cp;
    int rc = sf_cof_plan_alloc(&sp[NLEV - 1], &cp, err, sizeof err);
    if (rc) {
        sf_note(r, "**Cannot plan the fine field:** %s", err);
        return rc;
    }
    sf_cof *fine = NULL, *coarse = NULL;
    double t0 = check_cpu_seconds();
    rc = check_draw(cp, seed, i, &fine);
    if (!rc && !(coarse = check_cellavg_filter(fine, &sc, 2 * sc.R / (double)sc.cells, 1, r)))
        rc = SF_EFAIL;
    sf_cof_free(fine);
    *t_draw = check_cpu_seconds() - t0;
    if (!rc)
        rc = run_level0(&sc, coarse, pr, r);
    pr->np = *pl;   /* the promise is the auto plan's (the same cells and rtol) */
    sf_cof_free(coarse);
    sf_osc_result res;
    for (int l = 1; l < NLEV && !rc; l++) {
        t0 = check_cpu_seconds();
        if (!(rc = check_draw(cp, seed, i, &fine)) && !(rc = check_osc_run(&sp[l], NULL, fine, 0, &res, NULL, NULL, r))) {
            qois(&res, pr->q[l]);
            pr->cycles[l] = res.ncycles;
            sf_osc_result_free(&res);
        }
        sf_cof_free(fine);
        pr->cpu[l] = check_cpu_seconds() - t0;
    }
    pr->ref_cells[0] = sp[1].cells;
    pr->ref_cells[1] = sp[2].cells;
    sf_cof_plan_free(cp);
    return rc;
}

/* The design's box from the case's scene (lo, hi per dimension) and its
 * Latin hypercube (n points, design seed; the caller frees *u);
 * SF_EINVAL with the scene's requirements noted. */
static int design_box(const sf_case *c, sf_result *r, double *lo, double *hi)
{
    const sf_scene *s0 = &c->scene;
    if (s0->samples < 2 || c->spec.sweep.n != 2 || c->spec.sweep2.n != 2 || strcmp(c->spec.sweep_param, "l_over_R") ||
        s0->cells || s0->rtol > 0 || s0->cof != SF_COF_FIELD || !(c->spec.tolerance >= 1) || !(s0->T >= 20)) {
        sf_note(r, "The scene must set cof = field, samples (design points, >= 2), sweep_param = l_over_R, sweep = "
                   "the l/R range (lo, hi), sweep2 = the qoi_tol range (lo, hi), tolerance = the worst achieved / "
                   "qoi_tol allowed (>= 1), T = the longest run (>= 20 s; the design draws T from 20 s to it), and "
                   "leave cells and rtol to the plan.");
        return SF_EINVAL;
    }
    const double l[ND] = { c->spec.sweep.v[0], 0.05, 0.1, 0.2, 20, c->spec.sweep2.v[0] };
    const double h[ND] = { c->spec.sweep.v[1], 1, 0.8, 1, s0->T, c->spec.sweep2.v[1] };
    memcpy(lo, l, sizeof l);
    memcpy(hi, h, sizeof h);
    return SF_SUCCESS;
}

static double *design_points(unsigned long seed, size_t n)
{
    double *u = check_alloc(n * ND * sizeof *u);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, sf_mc_seed(seed, (size_t)-1));   /* the design's own stream */
    lhs(g, n, u);
    gsl_rng_free(g);
    return u;
}

/* Point ui's scene: s0 at the point's l/R (*lr), CV, v_b, mean COF, T, qoi_tol */
static int design_scene(const sf_scene *s0, const double *lo, const double *hi, const double *ui, sf_scene *s,
                        double *lr, char *err, size_t errlen)
{
    double cv = lin(ui[1], lo[1], hi[1]), mu = lin(ui[3], lo[3], hi[3]);
    *s = *s0;
    s->mu_mean = mu;
    s->mu_std = cv * mu;
    s->v_b = lin(ui[2], lo[2], hi[2]);
    s->T = lin(ui[4], lo[4], hi[4]);
    s->qoi_tol = logmap(ui[5], lo[5], hi[5]);
    *lr = logmap(ui[0], lo[0], hi[0]);
    return sf_sweep_set(s, "l_over_R", *lr, err, errlen);
}

/* A point's scene and settings as the design's table prints them (the
 * stored measurements are matched against this text): l/R, CV, v_b, mu,
 * T, qoi_tol, rings, rtol, separated by sep */
static void point_text(char *buf, size_t len, const char *sep, double lr, const sf_scene *s, const sf_numplan *np)
{
    snprintf(buf, len, "%.3g%s%.2f%s%.2f%s%.2f%s%.0f%s%.2g%s%zu%s%.2g", lr, sep, s->mu_std / s->mu_mean, sep, s->v_b,
             sep, s->mu_mean, sep, s->T, sep, s->qoi_tol, sep, np->quadrature ? np->cells : 0, sep, np->rtol);
}

static int chk_design(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t n = s0->samples;
    double lo[ND], hi[ND];
    if (design_box(c, r, lo, hi))
        return SF_EINVAL;
    double *u = design_points(s0->seed, n);
    size_t np_ = n * NQ;
    double *ratio = check_alloc(n * sizeof *ratio), *pred = check_alloc(np_ * sizeof *pred), *ach = check_alloc(np_ * sizeof *ach), *un = check_alloc(np_ * sizeof *un);
    size_t npairs = 0, within = 0, cont_points = 0, disc_points = 0, covered = 0, undecided = 0, bounded = 0;
    size_t pts = 0, pt_miss = 0, pt_wild = 0, pt_under = 0;   /* decided points and their counts */
    size_t n_cell = 0;   /* points where the plan takes the cell averages */
    double worst = 0, worst_ref = 0, cpu_run = 0, cpu_u = 0;
    sf_note(r, "Latin hypercube of %zu points (seed %lu): l/R %g-%g (log), CV 0.05-1, v_b 0.1-0.8 m/s, mean COF "
               "0.2-1, T 20-%g s, qoi_tol %g-%g (log); one realisation per point. Levels on the same field: the "
               "plan's settings (0), 2x its rings and rtol / 10 (1), 3x its rings and rtol / 100 (2, the "
               "reference). Errors relative to level 2; 'ref' is |Q1 - Q2| / |Q2|, the reference's own error "
               "estimate; u_num is the run's a-posteriori estimate (companion at half the rings, 16x rtol). Where "
               "the plan takes the cell averages (its rings column then counts Cartesian cells per diameter), level 0 "
               "is its run fed with the exact box averages of a fine point field (spacing l/8, tiles) and levels 1 and "
               "2 are the point model on that field at %g / (l/R) x 2/3 and %g / (l/R) rings, rtol / 10 and / 100; "
               "its u_num holds the plan's a-priori cell-average error.\n\n"
               "| # | l/R | CV | v_b | mu | T | qoi_tol | rings | rtol | cycles (0/1/2) | predicted | achieved "
               "PV_x, PV_F, SF | ref PV_x, PV_F, SF | u_num PV_x, PV_F, SF | CPU s (draw; levels 0, 1, 2) |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
            n, s0->seed, lo[0], hi[0], hi[4], lo[5], hi[5], REF_RINGS_C, REF_RINGS_C);
    int rc = SF_SUCCESS;
    for (size_t i = 0; i < n && !rc; i++) {
        const double *ui = u + ND * i;
        double lr;
        sf_scene s;
        char err[256] = "";
        if ((rc = design_scene(s0, lo, hi, ui, &s, &lr, err, sizeof err))) {
            sf_note(r, "**Bad design point:** %s", err);
            break;
        }
        double tol = s.qoi_tol, t_draw = 0;
        sf_numplan pl;
        if ((rc = sf_numplan_make(&s, 1, &pl, err, sizeof err))) {
            sf_note(r, "**No plan at point %zu:** %s", i, err);
            break;
        }
        point_run pr;
        memset(&pr, 0, sizeof pr);
        if (pl.cell_average) {
            rc = run_point_cellavg(&s, &pl, s.seed, i, &pr, &t_draw, r);
            n_cell++;
        } else {
            sf_cof_plan *cp;
            if ((rc = sf_cof_plan_alloc(&s, &cp, err, sizeof err))) {
                sf_note(r, "**Cannot plan the COF at point %zu:** %s", i, err);
                break;
            }
            sf_cof *cof = NULL;
            t_draw = check_cpu_seconds();
            rc = check_draw(cp, s.seed, i, &cof);
            t_draw = check_cpu_seconds() - t_draw;
            sf_cof_plan_free(cp);
            if (!rc)
                rc = run_point(&s, cof, &pr, r);
            sf_cof_free(cof);
        }
        if (rc)
            break;
        cpu_run += pr.cpu[0];
        cpu_u += pr.cpu_u;
        /* a QoI the definition cannot measure at some level (a run with one
         * maximum of x has a cycle but no peak-to-valley) is the same jump */
        int nan_q = 0;
        for (int l = 0; l < NLEV; l++)
            for (int k = 0; k < NQ; k++)
                nan_q |= !isfinite(pr.q[l][k]);
        int disc = pr.cycles[0] != pr.cycles[2] || pr.cycles[1] != pr.cycles[2] || !pr.cycles[2] || nan_q;
        double a[NQ], e1[NQ];
        for (int k = 0; k < NQ; k++) {
            a[k] = fabs(pr.q[0][k] - pr.q[2][k]) / fabs(pr.q[2][k]);
            e1[k] = fabs(pr.q[1][k] - pr.q[2][k]) / fabs(pr.q[2][k]);
        }
        char pt[160];
        point_text(pt, sizeof pt, " | ", lr, &s, &pr.np);
        char refs[96] = "";
        if (pr.ref_cells[0])
            snprintf(refs, sizeof refs, " (cell averages; point references %zu, %zu rings)", pr.ref_cells[0],
                     pr.ref_cells[1]);
        sf_note(r, "| %zu | %s | %zu/%zu/%zu%s%s | %.2g | %.2g, %.2g, "
                   "%.2g | %.2g, %.2g, %.2g | %.2g, %.2g, %.2g | %.2f; %.2f, %.2f, %.2f |",
                i, pt, pr.cycles[0], pr.cycles[1],
                pr.cycles[2], disc ? (!pr.cycles[2] ? " (no cycle)" : nan_q ? " (no peak-to-valley)" : " (edge)") : "", refs, pr.np.err_pred, a[0], a[1], a[2], e1[0], e1[1], e1[2], pr.u[0],
                pr.u[1], pr.u[2], t_draw, pr.cpu[0], pr.cpu[1], pr.cpu[2]);
        if (disc) {
            disc_points++;
            continue;
        }
        cont_points++;
        double pa = -1;   /* the point's error: the largest over its decided QoIs */
        for (int k = 0; k < NQ; k++) {
            if (!(isfinite(a[k]) && isfinite(e1[k]) && isfinite(pr.u[k]))) {
                rc = SF_EFAIL;   /* NaN/Inf in the data fails the case */
                sf_note(r, "**Non-finite error at point %zu, %s.**", i, qname[k]);
                break;
            }
            worst_ref = sf_max(worst_ref, e1[k] / tol);
            if (e1[k] > tol) {   /* the reference not converged to qoi_tol: this pair cannot decide */
                undecided++;
                continue;
            }
            pred[npairs] = fmax(pr.np.err_pred, 1e-17);
            ach[npairs] = fmax(a[k], 1e-17);
            un[npairs] = fmax(pr.u[k], 1e-17);
            within += a[k] <= tol;
            bounded += a[k] <= pr.np.err_pred;
            covered += a[k] <= pr.u[k];
            worst = sf_max(worst, a[k] / tol);
            pa = sf_max(pa, a[k]);
            npairs++;
        }
        if (rc || !(pa >= 0))
            continue;   /* no decided QoI: an undecidable point */
        pts++;
        pt_miss += pa > tol;
        pt_wild += pa > c->spec.tolerance * tol;
        pt_under += pa > pr.np.err_pred;
        ratio[pts - 1] = pa / pr.np.err_pred;
    }
    free(u);
    if (!rc) {
        char t[200];
        double a_row = c->spec.alpha / NTEST;
        sf_note(r, "\n**The promise as rates over the %zu design points** (a point's error: the largest relative error of "
                   "its decided QoIs; each rate an exact one-sided binomial test at alpha %.3g = the case's %.3g / %d, "
                   "Bonferroni; the points are independent realisations, their design a Latin hypercube):\n",
                n, a_row, c->spec.alpha, NTEST);
        rate_test(r, "points whose error exceeds qoi_tol", pt_miss, pts, MISS_RATE, a_row);
        snprintf(t, sizeof t, "points whose error exceeds %g qoi_tol", c->spec.tolerance);
        rate_test(r, t, pt_wild, pts, WILD_RATE, a_row);
        rate_test(r, "points whose error exceeds the plan's predicted error", pt_under, pts, UNDER_RATE, a_row);
        rate_test(r, "undecidable points (no cycle, a cycle at the window's edge, or no QoI whose reference is "
                     "converged to qoi_tol)", n - pts, n, UNDECIDED_RATE, a_row);
        sf_note(r, "\nOver the %zu decided (point, QoI) pairs (%zu undecided: |Q1 - Q2| > qoi_tol; %zu points with "
                   "a cycle at the window's edge or none): %zu within qoi_tol (%.3f), %zu within the prediction, "
                   "worst achieved / qoi_tol %.3g (reported; the three QoIs of a realisation are not independent, so "
                   "the tests count points).",
                npairs, undecided, disc_points, within, npairs ? (double)within / (double)npairs : 0, bounded, worst);
        report_sharpness(r, ratio, pts);
        sf_note(r, "Reference convergence: worst |Q1 - Q2| / |Q2| / qoi_tol = %.2g. The a-posteriori u_num of a "
                   "run (unum.h) covers the achieved error in %zu of %zu pairs (%.0f%%); its companion cost %.0f%% of "
                   "the plan's runs (CPU %.2f s against %.2f s, field draws excluded).",
                worst_ref, covered, npairs, npairs ? 100.0 * (double)covered / (double)npairs : 0,
                cpu_run > 0 ? 100 * cpu_u / cpu_run : 0, cpu_u, cpu_run);
        if (n_cell)
            sf_note(r, "The plan took the cell averages at %zu of the %zu points (their references: the point model on "
                       "the fine field the averages are taken from).", n_cell, n);
        check_plot_vs_predicted(r, "design_scatter", "Accuracy plan on a space-filling design: predicted vs achieved",
                                "predicted relative QoI error (the plan's err_pred, a 95% bound) [-]",
                                "achieved relative QoI error [-]", "(point, QoI) pairs", "achieved = predicted", npairs,
                                pred, ach, 1e-6, 1e-1);
        check_plot_vs_predicted(r, "design_unum", "A-posteriori u_num (companion solve) vs achieved error",
                                "u_num / |Q| (coarser companion, Fs = 3) [-]", "achieved relative QoI error [-]",
                                "(point, QoI) pairs", "achieved = u_num", npairs, un, ach, 1e-6, 1e-1);
    }
    free(ratio);
    free(pred);
    free(ach);
    free(un);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

/* ---- Stored design data: the design's per-point tables at fixed seeds
 * (scripts/design-data.sh writes them beside a case, as NAME.tsv for
 * NAME.md), read without a solve.  Every stored point's scene is rebuilt
 * from its design seed and index (the Latin hypercube above) and planned
 * by the code under test.  Its settings must be the stored ones: the
 * stored errors describe those settings and no others, so a changed plan
 * makes the data stale, and the case fails.  A point decides as in
 * plan_design: every level counts the same cycles and at least one QoI's
 * reference is converged to qoi_tol; its error is the largest stored error
 * of those QoIs (two significant digits as printed). */
enum { ECOLS = 22, EC_SEED = 0, EC_DSEED = 1, EC_I = 2, EC_PT = 3, EC_UND = 12, EC_A = 13, EC_E = 16 };

typedef struct {
    double lr, cv, mu;           /* the point's scene (from its design seed, not the table's rounded print) */
    double ach;                  /* its error as stored */
    double err_total, err_pred;  /* the plan under test's budget and prediction */
    int fitted;                  /* err_pred is the fit's (inside its box, numplan.c) */
} stored_point;

typedef struct {
    char path[600], found[400], hdr[1200];
    size_t rows, stale, undecided, nonfinite, pts;
    stored_point *pt;                /* the decided points, pts of them */
    double *rings_st, *rings_now;    /* per row: the stored and the planned rings */
} stored_data;

static void stored_free(stored_data *d)
{
    free(d->pt);
    free(d->rings_st);
    free(d->rings_now);
}

/* Read case c's stored data into d (the caller frees it with stored_free,
 * whatever the return): SF_EIO (no file), SF_EPARSE (a malformed line) or
 * the planner's refusal, noted. */
static int stored_read(const sf_case *c, sf_result *r, const double *lo, const double *hi, stored_data *d)
{
    const sf_scene *s0 = &c->scene;
    size_t n = s0->samples;
    memset(d, 0, sizeof *d);
    if (check_data_path(c, d->path, sizeof d->path))
        return SF_EINVAL;
    FILE *f = fopen(d->path, "r");
    if (!f) {
        sf_note(r, "**Stored data missing:** cannot read %s: regenerate it with `sh scripts/design-data.sh FIRST LAST "
                   "> %s`.", d->path, d->path);
        return SF_EIO;
    }
    char *line = NULL, *fld[ECOLS];
    size_t cap = 0, lineno = 0, ncap = 0;
    while (getline(&line, &cap, f) > 0)
        ncap++;   /* at most this many points */
    rewind(f);
    d->pt = check_alloc(ncap * sizeof *d->pt);
    d->rings_st = check_alloc(ncap * sizeof *d->rings_st);
    d->rings_now = check_alloc(ncap * sizeof *d->rings_now);
    double *u = NULL;
    unsigned long dseed = 0;
    int rc = SF_SUCCESS;
    while (getline(&line, &cap, f) > 0) {
        lineno++;
        line[strcspn(line, "\r\n")] = 0;
        if (line[0] == '#') {
            size_t k = strlen(d->hdr);
            snprintf(d->hdr + k, sizeof d->hdr - k, "> %s\n", line + 1 + (line[1] == ' '));
            continue;
        }
        if (!line[0] || !strncmp(line, "seed\t", 5))
            continue;
        size_t nf = 1;
        for (const char *t = line; (t = strchr(t, '\t')); t++)
            nf++;
        int ok = nf == ECOLS;
        for (size_t k = 0; ok && k < ECOLS; k++) {
            fld[k] = k ? strchr(fld[k - 1], 0) + 1 : line;
            char *tab = strchr(fld[k], '\t');
            if (tab)
                *tab = 0;
        }
        double a[NQ], e[NQ], lr;
        char *end1 = NULL, *end2 = NULL;
        unsigned long ds = ok ? strtoul(fld[EC_DSEED], &end1, 10) : 0;
        size_t i = ok ? (size_t)strtoul(fld[EC_I], &end2, 10) : 0;
        ok = ok && !*end1 && !*end2 && i < n;
        for (int k = 0; k < NQ && ok; k++)
            ok = check_parse_num(fld[EC_A + k], &a[k]) && check_parse_num(fld[EC_E + k], &e[k]);
        if (!ok) {
            sf_note(r, "**%s:%zu: not a stored design point** (%d tab-separated columns wanted, a point index "
                       "below the design's %zu samples, numbers in the error columns).", d->path, lineno, ECOLS, n);
            rc = SF_EPARSE;
            break;
        }
        if (!u || ds != dseed) {
            free(u);
            u = design_points(dseed = ds, n);
        }
        sf_scene s;
        sf_plan pl;
        char err[256] = "";
        if ((rc = design_scene(s0, lo, hi, u + ND * i, &s, &lr, err, sizeof err)) ||
            (rc = sf_plan_make(&s, &pl, err, sizeof err))) {
            sf_note(r, "**%s:%zu: cannot plan the point:** %s", d->path, lineno, err);
            break;
        }
        d->rings_st[d->rows] = strtod(fld[EC_PT + 6], NULL);
        d->rings_now[d->rows] = pl.num.quadrature ? (double)pl.num.cells : 0;
        d->rows++;
        char want[200], got[200];
        point_text(want, sizeof want, "\t", lr, &s, &pl.num);
        snprintf(got, sizeof got, "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s", fld[EC_PT], fld[EC_PT + 1], fld[EC_PT + 2],
                 fld[EC_PT + 3], fld[EC_PT + 4], fld[EC_PT + 5], fld[EC_PT + 6], fld[EC_PT + 7]);
        if (strcmp(want, got)) {
            if (!d->stale++) {
                for (char *t = want; (t = strchr(t, '\t'));)
                    *t = ' ';
                for (char *t = got; (t = strchr(t, '\t'));)
                    *t = ' ';
                snprintf(d->found, sizeof d->found, "line %zu (seed %.12s, point %zu): stored l/R, CV, v_b, mu, T, "
                         "qoi_tol, rings, rtol '%.120s', planned now '%.120s'", lineno, fld[EC_SEED], i, got, want);
            }
            continue;
        }
        if (!strcmp(fld[EC_UND], "1")) {   /* undecidable as measured (a cycle at the edge, none, no PV_x) */
            d->undecided++;
            continue;
        }
        double pa = -1;
        for (int k = 0; k < NQ; k++) {
            if (!isfinite(a[k]) || !isfinite(e[k])) {
                d->nonfinite++;
                pa = NAN;
                break;
            }
            if (e[k] <= s.qoi_tol)   /* the reference converged to the tolerance under test */
                pa = sf_max(pa, a[k]);
        }
        if (!(pa >= 0)) {
            d->undecided += !isnan(pa);
            continue;
        }
        stored_point *p = &d->pt[d->pts++];
        p->lr = lr;
        p->cv = s.mu_std / s.mu_mean;
        p->mu = s.mu_mean;
        p->ach = pa;
        p->err_total = pl.num.err_total;
        p->err_pred = pl.num.err_pred;
        p->fitted = pl.num.pred_fitted;
    }
    free(line);
    free(u);
    fclose(f);
    return rc;
}

/* The rows every stored-data case shares (the data describe the plan under
 * test, finite, some decided: n of the named test), and the evidence of
 * stale data.  1: the data can be used. */
static int stored_gates(sf_result *r, const stored_data *d, const char *test)
{
    sf_note(r, "Stored data: %s, %zu design points (its header:)\n\n%s", d->path, d->rows, d->hdr);
    char t[700];
    if (d->stale)
        snprintf(t, sizeof t, "stored data stale: %zu of %zu points differ; regenerate with scripts/design-data.sh",
                 d->stale, d->rows);
    else
        snprintf(t, sizeof t, "all %zu stored points: the same design point and the same rings and rtol", d->rows);
    sf_check_true(r, "stored points describe the plan under test (each point's scene from its design seed, "
                     "the planner's rings and rtol as the measuring run printed them)", d->rows > 0 && !d->stale, t);
    sf_check_le(r, "decidable stored points with a non-finite error", (double)d->nonfinite, 0);
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "decided stored points (the %s's n)", test);
    sf_check_ge(r, q, (double)d->pts, 1);
    if (d->stale) {   /* the evidence: the settings planned now against the stored ones */
        sf_note(r, "\n**Stored data stale:** the plan under test does not make the settings the stored errors were "
                   "measured at (%zu of %zu points; the first, %s); regenerate them with `sh scripts/design-data.sh` "
                   "(the seeds in the header above).", d->stale, d->rows, d->found);
        sf_plot *pp = sf_result_plot(r, "errmodel_stale", "Stale stored data: the rings planned now against the stored",
                                     "rings the measuring run planned (stored) [-]", "rings the code under test plans [-]");
        sf_plot_series(pp, "stored design points", SF_STYLE_POINTS, d->rows, d->rings_st, d->rings_now);
        double dx[2] = { 0, SF_PLAN_MAX_RINGS };
        sf_plot_series(pp, "the same rings", SF_STYLE_LINES, 2, dx, dx);
    }
    return !d->stale && d->pts;
}

/* Run body on case c's stored data (its design box lo, hi; the data read
 * and gated by stored_read and stored_gates) when they can be used, and
 * free them: SF_SUCCESS when stale or without a decided point (a row
 * failed), SF_EINVAL (the scene), SF_EIO, SF_EPARSE, the planner's refusal
 * or body's return. */
typedef int stored_body(const sf_case *c, sf_result *r, const double *lo, const double *hi, const stored_data *d);

static int stored_run(const sf_case *c, sf_result *r, const char *test, stored_body *body)
{
    double lo[ND], hi[ND];
    stored_data d;
    memset(&d, 0, sizeof d);
    if (design_box(c, r, lo, hi))
        return SF_EINVAL;
    int rc = stored_read(c, r, lo, hi, &d);
    if (!rc && stored_gates(r, &d, test))
        rc = body(c, r, lo, hi, &d);
    stored_free(&d);
    return rc;
}

/* ---- plan_errmodel: the predicted error err_pred (numplan.c) against
 * stored, held-out measurements: the design's tables at seeds never used
 * to fit it.  The points whose stored error exceeds the recomputed
 * err_pred are counted: an exact one-sided binomial test of H0 'rate <=
 * 5%' at the case's alpha.  The stored errors carry two significant
 * digits; one within its print's rounding of the prediction counts as
 * above (against the model). */
#define ERR_LR_BINS 3

/* the largest value a 2-significant-digit print of x >= 0 may stand for */
static double print_hi(double x)
{
    return x > 0 ? x + 0.5 * pow(10, floor(log10(x)) - 1) : 0;
}

static int errmodel_body(const sf_case *c, sf_result *r, const double *lo, const double *hi, const stored_data *d)
{
    size_t pts = d->pts, over = 0, over_hi = 0, fitted = 0, bin_n[ERR_LR_BINS] = { 0 }, bin_over[ERR_LR_BINS] = { 0 };
    double *pred = check_alloc(pts * sizeof *pred), *ach = check_alloc(pts * sizeof *ach);
    double *ratio = check_alloc(pts * sizeof *ratio), *ratio_hi = check_alloc(pts * sizeof *ratio_hi);
    for (size_t j = 0; j < pts; j++) {
        const stored_point *q = &d->pt[j];
        double p = q->err_pred, ah = print_hi(q->ach);
        fitted += q->fitted;
        pred[j] = p;
        ach[j] = fmax(q->ach, 1e-17);
        ratio[j] = q->ach / p;
        ratio_hi[j] = ah / p;
        over += q->ach > p;
        over_hi += ah > p;
        double x = log(q->lr / lo[0]) / log(hi[0] / lo[0]) * ERR_LR_BINS;
        size_t b = x < 0 ? 0 : x >= ERR_LR_BINS ? ERR_LR_BINS - 1 : (size_t)x;
        bin_n[b]++;
        bin_over[b] += ah > p;
    }
    sf_note(r, "\n**The prediction against the stored errors** (%zu decidable points of %zu: %zu undecidable as "
               "measured; err_pred from the fit at %zu of them, the budget at the rest). A point's error is the "
               "largest stored error of its QoIs whose reference is converged to qoi_tol; %zu exceed the "
               "recomputed err_pred as printed, %zu when a print within its rounding counts as above (the "
               "gated count):\n", pts, d->rows, d->undecided, fitted, over, over_hi);
    rate_test(r, "decided points whose stored error exceeds the recomputed err_pred", over_hi, pts, UNDER_RATE,
              c->spec.alpha);
    size_t kc = binom_critical(pts, UNDER_RATE, c->spec.alpha);
    if (kc <= pts) {
        gsl_sort(ratio_hi, 1, pts);   /* the gate fails when kc points exceed: below the kc-th largest ratio */
        sf_note(r, "- Power on these data (deterministic): err_pred scaled by any factor below %.3g puts %zu or "
                   "more points above it, and the gate fails (a factor above it passes).",
                ratio_hi[pts - kc], kc);
    }
    sf_note(r, "\n| l/R (log thirds of %g-%g) | decided points | above err_pred | fraction |\n|---|---|---|---|",
            lo[0], hi[0]);
    for (int b = 0; b < ERR_LR_BINS; b++) {
        double e0 = lo[0] * pow(hi[0] / lo[0], (double)b / ERR_LR_BINS);
        double e1 = lo[0] * pow(hi[0] / lo[0], (double)(b + 1) / ERR_LR_BINS);
        sf_note(r, "| %.3g-%.3g | %zu | %zu | %.3f |%s", e0, e1, bin_n[b], bin_over[b],
                bin_n[b] ? (double)bin_over[b] / (double)bin_n[b] : 0, b + 1 == ERR_LR_BINS ? "\n" : "");
    }
    report_sharpness(r, ratio, pts);
    check_plot_vs_predicted(r, "errmodel_scatter", "Predicted vs stored achieved error (held-out seeds)",
                            "predicted relative QoI error err_pred (the plan's 95% bound) [-]",
                            "achieved relative QoI error of the point (stored) [-]", "decided design points",
                            "achieved = predicted", pts, pred, ach, 1e-5, 2e-2);
    free(pred);
    free(ach);
    free(ratio);
    free(ratio_hi);
    return SF_SUCCESS;
}

/* ---- plan_errfit: the provenance of err_pred's constants (numplan.c).
 * From the stored design data err_pred was fitted on, redo its fit: least
 * squares (GSL's gsl_multifit_linear) of y = ln(achieved / err_total) on
 * 1, ln(l/R), CV and mean COF over the decided points inside its box,
 * then the intercept lifted by the residuals' 95th percentile (GSL's
 * quantile: linear interpolation between order statistics), so that
 *   err_pred = err_total exp(b0 + q95) (l/R)^b1 exp(b2 CV + b3 mu)
 * and factor = exp(b0 + q95), lr_exp = -b1, cv_coef = b2, mu_coef = b3.
 * The code's constants (sf_numplan_pred_model_get) must be that fit to
 * their printed precision: written with 3 decimals, |code - refit| <=
 * 0.5e-3, plus FIT_ROUNDOFF for the fit's own floating point (an SVD of a
 * 4-column matrix with condition ~1e2: ~1e-13, bounded far above).  It
 * tells a constant that is not the fit of its data (a typo, an edit, a
 * refit on other data), not a wrong model: the constants' statistical
 * uncertainty (their standard errors, reported) is 100-600x larger. */
#define FIT_HALF_ULP 0.5e-3
#define FIT_ROUNDOFF 1e-9
#define FIT_QUANTILE 0.95
enum { NFIT = 4 };

static int errfit_body(const sf_case *c, sf_result *r, const double *lo, const double *hi, const stored_data *d)
{
    (void)c;
    (void)lo;
    (void)hi;
    size_t n = 0, zero = 0;
    for (size_t j = 0; j < d->pts; j++) {
        n += d->pt[j].fitted && d->pt[j].ach > 0;
        zero += d->pt[j].fitted && !(d->pt[j].ach > 0);
    }
    sf_check_ge(r, "decided stored points inside err_pred's box (the fit's n; 2x its parameters at least)", (double)n,
                2 * NFIT);
    sf_check_le(r, "decided points inside the box with a stored error of 0 (no logarithm)", (double)zero, 0);
    if (n < 2 * NFIT)
        return SF_SUCCESS;
    gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(n, NFIT);
    if (!w)
        return SF_ENOMEM;
    double *xd = check_alloc(n * NFIT * sizeof *xd), *yd = check_alloc(n * sizeof *yd), *rd = check_alloc(n * sizeof *rd);
    double bd[NFIT], cd[NFIT * NFIT], *ys = check_alloc(n * sizeof *ys), *rs = check_alloc(n * sizeof *rs), chisq;
    gsl_matrix_view Xv = gsl_matrix_view_array(xd, n, NFIT), cv_ = gsl_matrix_view_array(cd, NFIT, NFIT);
    gsl_vector_view yv = gsl_vector_view_array(yd, n), bv = gsl_vector_view_array(bd, NFIT), rv = gsl_vector_view_array(rd, n);
    gsl_matrix *X = &Xv.matrix, *cov = &cv_.matrix;
    gsl_vector *y = &yv.vector, *b = &bv.vector, *res = &rv.vector;
    for (size_t j = 0, k = 0; j < d->pts; j++) {
        const stored_point *q = &d->pt[j];
        if (!(q->fitted && q->ach > 0))
            continue;
        gsl_matrix_set(X, k, 0, 1);
        gsl_matrix_set(X, k, 1, log(q->lr));
        gsl_matrix_set(X, k, 2, q->cv);
        gsl_matrix_set(X, k, 3, q->mu);
        gsl_vector_set(y, k, ys[k] = log(q->ach / q->err_total));
        k++;
    }
    gsl_multifit_linear(X, y, b, cov, &chisq, w);
    gsl_multifit_linear_residuals(X, y, b, res);
    for (size_t k = 0; k < n; k++)
        rs[k] = gsl_vector_get(res, k);
    gsl_sort(rs, 1, n);
    double q95 = gsl_stats_quantile_from_sorted_data(rs, 1, n, FIT_QUANTILE);
    /* the quantile's distribution-free 95% interval [rs[jl], rs[jh]]
     * (0-based order statistics): the count X of residuals below the true
     * quantile is Bin(n, 0.95); P(X <= jl) <= 0.025 and P(X > jh) <= 0.025 */
    size_t jl = 0, jh = n - 1;
    while (jl + 1 < n && gsl_cdf_binomial_P((unsigned)(jl + 1), FIT_QUANTILE, (unsigned)n) <= 0.025)
        jl++;
    while (jh > jl + 1 && gsl_cdf_binomial_Q((unsigned)(jh - 1), FIT_QUANTILE, (unsigned)n) <= 0.025)
        jh--;
    double b0 = gsl_vector_get(b, 0);
    sf_numplan_pred_model m;
    sf_numplan_pred_model_get(&m);
    const char *name[NFIT] = { "factor (PF)", "l/R exponent (PL)", "CV coefficient (PC)", "mean COF coefficient (PM)" };
    double code[NFIT] = { m.factor, m.lr_exp, m.cv_coef, m.mu_coef };
    double fit[NFIT] = { exp(b0 + q95), -gsl_vector_get(b, 1), gsl_vector_get(b, 2), gsl_vector_get(b, 3) };
    double se[NFIT];
    for (int k = 0; k < NFIT; k++)
        se[k] = sqrt(gsl_matrix_get(cov, (size_t)k, (size_t)k));
    /* ln factor = b0 + q95: the intercept's se and the quantile's, read
     * off its interval as a normal one's (width / 3.92), in quadrature */
    double se_q = (rs[jh] - rs[jl]) / 3.92;
    double se_lnf = hypot(se[0], se_q);
    se[0] = fit[0] * se_lnf;
    size_t above = 0;
    for (size_t k = 0; k < n; k++)
        above += gsl_vector_get(res, k) > q95;
    sf_note(r, "\n**The refit** (%zu decided points inside the box; %zu of %zu decided points outside it left out): "
               "least squares of ln(achieved / err_total) on 1, ln(l/R), CV, mean COF: intercept b0 = %.4f, residual "
               "sd %.3f (sd of ln(achieved / err_total) itself %.3f); the residuals' %.0fth percentile %.4f "
               "(distribution-free 95%% interval [%.3f, %.3f]); ln factor = b0 + q95 = %.4f; %zu of %zu fitting "
               "points above the refit bound (%.1f%%).\n", n, d->pts - n - zero, d->pts, b0,
            sqrt(chisq / (double)(n - NFIT)), gsl_stats_sd(ys, 1, n), 100 * FIT_QUANTILE, q95, rs[jl], rs[jh],
            b0 + q95, above, n, 100.0 * (double)above / (double)n);
    sf_note(r, "| constant | refit from the data | numplan.c | code - refit | standard error of the fit (statistical) "
               "| se / allowed difference |\n|---|---|---|---|---|---|");
    for (int k = 0; k < NFIT; k++)
        sf_note(r, "| %s | %.5f | %.5g | %+.2e | %.3f | %.0f |%s", name[k], fit[k], code[k], code[k] - fit[k], se[k],
                se[k] / FIT_HALF_ULP, k + 1 == NFIT ? "\n" : "");
    sf_note(r, "The factor's standard error combines the intercept's (%.3f in ln) and the 95th percentile's (its "
               "interval's width / 3.92: %.3f in ln). The gate below is exact (the fit of fixed data): it holds the "
               "code's constants to the fit at their printed 3 decimals; their statistical uncertainty, tens to "
               "hundreds of times that, is what a different set of seeds would move them by.\n",
            sqrt(gsl_matrix_get(cov, 0, 0)), se_q);
    double *px = check_alloc(n * sizeof *px), *py = check_alloc(n * sizeof *py);
    for (size_t k = 0; k < n; k++) {   /* the refit bound at each fitting point, over err_total */
        py[k] = exp(ys[k]);
        px[k] = exp(ys[k] - gsl_vector_get(res, k) + q95);
    }
    sf_plot *pp = sf_result_plot(r, "errfit_scatter", "err_pred's fitting data against the refit bound",
                                 "refit bound / err_total at the point, exp(b0 + q95 + b1 ln(l/R) + b2 CV + b3 mu) [-]",
                                 "achieved error / err_total (stored) [-]");
    sf_plot_log(pp, 1, 1);
    sf_plot_series(pp, "decided design points inside the box", SF_STYLE_POINTS, n, px, py);
    double dx[2];
    gsl_stats_minmax(&dx[0], &dx[1], px, 1, n);
    sf_plot_series(pp, "achieved = the refit bound", SF_STYLE_LINES, 2, dx, dx);
    free(px);
    free(py);
    for (int k = 0; k < NFIT; k++) {
        char t[160];
        snprintf(t, sizeof t, "err_pred's %s in numplan.c against its refit from the stored design data", name[k]);
        sf_check_abs(r, t, code[k], fit[k], FIT_HALF_ULP + FIT_ROUNDOFF);
    }
    gsl_multifit_linear_free(w);
    free(xd);
    free(yd);
    free(rd);
    free(ys);
    free(rs);
    return SF_SUCCESS;
}

static int chk_errmodel(const sf_case *c, sf_result *r) { return stored_run(c, r, "calibration test", errmodel_body); }

static int chk_errfit(const sf_case *c, sf_result *r) { return stored_run(c, r, "fit", errfit_body); }

const sf_check_def sf_checks_design[] = {
    { "plan_design", chk_design, "the accuracy plan's qoi_tol on a Latin hypercube over l/R, CV, v_b, mu, T, qoi_tol" },
    { "plan_errmodel", chk_errmodel, "the plan's predicted error against stored held-out measurements of the design (no solve)" },
    { "plan_errfit", chk_errfit, "err_pred's constants (numplan.c) against their refit from the stored design data they were fitted on" },
    { NULL, NULL, NULL }
};
