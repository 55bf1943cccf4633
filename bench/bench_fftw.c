/* FFTW planning rigour: what FFTW_MEASURE (and so wisdom) would buy over
 * the FFTW_ESTIMATE plans the field generator makes once per plan and
 * reuses for every realisation.  MEASURE picks plans by timing, so two
 * runs (or two machines) may execute different plans and differ in the
 * last bits (docs/design.md sec. 8); ESTIMATE is deterministic.  This section
 * measures the price of that choice on the embedding sizes we use. */
#include "bench.h"

#include <complex.h>
#include <string.h>
#include <fftw3.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

enum { REPS = 15 };

int bench_fftw(FILE *f, const char *dir)
{
    (void)dir;
    const size_t sizes[][2] = { { 512, 512 }, { 2048, 2048 }, { 8000, 400 } };
    fprintf(f, "## FFTW planning: FFTW_ESTIMATE (ours) vs FFTW_MEASURE\n\n"
               "The sampling FFT (complex, in place, 2-D) at three embedding sizes: the 256^2 and 1024^2 grids "
               "of the field section with minimal embedding, and a 4000 x 200 belt strip. Execute times are "
               "medians of %d interleaved executions of each plan. MEASURE's planning time is paid once per "
               "plan; wisdom would carry it across runs, but the plan it picks depends on timings, so results "
               "could change in the last bits between runs and machines. So ESTIMATE stays the default (the "
               "same bits everywhere), and a scene may ask for `fftw_planner = measure`, with "
               "`SLIPFIELD_FFTW_WISDOM=FILE` to keep the plans (and so the bits) across runs "
               "(`cases/field/measure-planner-roundoff`: the fields agree to round-off).\n\n"
               "| embedding | ESTIMATE execute [s] | MEASURE execute [s] | ratio ESTIMATE/MEASURE | MEASURE planning "
               "[s] | realisations to repay planning |\n|---|---|---|---|---|---|\n", REPS);
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        int nx = (int)sizes[k][0], ny = (int)sizes[k][1];
        size_t M = sizes[k][0] * sizes[k][1];
        fftw_complex *a = fftw_alloc_complex(M), *b = fftw_alloc_complex(M);
        fftw_plan pe = fftw_plan_dft_2d(ny, nx, a, a, FFTW_FORWARD, FFTW_ESTIMATE);
        double t0 = now();
        fftw_plan pm = fftw_plan_dft_2d(ny, nx, b, b, FFTW_FORWARD, FFTW_MEASURE);
        double tplan = now() - t0;
        for (size_t i = 0; i < M; i++)
            a[i] = b[i] = (double)(i % 7) - 3 + I * (double)(i % 5);
        double te[REPS], tm[REPS];
        for (int r = 0; r < REPS; r++) {
            t0 = now();
            fftw_execute(pe);
            double t1 = now();
            fftw_execute(pm);
            te[r] = t1 - t0;
            tm[r] = now() - t1;
        }
        gsl_sort(te, 1, REPS);
        gsl_sort(tm, 1, REPS);
        double me = gsl_stats_median_from_sorted_data(te, 1, REPS), mm = gsl_stats_median_from_sorted_data(tm, 1, REPS);
        double gain = me - mm;
        char repay[48];
        if (gain > 0)
            snprintf(repay, sizeof repay, "%.0f", tplan / gain);
        else
            snprintf(repay, sizeof repay, "never (no gain)");
        fprintf(f, "| %d x %d | %.4g | %.4g | %.2f | %.3g | %s |\n", nx, ny, me, mm, me / mm, tplan, repay);
        fprintf(stderr, "bench: fftw %d x %d: estimate %.4g s, measure %.4g s, planning %.3g s\n", nx, ny, me, mm,
                tplan);
        fftw_destroy_plan(pe);
        fftw_destroy_plan(pm);
        fftw_free(a);
        fftw_free(b);
    }
    fprintf(f, "\nA ratio near 1 means ESTIMATE already finds a plan as good as a timed search; the last column is "
               "how many realisations a sweep would need before MEASURE's planning paid for itself.\n");
    return 0;
}
