/* slipfield: the high-level calls (model.h): one realisation's solve
 * with its workspace's cache, and the handle over it. */
#include "model.h"
#include "cof.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "sf_alloc.h"
#include "sf_error.h"
#include "mcstop.h"
#include "sweep.h"
#include "unum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sf_model_ws {
    sf_scene plan_scene, det_scene;
    sf_cof_plan *plan;
    int det_held, det_rc;
    double det[SF_SWEEP_NQ];
    char det_err[240];
};

sf_model_ws *sf_model_ws_alloc(void) { return sf_calloc(1, sizeof(sf_model_ws)); }

void sf_model_ws_free(sf_model_ws *w)
{
    if (!w)
        return;
    sf_cof_plan_free_mt(w->plan);
    free(w);
}

/* a and b differ only in their seed (which no plan reads: the field's is the stream) */
static int same_scene(const sf_scene *a, const sf_scene *b)
{
    sf_scene t;
    memcpy(&t, a, sizeof t);
    t.seed = b->seed;
    return !memcmp(&t, b, sizeof t);
}

/* The run on its stream: the QoIs and u_num into out. */
static int solve(sf_model_ws *w, const sf_scene *s, gsl_rng *rng, int unum, double *out, char *err, size_t errlen)
{
    if (!(s->T > s->t_skip))
        return sf_seterr(err, errlen, SF_EINVAL, "T = %g s is not above t_skip = %g s: no cycle to measure", s->T,
                         s->t_skip);
    sf_plan pl;
    int rc = sf_plan_make(s, &pl, err, errlen);
    if (rc)
        return rc;
    pl.history = 0;   /* the QoIs only, as a sweep's rows */
    if (!w->plan || !same_scene(&w->plan_scene, s)) {
        sf_cof_plan_free_mt(w->plan);
        w->plan = NULL;
        if ((rc = sf_cof_plan_build_mt(s, &pl, &w->plan, err, errlen)))
            return rc;
        memcpy(&w->plan_scene, s, sizeof *s);
    }
    sf_cof *cof = NULL;
    sf_osc *o = NULL;
    sf_osc_result r = { 0 };
    if ((rc = sf_cof_plan_draw(w->plan, rng, &cof)) || (rc = sf_osc_alloc_plan(s, &pl, cof, &o, err, errlen))) {
        sf_cof_free(cof);
        return rc;
    }
    if (!(rc = sf_osc_run(o, NULL, NULL, 0, &r, err, errlen))) {
        out[SF_MODEL_PVX] = r.pv_x;
        out[SF_MODEL_PVF] = r.pv_F;
        out[SF_MODEL_SF] = r.stick_fraction;
        sf_unum u;
        char uerr[200] = "";
        if (unum && sf_unum_estimate(s, cof, sf_osc_get_plan(o), &r, &u, uerr, sizeof uerr) == SF_SUCCESS)
            for (int q = 0; q < SF_SWEEP_NQ; q++)
                out[SF_MODEL_U + q] = u.u[q];
        else if (unum && err)   /* a warning: the run's values stand */
            snprintf(err, errlen, "warning: no u_num (its companion solve: %s)", uerr);
    }
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc;
}

int sf_model_ws_solve(sf_model_ws *w, const sf_scene *s, gsl_rng *rng, int unum, double *out, char *err,
                      size_t errlen)
{
    for (int k = 0; k < SF_MODEL_NOUT; k++)
        out[k] = NAN;
    if (err && errlen)
        *err = 0;
    int rc = solve(w, s, rng, unum, out, err, errlen);
    if (rc)
        return rc;
    /* the deterministic reference, as sweep's ratios */
    if (!w->det_held || !same_scene(&w->det_scene, s)) {
        w->det_rc = sf_sweep_det(s, w->det, w->det_err, sizeof w->det_err);
        memcpy(&w->det_scene, s, sizeof *s);
        w->det_held = 1;
    }
    if (w->det_rc)
        return sf_seterr(err, errlen, w->det_rc, "%s", w->det_err);
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        out[SF_MODEL_RATIO + q] = out[q] / w->det[q];
    return SF_SUCCESS;
}

/* ---- a sweep point by its estimator's name */

int sf_model_estimator(const char *name, int *by)
{
    static const char *const names[] = { "plain", "mlmc", "mlmc-boxes", "mlmc-sub", "antithetic", "auto" };
    for (int k = 0; k < (int)(sizeof names / sizeof *names); k++)
        if (!name || !strcmp(name, names[k])) {
            *by = name ? k : SF_MODEL_PLAIN;
            return SF_SUCCESS;
        }
    return SF_EINVAL;
}

int sf_model_spec_check(sf_model_spec *spec, char *err, size_t errlen)
{
    int paired = spec->by != SF_MODEL_PLAIN, staged = !isnan(spec->target_se);
    static const char *const names[] = { "plain", "mlmc", "mlmc-boxes", "mlmc-sub", "antithetic", "auto" };
    if (spec->by < SF_MODEL_PLAIN || spec->by > SF_MODEL_AUTO)
        return sf_seterr(err, errlen, SF_EINVAL, "unknown estimator %d", spec->by);
    if (staged && !(spec->target_se > 0))
        return sf_seterr(err, errlen, SF_EINVAL, "--target-se takes a standard error > 0 (got %g)", spec->target_se);
    if (paired && (spec->control_variate || spec->resume))
        return sf_seterr(err, errlen, SF_EINVAL, "--estimator %s does not combine with --control-variate or --resume",
                         names[spec->by]);
    if (spec->pilot && !staged && !paired)
        return sf_seterr(err, errlen, SF_EINVAL, "--pilot needs --target-se or --estimator (not plain)");
    if (staged && spec->control_variate)
        return sf_seterr(err, errlen, SF_EINVAL, "--control-variate and --target-se do not combine");
    size_t def = paired ? 10 : 20;
    if ((staged || paired) && !spec->pilot)
        spec->pilot = spec->n < def ? spec->n : def;
    if ((staged || paired) && (spec->pilot < 2 || spec->pilot > spec->n))
        return sf_seterr(err, errlen, SF_EINVAL, "--pilot %zu: the pilot needs 2 to %zu (the cap, --realisations) "
                         "realisations", spec->pilot, spec->n);
    return SF_SUCCESS;
}

int sf_model_point(const sf_scene *s, const sf_model_spec *spec, int unum, sf_sweep_point *p, char *err,
                   size_t errlen)
{
    size_t n = spec->n, pilot = spec->pilot;
    int th = spec->threads, by = spec->by, staged = !isnan(spec->target_se), rc;
    const char *lb = spec->label;
    if (by == SF_MODEL_AUTO) {   /* the plan's rule, point by point (sweep.h) */
        int e = sf_sweep_estimator_auto(s);
        by = e == SF_EST_MLMC_BOXES ? SF_MODEL_MLMC_BOXES
           : e == SF_EST_MLMC_SUB   ? SF_MODEL_MLMC_SUB
           : e == SF_EST_MLMC       ? SF_MODEL_MLMC
                                    : SF_MODEL_ANTITHETIC;
    }
    if (staged && by != SF_MODEL_PLAIN) {
        static const int est[] = { 0, SF_EST_MLMC, SF_EST_MLMC_BOXES, SF_EST_MLMC_SUB, SF_EST_ANTITHETIC };
        const double tse[SF_SWEEP_NQ] = { spec->target_se, spec->target_se, spec->target_se };
        rc = sf_sweep_run_estimator_se(s, est[by], tse, pilot, n, th, lb, p, err, errlen);
    } else if (by == SF_MODEL_MLMC_BOXES)
        rc = sf_sweep_run_mlmc_boxes(s, n, pilot, th, lb, p, err, errlen);
    else if (by == SF_MODEL_MLMC_SUB)
        rc = sf_sweep_run_mlmc_sub(s, n, pilot, th, lb, p, err, errlen);
    else if (by == SF_MODEL_MLMC)
        rc = sf_sweep_run_mlmc(s, n, pilot, th, lb, p, err, errlen);
    else if (by == SF_MODEL_ANTITHETIC)
        rc = sf_sweep_run_antithetic(s, n, pilot, th, lb, p, err, errlen);
    else if (staged)
        rc = sf_sweep_run_target(s, spec->target_se, pilot, n, th, spec->checkpoint, spec->resume, lb, p, err,
                                 errlen);
    else if (spec->control_variate)
        rc = sf_sweep_run_cv(s, n, th, spec->checkpoint, spec->resume, lb, p, err, errlen);
    else
        rc = sf_sweep_run(s, n, th, spec->checkpoint, spec->resume, lb, p, err, errlen);
    if (!rc && unum && sf_unum_sweep(s, p, th, err, errlen) && err && errlen) {
        char why[240];
        snprintf(why, sizeof why, "%s", err);
        snprintf(err, errlen, "warning: no numerical error of the means (its companion failed: %s)", why);
    }
    return rc;
}

/* ---- the handle */

struct sf_model {
    sf_scene s;
    sf_model_ws *ws;
    gsl_rng *rng;
};

static int model_alloc(sf_model **out)
{
    sf_model *m = sf_calloc(1, sizeof *m);
    if (!m)
        return SF_ENOMEM;
    m->ws = sf_model_ws_alloc();
    m->rng = SF_FALLIBLE(gsl_rng_alloc(gsl_rng_mt19937));
    if (!m->ws || !m->rng) {
        sf_model_free(m);
        return SF_ENOMEM;
    }
    sf_scene_default(&m->s);
    *out = m;
    return SF_SUCCESS;
}

int sf_model_new(const char *text, sf_model **out, char *err, size_t errlen)
{
    *out = NULL;
    sf_model *m;
    int rc = model_alloc(&m);
    if (!rc && text && (rc = sf_scene_parse(&m->s, text, "scene", 1, err, errlen)))
        sf_model_free(m);
    else if (!rc)
        *out = m;
    return rc;
}

int sf_model_load(const char *path, sf_model **out, char *err, size_t errlen)
{
    *out = NULL;
    sf_model *m;
    int rc = model_alloc(&m);
    if (!rc && (rc = sf_scene_read_file(&m->s, path, err, errlen)))
        sf_model_free(m);
    else if (!rc)
        *out = m;
    return rc;
}

void sf_model_free(sf_model *m)
{
    if (!m)
        return;
    sf_model_ws_free(m->ws);
    gsl_rng_free(m->rng);
    free(m);
}

int sf_model_set(sf_model *m, const char *key, const char *value, char *err, size_t errlen)
{
    if (!strcmp(key, "l_over_R")) {
        char *end;
        double v = strtod(value, &end);
        if (end == value || *end)
            return sf_seterr(err, errlen, SF_EPARSE, "l_over_R: expected a number, got '%.40s'", value);
        return sf_sweep_set(&m->s, key, v, err, errlen);
    }
    char line[512];
    int n = snprintf(line, sizeof line, "%s = %s\n", key, value);
    if (n < 0 || (size_t)n >= sizeof line || strpbrk(key, "=#\n") || strpbrk(value, "#\n"))
        return sf_seterr(err, errlen, SF_EPARSE, "'%.40s = %.40s' is not one scene line", key, value);
    sf_scene t = m->s;
    sf_keytab kt = sf_scene_keytab(&t);
    for (size_t i = 0; i < kt.n; i++)   /* a key set again is set anew (a file may set it once) */
        if (!strcmp(kt.keys[i].name, key))
            kt.set[i] = 0;
    int rc = sf_scene_parse(&t, line, key, 1, err, errlen);
    if (!rc)
        m->s = t;
    return rc;
}

const sf_scene *sf_model_scene(const sf_model *m) { return &m->s; }

int sf_model_run(sf_model *m, size_t realisation, int unum, double *out, char *err, size_t errlen)
{
    sf_mc_stream(m->rng, m->s.seed, realisation);
    return sf_model_ws_solve(m->ws, &m->s, m->rng, unum, out, err, errlen);
}

/* ---- a sweep through the handle */

struct sf_model_sweep {
    size_t nv;
    sf_sweep_answer *a;   /* nv x SF_SWEEP_NQ */
};

int sf_model_sweep_run(sf_model *m, const char *param, const double *values, size_t nv, const sf_model_spec *spec,
                       sf_model_sweep **out, char *err, size_t errlen)
{
    *out = NULL;
    sf_model_spec sp = *spec;
    int rc = sf_model_spec_check(&sp, err, errlen);
    if (rc)
        return rc;
    if (nv == 0)
        return sf_seterr(err, errlen, SF_EINVAL, "no values to sweep");
    sf_model_sweep *w = sf_calloc(1, sizeof *w);
    if (!w || !(w->a = sf_calloc(nv * SF_SWEEP_NQ, sizeof *w->a))) {
        free(w);
        return SF_ENOMEM;
    }
    w->nv = nv;
    for (size_t k = 0; k < nv && !rc; k++) {
        sf_scene s = m->s;
        char why[300] = "";
        sf_sweep_point p;
        if (!(rc = sf_sweep_set(&s, param, values[k], why, sizeof why)) &&
            !(rc = sf_model_point(&s, &sp, 1, &p, why, sizeof why))) {
            for (int q = 0; q < SF_SWEEP_NQ; q++)
                sf_sweep_estimate(&p, q, &w->a[k * SF_SWEEP_NQ + (size_t)q]);
            sf_sweep_point_free(&p);
        }
        if (rc)
            sf_seterr(err, errlen, rc, "%s = %g: %s", param, values[k], *why ? why : sf_strerror(rc));
    }
    if (rc) {
        sf_model_sweep_free(w);
        return rc;
    }
    *out = w;
    return SF_SUCCESS;
}

size_t sf_model_sweep_points(const sf_model_sweep *w) { return w->nv; }

int sf_model_sweep_answer(const sf_model_sweep *w, size_t k, int q, double *f, const char **estimator,
                          const char **stop)
{
    if (k >= w->nv || q < 0 || q >= SF_SWEEP_NQ)
        return SF_EINVAL;
    const sf_sweep_answer *a = &w->a[k * SF_SWEEP_NQ + (size_t)q];
    f[0] = a->estimate;
    f[1] = a->se;
    f[2] = a->ci_lo;
    f[3] = a->ci_hi;
    f[4] = a->u_num;
    f[5] = (double)a->n;
    *estimator = sf_sweep_estimator_name(a->estimator);
    *stop = sf_mcstop_reason(a->stop);
    return SF_SUCCESS;
}

int sf_model_sweep_table(const sf_model_sweep *w, double *f, const char **names)
{
    for (size_t k = 0; k < w->nv; k++)
        for (int q = 0; q < SF_SWEEP_NQ; q++) {
            size_t r = k * SF_SWEEP_NQ + (size_t)q;
            sf_model_sweep_answer(w, k, q, f + r * 6, &names[2 * r], &names[2 * r + 1]);
        }
    return SF_SUCCESS;
}

void sf_model_sweep_free(sf_model_sweep *w)
{
    if (!w)
        return;
    free(w->a);
    free(w);
}
