/* slipfield: the static COF mu_s seen by the disc, in belt coordinates.
 *
 * Belt-fixed frame (paper Sec. 2.1): the belt point under the disc centre
 * at time t is (xb, yb) = (x - v_b t, y); the disc starts over the origin
 * and the belt carries the pattern in +x, so xb decreases during a run.
 * Three kinds, cheapest first: uniform, one random variable (uniform value
 * drawn once per realisation), a lognormal field sampled on the strip of
 * belt that passes under the disc, interpolated bilinearly in between.
 * The kinetic COF is mu_k = ratio * mu_s locally (Eq. 1).
 */
#ifndef SF_COF_H
#define SF_COF_H

#include <stddef.h>

typedef enum { SF_COF_UNIFORM = 0, SF_COF_VARIABLE = 1, SF_COF_FIELD = 2 } sf_cof_kind;

typedef struct sf_cof sf_cof;

/* Uniform (or one random variable already drawn): mu_s everywhere. */
int sf_cof_alloc_uniform(double mu_s, sf_cof **out);

/* Gridded field: mu_s[i + m*j] at (x0 + i dx, y0 + j dy); copied. */
int sf_cof_alloc_grid(size_t m, size_t n, double x0, double y0,
                      double dx, double dy, const double *mu_s, sf_cof **out);

void sf_cof_free(sf_cof *c);
sf_cof_kind sf_cof_get_kind(const sf_cof *c);

/* mu_s at belt point (xb, yb); bilinear on a grid.  Points outside the
 * grid are clamped to its edge (callers size the strip so that this does
 * not happen; sf_cof_outside() counts how often it did). */
double sf_cof_eval(const sf_cof *c, double xb, double yb);
unsigned long sf_cof_outside(const sf_cof *c);

#endif
