/* The mean COF, Fig. 13's axis, against independent oracles: the
 * closed-form 1-D cycle on deterministic runs, and the exact long-l/R
 * means over the lognormal (quadrature) on full-field realisations. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "sweep.h"
#include "oscillator.h"
#include "sf_error.h"
#include "montecarlo.h"
#include "cof.h"
#include "claims_engine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_statistics_double.h>

/* ---- The mean COF (Fig. 13's axis, Sec. 3) against independent oracles.
 *
 * Fig. 13 moves the mean static COF at a fixed CV.  What the paper's
 * Sec. 3 rests on for that axis is the 1-D stick-slip cycle of Eqs. 3-4,
 * whose stick duration, slip amplitude and friction range scale with mu:
 * written in closed form from the equations (ref_cycle, checks/common.c;
 * it shares no code with solver/dynamics/cycle1d.c), and checked on the
 * deterministic runs at each mean COF.  The stochastic model has an exact statement about
 * the mean COF in the long-correlation limit: there every realisation is
 * that cycle at its own mu_s, a lognormal with the scene's mean and CV,
 * so the mean of each QoI over realisations is an integral of the closed
 * form against the lognormal density (ref_expect: the oracle's own
 * lognormal parameters, GSL quadrature), known to quadrature precision.
 * The realisations run the full field path (circulant strip, contact
 * quadrature: shortcuts = false), so a defect in the generator's mean or
 * in the stochastic model's kinetic COF moves the sample means away from
 * the exact ones by many standard errors.  (The small-l/R end has no such
 * oracle: the homogenised means carry a bias of a few percent that no
 * closed form gives -- cases/limits/small-lr-homogenisation.) */

/* Run length for a realisation at static COF mu: the first slip from rest
 * (under a quarter period), the first stick to x_s, then two cycles (the
 * first from the stick onset after the slip from rest is not the limit
 * cycle; the next one is), with 25% and 2 s of margin [s]. */
static double mc_run_length(const sf_scene *s, double mu)
{
    ref_cycle1d c;
    if (ref_cycle(s, mu, &c))
        return s->T;
    double t = M_PI / (2 * c.omega) + c.xs / s->v_b + 2 * (c.t_stick + c.t_slip);
    return fmin(s->T, 1.25 * t + 2);
}

#define MC_REL_TOL 1e-4   /* the stick-slip relations inside a realisation (chk_mean_cof) */
enum { MC_MU0, MC_PVX, MC_PVF, MC_TSTK, MC_TSLIP, MC_SF, MC_NCYC, MC_NOUT };

/* The QoIs of the cycles after the first (means), from one run on cof. */
static int mc_run(const sf_scene *s0, const sf_cof *cof, double mu0, double *out)
{
    for (int j = 0; j < MC_NOUT; j++)
        out[j] = NAN;
    out[MC_MU0] = mu0;
    sf_scene s = *s0;
    s.T = mc_run_length(s0, mu0);
    s.t_skip = 0;
    s.history = 0;
    sf_osc *o;
    sf_osc_result res;
    int rc = sf_osc_alloc(&s, cof, &o, NULL, 0);
    if (rc)
        return rc;
    rc = sf_osc_run(o, NULL, NULL, 0, &res, NULL, 0);
    sf_osc_free(o);
    if (rc)
        return rc;
    double a[5] = { 0, 0, 0, 0, 0 };
    size_t m = 0;
    for (size_t i = 1; i < res.ncycles; i++) {   /* cycle 0 starts after the slip from rest */
        a[0] += res.cycle_pv_x[i];
        a[1] += res.cycle_pv_F[i];
        a[2] += res.cycle_stick[i];
        a[3] += res.cycle_period[i] - res.cycle_stick[i];
        a[4] += res.cycle_stick[i] / res.cycle_period[i];
        m++;
    }
    if (m) {
        out[MC_PVX] = a[0] / (double)m;
        out[MC_PVF] = a[1] / (double)m;
        out[MC_TSTK] = a[2] / (double)m;
        out[MC_TSLIP] = a[3] / (double)m;
        out[MC_SF] = a[4] / (double)m;
    }
    out[MC_NCYC] = (double)m;
    sf_osc_result_free(&res);
    return SF_SUCCESS;
}

/* the realisation's COF where the disc starts (belt coordinate 0): sets
 * the run length only; the field barely varies over the strip */
static int mc_run_ws(const claims_ws *w, const sf_cof *cof, double *out)
{
    return mc_run(w->s, cof, sf_cof_eval(cof, 0, 0), out);
}

static int mc_realise(void *p, size_t i, gsl_rng *rng, double *out)
{
    (void)i;
    return claims_ws_realise(p, rng, out, mc_run_ws);
}

/* E[g(mu_s)] and E[g(mu_s)^2] for the QoI q of the cycle at a lognormal
 * mu_s (the oracle's parameters: ref_lognormal_par), by adaptive
 * Gauss-Kronrod quadrature over the standard normal variable z, mu_s =
 * exp(m + s z), on |z| <= 8 (the tail beyond holds 1e-15 of the mass). */
typedef struct { const sf_scene *s; ref_ln_par ln; int q, pw; } mc_qpar;
static double mc_integrand(double z, void *p)
{
    const mc_qpar *a = p;
    ref_cycle1d c;
    if (ref_cycle(a->s, exp(a->ln.mu + a->ln.sigma * z), &c))
        return 0;
    double g = a->q == MC_PVX ? c.pv_x : a->q == MC_PVF ? c.pv_F : a->q == MC_TSTK ? c.t_stick
             : a->q == MC_TSLIP ? c.t_slip : c.sf;
    return (a->pw == 2 ? g * g : g) * exp(-0.5 * z * z) / sqrt(2 * M_PI);
}

static void ref_expect(const sf_scene *s, double mean, double std, int q, double *m1, double *sd)
{
    mc_qpar a = { s, ref_lognormal_par(mean, std), q, 1 };
    gsl_function F = { mc_integrand, &a };
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    double e1, e2, err;
    /* a quadrature that misses its tolerance gives NaN: the rows fail */
    if (gsl_integration_qag(&F, -8, 8, 0, 1e-12, 200, GSL_INTEG_GAUSS61, w, &e1, &err))
        e1 = NAN;
    a.pw = 2;
    if (gsl_integration_qag(&F, -8, 8, 0, 1e-12, 200, GSL_INTEG_GAUSS61, w, &e2, &err))
        e2 = NAN;
    gsl_integration_workspace_free(w);
    *m1 = e1;
    *sd = sqrt(fmax(0, e2 - e1 * e1));
}

static int chk_mean_cof(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    const sf_scene gs0 = check_gen_scene(c);   /* the realisations' generator (a power run's alternative) */
    size_t K = c->spec.sweep.n, n = s0->samples;
    if (!K || K > SF_LIST_MAX || strcmp(c->spec.sweep_param, "mu_mean") || !(s0->mu_mean > 0) || n < 2)
        return SF_EINVAL;
    const double fm = gs0.mu_mean / s0->mu_mean, fs = s0->mu_std > 0 ? gs0.mu_std / s0->mu_std : 1;
    const int NQT = 3;   /* the tested means: PV_x, PV_F, stick fraction (Fig. 13's three panels) */
    const int qt[3] = { MC_PVX, MC_PVF, MC_SF };
    const char *const qn[3] = { "PV_x [m]", "PV_F [N]", "stick fraction [-]" };
    double det_worst[4] = { 0, 0, 0, 0 }, rel_worst[3] = { 0, 0, 0 };
    size_t short_runs = 0, ntests = (size_t)NQT * K;
    double *mean = check_alloc(K * NQT * sizeof *mean), *se = check_alloc(K * NQT * sizeof *se),
           *ex = check_alloc(K * NQT * sizeof *ex), *exsd = check_alloc(K * NQT * sizeof *exsd),
           *detq = check_alloc(K * NQT * sizeof *detq), *pv = check_alloc(K * NQT * sizeof *pv);
    double cv = s0->mu_std / s0->mu_mean, dstk[SF_LIST_MAX], dslp[SF_LIST_MAX];
    {
        sf_cof_plan *pl;
        char e2[256] = "";
        if (sf_cof_plan_alloc(&gs0, &pl, e2, sizeof e2)) {
            sf_note(r, "**Cannot plan the COF:** %s", e2);
            return SF_EFAIL;
        }
        const sf_cof_plan_info *in = sf_cof_plan_get_info(pl);
        sf_note(r, "COF path of the realisations: %s, %zu x %zu points at spacing %.4g m (l/R = %g, (E/l)^2 = %.3g): "
                   "every point of the strip correlates with every other at 1 - %.1g or more, so each realisation is "
                   "one lognormal mu_s to within the relations' tolerance, but it runs the stochastic model's code "
                   "(the strip generator and the contact quadrature).\n", in->kind == SF_COF_FIELD ? "a strip field"
                   : "one random variable (shortcut)", in->nx, in->ny, in->dx, gs0.l / gs0.R,
                in->strip_diag * in->strip_diag / (gs0.l * gs0.l), in->strip_diag * in->strip_diag / (gs0.l * gs0.l));
        sf_check_true(r, "the realisations run the field path (strip generator, contact quadrature), not the shortcut",
                      in->kind == SF_COF_FIELD, in->kind == SF_COF_FIELD ? "field" : "shortcut");
        sf_cof_plan_free(pl);
    }
    sf_note(r, "| mean COF | QoI | closed form at the mean (deterministic run) | exact mean over the lognormal "
               "(std) | sample mean +- standard error (n) | t | p (two-sided) |\n|---|---|---|---|---|---|---|");
    for (size_t k = 0; k < K; k++) {
        double v = c->spec.sweep.v[k];
        char err[256] = "";
        sf_scene sp = *s0, gp = gs0;
        if (sf_sweep_set(&sp, "mu_mean", v, err, sizeof err)) {
            sf_note(r, "**Cannot set mu_mean = %g:** %s", v, err);
            return SF_EFAIL;
        }
        gp.mu_mean = v * fm;
        gp.mu_std = v * cv * fs;
        /* deterministic: uniform COF at the mean, the claims' reference path */
        ref_cycle1d cf;
        if (ref_cycle(&sp, v, &cf)) {
            sf_note(r, "**No stick-slip cycle at mu = %g.**", v);
            return SF_EFAIL;
        }
        sf_scene sd = sp;
        sd.cof = SF_COF_UNIFORM;
        sf_cof *u;
        double det[MC_NOUT];
        int rc = sf_cof_alloc_uniform(v, &u);
        if (!rc)
            rc = mc_run(&sd, u, v, det);
        sf_cof_free(u);
        if (rc) {
            sf_note(r, "**Deterministic run failed at mu = %g:** %s", v, sf_strerror(rc));
            return SF_EFAIL;
        }
        const double dq[4] = { det[MC_PVX] / cf.pv_x, det[MC_PVF] / cf.pv_F, det[MC_TSTK] / cf.t_stick,
                               det[MC_TSLIP] / cf.t_slip };
        dstk[k] = det[MC_TSTK];
        dslp[k] = det[MC_TSLIP];
        for (int j = 0; j < 4; j++)   /* a NaN makes the worst NaN: the row fails */
            det_worst[j] = isnan(det_worst[j]) || isnan(dq[j]) ? NAN : fmax(det_worst[j], fabs(dq[j] - 1));
        /* the realisations */
        double *raw = check_alloc(n * MC_NOUT * sizeof *raw);
        claims_ws ctx = { &gp, 0, 0, NULL };
        sf_mc_spec spec = { n, MC_NOUT, s0->seed + k, 0, NULL, 0, 0, NULL };
        sf_mc_ops ops = { claims_ws_alloc, claims_ws_free, mc_realise };
        if (sf_mc_run(&spec, &ops, &ctx, raw, NULL, err, sizeof err)) {
            sf_note(r, "**Monte Carlo failed at mu = %g:** %s", v, err);
            free(raw);
            return SF_EFAIL;
        }
        double *x = check_alloc(n * sizeof *x);
        for (int j = 0; j < NQT; j++) {
            size_t m = 0;
            for (size_t i = 0; i < n; i++) {
                const double *o = raw + i * MC_NOUT;
                if (j == 0 && !(o[MC_NCYC] >= 1))
                    short_runs++;
                x[m++] = o[qt[j]];   /* NaN stays: the mean is NaN and the row fails */
            }
            size_t ij = k * (size_t)NQT + (size_t)j;
            mean[ij] = gsl_stats_mean(x, 1, m);
            se[ij] = gsl_stats_sd(x, 1, m) / sqrt((double)m);
            ref_expect(&sp, v, v * cv, qt[j], &ex[ij], &exsd[ij]);
            detq[ij] = det[qt[j]];
            double t = (mean[ij] - ex[ij]) / se[ij];
            pv[ij] = isfinite(t) ? 2 * gsl_cdf_tdist_Q(fabs(t), (double)m - 1) : 0;
            sf_note(r, "| %g | %s | %.6g (%.6g) | %.6g (%.4g) | %.6g +- %.3g (%zu) | %.2f | %.3g |", v, qn[j],
                    j == 0 ? cf.pv_x : j == 1 ? cf.pv_F : cf.sf, detq[ij], ex[ij], exsd[ij], mean[ij], se[ij], m, t,
                    pv[ij]);
        }
        /* the stick-slip relations inside each realisation: the friction
         * range from the realisation's own mu_s (Eq. 1's mu_k enters
         * here), then, free of mu_s, the amplitude and the slip duration
         * from d = PV_F / (2 k).  (Not the stick duration: the solver's
         * PV_F is k times the stick distance, so stick = PV_F / (k v_b)
         * holds by construction.) */
        for (size_t i = 0; i < n; i++) {
            const double *o = raw + i * MC_NOUT;
            double d = o[MC_PVF] / (2 * sp.k), w = cf.omega, vr = cf.vr;
            double e[3] = { o[MC_PVF] / (2 * (1 - sp.mu_k_ratio) * o[MC_MU0] * sp.m * sp.g) - 1,
                            o[MC_PVX] / (2 * sqrt(d * d + (vr / w) * (vr / w))) - 1,
                            o[MC_TSLIP] / ((M_PI + 2 * atan2(vr, w * d)) / w) - 1 };
            for (int j = 0; j < 3; j++)
                rel_worst[j] = isnan(rel_worst[j]) || isnan(e[j]) ? NAN : fmax(rel_worst[j], fabs(e[j]));
        }
        free(x);
        free(raw);
    }
    /* rows */
    sf_check_le(r, "deterministic runs: max |PV_x / closed form - 1| over the mean COFs", det_worst[0], c->spec.tolerance);
    sf_check_le(r, "deterministic runs: max |PV_F / closed form - 1|", det_worst[1], c->spec.tolerance);
    sf_check_le(r, "deterministic runs: max |stick duration / closed form - 1|", det_worst[2], c->spec.tolerance);
    sf_check_le(r, "deterministic runs: max |slip duration / closed form - 1|", det_worst[3], c->spec.tolerance);
    sf_check_le(r, "realisations without a limit cycle (one after the first) in their run", (double)short_runs, 0);
    /* MC_REL_TOL: the realisations' field is not exactly constant: at l =
     * 5e5 m its relative change along the belt the disc sees in a run (<=
     * 25 m) is about sigma_g sqrt(2) h / l ~ 1e-5 and the cycle amplifies
     * a change of mu by 1 / (1 - mu_k/mu_s) = 10 in d; measured 8e-6 at
     * most over 1200 realisations, and 7e-4 at l = 5e3 m (linear in 1 / l:
     * the field's gradient, not the solver) */
    const double rel_tol = MC_REL_TOL;
    sf_check_le(r, "every realisation: max |PV_F / (2 (1 - mu_k/mu_s) mu_s m g) - 1|, mu_s its COF", rel_worst[0],
                rel_tol);
    sf_check_le(r, "every realisation: max |PV_x / 2 sqrt((PV_F/2k)^2 + (v_r/omega)^2) - 1|", rel_worst[1], rel_tol);
    sf_check_le(r, "every realisation: max |slip duration / (pi + 2 atan(v_r / (omega d)))/omega - 1|, d = PV_F/2k",
                rel_worst[2], rel_tol);
    for (size_t k = 0; k < K; k++)
        for (int j = 0; j < NQT; j++) {
            size_t ij = k * (size_t)NQT + (size_t)j;
            char t[200];
            snprintf(t, sizeof t, "mean COF %g: mean %s = its exact lognormal mean %.5g (two-sided t, Bonferroni x%zu)",
                     c->spec.sweep.v[k], qn[j], ex[ij], ntests);
            sf_check_pvalue(r, t, sf_min(1, (double)ntests * pv[ij]), c->spec.alpha, n);
        }
    /* plots: the means against the exact curves (as ratios to the cycle at
     * the mean COF, Fig. 13's scale), and the deterministic durations */
    {
        enum { NG = 41 };
        double lo = c->spec.sweep.v[0], hi = c->spec.sweep.v[0];
        for (size_t k = 1; k < K; k++) {
            lo = fmin(lo, c->spec.sweep.v[k]);
            hi = fmax(hi, c->spec.sweep.v[k]);
        }
        lo *= 0.8;
        hi *= 1.05;
        double g[NG], ey[NG], e2[NG], xk[SF_LIST_MAX], yk[SF_LIST_MAX], bl[SF_LIST_MAX], bh[SF_LIST_MAX];
        double zq = gsl_cdf_ugaussian_Qinv(0.5 * c->spec.alpha / (double)ntests);
        char ttl[160];
        snprintf(ttl, sizeof ttl, "Mean COF (Fig. 13 axis) at l/R = %g: means over realisations vs exact", s0->l / s0->R);
        sf_plot *p = sf_result_plot(r, "mean_cof_means", ttl,
                                    "mean static COF [-]", "mean QoI / QoI of the cycle at the mean COF [-]");
        for (int j = 0; j < NQT; j++) {
            for (int i = 0; i < NG; i++) {
                g[i] = lo + (hi - lo) * i / (NG - 1);
                sf_scene t = *s0;
                ref_cycle1d cc;
                double sd;
                ref_expect(&t, g[i], g[i] * cv, qt[j], &ey[i], &sd);
                ref_cycle(&t, g[i], &cc);
                ey[i] /= j == 0 ? cc.pv_x : j == 1 ? cc.pv_F : cc.sf;
            }
            for (size_t k = 0; k < K; k++) {
                size_t ij = k * (size_t)NQT + (size_t)j;
                ref_cycle1d cc;
                ref_cycle(s0, c->spec.sweep.v[k], &cc);
                double den = j == 0 ? cc.pv_x : j == 1 ? cc.pv_F : cc.sf;
                xk[k] = c->spec.sweep.v[k];
                yk[k] = mean[ij] / den;
                bl[k] = (mean[ij] - zq * se[ij]) / den;
                bh[k] = (mean[ij] + zq * se[ij]) / den;
            }
            char lb[96];
            snprintf(lb, sizeof lb, "%s: exact mean (lognormal mu_s)", qn[j]);
            sf_plot_series(p, lb, SF_STYLE_LINES, NG, g, ey);
            snprintf(lb, sizeof lb, "%s: sample mean, Bonferroni CI", qn[j]);
            sf_plot_band(p, lb, K, xk, bl, bh);
            snprintf(lb, sizeof lb, "%s: sample mean", qn[j]);
            sf_plot_series(p, lb, SF_STYLE_POINTS, K, xk, yk);
        }
        sf_plot_hline(p, "1 (the cycle at the mean COF)", 1);
        p = sf_result_plot(r, "mean_cof_det", "Deterministic cycle vs mean COF: closed form (lines) and runs (points)",
                           "static COF [-]", "duration per cycle [s]");
        for (int i = 0; i < NG; i++) {
            ref_cycle1d cc;
            g[i] = lo + (hi - lo) * i / (NG - 1);
            ref_cycle(s0, g[i], &cc);
            ey[i] = cc.t_stick;
            e2[i] = cc.t_slip;
        }
        sf_plot_series(p, "stick 2 d / v_b (closed form)", SF_STYLE_DASHED, NG, g, ey);
        sf_plot_series(p, "slip (pi + 2 atan(v_r / omega d)) / omega (closed form)", SF_STYLE_DASHED, NG, g, e2);
        sf_plot_series(p, "stick (deterministic runs)", SF_STYLE_POINTS, K, c->spec.sweep.v, dstk);
        sf_plot_series(p, "slip (deterministic runs)", SF_STYLE_POINTS, K, c->spec.sweep.v, dslp);
    }
    free(mean); free(se); free(ex); free(exsd); free(detq); free(pv);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_mean_cof[] = {
    { "val_mean_cof", chk_mean_cof, "Fig. 13's mean-COF axis: closed-form cycle and exact long-l/R means (lognormal)" },
    { NULL, NULL, NULL }
};
