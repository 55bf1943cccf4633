/* slipfield: Sobol' indices of the QoI ratios over the model's parameters
 * (sensitivity.h): the inputs' ranges, each evaluation's scene and run,
 * and the writers of the indices and evaluations. */
#include "sensitivity.h"
#include "cof.h"
#include "montecarlo.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NOUT (2 * SF_SWEEP_NQ)
#define RANK_SPLITS 200   /* random splits of the given-data estimator's standard error (sobol.h) */

static const char *const iname[SF_SENS_D] = { "log10_l_over_R", "cv", "v_b", "mu_mean", "field" };
static const char *const qname[SF_SWEEP_NQ] = { "pv_x_ratio", "pv_F_ratio", "stick_fraction_ratio" };

const char *sf_sens_input_name(int i)
{
    return i >= 0 && i < SF_SENS_D ? iname[i] : "?";
}

void sf_sens_ranges_default(sf_sens_ranges *r)
{
    static const double lo[SF_SENS_NPAR] = { -2, 0.1, 0.1, 0.2 }, hi[SF_SENS_NPAR] = { 3, 0.3, 0.6, 1 };
    memcpy(r->lo, lo, sizeof lo);
    memcpy(r->hi, hi, sizeof hi);
}

int sf_sens_ranges_check(const sf_sens_ranges *r, char *err, size_t errlen)
{
    for (int i = 0; i < SF_SENS_NPAR; i++) {
        if (!isfinite(r->lo[i]) || !isfinite(r->hi[i]) || !(r->lo[i] < r->hi[i]))
            return sf_seterr(err, errlen, SF_EINVAL, "%s: the range [%g, %g] is not an interval", iname[i],
                             r->lo[i], r->hi[i]);
        if (i != SF_SENS_LOGLR && !(r->lo[i] > 0))
            return sf_seterr(err, errlen, SF_EINVAL, "%s: the range must be positive (got %g)", iname[i], r->lo[i]);
    }
    return SF_SUCCESS;
}

void sf_sens_scene(const sf_scene *base, const sf_sens_ranges *r, const double *u, sf_scene *s, double *x)
{
    for (int i = 0; i < SF_SENS_NPAR; i++)
        x[i] = r->lo[i] + u[i] * (r->hi[i] - r->lo[i]);
    *s = *base;
    s->l = pow(10, x[SF_SENS_LOGLR]) * s->R;
    s->v_b = x[SF_SENS_VB];
    s->mu_mean = x[SF_SENS_MU];
    s->mu_std = x[SF_SENS_CV] * x[SF_SENS_MU];
}

typedef struct {
    const sf_scene *base;
    const sf_sens_ranges *r;
    const sf_sobol_design *D;
    unsigned long inputs;   /* the blocks run */
    double *x;   /* the parameters, written by each evaluation into its own slot */
    gsl_rng *rng;
} ctx_t;

static void *ws_alloc(void *p)
{
    const ctx_t *c = p;
    ctx_t *w = sf_malloc(sizeof *w);
    if (!w)
        return NULL;
    *w = *c;
    w->rng = SF_FALLIBLE(gsl_rng_alloc(gsl_rng_mt19937));
    if (!w->rng) {
        free(w);
        return NULL;
    }
    return w;
}

static void ws_free(void *p)
{
    ctx_t *w = p;
    gsl_rng_free(w->rng);
    free(w);
}

void sf_sens_point(const sf_scene *base, const sf_sens_ranges *r, const sf_sobol_design *D, size_t e, sf_scene *s,
                   double *x, gsl_rng *field_rng)
{
    double u[SF_SENS_D];
    sf_sobol_point(D, e, u);
    sf_sens_scene(base, r, u, s, x);
    s->cof_generator = SF_COFGEN_BELT_NOISE;   /* the field input: one white noise for every parameter */
    gsl_rng_set(field_rng, sf_mc_seed(base->seed, sf_sobol_source_row(D, e, SF_SENS_FIELD)));
}

/* Evaluation e: its scene and field, the run and the deterministic
 * reference. */
static int evaluate(void *p, size_t e, gsl_rng *unused, double *out)
{
    (void)unused;
    ctx_t *w = p;
    if (!sf_sobol_in_blocks(w->D, w->inputs, e)) {   /* a block not asked for */
        for (int k = 0; k < SF_SENS_NPAR; k++)
            w->x[e * SF_SENS_NPAR + k] = NAN;
        for (int k = 0; k < NOUT; k++)
            out[k] = NAN;
        return SF_SUCCESS;
    }
    sf_scene s;
    sf_sens_point(w->base, w->r, w->D, e, &s, w->x + e * SF_SENS_NPAR, w->rng);
    double det[SF_SWEEP_NQ], q[SF_SWEEP_NQ];
    sf_cof_plan *plan;
    int rc = sf_sweep_det(&s, det, NULL, 0);
    if (!rc && !(rc = sf_cof_plan_alloc_mt(&s, &plan, NULL, 0))) {
        rc = sf_sweep_realise(&s, plan, w->rng, q);
        sf_cof_plan_free_mt(plan);
    }
    if (rc)
        return rc;
    for (int k = 0; k < SF_SWEEP_NQ; k++) {
        out[k] = q[k] / det[k];
        out[SF_SWEEP_NQ + k] = q[k];
    }
    return SF_SUCCESS;
}

int sf_sens_run(const sf_scene *base, const sf_sens_ranges *r, size_t n, size_t nboot, double level,
                int threads, const char *label, sf_sens **out, char *err, size_t errlen)
{
    return sf_sens_run_some(base, r, n, SF_SOBOL_ALL, nboot, level, threads, label, out, err, errlen);
}

int sf_sens_run_some(const sf_scene *base, const sf_sens_ranges *r, size_t n, unsigned long inputs, size_t nboot,
                     double level, int threads, const char *label, sf_sens **out, char *err, size_t errlen)
{
    *out = NULL;
    inputs &= (1UL << SF_SENS_D) - 1;
    int rc = sf_sens_ranges_check(r, err, errlen);
    if (rc)
        return rc;
    if (base->cof != SF_COF_FIELD)
        return sf_seterr(err, errlen, SF_EINVAL, "the study needs cof = field (the field is one of its inputs)");
    if (n < 2 || !(level > 0 && level < 1))
        return sf_seterr(err, errlen, SF_EINVAL, "need at least 2 rows and a level in (0, 1) (got %zu, %g)", n,
                         level);
    if (!inputs)
        return sf_seterr(err, errlen, SF_EINVAL, "no input's block asked for");
    sf_sens *S = sf_calloc(1, sizeof *S);
    if (!S)
        return SF_ENOMEM;
    gsl_rng *g = SF_FALLIBLE(gsl_rng_alloc(gsl_rng_mt19937));
    rc = SF_ENOMEM;
    if (!g)
        goto fail;
    /* the design's stream: the seed's own (the fields use sf_mc_seed(seed, row)) */
    gsl_rng_set(g, base->seed);
    rc = sf_sobol_design_alloc(n, SF_SENS_D, g, &S->D);
    gsl_rng_free(g);
    if (rc)
        goto fail;
    S->inputs = inputs;
    size_t ne = sf_sobol_nevals(S->D);
    S->x = sf_calloc(ne * SF_SENS_NPAR, sizeof *S->x);
    S->y = sf_calloc(ne * NOUT, sizeof *S->y);
    rc = SF_ENOMEM;
    if (!S->x || !S->y)
        goto fail;
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        if (!(S->boot[q] = sf_malloc((nboot ? nboot : 1) * 2 * SF_SENS_D * sizeof *S->boot[q])))
            goto fail;
    ctx_t c = { base, r, S->D, inputs, S->x, NULL };
    sf_mc_spec spec = { ne, NOUT, base->seed, threads, NULL, 0, 0, label };
    sf_mc_ops ops = { ws_alloc, ws_free, evaluate };
    if ((rc = sf_mc_run(&spec, &ops, &c, S->y, NULL, err, errlen))) {
        sf_seterr(err, errlen, rc, "a run of the study failed: %s (a deterministic reference without an "
                  "oscillation in [t_skip, T] is refused: raise T)", sf_strerror(rc));
        goto fail;
    }
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        if ((rc = sf_sobol_estimate_some(S->D, inputs, S->y + q, NOUT, nboot, level,
                                         sf_mc_seed(base->seed, 2 * n + (size_t)q), &S->res[q], S->boot[q]))) {
            sf_seterr(err, errlen, rc, "%s: no indices: a constant ratio, or fewer than 2 rows whose runs are all "
                      "finite", qname[q]);
            goto fail;
        }
    for (int q = 0; q < SF_SWEEP_NQ; q++)   /* the same rows as given data: 2n of them, A's then B's */
        if ((rc = sf_sobol_rank_s1(2 * n, SF_SENS_NPAR, S->x, SF_SENS_NPAR, S->y + q, NOUT, RANK_SPLITS, level,
                                   sf_mc_seed(base->seed, 2 * n + SF_SWEEP_NQ + (size_t)q), &S->rank[q]))) {
            sf_seterr(err, errlen, rc, "%s: no given-data indices (fewer than 3 finite rows)", qname[q]);
            goto fail;
        }
    *out = S;
    return SF_SUCCESS;
fail:
    sf_sens_free(S);
    return rc;
}

void sf_sens_free(sf_sens *S)
{
    if (!S)
        return;
    sf_sobol_design_free(S->D);
    free(S->x);
    free(S->y);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        free(S->boot[q]);
    free(S);
}

void sf_sens_write_indices(FILE *f, const sf_sens *S)
{
    int lv = (int)lround(100 * S->res[0].level);
    fprintf(f, "qoi\tinput\tS1\tS1_ci%d_lo\tS1_ci%d_hi\tS1_se\tST\tST_ci%d_lo\tST_ci%d_hi\tST_se\tn_rows\t"
               "n_excluded\tnboot\tvariance\tS1_rank\tS1_rank_ci%d_lo\tS1_rank_ci%d_hi\tS1_rank_se\n", lv, lv, lv,
            lv, lv, lv);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const sf_sobol_result *r = &S->res[q];
        for (int i = 0; i < SF_SENS_D; i++) {
            const sf_sobol_index *x = &r->idx[i];
            const sf_sobol_rank_index *g = i < SF_SENS_NPAR ? &S->rank[q].idx[i] : NULL;
            fprintf(f, "%s\t%s\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%zu\t%zu\t%zu\t%.17g\t"
                       "%.17g\t%.17g\t%.17g\t%.17g\n",
                    qname[q], iname[i], x->s1, x->s1_lo, x->s1_hi, x->s1_se, x->st, x->st_lo, x->st_hi, x->st_se,
                    r->n_used, r->n_excluded, r->nboot, r->var, g ? g->s1 : NAN, g ? g->lo : NAN, g ? g->hi : NAN,
                    g ? g->se : NAN);
        }
    }
}

void sf_sens_write_evals(FILE *f, const sf_sens *S)
{
    fprintf(f, "block\trow\tfield_row");
    for (int i = 0; i < SF_SENS_NPAR; i++)
        fprintf(f, "\t%s", iname[i]);
    fputs("\tpv_x_ratio\tpv_F_ratio\tstick_fraction_ratio\tpv_x[m]\tpv_F[N]\tstick_fraction[-]\n", f);
    size_t n = S->D->n, ne = sf_sobol_nevals(S->D);
    for (size_t e = 0; e < ne; e++) {
        size_t k = e / n;
        if (!sf_sobol_in_blocks(S->D, S->inputs, e))
            continue;
        fprintf(f, "%s%s\t%zu\t%zu", k == 0 ? "A" : k == 1 ? "B" : "AB_", k >= 2 ? iname[k - 2] : "", e % n,
                sf_sobol_source_row(S->D, e, SF_SENS_FIELD));
        for (int i = 0; i < SF_SENS_NPAR; i++)
            fprintf(f, "\t%.17g", S->x[e * SF_SENS_NPAR + i]);
        for (int k2 = 0; k2 < NOUT; k2++)
            fprintf(f, "\t%.17g", S->y[e * NOUT + k2]);
        fputc('\n', f);
    }
}
