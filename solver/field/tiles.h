/* slipfield: a Gaussian field with the covariance of Eq. 2 generated on
 * demand, column by column, from white noise in tiles (a belt
 * without end; docs/design.md sec. 4.3).
 *
 * The squared-exponential kernel's square root is a squared exponential:
 * exp(-r^2/a^2) convolved with itself is proportional to
 * exp(-r^2/(2 a^2)).  White noise convolved with the normalised kernel of
 * length a = l/sqrt(2) therefore has covariance exp(-r^2/l^2) (Eq. 2).  On
 * a lattice (spacings dx, dy) with the kernel sampled and truncated at
 * `trunc` a (default 6: the kernel is below 2.4e-16 of its peak there):
 *
 *   Y(i, j) = sum_{b=-Ky..Ky} wy(b) xi(i, j - b),
 *   G(i, j) = sum_{a=-Kx..Kx} wx(a) Y(i - a, j),
 *   w(a) = exp(-(a h)^2 / a^2) / sqrt(sum_a exp(-2 (a h)^2 / a^2)),
 *
 * and the covariance it produces is exactly (no sampling, a finite sum)
 *   Cov(G(i, j), G(i + p, j + q)) = Cx(p) Cy(q),  C(p) = sum_a w(a) w(a + p),
 * which sf_tiles_covariance() returns for comparison with Eq. 2
 * (cases/field/tiles-exact-covariance).  Aliasing of the sampled kernel is
 * far below round-off for spacings up to l/4 (Poisson summation; docs/design.md
 * sec. 4.3).
 *
 * Noise.  Column i of the lattice (any integer, negative included) lies in
 * tile t = floor(i / tile_cols); a tile's noise is tile_cols columns of
 * nyp + 2 Ky standard normals, nyp = ny rounded up to a multiple of 16
 * (column by column, the row index fastest; row r is lattice row r - Ky),
 * drawn with gsl_ran_gaussian_ziggurat from
 * one gsl_rng of type sf_rng_splitmix64 seeded with sf_tiles_tile_seed(key,
 * t).  So any column is a function of (key, i) alone: random access, the
 * same bits whatever was generated before and whatever the thread count.
 * SplitMix64 (Steele, Lea & Flood 2014; the seeding generator of
 * xoshiro, passes BigCrush) is used because GSL has no counter-based
 * generator and its own generators take at most 32 bits of seed: with a
 * 64-bit seed per tile, two tiles of a run share a stream with probability
 * about (tiles)^2 / 2^64.
 */
#ifndef SF_TILES_H
#define SF_TILES_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdint.h>
#include <gsl/gsl_rng.h>

typedef struct {
    size_t ny;          /* lattice rows (>= 1) */
    double dx, dy;      /* lattice spacings [m] (> 0) */
    double l;           /* correlation length of Eq. 2 [m] (> 0) */
    double trunc;       /* kernel support as a multiple of l/sqrt(2); 0 -> 6 */
    size_t tile_cols;   /* columns per noise tile; 0 -> 64 */
} sf_tiles_spec;

typedef struct sf_tiles sf_tiles;

int sf_tiles_alloc(const sf_tiles_spec *spec, sf_tiles **out);
void sf_tiles_free(sf_tiles *t);

/* The realisation: every column is a function of (key, column index). */
void sf_tiles_set_key(sf_tiles *t, uint64_t key);

/* G at lattice columns i0 .. i0+m-1, rows 0 .. ny-1, into
 * out[c + ld * j] (c < m, ld >= m).  Each value is computed by the same
 * operations in the same order wherever the range starts. */
int sf_tiles_fill(sf_tiles *t, long i0, size_t m, double *out, size_t ld);

/* Another source of the noise (noise.h's belt noise): fn(ctx, i) returns
 * lattice column i's nr standard normals, nr = sf_tiles_noise_rows (row r
 * is lattice row r - Ky), valid until its next call; NULL: the tiles'
 * own.  The convolution, its weights and its covariance are unchanged. */
typedef const double *(*sf_tiles_noise_fn)(void *ctx, long i);
void sf_tiles_set_noise(sf_tiles *t, sf_tiles_noise_fn fn, void *ctx);
size_t sf_tiles_noise_rows(const sf_tiles *t, size_t *ky);

/* The produced covariance at lattice lag (p, q): Cx(p) Cy(q), exact. */
double sf_tiles_covariance(const sf_tiles *t, long p, long q);

/* Kernel weights along an axis (0: x, 1: y): w[a + K], a = -K..K. */
const double *sf_tiles_weights(const sf_tiles *t, int axis, size_t *K);

size_t sf_tiles_tile_cols(const sf_tiles *t);

/* The seed of tile `tile` of realisation `key` (a SplitMix64 hash). */
uint64_t sf_tiles_tile_seed(uint64_t key, long tile);

/* The generator the tiles draw from: SplitMix64, 32-bit outputs (the
 * high half) for gsl_rng_get, 53-bit doubles for gsl_rng_uniform; the
 * 64-bit state is the seed (unsigned long is 64 bits on the LP64 systems
 * slipfield builds on). */
extern const gsl_rng_type *sf_rng_splitmix64;

#ifdef __cplusplus
}
#endif
#endif
