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
#include <gsl/gsl_rng.h>
#include "scene.h"

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
 * grid are clamped to its edge; sf_cof_outside() counts how often.  Such
 * look-ups are harmless at the trial stages of a step the error control
 * rejects (they can lie far off the path); what must stay on the grid is
 * the accepted path: sf_cof_covers(). */
double sf_cof_eval(const sf_cof *c, double xb, double yb);
unsigned long sf_cof_outside(const sf_cof *c);

/* 1 when the disc of radius r centred at belt point (xb, yb) lies on the
 * grid (always, for a uniform COF). */
int sf_cof_covers(const sf_cof *c, double xb, double yb, double r);

/* Read-only view of a gridded COF (verification reads the drawn strip
 * through it): m x n nodes at (x0 + i dx, y0 + j dy), values
 * (*mu)[i + m*j], owned by c and valid while c lives.  SF_EINVAL (outputs
 * untouched) for a uniform or one-variable COF.  Any output may be NULL. */
int sf_cof_grid_view(const sf_cof *c, size_t *m, size_t *n, double *x0, double *y0, double *dx, double *dy,
                     const double **mu);

/* ---- The COF of a run, planned once per scene, drawn per realisation.
 *
 * The plan decides what a scene needs (one place): cof = uniform draws
 * nothing; variable draws one lognormal value; field samples a lognormal
 * field on the belt strip the disc can visit during [0, T]:
 *   xb in [-v_b T - B, B],  yb in [-W, W],
 *   B = R + 2 mu_hi m g / k + 2 h,  W = strip_halfwidth + R + 2 h (0: W = B),
 * where 2 mu_hi m g / k (mu_hi = mu_mean + 4 mu_std) bounds the spring
 * excursion |r| (the spring force never exceeds twice the largest
 * friction force it balances).  Grid spacing h = l/8: bilinear
 * interpolation then costs 0.7% of the field's std, RMS
 * (cases/contact/interpolation).  A grid above SF_COF_MAX_POINTS is
 * refused with SF_ECAP and the reason in err.
 * Shortcut: when the strip's diagonal E is so short against l that any
 * two of its points have correlation >= 1 - 1e-6 ((E/l)^2 <= 1e-6), the
 * field is one random variable over the run and the plan draws one
 * (kind SF_COF_VARIABLE; info.shortcut = 1); so it does when mu_std = 0.
 * A scene with shortcuts = false gets the field whatever l and E
 * (cases/plan verify the shortcut against it). */
#define SF_COF_SHORTCUT_E2 1e-6
typedef struct sf_cof_plan sf_cof_plan;

typedef struct {
    sf_cof_kind kind;
    double x0, y0, dx, dy;   /* strip origin and spacing [m] */
    size_t nx, ny;           /* strip grid points */
    double bound;            /* B [m] */
    int shortcut;            /* 1: a field scene planned as one variable */
    double strip_diag;       /* E: diagonal of the strip the disc can visit [m] (field scenes) */
} sf_cof_plan_info;

int sf_cof_plan_alloc(const sf_scene *s, sf_cof_plan **out, char *err, size_t errlen);
void sf_cof_plan_free(sf_cof_plan *p);
const sf_cof_plan_info *sf_cof_plan_get_info(const sf_cof_plan *p);
/* One realisation from rng (nothing is drawn for a uniform COF).  A
 * function of the rng state alone: no field is carried over between
 * draws (each costs one FFT of which the second field is discarded). */
int sf_cof_plan_draw(sf_cof_plan *p, gsl_rng *rng, sf_cof **out);

/* Convenience: plan, draw one realisation, free the plan. */
int sf_cof_from_scene(const sf_scene *s, gsl_rng *rng, sf_cof **out);

/* The largest number of strip grid points a plan accepts. */
#define SF_COF_MAX_POINTS ((size_t)1 << 24)

#endif
