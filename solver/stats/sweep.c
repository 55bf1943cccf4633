/* slipfield: Monte Carlo sweeps of the stochastic oscillator over a
 * parameter (sweep.h): each point's realisations and deterministic
 * reference, their statistics and the rows written. */
#include "sweep.h"
#include "cof.h"
#include "mcstop.h"
#include "montecarlo.h"
#include "oscillator.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
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
    int known = 0;
    for (size_t k = 0; k < t.n; k++)
        if (!strcmp(t.keys[k].name, name)) {
            t.set[k] = 0;
            known = 1;
        }
    if (!known)
        return sf_seterr(err, errlen, SF_EPARSE, "unknown parameter '%.40s' (l_over_R or a numeric scene key: see "
                         "'slipfield help scene')", name);
    char line[160];
    snprintf(line, sizeof line, "%s = %.17g\n", name, value);
    int rc = sf_scene_parse(s, line, "--param", 1, err, errlen);
    if (!rc && !strcmp(name, "mu_mean"))
        s->mu_std = cv * s->mu_mean;   /* fixed CV (Fig. 13) */
    return rc;
}

double sf_sweep_companion(const sf_cof *cof, const sf_scene *s)
{
    if (sf_cof_window_margin(cof) > 0)
        return NAN;
    enum { LINES = 3, K = SF_SWEEP_CV_POINTS / LINES };
    double sum = 0;
    for (int j = 0; j < LINES; j++)
        for (int k = 0; k < K; k++) {
            double t = s->t_skip + (k + 0.5) * (s->T - s->t_skip) / K;
            sum += sf_cof_eval(cof, -s->v_b * t, 0.5 * s->R * (j - 1));
        }
    return sum / (LINES * K);
}

void *sf_sweep_ws_alloc(void *ctx)
{
    const sf_sweep_ws *c = ctx;
    sf_sweep_ws *w = sf_malloc(sizeof *w);
    if (!w)
        return NULL;
    *w = *c;
    if (sf_cof_plan_build_mt(c->s, c->pl, &w->plan, NULL, 0)) {
        free(w);
        return NULL;
    }
    return w;
}

void sf_sweep_ws_free(void *p)
{
    sf_sweep_ws *w = p;
    sf_cof_plan_free_mt(w->plan);
    free(w);
}

/* one realisation: a COF drawn from plan, the run on the scene's plan pl
 * (NULL: the oscillator plans it, the same bits), its QoIs into out and,
 * with companion, C into out[SF_SWEEP_NQ] */
static int realise_on(const sf_scene *s, const sf_plan *pl, sf_cof_plan *plan, int companion, gsl_rng *rng,
                      double *out)
{
    sf_cof *cof;
    int rc = sf_cof_plan_draw(plan, rng, &cof);
    if (rc)
        return rc;
    rc = sf_sweep_solve(s, pl, cof, out, NULL);
    if (!rc && companion)   /* after the run: its window stays where the run left it */
        out[SF_SWEEP_NQ] = sf_sweep_companion(cof, s);
    sf_cof_free(cof);
    return rc;
}

int sf_sweep_solve(const sf_scene *s, const sf_plan *pl, const sf_cof *cof, double out[SF_SWEEP_NQ], double *work)
{
    sf_osc *o;
    sf_osc_result r;
    int rc = pl ? sf_osc_alloc_plan(s, pl, cof, &o, NULL, 0) : sf_osc_alloc(s, cof, &o, NULL, 0);
    if (rc)
        return rc;
    rc = sf_osc_run(o, NULL, NULL, 0, &r, NULL, 0);
    out[SF_SWEEP_PVX] = r.pv_x;
    out[SF_SWEEP_PVF] = r.pv_F;
    out[SF_SWEEP_SF] = r.stick_fraction;
    if (work)
        *work = (double)r.wrench_evals * (double)sf_osc_ncells(o);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    return rc;
}

int sf_sweep_realise(const sf_scene *s, sf_cof_plan *plan, gsl_rng *rng, double out[SF_SWEEP_NQ])
{
    return realise_on(s, NULL, plan, 0, rng, out);
}

static int realise(void *p, size_t i, gsl_rng *rng, double *out)
{
    sf_sweep_ws *w = p;
    (void)i;
    return realise_on(w->s, w->pl, w->plan, w->companion, rng, out);
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

/* n realisations, or two stages up to n with target_se > 0; with the
 * companion C of each (cv) */
static int run(const sf_scene *s, size_t n, double target_se, size_t n_pilot, int cv, int threads,
               const char *checkpoint, int resume, const char *label, sf_sweep_point *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->estimator = target_se > 0 ? SF_EST_TARGET : cv ? SF_EST_CV : SF_EST_PLAIN;
    /* the deterministic reference, same definitions */
    int rc = sf_sweep_det(s, out->det, err, errlen);
    if (rc)
        return rc;
    out->n = n;
    out->qoi = sf_calloc(n * SF_SWEEP_NQ, sizeof *out->qoi);
    out->ratio = sf_calloc(n * SF_SWEEP_NQ, sizeof *out->ratio);
    if (!out->qoi || !out->ratio)
        return SF_ENOMEM;
    sf_plan pl;
    if ((rc = sf_plan_make(s, &pl, err, errlen)))
        return rc;
    pl.history = 0;   /* a sweep keeps only the QoIs */
    out->plan = pl;   /* the rows' plan, for u_num's companion (sweep.h) */
    out->planned = 1;
    sf_sweep_ws ctx = { s, &pl, NULL, NULL, cv };
    size_t nout = SF_SWEEP_NQ + (cv != 0);
    double *vals = out->qoi;   /* n x nout: the QoIs, and C when cv */
    if (cv) {
        out->cv_known = s->mu_mean;
        out->companion = sf_calloc(n, sizeof *out->companion);
        vals = sf_calloc(n * nout, sizeof *vals);
        if (!out->companion || !vals) {
            free(vals);
            return SF_ENOMEM;
        }
    }
    sf_mc_spec spec = { n, nout, s->seed, threads, checkpoint, resume, 0, label };
    /* the checkpoint's identity: what a line holds and the effective
     * scene as text (no padding bytes) */
    char *text = NULL;
    size_t len = 0;
    FILE *m = SF_FALLIBLE(open_memstream(&text, &len));
    if (!m) {
        if (vals != out->qoi)
            free(vals);
        return SF_ENOMEM;
    }
    fputs(cv ? "sweep v2: pv_x pv_F stick_fraction companion\n" : "sweep v2: pv_x pv_F stick_fraction\n", m);
    sf_scene_write(s, m);
    fclose(m);
    spec.key = sf_mc_hash(text, len, 0);
    free(text);
    sf_mc_ops ops = { sf_sweep_ws_alloc, sf_sweep_ws_free, realise };
    if (target_se > 0) {
        double target[SF_SWEEP_NQ];
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            target[q] = target_se * out->det[q];
        sf_mcstop_spec st = { n_pilot, n, target };
        out->n_pilot = n_pilot;
        rc = sf_mcstop_run(&spec, &st, &ops, &ctx, out->qoi, &out->n, &out->stop, &out->from_checkpoint, err,
                           errlen);
    } else {
        rc = sf_mc_run(&spec, &ops, &ctx, vals, &out->from_checkpoint, err, errlen);
    }
    if (vals != out->qoi) {   /* split the QoIs from the companion */
        for (size_t i = 0; i < out->n; i++) {
            memcpy(out->qoi + i * SF_SWEEP_NQ, vals + i * nout, SF_SWEEP_NQ * sizeof *vals);
            out->companion[i] = vals[i * nout + SF_SWEEP_NQ];
        }
        free(vals);
    }
    return rc ? rc : sf_sweep_point_stats(out);
}

int sf_sweep_run(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume, const char *label,
                 sf_sweep_point *out, char *err, size_t errlen)
{
    return run(s, n, 0, 0, 0, threads, checkpoint, resume, label, out, err, errlen);
}

int sf_sweep_run_cv(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume, const char *label,
                    sf_sweep_point *out, char *err, size_t errlen)
{
    return run(s, n, 0, 0, 1, threads, checkpoint, resume, label, out, err, errlen);
}

int sf_sweep_run_target(const sf_scene *s, double target_se, size_t n_pilot, size_t n_max, int threads,
                        const char *checkpoint, int resume, const char *label, sf_sweep_point *out, char *err,
                        size_t errlen)
{
    if (!(target_se > 0) || !isfinite(target_se) || n_pilot < 2 || n_max < n_pilot) {
        memset(out, 0, sizeof *out);
        return sf_seterr(err, errlen, SF_EINVAL,
                         "two-stage sweep: target_se must be finite and > 0 (got %g), 2 <= pilot (%zu) <= cap (%zu)",
                         target_se, n_pilot, n_max);
    }
    return run(s, n_max, target_se, n_pilot, 0, threads, checkpoint, resume, label, out, err, errlen);
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

/* The regression estimator of ratio q (sweep.h: cv[q]). */
static int cv_stats(sf_sweep_point *p, int q)
{
    double *x = sf_malloc((p->n ? p->n : 1) * sizeof *x), *y = sf_malloc((p->n ? p->n : 1) * sizeof *y);
    if (!x || !y) {
        free(x);
        free(y);
        return SF_ENOMEM;
    }
    size_t m = 0;
    for (size_t i = 0; i < p->n; i++) {
        double c = p->companion[i], r = p->ratio[i * SF_SWEEP_NQ + q];
        if (isfinite(c) && isfinite(r)) {
            x[m] = c - p->cv_known;
            y[m++] = r;
        }
    }
    p->cv[q].m = m;
    p->cv[q].mean = p->cv[q].se = p->cv[q].ci_lo = p->cv[q].ci_hi = p->cv[q].beta = p->cv[q].vrf = NAN;
    double c0, c1, v00, v01, v11, ss;
    if (m > 2 && !gsl_fit_linear(x, 1, y, 1, m, &c0, &c1, &v00, &v01, &v11, &ss)) {
        double t = gsl_cdf_tdist_Pinv(0.5 * (1 + SF_SWEEP_CI_LEVEL), (double)(m - 2));
        double plain = gsl_stats_variance(y, 1, m) / (double)m;
        p->cv[q].mean = c0;
        p->cv[q].se = sqrt(v00);
        p->cv[q].ci_lo = c0 - t * p->cv[q].se;
        p->cv[q].ci_hi = c0 + t * p->cv[q].se;
        p->cv[q].beta = c1;
        p->cv[q].vrf = plain / v00;
    }
    free(x);
    free(y);
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
        p->rci_lo[q] = p->rstat[q].ci_lo;
        p->rci_hi[q] = p->rstat[q].ci_hi;
        if (p->n_pilot && (rc = sf_mcstop_interval(p->ratio + q, SF_SWEEP_NQ, p->n_pilot, p->n, SF_SWEEP_CI_LEVEL,
                                                   &p->rci_lo[q], &p->rci_hi[q])))
            return rc;   /* two stages: Stein's interval from the pilot's spread */
        if (p->companion && (rc = cv_stats(p, q)))
            return rc;
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
    for (int q = 0; q < SF_SWEEP_NQ; q++)   /* u_num's companion (sf_unum_sweep) */
        fprintf(f, "\t%s_coarse[%s]", qname[q], qunit[q]);
    fputs("\tunum_rho[-]\tunum_apriori[-]\n", f);
}

void sf_sweep_write_rows(FILE *f, const char *param, double value, const sf_sweep_point *p)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    for (size_t i = 0; i < p->n; i++) {
        const double *r = p->ratio + i * SF_SWEEP_NQ, *x = p->qoi + i * SF_SWEEP_NQ;
        int c = i < p->num_m;   /* (num_m > 0: the companion arrays are held) */
        const double *qc = c ? p->num_qc + i * SF_SWEEP_NQ : NULL;
        fprintf(f, "%s\t%s\t%zu\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", param,
                v, i, r[0], r[1], r[2], x[0], x[1], x[2], c ? qc[0] : NAN, c ? qc[1] : NAN, c ? qc[2] : NAN,
                c ? p->num_rho[i] : NAN, c ? p->num_apriori[i] : NAN);
    }
}

void sf_sweep_tuples_header(FILE *f)
{
    fputs("param\tvalue\testimator\tlevel\tindex", f);
    for (int k = 0; k < 2; k++)
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            fprintf(f, "\t%c_%s", "ab"[k], qname[q]);
    fputc('\n', f);
}

/* one tuple: its level, index, and a[], b[] (NULL: nan) */
static void tuple_row(FILE *f, const char *param, const char *v, const sf_sweep_point *p, const char *level, size_t i,
                      const double *a, const double *b)
{
    fprintf(f, "%s\t%s\t%s\t%s\t%zu", param, v, sf_sweep_estimator_name(p->estimator), level, i);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%.17g", a ? a[q] : NAN);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%.17g", b ? b[q] : NAN);
    fputc('\n', f);
}

void sf_sweep_write_tuples(FILE *f, const char *param, double value, const sf_sweep_point *p)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    double a[SF_SWEEP_NQ], b[SF_SWEEP_NQ];
    int ml = p->ml.n[1] > 0, an = p->anti.n > 0;
    if (ml || an) {   /* the levels' mean work per sample (an antithetic point: a pair's) */
        double c[SF_SWEEP_NQ] = { ml ? p->ml.cost[0] : p->anti.cost, ml ? p->ml.cost[1] : NAN, NAN };
        tuple_row(f, param, v, p, "cost", 0, c, NULL);
    }
    for (size_t i = 0; ml && i < p->ml.n[0]; i++) {
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            a[q] = p->ml.coarse0[i * SF_SWEEP_NQ + q] / p->det[q];
        tuple_row(f, param, v, p, "level0", i, a, NULL);
    }
    for (size_t i = 0; i < p->n; i++) {
        const double *r = p->ratio + i * SF_SWEEP_NQ;
        const char *level = ml ? "level1" : an ? "pair" : p->companion ? "cv" : "row";
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            b[q] = ml ? p->ml.coarse1[i * SF_SWEEP_NQ + q] / p->det[q]
                 : an ? p->anti.qoi_anti[i * SF_SWEEP_NQ + q] / p->det[q]
                      : NAN;
        if (!ml && !an && p->companion) {
            b[0] = p->companion[i];
            b[1] = p->cv_known;
        }
        tuple_row(f, param, v, p, level, i, r, ml || an || p->companion ? b : NULL);
    }
}

void sf_sweep_diagnostics_header(FILE *f)
{
    int lv = (int)lround(100 * SF_SWEEP_CI_LEVEL);
    fputs("param\tvalue\tn", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const char *a = qname[q], *u = qunit[q];
        fprintf(f, "\t%s_n_used\t%s_n_excluded\t%s_mean[%s]\t%s_std[%s]\t%s_se[%s]\t%s_ci%d_lo[%s]\t%s_ci%d_hi[%s]"
                   "\t%s_det[%s]\t%s_ratio_mean[-]\t%s_ratio_std[-]\t%s_ratio_se[-]"
                   "\t%s_num_n\t%s_num_bias[%s]\t%s_num_bias_se[%s]\t%s_u_num_mean[%s]",
                a, a, a, u, a, u, a, u, a, lv, u, a, lv, u, a, u, a, a, a, a, a, u, a, u, a, u);
    }
    /* appended: the design (why the point stopped) and the interval it guarantees */
    fputs("\tstop\tn_pilot", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%s_ratio_ci%d_lo[-]\t%s_ratio_ci%d_hi[-]", qname[q], lv, qname[q], lv);
    for (int q = 0; q < SF_SWEEP_NQ; q++)   /* the control variate (nan without it) */
        fprintf(f, "\t%s_cv_ratio_mean[-]\t%s_cv_ratio_se[-]\t%s_cv_ratio_ci%d_lo[-]\t%s_cv_ratio_ci%d_hi[-]\t%s_cv_vrf[-]",
                qname[q], qname[q], qname[q], lv, qname[q], lv, qname[q]);
    /* the two-level estimator (nan without it): each level's N and work
       per sample [cell evaluations], per ratio the estimate, its interval,
       each level's variance and the variance reduction factor */
    fputs("\tml_n0\tml_n1\tml_cost0\tml_cost1\tml_cost_plain", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%s_ml_ratio_mean[-]\t%s_ml_ratio_se[-]\t%s_ml_ratio_ci%d_lo[-]\t%s_ml_ratio_ci%d_hi[-]"
                   "\t%s_ml_var0[-]\t%s_ml_var1[-]\t%s_ml_vrf[-]",
                qname[q], qname[q], qname[q], lv, qname[q], lv, qname[q], qname[q], qname[q]);
    /* antithetic pairs (nan without them): the pairs, a pair's and a
       plain realisation's work [cell evaluations], per ratio the pairs
       used (both members finite; the others are excluded and counted),
       the estimate, its interval, rho and the variance reduction factor */
    fputs("\tanti_n\tanti_cost\tanti_cost_plain", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%s_anti_n_used\t%s_anti_ratio_mean[-]\t%s_anti_ratio_se[-]\t%s_anti_ratio_ci%d_lo[-]"
                   "\t%s_anti_ratio_ci%d_hi[-]\t%s_anti_rho[-]\t%s_anti_vrf[-]",
                qname[q], qname[q], qname[q], qname[q], lv, qname[q], lv, qname[q], qname[q]);
    fputs("\testimator", f);   /* which estimator made the point (sf_sweep_estimator_name) */
    fputc('\n', f);
}

void sf_sweep_diagnostics_row(FILE *f, const char *param, double value, const sf_sweep_point *p)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    fprintf(f, "%s\t%s\t%zu", param, v, p->n);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const sf_sweep_stat *a = &p->stat[q], *b = &p->rstat[q];
        const sf_sweep_num *e = &p->num[q];
        int est = e->n_sub > 0;
        fprintf(f, "\t%zu\t%zu\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%zu\t%.3g\t%.3g\t%.3g",
                a->n_used, a->n_excluded, a->mean, a->std, a->se, a->ci_lo, a->ci_hi, p->det[q], b->mean, b->std,
                b->se, e->n_used, est ? e->bias : NAN, est ? e->bias_se : NAN, est ? e->u_mean : NAN);
    }
    fprintf(f, "\t%s\t%zu", sf_mcstop_reason(p->stop), p->n_pilot);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        fprintf(f, "\t%.17g\t%.17g", p->rci_lo[q], p->rci_hi[q]);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        double nan = NAN;
        const double *c = p->companion ? &p->cv[q].mean : &nan;
        fprintf(f, "\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g", c[0], p->companion ? p->cv[q].se : nan,
                p->companion ? p->cv[q].ci_lo : nan, p->companion ? p->cv[q].ci_hi : nan,
                p->companion ? p->cv[q].vrf : nan);
    }
    int ml = p->ml.n[1] > 0;
    fprintf(f, "\t%zu\t%zu\t%.6g\t%.6g\t%.6g", p->ml.n[0], p->ml.n[1], ml ? p->ml.cost[0] : NAN,
            ml ? p->ml.cost[1] : NAN, ml ? p->ml.cost_fine : NAN);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const sf_sweep_ml *e = &p->ml.q[q];
        if (ml)
            fprintf(f, "\t%.17g\t%.17g\t%.17g\t%.17g\t%.6g\t%.6g\t%.6g", e->mean, e->se, e->ci_lo, e->ci_hi,
                    e->var[0], e->var[1], e->vrf);
        else
            fputs("\tnan\tnan\tnan\tnan\tnan\tnan\tnan", f);
    }
    int an = p->anti.n > 0;
    fprintf(f, "\t%zu\t%.6g\t%.6g", p->anti.n, an ? p->anti.cost : NAN, an ? p->anti.cost_fine : NAN);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const sf_sweep_anti *e = &p->anti.q[q];
        if (an)
            fprintf(f, "\t%zu\t%.17g\t%.17g\t%.17g\t%.17g\t%.6g\t%.6g", e->m, e->mean, e->se, e->ci_lo, e->ci_hi,
                    e->rho, e->vrf);
        else
            fputs("\t0\tnan\tnan\tnan\tnan\tnan\tnan", f);
    }
    fprintf(f, "\t%s", sf_sweep_estimator_name(p->estimator));
    fputc('\n', f);
}

int sf_sweep_estimator_work(int est)
{
    return est == SF_EST_MLMC || est == SF_EST_MLMC_BOXES || est == SF_EST_MLMC_SUB || est == SF_EST_ANTITHETIC;
}

/* a companion was formed for some realisation (none for a window of tiles) */
static int cv_formed(const sf_sweep_point *p)
{
    for (size_t i = 0; p->companion && i < p->n; i++)
        if (isfinite(p->companion[i]))
            return 1;
    return 0;
}

int sf_sweep_estimate(const sf_sweep_point *p, int q, sf_sweep_answer *a)
{
    *a = (sf_sweep_answer){ p->estimator, NAN, NAN, NAN, NAN, NAN, p->n, NAN, p->stop };
    if (q < 0 || q >= SF_SWEEP_NQ)
        return SF_EINVAL;
    if (p->num[q].n_sub > 0)
        a->u_num = p->num[q].u_mean / p->det[q];
    switch (p->estimator) {
    case SF_EST_CV:
        if (cv_formed(p)) {
            a->estimate = p->cv[q].mean;
            a->se = p->cv[q].se;
            a->ci_lo = p->cv[q].ci_lo;
            a->ci_hi = p->cv[q].ci_hi;
            return SF_SUCCESS;
        }
        a->estimator = SF_EST_PLAIN;   /* no companion: plain Monte Carlo's */
        /* fall through */
    case SF_EST_PLAIN:
    case SF_EST_TARGET:   /* the interval the design guarantees (Stein's for two stages) */
        a->estimate = p->rstat[q].mean;
        a->se = p->rstat[q].se;
        a->ci_lo = p->rci_lo[q];
        a->ci_hi = p->rci_hi[q];
        return SF_SUCCESS;
    case SF_EST_MLMC:
    case SF_EST_MLMC_BOXES:
    case SF_EST_MLMC_SUB:
        a->estimate = p->ml.q[q].mean;
        a->se = p->ml.q[q].se;
        a->ci_lo = p->ml.q[q].ci_lo;
        a->ci_hi = p->ml.q[q].ci_hi;
        a->n = p->ml.n[0] + p->ml.n[1];
        a->work = p->ml.work;
        return SF_SUCCESS;
    case SF_EST_ANTITHETIC:
        a->estimate = p->anti.q[q].mean;
        a->se = p->anti.q[q].se;
        a->ci_lo = p->anti.q[q].ci_lo;
        a->ci_hi = p->anti.q[q].ci_hi;
        a->n = p->anti.n;
        a->work = p->anti.work;
        return SF_SUCCESS;
    default:
        return SF_EINVAL;
    }
}

void sf_sweep_summary_header(FILE *f, int work)
{
    int lv = (int)lround(100 * SF_SWEEP_CI_LEVEL);
    fputs("param\tvalue", f);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        const char *a = qname[q];
        fprintf(f, "\t%s_ratio_estimate[-]\t%s_ratio_se[-]\t%s_ratio_ci%d_lo[-]\t%s_ratio_ci%d_hi[-]\t%s_ratio_u_num[-]",
                a, a, a, lv, a, lv, a);
    }
    fputs(work ? "\tn\twork\testimator\tstop\n" : "\tn\testimator\tstop\n", f);
}

void sf_sweep_summary_row(FILE *f, const char *param, double value, const sf_sweep_point *p, int work)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    fprintf(f, "%s\t%s", param, v);
    sf_sweep_answer a;
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_estimate(p, q, &a);
        fprintf(f, "\t%.17g\t%.17g\t%.17g\t%.17g\t%.3g", a.estimate, a.se, a.ci_lo, a.ci_hi, a.u_num);
    }
    fprintf(f, "\t%zu", a.n);
    if (work)
        fprintf(f, "\t%.6g", a.work);
    fprintf(f, "\t%s\t%s\n", sf_sweep_estimator_name(a.estimator), sf_mcstop_reason(a.stop));
}

void sf_sweep_summary_long_header(FILE *f)
{
    fputs("param\tvalue\tqoi\testimate\tse\tci_lo\tci_hi\tu_num\tn\testimator\tstop\tunit\n", f);
}

void sf_sweep_summary_long_rows(FILE *f, const char *param, double value, const sf_sweep_point *p)
{
    char v[32];
    sf_sweep_fmt(v, sizeof v, value);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        sf_sweep_answer a;
        sf_sweep_estimate(p, q, &a);
        fprintf(f, "%s\t%s\t%s_ratio\t%.17g\t%.17g\t%.17g\t%.17g\t%.3g\t%zu\t%s\t%s\t-\n", param, v, qname[q],
                a.estimate, a.se, a.ci_lo, a.ci_hi, a.u_num, a.n, sf_sweep_estimator_name(a.estimator),
                sf_mcstop_reason(a.stop));
    }
}

const char *sf_sweep_estimator_name(int est)
{
    static const char *const name[] = { "plain", "control-variate", "target-se", "mlmc", "mlmc-boxes", "antithetic",
                                        "mlmc-sub" };
    return est >= 0 && est < (int)(sizeof name / sizeof *name) ? name[est] : "unknown";
}

int sf_sweep_estimator_auto(const sf_scene *s)
{
    sf_plan pl;
    if (sf_plan_make(s, &pl, NULL, 0) || pl.cof.kind != SF_COF_FIELD)
        return SF_EST_ANTITHETIC;
    if (pl.num.cell_average && pl.cof.generator != SF_COFGEN_TILES)   /* box means of a circulant strip (mlmc.h) */
        return SF_EST_MLMC_BOXES;
    if (pl.cof.generator == SF_COFGEN_TILES || s->l >= SF_SWEEP_AUTO_ANTI_LR * s->R)
        return SF_EST_ANTITHETIC;
    return s->l < SF_SWEEP_AUTO_SUB_LR * s->R ? SF_EST_MLMC_SUB : SF_EST_MLMC;
}

void sf_sweep_point_free(sf_sweep_point *p)
{
    free(p->qoi);
    free(p->ratio);
    free(p->companion);
    free(p->num_qc);
    free(p->num_rho);
    free(p->num_apriori);
    free(p->ml.coarse0);
    free(p->ml.coarse1);
    free(p->anti.qoi_anti);
    p->anti.qoi_anti = NULL;
    p->qoi = p->ratio = p->companion = p->num_qc = p->num_rho = p->num_apriori = NULL;
    p->ml.coarse0 = p->ml.coarse1 = NULL;
    p->num_m = 0;
}
