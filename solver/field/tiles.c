/* slipfield: a Gaussian field with the covariance of Eq. 2 generated on
 * demand from white noise in tiles (tiles.h): the tiles' seeds, kernel
 * weights and the column-by-column fill. */
#include "tiles.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_randist.h>

/* ---- SplitMix64 as a gsl_rng type */

typedef struct { uint64_t s; } sm_state;

static uint64_t sm_mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static uint64_t sm_next(void *st)
{
    sm_state *s = st;
    s->s += 0x9e3779b97f4a7c15ULL;
    return sm_mix(s->s);
}

static void sm_set(void *st, unsigned long seed) { ((sm_state *)st)->s = (uint64_t)seed; }
static unsigned long sm_get(void *st) { return (unsigned long)(sm_next(st) >> 32); }
static double sm_get_double(void *st) { return (double)(sm_next(st) >> 11) * 0x1.0p-53; }

static const gsl_rng_type sm_type = { "sf_splitmix64", 0xffffffffUL, 0, sizeof(sm_state), sm_set, sm_get,
                                      sm_get_double };
const gsl_rng_type *sf_rng_splitmix64 = &sm_type;

uint64_t sf_tiles_tile_seed(uint64_t key, long tile)
{
    return sm_mix(sm_mix(key + 0x9e3779b97f4a7c15ULL * (uint64_t)tile) ^ 0x5851f42d4c957f2dULL);
}

/* ---- the generator */

enum { NSLOT = 4 };
enum { FILL_BLOCK = 256 };   /* columns per fill block */

struct sf_tiles {
    size_t ny, nyp, tw, nr;  /* rows, rows rounded up to 16, tile columns, noise rows per column (nyp + 2 Ky) */
    size_t kx, ky;
    double *wx, *wy;         /* kernel weights, 2K+1 each */
    double *cx, *cy;         /* produced 1-D covariances at lags 0..2K */
    uint64_t key;
    gsl_rng *rng;
    double *slot[NSLOT];
    long slot_tile[NSLOT];
    unsigned long slot_used[NSLOT], clock;
    int slot_ok[NSLOT];
    double *ybuf, *acc;
    size_t ycap;
    sf_tiles_noise_fn noise;   /* NULL: the tiles' own noise */
    void *noise_ctx;
};

/* Normalised kernel of length l/sqrt(2) sampled at spacing h, truncated
 * at trunc l/sqrt(2); and its autocorrelation (the produced covariance). */
static int kernel(double h, double l, double trunc, size_t *K, double **w, double **cov)
{
    double a = l / sqrt(2.0), span = ceil(trunc * a / h);
    if (!(span >= 0) || span > 1e6)
        return SF_EINVAL;
    size_t k = (size_t)span, n = 2 * k + 1;
    *w = sf_malloc(n * sizeof **w);
    *cov = sf_calloc(n, sizeof **cov);
    if (!*w || !*cov)
        return SF_ENOMEM;
    double s2 = 0;
    for (size_t i = 0; i < n; i++) {
        double q = ((double)i - (double)k) * h / a;
        (*w)[i] = exp(-q * q);
        s2 += (*w)[i] * (*w)[i];
    }
    double norm = 1 / sqrt(s2);   /* unit variance: sum w^2 = 1 */
    for (size_t i = 0; i < n; i++)
        (*w)[i] *= norm;
    for (size_t p = 0; p < n; p++)
        for (size_t i = 0; i + p < n; i++)
            (*cov)[p] += (*w)[i] * (*w)[i + p];
    *K = k;
    return SF_SUCCESS;
}

int sf_tiles_alloc(const sf_tiles_spec *spec, sf_tiles **out)
{
    *out = NULL;
    if (!spec || spec->ny < 1 || !(spec->dx > 0) || !(spec->dy > 0) || !(spec->l > 0) || !isfinite(spec->l) ||
        !(spec->trunc >= 0))
        return SF_EINVAL;
    sf_tiles *t = sf_calloc(1, sizeof *t);
    if (!t)
        return SF_ENOMEM;
    double trunc = spec->trunc > 0 ? spec->trunc : 6.0;
    int rc = kernel(spec->dx, spec->l, trunc, &t->kx, &t->wx, &t->cx);
    if (!rc)
        rc = kernel(spec->dy, spec->l, trunc, &t->ky, &t->wy, &t->cy);
    t->ny = spec->ny;
    t->tw = spec->tile_cols ? spec->tile_cols : 64;
    t->nyp = (t->ny + 15) / 16 * 16;
    t->nr = t->nyp + 2 * t->ky;
    t->rng = SF_FALLIBLE(gsl_rng_alloc(sf_rng_splitmix64));
    t->acc = sf_malloc((size_t)FILL_BLOCK * 16 * sizeof *t->acc);
    if (!rc && (!t->rng || !t->acc))
        rc = SF_ENOMEM;
    for (int s = 0; s < NSLOT && !rc; s++)
        if (!(t->slot[s] = sf_malloc(t->tw * t->nr * sizeof *t->slot[s])))
            rc = SF_ENOMEM;
    if (rc) {
        sf_tiles_free(t);
        return rc;
    }
    *out = t;
    return SF_SUCCESS;
}

void sf_tiles_free(sf_tiles *t)
{
    if (!t)
        return;
    free(t->wx);
    free(t->wy);
    free(t->cx);
    free(t->cy);
    gsl_rng_free(t->rng);
    for (int s = 0; s < NSLOT; s++)
        free(t->slot[s]);
    free(t->ybuf);
    free(t->acc);
    free(t);
}

void sf_tiles_set_key(sf_tiles *t, uint64_t key)
{
    t->key = key;
    memset(t->slot_ok, 0, sizeof t->slot_ok);
}

size_t sf_tiles_tile_cols(const sf_tiles *t) { return t->tw; }

const double *sf_tiles_weights(const sf_tiles *t, int axis, size_t *K)
{
    *K = axis ? t->ky : t->kx;
    return axis ? t->wy : t->wx;
}

double sf_tiles_covariance(const sf_tiles *t, long p, long q)
{
    unsigned long ap = (unsigned long)labs(p), aq = (unsigned long)labs(q);
    if (ap > 2 * t->kx || aq > 2 * t->ky)
        return 0;
    return t->cx[ap] * t->cy[aq];
}

void sf_tiles_set_noise(sf_tiles *t, sf_tiles_noise_fn fn, void *ctx)
{
    t->noise = fn;
    t->noise_ctx = ctx;
}

size_t sf_tiles_noise_rows(const sf_tiles *t, size_t *ky)
{
    *ky = t->ky;
    return t->nr;
}

/* The noise of lattice column i: nr normals (row r is lattice row r - Ky). */
static const double *noise_column(sf_tiles *t, long i)
{
    if (t->noise)
        return t->noise(t->noise_ctx, i);
    long tw = (long)t->tw, tile = i >= 0 ? i / tw : -((-i + tw - 1) / tw);
    size_t off = (size_t)(i - tile * tw);
    int s = -1;
    for (int k = 0; k < NSLOT; k++)
        if (t->slot_ok[k] && t->slot_tile[k] == tile)
            s = k;
    if (s < 0) {   /* draw the tile: the least recently used slot */
        s = 0;
        for (int k = 1; k < NSLOT; k++)
            if (!t->slot_ok[k] || (t->slot_ok[s] && t->slot_used[k] < t->slot_used[s]))
                s = k;
        gsl_rng_set(t->rng, (unsigned long)sf_tiles_tile_seed(t->key, tile));
        double *b = t->slot[s];
        for (size_t n = 0; n < t->tw * t->nr; n++)
            b[n] = gsl_ran_gaussian_ziggurat(t->rng, 1.0);
        t->slot_ok[s] = 1;
        t->slot_tile[s] = tile;
    }
    t->slot_used[s] = ++t->clock;
    return t->slot[s] + off * t->nr;
}

static int fill_block(sf_tiles *t, long i0, size_t m, double *out, size_t ld);

/* Blocks of FILL_BLOCK columns keep the buffer of y-convolved columns at
 * (FILL_BLOCK + 2 Kx) x ny values whatever m; a column's value does not
 * depend on the block it falls in. */

int sf_tiles_fill(sf_tiles *t, long i0, size_t m, double *out, size_t ld)
{
    if (ld < m || !out)
        return SF_EINVAL;
    for (size_t c = 0; c < m; c += FILL_BLOCK) {
        int rc = fill_block(t, i0 + (long)c, m - c < FILL_BLOCK ? m - c : FILL_BLOCK, out + c, ld);
        if (rc)
            return rc;
    }
    return SF_SUCCESS;
}

/* out[r] = sum_k w[k] src[r + off(k)], r < RB, k in order: the RB sums
 * stay in registers (RB doubles, a multiple of the vector width), so -O2
 * vectorises this; off(k) = k0 - k s steps back through the sources. */
#define RB 16
static void conv_block(size_t nk, const double *restrict w, const double *restrict src, ptrdiff_t step,
                       double *restrict out)
{
    /* sixteen named sums: GCC keeps them in registers (an array it keeps
     * in memory, a store per term) */
    double a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0, a6 = 0, a7 = 0;
    double a8 = 0, a9 = 0, a10 = 0, a11 = 0, a12 = 0, a13 = 0, a14 = 0, a15 = 0;
    for (size_t k = 0; k < nk; k++) {
        const double *q = src - (ptrdiff_t)k * step;
        double wk = w[k];
        a0 += wk * q[0]; a1 += wk * q[1]; a2 += wk * q[2]; a3 += wk * q[3];
        a4 += wk * q[4]; a5 += wk * q[5]; a6 += wk * q[6]; a7 += wk * q[7];
        a8 += wk * q[8]; a9 += wk * q[9]; a10 += wk * q[10]; a11 += wk * q[11];
        a12 += wk * q[12]; a13 += wk * q[13]; a14 += wk * q[14]; a15 += wk * q[15];
    }
    out[0] = a0; out[1] = a1; out[2] = a2; out[3] = a3; out[4] = a4; out[5] = a5; out[6] = a6; out[7] = a7;
    out[8] = a8; out[9] = a9; out[10] = a10; out[11] = a11; out[12] = a12; out[13] = a13; out[14] = a14;
    out[15] = a15;
}

static int fill_block(sf_tiles *t, long i0, size_t m, double *out, size_t ld)
{
    size_t ny = t->ny, nyp = t->nyp, kx = t->kx, ky = t->ky, ncol = m + 2 * kx;
    if (ncol * nyp > t->ycap) {
        double *b = sf_realloc(t->ybuf, ncol * nyp * sizeof *b);
        if (!b)
            return SF_ENOMEM;
        t->ybuf = b;
        t->ycap = ncol * nyp;
    }
    /* along y: Y(i, j) = sum_b wy(b) xi(i, j - b), b in order -Ky..Ky
     * (xi row j - b + Ky = j + 2 Ky - bb for b = bb - Ky) */
    for (size_t c = 0; c < ncol; c++) {
        const double *xi = noise_column(t, i0 - (long)kx + (long)c);
        for (size_t j0 = 0; j0 < nyp; j0 += RB)
            conv_block(2 * ky + 1, t->wy, xi + j0 + 2 * ky, 1, t->ybuf + c * nyp + j0);
    }
    /* along x: G(i, j) = sum_a wx(a) Y(i - a, j), a in order -Kx..Kx (Y
     * column c + 2 Kx - aa for a = aa - Kx); RB rows at a time, written
     * row by row (contiguous in out) */
    double *acc = t->acc;
    for (size_t j0 = 0; j0 < ny; j0 += RB) {
        size_t nr = ny - j0 < RB ? ny - j0 : RB;
        for (size_t c = 0; c < m; c++)
            conv_block(2 * kx + 1, t->wx, t->ybuf + (c + 2 * kx) * nyp + j0, (ptrdiff_t)nyp, acc + c * RB);
        for (size_t r = 0; r < nr; r++) {
            double *o = out + ld * (j0 + r);
            for (size_t c = 0; c < m; c++)
                o[c] = acc[c * RB + r];
        }
    }
    return SF_SUCCESS;
}
