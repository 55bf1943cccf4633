/* Calibration of the accuracy-driven plan (solver/plan/numplan.h): the error of
 * a realisation's quantities of interest (PV_x, PV_F, stick fraction;
 * relative, the largest of the three) against the quadrature resolution
 * (rings, at a tight rtol) and against the stepper's rtol (at a fine
 * quadrature), across l/R, on the same fields: each error is against a
 * run at 4x the rings (resp. at rtol 1e-11) of the same realisation.
 * Table 1 otherwise, T = 60 s (t_skip 10 s).  `make bench
 * BENCH_SECTIONS=plan`; the numbers behind the rule in numplan.c. */
#include "bench.h"
#include "cof.h"
#include "montecarlo.h"
#include "oscillator.h"
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>

static int qoi(const sf_scene *s, const sf_cof *cof, double q[3], double *cpu)
{
    sf_osc *o;
    char err[200];
    if (sf_osc_alloc(s, cof, &o, err, sizeof err))
        return 1;
    sf_osc_result r;
    double t0 = bench_cpu();
    int rc = sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err);
    if (cpu)
        *cpu = bench_cpu() - t0;
    q[0] = r.pv_x;
    q[1] = r.pv_F;
    q[2] = r.stick_fraction;
    sf_osc_result_free(&r);
    sf_osc_free(o);
    return rc;
}

static double relerr(const double a[3], const double b[3])
{
    double e = 0;
    for (int i = 0; i < 3; i++) {
        double d = fabs(a[i] - b[i]) / fabs(b[i]);
        if (!(d <= e))   /* NaN: no complete cycle (fmax would drop it) */
            e = isnan(d) ? INFINITY : d;
    }
    return e;
}

int bench_plan(FILE *f, const char *dir)
{
    (void)dir;
    enum { NS = 4, NL = 5, NRING = 5, NRT = 5 };
    const double lr[NL] = { 1, 0.2, 5, 50, 0.05 };
    const size_t rings[NRING] = { 4, 6, 8, 12, 16 };
    const double rtols[NRT] = { 1e-5, 1e-6, 1e-7, 1e-8, 1e-9 };
    fprintf(f, "## Plan calibration: QoI error vs rings and rtol across l/R\n\nRelative error of a realisation's "
               "QoIs (the largest of PV_x, PV_F, stick fraction), RMS and max over %d realisations (seeds 1..%d), "
               "Table 1, T = 60 s. Rings: at rtol 1e-8 against 4x the rings at rtol 1e-8. rtol: at 16 rings "
               "against rtol 1e-11 at 16 rings. Same fields throughout.\n\n", NS, NS);
    fprintf(f, "| l/R | knob | value | RMS error | max error | CPU per realisation [s] |\n|---|---|---|---|---|---|\n");
    for (int L = 0; L < NL; L++) {
        sf_scene s;
        sf_scene_default(&s);
        s.T = 60;
        s.l = lr[L] * s.R;
        s.rtol = 1e-8;
        s.cells = 32;
        double e2r[NRING] = { 0 }, emr[NRING] = { 0 }, cr[NRING] = { 0 };
        double e2t[NRT] = { 0 }, emt[NRT] = { 0 }, ct[NRT] = { 0 };
        for (int k = 0; k < NS; k++) {
            gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
            gsl_rng_set(rng, (unsigned long)k + 1);
            sf_cof *cof;
            if (sf_cof_from_scene(&s, rng, &cof)) {
                gsl_rng_free(rng);
                fprintf(f, "| %g | - | - | cannot draw the field | | |\n", lr[L]);
                goto next;
            }
            gsl_rng_free(rng);
            for (int i = 0; i < NRING; i++) {
                double q[3], qr[3], c;
                sf_scene a = s;
                a.cells = rings[i];
                qoi(&a, cof, q, &c);
                a.cells = 4 * rings[i];
                qoi(&a, cof, qr, NULL);
                double e = relerr(q, qr);
                e2r[i] += e * e / NS;
                emr[i] = fmax(emr[i], e);
                cr[i] += c / NS;
            }
            double qref[3];
            sf_scene a = s;
            a.cells = 16;
            a.rtol = 1e-11;
            qoi(&a, cof, qref, NULL);
            for (int i = 0; i < NRT; i++) {
                double q[3], c;
                a.rtol = rtols[i];
                qoi(&a, cof, q, &c);
                double e = relerr(q, qref);
                e2t[i] += e * e / NS;
                emt[i] = fmax(emt[i], e);
                ct[i] += c / NS;
            }
            sf_cof_free(cof);
            fprintf(stderr, "bench: plan l/R = %g, realisation %d done\n", lr[L], k + 1);
        }
        for (int i = 0; i < NRING; i++)
            fprintf(f, "| %g | rings | %zu | %.2e | %.2e | %.3f |\n", lr[L], rings[i], sqrt(e2r[i]), emr[i], cr[i]);
        for (int i = 0; i < NRT; i++)
            fprintf(f, "| %g | rtol | %g | %.2e | %.2e | %.3f |\n", lr[L], rtols[i], sqrt(e2t[i]), emt[i], ct[i]);
        fflush(f);
    next:;
    }
    return 0;
}

/* One realisation at l/R = 1 (Table 1 otherwise, T = 100 s) on one core:
 * COF plan, draw and run, CPU time of this thread, at the default
 * qoi_tol (the plan's settings) and at the fixed settings the plan
 * replaced (32 rings, rtol 1e-8); interleaved, medians. */
/* Draw realisation `seed`'s COF from plan p and run it (no history). */
static int draw_and_run(const sf_scene *s, sf_cof_plan *p, unsigned long seed)
{
    char err[200];
    sf_cof *cof = NULL;
    sf_osc *o = NULL;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, seed);
    int rc = sf_cof_plan_draw(p, rng, &cof);
    gsl_rng_free(rng);
    if (!rc && !(rc = sf_osc_alloc(s, cof, &o, err, sizeof err))) {
        sf_osc_result r;
        rc = sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err);
        sf_osc_result_free(&r);
    }
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc;
}

static double one_realisation(const sf_scene *s, int *rc)
{
    double t0 = bench_cpu();
    sf_cof_plan *p;
    char err[200];
    *rc = sf_cof_plan_alloc(s, &p, err, sizeof err);
    if (*rc)
        return NAN;
    *rc = draw_and_run(s, p, s->seed);
    sf_cof_plan_free(p);
    return bench_cpu() - t0;
}

/* Inside a Monte Carlo sweep the COF plan is made once: the marginal cost
 * of realisation i (stream (seed, i): draw, oscillator, run), CPU time of
 * this thread, for scenes a and b interleaved realisation by realisation;
 * medians over K into med[2]. */
static int per_realisation(const sf_scene *sc[2], int K, double med[2])
{
    sf_cof_plan *p[2] = { NULL, NULL };
    char err[200];
    int rc = 0;
    for (int j = 0; j < 2 && !rc; j++)
        rc = sf_cof_plan_alloc(sc[j], &p[j], err, sizeof err);
    double *t = calloc(2 * (size_t)K, sizeof *t);
    for (int i = 0; i < K && !rc && t; i++)
        for (int j = 0; j < 2 && !rc; j++) {
            double t0 = bench_cpu();
            rc = draw_and_run(sc[j], p[j], sf_mc_seed(sc[j]->seed, (size_t)i));
            t[j * K + i] = bench_cpu() - t0;
        }
    for (int j = 0; j < 2; j++) {
        sf_cof_plan_free(p[j]);
        if (t) {
            gsl_sort(t + j * K, 1, (size_t)K);
            med[j] = t[j * K + K / 2];
        }
    }
    free(t);
    return rc || !t;
}

/* CPU time of one draw from a plan made once (streams (seed, i)),
 * median over K; NAN when the plan or a draw fails. */
static double draw_only(const sf_scene *s, int K)
{
    sf_cof_plan *p;
    char err[200];
    if (sf_cof_plan_alloc(s, &p, err, sizeof err))
        return NAN;
    double t[64];
    int n = 0;
    for (int i = 0; i < K && i < 64; i++) {
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        gsl_rng_set(rng, sf_mc_seed(s->seed, (size_t)i));
        sf_cof *cof = NULL;
        double t0 = bench_cpu();
        int rc = sf_cof_plan_draw(p, rng, &cof);
        t[n] = bench_cpu() - t0;
        n += !rc;
        sf_cof_free(cof);
        gsl_rng_free(rng);
    }
    sf_cof_plan_free(p);
    if (n < K)
        return NAN;
    gsl_sort(t, 1, (size_t)n);
    return t[n / 2];
}

int bench_realisation(FILE *f, const char *dir)
{
    (void)dir;
    enum { REPS = 9 };
    sf_scene s[2];
    sf_scene_default(&s[0]);
    s[0].l = s[0].R;   /* l/R = 1 */
    s[1] = s[0];
    s[1].cells = 32;   /* the fixed defaults the plan replaced */
    s[1].rtol = 1e-8;
    double t[2][REPS];
    int rc = 0;
    for (int k = 0; k < REPS; k++)
        for (int j = 0; j < 2; j++)
            t[j][k] = one_realisation(&s[j], &rc);
    gsl_sort(t[0], 1, REPS);
    gsl_sort(t[1], 1, REPS);
    double a = t[0][REPS / 2], b = t[1][REPS / 2];
    sf_osc *o;
    sf_numplan np = { 0 };
    char err[200];
    sf_cof *g;
    {   /* the plan's record at l/R = 1 (any field COF: the plan depends on the scene) */
        double v[4] = { 0.5, 0.5, 0.5, 0.5 };
        sf_cof_alloc_grid(2, 2, -1, -1, 2, 2, v, &g);
        if (!sf_osc_alloc(&s[0], g, &o, err, sizeof err)) {
            np = *sf_osc_get_plan(o);
            sf_osc_free(o);
        }
        sf_cof_free(g);
    }
    fprintf(f, "## One realisation at l/R = 1: default vs the 0.05 s target\n\nTable 1 otherwise (T = 100 s), one core, "
               "CPU time of this thread for COF plan + draw + run, medians of %d interleaved repetitions. Default: "
               "qoi_tol = %g, the plan's settings (%zu rings, rtol %.3g, predicted QoI error %.2g).\n\n"
               "| settings | CPU time per realisation [s] | / 0.05 s target |\n|---|---|---|\n"
               "| default (plan for qoi_tol) | %.4f | %.2f |\n| before the plan (32 rings, rtol 1e-8) | %.4f | %.2f |\n\n"
               "Default vs before: **%.1fx** faster; the 0.05 s target is **%s** (%.2f of it).\n",
            REPS, s[0].qoi_tol, np.cells, np.rtol, np.err_total, a, a / 0.05, b, b / 0.05, b / a,
            a <= 0.05 ? "met" : "NOT met", a / 0.05);
    bench_target("a realisation at l/R = 1 (Table 1, T = 100 s) <= 0.05 s on one core at the default tolerance, "
                 "section realisation", a <= 0.05, "%.4f s (%.2f of the target)", a, a / 0.05);
    fprintf(f, "Against the tighter 0.02 s target: **%s** (%.2f of it; what bounds it: docs/design.md sec. 6.1; the "
               "profile: docs/studies/2026-11-28-kernel-cost.md).\n", a <= 0.02 ? "met" : "NOT met", a / 0.02);
    bench_target("a realisation at l/R = 1 (Table 1, T = 100 s) <= 0.02 s on one core at the default tolerance, "
                 "section realisation", a <= 0.02, "%.4f s (%.2f of the target)", a, a / 0.02);
    /* the marginal cost in a sweep: l/R = 0.01 against l/R = 1 */
    enum { K = 7 };
    sf_scene sm = s[0];
    sm.l = 0.01 * sm.R;
    const sf_scene *pair[2] = { &s[0], &sm };
    double med[2] = { NAN, NAN };
    rc |= per_realisation(pair, K, med);
    fprintf(f, "\nInside a sweep (the COF plan made once, realisation i from stream (seed, i): draw, oscillator, run; "
               "CPU time of this thread, medians of %d interleaved): l/R = 1 **%.4f s**, l/R = 0.01 (the plan's cell "
               "averages) **%.4f s** per realisation: **%.1fx** (target <= 10x).\n",
            K, med[0], med[1], med[1] / med[0]);
    bench_target("l/R = 0.01: time per realisation inside a sweep <= 10x that at l/R = 1 (plan made once), "
                 "section realisation", med[1] <= 10 * med[0], "%.1fx (%.4f s against %.4f s)", med[1] / med[0],
                 med[1], med[0]);
    /* the floor a faster run cannot go below: the draw alone (Gaussian
     * numbers, the FFT, the Nataf map), plan made once */
    double td = draw_only(&s[0], K);
    fprintf(f, "\nThe draw alone at l/R = 1 (plan made once; Gaussian numbers, FFT, Nataf map; median of %d): "
               "**%.4f s**, %.0f%% of a realisation inside a sweep: the run is the rest (%.4f s).\n",
            K, td, 100 * td / med[0], med[0] - td);
    return rc ? 1 : 0;
}
