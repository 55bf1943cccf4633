/* Helpers shared by the `make bench` field section (bench_field.c,
 * bench_field_chol.c, bench_field_peers.c), defined in bench_field_common.c,
 * which calls none of those files.  Internal to the bench. */
#ifndef SF_BENCH_FIELD_COMMON_H
#define SF_BENCH_FIELD_COMMON_H

#include <stddef.h>
#include "field.h"
#include "result.h"

/* One method on one grid: set-up time and time per *field* (medians), the
 * exact covariance error of what it samples, and the repetitions used. */
typedef struct {
    size_t n;            /* n x n grid */
    size_t px, py;       /* circulant embedding (0 for other methods) */
    double setup, sample, cov_err;
    size_t reps_setup, reps_sample;
} fb_cost;

/* Median of t[0..n-1] (sorts t in place). */
double fb_median(double *t, size_t n);

/* Render r's plots into dir (message on stderr on failure), free r. */
int fb_render(sf_result *r, const char *dir);

/* Keep repeating while fewer than min_reps, or while the elapsed time since
 * t_start is below budget, up to max_reps. */
int fb_more(size_t reps, size_t min_reps, size_t max_reps, double t_start, double budget);

/* Plan a field; SF_ETRUNC (padding cap reached, plan usable) is not an error
 * here: the caller reports cov_error.  NULL (message on stderr naming
 * `what`) when the plan fails. */
sf_field *fb_plan(const sf_field_spec *spec, const char *what);

/* Circulant embedding (sf_field) for spec[0..k-1], measured round robin
 * (interleaved, so machine noise hits all alike): set-up = sf_field_alloc
 * (median of repeated plans), per field = half a sf_field_sample_pair call
 * (median), cov_err = sf_field_info.cov_error.  Each phase repeats while
 * under `budget` seconds (at least 3 and 5 rounds, at most 41). */
int fb_circulant_costs(const sf_field_spec *spec, size_t k, double budget, fb_cost *out);

#endif
