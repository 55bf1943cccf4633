/* The cost of a run's numerical error estimate (unum.h: a coarser
 * companion solve of the same realisation) next to the run it accompanies:
 * `slipfield run --summary` does the run (COF plan, draw, oscillator, run)
 * and then the companion.  CPU time of this thread, medians of REPS
 * interleaved repetitions, across l/R (Table 1 otherwise, T = 100 s;
 * l/R = 0.02 takes the cell averages) and at qoi_tol 1e-4.  The budget:
 * at most 50% of the run.  `make bench BENCH_SECTIONS=unum`. */
#include "bench.h"
#include "cof.h"
#include "oscillator.h"
#include "scene.h"
#include "unum.h"

#include <math.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>

/* one `slipfield run --summary`: *run the CPU of plan + draw + run, *est
 * the companion's; u the estimate */
static int run_with_estimate(const sf_scene *s, double *run, double *est, sf_unum *u)
{
    char err[200];
    sf_cof_plan *p = NULL;
    sf_cof *cof = NULL;
    sf_osc *o = NULL;
    double t0 = bench_cpu();
    int rc = sf_cof_plan_alloc(s, &p, err, sizeof err);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, s->seed);
    if (!rc)
        rc = sf_cof_plan_draw(p, g, &cof);
    gsl_rng_free(g);
    sf_cof_plan_free(p);
    sf_osc_result r;
    if (!rc && !(rc = sf_osc_alloc(s, cof, &o, err, sizeof err)) &&
        !(rc = sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err))) {
        *run = bench_cpu() - t0;
        t0 = bench_cpu();
        rc = sf_unum_estimate(s, cof, sf_osc_get_plan(o), &r, u, err, sizeof err);
        *est = bench_cpu() - t0;
        sf_osc_result_free(&r);
    }
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc;
}

int bench_unum(FILE *f, const char *dir)
{
    (void)dir;
    enum { REPS = 5, NC = 6 };
    const double lr[NC] = { 0.02, 0.1, 0.5, 1, 5, 1 };
    const double tol[NC] = { 1e-3, 1e-3, 1e-3, 1e-3, 1e-3, 1e-4 };
    fprintf(f, "## The cost of the error estimate (run --summary: u_num from a coarser companion solve)\n\nTable 1, "
               "T = 100 s, cof = field, one core; CPU time of this thread, medians of %d interleaved repetitions. "
               "Run: COF plan + draw + oscillator + run (what `slipfield run` does); estimate: the companion solve "
               "on the same field (unum.h). Budget: estimate <= 0.5 run.\n\n| l/R | qoi_tol | run [s] | estimate [s] | "
               "estimate / run | cells: run, companion | rtol: run, companion | u_num / Q: PV_x, PV_F, SF |\n"
               "|---|---|---|---|---|---|---|---|\n", REPS);
    int rc = 0;
    double worst = 0;
    for (int c = 0; c < NC && !rc; c++) {
        sf_scene s;
        sf_scene_default(&s);
        s.cof = SF_COF_FIELD;
        s.T = 100;
        s.l = lr[c] * s.R;
        s.qoi_tol = tol[c];
        double a[REPS], b[REPS];
        sf_unum u;
        for (int k = 0; k < REPS && !rc; k++)
            rc = run_with_estimate(&s, &a[k], &b[k], &u);
        if (rc)
            break;
        gsl_sort(a, 1, REPS);
        gsl_sort(b, 1, REPS);
        double ra = a[REPS / 2], rb = b[REPS / 2];
        worst = fmax(worst, rb / ra);
        fprintf(f, "| %g | %g | %.4f | %.4f | %.2f | %zu, %zu%s | %.3g, %.3g | %.2g, %.2g, %.2g |\n", lr[c], tol[c], ra,
                rb, rb / ra, u.cells, u.cells_c, u.cell_average ? " (cell averages)" : "", u.rtol, u.rtol_c,
                u.u[0] / fabs(u.q[0]), u.u[1] / fabs(u.q[1]), u.u[2] / fabs(u.q[2]));
    }
    bench_target("the error estimate of run --summary costs <= 50% of the run it accompanies (every l/R, qoi_tol "
                 "measured), section unum", !rc && worst <= 0.5, "worst %.2f of the run", worst);
    return rc;
}
