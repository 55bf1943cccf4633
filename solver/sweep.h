/* slipfield: Monte Carlo sweeps of the stochastic oscillator (Sec. 3).
 *
 * At each parameter value: the deterministic reference (uniform COF at
 * mu_mean, same T, t_skip, eps_lambda and stepper: the same QoI
 * definitions over the same window [t_skip, T], so ratios compare like
 * with like; under the default qoi_def = paper the stick-fraction ratio is
 * the paper's T_sk,s / T_sk,d), then N realisations
 * (montecarlo.h: realisation i has its own stream, OpenMP, checkpoint),
 * each giving pv_x [m], pv_F [N] and the stick fraction [-], and their
 * ratios to the deterministic values.
 *
 * Parameters: any numeric scene key, plus `l_over_R` (sets l = value x R,
 * dimensionless) and `mu_mean` at fixed CV (mu_std scales with it, as in
 * Fig. 13).
 */
#ifndef SF_SWEEP_H
#define SF_SWEEP_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdio.h>
#include <gsl/gsl_rng.h>
#include "cof.h"
#include "scene.h"

enum { SF_SWEEP_PVX = 0, SF_SWEEP_PVF = 1, SF_SWEEP_SF = 2, SF_SWEEP_NQ = 3 };

/* The level of every confidence interval a sweep reports. */
#define SF_SWEEP_CI_LEVEL 0.95

/* One quantity over a point's realisations.  A non-finite value (a
 * realisation the QoI's definition cannot measure) is excluded and
 * counted, never averaged: n_used + n_excluded = n.  std divides by
 * n_used - 1; se = std / sqrt(n_used), the Monte Carlo standard error of
 * the mean; [ci_lo, ci_hi] = mean -+ t se, t the Student quantile at
 * (1 + SF_SWEEP_CI_LEVEL) / 2 with n_used - 1 degrees of freedom.  NAN
 * where too few values are used (mean: none; the rest: fewer than 2). */
typedef struct {
    size_t n_used, n_excluded;
    double mean, std, se, ci_lo, ci_hi;
} sf_sweep_stat;

typedef struct {
    double det[SF_SWEEP_NQ];    /* deterministic pv_x [m], pv_F [N], stick fraction [-] */
    double *qoi;                /* n x SF_SWEEP_NQ, realisation-major: the values, in their units */
    double *ratio;              /* n x SF_SWEEP_NQ: qoi / det */
    sf_sweep_stat stat[SF_SWEEP_NQ];    /* of the values */
    sf_sweep_stat rstat[SF_SWEEP_NQ];   /* of the ratios */
    double mean[SF_SWEEP_NQ], std[SF_SWEEP_NQ];   /* of the ratios: rstat[q].mean, rstat[q].std */
    size_t n, from_checkpoint;
    size_t n_valid;             /* realisations whose every QoI is finite */
} sf_sweep_point;

/* Apply parameter `name` = value to s (SF_EPARSE with the reason). */
int sf_sweep_set(sf_scene *s, const char *name, double value, char *err, size_t errlen);

/* The deterministic reference of s (uniform COF at mu_mean, same T,
 * t_skip, eps_lambda and stepper): det[q] for each QoI.  SF_EINVAL with the
 * reason when one is not positive (no ratio can be formed: raise T). */
int sf_sweep_det(const sf_scene *s, double det[SF_SWEEP_NQ], char *err, size_t errlen);

/* One realisation of s: a COF drawn from plan (made for s) with rng, the
 * run, its QoIs (pv_x [m], pv_F [N], stick fraction [-]) into out. */
int sf_sweep_realise(const sf_scene *s, sf_cof_plan *plan, gsl_rng *rng, double out[SF_SWEEP_NQ]);

/* Run one sweep point. checkpoint may be NULL. threads 0: default. */
int sf_sweep_run(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume,
                 const char *label, sf_sweep_point *out, char *err, size_t errlen);
void sf_sweep_point_free(sf_sweep_point *p);

/* The statistics of x[0], x[stride], ... x[(n - 1) stride]. */
int sf_sweep_stat_of(const double *x, size_t stride, size_t n, sf_sweep_stat *st);

/* From p->qoi, p->det and p->n: the ratios and every statistic above
 * (sf_sweep_run calls it; so may a caller that changed p->qoi). */
int sf_sweep_point_stats(sf_sweep_point *p);

/* The shortest %g text of x that reads back to x (0.1, not
 * 0.10000000000000001). */
void sf_sweep_fmt(char *buf, size_t len, double x);

/* The sweep's two tables (TSV, a header line, then the rows of each
 * point): per realisation, and the summary per point.  `slipfield sweep`
 * writes them with --out and --summary. */
void sf_sweep_write_header(FILE *f);
void sf_sweep_write_rows(FILE *f, const char *param, double value, const sf_sweep_point *p);
void sf_sweep_summary_header(FILE *f);
void sf_sweep_summary_row(FILE *f, const char *param, double value, const sf_sweep_point *p);

#ifdef __cplusplus
}
#endif
#endif
