/* Code-to-code checks of the 3-DOF integrator against the independent
 * oracle verification/oracle/ref3dof (docs/design.md sec. 7.3): trajectories up
 * to the first few transitions, QoI distributions beyond, the work-energy
 * balance with the oracle's wrench along the solver's history, and Eq. 15
 * computed by both codes. */
#include "checks.h"
#include "../stats.h"
#include "common.h"
#include "contact.h"
#include "oracle/ref3dof.h"
#include "stats.h"
#include "sf_error.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Every history row of a solver run (all the state the checks need). */
typedef struct {
    size_t n, cap;
    sf_osc_row *rows;
} rows_t;

static void rows_add(void *ctx, const sf_osc_row *row)
{
    rows_t *h = ctx;
    if (h->n == h->cap) {
        h->cap = h->cap ? 2 * h->cap : 4096;
        h->rows = realloc(h->rows, h->cap * sizeof *h->rows);
        if (!h->rows)
            exit(SF_EXIT_INTERNAL);
    }
    h->rows[h->n++] = *row;
}

/* The solver's post-jump state at transition time te of kind k: the last
 * row at te in the mode the transition enters. */
static const sf_osc_row *post_row(const rows_t *h, double te, int kind)
{
    const sf_osc_row *p = NULL;
    for (size_t i = 0; i < h->n; i++)
        if (h->rows[i].t == te && h->rows[i].stick == (kind == SF_OSC_STICK_ONSET))
            p = &h->rows[i];
    return p;
}

/* The oracle's Gauss-Legendre radii for a scene (angles: 4x as many). */
static size_t oracle_nr(const sf_scene *s)
{
    return s->cells / 2 > 4 ? s->cells / 2 : 4;
}

enum { NQ = 7, Q_VX = 4, Q_VY = 5 };   /* Q_VX, Q_VY: the columns vx+, vy+ */
static const char *qname[NQ] = { "t [s]", "x [m]", "y [m]", "phi [rad]", "vx+ [m/s]", "vy+ [m/s]", "w+ [rad/s]" };

/* The first transitions (up to K) of a solver run as rows of NQ values,
 * their number in *n; the time of the K-th (or T) in *tK. */
static int solver_transitions(const sf_scene *s, const sf_cof *cof, size_t K, double *v, size_t *n, double *tK,
                              sf_result *r)
{
    rows_t h = { 0 };
    sf_osc_result res;
    if (check_osc_run(s, NULL, cof, 0, &res, rows_add, &h, r))
        return SF_EFAIL;
    int rc = SF_SUCCESS;
    *n = res.ntrans < K ? res.ntrans : K;
    if (tK)
        *tK = res.ntrans >= K ? res.trans_t[K - 1] : s->T;
    for (size_t i = 0; !rc && i < *n; i++) {
        const sf_osc_row *p = post_row(&h, res.trans_t[i], res.trans_kind[i]);
        if (!p) {
            rc = SF_EFAIL;
            break;
        }
        double q[NQ] = { p->t, p->x, p->y, p->phi, p->vx, p->vy, p->w };
        memcpy(v + NQ * i, q, sizeof q);
    }
    sf_osc_result_free(&res);
    free(h.rows);
    return rc;
}

/* A run with no transition compared by its end: the state at its T (t,
 * then x ... w, as a transition's row) and its transition count. */
static int solver_end(const sf_scene *s, const sf_cof *cof, double *v, size_t *ntrans, sf_result *r)
{
    rows_t h = { 0 };
    sf_osc_result res;
    if (check_osc_run(s, NULL, cof, 0, &res, rows_add, &h, r))
        return SF_EFAIL;
    *ntrans = res.ntrans;
    int rc = h.n ? SF_SUCCESS : SF_EFAIL;
    if (!rc) {
        const sf_osc_row *p = &h.rows[h.n - 1];
        double q[NQ] = { p->t, p->x, p->y, p->phi, p->vx, p->vy, p->w };
        memcpy(v, q, sizeof q);
    }
    sf_osc_result_free(&res);
    free(h.rows);
    return rc;
}

/* How well posed a transition is: the smallest relative margin of the
 * switching criterion that decided it, from the state just before the
 * jump (docs/design.md sec. 7.3).  A stick onset (Sec. 2.4: lambda < eps
 * and the stick force (k x, k y) inside the circle of radius mu_bar m g)
 * is decided by the criterion that became true last; its margin is the
 * smaller of the other one's (how far inside: 1 - k |r| / (mu_bar m g),
 * or 1 - lambda / eps) and, when lambda decided, lambda's crossing rate
 * -dlambda/dt over the rate friction alone gives it, mu_k,bar g /
 * (omega_n R) (a graze has rate 0: the onset appears or vanishes with an
 * error of either code).  A stick break (Eq. 14) is decided by k |r|
 * reaching mu_bar m g as x moves at v_b: its rate relative to the
 * largest is x / |r| (0: a tangent exit). */
static double transition_margin(const ref3dof *o, const sf_scene *s, const ref3dof_event *e)
{
    const double *p = e->pre;
    double rr = hypot(p[REF_X], p[REF_Y]);
    if (e->kind == REF_SLIP_ONSET)
        return rr > 0 ? p[REF_X] / rr : 0;
    double wn = sqrt(s->k / s->m), V = wn * s->R, N = s->m * s->g, J = 0.5 * s->m * s->R * s->R;
    double mb = ref3dof_mean_cof(o, p[REF_X] - s->v_b * e->t, p[REF_Y]);
    double a = (p[REF_VX] - s->v_b) / V, b = p[REF_VY] / V, c = p[REF_W] / wn, lam = sqrt(a * a + b * b + c * c);
    double adm = 1 - s->k * rr / (mb * N);
    if (lam < s->eps_lambda * (1 - 1e-6))   /* the stick set was entered with lambda already below eps */
        return fmin(adm, 1 - lam / s->eps_lambda);
    double F[3];
    ref3dof_wrench(o, e->t, p, F);
    double da = (-s->k * p[REF_X] + F[0]) / (s->m * V), db = (-s->k * p[REF_Y] + F[1]) / (s->m * V), dc = F[2] / (J * wn);
    double rate = -(a * da + b * db + c * dc) / lam;
    return fmin(adm, rate / (s->mu_k_ratio * mb * s->g / V));
}

/* The first transitions (up to K) of an oracle run at step dt, on its own
 * nr x na rule, or on the solver's cells `rule` when not NULL; with
 * `margin`, each one's transition_margin. */
static int oracle_transitions(const sf_scene *s, const sf_cof *cof, double dt, double tol, size_t nr, size_t na,
                              const sf_contact *rule, size_t K, double *v, int *kinds, size_t *n, double *margin)
{
    ref3dof *o;
    ref3dof_result res;
    const double *rx, *ry, *wt;
    if (rule)
        sf_contact_cells(rule, &rx, &ry, &wt);
    if (rule ? ref3dof_alloc_nodes(s, cof, dt, tol, sf_contact_ncells(rule), rx, ry, wt, &o)
             : ref3dof_alloc(s, cof, dt, nr, na, &o))
        return SF_EFAIL;
    int rc = ref3dof_run(o, 0, &res);
    *n = res.nev < K ? res.nev : K;
    for (size_t i = 0; !rc && i < *n; i++) {
        const ref3dof_event *e = &res.ev[i];
        double q[NQ] = { e->t, e->post[REF_X], e->post[REF_Y], e->post[REF_PHI], e->post[REF_VX], e->post[REF_VY], e->post[REF_W] };
        memcpy(v + NQ * i, q, sizeof q);
        if (kinds)
            kinds[i] = e->kind;
        if (margin)
            margin[i] = transition_margin(o, s, e);
    }
    ref3dof_free(o);
    ref3dof_result_free(&res);
    return rc;
}

/* The oracle's state at its T and its transition count (solver_end). */
static int oracle_end(const sf_scene *s, const sf_cof *cof, double dt, size_t nr, size_t na, double *v, size_t *ntrans)
{
    ref3dof *o;
    ref3dof_result res;
    if (ref3dof_alloc(s, cof, dt, nr, na, &o))
        return SF_EFAIL;
    int rc = ref3dof_run(o, 0, &res);
    if (!rc) {
        *ntrans = res.nev;
        v[0] = s->T;
        memcpy(v + 1, res.end, REF_N * sizeof(double));
    }
    ref3dof_free(o);
    ref3dof_result_free(&res);
    return rc;
}

/* Trajectory by trajectory: the first `samples` transitions (times and
 * post-jump states) of the solver and the oracle, each at two resolutions.
 * Tolerance per quantity: `tolerance` x (estimated error of the solver +
 * estimated error of the oracle), each estimated as the largest gap over
 * the compared transitions between its two resolutions (the coarse run's
 * error, an over-estimate for the fine runs that are compared), plus a
 * floor of 1e-11 (the event tolerances, 1e-12 s, in the quantity's units
 * at unit speed); the velocities after a stick break add the position gap
 * at that break carried through Eq. 14 (below), and each row is reported
 * at the transition nearest its tolerance.
 *
 * The scene's T is a cap, not the window: how long the first slip phases
 * last depends on the field (a slip phase ends only when vx - v_b, vy and
 * the spin are all within eps_lambda at once, and near misses prolong
 * it), so the field is drawn for the cap and every run stops 1 s after
 * the coarse solver run's K-th transition.  A run with fewer than K
 * transitions in that window fails its row; when the coarse run itself
 * has fewer than K within the cap, its own count is compared, and when it
 * has none, every run's state at the cap (none may have a transition). */
static int chk_ref_trajectory(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = s0->samples;
    sf_cof *cof = check_case_cof(c, s0, r);
    if (!cof)
        return SF_EFAIL;
    sf_scene sc = *s0, sf = *s0, so = *s0;   /* solver: coarse (scene), fine (rtol/100, 2 cells); oracle */
    sf.rtol = s0->rtol / 100;
    sf.cells = 2 * s0->cells;
    /* oracle resolutions: RK4 at the scene's dt with cells/2 Gauss-Legendre
     * radii x 2 cells angles (a quarter of the solver's polar cells: the
     * oracle pays a fixed step); fine: dt/2 and twice the nodes each way */
    size_t nr = oracle_nr(s0), na = 4 * nr, nSc, nSf, nOc, nOf;
    double *Sc = check_alloc(K * NQ * sizeof(double)), *Sf = check_alloc(K * NQ * sizeof(double));
    double *Oc = check_alloc(K * NQ * sizeof(double)), *Of = check_alloc(K * NQ * sizeof(double));
    int *kind = check_alloc(K * sizeof(int)), *kindc = check_alloc(K * sizeof(int));
    double tK;
    int rc = solver_transitions(&sc, cof, K, Sc, &nSc, &tK, r);
    if (!rc) {
        sc.T = sf.T = so.T = fmin(s0->T, tK + 1);
        K = nSc;
        rc = solver_transitions(&sc, cof, K, Sc, &nSc, NULL, r) || solver_transitions(&sf, cof, K, Sf, &nSf, NULL, r) ||
             oracle_transitions(&so, cof, s0->dt, 1, nr, na, NULL, K, Oc, kindc, &nOc, NULL) ||
             oracle_transitions(&so, cof, s0->dt / 2, 1, 2 * nr, 2 * na, NULL, K, Of, kind, &nOf, NULL);
    }
    if (!rc && !K) {
        /* a slip phase from t = 0 to the cap (the field's torque keeps the
         * disc spinning whenever vx meets v_b; 1 fresh field in about 300):
         * the runs are compared by their state at the cap, and none may
         * have a transition; the same tolerance, one row of seven values */
        size_t tr[4];
        rc = solver_end(&sc, cof, Sc, &tr[0], r) || solver_end(&sf, cof, Sf, &tr[1], r) ||
             oracle_end(&so, cof, s0->dt, nr, na, Oc, &tr[2]) || oracle_end(&so, cof, s0->dt / 2, 2 * nr, 2 * na, Of, &tr[3]);
        if (!rc) {
            char cnt[96];
            snprintf(cnt, sizeof cnt, "%zu, %zu (solver), %zu, %zu (oracle)", tr[0], tr[1], tr[2], tr[3]);
            sf_check_true(r, "no run has a transition within the cap (their states at T compared)",
                          !(tr[0] | tr[1] | tr[2] | tr[3]), cnt);
            sf_note(r, "Window: the cap T = %g s: the coarse solver run has no transition in it; the state at T is "
                       "compared (t = T in every run).", s0->T);
            K = 1;
            kind[0] = kindc[0] = 0;
        }
    }
    if (rc) {
        sf_cof_free(cof);
        free(Sc); free(Sf); free(Oc); free(Of); free(kind); free(kindc);
        return SF_EFAIL;
    }
    if (nSc) {
        size_t nmin = nSc < nSf ? nSc : nSf;
        nmin = nmin < nOc ? nmin : nOc;
        nmin = nmin < nOf ? nmin : nOf;
        char cnt[96];
        snprintf(cnt, sizeof cnt, "%zu, %zu (solver), %zu, %zu (oracle)", nSc, nSf, nOc, nOf);
        sf_check_true(r, "every run has the transitions compared (coarse, fine)", nmin == K, cnt);
        sf_note(r, "Window: %g s (1 s after the coarse solver run's transition %zu; cap T = %g s); %zu transitions "
                   "compared.", sc.T, K, s0->T, nmin);
        K = nmin;
    }
    int kinds_ok = 1;
    for (size_t i = 0; i < K; i++)
        kinds_ok &= kind[i] == kindc[i];
    sf_check_true(r, "the oracle's transition kinds agree at both resolutions", kinds_ok, kinds_ok ? "yes" : "no");
    sf_note(r, "Oracle: RK4 at dt = %g s and %g s, Gauss-Legendre %zu x trapezoid %zu nodes and %zu x %zu. "
               "Solver: rtol %g, cells %zu and rtol %g, cells %zu (the fine runs are compared).\n\n"
               "Post-jump velocities after a stick break (Eq. 14) carry, besides the estimated errors, the position gap "
               "at that break through the jump (largest over the breaks in the column Eq. 14).\n\n"
               "| quantity | gap solver-oracle | est. error solver | est. error oracle | Eq. 14 | tolerance |\n"
               "|---|---|---|---|---|---|",
            s0->dt, s0->dt / 2, nr, na, 2 * nr, 2 * na, sc.rtol, sc.cells, sf.rtol, sf.cells);
    double *tt = check_alloc(K * sizeof(double)), *gap = check_alloc(K * sizeof(double));
    double qi[NQ - 1], rel[NQ - 1];   /* end-state mode: each state's gap over its tolerance */
    double *jump = check_alloc(K * sizeof(double));
    double delta = s0->velocity_jump ? check_jump_speed(s0) : 0, jmax = 0;
    for (size_t i = 0; i < K; i++) {
        /* Eq. 14 sets v+ = (v_b, 0, 0) - delta r/|r| from the position r =
         * (x, y) at the break, so the codes' post-jump velocities differ by
         * delta |r_S/|r_S| - r_O/|r_O||, which equals delta sqrt(|dr|^2 -
         * (|r_S| - |r_O|)^2) / sqrt(|r_S| |r_O|) <= delta |dr| /
         * sqrt(|r_S| |r_O|): the position gap (its own rows) carried
         * through the jump.  The refinement estimates do not bound it: they
         * see a code's position change along one direction, the gap between
         * the codes may lie across it. */
        const double *a = Sf + NQ * i, *b = Of + NQ * i;
        double rS = hypot(a[1], a[2]), rO = hypot(b[1], b[2]);
        jump[i] = kind[i] == REF_SLIP_ONSET && rS > 0 && rO > 0 ? delta * hypot(a[1] - b[1], a[2] - b[2]) / sqrt(rS * rO) : 0;
        jmax = fmax(jmax, jump[i]);
    }
    for (int q = 0; q < NQ; q++) {
        double eS = 0, eO = 0;
        for (size_t i = 0; i < K; i++) {
            eS = sf_max(eS, fabs(Sf[NQ * i + q] - Sc[NQ * i + q]));
            eO = sf_max(eO, fabs(Of[NQ * i + q] - Oc[NQ * i + q]));
        }
        double base = c->spec.tolerance * (eS + eO) + 1e-11, d = 0, tol = base, worst = -1;
        for (size_t i = 0; i < K; i++) {
            double a = Sf[NQ * i + q], b = Of[NQ * i + q];
            double di = isfinite(a) && isfinite(b) ? fabs(a - b) : INFINITY;
            double ti = base + (q == Q_VX || q == Q_VY ? jump[i] : 0);
            if (!(di / ti <= worst)) {   /* the transition nearest its tolerance (a NaN ratio wins) */
                worst = di / ti;
                d = di;
                tol = ti;
            }
            if (q == 0) {
                tt[i] = b;
                gap[i] = fmax(fabs(a - b), 1e-16);
            }
        }
        char name[SF_LABEL_LEN];
        if (q == Q_VX || q == Q_VY)
            snprintf(name, sizeof name, "|solver - oracle| at the worst of %zu transitions against its tolerance, %s", K,
                     qname[q]);
        else
            snprintf(name, sizeof name, "max over %zu transitions |solver - oracle|, %s", K, qname[q]);
        sf_check_le(r, name, d, tol);
        sf_note(r, "| %s | %.3g | %.3g | %.3g | %.3g | %.3g |", qname[q], d, eS, eO,
                q == Q_VX || q == Q_VY ? jmax : 0.0, tol);
        if (q) {
            qi[q - 1] = q;
            rel[q - 1] = fmax(d / tol, 1e-16);
        }
    }
    if (nSc) {
        sf_plot *p = sf_result_plot(r, "ref_trajectory", "Transition times: solver vs independent oracle",
                                    "oracle transition time [s]", "|t_solver - t_oracle| [s]");
        sf_plot_log(p, 0, 1);
        sf_plot_series(p, "gap", SF_STYLE_LINESPOINTS, K, tt, gap);
    } else {
        sf_plot *p = sf_result_plot(r, "ref_trajectory", "State at the cap T: solver vs independent oracle",
                                    "state (1 x, 2 y, 3 phi, 4 vx, 5 vy, 6 w)", "|solver - oracle| / tolerance [-]");
        sf_plot_log(p, 0, 1);
        sf_plot_series(p, "gap / tolerance", SF_STYLE_POINTS, NQ - 1, qi, rel);
    }
    free(tt); free(gap); free(jump);
    sf_cof_free(cof);
    free(Sc); free(Sf); free(Oc); free(Of); free(kind); free(kindc);
    return SF_SUCCESS;
}

/* The paired comparison of one QoI: d_i = solver_i / oracle_i - 1 on the
 * same field.  The gate is a test of the interval null |E d| <= margin
 * (the codes agree to within the margin): t = (|mean| - margin) / se,
 * p = Q_t(t) + Q_t((|mean| + margin) / se), df = n - 1, exact for normal d
 * at the boundary and conservative inside it.  Reported beside it: the
 * TOST verdict (equivalence shown: both one-sided (1 - alpha) bounds of
 * the mean inside +-margin) and the minimum detectable shift at power
 * 0.99, margin + (t_alpha + t_0.01) se.  Returns the p-value (0 when a
 * value is not finite). */
#define REF_STATS_MARGIN 0.01
static double ref_paired_test(sf_result *r, const char *what, const double *a, const double *b, size_t n,
                              double alpha, double *d)
{
    int fin = n > 1;
    for (size_t i = 0; i < n; i++) {
        d[i] = a[i] / b[i] - 1;
        fin &= isfinite(d[i]);
    }
    double m = fin ? gsl_stats_mean(d, 1, n) : NAN, se = fin ? gsl_stats_sd(d, 1, n) / sqrt((double)n) : NAN;
    double df = (double)n - 1, p = 0;
    if (fin)
        p = sf_interval_null_p(m, se, REF_STATS_MARGIN, df);
    double tq = gsl_cdf_tdist_Qinv(alpha, df), lo = m - tq * se, hi = m + tq * se;
    double mde = REF_STATS_MARGIN + (tq + gsl_cdf_tdist_Qinv(0.01, df)) * se;
    char name[SF_LABEL_LEN];
    /* the mean and its se are in the findings: a row's name must not
       change with its data (the drift page matches rows by name) */
    snprintf(name, sizeof name, "%.60s: paired relative difference, |mean| <= %g (one-sided t test)", what,
             REF_STATS_MARGIN);
    sf_check_pvalue(r, name, p, alpha, n);
    sf_note(r, "| %s | %.3g | %.3g | [%.3g, %.3g] | %s | %.3g |", what, m, se, lo, hi,
            lo > -REF_STATS_MARGIN && hi < REF_STATS_MARGIN ? "shown" : "not shown", mde);
    return p;
}

/* Statistics beyond the first transitions: paired tests on PV_x, PV_F
 * and the stick fraction, solver vs oracle, on the SAME field
 * realisations, at each l/R of `sweep`; the case's alpha split over the
 * 3 x (number of l/R) tests. */
static int chk_ref_stats(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = s0->samples, nl = c->spec.sweep.n ? c->spec.sweep.n : 1;
    double *a[3], *b[3];
    for (int q = 0; q < 3; q++) {
        a[q] = check_alloc(K * sizeof(double));
        b[q] = check_alloc(K * sizeof(double));
    }
    static const char *qn[3] = { "PV_x", "PV_F", "stick fraction" };
    double pmin = 1;
    for (size_t il = 0; il < nl; il++) {
        sf_scene s = *s0;
        if (c->spec.sweep.n)
            s.l = c->spec.sweep.v[il] * s0->R;
        sf_cof_plan *plan;
        char err[256];
        if (sf_cof_plan_alloc(&s, &plan, err, sizeof err)) {
            sf_note(r, "**Cannot plan the COF:** %s", err);
            return SF_EFAIL;
        }
        gsl_rng *rng = sf_case_rng(c);
        double worst = 0;
        size_t n = 0, nocycle = 0, refined = 0, refined_s = 0;
        for (size_t k = 0; k < K; k++) {
            sf_cof *cof = NULL;
            sf_cof_plan_draw(plan, rng, &cof);
            sf_osc_result rs;
            ref3dof *o;
            ref3dof_result ro;
            if (!cof || check_osc_run(&s, NULL, cof, 0, &rs, NULL, NULL, r) ||
                ref3dof_alloc(&s, cof, s.dt, oracle_nr(&s), 4 * oracle_nr(&s), &o)) {
                sf_cof_free(cof);
                sf_cof_plan_free(plan);
                gsl_rng_free(rng);
                return SF_EFAIL;
            }
            int orc = ref3dof_run(o, 0, &ro);
            ref3dof_free(o);
            if (!orc && rs.ncycles != ro.ncycles) {
                /* A cycle count that differs is a grazing stick onset:
                 * lambda's minimum in a long slip phase sits within the
                 * codes' discretisation error of eps_lambda (Sec. 2.4),
                 * so an event of one code is a near miss of the other.
                 * The oracle settles it by its own refinement (half the
                 * step, twice the nodes each way); a count that still
                 * differs stays a mismatch and fails below. */
                ref3dof_result rf;
                if (ref3dof_alloc(&s, cof, s.dt / 2, 2 * oracle_nr(&s), 8 * oracle_nr(&s), &o) == SF_SUCCESS) {
                    orc = ref3dof_run(o, 0, &rf);
                    ref3dof_free(o);
                    sf_note(r, "l/R = %g, realisation %zu: %zu complete cycles (solver), %zu (oracle), %zu (oracle "
                               "refined: the count it keeps).", s.l / s.R, k, rs.ncycles, ro.ncycles,
                            orc ? (size_t)0 : rf.ncycles);
                    ref3dof_result_free(&ro);
                    ro = rf;
                    refined++;
                }
            }
            if (orc) {
                sf_note(r, "**The oracle run failed.**");
                return SF_EFAIL;
            }
            if (rs.ncycles != ro.ncycles) {
                /* The oracle's refined count stands and the solver's
                 * differs: the same near miss may be the solver's, from
                 * its quadrature (the scene's rings, coarser than the
                 * oracle's nodes, move the wrench, and with it lambda's
                 * minimum, by more than its distance to eps_lambda).  The
                 * solver settles it by its own refinement, twice the
                 * rings; that run is the one compared.  A count that still
                 * differs stays a mismatch and fails below. */
                sf_scene s2 = s;
                s2.cells = 2 * (s.cells ? s.cells : 8);
                sf_osc_result rf;
                if (!check_osc_run(&s2, NULL, cof, 0, &rf, NULL, NULL, r)) {
                    sf_note(r, "l/R = %g, realisation %zu: %zu complete cycles (solver), %zu (oracle), %zu (solver "
                               "at %zu rings: the count it keeps).", s.l / s.R, k, rs.ncycles, ro.ncycles, rf.ncycles,
                            s2.cells);
                    sf_osc_result_free(&rs);
                    rs = rf;
                    refined_s++;
                }
            }
            if (rs.ncycles == 0 && ro.ncycles == 0) {
                /* both codes agree there is no complete cycle in the window:
                 * no QoI to compare (a field that sticks long); a cycle in
                 * one code only stays in the samples, as NaN, and fails */
                nocycle++;
                sf_osc_result_free(&rs);
                ref3dof_result_free(&ro);
                sf_cof_free(cof);
                continue;
            }
            double va[3] = { rs.cyc_pv_x, rs.cyc_pv_F, rs.cyc_stick_fraction }, vb[3] = { ro.pv_x, ro.pv_F, ro.stick_fraction };
            if (rs.ncycles != ro.ncycles)
                sf_note(r, "l/R = %g, realisation %zu: %zu complete cycles (solver), %zu (oracle).", s.l / s.R, k,
                        rs.ncycles, ro.ncycles);
            for (int q = 0; q < 3; q++) {
                a[q][n] = va[q];
                b[q][n] = vb[q];
                worst = sf_max(worst, fabs(va[q] / vb[q] - 1));
            }
            n++;
            sf_osc_result_free(&rs);
            ref3dof_result_free(&ro);
            sf_cof_free(cof);
        }
        sf_cof_plan_free(plan);
        gsl_rng_free(rng);
        sf_note(r, "l/R = %g: %zu realisations, largest paired relative gap %.3g (chaos beyond the first transitions, "
                   "and the two codes' discretisation); %zu more without a complete cycle in either code (left out); "
                   "%zu settled by the oracle's refinement, %zu by the solver's.",
                s.l / s.R, n, worst, nocycle, refined, refined_s);
        for (int q = 0; q < 3; q++) {
            int fin = 1;
            for (size_t i = 0; i < n; i++)
                fin &= isfinite(a[q][i]) && isfinite(b[q][i]);
            char name[SF_LABEL_LEN];
            snprintf(name, sizeof name, "l/R = %g: %s finite in every run (both codes)", s.l / s.R, qn[q]);
            sf_check_true(r, name, fin, fin ? "yes" : "NaN/Inf");
            if (q == 0) {   /* plot the PV_x samples of each l/R */
                char stem[32], title[96];
                snprintf(stem, sizeof stem, "ref_stats_%zu", il);
                snprintf(title, sizeof title, "PV_x per realisation, l/R = %g", s.l / s.R);
                sf_plot *p = sf_result_plot(r, stem, title, "solver PV_x [m]", "oracle PV_x [m]");
                sf_plot_series(p, "realisations", SF_STYLE_POINTS, n, a[0], b[0]);
                sf_plot_series(p, "equal", SF_STYLE_LINES, n, a[0], a[0]);
            }
            snprintf(name, sizeof name, "l/R = %g: %s", s.l / s.R, qn[q]);
            double *d = check_alloc((n ? n : 1) * sizeof *d);
            if (q == 0 && il == 0)
                sf_note(r, "\n| l/R, QoI | mean paired relative difference | se | one-sided (1 - alpha) bounds "
                           "| equivalence within +-%g (TOST) | minimum detectable shift (power 0.99) |\n"
                           "|---|---|---|---|---|---|", REF_STATS_MARGIN);
            double pv = ref_paired_test(r, name, a[q], b[q], n, c->spec.alpha / (double)(3 * nl), d);
            sf_result_data(r, name, n, d);
            free(d);
            pmin = sf_min(pmin, pv);
        }
    }
    sf_note(r, "\nSmallest p-value %.3g (alpha %.3g per test: the case's %g over %zu tests).", pmin,
            c->spec.alpha / (double)(3 * nl), c->spec.alpha, 3 * nl);
    for (int q = 0; q < 3; q++) {
        free(a[q]);
        free(b[q]);
    }
    return SF_SUCCESS;
}

/* Work-energy balance along the solver's emitted history with the
 * ORACLE's wrench: E(T) - E(0) = W_slip + W_stick + sum of jumps, where
 * W_slip integrates the oracle wrench's power over the slip rows
 * (composite trapezoid; its error estimated from the same sum on every
 * other row, Richardson: (W_h - W_2h)/3), W_stick = k x v_b integrated
 * exactly over the stick rows (Eq. 6), jumps from the rows either side
 * of each transition.  The solver's own work state is not used.
 *
 * The stick work and the jumps are exact, so the residual is the sum of
 * the slip segments' residuals dE_seg - W_seg; each error estimate is a
 * sum over the segments of |the estimate on that segment|: two segments'
 * quadrature errors can cancel in the run's total (a field run with the
 * pole on the disc in one slip phase and off it in the next does), their
 * estimates must not. */
typedef struct {
    size_t n, cap;
    double *dE, *W, *W2, *Wq;   /* per slip segment: energy change, work (fine oracle, every other row, coarse oracle) */
} segs_t;

static void segs_free(segs_t *g)
{
    free(g->dE);
    free(g->W);
    free(g->W2);
    free(g->Wq);
    memset(g, 0, sizeof *g);
}

static double row_energy(const sf_osc_row *a, double m, double J, double k)
{
    return 0.5 * m * (a->vx * a->vx + a->vy * a->vy) + 0.5 * J * a->w * a->w + 0.5 * k * (a->x * a->x + a->y * a->y);
}

/* The oracle wrench's power at every slip row (0 on stick rows). */
static double *rows_power(const ref3dof *o, const rows_t *h)
{
    double *P = check_alloc(h->n * sizeof(double));
    for (size_t i = 0; i < h->n; i++) {
        const sf_osc_row *a = &h->rows[i];
        double st[REF_N] = { a->x, a->y, a->phi, a->vx, a->vy, a->w }, F[3];
        P[i] = 0;
        if (!a->stick) {
            ref3dof_wrench(o, a->t, st, F);
            P[i] = F[0] * a->vx + F[1] * a->vy + F[2] * a->w;
        }
    }
    return P;
}

/* Trapezoid of P over rows [a, b], every `step`-th row (ends kept). */
static double trapezoid(const rows_t *h, const double *P, size_t a, size_t b, size_t step)
{
    double w = 0;
    for (size_t j = a; j < b;) {
        size_t jn = j + step <= b ? j + step : b;
        w += 0.5 * (h->rows[jn].t - h->rows[j].t) * (P[j] + P[jn]);
        j = jn;
    }
    return w;
}

/* The balance's terms along the rows: per slip segment (fine oracle o2,
 * every other row, coarse oracle o), the exact stick work and the jumps. */
static void rows_work(const ref3dof *o, const ref3dof *o2, const rows_t *h, double m, double J, double k, segs_t *g,
                      double *Wstick, double *jumps)
{
    double *P = rows_power(o2, h), *Pq = rows_power(o, h);
    double jp = 0, ws = 0;
    size_t i = 1;
    while (i < h->n) {
        const sf_osc_row *a = &h->rows[i], *b = &h->rows[i - 1];
        if (a->t == b->t) {   /* a jump (Eq. 12 or 14) */
            jp += 0.5 * m * (a->vx * a->vx + a->vy * a->vy - b->vx * b->vx - b->vy * b->vy) + 0.5 * J * (a->w * a->w - b->w * b->w);
            i++;
        } else if (a->stick && b->stick) {   /* Eq. 6: power k x v_b, x linear in t */
            ws += 0.5 * k * (a->x * a->x - b->x * b->x);
            i++;
        } else {   /* a slip segment [i - 1, e] */
            size_t s0 = i - 1, e = i;
            while (e + 1 < h->n && !h->rows[e + 1].stick && h->rows[e + 1].t != h->rows[e].t)
                e++;
            if (g->n == g->cap) {
                g->cap = g->cap ? 2 * g->cap : 16;
                double **arr[] = { &g->dE, &g->W, &g->W2, &g->Wq };
                for (int q = 0; q < 4; q++)
                    if (!(*arr[q] = realloc(*arr[q], g->cap * sizeof(double))))
                        exit(SF_EXIT_INTERNAL);
            }
            g->dE[g->n] = row_energy(&h->rows[e], m, J, k) - row_energy(&h->rows[s0], m, J, k);
            g->W[g->n] = trapezoid(h, P, s0, e, 1);
            g->W2[g->n] = trapezoid(h, P, s0, e, 2);
            g->Wq[g->n] = trapezoid(h, Pq, s0, e, 1);
            g->n++;
            i = e + 1;
        }
    }
    free(P);
    free(Pq);
    *Wstick = ws;
    *jumps = jp;
}

/* The balance along one solver run's history: residual, trapezoid and
 * oracle-quadrature error estimates (sums over the slip segments of their
 * moduli), energy turned over; the per-segment terms kept in g. */
typedef struct {
    double dE, W, jumps, resid, e_trap, e_quad, turnover, own;
    segs_t g;
} balance_t;

static int balance(const sf_scene *s, const sf_cof *cof, const ref3dof *o, const ref3dof *o2, balance_t *b,
                   rows_t *keep, sf_result *r)
{
    rows_t h = { 0 };
    sf_osc_result res;
    if (check_osc_run(s, NULL, cof, 0, &res, rows_add, &h, r) || h.n < 2) {
        free(h.rows);
        return SF_EFAIL;
    }
    double m = s->m, J = 0.5 * s->m * s->R * s->R, k = s->k, ws;
    b->g = (segs_t){ 0 };
    rows_work(o, o2, &h, m, J, k, &b->g, &ws, &b->jumps);
    b->W = ws;
    b->e_trap = b->e_quad = 0;
    for (size_t i = 0; i < b->g.n; i++) {
        b->W += b->g.W[i];
        b->e_trap += fabs(b->g.W[i] - b->g.W2[i]) / 3;
        b->e_quad += fabs(b->g.W[i] - b->g.Wq[i]);
    }
    b->dE = row_energy(&h.rows[h.n - 1], m, J, k) - row_energy(&h.rows[0], m, J, k);
    b->resid = b->dE - b->W - b->jumps;
    b->turnover = 0;
    for (size_t i = 1; i < h.n; i++)
        b->turnover += fabs(row_energy(&h.rows[i], m, J, k) - row_energy(&h.rows[i - 1], m, J, k));
    b->own = res.energy_residual;
    sf_osc_result_free(&res);
    if (keep)
        *keep = h;
    else
        free(h.rows);
    return SF_SUCCESS;
}

/* The solver's quadrature error: the change of the residual between the
 * run at the scene's cells (bc) and at twice as many (b), segment by
 * segment when both runs have the same slip segments (the same
 * transitions), else of the total. */
static double solver_quad_error(const balance_t *b, const balance_t *bc)
{
    if (b->g.n != bc->g.n)
        return fabs(b->resid - bc->resid);
    double e = 0;
    for (size_t i = 0; i < b->g.n; i++)
        e += fabs((b->g.dE[i] - b->g.W[i]) - (bc->g.dE[i] - bc->g.W[i]));
    return e;
}

/* A field COF: the solver's wrench is its own quadrature, whose error
 * enters the residual; it is estimated from a second run at half the
 * cells (|resid(cells) - resid(2 cells)|: it shrinks with the cells, a
 * defect in the model does not), and the 2-cell run is the one checked.
 * A constant COF: the solver's wrench is the exact closed form. */
static int chk_ref_energy(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cof *cof = check_case_cof(c, s, r);
    if (!cof)
        return SF_EFAIL;
    int field = sf_cof_get_kind(cof) == SF_COF_FIELD;
    sf_scene sf = *s;
    if (field)
        sf.cells = 2 * s->cells;
    ref3dof *o = NULL, *o2 = NULL;
    rows_t h = { 0 };
    balance_t b = { 0 }, bc = { 0 };
    if (ref3dof_alloc(s, cof, s->dt, oracle_nr(s), 4 * oracle_nr(s), &o) ||
        ref3dof_alloc(s, cof, s->dt, 2 * oracle_nr(s), 8 * oracle_nr(s), &o2) || balance(&sf, cof, o, o2, &b, &h, r) ||
        (field && balance(s, cof, o, o2, &bc, NULL, r))) {
        ref3dof_free(o);
        ref3dof_free(o2);
        free(h.rows);
        segs_free(&b.g);
        segs_free(&bc.g);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    double e_solver = field ? solver_quad_error(&b, &bc) : 0;
    double tol = c->spec.tolerance * (b.e_trap + b.e_quad + e_solver) + 1e-12 * b.turnover;
    int fin = isfinite(b.resid) && isfinite(tol) && (!field || isfinite(bc.resid));
    sf_check_true(r, "balance terms finite", fin, fin ? "yes" : "NaN/Inf");
    sf_check_le(r, "|E(T) - E(0) - W_oracle - jumps| [J]", fabs(b.resid), tol);
    sf_note(r, "%zu history rows over %g s%s. E(T) - E(0) = %.10g J, W (oracle wrench, %zu x %zu nodes) = %.10g J, jumps "
               "%.6g J, residual %.3g J. Estimated errors, each the sum over the %zu slip segments of its modulus on the "
               "segment: trapezoid (Richardson on every other row) %.3g J, oracle quadrature (gap to %zu x %zu nodes) "
               "%.3g J, solver quadrature %.3g J (%s); tolerance = %g x their sum + "
               "1e-12 x energy turned over (%.4g J) = %.3g J. For comparison the solver's own residual (its work "
               "state) is %.3g J.",
            h.n, s->T, field ? " (solver at 2 x cells)" : "", b.dE, 2 * oracle_nr(s), 8 * oracle_nr(s), b.W, b.jumps,
            b.resid, b.g.n, b.e_trap, oracle_nr(s), 4 * oracle_nr(s), b.e_quad, e_solver,
            field ? "residual change from the run at the scene's cells" : "closed-form wrench", c->spec.tolerance, b.turnover,
            tol, b.own);
    double m = s->m, J = 0.5 * s->m * s->R * s->R, k = s->k;
    size_t np = 0;
    double *tp = check_alloc(h.n * sizeof(double)), *ep = check_alloc(h.n * sizeof(double));
    for (size_t i = 0; i < h.n; i += (h.n / 400 + 1)) {
        tp[np] = h.rows[i].t;
        ep[np++] = row_energy(&h.rows[i], m, J, k);
    }
    sf_plot *p = sf_result_plot(r, "ref_energy", "Mechanical energy along the solver's history", "t [s]", "E [J]");
    sf_plot_series(p, "E(t)", SF_STYLE_LINES, np, tp, ep);
    free(tp); free(ep);
    ref3dof_free(o);
    ref3dof_free(o2);
    free(h.rows);
    segs_free(&b.g);
    segs_free(&bc.g);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Eq. 15 by both codes: the error of the eps_lambda = sweep[0] run against
 * the eps_lambda = sweep[1] reference, x sampled every 0.01 s over T,
 * sf_osc_error_eq15 on the solver's runs vs the oracle's own samples and
 * its own sum.  Tolerance: `tolerance` x the sum of each code's estimated
 * error (the change of its Eq. 15 value between two resolutions). */
static int chk_ref_eq15(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    if (c->spec.sweep.n != 2)
        return SF_EINVAL;
    sf_cof *cof = check_case_cof(c, s0, r);
    if (!cof)
        return SF_EFAIL;
    double sdt = 0.01, Es[2], Eo[2];
    for (int lev = 0; lev < 2; lev++) {
        sf_osc_result ra, rb;
        ref3dof_result oa, ob;
        sf_scene sa = *s0, sb = *s0;
        sa.eps_lambda = c->spec.sweep.v[0];
        sb.eps_lambda = c->spec.sweep.v[1];
        sa.rtol = sb.rtol = s0->rtol / (lev ? 100 : 1);
        ref3dof *o1 = NULL, *o2 = NULL;
        double dt = s0->dt / (lev ? 2 : 1);
        size_t nr = oracle_nr(s0) * (lev ? 2 : 1);
        if (check_osc_run(&sa, NULL, cof, sdt, &ra, NULL, NULL, r) || check_osc_run(&sb, NULL, cof, sdt, &rb, NULL, NULL, r) ||
            ref3dof_alloc(&sa, cof, dt, nr, 4 * nr, &o1) || ref3dof_alloc(&sb, cof, dt, nr, 4 * nr, &o2) ||
            ref3dof_run(o1, sdt, &oa) || ref3dof_run(o2, sdt, &ob)) {
            sf_cof_free(cof);
            return SF_EFAIL;
        }
        Es[lev] = sf_osc_error_eq15(&ra, &rb);
        Eo[lev] = ref3dof_eq15(oa.x_samples, ob.x_samples, oa.nsamples < ob.nsamples ? oa.nsamples : ob.nsamples, sdt);
        if (lev == 1) {
            double *t = check_alloc(oa.nsamples * sizeof(double)), *d = check_alloc(oa.nsamples * sizeof(double));
            for (size_t i = 0; i < oa.nsamples && i < ra.nsamples; i++) {
                t[i] = (double)i * sdt;
                d[i] = fabs(ra.x_samples[i] - oa.x_samples[i]) + 1e-16;
            }
            sf_plot *p = sf_result_plot(r, "ref_eq15", "x samples: solver vs oracle (eps = sweep[0])", "t [s]",
                                        "|x_solver - x_oracle| [m]");
            sf_plot_log(p, 0, 1);
            sf_plot_series(p, "gap", SF_STYLE_LINES, oa.nsamples < ra.nsamples ? oa.nsamples : ra.nsamples, t, d);
            free(t); free(d);
        }
        sf_osc_result_free(&ra); sf_osc_result_free(&rb);
        ref3dof_result_free(&oa); ref3dof_result_free(&ob);
        ref3dof_free(o1); ref3dof_free(o2);
    }
    double tol = c->spec.tolerance * (fabs(Es[1] - Es[0]) + fabs(Eo[1] - Eo[0])) + 1e-12 * Eo[1];
    int fin = isfinite(Es[1]) && isfinite(Eo[1]) && Es[1] > 0;
    sf_check_true(r, "Eq. 15 values finite and positive", fin, fin ? "yes" : "no");
    sf_check_abs(r, "Eq. 15 error, solver (sf_osc_error_eq15) vs oracle [m^2 s]", Es[1], Eo[1], tol);
    sf_note(r, "Eq. 15 of eps = %g against eps = %g over %g s: solver %.10g and %.10g (rtol %g, %g), oracle %.10g "
               "and %.10g (dt %g, %g s; %zu and %zu radial nodes) m^2 s; tolerance %g x (%.3g + %.3g) = %.3g.",
            c->spec.sweep.v[0], c->spec.sweep.v[1], s0->T, Es[0], Es[1], s0->rtol, s0->rtol / 100, Eo[0], Eo[1], s0->dt,
            s0->dt / 2, oracle_nr(s0), 2 * oracle_nr(s0), c->spec.tolerance, fabs(Es[1] - Es[0]), fabs(Eo[1] - Eo[0]), tol);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* The quadratures' own convergence on a field (the dynamics rows of
 * ref_converge run both codes on the solver's cells, so they cannot see
 * it): at up to REF_QUAD_STATES slip states of the solver's run (its
 * history rows, evenly spaced), the wrench and the disc-averaged COF by
 * the solver's polar cells (cells 2^i rings) and by the oracle's own
 * Gauss-Legendre x trapezoid rule (oracle_nr 2^i radii, 4x as many
 * angles), i = 0 .. 3.  The paired difference (max over the states of
 * |F_s - F_o| / (m g), |T_s - T_o| / (m g R), |mu_bar_s - mu_bar_o|)
 * falls with the cell size at the slower rule's order: about 2 on a
 * bilinear field (its kinks along the grid lines cut cells; the pole of
 * the slip field, inside the disc near a stick onset, likewise), so the
 * gate is an observed order (least squares) of at least REF_QUAD_ORDER =
 * 1 over the 8-fold refinement.  Four levels, because the coarsest two
 * rules' errors can cancel on a field (a difference that rises from the
 * first level to the second): over three levels that read as order 0.4
 * at one field in a few hundred, over four its order is 1.7 (smallest
 * per field over 80 fields 1.65, mean 2.1).  A difference in the
 * integrand (a term of Eqs. 7-8, the kinetic ratio, a weight) is a
 * plateau under which it cannot fall. */
#define REF_QUAD_STATES 64
#define REF_QUAD_ORDER 1.0
static int quad_converge(const sf_scene *s, const sf_cof *cof, sf_result *r)
{
    rows_t h = { 0 };
    sf_osc_result res;
    if (check_osc_run(s, NULL, cof, 0, &res, rows_add, &h, r)) {
        free(h.rows);
        return SF_EFAIL;
    }
    sf_osc_result_free(&res);
    size_t nslip = 0, ns = 0;
    for (size_t i = 0; i < h.n; i++)
        nslip += !h.rows[i].stick;
    const sf_osc_row **st = check_alloc(REF_QUAD_STATES * sizeof *st);
    for (size_t i = 0, k = 0; i < h.n && ns < REF_QUAD_STATES; i++)
        if (!h.rows[i].stick && k++ * REF_QUAD_STATES >= ns * nslip)
            st[ns++] = &h.rows[i];
    enum { NL = 4 };
    static const char *what[3] = { "|F| / (m g)", "|T| / (m g R)", "mu_bar" };
    double d[3][NL], hs[NL], N = s->m * s->g;
    int rc = SF_SUCCESS;
    for (size_t l = 0; l < NL && !rc; l++) {
        sf_contact_spec spec = { s->R, N, (sf_layout)s->layout, s->cells << l };
        sf_contact *ct = NULL;
        ref3dof *o = NULL;
        hs[l] = 1.0 / (double)(1u << l);
        if (sf_contact_alloc(&spec, cof, &ct) || ref3dof_alloc(s, cof, s->dt, oracle_nr(s) << l, 4 * oracle_nr(s) << l, &o))
            rc = SF_EFAIL;
        for (int q = 0; q < 3; q++)
            d[q][l] = 0;
        for (size_t j = 0; j < ns && !rc; j++) {
            const sf_osc_row *w = st[j];
            double xb = w->x - s->v_b * w->t, Fs[3], Fo[3], y[REF_N] = { w->x, w->y, w->phi, w->vx, w->vy, w->w };
            sf_contact_wrench(ct, xb, w->y, w->vx - s->v_b, w->vy, w->w, s->mu_k_ratio, Fs);
            ref3dof_wrench(o, w->t, y, Fo);
            double e[3] = { hypot(Fs[0] - Fo[0], Fs[1] - Fo[1]) / N, fabs(Fs[2] - Fo[2]) / (N * s->R),
                            fabs(sf_contact_mean_cof(ct, xb, w->y) - ref3dof_mean_cof(o, xb, w->y)) };
            for (int q = 0; q < 3; q++)
                d[q][l] = isnan(d[q][l]) || !isfinite(e[q]) ? NAN : fmax(d[q][l], e[q]);
        }
        sf_contact_free(ct);
        ref3dof_free(o);
    }
    free(h.rows);
    free(st);
    if (rc)
        return rc;
    sf_note(r, "Quadratures on the field, at %zu slip states of the solver's run: solver %zu, %zu, %zu, %zu polar rings; "
               "oracle %zu x %zu Gauss-Legendre x trapezoid nodes, doubled each way per level.\n\n"
               "| quantity | max paired difference at each level | order in cell size |\n|---|---|---|",
            ns, s->cells, s->cells << 1, s->cells << 2, s->cells << 3, oracle_nr(s), 4 * oracle_nr(s));
    sf_plot *p = sf_result_plot(r, "ref_quadrature", "Quadratures on the field: solver's cells vs oracle's nodes",
                                "cell size / the first level's", "max |solver - oracle| over the states");
    sf_plot_log(p, 1, 1);
    for (int q = 0; q < 3; q++) {
        sf_plot_series(p, what[q], SF_STYLE_LINESPOINTS, NL, hs, d[q]);
        double slope = check_loglog_slope(hs, d[q], NL);
        char name[SF_LABEL_LEN];
        snprintf(name, sizeof name, "quadrature, %s: observed order of max |solver - oracle| in the cell size", what[q]);
        sf_check_ge(r, name, ns ? slope : NAN, REF_QUAD_ORDER);
        sf_note(r, "| %s | %.3g, %.3g, %.3g, %.3g | %.2f |", what[q], d[q][0], d[q][1], d[q][2], d[q][3], slope);
    }
    return SF_SUCCESS;
}

/* The smallest transition_margin of a transition compared on a field:
 * at least 1000x the largest relative perturbation either code's error
 * makes in a criterion at the coarsest level (state differences of 1e-6
 * of the stick distance, lambda's of 1e-6 of eps: measured, 1e-7 and
 * below). */
#define REF_WELL_POSED 1e-3

/* The paired difference as both codes refine together, on the same COF:
 * level i runs the solver at rtol_i = rtol (dt_i / dt_0)^4 (its error is
 * proportional to rtol: cases/mms/events) and the oracle's RK4 at dt_i
 * (error ~ dt^4) with 2^i x (cells/2) Gauss-Legendre radii x 4x as many
 * angles (its quadrature error falls ~2^3.2 per doubling where the disc's
 * pole comes inside it near a stick onset).  Both errors then fall at
 * least ~2^3 per level, so the difference d_i = max over the first
 * transitions |solver_i - oracle_i| of each quantity falls at an order
 * of about 3 or more in dt, whatever the two codes' error constants, if
 * and only if they solve the same equations; a difference D in the model
 * (a term, a jump, an event test) is a plateau under which d cannot fall,
 * and the least-squares order over three levels drops below the case's
 * `tolerance` (2.5) once D exceeds about twice the finest level's
 * numerical difference (at a true order of 3.2).  The gate is on that order, not on a
 * multiple of either code's own error.  (A floor, such as the event
 * location's 1e-12 s, can only lower an order: it cannot make a row pass.)
 * Quantities identically equal in both codes (d = 0 at every level, e.g.
 * the post-jump spin) are reported, not fitted.
 *
 * A field: `sweep` holds tolerances, and both codes run on the solver's
 * cells at the scene's `cells` at every level (ref3dof_alloc_nodes), so
 * the discrete wrench and disc average are the same and only the time
 * integration, the events and the jumps differ: the solver at rtol =
 * tol_i, the oracle's RK4 with its own step doubling at tol_i (largest
 * step: the scene's dt).  The wrench on points is only piecewise smooth in
 * the state (kinks where a point crosses a grid line of the bilinear
 * field, jumps where the slip field's pole crosses a point): fixed steps
 * lose their order there (measured: 0.7 to 4 over a 16-fold dt, the error
 * changing sign from one dt to the next), error control does not (the
 * difference falls as tol^0.45 to tol^1.3 over 1e-6 -> 1e-10), so the
 * gate is an order in tol.  Transitions from the first ill-posed one on
 * are not compared (transition_margin, REF_WELL_POSED; each one's margin
 * is reported), and quad_converge adds the quadratures' own convergence. */
static int chk_ref_converge(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    const sf_list *L = &c->spec.sweep;
    size_t K = s0->samples, nl = L->n;
    if (nl < 3 || !(s0->rtol > 0) || !(c->spec.tolerance > 0)) {
        sf_note(r, "ref_converge needs sweep (the oracle's steps, >= 3, coarse first), rtol > 0 and tolerance (the "
                   "minimum order) > 0.");
        return SF_EINVAL;
    }
    sf_cof *cof = check_case_cof(c, s0, r);
    if (!cof)
        return SF_EFAIL;
    size_t nr = oracle_nr(s0), na = 4 * nr;
    int field = sf_cof_get_kind(cof) == SF_COF_FIELD;
    double *S = check_alloc(nl * K * NQ * sizeof(double)), *O = check_alloc(nl * K * NQ * sizeof(double));
    size_t nS[SF_LIST_MAX], nO[SF_LIST_MAX];
    double tK, dts[SF_LIST_MAX], rt[SF_LIST_MAX], *marg = check_alloc(K * sizeof(double));
    int *kinds = check_alloc(nl * K * sizeof(int));
    sf_scene sc = *s0;
    int rc = solver_transitions(&sc, cof, K, S, &nS[0], &tK, r);
    sc.T = fmin(s0->T, tK + 1);   /* the window: 1 s after the first run's K-th transition */
    for (size_t i = 0; !rc && i < nl; i++) {
        sf_scene si = sc, so = sc;
        dts[i] = L->v[i];
        /* a field: sweep holds the tolerances (solver rtol, oracle's step
         * doubling), both codes on the solver's cells at the scene's
         * resolution, the oracle's largest step the scene's dt */
        rt[i] = field ? dts[i] : s0->rtol * pow(dts[i] / dts[0], 4);
        si.rtol = rt[i];
        sf_contact_spec spec = { s0->R, s0->m * s0->g, (sf_layout)s0->layout, s0->cells };
        sf_contact *rule = NULL;
        rc = (field && sf_contact_alloc(&spec, cof, &rule)) ||
             solver_transitions(&si, cof, K, S + i * K * NQ, &nS[i], NULL, r) ||
             oracle_transitions(&so, cof, field ? s0->dt : dts[i], field ? dts[i] : 0, nr << i, na << i, rule, K,
                                O + i * K * NQ, kinds + i * K, &nO[i], i + 1 == nl ? marg : NULL);
        sf_contact_free(rule);
    }
    if (!rc && field)
        rc = quad_converge(&sc, cof, r);
    sf_cof_free(cof);
    /* a field: the transitions compared end before the first ill-posed
     * one (transition_margin below REF_WELL_POSED at the finest oracle
     * run): from there on a transition may appear, vanish or move by more
     * than either code's error, in one run and not another */
    size_t Kw = K;
    if (field && !rc) {
        Kw = nO[nl - 1];
        for (size_t j = 0; j < nO[nl - 1]; j++) {
            sf_note(r, "Transition %zu (%s at %.6g s): margin %.3g%s.", j + 1,
                    kinds[(nl - 1) * K + j] == REF_STICK_ONSET ? "stick onset" : "stick break", O[((nl - 1) * K + j) * NQ],
                    marg[j], marg[j] >= REF_WELL_POSED ? "" : " (ill-posed)");
            if (!(marg[j] >= REF_WELL_POSED) && Kw > j)
                Kw = j;
        }
        if (Kw < K)
            sf_note(r, "**Compared: the %zu transitions before the first ill-posed one** (margin below %g).", Kw,
                    REF_WELL_POSED);
        if (Kw == 0)   /* nothing well posed to compare in this draw: said, not failed */
            sf_note(r, "**The first transition is ill-posed: no dynamics rows for this field** (the quadrature rows "
                       "stand).");
    }
    if (rc || (field && Kw == 0)) {
        free(S);
        free(O);
        free(marg);
        free(kinds);
        return rc ? SF_EFAIL : SF_SUCCESS;
    }
    size_t nmin = Kw;
    for (size_t i = 0; i < nl; i++)
        nmin = sf_min(nmin, sf_min(nS[i], nO[i]));
    int kinds_ok = 1;
    for (size_t i = 0; i < nl; i++)
        for (size_t j = 0; j < nmin; j++)
            kinds_ok &= kinds[i * K + j] == kinds[j];
    char cnt[64];
    snprintf(cnt, sizeof cnt, "%zu of %zu", nmin, Kw);
    sf_check_true(r, "every run (both codes, every level) has the transitions compared", nmin == Kw && Kw > 0, cnt);
    if (field)
        sf_check_true(r, "the oracle's transition kinds agree at every level", kinds_ok, kinds_ok ? "yes" : "no");
    if (field)
        sf_note(r, "Window %g s; %zu transitions. Both codes on the solver's %zu-ring polar cells (the same discrete "
                   "wrench and disc average); level i: solver rtol = tol_i, oracle RK4 with step doubling at tol_i "
                   "(largest step %g s).\n\n| quantity | d at each level (tol, solver rtol) | order in tol |\n|---|---|---|",
                sc.T, nmin, s0->cells, s0->dt);
    else
        sf_note(r, "Window %g s; %zu transitions. Oracle: RK4 at dt, Gauss-Legendre %zu x trapezoid %zu nodes at the "
                   "first level, doubled each way per level; solver: rtol = %g (dt/dt_0)^4.\n\n"
                   "| quantity | d at each level (dt [s], solver rtol) | order |\n|---|---|---|",
                sc.T, nmin, nr, na, s0->rtol);
    free(marg);
    sf_plot *p = sf_result_plot(r, "ref_converge", "Paired difference solver - oracle as both refine",
                                field ? "tolerance (solver rtol, oracle step doubling)"
                                      : "oracle step dt [s] (solver rtol = rtol_0 (dt/dt_0)^4)",
                                "max |solver - oracle|");
    sf_plot_log(p, 1, 1);
    for (int q = 0; q < NQ; q++) {
        double d[SF_LIST_MAX], dmax = 0;
        for (size_t i = 0; i < nl; i++) {
            d[i] = 0;
            for (size_t j = 0; j < nmin; j++) {
                double a = S[(i * K + j) * NQ + q], b = O[(i * K + j) * NQ + q];
                d[i] = isnan(d[i]) || !isfinite(a) || !isfinite(b) ? NAN : fmax(d[i], fabs(a - b));
            }
            dmax = isnan(dmax) || isnan(d[i]) ? NAN : fmax(dmax, d[i]);
        }
        char line[600], name[160];
        int len = 0;
        for (size_t i = 0; i < nl && len >= 0 && (size_t)len < sizeof line; i++)
            len += snprintf(line + len, sizeof line - (size_t)len, "%s%.3g (%g, %g)", i ? ", " : "", d[i], dts[i], rt[i]);
        if (dmax == 0) {   /* identical in both codes at every level */
            sf_note(r, "| %s | 0 at every level | (exact) |", qname[q]);
            continue;
        }
        /* a difference below round-off of the quantity (both codes on the
         * same bits, e.g. a post-jump velocity) counts as round-off (log 0
         * has no order); it cannot make a plateau pass */
        double xs[SF_LIST_MAX], ys[SF_LIST_MAX], mag = 0;
        for (size_t i = 0; i < nl; i++)
            for (size_t j = 0; j < nmin; j++)
                mag = fmax(mag, fabs(S[(i * K + j) * NQ + q]));
        for (size_t i = 0; i < nl; i++) {
            xs[i] = dts[i];
            ys[i] = isnan(d[i]) ? d[i] : fmax(d[i], 4 * DBL_EPSILON * mag);
        }
        double slope = check_loglog_slope(xs, ys, nl);
        snprintf(name, sizeof name, "%s: observed order in %s of max |solver - oracle| (both refined together)", qname[q],
                 field ? "the tolerance" : "dt");
        sf_check_ge(r, name, slope, c->spec.tolerance);
        sf_note(r, "| %s | %s | %.2f |", qname[q], line, slope);
        sf_plot_series(p, qname[q], SF_STYLE_LINESPOINTS, nl, xs, ys);
    }
    free(S);
    free(O);
    free(kinds);
    return SF_SUCCESS;
}

/* ---- The paper's QoIs at the window's edges on a field: solver against
 * the oracle, each with its own window code (solver/dynamics/oscillator.c;
 * verification/oracle/ref3dof.c). */
enum { WQ_STICK, WQ_TSK, WQ_NOSC, WQ_PVX, WQ_PVF, WQ_N };
static const char *wq_name[WQ_N] = { "stick time inside [t_skip, T] [s]", "T_sk [-]", "oscillations",
                                     "PV_x per oscillation [m]", "PV_F per oscillation [N]" };

static int window_solver(const sf_scene *s, const sf_cof *cof, double q[WQ_N], sf_result *r)
{
    sf_osc_result res;
    if (check_osc_run(s, NULL, cof, 0, &res, NULL, NULL, r))
        return SF_EFAIL;
    q[WQ_STICK] = res.stick_time;
    q[WQ_TSK] = res.win_stick_fraction;
    q[WQ_NOSC] = (double)res.nosc;
    q[WQ_PVX] = res.osc_pv_x_mean;
    q[WQ_PVF] = res.osc_pv_F_mean;
    sf_osc_result_free(&res);
    return SF_SUCCESS;
}

static int window_oracle(const sf_scene *s, const sf_cof *cof, double dt, size_t nr, double q[WQ_N])
{
    ref3dof *o;
    ref3dof_result res;
    if (ref3dof_alloc(s, cof, dt, nr, 4 * nr, &o))
        return SF_EFAIL;
    int rc = ref3dof_run(o, 0, &res);
    ref3dof_free(o);
    q[WQ_STICK] = res.stick_time;
    q[WQ_TSK] = res.win_stick_fraction;
    q[WQ_NOSC] = (double)res.nosc;
    q[WQ_PVX] = res.osc_pv_x;
    q[WQ_PVF] = res.osc_pv_F;
    ref3dof_result_free(&res);
    return rc;
}

/* On `samples` fields drawn from the case's stream (a field with fewer
 * than 5 stick phases within the cap is replaced by the next, at most
 * 4 x samples drawn): a coarse solver run
 * over the scene's T (a cap) gives the stick phases [on_j, off_j]; the
 * window starts mid-stick (t_skip = the middle of stick phase 1, the
 * second) and ends mid-stick (T = the middle of stick phase 4) or
 * mid-slip (T = the middle of the slip after stick phase 3: it cuts an
 * oscillation).  Each window is run by the solver (scene: rtol, cells;
 * fine: rtol / 100, 2 cells) and the oracle (RK4 at dt with cells/2 x
 * 2 cells nodes; fine: dt / 2, twice the nodes each way), the fine runs
 * compared: per QoI, `tolerance` x (the solver's coarse-to-fine change +
 * the oracle's) + 1e-9 of the value, as ref_trajectory; the number of
 * oscillations must agree exactly in all four runs. */
static int chk_ref_window_edges(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    char err[256];
    sf_cof_plan *plan;
    if (sf_cof_plan_alloc(s0, &plan, err, sizeof err)) {
        sf_note(r, "**Cannot plan the COF:** %s", err);
        return SF_EFAIL;
    }
    gsl_rng *rng = sf_case_rng(c);
    size_t nr = oracle_nr(s0);
    int rc = SF_SUCCESS;
    sf_note(r, "Solver: rtol %g, %zu rings (coarse) and rtol %g, %zu rings (fine). Oracle: RK4 at dt = %g s, %zu x "
               "%zu nodes (coarse) and %g s, %zu x %zu (fine). Fine runs compared; tolerance %g x (est. solver "
               "error + est. oracle error) + 1e-9 relative.\n",
            s0->rtol, s0->cells, s0->rtol / 100, 2 * s0->cells, s0->dt, nr, 4 * nr, s0->dt / 2, 2 * nr, 8 * nr,
            c->spec.tolerance);
    double *gx = check_alloc(2 * s0->samples * sizeof *gx), *gy = check_alloc(2 * s0->samples * sizeof *gy);
    size_t ng = 0, used = 0, drawn = 0;
    for (size_t k = 0; used < s0->samples && drawn < 4 * s0->samples && !rc; k++) {
        drawn++;
        sf_cof *cof = NULL;
        sf_cof_plan_draw(plan, rng, &cof);
        sf_osc_result cap;
        if (!cof || check_osc_run(s0, NULL, cof, 0, &cap, NULL, NULL, r)) {
            sf_cof_free(cof);
            rc = SF_EFAIL;
            break;
        }
        /* the stick phases: an onset followed by its break */
        double on[5], off[5];
        size_t ns = 0;
        for (size_t i = 0; i + 1 < cap.ntrans && ns < 5; i++)
            if (cap.trans_kind[i] == SF_OSC_STICK_ONSET && cap.trans_kind[i + 1] == SF_OSC_SLIP_ONSET) {
                on[ns] = cap.trans_t[i];
                off[ns++] = cap.trans_t[i + 1];
            }
        sf_osc_result_free(&cap);
        char q[240];
        if (ns < 5) {   /* long slips: too few stick phases for the windows' edges; the next field */
            sf_note(r, "Field %zu: %zu stick phases within the cap T = %g s (5 needed): replaced by the next field.\n", k,
                    ns, s0->T);
            sf_cof_free(cof);
            continue;
        }
        used++;
        struct {
            const char *name;
            double t_skip, T;
        } w[2] = {
            { "t_skip mid-stick 1, T mid-stick 4", 0.5 * (on[1] + off[1]), 0.5 * (on[4] + off[4]) },
            { "t_skip mid-stick 1, T mid-slip after stick 3", 0.5 * (on[1] + off[1]), 0.5 * (off[3] + on[4]) },
        };
        sf_note(r, "Field %zu: stick phases 1-4 (coarse solver run) [%.6f, %.6f], [%.6f, %.6f], [%.6f, %.6f], "
                   "[%.6f, %.6f] s.\n\n| window | QoI | solver (fine) | oracle (fine) | est. error solver | "
                   "est. error oracle | tolerance |\n|---|---|---|---|---|---|---|",
                k, on[1], off[1], on[2], off[2], on[3], off[3], on[4], off[4]);
        for (int iw = 0; iw < 2 && !rc; iw++) {
            sf_scene sc = *s0, sf = *s0;
            sc.t_skip = sf.t_skip = w[iw].t_skip;
            sc.T = sf.T = w[iw].T;
            sf.rtol = s0->rtol / 100;
            sf.cells = 2 * s0->cells;
            double Sc[WQ_N], Sf[WQ_N], Oc[WQ_N], Of[WQ_N];
            if (window_solver(&sc, cof, Sc, r) || window_solver(&sf, cof, Sf, r) ||
                window_oracle(&sc, cof, s0->dt, nr, Oc) || window_oracle(&sc, cof, s0->dt / 2, 2 * nr, Of)) {
                rc = SF_EFAIL;
                break;
            }
            for (int iq = 0; iq < WQ_N; iq++) {
                double eS = fabs(Sf[iq] - Sc[iq]), eO = fabs(Of[iq] - Oc[iq]);
                snprintf(q, sizeof q, "field %zu, %s: %s, solver vs oracle", k, w[iw].name, wq_name[iq]);
                if (iq == WQ_NOSC) {
                    char cnt[96];
                    snprintf(cnt, sizeof cnt, "%g, %g (solver), %g, %g (oracle)", Sc[iq], Sf[iq], Oc[iq], Of[iq]);
                    sf_check_true(r, q, Sc[iq] == Sf[iq] && Sf[iq] == Oc[iq] && Oc[iq] == Of[iq] && Sf[iq] >= 1, cnt);
                    sf_note(r, "| %s | %s | %g | %g | %g | %g | 0 |", w[iw].name, wq_name[iq], Sf[iq], Of[iq], eS, eO);
                    continue;
                }
                double tol = c->spec.tolerance * (eS + eO) + 1e-9 * fabs(Of[iq]);
                sf_check_abs(r, q, Sf[iq], Of[iq], tol);
                sf_note(r, "| %s | %s | %.10g | %.10g | %.3g | %.3g | %.3g |", w[iw].name, wq_name[iq], Sf[iq], Of[iq],
                        eS, eO, tol);
                if (iq == WQ_STICK) {
                    gx[ng] = Of[iq];
                    gy[ng++] = fmax(fabs(Sf[iq] - Of[iq]) / tol, 1e-6);
                }
            }
        }
        sf_cof_free(cof);
    }
    if (!rc) {
        char q[160], found[64];
        snprintf(q, sizeof q, "fields with 5 stick phases within the cap: at least %zu (of at most %zu drawn)",
                 s0->samples, 4 * s0->samples);
        snprintf(found, sizeof found, "%zu of %zu drawn", used, drawn);
        sf_check_true(r, q, used >= s0->samples, found);
    }
    if (!rc && ng) {
        sf_plot *p = sf_result_plot(r, "window_edges_field", "Stick time inside the window: solver vs oracle",
                                    "stick time inside [t_skip, T], oracle [s]", "|solver - oracle| / tolerance [-]");
        sf_plot_log(p, 0, 1);
        sf_plot_series(p, "fields x windows", SF_STYLE_POINTS, ng, gx, gy);
        sf_plot_hline(p, "tolerance", 1);
    }
    free(gx);
    free(gy);
    gsl_rng_free(rng);
    sf_cof_plan_free(plan);
    return rc;
}

const sf_check_def sf_checks_ref3dof[] = {
    { "ref_window_edges", chk_ref_window_edges,
      "independent 3-DOF oracle: the paper's QoIs at windows that start and end inside a stick phase, on fields" },
    { "ref_trajectory", chk_ref_trajectory, "independent 3-DOF oracle: first transitions, trajectory by trajectory" },
    { "ref_converge", chk_ref_converge,
      "independent 3-DOF oracle: the paired difference falls at order 4 as both codes refine together" },
    { "ref_stats", chk_ref_stats, "independent 3-DOF oracle: paired tests on PV_x, PV_F, stick fraction (margin 1%)" },
    { "ref_energy", chk_ref_energy, "work-energy balance with the oracle's wrench along the solver's history" },
    { "ref_eq15", chk_ref_eq15, "Eq. 15 by the solver and by the oracle" },
    { NULL, NULL, NULL },
};
