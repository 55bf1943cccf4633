/* slipfield: white noise fixed in belt coordinates (noise.h): dyadic
 * cells made top-down, block columns of BW cells cached per level. */
#include "noise.h"
#include "tiles.h"   /* sf_rng_splitmix64 */
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>

enum { BW = 64 };      /* cells per block column (even: a block's parents are half a parent block) */
enum { NSLOT = 3 };    /* block columns kept per level: the one in use, its neighbours */

typedef struct {
    long r0;               /* first row held at this level */
    size_t nr;             /* rows held */
    double *slot[NSLOT];   /* BW columns of nr values each, column-major */
    long slot_b[NSLOT];    /* block column index held */
    unsigned long used[NSLOT];
    int ok[NSLOT];
} level_t;

struct sf_noise {
    int L;
    uint64_t key;
    gsl_rng *rng;
    unsigned long clock;
    level_t lv[SF_NOISE_MAX_LEVEL + 1];
};

int sf_noise_level(double l, int *level, double *h)
{
    double lo = l / (8 * M_SQRT2), c = SF_NOISE_H0;
    if (!(l > 0) || !isfinite(l) || c < lo)
        return SF_EINVAL;
    int L = 0;
    while (c / 2 >= lo && L < SF_NOISE_MAX_LEVEL) {
        c /= 2;
        L++;
    }
    if (c / 2 >= lo)   /* finer than the deepest level */
        return SF_EINVAL;
    *level = L;
    *h = c;
    return SF_SUCCESS;
}

static long floordiv(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

int sf_noise_alloc(int level, long row_lo, size_t nrows, sf_noise **out)
{
    *out = NULL;
    if (nrows == 0 || level < 0 || level > SF_NOISE_MAX_LEVEL)
        return SF_EINVAL;
    sf_noise *z = sf_calloc(1, sizeof *z);
    if (!z)
        return SF_ENOMEM;
    z->L = level;
    z->rng = SF_FALLIBLE(gsl_rng_alloc(sf_rng_splitmix64));
    int rc = z->rng ? SF_SUCCESS : SF_ENOMEM;
    long r0 = row_lo, r1 = row_lo + (long)nrows - 1;
    for (int k = level; k >= 0 && !rc; k--) {
        level_t *v = &z->lv[k];
        v->r0 = r0;
        v->nr = (size_t)(r1 - r0 + 1);
        for (int s = 0; s < NSLOT && !rc; s++)
            if (!(v->slot[s] = sf_malloc((size_t)BW * v->nr * sizeof *v->slot[s])))
                rc = SF_ENOMEM;
        r0 = floordiv(r0, 2);   /* the parents' rows */
        r1 = floordiv(r1, 2);
    }
    if (rc) {
        sf_noise_free(z);
        return rc;
    }
    *out = z;
    return SF_SUCCESS;
}

void sf_noise_free(sf_noise *z)
{
    if (!z)
        return;
    for (int k = 0; k <= SF_NOISE_MAX_LEVEL; k++)
        for (int s = 0; s < NSLOT; s++)
            free(z->lv[k].slot[s]);
    gsl_rng_free(z->rng);
    free(z);
}

void sf_noise_set_key(sf_noise *z, uint64_t key)
{
    z->key = key;
    for (int k = 0; k <= z->L; k++)
        memset(z->lv[k].ok, 0, sizeof z->lv[k].ok);
}

/* SplitMix64's finaliser (Steele, Lea & Flood 2014) */
static uint64_t mix(uint64_t x)
{
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/* The stream of cell (i, j)'s draws at level k: a hash of (key, k, i, j). */
static void seed_cell(sf_noise *z, int k, long i, long j)
{
    uint64_t x = mix(z->key ^ (0x9e3779b97f4a7c15ULL * (uint64_t)(k + 1)));
    x = mix(x + 0xd1b54a32d192ed03ULL * (uint64_t)i);
    x = mix(x ^ (0x8cb92ba72f3d8dd7ULL * (uint64_t)j));
    gsl_rng_set(z->rng, (unsigned long)x);
}

static const double *block(sf_noise *z, int k, long b);

/* Make block column b of level k into slot buffer g. */
static void make_block(sf_noise *z, int k, long b, double *g)
{
    const level_t *v = &z->lv[k];
    if (k == 0) {   /* the root: every cell drawn alone */
        for (size_t c = 0; c < BW; c++)
            for (size_t r = 0; r < v->nr; r++) {
                seed_cell(z, 0, b * BW + (long)c, v->r0 + (long)r);
                g[c * v->nr + r] = gsl_ran_gaussian_ziggurat(z->rng, 1.0);
            }
        return;
    }
    long pb = floordiv(b, 2);
    const double *pg = block(z, k - 1, pb);   /* made before this level's slot is written: no aliasing */
    const level_t *pv = &z->lv[k - 1];
    long i0 = b * BW;   /* first cell column of the block */
    for (size_t pc = 0; pc < BW / 2; pc++) {
        long I = floordiv(i0, 2) + (long)pc;   /* parent column */
        const double *pcol = pg + (size_t)(I - pb * BW) * pv->nr;
        for (size_t pr = 0; pr < pv->nr; pr++) {
            long J = pv->r0 + (long)pr;
            seed_cell(z, k, I, J);
            double p = pcol[pr], e1 = gsl_ran_gaussian_ziggurat(z->rng, 1.0),
                   e2 = gsl_ran_gaussian_ziggurat(z->rng, 1.0), e3 = gsl_ran_gaussian_ziggurat(z->rng, 1.0);
            double q[4] = { p + e1 + e2 + e3, p - e1 + e2 - e3, p + e1 - e2 - e3, p - e1 - e2 + e3 };
            for (int ab = 0; ab < 4; ab++) {   /* child (2I + a, 2J + b): a = ab & 1, b = ab >> 1 */
                long r = 2 * J + (ab >> 1) - v->r0;
                if (r < 0 || r >= (long)v->nr)
                    continue;
                size_t c = (size_t)(2 * I + (ab & 1) - i0);
                g[c * v->nr + (size_t)r] = 0.5 * q[ab];
            }
        }
    }
}

/* Block column b of level k, from the cache or made (least recently used
 * slot). */
static const double *block(sf_noise *z, int k, long b)
{
    level_t *v = &z->lv[k];
    int s = -1;
    for (int t = 0; t < NSLOT; t++)
        if (v->ok[t] && v->slot_b[t] == b)
            s = t;
    if (s < 0) {
        s = 0;
        for (int t = 1; t < NSLOT; t++)
            if (!v->ok[t] || (v->ok[s] && v->used[t] < v->used[s]))
                s = t;
        make_block(z, k, b, v->slot[s]);
        v->ok[s] = 1;
        v->slot_b[s] = b;
    }
    v->used[s] = ++z->clock;
    return v->slot[s];
}

const double *sf_noise_column(sf_noise *z, long i)
{
    long b = floordiv(i, BW);
    return block(z, z->L, b) + (size_t)(i - b * BW) * z->lv[z->L].nr;
}
