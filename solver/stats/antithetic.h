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

/* sf_sweep_run_antithetic (tse NULL) and its target standard errors
 * tse[q] (sweep.h: sf_sweep_run_estimator_se; n_plain the cap). */
int sf_anti_run(const sf_scene *s, size_t n_plain, size_t n_pilot, const double *tse, int threads, const char *label,
                sf_sweep_point *out, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
