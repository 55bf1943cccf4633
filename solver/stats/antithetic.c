/* slipfield: antithetic pairs, an estimator of a sweep point's ratio
 * means (antithetic.h): each pair runs a drawn field G and its partner -G. */
#include "antithetic.h"
#include "cof.h"
#include "mlmc.h"
#include "mcstop.h"
#include "montecarlo.h"
#include "sf_alloc.h"
#include "sf_error.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

enum { NQ = SF_SWEEP_NQ };
/* a pair's values: QoIs of G, QoIs of -G, a draw's work, the draws a
 * pair makes (1; a tiled window: 1 plus the share of its columns the
 * partner made afresh, those off the first window's path), each run's
 * work */
enum { A_ANTI = NQ, A_DRAW = 2 * NQ, A_NDRAW, A_W0, A_W1, A_OUT };

double sf_anti_want(const double *vpair, const double *target, int nq)
{
    double m = 0;
    for (int q = 0; q < nq; q++)
        if (target[q] > 0 && isfinite(target[q]) && vpair[q] >= 0 && isfinite(vpair[q]))
            m = fmax(m, ceil(vpair[q] / target[q]));
    return m;
}

static size_t clampz(double m, size_t lo, size_t hi)
{
    return !(m > (double)lo) ? lo : m >= (double)hi ? hi : (size_t)m;
}

size_t sf_anti_size(const double *vpair, const double *vf, int nq, size_t n_plain, size_t n_pilot)
{
    double target[SF_SWEEP_NQ];
    int k = nq < NQ ? nq : NQ;
    for (int q = 0; q < k; q++)
        target[q] = vf[q] / (double)n_plain;
    return clampz(sf_anti_want(vpair, target, k), n_pilot, n_plain);
}

static int realise_pair(void *ws, size_t i, gsl_rng *rng, double *out)
{
    (void)i;
    sf_mlmc_ws *m = ws;
    sf_cof *cof, *anti = NULL;
    sf_cof_plan_keep_columns(m->w.plan, 1);   /* a tiled pair: one draw, not two */
    int rc = sf_cof_plan_draw(m->w.plan, rng, &cof);
    if (rc)
        return rc;
    rc = sf_cof_plan_antithetic(m->w.plan, cof, &anti);
    if (!rc)
        rc = sf_sweep_solve(m->w.s, m->w.pl, cof, out, &out[A_W0]);
    if (!rc)
        rc = sf_sweep_solve(m->w.s, m->w.pl, anti, out + A_ANTI, &out[A_W1]);
    out[A_DRAW] = m->draw;
    /* a tiled window's columns: the partner's made afresh, over the first's */
    size_t made = sf_cof_columns_made(cof);
    out[A_NDRAW] = anti && sf_cof_window_margin(cof) > 0 && made ? 1 + (double)sf_cof_columns_made(anti) / (double)made : 1;
    sf_cof_free(cof);
    sf_cof_free(anti);
    return rc;
}

/* ratio q of the first n pairs (pair i's G member's QoIs at v[i stride],
 * its partner's at v[i stride + off]): the members a[k], b[k] and pair
 * means h[k] over the k = *m pairs whose both members are finite */
static void pair_ratios(const double *v, size_t stride, size_t off, size_t n, const double *det, int q, double *a,
                        double *b, double *h, size_t *m)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        double x = v[i * stride + q] / det[q], y = v[i * stride + off + q] / det[q];
        if (isfinite(x) && isfinite(y)) {
            a[k] = x;
            b[k] = y;
            h[k++] = 0.5 * (x + y);
        }
    }
    *m = k;
}

/* the variance of the 2 m members a[], b[] (each a realisation of Q; m >= 1) */
static double member_var(const double *a, const double *b, size_t m, double *buf)
{
    memcpy(buf, a, m * sizeof *a);
    memcpy(buf + m, b, m * sizeof *b);
    return gsl_stats_variance(buf, 1, 2 * m);
}

/* the mean work of a pair (pair = 1) or of a plain realisation, its G
 * member alone (pair = 0), over n pairs */
static double mean_work(const double *v, size_t n, int pair)
{
    double w = 0;
    for (size_t i = 0; i < n; i++) {
        const double *r = v + i * A_OUT;
        w += pair ? r[A_DRAW] * r[A_NDRAW] + r[A_W0] + r[A_W1] + 2 * SF_MLMC_RUN_WORK
                  : r[A_DRAW] + r[A_W0] + SF_MLMC_RUN_WORK;
    }
    return w / (double)n;
}

int sf_anti_stage(const double *v, size_t stride, size_t off, const double *det, size_t n, size_t n_pilot,
                  size_t n_plain, const double *tse, size_t *next, int *capped)
{
    double *buf = sf_malloc(5 * (n ? n : 1) * sizeof *buf);
    if (!buf)
        return SF_ENOMEM;
    double *a = buf, *b = a + n, *h = b + n, *mb = h + n;
    double vp[NQ], vf[NQ];
    size_t m;
    for (int q = 0; q < NQ; q++) {
        pair_ratios(v, stride, off, n, det, q, a, b, h, &m);
        vp[q] = vf[q] = NAN;   /* fewer than 2 pairs: this ratio sets no size */
        if (m > 1) {   /* per pair drawn, vp n / m: the size then bounds vp / m, the estimate's */
            vp[q] = gsl_stats_variance(h, 1, m) * (double)n / (double)m;
            vf[q] = member_var(a, b, m, mb);
        }
    }
    free(buf);
    double target[NQ];
    for (int q = 0; q < NQ; q++)
        target[q] = tse ? tse[q] * tse[q] : vf[q] / (double)n_plain;
    double want = sf_anti_want(vp, target, NQ);
    for (int q = 0; tse && q < NQ; q++)   /* a target whose spread is not known yet: more, to the cap */
        if (target[q] > 0 && isfinite(target[q]) && !isfinite(vp[q]))
            want = INFINITY;
    *capped = want > (double)n_plain;
    *next = sf_mlmc_stage(n, clampz(want, n_pilot, n_plain));
    return SF_SUCCESS;
}

int sf_anti_interval(const double *v, size_t stride, size_t off, const double *det, int q, size_t n,
                     sf_sweep_anti *e)
{
    double *buf = sf_malloc(5 * (n ? n : 1) * sizeof *buf);
    if (!buf)
        return SF_ENOMEM;
    double *a = buf, *b = a + n, *h = b + n, *mb = h + n;
    size_t m;
    pair_ratios(v, stride, off, n, det, q, a, b, h, &m);
    e->m = m;
    e->mean = e->se = e->rho = e->var_fine = e->ci_lo = e->ci_hi = e->vrf = NAN;
    if (m >= 2) {   /* a single pair's mean alone is not an interval */
        e->mean = gsl_stats_mean(h, 1, m);
        e->se = sqrt(gsl_stats_variance_m(h, 1, m, e->mean) / (double)m);
        e->rho = m > 2 ? gsl_stats_correlation(a, 1, b, 1, m) : NAN;
        e->var_fine = member_var(a, b, m, mb);
        double t = gsl_cdf_tdist_Pinv(0.5 * (1 + SF_SWEEP_CI_LEVEL), (double)(m - 1));
        e->ci_lo = e->mean - t * e->se;
        e->ci_hi = e->mean + t * e->se;
    }
    free(buf);
    return SF_SUCCESS;
}

int sf_sweep_run_antithetic(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                            sf_sweep_point *out, char *err, size_t errlen)
{
    return sf_anti_run(s, n_plain, n_pilot, NULL, threads, label, out, err, errlen);
}

int sf_anti_run(const sf_scene *s, size_t n_plain, size_t n_pilot, const double *tse, int threads, const char *label,
                sf_sweep_point *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    if (n_pilot < 2 || n_plain < n_pilot)
        return sf_seterr(err, errlen, SF_EINVAL, "antithetic sweep: 2 <= pilot (%zu) <= realisations (%zu)", n_pilot,
                         n_plain);
    int rc = sf_sweep_det(s, out->det, err, errlen);
    if (rc)
        return rc;
    sf_plan fine;
    if ((rc = sf_plan_make(s, &fine, err, errlen)))
        return rc;
    fine.history = 0;
    out->plan = fine;   /* the rows' (the G members'), for u_num's companion (sweep.h) */
    out->planned = 1;
    double *pairs = sf_calloc(n_plain * A_OUT, sizeof *pairs);
    if (!pairs)
        return SF_ENOMEM;
    sf_mlmc_ws ctx = { { s, &fine, NULL, NULL, 0 }, NULL, 0, 0, 0, NULL, NULL, 0 };
    sf_mc_ops ops = { sf_mlmc_ws_alloc, sf_mlmc_ws_free, realise_pair };
    sf_mc_spec spec = { n_plain, A_OUT, s->seed, threads, NULL, 0, 0, label };
    rc = sf_mc_run_range(&spec, 0, n_pilot, &ops, &ctx, pairs, NULL, err, errlen);
    size_t n = n_pilot;
    int capped = 0;
    while (!rc) {   /* the size in stages, each from every pair so far (sf_anti_stage) */
        size_t g;
        if ((rc = sf_anti_stage(pairs, A_OUT, A_ANTI, out->det, n, n_pilot, n_plain, tse, &g, &capped)) || g == n)
            break;
        rc = sf_mc_run_range(&spec, n, g, &ops, &ctx, pairs, NULL, err, errlen);
        n = g;
    }
    if (!rc && (!(out->qoi = sf_calloc(n * NQ, sizeof *out->qoi)) ||
                !(out->ratio = sf_calloc(n * NQ, sizeof *out->ratio)) ||
                !(out->anti.qoi_anti = sf_calloc(n * NQ, sizeof *out->anti.qoi_anti))))
        rc = SF_ENOMEM;
    if (!rc) {   /* the rows: the pairs' fields G, plain Monte Carlo's first n */
        out->estimator = SF_EST_ANTITHETIC;
        out->stop = !tse ? SF_MCSTOP_FIXED : capped ? SF_MCSTOP_CAP : SF_MCSTOP_TARGET;
        out->n = out->anti.n = n;
        for (size_t i = 0; i < n; i++) {
            memcpy(out->qoi + i * NQ, pairs + i * A_OUT, NQ * sizeof *pairs);
            memcpy(out->anti.qoi_anti + i * NQ, pairs + i * A_OUT + A_ANTI, NQ * sizeof *pairs);
        }
        out->anti.cost = mean_work(pairs, n, 1);
        out->anti.cost_fine = mean_work(pairs, n, 0);
        out->anti.work = (double)n * out->anti.cost;
        rc = sf_sweep_point_stats(out);
    }
    for (int q = 0; q < NQ && !rc; q++) {
        sf_sweep_anti *e = &out->anti.q[q];
        if ((rc = sf_anti_interval(pairs, A_OUT, A_ANTI, out->det, q, n, e)) || e->m < 2)
            continue;   /* no spread: not estimated (a single pair's mean alone is not an interval) */
        e->vrf = e->var_fine * out->anti.cost_fine / (e->se * e->se * out->anti.work);
    }
    free(pairs);
    return rc;
}
