/* make bench: field sample time against the bare cost measured in the same
 * run (one FFTW execute of the embedding size plus the 2M normal draws).
 * Measurements are interleaved (bare, ours, bare, ours, ...) and the
 * medians compared, so machine noise hits both sides alike. */
#include "bench.h"
#include "field.h"
#include "sf_error.h"

#include <complex.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <fftw3.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>


typedef struct {
    const char *name;
    size_t m, n;
} grid;

typedef struct {
    double ours, bare, ratio;
    size_t px, py, reps;
} result;

static result bench_grid(const grid *g)
{
    double dx = 0.025, l = 4 * dx;
    sf_field_spec spec;
    sf_field_spec_default(&spec, g->m, g->n, dx, dx, l);
    sf_field *f;
    int rc = sf_field_alloc(&spec, &f);
    if (rc && rc != SF_ECAP) {
        fprintf(stderr, "bench: cannot plan %s: %s\n", g->name, sf_strerror(rc));
        exit(3);
    }
    const sf_field_info *in = sf_field_get_info(f);
    size_t M = in->px * in->py, mn = g->m * g->n;
    fftw_complex *w = fftw_alloc_complex(M);
    fftw_plan p = fftw_plan_dft_2d((int)in->py, (int)in->px, w, w, FFTW_FORWARD, FFTW_ESTIMATE);
    double *re = malloc(mn * sizeof *re), *im = malloc(mn * sizeof *im);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    enum { MAXR = 41 };
    double tb[MAXR], to[MAXR];
    size_t reps = 0;
    double t_start = now();
    while (reps < MAXR && (reps < 5 || now() - t_start < 3.0)) {
        double t0 = now();
        for (size_t k = 0; k < M; k++) {
            double a = gsl_ran_gaussian_ziggurat(rng, 1.0), b = gsl_ran_gaussian_ziggurat(rng, 1.0);
            w[k] = a + I * b;
        }
        fftw_execute(p);
        double t1 = now();
        sf_field_sample_pair(f, rng, re, im);
        double t2 = now();
        tb[reps] = t1 - t0;
        to[reps] = t2 - t1;
        reps++;
    }
    gsl_sort(tb, 1, reps);
    gsl_sort(to, 1, reps);
    result r;
    r.bare = gsl_stats_median_from_sorted_data(tb, 1, reps);
    r.ours = gsl_stats_median_from_sorted_data(to, 1, reps);
    r.ratio = r.ours / r.bare;
    r.px = in->px;
    r.py = in->py;
    r.reps = reps;
    gsl_rng_free(rng);
    free(re);
    free(im);
    fftw_destroy_plan(p);
    fftw_free(w);
    sf_field_free(f);
    return r;
}

int bench_field(FILE *f, const char *dir)
{
    (void)dir;
    const grid grids[] = {
        { "256 x 256", 256, 256 },
        { "1024 x 1024", 1024, 1024 },
        { "belt strip 4000 x 200", 4000, 200 },
    };
    size_t ng = sizeof grids / sizeof grids[0];
    result res[3];
    for (size_t i = 0; i < ng; i++) {
        res[i] = bench_grid(&grids[i]);
        fprintf(stderr, "bench: %-22s embedding %zu x %zu: %.4f s per sample pair, bare %.4f s, ratio %.3f (%zu reps)\n",
                grids[i].name, res[i].px, res[i].py, res[i].ours, res[i].bare, res[i].ratio, res[i].reps);
    }
    fprintf(f, "## Field sampling vs the bare FFT + normal-draw cost\n\n"
               "l = 4 dx (minimal embedding suffices; round-off eigenvalues clamped). One sample call\n"
               "produces two independent fields (real and imaginary parts). The bare cost is one\n"
               "FFTW execute (FFTW_ESTIMATE, in place, same size) plus the 2M ziggurat normal draws,\n"
               "measured interleaved with ours in the same run; medians of %s repetitions.\n\n"
               "| grid | embedding | ours per pair [s] | ours per field [s] | bare FFT + RNG [s] | ratio ours/bare |\n"
               "|---|---|---|---|---|---|\n", "up to 41");
    for (size_t i = 0; i < ng; i++)
        fprintf(f, "| %s | %zu x %zu | %.4g | %.4g | %.4g | %.3f |\n", grids[i].name, res[i].px, res[i].py,
                res[i].ours, res[i].ours / 2, res[i].bare, res[i].ratio);
    fprintf(f, "\nTarget: ratio <= 1.5 per FFT (issue 6). The extra over the bare cost is the\n"
               "amplitude multiply and the extraction of the m x n window of both fields.\n");
    return 0;
}
