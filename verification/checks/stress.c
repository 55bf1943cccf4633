/* Numerical stress: the solver at extreme parameters.  Each check states
 * what must hold there (finite results, physical bounds, a documented
 * decision, or a clear refusal with its reason) and checks exactly that. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "contact.h"
#include "cof.h"
#include "field.h"
#include "sf_error.h"
#include "oscillator.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_math.h>
#include <stdio.h>

/* "v_b [m/s]": the axis label of a swept scene key, unit from the key table */
static void sweep_label(const char *key, char *buf, size_t n)
{
    const char *u = sf_scene_key_unit(key);
    snprintf(buf, n, "%s [%s]", key, !u || !*u || !strcmp(u, "1") ? "dimensionless" : u);
}

/* log x when the values are positive and span more than a decade */
static int spans_decades(size_t n, const double *v)
{
    double lo = INFINITY, hi = 0;
    for (size_t i = 0; i < n; i++) {
        if (!(v[i] > 0))
            return 0;
        lo = fmin(lo, v[i]);
        hi = fmax(hi, v[i]);
    }
    return n > 1 && hi > 10 * lo;
}

/* The COF plan over l/R from the sweep: each l either plans a strip field
 * whose draws are finite and positive, takes the one-variable shortcut
 * (documented threshold), or is refused with SF_ETOOBIG and a reason; never
 * anything else. */
static int chk_cof_plan_range(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, bad = 0, refused = 0, shortcut = 0, fields = 0;
    if (!K)
        return SF_EINVAL;
    gsl_rng *rng = sf_case_rng(c);
    sf_note(r, "| l/R | decision | grid | smallest COF drawn |\n|---|---|---|---|");
    /* for the plot: (l/R, smallest COF drawn) per decision: 0 field,
     * 1 shortcut, 2 refused (x at [2K d + i], y at [2K d + K + i]) */
    double *pd = check_alloc(6 * K * sizeof *pd);
    size_t nd[3] = { 0, 0, 0 };
#define PUSH(d, xv, yv) (pd[2 * K * (d) + nd[d]] = (xv), pd[2 * K * (d) + K + nd[d]] = (yv), nd[d]++)
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        s.l = c->spec.sweep.v[k] * s0->R;
        char err[256] = "";
        sf_cof_plan *p;
        int rc = sf_cof_plan_alloc(&s, &p, err, sizeof err);
        if (rc == SF_ETOOBIG) {
            refused++;
            int has_reason = strstr(err, "grid points") && strstr(err, "raise l");
            bad += !has_reason;
            sf_note(r, "| %g | refused: %s | | |", c->spec.sweep.v[k], err);
            PUSH(2, c->spec.sweep.v[k], 0);
            continue;
        }
        if (rc) {
            bad++;
            sf_note(r, "| %g | **error %s** | | |", c->spec.sweep.v[k], sf_strerror(rc));
            continue;
        }
        const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
        sf_cof *cof;
        double mn = INFINITY;
        rc = sf_cof_plan_draw(p, rng, &cof);
        if (rc) {
            bad++;
        } else {
            /* probe the strip densely along its centre line and edges; a
             * tiled window is made to follow the probe (over the first
             * 1 m of belt: the whole 20 m would cost seconds at l = 5 mm,
             * and cases/dynamics/tiles-small-l covers the sliding) */
            int tiled = in->kind == SF_COF_FIELD && in->generator == SF_COFGEN_TILES;
            double reach = tiled ? fmin(s.v_b * s.T, 1.0) : s.v_b * s.T;
            for (int q = 0; q <= 2000; q++) {
                double xb = -reach * q / 2000.0;
                if (tiled && sf_cof_follow(cof, xb - 1e-3, xb + 1e-3))
                    bad++;
                for (int e = -1; e <= 1; e++) {
                    double v = sf_cof_eval(cof, xb, e * 0.5 * s.R);
                    if (!(v > 0) || !isfinite(v))
                        bad++;
                    mn = sf_min(mn, v);
                }
            }
            bad += sf_cof_outside(cof) != 0;
            sf_cof_free(cof);
        }
        if (in->shortcut)
            shortcut++;
        else
            fields++;
        PUSH(in->shortcut ? 1 : 0, c->spec.sweep.v[k], mn);
        sf_note(r, "| %g | %s | %zu x %zu | %.4g |", c->spec.sweep.v[k],
                in->shortcut ? "one random variable"
                : in->generator == SF_COFGEN_TILES ? "strip field, tiles in a sliding window"
                                                   : "strip field (circulant)",
                in->nx, in->ny, mn);
        sf_cof_plan_free(p);
    }
    sf_check_le(r, "cases that neither planned, took the shortcut, nor refused with a reason; or drew a bad COF",
                (double)bad, 0);
    sf_check_true(r, "the sweep exercises all three decisions (field, shortcut, refusal)",
                  fields && shortcut && refused, fields && shortcut && refused ? "all three seen" : "one is missing");
    sf_plot *pl = sf_result_plot(r, "cof_plan_range", "COF plan over l/R: decision and smallest COF drawn",
                                 "correlation length l/R [dimensionless]", "smallest COF drawn [dimensionless]");
    sf_plot_log(pl, spans_decades(K, c->spec.sweep.v), 0);
    const char *lab[3] = { "strip field", "one random variable (shortcut)", "refused with a reason (no draw; shown at 0)" };
    for (int d = 0; d < 3; d++)
        if (nd[d])
            sf_plot_series(pl, lab[d], SF_STYLE_POINTS, nd[d], pd + 2 * K * d, pd + 2 * K * d + K);
#undef PUSH
    sf_plot_hline(pl, "COF = 0 (a draw must stay above)", 0);
    free(pd);
    gsl_rng_free(rng);
    return SF_SUCCESS;
}

/* Circulant embedding on grids where the squared-exponential covariance
 * matrix is near-singular (l/dx up to 1e3): padding either reaches a PSD
 * embedding (round-off clamps only) or reports truncation with its exact
 * covariance error; samples stay finite with unit variance scale. */
static int chk_near_singular(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, bad = 0;
    if (!K)
        return SF_EINVAL;
    gsl_rng *rng = sf_case_rng(c);
    double worst_err_untruncated = 0;
    sf_note(r, "| l/dx | embedding | truncated | clamped | covariance error | max abs sample |\n|---|---|---|---|---|---|");
    /* for the plot: (l/dx, covariance error), untruncated (0) and truncated (1):
     * x at [2K d + i], y at [2K d + K + i] */
    double *pe = check_alloc(4 * K * sizeof *pe);
    size_t ne[2] = { 0, 0 };
    for (size_t k = 0; k < K; k++) {
        sf_field_spec spec;
        sf_field_spec_default(&spec, s0->nx, s0->ny, s0->dx, s0->dy, c->spec.sweep.v[k] * s0->dx);
        sf_field *f;
        int rc = sf_field_alloc(&spec, &f);
        if (!sf_usable(rc)) {
            sf_note(r, "| %g | refused: %s | | | | |", c->spec.sweep.v[k], sf_strerror(rc));
            bad += rc != SF_ETOOBIG;   /* too large an embedding is a fair refusal */
            continue;
        }
        const sf_field_info *in = sf_field_get_info(f);
        size_t n = s0->nx * s0->ny;
        double *g = check_alloc(n * sizeof *g), mx = 0;
        for (int q = 0; q < 4; q++) {
            sf_field_sample(f, rng, g);
            for (size_t i = 0; i < n; i++) {
                if (!isfinite(g[i]))
                    bad++;
                mx = sf_max(mx, fabs(g[i]));
            }
        }
        if ((rc == SF_ETRUNC) != in->truncated || !isfinite(in->cov_error))
            bad++;
        if (!in->truncated)
            worst_err_untruncated = sf_max(worst_err_untruncated, in->cov_error);
        /* floored at 1e-17 so that an exact 0 shows on the log axis */
        {
            int d = in->truncated != 0;
            pe[2 * K * d + ne[d]] = c->spec.sweep.v[k];
            pe[2 * K * d + K + ne[d]] = isnan(in->cov_error) ? NAN : fmax(in->cov_error, 1e-17);
            ne[d]++;
        }
        sf_note(r, "| %g | %zu x %zu | %s | %zu | %.3e | %.3g |", c->spec.sweep.v[k], in->px, in->py,
                in->truncated ? "yes" : "no", in->n_clamped, in->cov_error, mx);
        bad += mx > 8;   /* |N(0,1)| > 8 has probability 1e-15 per value */
        free(g);
        sf_field_free(f);
    }
    sf_check_le(r, "non-finite samples, wrong truncation flag, or |sample| > 8", (double)bad, 0);
    sf_check_le(r, "covariance error of the untruncated embeddings (round-off clamps only)",
                worst_err_untruncated, c->spec.tolerance);
    sf_plot *pl = sf_result_plot(r, "near_singular", "Circulant embedding: covariance error against l/dx",
                                 "correlation length l/dx [dimensionless]",
                                 "max covariance error (floored at 1e-17) [dimensionless]");
    sf_plot_log(pl, spans_decades(K, c->spec.sweep.v), 1);
    if (ne[0])
        sf_plot_series(pl, "PSD embedding (round-off clamps only)", SF_STYLE_POINTS, ne[0], pe, pe + K);
    if (ne[1])
        sf_plot_series(pl, "truncated (error reported)", SF_STYLE_POINTS, ne[1], pe + 2 * K, pe + 3 * K);
    sf_plot_hline(pl, "tolerance (untruncated)", c->spec.tolerance);
    free(pe);
    gsl_rng_free(rng);
    return SF_SUCCESS;
}

/* The friction wrench at extreme motions and COFs: finite, |F| <= mu N,
 * |T| <= mu N R, force against the centre slip for pure translation,
 * torque against the spin for pure spin, with the exact magnitudes mu N
 * and (2/3) mu N R there (polar layout) (for combined motions the minor
 * component is below the round-off of the major one, so its sign is not
 * defined to check); Contensou forms finite and
 * within [0, 1] x [0, 2/3] over eps from 1e-300 to 1e300. */
static int chk_wrench_extremes(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    double mus[4] = { 0, 1e-300, 1e-12, 1e3 };
    double vel[7] = { 0, 1e-300, 1e-150, 1e-8, 1, 1e8, 1e150 };
    size_t bad = 0, tried = 0;
    /* for the plot (COF 1e3): |F|/(mu N) in pure translation and
       |T|/(mu N R) in pure spin against the speed (slip, or w R) */
    double spd[6] = { 0 }, fpl[6] = { 0 }, tpl[6] = { 0 };
    for (int a = 0; a < 4; a++) {
        sf_cof *cof;
        sf_cof_alloc_uniform(mus[a], &cof);
        sf_contact_spec spec = { s->R, s->m * s->g, (sf_layout)s->layout, s->cells };
        sf_contact *ct;
        if (sf_contact_alloc(&spec, cof, &ct)) {
            sf_cof_free(cof);
            return SF_EFAIL;
        }
        double N = s->m * s->g, bound = mus[a] * N * (1 + 1e-12);
        for (int i = 0; i < 7; i++)
            for (int j = 0; j < 7; j++)
                for (int sg = 0; sg < 4; sg++) {
                    double u = (sg & 1 ? -1 : 1) * vel[i], w = (sg & 2 ? -1 : 1) * vel[j] / s->R, q[3];
                    int rc = sf_contact_wrench(ct, 0, 0, u, 0, w, 1.0, q);
                    tried++;
                    if (a == 3 && sg == 0 && (i == 0) != (j == 0)) {
                        int m = (i ? i : j) - 1;
                        spd[m] = vel[i ? i : j];
                        if (i)
                            fpl[m] = hypot(q[0], q[1]) / (mus[a] * N);
                        else
                            tpl[m] = fabs(q[2]) / (mus[a] * N * s->R);
                    }
                    if (rc || !isfinite(q[0]) || !isfinite(q[1]) || !isfinite(q[2]) ||
                        hypot(q[0], q[1]) > bound || fabs(q[2]) > bound * s->R ||
                        (w == 0 && q[0] * u > 0) || (u == 0 && q[2] * w > 0) ||
                        (w == 0 && u != 0 && fabs(hypot(q[0], q[1]) - mus[a] * N) > 1e-12 * mus[a] * N) ||
                        (u == 0 && w != 0 && s->layout == SF_LAYOUT_POLAR &&
                         fabs(fabs(q[2]) - 2.0 / 3.0 * mus[a] * N * s->R) > 1e-12 * mus[a] * N * s->R))
                        bad++;
                }
        sf_contact_free(ct);
        sf_cof_free(cof);
    }
    double pf = -1, pt = 1, pe[60], pfe[60], pte[60];
    size_t ne = 0;
    for (double e = 1e-300; e < 1e300; e *= 1e10) {
        double f, t;
        sf_contensou(e, &f, &t);
        tried++;
        if (ne < 60) {
            pe[ne] = e;
            pfe[ne] = f;
            pte[ne++] = t;
        }
        const double ro = 1e-14;   /* round-off slack, relative */
        if (!isfinite(f) || !isfinite(t) || f < 0 || f > 1 + ro || t < 0 || t > 2.0 / 3.0 * (1 + ro) ||
            f < pf * (1 - ro) || t > pt * (1 + ro))
            bad++;
        pf = f;
        pt = t;
    }
    sf_check_le(r, "wrench or closed-form evaluations that broke a bound or were not finite", (double)bad, 0);
    sf_note(r, "%zu evaluations: COF in {0, 1e-300, 1e-12, 1e3}, slip and spin speeds from 1e-300 to 1e150 "
               "(both signs), eps from 1e-300 to 1e300. hypot() keeps subnormal slip speeds from "
               "underflowing to a zero direction.", tried);
    sf_plot *pl = sf_result_plot(r, "contensou_extremes", "Contensou closed forms over eps = 1e-300 .. 1e300",
                                 "eps = U / (|w| R) [dimensionless]", "f = |F|/(mu N), t = |T|/(mu N R) [dimensionless]");
    sf_plot_log(pl, 1, 0);
    sf_plot_series(pl, "f (force)", SF_STYLE_LINESPOINTS, ne, pe, pfe);
    sf_plot_series(pl, "t (torque)", SF_STYLE_LINESPOINTS, ne, pe, pte);
    sf_plot_hline(pl, "bound of f: 1", 1);
    sf_plot_hline(pl, "bound of t: 2/3", 2.0 / 3.0);
    pl = sf_result_plot(r, "wrench_extremes", "Wrench at COF 1e3: pure translation and pure spin",
                        "slip speed |u|, or |w| R [m/s]", "|F|/(mu N), |T|/(mu N R) [dimensionless]");
    sf_plot_log(pl, 1, 0);
    sf_plot_series(pl, "|F|/(mu N), pure translation (exact: 1)", SF_STYLE_POINTS, 6, spd, fpl);
    sf_plot_series(pl, "|T|/(mu N R), pure spin (polar exact: 2/3)", SF_STYLE_POINTS, 6, spd, tpl);
    return SF_SUCCESS;
}


/* A run at extreme parameters (optionally over a sweep of one): it must
 * finish (SF_SUCCESS) with finite states, |x| and |y| within the
 * spring-excursion bound 2 mu_hi m g / k, and the energy balance to the
 * tolerance (relative to the energy turned over).  A scene that sets
 * max_steps may instead be stopped by it (SF_EMAXITER) where a quadrature
 * cell holds the centre of rotation (the solver names the cell): the run
 * up to its stop must then be finite, bounded and balanced the same way;
 * a stop that no held cell explains fails. */
static int chk_run(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = *c->spec.sweep_param ? c->spec.sweep.n : 1;
    size_t bad = 0, held = 0;
    double worst_e = 0;
    int budget = sf_scene_was_set(s0, "max_steps"), drawn = 0;   /* drawn: the one run's transitions plot */
    /* for the plot: the stressed value, the energy residual and the
       excursion over its bound */
    double *pv = check_alloc(3 * K * sizeof *pv), *pe = pv + K, *px = pv + 2 * K;
    /* the table's rows, noted after the runs (a run's own note, e.g. why it
       stopped, would split the table) */
    enum { ROW = 320 };
    char *rows = check_alloc(K * ROW);
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        if (*c->spec.sweep_param && sf_sweep_set(&s, c->spec.sweep_param, c->spec.sweep.v[k], err, sizeof err)) {
            free(pv);
            free(rows);
            return SF_EINVAL;
        }
        gsl_rng *rng = sf_case_rng(c);
        sf_osc_result res;
        int rc = check_osc_run(&s, rng, NULL, 0, &res, NULL, NULL, r);
        gsl_rng_free(rng);
        double bound = 2 * (s.mu_mean + 4 * s.mu_std) * s.m * s.g / s.k;
        double e = fabs(res.energy_residual) / sf_max(fabs(res.friction_work) + fabs(res.energy_change), 1e-300);
        /* stopped by the scene's budget where a cell holds the centre of rotation */
        int stop = budget && rc == SF_EMAXITER && res.held_cell >= 0 && res.held_slip < SF_OSC_HELD_SLIP;
        int done = rc == SF_SUCCESS || stop;
        held += stop;
        int ok = done && isfinite(res.x_min) && isfinite(res.x_max) &&
                 sf_max(fabs(res.x_min), fabs(res.x_max)) <= bound && res.y_absmax <= bound && e <= c->spec.tolerance;
        bad += !ok;
        worst_e = sf_max(worst_e, done ? e : INFINITY);
        pv[k] = *c->spec.sweep_param ? c->spec.sweep.v[k] : 1.0;
        pe[k] = done ? fmax(e, 1e-17) : NAN;
        px[k] = done ? fmax(fmax(fabs(res.x_min), fabs(res.x_max)), res.y_absmax) / bound : NAN;
        if (K == 1 && done && res.ntrans) {   /* a run stopped early may have none to draw */
            drawn = 1;
            /* one run: its stick-slip transitions against the bound */
            sf_plot *pt = sf_result_plot(r, "transitions", "Stick-slip transitions of the run, within the bound",
                                         "time t [s]", "x at a transition [m]");
            sf_plot_series(pt, "x at a stick-slip transition", SF_STYLE_POINTS, res.ntrans, res.trans_t, res.trans_x);
            sf_plot_hline(pt, "+2 mu_hi m g / k", bound);
            sf_plot_hline(pt, "-2 mu_hi m g / k", -bound);
        }
        snprintf(rows + k * ROW, ROW, "| %g | %s | %zu | %zu | %.4g | [%.4g, %.4g] | %.3g | %.2e | %lu |",
                *c->spec.sweep_param ? c->spec.sweep.v[k] : 0.0,
                stop ? (ok ? "ok, stopped by max_steps at a held cell" : "**out of bounds** (stopped at a held cell)")
                     : rc ? sf_strerror(rc) : (ok ? "ok" : "**out of bounds**"),
                res.ntrans, res.ncycles, res.stick_fraction, res.x_min, res.x_max, res.y_absmax, e, res.steps);
        sf_osc_result_free(&res);
    }
    sf_note(r, "| %s | result | transitions | cycles | stick fraction | x range [m] | max abs y [m] | energy residual (rel.) | steps |\n"
               "|---|---|---|---|---|---|---|---|---|", *c->spec.sweep_param ? c->spec.sweep_param : "run");
    for (size_t k = 0; k < K; k++)
        sf_note(r, "%s", rows + k * ROW);
    free(rows);
    sf_check_le(r, "runs that failed, went non-finite, left the bound 2 mu_hi m g / k, or broke the energy balance",
                (double)bad, 0);
    sf_check_le(r, "worst relative energy residual", worst_e, c->spec.tolerance);
    sf_keytab kt = sf_case_spec_keytab(&c->spec);
    if (sf_keys_was_set(&kt, "held_stops"))
        sf_check_abs(r, "runs the step budget stopped at a cell holding the centre of rotation", (double)held,
                     (double)c->spec.held_stops, 0);
    else if (budget)
        sf_note(r, "%zu of %zu runs stopped by max_steps = %zu at a cell holding the centre of rotation.", held, K,
                s0->max_steps);
    char xl[64];
    if (*c->spec.sweep_param)
        sweep_label(c->spec.sweep_param, xl, sizeof xl);
    else
        snprintf(xl, sizeof xl, "run [index]");
    sf_plot *pl = drawn ? NULL
                        : sf_result_plot(r, "stress_run", "Energy balance and excursion at the stressed parameter",
                                         xl, "ratio [dimensionless]");
    if (pl) {
        sf_plot_log(pl, spans_decades(K, pv), 1);
        sf_plot_series(pl, "relative energy residual (floored at 1e-17)", SF_STYLE_LINESPOINTS, K, pv, pe);
        sf_plot_series(pl, "max(|x|, |y|) / (2 mu_hi m g / k)", SF_STYLE_LINESPOINTS, K, pv, px);
        sf_plot_hline(pl, "energy tolerance", c->spec.tolerance);
        sf_plot_hline(pl, "excursion bound", 1);
    }
    free(pv);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_stress[] = {
    { "stress_run", chk_run, "runs at extreme parameters: finish, finite, bounded, energy balance" },
    { "stress_cof_plan_range", chk_cof_plan_range, "COF plan over l/R 1e-3..1e4: field, shortcut or a clear refusal" },
    { "stress_near_singular", chk_near_singular, "embedding of near-singular covariances: PSD or reported truncation" },
    { "stress_wrench_extremes", chk_wrench_extremes, "wrench and closed forms finite and bounded at extremes" },
    { NULL, NULL, NULL }
};
