/* Work-precision of the stick-slip integrators: error against an exact or
 * converged answer vs CPU time, for fixed-step RK4 (the paper's dt = 1e-3
 * s and neighbours) and the adaptive rk8pd at several tolerances.
 *  - 1-D Table 1 (T = 100 s): max transition-time error vs the
 *    eps-corrected closed form (solver/cycle1d.h).
 *  - Table 1 stochastic baseline (T = 100 s, one field, 12 rings): Eq. 15
 *    error vs a run at rtol = 1e-12 on the same field. */
#include "bench.h"
#include "cof.h"
#include "cycle1d.h"
#include "oscillator.h"
#include "result.h"
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>

typedef struct { int rk4; double knob; double err, time; unsigned long steps; } point;

static double run_time(const sf_scene *s, const sf_cof *cof, double sample_dt, int reps, sf_osc_result *keep)
{
    double t[7];
    for (int k = 0; k < reps; k++) {
        sf_osc *o;
        char err[200];
        sf_osc_alloc(s, cof, &o, err, sizeof err);
        sf_osc_result r;
        double t0 = now();
        sf_osc_run(o, NULL, NULL, sample_dt, &r, err, sizeof err);
        t[k] = now() - t0;
        if (k == reps - 1)
            *keep = r;
        else
            sf_osc_result_free(&r);
        sf_osc_free(o);
    }
    gsl_sort(t, 1, (size_t)reps);
    return t[reps / 2];
}

static double transition_error(const sf_osc_result *r, const sf_cycle1d *c)
{
    double e = 0;
    for (size_t i = 0; i < r->ntrans; i++)
        e = fmax(e, fabs(r->trans_t[i] - sf_cycle1d_transition(c, (unsigned)i)));
    return e;
}

static void table(FILE *f, const char *what, point *p, size_t n)
{
    fprintf(f, "| stepper | dt or rtol | %s | CPU time [s] | steps |\n|---|---|---|---|---|\n", what);
    for (size_t i = 0; i < n; i++)
        fprintf(f, "| %s | %g | %.3e | %.4f | %lu |\n", p[i].rk4 ? "RK4 (fixed)" : "rk8pd (adaptive)", p[i].knob,
                p[i].err, p[i].time, p[i].steps);
}

/* Time RK4 at each dt and rk8pd at each rtol; err(result, ctx) scores a run. */
static size_t sweep_points(const sf_scene *s, const sf_cof *cof, double sample_dt, int reps, const double *dts, size_t ndt,
                           const double *rtols, size_t nrt, double (*err)(const sf_osc_result *, const void *),
                           const void *ctx, point *p)
{
    size_t n = 0;
    for (size_t i = 0; i < ndt + nrt; i++) {
        sf_scene t = *s;
        int rk4 = i < ndt;
        if (rk4) {
            t.integrator = SF_INTEG_RK4;
            t.dt = dts[i];
        } else {
            t.rtol = rtols[i - ndt];
        }
        sf_osc_result r;
        double tm = run_time(&t, cof, sample_dt, reps, &r);
        p[n++] = (point){ rk4, rk4 ? t.dt : t.rtol, err(&r, ctx), tm, r.steps };
        if (reps == 1)
            fprintf(stderr, "bench: %s %g: error %.3e in %.2f s\n", rk4 ? "RK4 dt" : "rk8pd rtol", p[n - 1].knob,
                    p[n - 1].err, tm);
        sf_osc_result_free(&r);
    }
    return n;
}

static double err_1d(const sf_osc_result *r, const void *c) { return transition_error(r, c); }
static double err_eq15(const sf_osc_result *r, const void *ref) { return sf_osc_error_eq15(r, ref); }

/* time of the cheapest adaptive point reaching error <= target */
static double cheapest(const point *p, size_t n, int rk4, double target)
{
    double best = INFINITY;
    for (size_t i = 0; i < n; i++)
        if (p[i].rk4 == rk4 && p[i].err <= target)
            best = fmin(best, p[i].time);
    return best;
}

static void plot(sf_result *r, const char *stem, const char *title, const char *ylabel, point *p, size_t n)
{
    double x[2][16], y[2][16];
    size_t m[2] = { 0, 0 };
    for (size_t i = 0; i < n; i++) {
        int k = p[i].rk4;
        x[k][m[k]] = p[i].time;
        y[k][m[k]] = fmax(p[i].err, 1e-300);
        m[k]++;
    }
    sf_plot *pl = sf_result_plot(r, stem, title, "CPU time per run [s]", ylabel);
    sf_plot_log(pl, 1, 1);
    sf_plot_series(pl, "rk8pd, rtol 1e-4 ... 1e-12", SF_STYLE_LINESPOINTS, m[0], x[0], y[0]);
    sf_plot_series(pl, "RK4, dt 1e-2 ... 2.5e-4 s", SF_STYLE_LINESPOINTS, m[1], x[1], y[1]);
}

int bench_dynamics(FILE *f, const char *dir)
{
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.dof = SF_DOF_1;
    sf_cof *u;
    sf_cof_alloc_uniform(s.mu_mean, &u);
    sf_cycle1d cf;
    sf_cycle1d_init(&cf, &s, s.eps_lambda);
    const double dts[] = { 1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2.5e-4 }, rtols[] = { 1e-4, 1e-6, 1e-8, 1e-10, 1e-12 };
    point p1[16];
    size_t n1 = sweep_points(&s, u, 0, 5, dts, 6, rtols, 5, err_1d, &cf, p1);
    sf_cof_free(u);
    fprintf(f, "## Stick-slip integrators: work-precision\n\n### 1-D Table 1 oscillator, exact answer\n\n"
               "Error: max |transition time - closed form| over the 46 transitions of 100 s (eps_lambda = 1e-3, "
               "closed form corrected for it). Medians of 5 runs.\n\n");
    table(f, "max transition-time error [s]", p1, n1);
    double rk4_paper = p1[3].time, e_paper = p1[3].err, ad = cheapest(p1, n1, 0, e_paper);
    fprintf(f, "\nRK4 at the paper's dt = 1e-3 s reaches %.1e s in %.4f s; the cheapest adaptive run at least as "
               "accurate takes %.4f s: ratio RK4/adaptive = %.1f.\n", e_paper, rk4_paper, ad, rk4_paper / ad);
    /* stochastic baseline */
    sf_scene st;
    sf_scene_default(&st);
    st.cells = 12;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, st.seed);
    sf_cof *fc;
    sf_cof_from_scene(&st, rng, &fc);
    gsl_rng_free(rng);
    const double sdt = 1e-3;
    sf_scene sr = st;
    sr.rtol = 1e-12;
    sf_osc_result ref;
    double tref = run_time(&sr, fc, sdt, 1, &ref);
    const double dts2[] = { 2e-3, 1e-3, 5e-4 }, rtols2[] = { 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10 };
    point p2[16];
    size_t n2 = sweep_points(&st, fc, sdt, 1, dts2, 3, rtols2, 6, err_eq15, &ref, p2);
    sf_osc_result_free(&ref);
    sf_cof_free(fc);
    fprintf(f, "\n### Table 1 stochastic baseline, converged reference\n\nError: Eq. 15 (sum of (x - x_ref)^2 dt, "
               "samples every 1e-3 s) against rk8pd at rtol = 1e-12 on the same field (%.2f s). Polar quadrature, "
               "12 rings. Single runs (each takes seconds: the ratios below are far above the noise).\n\n", tref);
    table(f, "Eq. 15 error [m^2 s]", p2, n2);
    double rk = p2[1].time, erk = p2[1].err, a6 = cheapest(p2, n2, 0, 1e-6), arl = cheapest(p2, n2, 0, erk);
    fprintf(f, "\nTarget (issue 6): Eq. 15 error 1e-6 at least 10x faster than RK4 at dt = 1e-3 s reaching the same "
               "error. Measured: RK4 at dt = 1e-3 s reaches %.2e in %.2f s; the cheapest adaptive run reaching "
               "1e-6 takes %.2f s (ratio RK4/adaptive %.1f at the target error), and reaching RK4's own error "
               "%.2f s (ratio %.1f). RK4 at dt >= 2e-3 s loses the cycle: the relative speed crosses the "
               "slip-to-stick band (2 eps omega_n R wide) within one step, the paper's remark that a smaller "
               "threshold needs a smaller step.\n", erk, rk, a6, rk / a6, arl, rk / arl);
    sf_result *r = sf_result_alloc();
    plot(r, "dyn_wp_1d", "Work-precision, 1-D oscillator (exact answer)", "max transition-time error [s]", p1, n1);
    plot(r, "dyn_wp_stochastic", "Work-precision, stochastic baseline (Eq. 15 vs converged run)", "Eq. 15 error [m^2 s]",
         p2, n2);
    char e[200];
    int rc = sf_result_render_plots(r, dir, e, sizeof e);
    sf_result_free(r);
    fprintf(f, "\n![1-D work-precision](dyn_wp_1d.png)\n\n![Stochastic work-precision](dyn_wp_stochastic.png)\n\n"
               "SUNDIALS CVODE (a benchmark-only peer, issue 6) is not in this run yet.\n");
    return rc ? 1 : 0;
}
