/* slipfield: Monte Carlo sweeps of the stochastic oscillator (Sec. 3).
 *
 * At each parameter value: the deterministic reference (uniform COF at
 * mu_mean, same T, t_skip, eps_lambda and stepper: the same QoI
 * definitions over the same window [t_skip, T], so ratios compare like
 * with like; under the default qoi_def = paper the stick-fraction ratio is
 * the paper's T_sk,s / T_sk,d), then N realisations
 * (montecarlo.h: realisation i has its own stream, OpenMP, checkpoint),
 * each giving the ratios pv_x / pv_x,det, pv_F / pv_F,det and
 * stick_fraction / stick_fraction,det.
 *
 * Parameters: any numeric scene key, plus `l_over_R` (sets l = value x R,
 * dimensionless) and `mu_mean` at fixed CV (mu_std scales with it, as in
 * Fig. 13).
 */
#ifndef SF_SWEEP_H
#define SF_SWEEP_H

#include <stddef.h>
#include "scene.h"

enum { SF_SWEEP_PVX = 0, SF_SWEEP_PVF = 1, SF_SWEEP_SF = 2, SF_SWEEP_NQ = 3 };

typedef struct {
    double det[SF_SWEEP_NQ];    /* deterministic pv_x [m], pv_F [N], stick fraction [-] */
    double *ratio;              /* n x SF_SWEEP_NQ, realisation-major */
    double mean[SF_SWEEP_NQ], std[SF_SWEEP_NQ];   /* over the realisations with a finite ratio */
    size_t n, from_checkpoint;
    size_t n_valid;             /* realisations with a finite PV_x ratio (paper definitions: all
                                   but those with no whole oscillation in [t_skip, T]) */
} sf_sweep_point;

/* Apply parameter `name` = value to s (SF_EPARSE with the reason). */
int sf_sweep_set(sf_scene *s, const char *name, double value, char *err, size_t errlen);

/* Run one sweep point. checkpoint may be NULL. threads 0: default. */
int sf_sweep_run(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume,
                 const char *label, sf_sweep_point *out, char *err, size_t errlen);
void sf_sweep_point_free(sf_sweep_point *p);

#endif
