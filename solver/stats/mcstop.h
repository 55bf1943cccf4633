/* slipfield: when to stop adding realisations, with intervals that keep
 * their coverage: Stein's two-stage design (Stein, Ann. Math. Stat. 16,
 * 1945).
 *
 * Stage 1, the pilot (the floor on N): realisations 0 .. n0-1 give each
 * output's standard deviation s0 over its m0 finite values.  The sample
 * size is then decided from the pilot alone,
 *
 *     N = min(n_max, max(n0, max over outputs of ceil(s0^2 / X^2))),
 *
 * X the output's target standard error, and stage 2 runs realisations
 * n0 .. N-1 (each on its own stream, montecarlo.h: the same N and the same
 * bits for any thread count).  For normal values the pilot's s0 is
 * independent of every value's mean, so given s0 (hence N) the mean of
 * all N values is normal with variance sigma^2 / N, and
 *
 *     mean -+ t_{m0-1, (1 + level)/2} s0 / sqrt(N)
 *
 * covers the true mean with probability `level` exactly, for whichever N
 * the rule picked, the cap's included (the interval is then wider than
 * the target).  A rule that stops when the running standard error falls
 * below X has no such guarantee: its N depends on the spread of the very
 * values the interval is made of.  Skewed values under-cover a little, as
 * any Student interval over tens of values does.
 */
#ifndef SF_MCSTOP_H
#define SF_MCSTOP_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include "montecarlo.h"

/* Why a two-stage run stopped where it did. */
enum {
    SF_MCSTOP_FIXED = 0,   /* no target: a fixed N */
    SF_MCSTOP_TARGET,      /* every target met at N <= n_max */
    SF_MCSTOP_CAP          /* a target needs more than n_max (or the pilot had < 2 finite values) */
};
/* "fixed", "target", "cap" */
const char *sf_mcstop_reason(int reason);

typedef struct {
    size_t n_pilot;           /* stage 1, the floor (>= 2) */
    size_t n_max;             /* the cap (>= n_pilot) */
    const double *target_se;  /* per output, in its unit; not > 0: no target for it */
} sf_mcstop_spec;

/* The sample size one output asks for: ceil(s0^2 / X^2), at least 1;
 * SIZE_MAX when s0 is not finite. */
size_t sf_mcstop_size(double s0, double target);

/* The decision from the pilot's values pilot[n_pilot x nout]
 * (realisation-major; non-finite values left out): *n and *reason. */
int sf_mcstop_decide(const sf_mcstop_spec *st, size_t nout, const double *pilot, size_t *n, int *reason);

/* Stein's half-width t_{m0-1, (1 + level)/2} s0 / sqrt(m): NAN when
 * m0 < 2 or m < 1. */
double sf_mcstop_halfwidth(double s0, size_t m0, size_t m, double level);

/* Stein's interval [*lo, *hi] at `level` for the mean of x[0], x[stride],
 * ... x[(n - 1) stride], of which the first n_pilot were the pilot
 * (non-finite values left out of both): the mean -+ the half-width above
 * with the pilot's s0 and m0 and m the finite values of all n.  NAN when
 * too few are finite. */
int sf_mcstop_interval(const double *x, size_t stride, size_t n_pilot, size_t n, double level, double *lo,
                       double *hi);

/* Both stages: spec->n is set to st->n_max (the checkpoint's size: a
 * resumed run finds either stage's realisations), out has room for
 * n_max x nout values.  *n, *reason: the decision; *done_before (may be
 * NULL): realisations taken from the checkpoint.  Errors as sf_mc_run's;
 * SF_EINVAL for a spec out of range. */
int sf_mcstop_run(const sf_mc_spec *spec, const sf_mcstop_spec *st, const sf_mc_ops *ops, void *ctx, double *out,
                  size_t *n, int *reason, size_t *done_before, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
