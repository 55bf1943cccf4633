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
 * plan_errmodel and plan_errfit (design_stored.c): the plan's predicted
 * error against the stored tables of this design at held-out seeds, and
 * the provenance of its constants, without a solve. */
#include "checks.h"
#include "common.h"
#include "design_common.h"
#include "../stats.h"
#include "cof.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "sf_error.h"
#include "stats.h"
#include "sweep.h"
#include "unum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

static const char *const qname[NQ] = { "PV_x", "PV_F", "stick fraction" };

/* P(X >= k), X ~ Bin(n, p) */
static double binom_upper(size_t k, double p, size_t n)
{
    return k == 0 ? 1 : k > n ? 0 : gsl_cdf_binomial_Q((unsigned)(k - 1), p, (unsigned)n);
}

/* See design_common.h. */
size_t design_binom_critical(size_t n, double p0, double alpha)
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

/* See design_common.h. */
void design_rate_test(sf_result *r, const char *what, size_t k, size_t n, double p0, double alpha)
{
    double p = binom_upper(k, p0, n);
    size_t kc = design_binom_critical(n, p0, alpha);
    double lo, hi;
    sf_clopper_pearson((double)k, (double)n, &lo, &hi);
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

/* See design_common.h. */
void design_report_sharpness(sf_result *r, double *ratio, size_t n)
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

/* See design_common.h. */
int design_box(const sf_case *c, sf_result *r, double *lo, double *hi)
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

double *design_points(unsigned long seed, size_t n)
{
    double *u = check_alloc(n * ND * sizeof *u);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, sf_mc_seed(seed, (size_t)-1));   /* the design's own stream */
    lhs(g, n, u);
    gsl_rng_free(g);
    return u;
}

/* See design_common.h. */
int design_scene(const sf_scene *s0, const double *lo, const double *hi, const double *ui, sf_scene *s,
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

/* See design_common.h. */
void design_point_text(char *buf, size_t len, const char *sep, double lr, const sf_scene *s, const sf_numplan *np)
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
        design_point_text(pt, sizeof pt, " | ", lr, &s, &pr.np);
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
        design_rate_test(r, "points whose error exceeds qoi_tol", pt_miss, pts, MISS_RATE, a_row);
        snprintf(t, sizeof t, "points whose error exceeds %g qoi_tol", c->spec.tolerance);
        design_rate_test(r, t, pt_wild, pts, WILD_RATE, a_row);
        design_rate_test(r, "points whose error exceeds the plan's predicted error", pt_under, pts, UNDER_RATE, a_row);
        design_rate_test(r, "undecidable points (no cycle, a cycle at the window's edge, or no QoI whose reference is "
                     "converged to qoi_tol)", n - pts, n, UNDECIDED_RATE, a_row);
        sf_note(r, "\nOver the %zu decided (point, QoI) pairs (%zu undecided: |Q1 - Q2| > qoi_tol; %zu points with "
                   "a cycle at the window's edge or none): %zu within qoi_tol (%.3f), %zu within the prediction, "
                   "worst achieved / qoi_tol %.3g (reported; the three QoIs of a realisation are not independent, so "
                   "the tests count points).",
                npairs, undecided, disc_points, within, npairs ? (double)within / (double)npairs : 0, bounded, worst);
        design_report_sharpness(r, ratio, pts);
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

const sf_check_def sf_checks_design[] = {
    { "plan_design", chk_design, "the accuracy plan's qoi_tol on a Latin hypercube over l/R, CV, v_b, mu, T, qoi_tol" },
    { NULL, NULL, NULL }
};
