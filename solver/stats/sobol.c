/* slipfield: Sobol' indices by pick-freeze (sobol.h): the design of
 * sample matrices, the estimators with their bootstrap intervals and the
 * ranking of S1. */
#include "sobol.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

int sf_sobol_design_alloc(size_t n, size_t d, gsl_rng *rng, sf_sobol_design **out)
{
    *out = NULL;
    if (n < 2 || d == 0 || d > SF_SOBOL_MAXD)
        return SF_EINVAL;
    if (n > SIZE_MAX / (d + 2) / sizeof(double))
        return SF_ETOOBIG;
    sf_sobol_design *D = sf_calloc(1, sizeof *D);
    if (!D)
        return SF_ENOMEM;
    D->n = n;
    D->d = d;
    D->a = sf_malloc(n * d * sizeof *D->a);
    D->b = sf_malloc(n * d * sizeof *D->b);
    if (!D->a || !D->b) {
        sf_sobol_design_free(D);
        return SF_ENOMEM;
    }
    for (size_t k = 0; k < n * d; k++)
        D->a[k] = gsl_rng_uniform(rng);
    for (size_t k = 0; k < n * d; k++)
        D->b[k] = gsl_rng_uniform(rng);
    *out = D;
    return SF_SUCCESS;
}

void sf_sobol_design_free(sf_sobol_design *D)
{
    if (!D)
        return;
    free(D->a);
    free(D->b);
    free(D);
}

size_t sf_sobol_nevals(const sf_sobol_design *D)
{
    return D->n * (D->d + 2);
}

void sf_sobol_point(const sf_sobol_design *D, size_t e, double *u)
{
    size_t k = e / D->n, j = e % D->n;
    const double *a = D->a + j * D->d, *b = D->b + j * D->d;
    memcpy(u, k == 1 ? b : a, D->d * sizeof *u);
    if (k >= 2)
        u[k - 2] = b[k - 2];
}

size_t sf_sobol_source_row(const sf_sobol_design *D, size_t e, size_t i)
{
    size_t k = e / D->n, j = e % D->n;
    return k == 1 || k == 2 + i ? D->n + j : j;
}

int sf_sobol_in_blocks(const sf_sobol_design *D, unsigned long inputs, size_t e)
{
    size_t k = e / D->n;
    return k < 2 || (k - 2 < sizeof inputs * 8 && (inputs >> (k - 2) & 1));
}

/* The estimators over rows[0..m) (repeats allowed: a bootstrap resample)
 * for the inputs of `inputs` (NAN for the others); buf holds 2 m doubles.
 * SF_EFAIL when V = 0. */
static int indices(const sf_sobol_design *D, unsigned long inputs, const double *y, size_t stride,
                   const size_t *rows, size_t m, double *buf, double *s1, double *st, double *mean, double *var)
{
    size_t n = D->n;
#define Y(k, j) y[((k) * n + (j)) * stride]
    for (size_t r = 0; r < m; r++) {
        buf[r] = Y(0, rows[r]);
        buf[m + r] = Y(1, rows[r]);
    }
    *mean = gsl_stats_mean(buf, 1, 2 * m);
    *var = gsl_stats_variance_m(buf, 1, 2 * m, *mean);
    if (!(*var > 0))
        return SF_EFAIL;
    for (size_t i = 0; i < D->d; i++) {
        double f = 0, t = 0;
        if (!(inputs >> i & 1)) {
            s1[i] = st[i] = NAN;
            continue;
        }
        for (size_t r = 0; r < m; r++) {
            double fa = Y(0, rows[r]), fb = Y(1, rows[r]), fi = Y(2 + i, rows[r]);
            f += (fb - *mean) * (fi - fa);
            t += (fa - fi) * (fa - fi);
        }
        s1[i] = f / (double)m / *var;
        st[i] = t / (2.0 * (double)m) / *var;
    }
#undef Y
    return SF_SUCCESS;
}

int sf_sobol_estimate(const sf_sobol_design *D, const double *y, size_t stride, size_t nboot, double level,
                      unsigned long seed, sf_sobol_result *res, double *boot)
{
    return sf_sobol_estimate_some(D, SF_SOBOL_ALL, y, stride, nboot, level, seed, res, boot);
}

int sf_sobol_estimate_some(const sf_sobol_design *D, unsigned long inputs, const double *y, size_t stride,
                           size_t nboot, double level, unsigned long seed, sf_sobol_result *res, double *boot)
{
    memset(res, 0, sizeof *res);
    if (D->d < sizeof inputs * 8)
        inputs &= (1UL << D->d) - 1;
    if (!(level > 0 && level < 1) || !inputs)
        return SF_EINVAL;
    size_t n = D->n, d = D->d, m = 0;
    size_t *rows = sf_malloc(n * sizeof *rows), *pick = sf_malloc(n * sizeof *pick);
    double *buf = sf_malloc(2 * n * sizeof *buf);
    double *bs = sf_malloc((nboot ? nboot : 1) * 2 * d * sizeof *bs);
    gsl_rng *rng = SF_FALLIBLE(gsl_rng_alloc(gsl_rng_mt19937));
    int rc = SF_ENOMEM;
    if (!rows || !pick || !buf || !bs || !rng)
        goto done;
    for (size_t j = 0; j < n; j++) {
        int ok = 1;
        for (size_t k = 0; k < d + 2; k++)
            ok = ok && (!sf_sobol_in_blocks(D, inputs, k * n + j) || isfinite(y[(k * n + j) * stride]));
        if (ok)
            rows[m++] = j;
    }
    res->n_used = m;
    res->n_excluded = n - m;
    res->nboot = nboot;
    res->level = level;
    rc = SF_EINVAL;
    if (m < 2)
        goto done;
    double s1[SF_SOBOL_MAXD], st[SF_SOBOL_MAXD], mean, var;
    if ((rc = indices(D, inputs, y, stride, rows, m, buf, s1, st, &res->mean, &res->var)))
        goto done;
    gsl_rng_set(rng, seed);
    /* bs: the nboot values of S_i, then of S_Ti, per input (contiguous for the sort) */
    size_t nb = 0;
    for (size_t b = 0; b < nboot; b++) {
        for (size_t r = 0; r < m; r++)
            pick[r] = rows[gsl_rng_uniform_int(rng, m)];
        double u1[SF_SOBOL_MAXD], ut[SF_SOBOL_MAXD];
        if (indices(D, inputs, y, stride, pick, m, buf, u1, ut, &mean, &var))
            continue;   /* a resample of constant values: no ratio (counted out of nb) */
        for (size_t i = 0; i < d; i++) {
            bs[(2 * i) * nboot + nb] = u1[i];
            bs[(2 * i + 1) * nboot + nb] = ut[i];
        }
        if (boot) {
            memcpy(boot + nb * 2 * d, u1, d * sizeof *u1);
            memcpy(boot + nb * 2 * d + d, ut, d * sizeof *ut);
        }
        nb++;
    }
    res->nboot_used = nb;
    double lo = 0.5 * (1 - level), hi = 0.5 * (1 + level);
    for (size_t i = 0; i < d; i++) {
        sf_sobol_index *x = &res->idx[i];
        x->s1 = s1[i];
        x->st = st[i];
        double *v1 = bs + 2 * i * nboot, *vt = bs + (2 * i + 1) * nboot;
        if (nb < 2 || !(inputs >> i & 1)) {
            x->s1_lo = x->s1_hi = x->st_lo = x->st_hi = x->s1_se = x->st_se = NAN;
            continue;
        }
        x->s1_se = gsl_stats_sd(v1, 1, nb);
        x->st_se = gsl_stats_sd(vt, 1, nb);
        gsl_sort(v1, 1, nb);
        gsl_sort(vt, 1, nb);
        x->s1_lo = gsl_stats_quantile_from_sorted_data(v1, 1, nb, lo);
        x->s1_hi = gsl_stats_quantile_from_sorted_data(v1, 1, nb, hi);
        x->st_lo = gsl_stats_quantile_from_sorted_data(vt, 1, nb, lo);
        x->st_hi = gsl_stats_quantile_from_sorted_data(vt, 1, nb, hi);
    }
    rc = SF_SUCCESS;
done:
    gsl_rng_free(rng);
    free(rows);
    free(pick);
    free(buf);
    free(bs);
    return rc;
}

/* ---- the rank-based estimator */

static int cmp_size(const void *a, const void *b)
{
    size_t u = *(const size_t *)a, v = *(const size_t *)b;
    return (u > v) - (u < v);
}

/* ord[0..m): the rows 0..m-1 by increasing xs, ties by row.  gsl_sort_index
 * (a heapsort) leaves the order of equal keys unspecified: each run of
 * equal keys is sorted by row afterwards. */
static void rank_order(const double *xs, size_t m, size_t *ord)
{
    gsl_sort_index(ord, xs, 1, m);
    for (size_t a = 0, b; a < m; a = b) {
        for (b = a + 1; b < m && xs[ord[b]] == xs[ord[a]]; b++)
            ;
        if (b - a > 1)
            qsort(ord + a, b - a, sizeof *ord, cmp_size);
    }
}

/* Per group g of a split: the running state of the walk along the
 * global order (first and last centred y seen, sum of neighbour
 * products, rows), the group's mean, sum of squares and range.  A group
 * of equal y is told by its range, not by its sum of squares: the
 * rounding of the group's mean leaves that at 1e-33, not 0. */
typedef struct {
    double mean, var, lo, hi, first, last, prod;
    size_t cnt;
} rank_group;

int sf_sobol_rank_s1(size_t n, size_t d, const double *x, size_t xstride, const double *y, size_t ystride,
                     size_t nsplit, double level, unsigned long seed, sf_sobol_rank_result *res)
{
    memset(res, 0, sizeof *res);
    res->nsplit = nsplit;
    res->level = level;
    if (!(level > 0 && level < 1) || d == 0 || d > SF_SOBOL_MAXD || xstride < d || n < 3)
        return SF_EINVAL;
    size_t m = 0;
    for (size_t j = 0; j < n; j++) {
        int ok = isfinite(y[j * ystride]);
        for (size_t i = 0; i < d; i++)
            ok = ok && isfinite(x[j * xstride + i]);
        m += ok;
    }
    res->n_used = m;
    res->n_excluded = n - m;
    if (m < 3)
        return SF_EINVAL;
    size_t K = (size_t)cbrt((double)m);
    K = K < 2 ? 2 : K;
    K = K > m / 2 ? 0 : K;   /* groups of 2 rows at least; 0: no split */
    res->groups = K;
    /* rows[0..m): the used rows; yc their centred y; xs one input's column;
     * ord the order; lab a split's group of each used row */
    size_t *rows = sf_malloc(m * sizeof *rows), *ord = sf_malloc(m * sizeof *ord), *lab = sf_malloc(m * sizeof *lab);
    double *yc = sf_malloc(m * sizeof *yc), *xs = sf_malloc(m * sizeof *xs), *th = sf_malloc((K ? K : 1) * sizeof *th);
    rank_group *G = sf_malloc((K ? K : 1) * sizeof *G);
    gsl_rng *rng = SF_FALLIBLE(gsl_rng_alloc(gsl_rng_mt19937));
    int rc = SF_ENOMEM;
    if (!rows || !ord || !lab || !yc || !xs || !th || !G || !rng)
        goto done;
    for (size_t j = 0, k = 0; j < n; j++) {
        int ok = isfinite(y[j * ystride]);
        for (size_t i = 0; i < d; i++)
            ok = ok && isfinite(x[j * xstride + i]);
        if (ok)
            rows[k++] = j;
    }
    double mean = 0, var = 0;
    for (size_t k = 0; k < m; k++)
        mean += y[rows[k] * ystride];
    mean /= (double)m;
    for (size_t k = 0; k < m; k++) {
        yc[k] = y[rows[k] * ystride] - mean;
        var += yc[k] * yc[k];
    }
    var /= (double)m;
    res->mean = mean;
    res->var = var;
    rc = SF_EFAIL;
    if (!(var > 0))
        goto done;
    double z = gsl_cdf_ugaussian_Qinv(0.5 * (1 - level));
    for (size_t i = 0; i < d; i++) {
        for (size_t k = 0; k < m; k++)
            xs[k] = x[rows[k] * xstride + i];
        rank_order(xs, m, ord);
        double c = yc[ord[m - 1]] * yc[ord[0]];   /* the wrapped pair */
        for (size_t k = 0; k + 1 < m; k++)
            c += yc[ord[k]] * yc[ord[k + 1]];
        sf_sobol_rank_index *o = &res->idx[i];
        o->s1 = c / (double)m / var;
        /* the splits: the same stream, so the same splits, for every input */
        gsl_rng_set(rng, seed);
        for (size_t k = 0; k < m; k++)
            lab[k] = K ? k % K : 0;
        double v = 0;
        size_t used = 0;
        for (size_t r = 0; K && r < nsplit; r++) {
            gsl_ran_shuffle(rng, lab, m, sizeof *lab);
            memset(G, 0, K * sizeof *G);
            for (size_t g = 0; g < K; g++) {
                G[g].lo = INFINITY;
                G[g].hi = -INFINITY;
            }
            for (size_t k = 0; k < m; k++) {
                rank_group *q = &G[lab[k]];
                q->mean += yc[k];
                q->lo = fmin(q->lo, yc[k]);
                q->hi = fmax(q->hi, yc[k]);
                q->cnt++;
            }
            for (size_t g = 0; g < K; g++)
                G[g].mean /= (double)G[g].cnt;
            for (size_t k = 0; k < m; k++)
                G[lab[k]].var += gsl_pow_2(yc[k] - G[lab[k]].mean);
            for (size_t g = 0; g < K; g++)
                G[g].cnt = 0;
            /* each group's rows in the global order are its own order */
            for (size_t k = 0; k < m; k++) {
                rank_group *q = &G[lab[ord[k]]];
                double u = yc[ord[k]] - q->mean;
                if (q->cnt++)
                    q->prod += q->last * u;
                else
                    q->first = u;
                q->last = u;
            }
            size_t kk = 0;
            for (size_t g = 0; g < K; g++)
                if (G[g].hi > G[g].lo)   /* a group of equal y has no index */
                    th[kk++] = (G[g].prod + G[g].last * G[g].first) / G[g].var;
            if (kk < 2)
                continue;
            v += gsl_stats_variance(th, 1, kk) / (double)K;
            used++;
        }
        res->nsplit_used = used;
        o->se = used ? sqrt(v / (double)used) : NAN;
        o->lo = o->s1 - z * o->se;
        o->hi = o->s1 + z * o->se;
    }
    rc = SF_SUCCESS;
done:
    gsl_rng_free(rng);
    free(rows);
    free(ord);
    free(lab);
    free(yc);
    free(xs);
    free(th);
    free(G);
    return rc;
}
