/* The `make bench` field section, split over bench_field.c (sample time vs
 * the bare FFT + RNG cost; padding work-precision), bench_field_chol.c
 * (circulant vs a direct GSL Cholesky sampler as N grows) and
 * bench_field_peers.c (RandomFields and OpenTURNS run as scripts from
 * bench/peers/).  The helpers all three use are in bench_field_common.c,
 * which calls none of them.  Internal to the bench: not part of any library. */
#ifndef SF_BENCH_FIELD_H
#define SF_BENCH_FIELD_H

#include <stdio.h>
#include <stddef.h>
#include "bench_field_common.h"

/* Section (b): circulant vs GSL Cholesky on n x n grids, l = 2 dx.  Fills
 * circ[] and chol[] (room for FB_NCHOL entries each) and returns how many
 * grids were run in *nrun. */
enum { FB_NCHOL = 9 };
int bench_field_cholesky(FILE *f, const char *dir, fb_cost *circ, fb_cost *chol, size_t *nrun);

/* Section (c): the peers, against circulant/Cholesky costs measured in this
 * run (circ/chol from section (b), for the OpenTURNS rows). */
int bench_field_peers(FILE *f, const fb_cost *circ, const fb_cost *chol, size_t nrun);

#endif
