/* slipfield: Stein's two-stage sample size and its intervals (mcstop.h):
 * when to stop adding realisations. */
#include "mcstop.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

const char *sf_mcstop_reason(int reason)
{
    return reason == SF_MCSTOP_TARGET ? "target" : reason == SF_MCSTOP_CAP ? "cap" : "fixed";
}

size_t sf_mcstop_size(double s0, double target)
{
    double r = ceil((s0 / target) * (s0 / target));
    if (!(r < 0x1p52))   /* NaN, Inf, or far beyond any cap */
        return SIZE_MAX;
    return r < 1 ? 1 : (size_t)r;
}

/* The mean and sd of the finite values among x[0 .. n) (stride), into *m. */
static int finite_stats(const double *x, size_t stride, size_t n, size_t *m, double *mean, double *sd)
{
    double *v = sf_malloc((n ? n : 1) * sizeof *v);
    if (!v)
        return SF_ENOMEM;
    *m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i * stride]))
            v[(*m)++] = x[i * stride];
    *mean = *m ? gsl_stats_mean(v, 1, *m) : NAN;
    *sd = *m > 1 ? gsl_stats_sd_m(v, 1, *m, *mean) : NAN;
    free(v);
    return SF_SUCCESS;
}

int sf_mcstop_decide(const sf_mcstop_spec *st, size_t nout, const double *pilot, size_t *n, int *reason)
{
    size_t need = st->n_pilot;
    for (size_t q = 0; q < nout; q++) {
        size_t m;
        double mean, s0;
        if (!(st->target_se[q] > 0))
            continue;
        int rc = finite_stats(pilot + q, nout, st->n_pilot, &m, &mean, &s0);
        if (rc)
            return rc;
        size_t nq = m < 2 ? SIZE_MAX : sf_mcstop_size(s0, st->target_se[q]);
        if (nq > need)
            need = nq;
    }
    *reason = need > st->n_max ? SF_MCSTOP_CAP : SF_MCSTOP_TARGET;
    *n = need > st->n_max ? st->n_max : need;
    return SF_SUCCESS;
}

double sf_mcstop_halfwidth(double s0, size_t m0, size_t m, double level)
{
    if (m0 < 2 || m < 1)
        return NAN;
    return gsl_cdf_tdist_Pinv(0.5 * (1 + level), (double)(m0 - 1)) * s0 / sqrt((double)m);
}

int sf_mcstop_interval(const double *x, size_t stride, size_t n_pilot, size_t n, double level, double *lo,
                       double *hi)
{
    size_t m0, m;
    double mean0, s0, mean, sd;
    int rc = finite_stats(x, stride, n_pilot < n ? n_pilot : n, &m0, &mean0, &s0);
    if (!rc)
        rc = finite_stats(x, stride, n, &m, &mean, &sd);
    double hw = rc ? NAN : sf_mcstop_halfwidth(s0, m0, m, level);
    *lo = mean - hw;
    *hi = mean + hw;
    return rc;
}

int sf_mcstop_run(const sf_mc_spec *spec, const sf_mcstop_spec *st, const sf_mc_ops *ops, void *ctx, double *out,
                  size_t *n, int *reason, size_t *done_before, char *err, size_t errlen)
{
    if (st->n_pilot < 2 || st->n_max < st->n_pilot)
        return sf_seterr(err, errlen, SF_EINVAL, "two-stage run: the pilot (%zu) must be >= 2 and <= the cap (%zu)",
                         st->n_pilot, st->n_max);
    sf_mc_spec s = *spec;
    s.n = st->n_max;
    size_t b1 = 0, b2 = 0;
    int rc = sf_mc_run_range(&s, 0, st->n_pilot, ops, ctx, out, &b1, err, errlen);
    if (!rc)
        rc = sf_mcstop_decide(st, s.nout, out, n, reason);
    if (!rc)
        rc = sf_mc_run_range(&s, st->n_pilot, *n, ops, ctx, out, &b2, err, errlen);
    if (done_before)
        *done_before = b1 + b2;
    return rc;
}
