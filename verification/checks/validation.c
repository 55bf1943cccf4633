/* The paper's findings (Sections 3-4) as validation cases: each sweeps a
 * parameter with Monte Carlo, plots our result beside the paper's
 * statement, and checks the statement (or the exact fact behind it).
 * Where we differ from the paper, the report says so.  (Fig. 13's mean-COF
 * axis against its exact oracles is in mean_cof.c.) */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "sweep.h"
#include "unum.h"
#include "oscillator.h"
#include "qoi.h"
#include "sf_error.h"
#include "cof.h"
#include "claims_engine.h"

#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_statistics_double.h>

typedef struct {
    size_t K;
    double *v;
    sf_sweep_point *pt;
} sweep_run;

/* The counts of a sweep point's ratio statistics, for results.json. */
static void sweep_samples(sf_result *r, const char *param, double v, const sf_sweep_point *p)
{
    static const char *const nm[SF_SWEEP_NQ] = { "PV_x ratio", "PV_F ratio", "stick-fraction ratio" };
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        char what[SF_LABEL_LEN];
        snprintf(what, sizeof what, "%s = %g: %s", *param ? param : "point", v, nm[q]);
        sf_result_sample(r, what, p->rstat[q].n_used, p->rstat[q].n_excluded);
    }
}

static int run_sweep(const sf_case *c, sf_result *r, sweep_run *sw)
{
    const sf_scene *s0 = &c->scene;
    sw->K = c->spec.sweep.n;
    if (!sw->K || !*c->spec.sweep_param)
        return SF_EINVAL;
    sw->v = check_alloc(sw->K * sizeof *sw->v);
    sw->pt = check_alloc(sw->K * sizeof *sw->pt);
    for (size_t k = 0; k < sw->K; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        sw->v[k] = c->spec.sweep.v[k];
        if (sf_sweep_set(&s, c->spec.sweep_param, sw->v[k], err, sizeof err) ||
            sf_sweep_run(&s, s0->samples, 0, NULL, 0, NULL, &sw->pt[k], err, sizeof err)) {
            sf_note(r, "**Sweep failed at %s = %g:** %s", c->spec.sweep_param, sw->v[k], err);
            return SF_EFAIL;
        }
        /* the numerical error of the means, as `sweep --summary` and `--diagnostics` make it
         * (a companion that fails leaves it unestimated, as there) */
        if (sf_unum_sweep(&s, &sw->pt[k], 0, err, sizeof err))
            sf_note(r, "(%s = %g: no numerical error of the means: %s)", c->spec.sweep_param, sw->v[k], err);
    }
    sf_note(r, "| %s | det PV_x [m] | det PV_F [N] | det stick fr. | PV_x ratio | PV_F ratio | stick-fr. ratio | "
               "used / excluded |\n|---|---|---|---|---|---|---|---|", c->spec.sweep_param);
    for (size_t k = 0; k < sw->K; k++) {
        const sf_sweep_point *p = &sw->pt[k];
        sf_note(r, "| %g | %.4f | %.4f | %.4f | %.4f +- %.4f (se %.4f) | %.4f +- %.4f (se %.4f) | %.4f +- %.4f (se %.4f) "
                   "| %zu/%zu, %zu/%zu, %zu/%zu |", sw->v[k], p->det[0], p->det[1], p->det[2], p->mean[0], p->std[0],
                p->rstat[0].se, p->mean[1], p->std[1], p->rstat[1].se, p->mean[2], p->std[2], p->rstat[2].se,
                p->rstat[0].n_used, p->rstat[0].n_excluded, p->rstat[1].n_used, p->rstat[1].n_excluded,
                p->rstat[2].n_used, p->rstat[2].n_excluded);
        sweep_samples(r, c->spec.sweep_param, sw->v[k], p);
        check_sweep_record(r, c->spec.sweep_param, sw->v[k], p);
    }
    sf_note(r, "\n(mean +- std and the standard error of the mean, each over the finite values of its QoI: used / "
               "excluded of %zu realisations, for PV_x, PV_F and the stick fraction in turn; T = %g s, t_skip = %g "
               "s, from rest at the origin; the scene's QoI definitions (qoi_def, default the paper's: T_sk = stick "
               "time in [t_skip, T] / (T - t_skip), PV per oscillation); ratios to the deterministic model at the "
               "same parameters, window and definitions. A value the definition cannot form is excluded, never "
               "averaged.)\n", s0->samples, s0->T, s0->t_skip);
    return SF_SUCCESS;
}

static void sweep_free(sweep_run *sw)
{
    for (size_t k = 0; k < sw->K; k++)
        sf_sweep_point_free(&sw->pt[k]);
    free(sw->pt);
    free(sw->v);
}

/* The three ratios vs the parameter: the means with their Monte Carlo
 * intervals (error bars) and numerical errors (bands), the PV_F spread */
static void plot_ratios(sf_result *r, const sweep_run *sw, const char *stem, const char *title, const char *xl, int logx)
{
    const char *nm[3] = { "PV_x ratio", "PV_F ratio", "stick-fraction ratio" };
    sf_plot *p = sf_result_plot(r, stem, title, xl, "ratio to the deterministic model [-]");
    sf_plot_log(p, logx, 0);
    check_plot_sweep_bands(p, sw->K, sw->v, sw->pt);
    double *m = check_alloc(sw->K * sizeof *m), *lo = check_alloc(sw->K * sizeof *lo), *hi = check_alloc(sw->K * sizeof *hi);
    for (int q = 0; q < 3; q++) {
        for (size_t k = 0; k < sw->K; k++) {
            m[k] = sw->pt[k].mean[q];
            lo[k] = m[k] - sw->pt[k].std[q];
            hi[k] = m[k] + sw->pt[k].std[q];
        }
        char lb[64];
        snprintf(lb, sizeof lb, "%s +- 1 std", nm[q]);
        if (q == 1)
            sf_plot_band(p, lb, sw->K, sw->v, lo, hi);
        snprintf(lb, sizeof lb, "%s, mean", nm[q]);
        sf_plot_series(p, lb, SF_STYLE_LINES, sw->K, sw->v, m);
    }
    sf_plot_hline(p, "1 (deterministic)", 1);
    free(m); free(lo); free(hi);
}

/* Fig. 10: convergence in the number of realisations.  The running mean of
 * the PV_x ratio settles; its 95% confidence half-width at N is within the
 * tolerance, and the running means stay inside the band around the final
 * one that the CLT predicts (checked at N/4, N/2). */
static int chk_fig10(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_sweep_point pt;
    char err[256] = "";
    if (sf_sweep_run(s, s->samples, 0, NULL, 0, NULL, &pt, err, sizeof err)) {
        sf_note(r, "**Sweep failed:** %s", err);
        return SF_EFAIL;
    }
    sweep_samples(r, "l_over_R", s->l / s->R, &pt);
    check_sweep_record(r, "l_over_R", s->l / s->R, &pt);   /* (no u_num: its running mean is the point) */
    size_t n = 0;
    for (size_t i = 0; i < pt.n; i++)   /* keep the realisations with a cycle, in order */
        if (isfinite(pt.ratio[3 * i]))
            pt.ratio[3 * n++] = pt.ratio[3 * i];
    double *nn = check_alloc(n * sizeof *nn), *rm = check_alloc(n * sizeof *rm), *lo = check_alloc(n * sizeof *lo), *hi = check_alloc(n * sizeof *hi);
    double sum = 0;
    for (size_t i = 0; i < n; i++) {
        sum += pt.ratio[3 * i];
        nn[i] = (double)(i + 1);
        rm[i] = sum / nn[i];
        double h = 1.96 * pt.std[0] / sqrt(nn[i]);
        lo[i] = pt.mean[0] - h;
        hi[i] = pt.mean[0] + h;
    }
    double half = 1.96 * pt.std[0] / sqrt((double)n);
    sf_check_le(r, "95% confidence half-width of the mean PV_x ratio at N", half, c->spec.tolerance);
    sf_note(r, "Mean PV_x ratio %.4f, std %.4f over %zu realisations (l/R = %g). The paper (Fig. 10) finds the mean "
               "settled beyond 100 realisations; here the half-width at N is %.4f and the running mean enters the "
               "CLT band early. The band is around the final mean (not an independent truth), so it shows the "
               "settling, not a bias. %zu of %zu realisations had a whole oscillation in [t_skip, T].", pt.mean[0], pt.std[0],
            n, s->l / s->R, half, n, pt.n);
    sf_plot *p = sf_result_plot(r, "fig10", "Convergence in realisations (Fig. 10)", "realisations N [-]",
                                "running mean of PV_x ratio [-]");
    sf_plot_band(p, "final mean +- 1.96 std / sqrt(N)", n, nn, lo, hi);
    sf_plot_series(p, "running mean", SF_STYLE_LINES, n, nn, rm);
    free(nn); free(rm); free(lo); free(hi);
    sf_sweep_point_free(&pt);
    return SF_SUCCESS;
}

/* Fig. 11: ratios vs l/R.  Paper: the spread peaks for l/R near 1 and
 * stabilises for l/R > 100 with a PV_F std near 0.2.  Exact behind it: at
 * large l/R the PV_F ratio is mu_s/mean, std = CV (chi-square test). */
static int chk_fig11(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    sweep_run sw = { 0 };
    if (run_sweep(c, r, &sw))
        return SF_EFAIL;
    size_t K = sw.K, kmax = 0;
    for (size_t k = 1; k < K; k++)
        if (!(sw.pt[k].std[1] <= sw.pt[kmax].std[1]) && !isnan(sw.pt[kmax].std[1]))   /* a NaN spread is the peak: it fails downstream */
            kmax = k;
    double cv = s0->mu_std / s0->mu_mean, s2 = sw.pt[K - 1].std[1] * sw.pt[K - 1].std[1];
    sf_check_pvalue(r, "largest l/R: var of the PV_F ratio = CV^2 (chi-square, mean estimated)",
                    sf_var_pvalue(s2, cv * cv, sw.pt[K - 1].rstat[1].n_used, 0), c->spec.alpha,
                    sw.pt[K - 1].rstat[1].n_used);
    sf_check_true(r, "the PV_F spread peaks at l/R between 0.3 and 10 (the paper: near 1)",
                  sw.v[kmax] >= 0.3 && sw.v[kmax] <= 10, "peak location in range");
    sf_note(r, "Peak of the PV_F spread at l/R = %g (std %.3f); at l/R = %g the std is %.3f (exact limit: CV = %g). "
               "The paper reports the same peak near l/R = 1 and a std near 0.2 beyond l/R = 100. Our mean ratios "
               "at the peak are above 1 (cycles on a field whose scale matches the disc are longer and wider; some "
               "stick phases are skipped when the stick wrench is not admissible as the slip slows): see the table.",
            sw.v[kmax], sw.pt[kmax].std[1], sw.v[K - 1], sw.pt[K - 1].std[1], cv);
    plot_ratios(r, &sw, "fig11", "QoI ratios vs correlation length (Fig. 11)", "l/R [-]", 1);
    sweep_free(&sw);
    return SF_SUCCESS;
}

/* Fig. 12: stick fraction vs v_b.  Paper: it falls with v_b, more steeply
 * for the stochastic model than the deterministic one. */
static int chk_fig12(const sf_case *c, sf_result *r)
{
    sweep_run sw = { 0 };
    if (run_sweep(c, r, &sw))
        return SF_EFAIL;
    size_t K = sw.K;
    double *lx = check_alloc(K * sizeof *lx), *ld = check_alloc(K * sizeof *ld), *ls = check_alloc(K * sizeof *ls);
    int mono = 1;
    for (size_t k = 0; k < K; k++) {
        lx[k] = log(sw.v[k]);
        ld[k] = log(sw.pt[k].det[2]);
        ls[k] = log(sw.pt[k].det[2] * sw.pt[k].mean[2]);
        if (k && !(sw.pt[k].det[2] < sw.pt[k - 1].det[2]))
            mono = 0;
    }
    /* weighted fit of the stochastic slope: weights from the standard
       error of log(mean stick fraction) at each point */
    double *w = check_alloc(K * sizeof *w);
    for (size_t k = 0; k < K; k++) {
        double se = sw.pt[k].rstat[2].se / sw.pt[k].mean[2];
        w[k] = 1 / (se * se);
    }
    double c0, bd, bs, a, b, cc, ss;
    gsl_fit_linear(lx, 1, ld, 1, K, &c0, &bd, &a, &b, &cc, &ss);
    gsl_fit_wlinear(lx, 1, w, 1, ls, 1, K, &c0, &bs, &a, &b, &cc, &ss);
    double E = bs - bd, u = sqrt(cc);
    free(w);
    sf_check_true(r, "deterministic stick fraction falls with v_b (closed form: t_stick = 2 d / v_b)", mono,
                  mono ? "monotone" : "not monotone");
    sf_check_le(r, "u_val: standard error of the stochastic slope (the comparison must be resolved)", u, c->spec.tolerance);
    int agree = E + 2 * u < 0, contra = E - 2 * u > 0;
    sf_note(r, "Slopes of log stick fraction vs log v_b: deterministic %.3f (exact), stochastic %.3f +- %.3f (1 "
               "standard error). Comparison with the paper (stochastic steeper, E = slope difference < 0): "
               "E = %.3f, u_val = %.3f. **Finding:** %s", bd, bs, u, E, u,
            agree ? "agrees (E < 0 beyond 2 u_val)."
                  : contra ? "differs: the stochastic stick fraction falls *less* steeply than the deterministic one "
                             "beyond 2 u_val in our model (T_sk over [t_skip, T], the paper's Sec. 3.1)."
                           : "not resolved: |E| < 2 u_val, so our runs neither confirm nor contradict the paper's "
                             "steeper stochastic fall at this sample size.");
    sf_plot *p = sf_result_plot(r, "fig12", "Stick fraction vs belt speed (Fig. 12)", "v_b [m/s]", "stick fraction [-]");
    sf_plot_log(p, 1, 1);
    double *d = check_alloc(K * sizeof *d), *st = check_alloc(K * sizeof *st);
    for (size_t k = 0; k < K; k++) {
        d[k] = sw.pt[k].det[2];
        st[k] = sw.pt[k].det[2] * sw.pt[k].mean[2];
    }
    sf_plot_series(p, "deterministic", SF_STYLE_LINESPOINTS, K, sw.v, d);
    sf_plot_series(p, "stochastic (mean over realisations)", SF_STYLE_LINESPOINTS, K, sw.v, st);
    free(d); free(st); free(lx); free(ld); free(ls);
    plot_ratios(r, &sw, "fig12_ratios", "QoI ratios vs belt speed", "v_b [m/s]", 1);
    sweep_free(&sw);
    return SF_SUCCESS;
}

/* Fig. 13: ratios vs the mean COF at fixed CV.  Paper: they approach 1 as
 * the mean COF grows. */
static int chk_fig13(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    sweep_run sw = { 0 };
    if (run_sweep(c, r, &sw))
        return SF_EFAIL;
    size_t K = sw.K;
    double d0 = fabs(sw.pt[0].mean[1] - 1), d1 = fabs(sw.pt[K - 1].mean[1] - 1);
    double se0 = sw.pt[0].rstat[1].se, se1 = sw.pt[K - 1].rstat[1].se;
    double z = (d0 - d1) / hypot(se0, se1);
    size_t valid = SIZE_MAX;
    for (size_t k = 0; k < K; k++)
        valid = valid < sw.pt[k].n_valid ? valid : sw.pt[k].n_valid;
    sf_check_ge(r, "fewest realisations with a PV formed at any mean COF", (double)valid, 0.8 * (double)s0->samples);
    sf_check_le(r, "u_val: standard error of the difference of |mean - 1| (the comparison must be resolved)",
                hypot(se0, se1), c->spec.tolerance);
    double p1 = 1 - gsl_cdf_ugaussian_P(z), p2 = gsl_cdf_ugaussian_P(z);
    sf_note(r, "|mean PV_F ratio - 1|: %.4f at mean COF %g, %.4f at %g; E = difference = %.4f, u_val = %.4f "
               "(z = %.2f). **Finding:** %s", d0, sw.v[0], d1, sw.v[K - 1], d0 - d1, hypot(se0, se1), z,
            p1 < c->spec.alpha ? "agrees with the paper: the ratios approach 1 as the mean COF grows."
            : p2 < c->spec.alpha
                ? "differs from the paper: in our model the PV_F ratio moves *away* from 1 as the mean COF grows at "
                  "fixed CV. A likely cause is the QoI definition: our PV_F is the peak-to-valley of Fx over the "
                  "whole cycle, slip included; a larger COF means longer slip paths over the field, whose friction "
                  "fluctuates, and the extreme values over a longer path grow. The paper does not define its "
                  "Delta F precisely enough to tell."
                : "not resolved at this sample size.");
    plot_ratios(r, &sw, "fig13", "QoI ratios vs mean COF at fixed CV (Fig. 13)", "mean static COF [-]", 0);
    sweep_free(&sw);
    return SF_SUCCESS;
}


/* x samples after t_skip of one run (sample_dt), their periodogram. */
typedef struct { size_t n; double *f, *p, var; } spectrum;

static int spectrum_of(const sf_scene *s, gsl_rng *rng, double dt, double window_period, spectrum *sp, double *period,
                       sf_result *r)
{
    sf_osc_result res;
    if (check_osc_run(s, rng, NULL, dt, &res, NULL, NULL, r))
        return SF_EFAIL;
    size_t i0 = (size_t)ceil(s->t_skip / dt), n = res.nsamples - i0;
    double wp = window_period > 0 ? window_period : res.period;
    if (wp > 0) {   /* a whole number of (deterministic) periods: no leakage for a periodic signal */
        double cycles = floor((double)n * dt / wp);
        if (cycles >= 1)
            n = (size_t)llround(cycles * wp / dt);
    }
    sp->n = n / 2 + 1;
    sp->f = check_alloc(sp->n * sizeof(double));
    sp->p = check_alloc(sp->n * sizeof(double));
    double m = 0, v = 0;
    for (size_t i = 0; i < n; i++)
        m += res.x_samples[i0 + i];
    m /= (double)n;
    for (size_t i = 0; i < n; i++)
        v += (res.x_samples[i0 + i] - m) * (res.x_samples[i0 + i] - m);
    sp->var = v / (double)n;
    sf_periodogram(res.x_samples + i0, n, dt, sp->f, sp->p);
    if (period)
        *period = res.period;
    sf_osc_result_free(&res);
    return SF_SUCCESS;
}

/* share of the power within +-2 bins of the harmonics k / period */
static double harmonic_share(const spectrum *sp, double period)
{
    double df = sp->f[1] - sp->f[0], tot = 0, in = 0;
    for (size_t k = 1; k < sp->n; k++) {
        tot += sp->p[k];
        double h = sp->f[k] * period, d = fabs(h - round(h)) / period;
        if (round(h) >= 1 && d <= 2 * df)
            in += sp->p[k];
    }
    return tot > 0 ? in / tot : NAN;
}

/* Fig. 15: spectra of x for several l/R against the deterministic
 * harmonics.  Exact: the deterministic response is periodic, so its power
 * sits at the harmonics k / period; every periodogram obeys Parseval. */
static int chk_fig15(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K)
        return SF_EINVAL;
    const double dt = 0.01;
    sf_scene sd = *s0;
    sd.cof = SF_COF_UNIFORM;
    spectrum det;
    double period;
    if (spectrum_of(&sd, NULL, dt, 0, &det, &period, r))
        return SF_EFAIL;
    double share_det = harmonic_share(&det, period), parseval = 0;
    double df = det.f[1] - det.f[0], sum = 0;
    for (size_t k = 0; k < det.n; k++)
        sum += det.p[k] * df;
    parseval = sf_max(parseval, fabs(sum / det.var - 1));
    sf_plot *p = sf_result_plot(r, "fig15", "Spectra of x (Fig. 15)", "frequency [Hz]", "power spectral density [m^2/Hz]");
    sf_plot_log(p, 0, 1);
    size_t nplot = 0;
    while (nplot < det.n && det.f[nplot] <= 2.0)
        nplot++;
    for (size_t k = 0; k < nplot; k++)
        det.p[k] = sf_max(det.p[k], 1e-16);
    sf_plot_series(p, "deterministic", SF_STYLE_LINES, nplot, det.f, det.p);
    sf_note(r, "Deterministic period %.5f s (fundamental %.4f Hz); share of its power within 2 bins of the "
               "harmonics: %.5f.", period, 1 / period, share_det);
    sf_note(r, "\n| l/R | share of power at the deterministic harmonics | Parseval residual |\n|---|---|---|");
    gsl_rng *rng = sf_case_rng(c);
    for (size_t j = 0; j < K; j++) {
        sf_scene s = *s0;
        char err[128];
        sf_sweep_set(&s, "l_over_R", c->spec.sweep.v[j], err, sizeof err);
        spectrum sp;
        if (spectrum_of(&s, rng, dt, period, &sp, NULL, r)) {
            gsl_rng_free(rng);
            return SF_EFAIL;
        }
        double sm = 0, d2 = sp.f[1] - sp.f[0];
        for (size_t k = 0; k < sp.n; k++)
            sm += sp.p[k] * d2;
        double pr = fabs(sm / sp.var - 1);
        parseval = sf_max(parseval, pr);
        sf_note(r, "| %g | %.4f | %.1e |", c->spec.sweep.v[j], harmonic_share(&sp, period), pr);
        for (size_t k = 0; k < nplot && k < sp.n; k++)
            sp.p[k] = sf_max(sp.p[k], 1e-16);
        char lb[64];
        snprintf(lb, sizeof lb, "stochastic, l/R = %g", c->spec.sweep.v[j]);
        sf_plot_series(p, lb, SF_STYLE_LINES, nplot < sp.n ? nplot : sp.n, sp.f, sp.p);
        free(sp.f);
        free(sp.p);
    }
    gsl_rng_free(rng);
    sf_check_ge(r, "deterministic: share of the power at the harmonics k / period (periodic response)", share_det,
                1 - c->spec.tolerance);
    sf_check_le(r, "Parseval: |sum p df / var(x) - 1| over all spectra", parseval, 1e-12);
    sf_note(r, "\nOne realisation per l/R, T = %g s, samples every %g s after t_skip = %g s. The paper's Fig. 15 "
               "shows the stochastic spectra keeping the deterministic harmonics with broadened, shifted peaks, "
               "most at l/R near 1; the share column quantifies that here (a finding, not gated).\n",
            s0->T, dt, s0->t_skip);
    free(det.f);
    free(det.p);
    return SF_SUCCESS;
}

/* Fig. 16: bifurcation diagrams, x at every slip-to-stick instant after
 * t_skip against a parameter.  Exact: the deterministic model sticks
 * always at x_e - d (closed form, eps-corrected arcs end there too). */
static int chk_fig16(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param)
        return SF_EINVAL;
    gsl_rng *rng = sf_case_rng(c);
    double worst = 0, *px = check_alloc(4096 * sizeof *px), *py = check_alloc(4096 * sizeof *py);
    double *dx = check_alloc(K * sizeof *dx), *dy = check_alloc(K * sizeof *dy);
    size_t np = 0;
    sf_note(r, "| %s | samples | min x [m] | max x [m] | deterministic x_e - d [m] |\n|---|---|---|---|---|", c->spec.sweep_param);
    for (size_t j = 0; j < K; j++) {
        sf_scene s = *s0, sd;
        char err[128];
        sf_sweep_set(&s, c->spec.sweep_param, c->spec.sweep.v[j], err, sizeof err);
        sd = s;
        sd.cof = SF_COF_UNIFORM;
        ref_cycle1d cf;   /* the checks' own closed form (common.h), not solver/dynamics/cycle1d.c */
        sf_osc_result rs, rd;
        if (ref_cycle(&sd, sd.mu_mean, &cf) || check_osc_run(&sd, NULL, NULL, 0, &rd, NULL, NULL, r) ||
            check_osc_run(&s, rng, NULL, 0, &rs, NULL, NULL, r)) {
            gsl_rng_free(rng);
            return SF_EFAIL;
        }
        double xc = cf.xe - cf.d, mn = INFINITY, mx = -INFINITY;
        for (size_t i = 0; i < rd.nbif; i++)
            worst = sf_max(worst, fabs(rd.bif[i] - xc));
        for (size_t i = 0; i < rs.nbif && np < 4096; i++) {
            px[np] = c->spec.sweep.v[j];
            py[np++] = rs.bif[i];
            mn = sf_min(mn, rs.bif[i]);
            mx = sf_max(mx, rs.bif[i]);
        }
        dx[j] = c->spec.sweep.v[j];
        dy[j] = xc;
        sf_note(r, "| %g | %zu | %.4f | %.4f | %.6f |", c->spec.sweep.v[j], rs.nbif, mn, mx, xc);
        sf_osc_result_free(&rs);
        sf_osc_result_free(&rd);
    }
    gsl_rng_free(rng);
    sf_check_le(r, "deterministic: max |x at slip-to-stick - (x_e - d)| over all values [m]", worst, c->spec.tolerance);
    sf_note(r, "\nOne stochastic realisation per value (T = %g s). The paper's Fig. 16 shows the stochastic "
               "slip-to-stick positions scattered around the deterministic branch, most widely at l/R near 1; the "
               "table gives our spread (a finding, not gated).\n", s0->T);
    int logx = !strcmp(c->spec.sweep_param, "l_over_R");
    sf_plot *p = sf_result_plot(r, "fig16", "Bifurcation diagram: x at slip-to-stick (Fig. 16)", c->spec.sweep_param,
                                "x at slip-to-stick [m]");
    sf_plot_log(p, logx, 0);
    sf_plot_series(p, "stochastic (one realisation per value)", SF_STYLE_POINTS, np, px, py);
    sf_plot_series(p, "deterministic x_e - d", SF_STYLE_LINESPOINTS, K, dx, dy);
    free(px); free(py); free(dx); free(dy);
    return SF_SUCCESS;
}

/* ==================================================================
 * The paper's claims as gated one-sided tests: the claims are data
 * (claims_paper.c), the sweep and the verdicts the engine
 * (claims_engine.c); these checks pick a table and add what is particular
 * to a figure.
 * ================================================================== */

/* ---- Figs. 10, 11, 16(a): the correlation length */
static int chk_claims_lr(const sf_case *c, sf_result *r)
{
    cpoint *pt;
    size_t K;
    if (claims_sweep(c, r, claims_lr, "fig11", "l/R [-]", 1, &pt, &K))
        return SF_EFAIL;
    /* the exact limit behind fig11-large-std-F: with one COF per
     * realisation (l/R large enough for the plan's one-variable shortcut)
     * the PV_F ratio is mu_s / mean, a lognormal with the COF's CV, so its
     * log is normal with variance sigma_g^2 = ln(1 + CV^2): chi-square on
     * the variance of log(ratio), exact.  (The variance of the ratio
     * itself against CV^2 assumed normal data: a lognormal's kurtosis
     * makes that test reject about 4 times too often at 1e-3, and fresh
     * seeds showed it, with the T = 20 s window that dropped the largest
     * mu_s: 4 failures in 20 runs.) */
    const sf_scene *s = &c->scene;
    const cpoint *L = &pt[K - 1];
    double cv = s->mu_std / s->mu_mean, sg2 = log1p(cv * cv);
    if (L->val * s->R >= 1e4) {
        double *lg = check_alloc(L->n * sizeof *lg);
        size_t m = 0;
        for (size_t i = 0; i < L->n; i++) {
            double x = L->raw[i * NOUT + D_OURS * NQ + Q_PVF];
            if (isfinite(x))
                lg[m++] = log(x);   /* a non-positive ratio gives NaN: the row fails */
        }
        double s2 = m > 1 ? gsl_stats_variance(lg, 1, m) : NAN;
        free(lg);
        sf_check_pvalue(r, "l/R at the one-variable limit: var of log(PV_F ratio) = ln(1 + CV^2) (chi-square, two-sided)",
                        sf_var_pvalue(s2, sg2, m, 0), c->spec.alpha, m);
        sf_check_ge(r, "l/R at the one-variable limit: realisations with a PV_F formed (a lost one is a large mu_s)",
                    (double)m, (double)L->n);
        sf_note(r, "At l/R = %g (one COF value per realisation) the std of the PV_F ratio is %.4f against the exact "
                   "CV = %g; the std of its log %.4f against sigma_g = %.4f.", L->val, L->sd[D_OURS][Q_PVF], cv,
                sqrt(s2), sqrt(sg2));
    }
    /* Fig. 10: running mean of the PV_x ratio at l/R = 1 */
    int k1 = claims_pick(pt, K, "=1");
    if (k1 >= 0) {
        const cpoint *P = &pt[k1];
        double *nn = check_alloc(P->n * sizeof *nn), *rm = check_alloc(P->n * sizeof *rm),
               *lo = check_alloc(P->n * sizeof *lo), *hi = check_alloc(P->n * sizeof *hi);
        double sum = 0;
        size_t m = 0;
        for (size_t i = 0; i < P->n; i++) {
            double v = P->raw[i * NOUT + Q_PVX];
            if (!isfinite(v))
                continue;
            sum += v;
            nn[m] = (double)(m + 1);
            rm[m] = sum / nn[m];
            double h = 1.96 * P->sd[D_OURS][Q_PVX] / sqrt(nn[m]);
            lo[m] = P->mean[D_OURS][Q_PVX] - h;
            hi[m] = P->mean[D_OURS][Q_PVX] + h;
            m++;
        }
        sf_plot *p = sf_result_plot(r, "fig10", "Fig. 10: running mean of the PV_x ratio at l/R = 1",
                                    "realisations N [-]", "running mean of PV_x ratio [-]");
        sf_plot_band(p, "final mean +- 1.96 std / sqrt(N)", m, nn, lo, hi);
        sf_plot_series(p, "running mean", SF_STYLE_LINES, m, nn, rm);
        free(nn); free(rm); free(lo); free(hi);
    }
    claims_free(pt, K);
    return SF_SUCCESS;
}

/* ---- Figs. 12, 16(b): the belt speed */
static int chk_claims_vb(const sf_case *c, sf_result *r)
{
    cpoint *pt;
    size_t K;
    if (claims_sweep(c, r, claims_vb, "fig12", "v_b [m/s]", 0, &pt, &K))
        return SF_EFAIL;
    claims_free(pt, K);
    return SF_SUCCESS;
}

/* ---- Figs. 13, 16(c): the mean COF at fixed CV */
static int chk_claims_mu(const sf_case *c, sf_result *r)
{
    cpoint *pt;
    size_t K;
    if (claims_sweep(c, r, claims_mu, "fig13", "mean static COF [-]", 0, &pt, &K))
        return SF_EFAIL;
    claims_free(pt, K);
    return SF_SUCCESS;
}

/* ---- Fig. 15: spectra; Fig. 3: the fields themselves.  Claims judged
 * with the same verdict rule (claims_judge_one) from per-realisation
 * statistics. */

/* Realisations from .. to-1 of the harmonic share at l/R = lr into sh
 * (sh[i]), drawn from rng in order; realisation 0's spectrum drawn into
 * p (nplot bins; p may be NULL). */
static int fig15_shares(const sf_scene *s0, double lr, gsl_rng *rng, double dt, double period, double *sh, size_t from,
                        size_t to, sf_plot *p, size_t nplot, sf_result *r)
{
    sf_scene s = *s0;
    char err[128];
    sf_sweep_set(&s, "l_over_R", lr, err, sizeof err);
    for (size_t i = from; i < to; i++) {
        spectrum sp;
        if (spectrum_of(&s, rng, dt, period, &sp, NULL, r))
            return SF_EFAIL;
        sh[i] = harmonic_share(&sp, period);
        if (i == 0 && p) {
            for (size_t k = 0; k < nplot && k < sp.n; k++)
                sp.p[k] = fmax(sp.p[k], 1e-16);
            char lb[64];
            snprintf(lb, sizeof lb, "stochastic, l/R = %g", lr);
            sf_plot_series(p, lb, SF_STYLE_LINES, nplot < sp.n ? nplot : sp.n, sp.f, sp.p);
        }
        free(sp.f);
        free(sp.p);
    }
    return SF_SUCCESS;
}

/* Fig. 15's claims' verdicts about the model (docs/design.md sec. 7.7):
 * the sequential design of claims_sequential_decide on the shares sh (K
 * = 3 points of N each), every point extended from rng (continuing the
 * stream after the paper-scale draws, so the first N are those) at the
 * looks its open claims need, up to the case's model_budget. */
static int fig15_model(const sf_case *c, sf_result *r, gsl_rng *rng, double dt, double period, const double *sh,
                       size_t N, double share_det)
{
    size_t Nl[CLAIMS_MAX_LOOKS], L = claims_model_looks(N, c->spec.model_budget, Nl), B = Nl[L - 1];
    double alpha = claims_alpha(c, claims_fig15) * (double)(c->spec.looks ? c->spec.looks : 1);
    double *x = check_alloc(3 * B * sizeof *x), est[3][CLAIMS_MAX_LOOKS], se[3][CLAIMS_MAX_LOOKS],
           df[3][CLAIMS_MAX_LOOKS], lo[3], hi[3];
    size_t n[3] = { N, N, N }, lk[3] = { 0, 0, 0 };
    int st[3] = { SF_CLAIM_UNDECIDED, SF_CLAIM_UNDECIDED, SF_CLAIM_UNDECIDED };
    const int pa[3] = { 1, 2, 0 }, pb[3] = { 0, 1, -1 };   /* the claims' points: a minus b (b < 0: the deterministic share) */
    for (int j = 0; j < 3; j++)
        memcpy(x + (size_t)j * B, sh + (size_t)j * N, N * sizeof *x);
    for (size_t l = 0; l < L; l++) {
        int need[3] = { 0, 0, 0 };
        for (int q = 0; q < 3; q++)
            if (st[q] == SF_CLAIM_UNDECIDED) {
                need[pa[q]] = 1;
                if (pb[q] >= 0)
                    need[pb[q]] = 1;
            }
        for (int j = 0; j < 3; j++)
            if (need[j] && n[j] < Nl[l]) {
                if (fig15_shares(&c->scene, c->spec.sweep.v[j], rng, dt, period, x + (size_t)j * B, n[j], Nl[l], NULL,
                                 0, r)) {
                    free(x);
                    return SF_EFAIL;
                }
                n[j] = Nl[l];
            }
        double m[3], v[3];
        for (int j = 0; j < 3; j++) {
            m[j] = gsl_stats_mean(x + (size_t)j * B, 1, n[j]);
            v[j] = gsl_stats_variance_m(x + (size_t)j * B, 1, n[j], m[j]) / (double)n[j];
        }
        for (int q = 0; q < 3; q++) {
            if (st[q] != SF_CLAIM_UNDECIDED)
                continue;
            int a = pa[q], b = pb[q];
            double vb = b >= 0 ? v[b] : 0, na = (double)n[a], nb = b >= 0 ? (double)n[b] : 1;
            est[q][l] = m[a] - (b >= 0 ? m[b] : share_det);
            se[q][l] = sqrt(v[a] + vb);
            df[q][l] = b >= 0 ? (v[a] + vb) * (v[a] + vb) / (v[a] * v[a] / (na - 1) + vb * vb / (nb - 1)) : na - 1;
            lk[q] = l;
            st[q] = claims_sequential_decide(&claims_fig15[q], Nl, L, l + 1, est[q], se[q], df[q], alpha,
                                             claims_margin_of(&claims_fig15[q], 1), 0, CLAIMS_SPEND_POCOCK, NULL,
                                             &lo[q], &hi[q]);
        }
    }
    free(x);
    sf_note(r, "\n### Verdicts about the model\n\nThe sequential design of docs/design.md sec. 7.7 (claims_engine.c): "
               "looks at N = %zu doubling to the budget %zu realisations per l/R (each extending the last from the "
               "case's stream), the model verdict's own alpha %.3g spent over the %zu looks (Pocock-type Lan-DeMets "
               "spending, union bound), the margin %.3g of the share. Reported, not gated.\n\n| claim | model verdict "
               "| N it took | estimate [bounds] | MDE at that N |\n|---|---|---|---|---|",
            N, B, alpha, L, claims_margin_of(&claims_fig15[0], 1));
    for (int q = 0; q < 3; q++) {
        size_t l = lk[q];
        double al = claims_look_alpha(alpha, Nl, L, l, CLAIMS_SPEND_POCOCK);
        sf_claim_model mv = { st[q], Nl[l], B, est[q][l], lo[q], hi[q], claims_mde(se[q][l], al, 0), alpha,
                              claims_margin_of(&claims_fig15[q], 1) };
        sf_claim_set_model(r, claims_fig15[q].id, &mv);
        sf_note(r, "| %s | %s | %zu | %.4g [%.4g, %.4g] | %.3g |", claims_fig15[q].id, sf_claim_model_name(st[q]),
                Nl[l], mv.est, mv.lo, mv.hi, mv.mde);
    }
    return SF_SUCCESS;
}

static int chk_claims_fig15(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, N = s0->samples;
    if (K != 3)
        return SF_EINVAL;   /* l/R = 0.1, 1, 10 as in the paper */
    const double dt = 0.01;
    sf_scene sd = *s0;
    sd.cof = SF_COF_UNIFORM;
    spectrum det;
    double period;
    if (spectrum_of(&sd, NULL, dt, 0, &det, &period, r))
        return SF_EFAIL;
    double share_det = harmonic_share(&det, period);
    sf_check_ge(r, "deterministic: share of the power at the harmonics k / period (periodic response)", share_det,
                1 - c->spec.tolerance);
    sf_plot *p = sf_result_plot(r, "fig15", "Fig. 15: spectra of x (realisation 0 per l/R)", "frequency [Hz]",
                                "power spectral density [m^2/Hz]");
    sf_plot_log(p, 0, 1);
    size_t nplot = 0;
    while (nplot < det.n && det.f[nplot] <= 2.0)
        nplot++;
    double *sh = check_alloc(K * N * sizeof *sh), m[3], sdv[3];
    sf_sweep_stat st[3];
    gsl_rng *rng = sf_case_rng(c);
    for (size_t j = 0; j < K; j++) {
        if (fig15_shares(s0, c->spec.sweep.v[j], rng, dt, period, sh + j * N, 0, N, p, nplot, r)) {
            gsl_rng_free(rng);
            free(sh);
            return SF_EFAIL;
        }
        /* mean, std, se and interval as every sweep states them */
        if (sf_sweep_stat_of(sh + j * N, 1, N, &st[j])) {
            gsl_rng_free(rng);
            free(sh);
            return SF_EFAIL;
        }
        m[j] = st[j].mean;
        sdv[j] = st[j].std;
    }
    for (size_t k = 0; k < nplot; k++)
        det.p[k] = fmax(det.p[k], 1e-16);
    sf_plot_series(p, "deterministic", SF_STYLE_DASHED, nplot, det.f, det.p);
    free(det.f);
    free(det.p);
    sf_note(r, "Deterministic period %.4f s; its share of power at the harmonics %.4f.\n\n| l/R | share of the power at "
               "the deterministic harmonics, mean +- std over %zu realisations |\n|---|---|", period, share_det, N);
    double worst = 0, *buf = check_alloc(N * sizeof *buf), ci_lo[3], ci_hi[3];
    size_t excluded = 0;
    for (size_t j = 0; j < K; j++) {
        sf_note(r, "| %g | %.4f +- %.4f |", c->spec.sweep.v[j], m[j], sdv[j]);
        check_sweep_stat_record(r, "l_over_R", c->spec.sweep.v[j], "harmonic_share", "-", &st[j], NULL);
        double w = check_sweep_row_off(sf_result_sweep_at(r, sf_result_nsweep(r) - 1), sh + j * N, 1, N, buf);
        worst = w > worst || isnan(w) ? w : worst;
        excluded += st[j].n_excluded;
        ci_lo[j] = st[j].ci_lo;
        ci_hi[j] = st[j].ci_hi;
    }
    free(buf);
    sf_note(r, "\n(Sweep statistics: the share per l/R with its std, Monte Carlo standard error and %g%% "
               "Student interval (sf_sweep_stat_of, as `slipfield sweep --diagnostics` states them), recomputed from the "
               "per-realisation shares with GSL and gated to 8 n eps; u_num not estimated: no coarser companion "
               "solves.)\n", 100 * SF_SWEEP_CI_LEVEL);
    sf_check_le(r, "sweep statistics per l/R: largest |reported - recomputed from the per-realisation shares| / "
                   "(8 n eps scale)", worst, 1);
    sf_check_le(r, "realisations whose harmonic share could not be formed (non-finite)", (double)excluded, 0);
    sf_plot *ps = sf_result_plot(r, "fig15_share", "Fig. 15: share of the power at the deterministic harmonics",
                                 "l/R [-]", "share of the power at the harmonics [-]");
    sf_plot_log(ps, 1, 0);
    char lb[96];
    snprintf(lb, sizeof lb, "mean, %g%% Monte Carlo interval (u_num not estimated)", 100 * SF_SWEEP_CI_LEVEL);
    sf_plot_errorbars(ps, lb, K, c->spec.sweep.v, m, ci_lo, ci_hi);
    sf_plot_hline(ps, "deterministic", share_det);
    sf_note(r, "\n| claim | ours [one-sided (1 - alpha) bounds] | verdict | minimum detectable effect |\n"
               "|---|---|---|---|");
    double n = (double)N, v[3];
    for (int j = 0; j < 3; j++)
        v[j] = sdv[j] * sdv[j] / n;
    char how[200];
    /* Welch on the difference of the mean shares */
    double d1 = m[1] - m[0], se1 = sqrt(v[1] + v[0]), df1 = (v[0] + v[1]) * (v[0] + v[1]) / ((v[0] * v[0] + v[1] * v[1]) / (n - 1));
    snprintf(how, sizeof how, "one-sided Welch t test; share at l/R = 1 minus share at 0.1; n = %zu each", N);
    claims_judge_one(c, r, claims_fig15, &claims_fig15[0], d1, se1, df1, how, "not cycle-based: the periodogram of x over [t_skip, T] cut to whole deterministic periods");
    double d2 = m[2] - m[1], se2 = sqrt(v[2] + v[1]), df2 = (v[2] + v[1]) * (v[2] + v[1]) / ((v[2] * v[2] + v[1] * v[1]) / (n - 1));
    snprintf(how, sizeof how, "one-sided Welch t test; share at l/R = 10 minus share at 1; n = %zu each", N);
    claims_judge_one(c, r, claims_fig15, &claims_fig15[1], d2, se2, df2, how, "not cycle-based: the periodogram of x over [t_skip, T] cut to whole deterministic periods");
    snprintf(how, sizeof how, "one-sided t test; share at l/R = 0.1 minus the deterministic share; n = %zu", N);
    claims_judge_one(c, r, claims_fig15, &claims_fig15[2], m[0] - share_det, sqrt(v[0]), n - 1, how, "not cycle-based: the periodogram of x over [t_skip, T] cut to whole deterministic periods");
    sf_note(r, "\nT = %g s, x sampled every %g s after t_skip = %g s, window cut to whole deterministic periods; "
               "share = power within 2 bins of k / period over the total.", s0->T, dt, s0->t_skip);
    int rc = c->spec.model_budget > N ? fig15_model(c, r, rng, dt, period, sh, N, share_det) : SF_SUCCESS;
    gsl_rng_free(rng);
    free(sh);
    return rc;
}

/* Fig. 3: three fields (l/R = 0.1, 1, 10) along the belt's centre line,
 * and the claim the paper draws from them. */
static int chk_fig3(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, N = s0->samples;
    if (K < 2)
        return SF_EINVAL;
    const double lag = 0.05, L = 4.0;   /* [m] */
    if (c->spec.model_budget && c->spec.model_budget != N) {   /* its model verdict is its one look at N */
        sf_note(r, "**model_budget:** this check draws N = samples fields once: model_budget must equal samples "
                   "(a one-look design) or be unset.");
        return SF_EINVAL;
    }
    size_t np = (size_t)(L / 0.005) + 1;
    double *xs = check_alloc(np * sizeof *xs), *mu = check_alloc(np * sizeof *mu);
    double *msi = check_alloc(K * N * sizeof *msi), mm[SF_LIST_MAX], sv[SF_LIST_MAX];
    sf_plot *p = sf_result_plot(r, "fig3", "Fig. 3: the static COF along the belt centre line (one draw per l/R)",
                                "belt coordinate x_b [m]", "static COF mu_s [-]");
    gsl_rng *rng = sf_case_rng(c);
    for (size_t j = 0; j < K; j++) {
        sf_scene s = *s0;
        char err[256];
        sf_sweep_set(&s, "l_over_R", c->spec.sweep.v[j], err, sizeof err);
        sf_cof_plan *plan;
        if (sf_cof_plan_alloc(&s, &plan, err, sizeof err)) {
            sf_note(r, "**Cannot plan the COF at l/R = %g:** %s", c->spec.sweep.v[j], err);
            gsl_rng_free(rng);
            return SF_EFAIL;
        }
        for (size_t i = 0; i < N; i++) {
            sf_cof *cof;
            if (sf_cof_plan_draw(plan, rng, &cof)) {
                sf_cof_plan_free(plan);
                gsl_rng_free(rng);
                return SF_EFAIL;
            }
            double acc = 0;
            size_t na = 0;
            for (size_t k = 0; k < np; k++) {
                xs[k] = -L + 0.005 * (double)k;
                mu[k] = sf_cof_eval(cof, xs[k], 0);
                if (k >= 10) {   /* 10 x 0.005 m = the lag */
                    acc += (mu[k] - mu[k - 10]) * (mu[k] - mu[k - 10]);
                    na++;
                }
            }
            msi[j * N + i] = acc / (double)na;
            if (i == 0) {
                char lb[64];
                snprintf(lb, sizeof lb, "l/R = %g", c->spec.sweep.v[j]);
                sf_plot_series(p, lb, SF_STYLE_LINES, np, xs, mu);
            }
            sf_cof_free(cof);
        }
        sf_cof_plan_free(plan);
        mm[j] = gsl_stats_mean(msi + j * N, 1, N);
        sv[j] = gsl_stats_sd(msi + j * N, 1, N);
    }
    gsl_rng_free(rng);
    double mean_line = s0->mu_mean;
    sf_plot_hline(p, "mean COF", mean_line);
    sf_note(r, "| l/R | mean square increment over %g m, mean +- std over %zu draws |\n|---|---|", lag, N);
    int finite = 1;
    for (size_t j = 0; j < K; j++) {
        sf_note(r, "| %g | %.3e +- %.3e |", c->spec.sweep.v[j], mm[j], sv[j]);
        finite &= isfinite(mm[j]) && isfinite(sv[j]);
    }
    sf_check_true(r, "every increment statistic is finite", finite, finite ? "finite" : "NaN or Inf");
    /* Exact for the squared-exponential Gaussian field behind it: at lag h
     * the increment variance is 2 var (1 - rho(h)), rho = exp(-h^2/l^2);
     * the claim is the fall of that with l. */
    sf_note(r, "\n| claim | ours [one-sided (1 - alpha) bounds] | verdict | minimum detectable effect |\n"
               "|---|---|---|---|");
    double n = (double)N, va = sv[0] * sv[0] / n, vb = sv[K - 1] * sv[K - 1] / n;
    char how[200];
    snprintf(how, sizeof how, "one-sided Welch t test; mean square increment at l/R = %g minus at %g; n = %zu draws each",
             c->spec.sweep.v[K - 1], c->spec.sweep.v[0], N);
    claims_judge_one(c, r, claims_fig3, &claims_fig3[0], mm[K - 1] - mm[0], sqrt(va + vb),
              (va + vb) * (va + vb) / ((va * va + vb * vb) / (n - 1)), how, "not a QoI of the dynamics: the field itself");
    free(xs);
    free(mu);
    free(msi);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_validation[] = {
    { "val_fig15", chk_fig15, "Fig. 15: spectra of x against the deterministic harmonics" },
    { "val_fig16", chk_fig16, "Fig. 16: bifurcation diagrams (x at slip-to-stick)" },
    { "val_fig10", chk_fig10, "Fig. 10: convergence in the number of realisations" },
    { "val_fig11", chk_fig11, "Fig. 11: QoI ratios vs l/R (spread peak, large-l/R std)" },
    { "val_fig12", chk_fig12, "Fig. 12: stick fraction vs v_b, stochastic steeper" },
    { "val_fig13", chk_fig13, "Fig. 13: ratios approach 1 as the mean COF grows" },
    { "val_claims_lr", chk_claims_lr, "Figs. 10, 11, 16(a): the paper's claims on l/R as gated one-sided tests" },
    { "val_claims_vb", chk_claims_vb, "Figs. 12, 16(b): the paper's claims on v_b as gated one-sided tests" },
    { "val_claims_fig15", chk_claims_fig15, "Fig. 15: the paper's claims on the spectra as gated one-sided tests" },
    { "val_fig3", chk_fig3, "Fig. 3: three fields along the belt and the correlation length's claim" },
    { "val_claims_mu", chk_claims_mu, "Figs. 13, 16(c): the paper's claims on the mean COF as gated one-sided tests" },
    { NULL, NULL, NULL }
};
