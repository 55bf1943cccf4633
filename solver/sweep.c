#include "sweep.h"
#include "cof.h"
#include "montecarlo.h"
#include "oscillator.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_statistics_double.h>

int sf_sweep_set(sf_scene *s, const char *name, double value, char *err, size_t errlen)
{
    if (!strcmp(name, "l_over_R")) {
        if (!(value > 0) || !isfinite(value)) {
            return sf_seterr(err, errlen, SF_EPARSE, "l_over_R must be > 0 (got %g)", value);
        }
        s->l = value * s->R;
        return SF_SUCCESS;
    }
    double cv = s->mu_std / s->mu_mean;
    char line[160];
    snprintf(line, sizeof line, "%s = %.17g\n", name, value);
    int rc = sf_scene_parse(s, line, "--param", 1, err, errlen);
    if (!rc && !strcmp(name, "mu_mean"))
        s->mu_std = cv * s->mu_mean;   /* fixed CV (Fig. 13) */
    return rc;
}

typedef struct {
    const sf_scene *s;
    const double *det;
    sf_cof_plan *plan;
} ws_t;

static void *ws_alloc(void *ctx)
{
    const ws_t *c = ctx;
    ws_t *w = sf_malloc(sizeof *w);
    if (!w)
        return NULL;
    *w = *c;
    if (sf_cof_plan_alloc_mt(c->s, &w->plan, NULL, 0)) {
        free(w);
        return NULL;
    }
    return w;
}

static void ws_free(void *p)
{
    ws_t *w = p;
    sf_cof_plan_free_mt(w->plan);
    free(w);
}

static int realise(void *p, size_t i, gsl_rng *rng, double *out)
{
    ws_t *w = p;
    (void)i;
    sf_cof *cof;
    int rc = sf_cof_plan_draw(w->plan, rng, &cof);
    if (rc)
        return rc;
    sf_osc *o;
    sf_osc_result r;
    rc = sf_osc_alloc(w->s, cof, &o, NULL, 0);
    if (!rc) {
        rc = sf_osc_run(o, NULL, NULL, 0, &r, NULL, 0);
        out[SF_SWEEP_PVX] = r.pv_x / w->det[SF_SWEEP_PVX];
        out[SF_SWEEP_PVF] = r.pv_F / w->det[SF_SWEEP_PVF];
        out[SF_SWEEP_SF] = r.stick_fraction / w->det[SF_SWEEP_SF];
        sf_osc_result_free(&r);
        sf_osc_free(o);
    }
    sf_cof_free(cof);
    return rc;
}

int sf_sweep_run(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume,
                 const char *label, sf_sweep_point *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    /* the deterministic reference, same definitions */
    sf_scene d = *s;
    d.cof = SF_COF_UNIFORM;
    sf_cof *u;
    sf_osc *o;
    sf_osc_result r = { 0 };   /* freed also when the run fails */
    int rc = sf_cof_alloc_uniform(s->mu_mean, &u);
    if (rc)
        return rc;
    rc = sf_osc_alloc(&d, u, &o, err, errlen);
    if (!rc)
        rc = sf_osc_run(o, NULL, NULL, 0, &r, err, errlen);
    sf_osc_free(o);
    sf_cof_free(u);
    if (rc) {
        sf_osc_result_free(&r);
        return rc;
    }
    out->det[SF_SWEEP_PVX] = r.pv_x;
    out->det[SF_SWEEP_PVF] = r.pv_F;
    out->det[SF_SWEEP_SF] = r.stick_fraction;
    sf_osc_result_free(&r);
    if (!(out->det[SF_SWEEP_PVX] > 0) || !(out->det[SF_SWEEP_SF] > 0)) {
        return sf_seterr(err, errlen, SF_EINVAL, "the deterministic reference has no %s in [t_skip, T]: raise T",
                         s->qoi_def == SF_QOI_PAPER ? "oscillation or no stick" : "complete cycle");
    }
    out->n = n;
    out->ratio = sf_calloc(n * SF_SWEEP_NQ, sizeof *out->ratio);
    if (!out->ratio)
        return SF_ENOMEM;
    ws_t ctx = { s, out->det, NULL };
    sf_mc_spec spec = { n, SF_SWEEP_NQ, s->seed, threads, checkpoint, resume, 0, label };
    /* the checkpoint's identity: the effective scene as text (no padding bytes) */
    char *text = NULL;
    size_t len = 0;
    FILE *m = SF_FALLIBLE(open_memstream(&text, &len));
    if (!m)
        return SF_ENOMEM;
    sf_scene_write(s, m);
    fclose(m);
    spec.key = sf_mc_hash(text, len, 0);
    free(text);
    sf_mc_ops ops = { ws_alloc, ws_free, realise };
    rc = sf_mc_run(&spec, &ops, &ctx, out->ratio, &out->from_checkpoint, err, errlen);
    if (rc)
        return rc;
    double *v = sf_malloc(n * sizeof *v);
    if (!v)
        return SF_ENOMEM;
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        size_t m = 0;
        for (size_t i = 0; i < n; i++)
            if (isfinite(out->ratio[i * SF_SWEEP_NQ + q]))
                v[m++] = out->ratio[i * SF_SWEEP_NQ + q];
        out->mean[q] = m ? gsl_stats_mean(v, 1, m) : NAN;
        out->std[q] = m > 1 ? gsl_stats_sd(v, 1, m) : NAN;
        if (q == SF_SWEEP_PVX)
            out->n_valid = m;
    }
    free(v);
    return SF_SUCCESS;
}

void sf_sweep_point_free(sf_sweep_point *p)
{
    free(p->ratio);
    p->ratio = NULL;
}
