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
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

static const char *const qname[SF_SWEEP_NQ] = { "pv_x", "pv_F", "stick_fraction" };
static const char *const qunit[SF_SWEEP_NQ] = { "m", "N", "-" };

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
    sf_keytab t = sf_scene_keytab(s);   /* the swept value overrides the scene's */
    for (size_t k = 0; k < t.n; k++)
        if (!strcmp(t.keys[k].name, name))
            t.set[k] = 0;
    char line[160];
    snprintf(line, sizeof line, "%s = %.17g\n", name, value);
    int rc = sf_scene_parse(s, line, "--param", 1, err, errlen);
    if (!rc && !strcmp(name, "mu_mean"))
        s->mu_std = cv * s->mu_mean;   /* fixed CV (Fig. 13) */
    return rc;
}

typedef struct {
    const sf_scene *s;
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

int sf_sweep_realise(const sf_scene *s, sf_cof_plan *plan, gsl_rng *rng, double out[SF_SWEEP_NQ])
{
    sf_cof *cof;
    int rc = sf_cof_plan_draw(plan, rng, &cof);
    if (rc)
        return rc;
    sf_osc *o;
    sf_osc_result r;
    rc = sf_osc_alloc(s, cof, &o, NULL, 0);
    if (!rc) {
        rc = sf_osc_run(o, NULL, NULL, 0, &r, NULL, 0);
        out[SF_SWEEP_PVX] = r.pv_x;
        out[SF_SWEEP_PVF] = r.pv_F;
        out[SF_SWEEP_SF] = r.stick_fraction;
        sf_osc_result_free(&r);
        sf_osc_free(o);
    }
    sf_cof_free(cof);
    return rc;
}

static int realise(void *p, size_t i, gsl_rng *rng, double *out)
{
    ws_t *w = p;
    (void)i;
    return sf_sweep_realise(w->s, w->plan, rng, out);
}

int sf_sweep_det(const sf_scene *s, double det[SF_SWEEP_NQ], char *err, size_t errlen)
{
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
    det[SF_SWEEP_PVX] = r.pv_x;
    det[SF_SWEEP_PVF] = r.pv_F;
    det[SF_SWEEP_SF] = r.stick_fraction;
    sf_osc_result_free(&r);
    for (int q = 0; q < SF_SWEEP_NQ; q++)   /* every ratio needs its reference */
        if (!(det[q] > 0) || !isfinite(det[q]))
            return sf_seterr(err, errlen, SF_EINVAL,
                             "the deterministic reference has no %s in [t_skip, T] (%s = %g): raise T",
                             s->qoi_def == SF_QOI_PAPER ? "oscillation or no stick" : "complete cycle",
                             qname[q], det[q]);
    return SF_SUCCESS;
}

int sf_sweep_run(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume,
                 const char *label, sf_sweep_point *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    /* the deterministic reference, same definitions */
    int rc = sf_sweep_det(s, out->det, err, errlen);
    if (rc)
        return rc;
    out->n = n;
    out->qoi = sf_calloc(n * SF_SWEEP_NQ, sizeof *out->qoi);
    out->ratio = sf_calloc(n * SF_SWEEP_NQ, sizeof *out->ratio);
    if (!out->qoi || !out->ratio)
        return SF_ENOMEM;
    ws_t ctx = { s, NULL };
    sf_mc_spec spec = { n, SF_SWEEP_NQ, s->seed, threads, checkpoint, resume, 0, label };
    /* the checkpoint's identity: what a line holds and the effective
     * scene as text (no padding bytes) */
    char *text = NULL;
    size_t len = 0;
    FILE *m = SF_FALLIBLE(open_memstream(&text, &len));
    if (!m)
        return SF_ENOMEM;
    fputs("sweep v2: pv_x pv_F stick_fraction\n", m);
    sf_scene_write(s, m);
    fclose(m);
    spec.key = sf_mc_hash(text, len, 0);
    free(text);
    sf_mc_ops ops = { ws_alloc, ws_free, realise };
    rc = sf_mc_run(&spec, &ops, &ctx, out->qoi, &out->from_checkpoint, err, errlen);
    return rc ? rc : sf_sweep_point_stats(out);
}

int sf_sweep_stat_of(const double *x, size_t stride, size_t n, sf_sweep_stat *st)
{
    double *v = sf_malloc((n ? n : 1) * sizeof *v);
    if (!v)
        return SF_ENOMEM;
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i * stride]))
            v[m++] = x[i * stride];
    st->n_used = m;
    st->n_excluded = n - m;
    st->mean = m ? gsl_stats_mean(v, 1, m) : NAN;
    st->std = st->se = st->ci_lo = st->ci_hi = NAN;
    if (m > 1) {
        st->std = gsl_stats_sd_m(v, 1, m, st->mean);
        st->se = st->std / sqrt((double)m);
        double t = gsl_cdf_tdist_Pinv(0.5 * (1 + SF_SWEEP_CI_LEVEL), (double)(m - 1));
        st->ci_lo = st->mean - t * st->se;
        st->ci_hi = st->mean + t * st->se;
    }
    free(v);
    return SF_SUCCESS;
}

int sf_sweep_point_stats(sf_sweep_point *p)
{
    p->n_valid = 0;
    for (size_t i = 0; i < p->n; i++) {
        int all = 1;
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            double *r = p->ratio + i * SF_SWEEP_NQ + q;
            *r = p->qoi[i * SF_SWEEP_NQ + q] / p->det[q];
            all = all && isfinite(*r) && isfinite(p->qoi[i * SF_SWEEP_NQ + q]);
        }
        p->n_valid += (size_t)all;
    }
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        int rc = sf_sweep_stat_of(p->qoi + q, SF_SWEEP_NQ, p->n, &p->stat[q]);
        if (rc || (rc = sf_sweep_stat_of(p->ratio + q, SF_SWEEP_NQ, p->n, &p->rstat[q])))
            return rc;
        p->mean[q] = p->rstat[q].mean;
        p->std[q] = p->rstat[q].std;
    }
    return SF_SUCCESS;
}

void sf_sweep_fmt(char *buf, size_t len, double x)
{
    /* an exponent only where plain digits would be long (20, not 2e+01) */
    int plain = fabs(x) >= 1e-4 && fabs(x) < 1e15;
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(buf, len, "%.*g", prec, x);
        if (!isfinite(x) || (strtod(buf, NULL) == x && !(plain && strchr(buf, 'e') && prec < 17)))
            return;
    }
}

void sf_sweep_write_header(FILE *f)
{
    fputs("param\tvalue\trealisation\tpv_x_ratio\tpv_F_ratio\tstick_fraction_ratio", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%s[%s]", qname[q], qunit[q]);
    fputc('\n', f);
}

void sf_sweep_write_rows(FILE *f, const char *param, double value, const sf_sweep_point *p)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    for (size_t i = 0; i < p->n; i++) {
        const double *r = p->ratio + i * SF_SWEEP_NQ, *x = p->qoi + i * SF_SWEEP_NQ;
        fprintf(f, "%s\t%s\t%zu\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", param, v, i, r[0], r[1], r[2], x[0],
                x[1], x[2]);
    }
}

void sf_sweep_summary_header(FILE *f)
{
    int lv = (int)lround(100 * SF_SWEEP_CI_LEVEL);
    fputs("param\tvalue\tn", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const char *a = qname[q], *u = qunit[q];
        fprintf(f, "\t%s_n_used\t%s_n_excluded\t%s_mean[%s]\t%s_std[%s]\t%s_se[%s]\t%s_ci%d_lo[%s]\t%s_ci%d_hi[%s]"
                   "\t%s_det[%s]\t%s_ratio_mean[-]\t%s_ratio_std[-]\t%s_ratio_se[-]",
                a, a, a, u, a, u, a, u, a, lv, u, a, lv, u, a, u, a, a, a);
    }
    fputc('\n', f);
}

void sf_sweep_summary_row(FILE *f, const char *param, double value, const sf_sweep_point *p)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    fprintf(f, "%s\t%s\t%zu", param, v, p->n);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const sf_sweep_stat *a = &p->stat[q], *b = &p->rstat[q];
        fprintf(f, "\t%zu\t%zu\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g", a->n_used,
                a->n_excluded, a->mean, a->std, a->se, a->ci_lo, a->ci_hi, p->det[q], b->mean, b->std, b->se);
    }
    fputc('\n', f);
}

void sf_sweep_point_free(sf_sweep_point *p)
{
    free(p->qoi);
    free(p->ratio);
    p->qoi = p->ratio = NULL;
}
