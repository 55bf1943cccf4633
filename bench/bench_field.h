/* The `make bench` field section, split over bench_field.c (sample time vs
 * the bare FFT + RNG cost; padding work-precision), bench_field_chol.c
 * (circulant vs a direct GSL Cholesky sampler as N grows) and
 * bench_field_peers.c (RandomFields and OpenTURNS run as scripts from
 * bench/peers/).  Internal to the bench: not part of any library. */
#ifndef SF_BENCH_FIELD_H
#define SF_BENCH_FIELD_H

#include <stdio.h>
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

/* Circulant embedding (sf_field) for spec[0..k-1], measured round robin
 * (interleaved, so machine noise hits all alike): set-up = sf_field_alloc
 * (median of repeated plans), per field = half a sf_field_sample_pair call
 * (median), cov_err = sf_field_info.cov_error.  Each phase repeats while
 * under `budget` seconds (at least 3 and 5 rounds, at most 41). */
int fb_circulant_costs(const sf_field_spec *spec, size_t k, double budget, fb_cost *out);

/* Section (b): circulant vs GSL Cholesky on n x n grids, l = 2 dx.  Fills
 * circ[] and chol[] (room for FB_NCHOL entries each) and returns how many
 * grids were run in *nrun. */
enum { FB_NCHOL = 9 };
int bench_field_cholesky(FILE *f, const char *dir, fb_cost *circ, fb_cost *chol, size_t *nrun);

/* Section (c): the peers, against circulant/Cholesky costs measured in this
 * run (circ/chol from section (b), for the OpenTURNS rows). */
int bench_field_peers(FILE *f, const fb_cost *circ, const fb_cost *chol, size_t nrun);

#endif
