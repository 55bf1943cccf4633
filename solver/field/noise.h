/* slipfield: white noise fixed in belt coordinates, at any resolution
 * (cof_generator = belt_noise).
 *
 * Why.  A field drawn from a random stream on a grid that the scene's
 * parameters set (spacing l/8, a strip or window sized from l, v_b and
 * the COF's spread) is another field whenever a parameter moves: the
 * stream is the same, the map from stream to field is not.  A study that
 * treats "the field" as one input (a Sobol' design keeps it while a
 * parameter changes) then credits the field's variance to the parameter.
 * Here the random input is a white noise W on the belt plane, the same for
 * every parameter; a scene builds its Gaussian field from it by the
 * convolution of tiles.h, G = k_l * W (Eq. 2's covariance exactly for
 * any l), so G moves continuously with l and not at all with v_b, the
 * CV or the mean COF (the lognormal map is pointwise; v_b only changes
 * which belt points the disc visits).
 *
 * The noise.  Dyadic cells of side h_L = SF_NOISE_H0 2^-L [m] (level L >=
 * 0), cell (i, j) = [i h_L, (i + 1) h_L) x [j h_L, (j + 1) h_L) for any
 * integers i, j: its value z = W(cell) / h_L is standard normal, and the
 * levels are one white noise (a cell's integral is the sum of its four
 * children's).  They are made top-down (the Haar / Levy construction): a
 * root cell's z is drawn, and a cell of level L - 1 with value p gives its
 * children (2i + a, 2j + b), a, b in {0, 1},
 *
 *   z = (p + s_a e1 + s_b e2 + s_a s_b e3) / 2,   s_0 = 1, s_1 = -1,
 *
 * e1, e2, e3 standard normals of that parent cell: the 4 x 4 matrix
 * [1 s_a s_b s_a s_b] / 2 is orthogonal, so the children are independent
 * standard normals whose sum is 2 p (= W(parent) / h_(L-1) in the
 * children's units).  Every draw is keyed by (key, level, cell) through
 * a SplitMix64 hash (tiles.h's generator): a cell's value is a function
 * of (key, L, i, j) alone, whatever was made before and whatever the
 * thread count.
 *
 * The level of a correlation length l: the finest with h_L >= l / 8 /
 * sqrt 2, so l / h_L lies in (4 sqrt 2, 8 sqrt 2] (5.66 to 11.3; the
 * point model's l/8 in geometric mean).  At that spacing the tiles'
 * convolution reproduces Eq. 2 to round-off (tiles.h), and at a switch of
 * level the two fields at one belt point correlate to 0.996 or more
 * (docs/design.md sec. 7.8): the only place where the field moves by more
 * than the kernel's change. */
#ifndef SF_NOISE_H
#define SF_NOISE_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdint.h>

#define SF_NOISE_H0 1024.0      /* root cell side [m] */
#define SF_NOISE_MAX_LEVEL 48   /* h = 3.6e-12 m */

/* The level of correlation length l [m] and its cell side *h [m].
 * SF_EINVAL (outputs untouched) for l not finite and positive, above
 * 8 sqrt(2) SF_NOISE_H0 (11.6 km) or below the finest level's scale. */
int sf_noise_level(double l, int *level, double *h);

typedef struct sf_noise sf_noise;

/* The cells of rows [row_lo, row_lo + nrows) at `level`, column by
 * column.  SF_EINVAL for nrows = 0 or a level outside [0, MAX_LEVEL]. */
int sf_noise_alloc(int level, long row_lo, size_t nrows, sf_noise **out);
void sf_noise_free(sf_noise *z);
/* The realisation: every cell's value is a function of (key, cell). */
void sf_noise_set_key(sf_noise *z, uint64_t key);
/* Column i's nrows values (row row_lo first), valid until the next call
 * (made once a block of columns: no allocation, no failure). */
const double *sf_noise_column(sf_noise *z, long i);

#ifdef __cplusplus
}
#endif
#endif
