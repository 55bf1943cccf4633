/* Shared helpers of the `make bench` field section: the timing helpers and
 * the circulant cost measurement that bench_field.c, bench_field_chol.c and
 * bench_field_peers.c all use.  bench_field_common.c calls none of those
 * three files, so the dependency runs one way: driver -> sections -> here. */
#include "bench.h"
#include "bench_field_common.h"
#include "field.h"
#include "result.h"
#include "sf_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

double fb_median(double *t, size_t n)
{
    gsl_sort(t, 1, n);
    return gsl_stats_median_from_sorted_data(t, 1, n);
}

int fb_more(size_t reps, size_t min_reps, size_t max_reps, double t_start, double budget)
{
    return reps < max_reps && (reps < min_reps || now() - t_start < budget);
}

int fb_render(sf_result *r, const char *dir)
{
    char e[200];
    int rc = sf_result_render_plots(r, dir, e, sizeof e);
    if (rc)
        fprintf(stderr, "bench: plot: %s\n", e);
    sf_result_free(r);
    return rc;
}

/* See bench_field_common.h. */
sf_field *fb_plan(const sf_field_spec *spec, const char *what)
{
    sf_field *f;
    int rc = sf_field_alloc(spec, &f);
    if (!sf_usable(rc)) {
        fprintf(stderr, "bench: cannot plan %s: %s\n", what, sf_strerror(rc));
        return NULL;
    }
    return f;
}

int fb_circulant_costs(const sf_field_spec *spec, size_t k, double budget, fb_cost *out)
{
    enum { MAXR = 41 };
    double *t = malloc(k * MAXR * sizeof *t);
    sf_field **f = calloc(k, sizeof *f);
    double **re = calloc(k, sizeof *re), **im = calloc(k, sizeof *im);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    int rc = !t || !f || !re || !im || !rng;
    /* set-up: plan and free, round robin over the specs */
    size_t r = 0;
    double t_start = now();
    while (!rc && fb_more(r, 3, MAXR, t_start, budget)) {
        for (size_t i = 0; i < k && !rc; i++) {
            double t0 = now();
            sf_field *g = fb_plan(&spec[i], "circulant");
            t[i * MAXR + r] = now() - t0;
            rc = !g;
            sf_field_free(g);
        }
        r++;
    }
    for (size_t i = 0; i < k && !rc; i++) {
        out[i].n = spec[i].n;
        out[i].reps_setup = r;
        out[i].setup = fb_median(t + i * MAXR, r);
        f[i] = fb_plan(&spec[i], "circulant");
        re[i] = malloc(spec[i].m * spec[i].n * sizeof **re);
        im[i] = malloc(spec[i].m * spec[i].n * sizeof **im);
        rc = !f[i] || !re[i] || !im[i];
        if (!rc) {
            const sf_field_info *in = sf_field_get_info(f[i]);
            out[i].px = in->px;
            out[i].py = in->py;
            out[i].cov_err = in->cov_error;
        }
    }
    /* per field: half a sample_pair, round robin */
    r = 0;
    t_start = now();
    while (!rc && fb_more(r, 5, MAXR, t_start, budget)) {
        for (size_t i = 0; i < k; i++) {
            double t0 = now();
            sf_field_sample_pair(f[i], rng, re[i], im[i]);
            t[i * MAXR + r] = 0.5 * (now() - t0);
        }
        r++;
    }
    for (size_t i = 0; i < k && !rc; i++) {
        out[i].reps_sample = r;
        out[i].sample = fb_median(t + i * MAXR, r);
    }
    for (size_t i = 0; i < k && f; i++) {
        sf_field_free(f[i]);
        if (re) free(re[i]);
        if (im) free(im[i]);
    }
    if (rng) gsl_rng_free(rng);
    free(re);
    free(im);
    free(f);
    free(t);
    return rc;
}
