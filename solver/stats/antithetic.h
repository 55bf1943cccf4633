/* slipfield: antithetic pairs, an estimator of a sweep point's ratio
 * means (sweep.h: sf_sweep_run_antithetic).
 *
 * A pair runs one drawn field G and its antithetic -G (cof.h:
 * sf_cof_plan_antithetic): -G has G's law, so each member is a
 * realisation of the model and the pair mean (Q(G) + Q(-G)) / 2 is an
 * unbiased estimate of E[Q], of variance Var Q (1 + rho) / 2, rho =
 * corr(Q(G), Q(-G)).  Pairs are independent (pair i draws G from plain
 * Monte Carlo's stream i: its first members are plain's first n values,
 * bit for bit), so the interval is Student's over the pair means.  A pair
 * costs one draw and two runs; against plain Monte Carlo at the same
 * variance it saves 2 (d + r) / ((d + 2 r)(1 + rho)), d a draw's work and
 * r a run's: the draw where the field is costly, and more where the QoIs
 * follow the field's sign (rho < 0: the disc averages it over few
 * correlation lengths, or over cell averages); at rho > 0 it costs more
 * than plain.
 *
 * Sample size: the first n_pilot pairs give, per ratio, the variance of
 * the pair means and Var Q (over both members); the target is plain Monte
 * Carlo's variance at n_plain, Var Q / n_plain, and
 *   n = ceil(max over the ratios of Var(pair mean) / target),
 * n_pilot <= n <= n_plain.  The pilot pairs are the first n (as the
 * two-level estimator's, mlmc.h, whose coverage check this one shares),
 * and n is reached in that estimator's stages (sf_mlmc_stage: recomputed
 * from every pair so far, at most doubled a stage).
 *
 * A pair with a member that forms no QoI (no complete cycle in the
 * window: NaN) is left out of that ratio's estimate and counted (the
 * summary's *_anti_n_used; `slipfield sweep` warns).  The estimate is
 * then of the mean over fields whose G and -G both form it, where plain
 * Monte Carlo's is over fields that form it: the two agree when no pair
 * is left out (at T = 100 s, Table 1, none is). */
#ifndef SF_ANTITHETIC_H
#define SF_ANTITHETIC_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include "sweep.h"

/* The pairs from the pilot's per-ratio variances vpair[q] (of the pair
 * means) and vf[q] (of a member): the rule above; a ratio whose
 * variances are not finite and positive sets no size. */
size_t sf_anti_size(const double *vpair, const double *vf, int nq, size_t n_plain, size_t n_pilot);

/* The pairs the variances vpair[q] ask for at target variances
 * target[q] of the ratio means (a ratio whose target or variance is not
 * finite, or target not > 0, asks for none): max ceil(vpair / target),
 * unclamped. */
double sf_anti_want(const double *vpair, const double *target, int nq);

/* The stage rule above as a function of the pairs alone (what the
 * sweep runs, and what cases/montecarlo/coverage-estimators.md replays on
 * stored pairs): pair i's G member's QoIs at v[i stride + q], its
 * partner's at v[i stride + off + q] (q < SF_SWEEP_NQ), det[q] the
 * deterministic values the ratios divide by; from the first n pairs, the
 * next stage's size *next (n: stop) and *capped (the size asked for is
 * above n_plain).  tse NULL: plain Monte Carlo's variance at n_plain;
 * else the ratios' standard-error targets (sf_sweep_run_estimator_se, n_plain then
 * the cap). */
int sf_anti_stage(const double *v, size_t stride, size_t off, const double *det, size_t n, size_t n_pilot,
                  size_t n_plain, const double *tse, size_t *next, int *capped);

/* The estimate and interval of ratio q from the first n pairs (layout as
 * sf_anti_stage): e's m, mean, se, rho, var_fine and the Student interval
 * at m - 1 degrees of freedom over the pair means (NaN below 2 usable
 * pairs); e->vrf NaN (it needs the costs: the sweep sets it). */
int sf_anti_interval(const double *v, size_t stride, size_t off, const double *det, int q, size_t n,
                     sf_sweep_anti *e);

/* sf_sweep_run_antithetic (tse NULL) and its target standard errors
 * tse[q] (sweep.h: sf_sweep_run_estimator_se; n_plain the cap). */
int sf_anti_run(const sf_scene *s, size_t n_plain, size_t n_pilot, const double *tse, int threads, const char *label,
                sf_sweep_point *out, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
