/* slipfield: the two-level Monte Carlo estimators of a sweep point's
 * ratio means (mlmc.h): the coarse levels' plans, the stage sizes and the
 * runs at a target standard error. */
#include "mlmc.h"
#include "cof.h"
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
/* a pair's values: fine QoIs, coarse QoIs, draw, fine and coarse work */
enum { P_C = NQ, P_DRAW = 2 * NQ, P_WF, P_WC, P_OUT };

void sf_mlmc_coarse_plan(const sf_plan *fine, sf_plan *coarse)
{
    *coarse = *fine;
    if (fine->num.quadrature && !fine->num.cell_average) {
        size_t c = (fine->num.cells + 1) / 2;
        coarse->num.cells = c < 2 ? 2 : c;
    }
    coarse->num.rtol = fmax(fine->num.rtol, SF_MLMC_RTOL);
}

double sf_mlmc_draw_work(const sf_cof_plan_info *info)
{
    if (info->kind != SF_COF_FIELD)
        return 0;
    return (double)info->nx * (double)info->ny * (info->box > 0 ? SF_MLMC_DRAW_WORK_CELL : SF_MLMC_DRAW_WORK_POINT);
}

static size_t clampz(double x, size_t lo, size_t hi)
{
    return !(x > (double)lo) ? lo : x >= (double)hi ? hi : (size_t)x;
}

size_t sf_mlmc_stage(size_t n, size_t want)
{
    return want <= n ? n : want / 2 >= n ? 2 * n : want;
}

void sf_mlmc_want(const double *v0, const double *v1, const double *target, int nq, double c0, double c1,
                  double *m0, double *m1)
{
    *m0 = *m1 = 0;
    for (int q = 0; q < nq; q++) {
        if (!(target[q] > 0) || !isfinite(target[q]) || !(v0[q] >= 0) || !(v1[q] >= 0) || !isfinite(v0[q] + v1[q]))
            continue;
        double sum = sqrt(v0[q] * c0) + sqrt(v1[q] * c1);
        *m0 = fmax(*m0, ceil(sqrt(v0[q] / c0) * sum / target[q]));
        *m1 = fmax(*m1, ceil(sqrt(v1[q] / c1) * sum / target[q]));
    }
}

void sf_mlmc_sizes(const double *v0, const double *v1, const double *vf, int nq, double c0, double c1,
                   size_t n_plain, size_t n_pilot, size_t *n0, size_t *n1)
{
    double target[SF_SWEEP_NQ], m0, m1;
    int k = nq < SF_SWEEP_NQ ? nq : SF_SWEEP_NQ;
    for (int q = 0; q < k; q++)
        target[q] = vf[q] / (double)n_plain;
    sf_mlmc_want(v0, v1, target, k, c0, c1, &m0, &m1);
    *n0 = clampz(m0, n_pilot, SF_MLMC_N0_CAP * n_plain);
    *n1 = clampz(m1, n_pilot, n_plain);
}

typedef sf_mlmc_ws ml_ws;

void *sf_mlmc_ws_alloc(void *ctx)
{
    const ml_ws *c = ctx;
    ml_ws *m = sf_malloc(sizeof *m);
    if (!m)
        return NULL;
    *m = *c;
    sf_sweep_ws *w = sf_sweep_ws_alloc(&m->w);
    if (!w) {
        free(m);
        return NULL;
    }
    m->w = *w;   /* the copy owns w's COF plan */
    free(w);
    m->draw = sf_mlmc_draw_work(sf_cof_plan_get_info(m->w.plan));
    m->cplan = NULL;
    if (m->cdraw) {   /* level 0's own draw on the coarse grid */
        if (sf_cof_plan_build_mt(m->w.s, m->cdraw, &m->cplan, NULL, 0)) {
            sf_mlmc_ws_free(m);
            return NULL;
        }
        m->cdraw_work = sf_mlmc_draw_work(sf_cof_plan_get_info(m->cplan));
    }
    return m;
}

void sf_mlmc_ws_free(void *p)
{
    ml_ws *m = p;
    sf_cof_plan_free_mt(m->w.plan);
    if (m->cplan)
        sf_cof_plan_free_mt(m->cplan);
    free(m);
}

/* level 0 on a derived coarse field (boxes of boxes, every k-th node): an
 * antithetic pair of coarse runs on a field drawn on the coarse grid;
 * out: the pair's mean QoIs */
static int realise_boxes0(ml_ws *m, gsl_rng *rng, double *out)
{
    sf_cof *c, *a = NULL;
    double qa[NQ];
    int rc = sf_cof_plan_draw(m->cplan, rng, &c);
    if (rc)
        return rc;
    rc = sf_cof_plan_antithetic(m->cplan, c, &a);
    if (!rc)
        rc = sf_sweep_solve(m->w.s, m->coarse, c, out, NULL);
    if (!rc)
        rc = sf_sweep_solve(m->w.s, m->coarse, a, qa, NULL);
    for (int q = 0; q < NQ; q++)
        out[q] = 0.5 * (out[q] + qa[q]);   /* NaN when either member forms no QoI */
    sf_cof_free(c);
    sf_cof_free(a);
    return rc;
}

/* a pair on one field (level 1: the coarse run on the field itself, its
 * box means or its every k-th node), or the coarse run alone (level 0) */
static int realise(ml_ws *m, gsl_rng *rng, int pair, double *out)
{
    if (!pair && m->cplan)
        return realise_boxes0(m, rng, out);
    sf_cof *cof, *box = NULL;
    int rc = sf_cof_plan_draw(m->w.plan, rng, &cof);
    if (rc)
        return rc;
    if (pair) {
        rc = !m->b ? SF_SUCCESS : m->sub ? sf_cof_subsample(cof, m->b, &box) : sf_cof_box_means(cof, m->b, &box);
        if (!rc)
            rc = sf_sweep_solve(m->w.s, m->w.pl, cof, out, &out[P_WF]);
        if (!rc)
            rc = sf_sweep_solve(m->w.s, m->coarse, box ? box : cof, out + P_C, &out[P_WC]);
        out[P_DRAW] = m->draw;
        sf_cof_free(box);
    } else {
        rc = sf_sweep_solve(m->w.s, m->coarse, cof, out, NULL);
    }
    sf_cof_free(cof);
    return rc;
}

static int realise_pair(void *p, size_t i, gsl_rng *rng, double *out)
{
    (void)i;
    return realise(p, rng, 1, out);
}

static int realise_coarse(void *p, size_t i, gsl_rng *rng, double *out)
{
    (void)i;
    return realise(p, rng, 0, out);
}

/* per ratio q over the first n pairs (pair i's fine QoIs at v[i stride],
 * its coarse at v[i stride + off]): the variances of the coarse ratio, of
 * fine - coarse and of the fine ratio (pairs with both finite) */
static int pair_vars(const double *v, size_t stride, size_t off, size_t n, const double *det, int q, double *vc,
                     double *vd, double *vf, size_t *m)
{
    double *x = sf_malloc(3 * (n ? n : 1) * sizeof *x);
    if (!x)
        return SF_ENOMEM;
    double *d = x + n, *f = d + n;
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        double a = v[i * stride + q] / det[q], b = v[i * stride + off + q] / det[q];
        if (isfinite(a) && isfinite(b)) {
            x[k] = b;
            d[k] = a - b;
            f[k++] = a;
        }
    }
    *m = k;
    *vc = k > 1 ? gsl_stats_variance(x, 1, k) : NAN;
    *vd = k > 1 ? gsl_stats_variance(d, 1, k) : NAN;
    *vf = k > 1 ? gsl_stats_variance(f, 1, k) : NAN;
    free(x);
    return SF_SUCCESS;
}

/* the variance of ratio q (value / det) over level 0's first n samples
 * (at v[i stride]) that are finite (x: room for n); NAN below 2 */
static double finite_var(const double *v, size_t stride, size_t n, int q, double det, double *x, size_t *m)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i * stride + q] / det))
            x[k++] = v[i * stride + q] / det;
    *m = k;
    return k > 1 ? gsl_stats_variance(x, 1, k) : NAN;
}

/* the mean work of a level over n samples: pairs (fine + coarse) or the
 * coarse run of a pair alone */
static double mean_work(const double *v, size_t n, int fine, int coarse)
{
    double w = 0;
    for (size_t i = 0; i < n; i++)
        w += v[i * P_OUT + P_DRAW] + (fine ? v[i * P_OUT + P_WF] + SF_MLMC_RUN_WORK : 0) +
             (coarse ? v[i * P_OUT + P_WC] + SF_MLMC_RUN_WORK : 0);
    return w / (double)n;
}

int sf_mlmc_interval(const double *pairs, size_t stride, size_t off, size_t n1, const double *lev0, size_t stride0,
                     size_t n0, const double *det, int q, int boxes, sf_sweep_ml *e)
{
    double vc, vd, vf, sum[2] = { 0, 0 };
    size_t m1, m0 = 0;
    int rc = pair_vars(pairs, stride, off, n1, det, q, &vc, &vd, &vf, &m1);
    if (rc)
        return rc;
    for (size_t i = 0; i < n1; i++) {
        double a = pairs[i * stride + q] / det[q], b = pairs[i * stride + off + q] / det[q];
        if (isfinite(a) && isfinite(b))
            sum[1] += a - b;
    }
    double *x = sf_malloc((n0 ? n0 : 1) * sizeof *x);
    if (!x)
        return SF_ENOMEM;
    for (size_t i = 0; i < n0; i++) {
        double b = lev0[i * stride0 + q] / det[q];
        if (isfinite(b)) {
            x[m0++] = b;
            sum[0] += b;
        }
    }
    double v0 = m0 > 1 ? gsl_stats_variance(x, 1, m0) : NAN;
    free(x);
    e->m[0] = m0;
    e->m[1] = m1;
    e->var[0] = v0;
    e->var[1] = vd;
    /* Var Q_c from level 0's many values, plus the pairs' Var Q_f -
       Var Q_c; on a derived field level 0's values are pair means,
       and the pairs' Var Q_f stands alone */
    e->var_fine = boxes ? vf : v0 + (vf - vc);
    e->mean = sum[0] / (double)m0 + sum[1] / (double)m1;
    double a = v0 / (double)m0, b = vd / (double)m1;
    e->se = sqrt(a + b);
    /* Welch-Satterthwaite; a level of zero variance adds no term */
    double den = (a > 0 ? a * a / (double)(m0 - 1) : 0) + (b > 0 ? b * b / (double)(m1 - 1) : 0);
    e->df = den > 0 ? (a + b) * (a + b) / den : NAN;
    double t = e->df > 0 ? gsl_cdf_tdist_Pinv(0.5 * (1 + SF_SWEEP_CI_LEVEL), e->df) : NAN;
    e->ci_lo = e->mean - t * e->se;
    e->ci_hi = e->mean + t * e->se;
    e->vrf = NAN;
    return SF_SUCCESS;
}

static int ml_stats(sf_sweep_point *p, const double *pairs, int boxes)
{
    for (int q = 0; q < NQ; q++) {
        sf_sweep_ml *e = &p->ml.q[q];
        int rc = sf_mlmc_interval(pairs, P_OUT, P_C, p->ml.n[1], p->ml.coarse0, NQ, p->ml.n[0], p->det, q, boxes, e);
        if (rc)
            return rc;
        e->vrf = e->var_fine * p->ml.cost_fine / (e->se * e->se * p->ml.work);
    }
    return SF_SUCCESS;
}

int sf_mlmc_next(const double *pairs, size_t stride, size_t off, size_t n1, const double *lev0, size_t stride0,
                 size_t n0, const double *det, double c0, double c1, size_t n_pilot, size_t n_plain,
                 const double *tse, size_t *g0, size_t *g1, int *capped)
{
    /* each level's variance per sample drawn, V_l n_l / m_l (m_l of them
       usable): the sizes then bound sum V_l / m_l, the estimate's */
    size_t cap0 = SF_MLMC_N0_CAP * n_plain;
    double v0[NQ], v1[NQ], vf[NQ], vc;
    double *x = sf_malloc((n0 ? n0 : 1) * sizeof *x);
    if (!x)
        return SF_ENOMEM;
    int rc = SF_SUCCESS;
    for (int q = 0; q < NQ && !rc; q++) {
        size_t m, m0;
        if ((rc = pair_vars(pairs, stride, off, n1, det, q, &vc, &v1[q], &vf[q], &m)))
            break;   /* m is not set */
        v1[q] *= m > 1 ? (double)n1 / (double)m : NAN;
        v0[q] = finite_var(lev0, stride0, n0, q, det[q], x, &m0);
        v0[q] *= m0 > 1 ? (double)n0 / (double)m0 : NAN;
    }
    free(x);
    if (rc)
        return rc;
    double target[NQ], w0, w1;
    for (int q = 0; q < NQ; q++)
        target[q] = tse ? tse[q] * tse[q] : vf[q] / (double)n_plain;
    sf_mlmc_want(v0, v1, target, NQ, c0, c1, &w0, &w1);
    for (int q = 0; tse && q < NQ; q++)   /* a target whose spread is not known yet: more, to the cap */
        if (target[q] > 0 && isfinite(target[q]) && !isfinite(v0[q] + v1[q]))
            w0 = w1 = INFINITY;
    *capped = w0 > (double)cap0 || w1 > (double)n_plain;
    *g1 = sf_mlmc_stage(n1, clampz(w1, n_pilot, n_plain));
    *g0 = sf_mlmc_stage(n0, clampz(w0, n_pilot, cap0));
    return SF_SUCCESS;
}

/* level 0's work per sample: the coarse draw and run of a pair's field,
 * or (a derived field) a coarse-grid draw and two coarse runs */
static double level0_work(const ml_ws *c, const double *pairs, size_t n)
{
    if (!c->cdraw)
        return mean_work(pairs, n, 0, 1);
    double w = 0;
    for (size_t i = 0; i < n; i++)
        w += pairs[i * P_OUT + P_WC] + SF_MLMC_RUN_WORK;
    return c->cdraw_work + 2 * w / (double)n;
}

enum { ML_SAME = 0, ML_BOXES, ML_SUB };
/* tse: NULL for plain's variance at n_plain, else each ratio mean's
 * standard error target (n_plain then the cap) */
static int run_levels(const sf_scene *s, size_t n_plain, size_t n_pilot, const double *tse, int threads,
                      const char *label, int mode, sf_sweep_point *out, char *err, size_t errlen)
{
    int boxes = mode != ML_SAME;   /* a derived coarse field: level 0 draws its own, in antithetic pairs */
    memset(out, 0, sizeof *out);
    if (n_pilot < 2 || n_plain < n_pilot)
        return sf_seterr(err, errlen, SF_EINVAL, "two-level sweep: 2 <= pilot (%zu) <= realisations (%zu)", n_pilot,
                         n_plain);
    int rc = sf_sweep_det(s, out->det, err, errlen);
    if (rc)
        return rc;
    sf_plan fine, coarse, cdraw;
    if (boxes) {
        if ((rc = mode == ML_SUB ? sf_mlmc_sub_plans(s, &fine, &coarse, &cdraw, err, errlen)
                                 : sf_mlmc_box_plans(s, &fine, &coarse, &cdraw, err, errlen)))
            return rc;
    } else {
        if ((rc = sf_plan_make(s, &fine, err, errlen)))
            return rc;
        fine.history = 0;
        sf_mlmc_coarse_plan(&fine, &coarse);
    }
    out->plan = fine;   /* the rows' (level 1's fine runs'), for u_num's companion (sweep.h) */
    out->planned = 1;
    double *pairs = sf_calloc(n_plain * P_OUT, sizeof *pairs), *lev0 = NULL;
    if (!pairs)
        return SF_ENOMEM;
    ml_ws ctx = { { s, &fine, NULL, NULL, 0 }, &coarse, 0, mode == ML_SUB ? SF_MLMC_SUB : boxes ? SF_MLMC_BOX : 0,
                  mode == ML_SUB, boxes ? &cdraw : NULL, NULL, 0 };
    if (boxes) {   /* the level-0 draw's work, for the sizes (a thread's copy measures its own) */
        sf_cof_plan *cp;
        if ((rc = sf_cof_plan_build(s, &cdraw, &cp, err, errlen))) {
            free(pairs);
            return rc;
        }
        ctx.cdraw_work = sf_mlmc_draw_work(sf_cof_plan_get_info(cp));
        sf_cof_plan_free(cp);
    }
    sf_mc_ops ops1 = { sf_mlmc_ws_alloc, sf_mlmc_ws_free, realise_pair },
              ops0 = { sf_mlmc_ws_alloc, sf_mlmc_ws_free, realise_coarse };
    sf_mc_spec spec1 = { n_plain, P_OUT, s->seed, threads, NULL, 0, 0, label };
    rc = sf_mc_run_range(&spec1, 0, n_pilot, &ops1, &ctx, pairs, NULL, err, errlen);
    size_t n0 = n_pilot, n1 = n_pilot, cap0 = SF_MLMC_N0_CAP * n_plain;
    int capped = 0;
    /* level 0's own pilot, its first samples (derived fields: antithetic pairs) */
    sf_mc_spec spec0 = { cap0, NQ, sf_mc_seed(s->seed, SF_MLMC_LEVEL0_STREAM), threads, NULL, 0, 0, label };
    if (!rc && !(lev0 = sf_calloc(cap0 * NQ, sizeof *lev0)))
        rc = SF_ENOMEM;
    if (!rc)
        rc = sf_mc_run_range(&spec0, 0, n_pilot, &ops0, &ctx, lev0, NULL, err, errlen);
    /* the sizes in stages, each from every sample so far (sf_mlmc_next) */
    while (!rc) {
        size_t g0, g1;
        if ((rc = sf_mlmc_next(pairs, P_OUT, P_C, n1, lev0, NQ, n0, out->det, level0_work(&ctx, pairs, n1),
                               mean_work(pairs, n1, 1, 1), n_pilot, n_plain, tse, &g0, &g1, &capped)))
            break;
        if (g1 == n1 && g0 == n0)
            break;
        if (g1 > n1)
            rc = sf_mc_run_range(&spec1, n1, g1, &ops1, &ctx, pairs, NULL, err, errlen);
        if (!rc && g0 > n0)
            rc = sf_mc_run_range(&spec0, n0, g0, &ops0, &ctx, lev0, NULL, err, errlen);
        n1 = g1;
        n0 = g0;
    }
    if (!rc && (!(out->qoi = sf_calloc(n1 * NQ, sizeof *out->qoi)) ||
                !(out->ratio = sf_calloc(n1 * NQ, sizeof *out->ratio)) ||
                !(out->ml.coarse1 = sf_calloc(n1 * NQ, sizeof *out->ml.coarse1))))
        rc = SF_ENOMEM;
    if (!rc) {   /* the rows: level 1's fine values, plain Monte Carlo's first n1 (same field) */
        out->estimator = mode == ML_SUB ? SF_EST_MLMC_SUB : boxes ? SF_EST_MLMC_BOXES : SF_EST_MLMC;
        out->stop = !tse ? SF_MCSTOP_FIXED : capped ? SF_MCSTOP_CAP : SF_MCSTOP_TARGET;
        out->n = n1;
        out->ml.coarse0 = lev0;
        lev0 = NULL;
        for (size_t i = 0; i < n1; i++) {
            memcpy(out->qoi + i * NQ, pairs + i * P_OUT, NQ * sizeof *pairs);
            memcpy(out->ml.coarse1 + i * NQ, pairs + i * P_OUT + P_C, NQ * sizeof *pairs);
        }
        out->ml.n[0] = n0;
        out->ml.n[1] = n1;
        out->ml.cost[0] = level0_work(&ctx, pairs, n1);
        out->ml.cost[1] = mean_work(pairs, n1, 1, 1);
        out->ml.cost_fine = mean_work(pairs, n1, 1, 0);
        out->ml.work = (double)n0 * out->ml.cost[0] + (double)n1 * out->ml.cost[1];
        rc = sf_sweep_point_stats(out);
    }
    if (!rc)
        rc = ml_stats(out, pairs, boxes);
    free(pairs);
    free(lev0);
    return rc;
}

int sf_sweep_run_mlmc(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                      sf_sweep_point *out, char *err, size_t errlen)
{
    return run_levels(s, n_plain, n_pilot, NULL, threads, label, ML_SAME, out, err, errlen);
}

int sf_sweep_run_mlmc_boxes(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                            sf_sweep_point *out, char *err, size_t errlen)
{
    return run_levels(s, n_plain, n_pilot, NULL, threads, label, ML_BOXES, out, err, errlen);
}

int sf_mlmc_run_se(const sf_scene *s, int est, const double *tse, size_t n_pilot, size_t n_max, int threads,
                   const char *label, sf_sweep_point *out, char *err, size_t errlen)
{
    int mode = est == SF_EST_MLMC_BOXES ? ML_BOXES : est == SF_EST_MLMC_SUB ? ML_SUB : ML_SAME;
    return run_levels(s, n_max, n_pilot, tse, threads, label, mode, out, err, errlen);
}

int sf_sweep_run_mlmc_sub(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                          sf_sweep_point *out, char *err, size_t errlen)
{
    return run_levels(s, n_plain, n_pilot, NULL, threads, label, ML_SUB, out, err, errlen);
}

int sf_mlmc_sub_plans(const sf_scene *s, sf_plan *fine, sf_plan *coarse, sf_plan *cdraw, char *err, size_t errlen)
{
    int rc = sf_plan_make(s, fine, err, errlen);
    if (rc)
        return rc;
    fine->history = 0;
    *cdraw = *fine;
    if (fine->cof.kind != SF_COF_FIELD || fine->num.cell_average || fine->cof.generator == SF_COFGEN_TILES ||
        sf_cof_sub_grid(&fine->cof, SF_MLMC_SUB, &cdraw->cof))
        return sf_seterr(err, errlen, SF_EINVAL, "two levels on every %d-th node need a plan that draws point values "
                         "on the circulant strip (cof = field; not cell averages, not tiles: raise l or set "
                         "cof_generator = circulant)", SF_MLMC_SUB);
    sf_mlmc_coarse_plan(fine, coarse);
    coarse->cof = cdraw->cof;
    return SF_SUCCESS;
}

int sf_mlmc_box_plans(const sf_scene *s, sf_plan *fine, sf_plan *coarse, sf_plan *cdraw, char *err, size_t errlen)
{
    int rc = sf_plan_make(s, fine, err, errlen);
    if (rc)
        return rc;
    if (!fine->num.cell_average)
        return sf_seterr(err, errlen, SF_EINVAL, "two levels on boxes of boxes need a plan that draws cell averages "
                         "(cof = field with cof_model = cell_average, or auto at small l/R); this scene's does not");
    sf_scene sb = *s;   /* the plan's cells rounded up to a multiple of b */
    size_t b = SF_MLMC_BOX;
    sb.cof_model = SF_COFMODEL_CELL;
    sb.cells = (fine->num.cells + b - 1) / b * b;
    if ((rc = sf_plan_make(&sb, fine, err, errlen)))
        return rc;
    fine->history = 0;
    fine->cof.x0 -= SF_MLMC_BOX_PAD * fine->cof.dx;
    fine->cof.y0 -= SF_MLMC_BOX_PAD * fine->cof.dy;
    fine->cof.nx += 2 * SF_MLMC_BOX_PAD;
    fine->cof.ny += 2 * SF_MLMC_BOX_PAD;
    sf_mlmc_coarse_plan(fine, coarse);
    *cdraw = *fine;
    if ((rc = sf_cof_box_grid(&fine->cof, b, &cdraw->cof)))
        return sf_seterr(err, errlen, rc, "boxes of boxes: the %zu x %zu strip is too small for %zu x %zu boxes",
                         fine->cof.nx, fine->cof.ny, b, b);
    coarse->num.cells = fine->num.cells / b;
    coarse->num.cell_size = cdraw->cof.box;
    coarse->num.box_over_l = cdraw->cof.box / s->l;
    coarse->cof = cdraw->cof;
    return SF_SUCCESS;
}
