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
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdint.h>
#include <gsl/gsl_rng.h>
#include "scene.h"
#include "numplan.h"   /* sf_cof_kind, sf_cof_plan_info: the plan decides, this module builds */

typedef struct sf_cof sf_cof;

/* Uniform (or one random variable already drawn): mu_s everywhere. */
int sf_cof_alloc_uniform(double mu_s, sf_cof **out);

/* Gridded field: mu_s[i + m*j] at (x0 + i dx, y0 + j dy); copied. */
int sf_cof_alloc_grid(size_t m, size_t n, double x0, double y0,
                      double dx, double dy, const double *mu_s, sf_cof **out);

void sf_cof_free(sf_cof *c);
sf_cof_kind sf_cof_get_kind(const sf_cof *c);

/* mu_s at belt point (xb, yb); bilinear on a grid.  Points outside the
 * grid are clamped to its edge; sf_cof_outside() counts how often.  Such
 * look-ups are harmless at the trial stages of a step the error control
 * rejects (they can lie far off the path); what must stay on the grid is
 * the accepted path: sf_cof_covers(). */
double sf_cof_eval(const sf_cof *c, double xb, double yb);
unsigned long sf_cof_outside(const sf_cof *c);

/* Read-only view of a gridded COF's values (the check of cases/mms does
 * its own bilinear look-up from them): mu_s[i + m*j] at (x0 + i dx,
 * y0 + j dy), valid while c lives.  SF_EINVAL (outputs untouched) for a
 * COF that is not a grid.  Any output may be NULL. */
int sf_cof_grid_view(const sf_cof *c, size_t *m, size_t *n, double *x0, double *y0, double *dx, double *dy,
                     const double **mu);

/* A read-only view of a gridded COF for look-ups inlined in a hot loop
 * (the wrench's cell loop: a call per cell to another translation unit
 * costs more than the interpolation).  Read it afresh at every use, never
 * cache it: a COF may move its grid window (a belt field that slides its
 * window along the belt).  sf_cof_get_view returns 1 and fills *v for a
 * grid (its points are int-indexable: sf_cof_alloc_grid refuses more than
 * INT_MAX), 0 otherwise (uniform, variable: use sf_cof_eval; a field
 * kind that returns 0 gets the wrench's cell-by-cell sf_cof_eval loop,
 * correct but about 5x slower).  Look-ups
 * clamped to the grid's edge are counted by the caller and reported with
 * sf_cof_count_outside (so sf_cof_outside stays the count of them all). */
typedef struct {
    const double *grid;     /* m*n values, x fastest */
    int m, n;               /* grid points along x, y */
    double x0, y0;          /* origin [m] */
    double idx, idy;        /* 1 / spacing [1/m] */
} sf_cof_view;

int sf_cof_get_view(const sf_cof *c, sf_cof_view *v);
void sf_cof_count_outside(const sf_cof *c, unsigned long n);

/* The one definition of the interpolation (sf_cof_eval and the wrench's
 * loop use these; sf_cof_view_eval_on8 below repeats sf_cof_view_eval_on's
 * operations 8 points at a time for AVX-512), written for a loop calling
 * them to vectorise: selects,
 * no branches; int indices into the grid (gathers); the clamp flag a
 * double (an int among the doubles keeps GCC 12 from vectorising).
 * sf_cof_view_cell: bilinear in grid cell (i, j) at grid coordinates
 * (sx, sy); sf_cof_view_at: at (sx, sy) in [0, m-1] x [0, n-1]. */
static inline double sf_cof_view_cell(const sf_cof_view *v, int i, int j, double sx, double sy)
{
    double tx = sx - (double)i, ty = sy - (double)j;
    int k0 = i + v->m * j, k1 = k0 + 1, k2 = k0 + v->m, k3 = k2 + 1;
    const double *g = v->grid;
    double a = g[k0] + tx * (g[k1] - g[k0]);
    double b = g[k2] + tx * (g[k3] - g[k2]);
    return a + ty * (b - a);
}

static inline double sf_cof_view_at(const sf_cof_view *v, double sx, double sy)
{
    int i = (int)sx, j = (int)sy;
    i = i < v->m - 2 ? i : v->m - 2;   /* the last node: the last cell at t = 1 */
    j = j < v->n - 2 ? j : v->n - 2;
    return sf_cof_view_cell(v, i, j, sx, sy);
}

/* Grid coordinates of belt point xb (resp. yb) [-]. */
static inline double sf_cof_view_gx(const sf_cof_view *v, double xb) { return (xb - v->x0) * v->idx; }
static inline double sf_cof_view_gy(const sf_cof_view *v, double yb) { return (yb - v->y0) * v->idy; }

/* mu_s at belt point (xb, yb), clamped to the grid's edge (*clamped = 1
 * then, else 0; NaN clamps to the origin). */
static inline double sf_cof_view_eval(const sf_cof_view *v, double xb, double yb, double *clamped)
{
    double sx = sf_cof_view_gx(v, xb), sy = sf_cof_view_gy(v, yb);
    double xm = (double)(v->m - 1), ym = (double)(v->n - 1);
    *clamped = (!(sx >= 0) | (sx > xm) | !(sy >= 0) | (sy > ym)) ? 1.0 : 0.0;
    sx = sx >= 0 ? sx : 0;   /* also NaN */
    sy = sy >= 0 ? sy : 0;
    sx = sx <= xm ? sx : xm;
    sy = sy <= ym ? sy : ym;
    return sf_cof_view_at(v, sx, sy);
}

/* The same for a point known to lie on the grid (sf_cof_view_holds):
 * no clamping, the same bits as sf_cof_view_eval there.  Nor the last-node
 * clamp of sf_cof_view_at: the spare cell of sf_cof_view_holds keeps the
 * grid coordinates below m - 1 and n - 1, where (int) already gives a
 * cell index <= m - 2, n - 2 (the same cell, so the same bits). */
static inline double sf_cof_view_eval_on(const sf_cof_view *v, double xb, double yb)
{
    double sx = sf_cof_view_gx(v, xb), sy = sf_cof_view_gy(v, yb);
    return sf_cof_view_cell(v, (int)sx, (int)sy, sx, sy);
}

/* The same look-up for 8 points at once (AVX-512) or 4 (AVX2): cof_x512.h,
 * a private header of the solver (not installed: no SIMD in the public
 * headers). */

/* 1 when every point within r (per axis) of (xb, yb) lies on the grid
 * with a grid cell to spare (the spare cell absorbs the rounding of the
 * grid coordinates): there sf_cof_view_eval_on needs no clamp. */
static inline int sf_cof_view_holds(const sf_cof_view *v, double xb, double yb, double r)
{
    return (xb - r - v->x0) * v->idx >= 1 && (xb + r - v->x0) * v->idx <= (double)(v->m - 2) &&
           (yb - r - v->y0) * v->idy >= 1 && (yb + r - v->y0) * v->idy <= (double)(v->n - 2);
}

/* A gridded COF whose values are cell averages over squares of side
 * box [m] (cof_model = cell_average, cellavg.h; sf_osc_alloc then runs the
 * matching Cartesian quadrature): sf_cof_box() returns it, 0 for point
 * values.  sf_cof_set_box marks a grid so (SF_EINVAL for a non-grid). */
double sf_cof_box(const sf_cof *c);
/* A tiled or belt-noise window's realisation key (its fields are functions
 * of the key and the belt point: cof.c), 0 for any other COF. */
uint64_t sf_cof_key(const sf_cof *c);
int sf_cof_set_box(sf_cof *c, double box);

/* 1 when the disc of radius r centred at belt point (xb, yb) lies on the
 * grid (always, for a uniform COF). */
int sf_cof_covers(const sf_cof *c, double xb, double yb, double r);

/* ---- Tiled fields (cof_generator = tiles, tiles.h): the grid is a
 * window of nx x ny points on the lattice x = i l/8 (any integer i), y =
 * y0 + j l/8, that slides along the belt.  Its values are a function of
 * (realisation key, lattice point) alone, so the window is a cache of one
 * field: sliding changes what is held, never a node value (between nodes
 * the bilinear weights come from (x - x0)/dx and may round differently
 * for another origin: the last bits of a look-up depend on where the
 * window stands, which is itself a function of the run), and the grid
 * interface (grid, x0, y0, dx, dy, nx, ny) stays that of a grid.
 * sf_cof_follow() makes the window hold belt x in [xlo, xhi] (all rows),
 * sliding it if needed: SF_SUCCESS (also for non-window COFs, which
 * hold what they hold), SF_ETOOBIG when [xlo, xhi] is wider than the window.
 * The oscillator calls it before every step with the disc's footprint
 * plus a margin M = sf_cof_window_margin() (0: not a window) and caps the
 * step so that the disc moves by less than M/2 (oscillator.c). */
int sf_cof_follow(const sf_cof *c, double xlo, double xhi);
double sf_cof_window_margin(const sf_cof *c);
/* The largest mu_s held (uniform: mu_s). */
double sf_cof_max(const sf_cof *c);
/* Grid points held (0 for a uniform COF); slides so far; lattice columns
 * made (the first fill included; not those copied from an antithetic
 * partner's kept columns, sf_cof_plan_keep_columns). */
size_t sf_cof_points_held(const sf_cof *c);
unsigned long sf_cof_slides(const sf_cof *c);
/* sf_cof_grid_view() (above) gives a window's values too: valid until
 * the next sf_cof_follow(). */
size_t sf_cof_columns_made(const sf_cof *c);

/* ---- The COF of a run, planned once per scene, drawn per realisation.
 * What a scene's COF is (uniform, one variable, a field on the belt strip,
 * by circulant embedding or tiles; its grid and bounds) is decided by the
 * plan (numplan.h: sf_cof_plan_info, sf_plan_cof); this module builds it
 * and draws realisations from it. */
typedef struct sf_cof_plan sf_cof_plan;

/* The COF plan of plan pl (made from scene s: sf_plan_make), built:
 * the field generator and its FFTW plans.  Its refusals: SF_ENOMEM, a
 * generator that cannot be planned (the embedding over its cap:
 * SF_ETOOBIG), a plan made from another scene (SF_EINVAL). */
int sf_cof_plan_build(const sf_scene *s, const sf_plan *pl, sf_cof_plan **out, char *err, size_t errlen);
/* The same, planning the COF's part of scene s first (sf_plan_cof). */
int sf_cof_plan_alloc(const sf_scene *s, sf_cof_plan **out, char *err, size_t errlen);
void sf_cof_plan_free(sf_cof_plan *p);
/* The same from a thread of an OpenMP team (a Monte Carlo workspace):
 * FFTW's planner is not thread-safe, so plans are made and freed one at a
 * time, in the library's one critical section for FFTW planning. */
int sf_cof_plan_alloc_mt(const sf_scene *s, sf_cof_plan **out, char *err, size_t errlen);
void sf_cof_plan_free_mt(sf_cof_plan *p);
int sf_cof_plan_build_mt(const sf_scene *s, const sf_plan *pl, sf_cof_plan **out, char *err, size_t errlen);
const sf_cof_plan_info *sf_cof_plan_get_info(const sf_cof_plan *p);
/* 1 when the field's circulant embedding reached its padding cap (the
 * scene's pad_cap) and its negative eigenvalues were clamped: a usable
 * plan whose covariance departs from Eq. 2's (`slipfield field` measures
 * by how much); 0 otherwise, and for COFs drawn without an embedding. */
int sf_cof_plan_truncated(const sf_cof_plan *p);
/* cof_model = cell_average (info.box > 0): the effective field's std
 * sqrt(Var mu_h) and its Gaussian plan (field.h: covariance, target;
 * planned with defer_covariance: sf_field_measure_covariance before
 * reading either); 0 and NULL otherwise. */
double sf_cof_plan_cell_std(const sf_cof_plan *p);
struct sf_field *sf_cof_plan_cell_field(const sf_cof_plan *p);
/* One realisation from rng (nothing is drawn for a uniform COF, and rng
 * may be NULL there; SF_EINVAL for a NULL rng otherwise).  A function of
 * the rng state alone: no field is carried over between draws (the cell
 * averages' draw is one real FFT, the lognormal strip's one complex FFT
 * of which the second field is not extracted).
 * Tiles (info.generator = SF_COFGEN_TILES): the draw takes the 64-bit key
 * of the realisation from two gsl_rng_get calls and returns a window of
 * info.nx x info.ny points over the disc at the origin; the rest of the
 * belt is made as sf_cof_follow() asks for it (the oscillator does). */
int sf_cof_plan_draw(sf_cof_plan *p, gsl_rng *rng, sf_cof **out);

/* cof_generator = belt_noise: the COF that sf_cof_plan_draw(p, rng)
 * would draw, at the one belt point (xb, yb), without its window (the
 * four lattice nodes around the point, interpolated bilinearly as the
 * window does: the same node values, the weights to the last bits).  A
 * functional of the field at a point costs about 10^4 noise cells
 * instead of a window over the disc.  Takes the key from rng as the draw
 * does.  SF_EINVAL for another generator or a point off the lattice's
 * range. */
int sf_cof_plan_point(const sf_cof_plan *p, gsl_rng *rng, double xb, double yb, double *mu);

/* The antithetic of COF c, which plan p drew: the same realisation with
 * its Gaussian values negated, G -> -G, before the marginal map (the
 * lognormal strip: exp(2 mu_g) / mu at each node; cell averages:
 * 2 mubar - mu; tiles: the same key, -G; one variable: exp(2 mu_g) / mu;
 * uniform: itself).  -G has G's law, so the antithetic is a realisation
 * of the same model, drawn at no cost of the generator (tiles: the
 * partner window copies the Gaussian columns c made, and has made, when
 * p keeps columns, and makes the others again as it slides).  SF_EINVAL
 * for a COF of another kind or generator than p's. */
int sf_cof_plan_antithetic(const sf_cof_plan *p, const sf_cof *c, sf_cof **out);

/* Tiles: each window p draws from now on keeps the Gaussian columns it
 * makes for its antithetic partner, which shares them (on: 1; off: 0):
 * at most 2^22 values, columns beyond are made again by the partner.
 * The values are the same bits either way; a draw or a follow that
 * cannot grow the store fails with SF_ENOMEM. */
void sf_cof_plan_keep_columns(sf_cof_plan *p, int on);
/* Boxes of boxes (cell averages only, cellavg.h).  The average of the
 * field over a box of side b h is the mean of the b^2 averages over the
 * boxes of side h that tile it, and the covariance is linear in the
 * field, so the means of b x b fine node values 3 nodes apart (a node
 * spacing is box / 3) have exactly the mean, covariance and Gaussian law
 * of the cell-average model at box b h, on a grid of spacing b h / 3
 * whose nodes are the big boxes' centres.  sf_cof_box_grid: that grid
 * from a cell-average plan's strip `fine` (coarse->box = b fine->box,
 * the rest of *coarse copied from *fine); SF_EINVAL unless fine is cell
 * averages with at least 3 (b - 1) + 2 nodes a side and b >= 2.
 * sf_cof_box_means: the coarse COF derived from a drawn cell-average COF
 * c, on exactly that grid. */
int sf_cof_box_grid(const sf_cof_plan_info *fine, size_t b, sf_cof_plan_info *coarse);
int sf_cof_box_means(const sf_cof *c, size_t b, sf_cof **out);
/* Every k-th node (point values on the circulant strip).  The field at
 * every k-th node of the fine grid has exactly the law of the field drawn
 * on the k-times coarser grid (the same covariance at the same points,
 * before and after the pointwise marginal map).  sf_cof_sub_grid: that
 * grid from a point-value strip `fine` (nodes 0, k, 2k, ... in x and y;
 * the rest of *coarse copied); SF_EINVAL for cell averages, tiles, k < 2
 * or fewer than 2 coarse nodes a side.  sf_cof_subsample: the coarse COF
 * of a drawn point-value grid c, on exactly that grid. */
int sf_cof_sub_grid(const sf_cof_plan_info *fine, size_t k, sf_cof_plan_info *coarse);
int sf_cof_subsample(const sf_cof *c, size_t k, sf_cof **out);
/* Convenience: plan, draw one realisation, free the plan. */
int sf_cof_from_scene(const sf_scene *s, gsl_rng *rng, sf_cof **out);

/* The strip's bounds and points (numplan.h: sf_plan_strip_bounds,
 * sf_plan_strip_points), under their former names. */
void sf_cof_strip_bounds(const sf_scene *s, double *B0, double *W0);
double sf_cof_strip_points(const sf_scene *s, double h);

#ifdef __cplusplus
}
#endif
#endif
