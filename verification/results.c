/* reports/results.json: see results.h.  jansson builds and writes the JSON
 * (escaping, UTF-8 checks, 17 significant digits so every double reads
 * back to the same bits). */
#include "results.h"
#include "sf_error.h"
#include "version.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <fftw3.h>
#include <gsl/gsl_version.h>
#include <jansson.h>

#define DUMP_FLAGS (JSON_INDENT(1) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(17))

/* For a bound, the share of the allowance between 0 and the bound that
 * the value uses, so that a margin is >= 0 and above 1 exactly when the
 * row fails, whatever the signs (sf_row.ratio is that for the error rows
 * and p-values, which are >= 0). */
static double bound_margin(double m, double b, int upper)
{
    if (isnan(m) || isnan(b))
        return NAN;
    if (!upper) {           /* m >= b: the same as -m <= -b */
        m = -m;
        b = -b;
    }
    if (b > 0)              /* m <= b, b > 0: m / b, and 0 below zero */
        return m <= 0 ? 0 : m / b;
    if (b == 0)
        return m <= 0 ? 0 : INFINITY;
    return m < 0 ? b / m : INFINITY;   /* m <= b < 0: b / m, 1 at the bound */
}

double sf_row_margin(const sf_row *row)
{
    switch (row->test) {
    case SF_ROW_ABS: case SF_ROW_REL: case SF_ROW_PVALUE:
        return row->ratio;
    case SF_ROW_LE:
        return bound_margin(row->measured, row->limit, 1);
    case SF_ROW_GE:
        return bound_margin(row->measured, row->limit, 0);
    default:
        return NAN;
    }
}

static int whole(double x) { return isfinite(x) && fabs(x) < 9007199254740992.0 && floor(x) == x; }

int sf_row_margin_fixed(const sf_row *row)
{
    if (!row->pass)
        return 0;
    switch (row->test) {
    case SF_ROW_ABS: case SF_ROW_REL:   /* an exact equality: 0 or a failure */
        return row->limit == 0;
    case SF_ROW_LE: case SF_ROW_GE:     /* a count at its bound: 1 (or 0 against 0) or a failure */
        return whole(row->measured) && whole(row->limit) && row->measured == row->limit;
    default:
        return 0;
    }
}

double sf_result_margin(const sf_result *r, size_t *which)
{
    double best = NAN;
    size_t at = 0;
    for (size_t i = 0; r && i < sf_result_nrows(r); i++) {
        const sf_row *row = sf_result_row(r, i);
        double m = sf_row_margin(row);
        if (row->test == SF_ROW_TRUE || row->test == 0 || sf_row_margin_fixed(row))
            continue;
        /* a NaN margin (NaN measured) is the worst there is */
        if (isnan(m))
            m = INFINITY;
        if (isnan(best) || m > best) {
            best = m;
            at = i;
        }
    }
    if (which)
        *which = at;
    return best;
}

const char *sf_row_test_name(int test)
{
    static const char *names[] = { "other", "abs", "rel", "le", "ge", "pvalue", "true" };
    return test >= SF_ROW_ABS && test <= SF_ROW_TRUE ? names[test] : names[0];
}

const char *sf_row_kind_name(int test)
{
    return test == SF_ROW_PVALUE ? "statistical" : test == SF_ROW_TRUE ? "boolean" : "exact";
}

static const char *verdict_word(int v)
{
    return v == SF_VERDICT_PASS ? "pass" : v == SF_VERDICT_FAIL ? "fail" : "error";
}

/* A JSON string from C text; bytes that are not valid UTF-8 become '?'. */
static json_t *jstr(const char *s)
{
    json_t *j = json_string(s ? s : "");
    if (j)
        return j;
    size_t n = strlen(s);
    char *t = malloc(n + 1);
    if (!t)
        return json_null();
    for (size_t i = 0; i <= n; i++)
        t[i] = (unsigned char)s[i] >= 0x80 ? '?' : s[i];
    j = json_string(t);
    free(t);
    return j ? j : json_null();
}

static const char *nonfinite_word(double x)
{
    return isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
}

/* obj[key] = x, or null and nonfinite[key] = "nan" | "inf" | "-inf". */
static void set_num(json_t *obj, const char *key, double x, json_t *nonfinite)
{
    if (isfinite(x)) {
        json_object_set_new(obj, key, json_real(x));
        return;
    }
    json_object_set_new(obj, key, json_null());
    if (nonfinite)
        json_object_set_new(nonfinite, key, json_string(nonfinite_word(x)));
}

static json_t *row_json(const sf_row *row)
{
    json_t *j = json_object(), *nf = json_object();
    int has_expected = row->test == SF_ROW_ABS || row->test == SF_ROW_REL || row->test == SF_ROW_TRUE;
    json_object_set_new(j, "quantity", jstr(row->quantity));
    json_object_set_new(j, "test", json_string(sf_row_test_name(row->test)));
    json_object_set_new(j, "kind", json_string(sf_row_kind_name(row->test)));
    set_num(j, "measured", row->measured, nf);
    /* le, ge and p-value rows compare against a bound, not a value: no
     * expected value (null, and not a non-finite one) */
    if (has_expected)
        set_num(j, "expected", row->expected, nf);
    else
        json_object_set_new(j, "expected", json_null());
    json_object_set_new(j, "criterion", jstr(row->criterion));
    if (row->test == SF_ROW_PVALUE) {
        json_object_set_new(j, "tolerance", json_null());
        set_num(j, "alpha", row->limit, nf);
        json_object_set_new(j, "n", json_integer((json_int_t)row->n));
    } else {
        if (row->test == SF_ROW_TRUE || row->test == 0)
            json_object_set_new(j, "tolerance", json_null());
        else
            set_num(j, "tolerance", row->limit, nf);
        json_object_set_new(j, "alpha", json_null());
        json_object_set_new(j, "n", json_null());
    }
    double m = sf_row_margin(row);
    if (row->test == SF_ROW_TRUE || row->test == 0)
        json_object_set_new(j, "margin", json_null());
    else
        set_num(j, "margin", m, nf);
    json_object_set_new(j, "pass", json_boolean(row->pass));
    if (json_object_size(nf))
        json_object_set_new(j, "nonfinite", nf);
    else
        json_decref(nf);
    return j;
}

/* One QoI of one sweep point (result.h: sf_sweep_row). */
static json_t *sweep_json(const sf_sweep_row *x)
{
    json_t *o = json_object(), *nf = json_object();
    json_object_set_new(o, "param", jstr(x->param));
    set_num(o, "value", x->value, nf);
    json_object_set_new(o, "qoi", jstr(x->qoi));
    json_object_set_new(o, "unit", jstr(x->unit));
    json_object_set_new(o, "n_used", json_integer((json_int_t)x->n_used));
    json_object_set_new(o, "n_excluded", json_integer((json_int_t)x->n_excluded));
    set_num(o, "mean", x->mean, nf);
    set_num(o, "std", x->std, nf);
    set_num(o, "se", x->se, nf);
    set_num(o, "ci_lo", x->ci_lo, nf);
    set_num(o, "ci_hi", x->ci_hi, nf);
    set_num(o, "level", x->level, nf);
    set_num(o, "u_num", x->u_num, nf);
    json_object_set_new(o, "u_num_realisations", json_integer((json_int_t)x->u_num_subset));
    json_object_set_new(o, "u_num_used", json_integer((json_int_t)x->u_num_used));
    if (json_object_size(nf))
        json_object_set_new(o, "nonfinite", nf);
    else
        json_decref(nf);
    return o;
}

/* A claim's status in results.json and claims.tsv */
static const char *claim_word(int status)
{
    return status == SF_CLAIM_CONFIRMED ? "confirmed" : status == SF_CLAIM_CONTRADICTED ? "contradicted" : "undecided";
}

/* One claim of the paper and our verdict on it (result.h: sf_claim_row). */
static json_t *claim_json(const sf_claim_row *c)
{
    json_t *o = json_object(), *nf = json_object();
    json_object_set_new(o, "id", jstr(c->id));
    json_object_set_new(o, "text", jstr(c->text));
    json_object_set_new(o, "status", json_string(claim_word(c->status)));
    set_num(o, "measured", c->measured, nf);
    set_num(o, "ci_lo", c->ci_lo, nf);
    set_num(o, "ci_hi", c->ci_hi, nf);
    set_num(o, "alpha", c->alpha, nf);
    json_object_set_new(o, "how", jstr(c->how));
    json_object_set_new(o, "note", jstr(c->note));
    if (c->model.status >= 0) {   /* the verdict about the model (schema: claim.model; non-finite as null) */
        const sf_claim_model *m = &c->model;
        json_t *mo = json_object();
        json_object_set_new(mo, "status", json_string(m->status == SF_CLAIM_WITHIN ? "within_margin"
                                                      : m->status == SF_CLAIM_UNDECIDED ? "budget_reached"
                                                                                        : claim_word(m->status)));
        json_object_set_new(mo, "n", json_integer((json_int_t)m->n));
        json_object_set_new(mo, "budget", json_integer((json_int_t)m->budget));
        static const char *const key[6] = { "estimate", "lo", "hi", "mde", "alpha", "margin" };
        const double val[6] = { m->est, m->lo, m->hi, m->mde, m->alpha, m->margin };
        for (int k = 0; k < 6; k++)
            set_num(mo, key[k], val[k], NULL);
        json_object_set_new(o, "model", mo);
    }
    if (json_object_size(nf))
        json_object_set_new(o, "nonfinite", nf);
    else
        json_decref(nf);
    return o;
}

static const char *vv_key(int vv)
{
    return vv == 0 ? "code" : vv == 1 ? "solution" : "validation";
}

/* Write j to path through a temporary file and a rename. */
static int dump_file(json_t *j, const char *path, char *err, size_t errlen)
{
    char tmp[1200];
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", path, (long)getpid());
    if (json_dump_file(j, tmp, DUMP_FLAGS) != 0 || rename(tmp, path) != 0) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        unlink(tmp);
        return SF_EIO;
    }
    return SF_SUCCESS;
}

static json_t *case_json(const sf_outcome *o, const sf_result *r)
{
    json_t *j = json_object();
    json_object_set_new(j, "id", jstr(o->id));
    json_object_set_new(j, "family", jstr(o->family));
    json_object_set_new(j, "title", jstr(o->title));
    json_object_set_new(j, "path", jstr(o->path));
    json_object_set_new(j, "check", jstr(o->check));
    json_object_set_new(j, "vv", json_string(vv_key(o->vv)));
    json_object_set_new(j, "tier", json_string(sf_case_enum_name("tier", o->tier)));
    json_object_set_new(j, "verdict", json_string(verdict_word(o->verdict)));
    json_object_set_new(j, "message", jstr(o->key));
    json_object_set_new(j, "seed", json_integer((json_int_t)o->seed));
    json_object_set_new(j, "seconds", json_real(isfinite(o->seconds) ? o->seconds : 0));
    json_object_set_new(j, "cpu_seconds", json_real(0));
    json_object_set_new(j, "git_revision", json_string(SF_GIT_REV));
    size_t at = 0;
    double m = sf_result_margin(r, &at);
    json_t *nf = json_object();
    /* NaN: no row has a margin (null, not a non-finite value) */
    if (isnan(m))
        json_object_set_new(j, "margin", json_null());
    else
        set_num(j, "margin", m, nf);
    json_object_set_new(j, "margin_row", isnan(m) ? json_null() : json_integer((json_int_t)at));
    json_object_set_new(j, "near_edge", json_boolean(o->verdict == SF_VERDICT_PASS && m >= SF_NEAR_EDGE));
    if (json_object_size(nf))
        json_object_set_new(j, "nonfinite", nf);
    else
        json_decref(nf);
    json_t *rows = json_array();
    for (size_t i = 0; r && i < sf_result_nrows(r); i++)
        json_array_append_new(rows, row_json(sf_result_row(r, i)));
    json_object_set_new(j, "rows", rows);
    if (r && sf_result_nsamples(r)) {
        json_t *sm = json_array();
        for (size_t i = 0; i < sf_result_nsamples(r); i++) {
            const sf_sample_row *x = sf_result_sample_at(r, i);
            json_t *o = json_object();
            json_object_set_new(o, "what", jstr(x->what));
            json_object_set_new(o, "n_used", json_integer((json_int_t)x->n_used));
            json_object_set_new(o, "n_excluded", json_integer((json_int_t)x->n_excluded));
            json_array_append_new(sm, o);
        }
        json_object_set_new(j, "samples", sm);
    }
    if (r && sf_result_nclaims(r)) {
        json_t *cl = json_array();
        for (size_t i = 0; i < sf_result_nclaims(r); i++)
            json_array_append_new(cl, claim_json(sf_result_claim(r, i)));
        json_object_set_new(j, "claims", cl);
    }
    if (r && sf_result_nsweep(r)) {
        json_t *sw = json_array();
        for (size_t i = 0; i < sf_result_nsweep(r); i++)
            json_array_append_new(sw, sweep_json(sf_result_sweep_at(r, i)));
        json_object_set_new(j, "sweep", sw);
    }
    return j;
}

int sf_results_case_write(const char *dir, const sf_case *c, const sf_result *r,
                          const sf_outcome *o, char *err, size_t errlen)
{
    (void)c;
    json_t *j = case_json(o, r);
    char path[1100];
    snprintf(path, sizeof path, "%s/result.json", dir);
    int rc = dump_file(j, path, err, errlen);
    json_decref(j);
    return rc;
}

/* The parent's view of a case: its result.json with verdict, message and
 * time from the runner, or an object without rows when there is none. */
static json_t *gather_case(const char *root, sf_outcome *o)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/%s/result.json", root, o->id);
    json_error_t jerr;
    json_t *j = json_load_file(path, 0, &jerr);
    if (!j || !json_is_object(j) || !json_is_array(json_object_get(j, "rows"))) {
        json_decref(j);
        j = case_json(o, NULL);
    }
    json_object_set_new(j, "verdict", json_string(verdict_word(o->verdict)));
    json_object_set_new(j, "message", jstr(o->key));
    json_object_set_new(j, "seconds", json_real(isfinite(o->seconds) ? o->seconds : 0));
    json_object_set_new(j, "cpu_seconds", json_real(isfinite(o->cpu_seconds) && o->cpu_seconds > 0 ? o->cpu_seconds : 0));
    /* the case's margin as written; a null one is NAN, or +inf when it
     * was non-finite (a NaN or infinite row) */
    json_t *m = json_object_get(j, "margin");
    o->margin = json_is_number(m) ? json_number_value(m)
              : json_object_get(json_object_get(j, "nonfinite"), "margin") ? INFINITY : NAN;
    o->near_edge = o->verdict == SF_VERDICT_PASS && o->margin >= SF_NEAR_EDGE;
    json_object_set_new(j, "near_edge", json_boolean(o->near_edge));
    return j;
}

int sf_results_write(const sf_run_meta *meta, sf_outcome *o, size_t n,
                     const char *baseline, char *err, size_t errlen)
{
    size_t np = 0, nf = 0, ne = 0, nedge = 0;
    json_t *cases = json_array();
    for (size_t i = 0; i < n; i++) {
        json_array_append_new(cases, gather_case(meta->root, &o[i]));
        np += o[i].verdict == SF_VERDICT_PASS;
        nf += o[i].verdict == SF_VERDICT_FAIL;
        ne += o[i].verdict == SF_VERDICT_ERROR;
        nedge += o[i].near_edge != 0;
    }
    /* the claims' tally over the cases (each case's "claims" array) */
    size_t ncl[3] = { 0, 0, 0 }, nmod[5] = { 0, 0, 0, 0, 0 };
    static const char *const mkey[5] = { "confirmed", "contradicted", "within_margin", "budget_reached", "not_run" };
    for (size_t i = 0; i < json_array_size(cases); i++) {
        json_t *cl = json_object_get(json_array_get(cases, i), "claims");
        for (size_t k = 0; k < json_array_size(cl); k++) {
            const char *w = json_string_value(json_object_get(json_array_get(cl, k), "status"));
            ncl[w && !strcmp(w, "confirmed") ? 0 : w && !strcmp(w, "contradicted") ? 1 : 2]++;
            json_t *mo = json_object_get(json_array_get(cl, k), "model");
            const char *mw = mo ? json_string_value(json_object_get(mo, "status")) : NULL;
            size_t u = 4;
            for (size_t q = 0; mw && q < 4; q++)
                u = !strcmp(mw, mkey[q]) ? q : u;
            nmod[u]++;
        }
    }
    json_t *tally = json_object();
    json_object_set_new(tally, "total", json_integer((json_int_t)(ncl[0] + ncl[1] + ncl[2])));
    json_object_set_new(tally, "confirmed", json_integer((json_int_t)ncl[0]));
    json_object_set_new(tally, "contradicted", json_integer((json_int_t)ncl[1]));
    json_object_set_new(tally, "undecided", json_integer((json_int_t)ncl[2]));
    if (nmod[4] < ncl[0] + ncl[1] + ncl[2]) {   /* some case ran model verdicts */
        json_t *mt = json_object();
        for (size_t q = 0; q < 5; q++)
            json_object_set_new(mt, mkey[q], json_integer((json_int_t)nmod[q]));
        json_object_set_new(tally, "model", mt);
    }
    json_t *s = json_object();
    json_object_set_new(s, "cases", json_integer((json_int_t)n));
    json_object_set_new(s, "passed", json_integer((json_int_t)np));
    json_object_set_new(s, "failed", json_integer((json_int_t)nf));
    json_object_set_new(s, "errors", json_integer((json_int_t)ne));
    json_object_set_new(s, "skipped", json_integer((json_int_t)meta->skipped));
    json_object_set_new(s, "near_edge", json_integer((json_int_t)nedge));
    json_object_set_new(s, "tier", jstr(meta->tier_name));
    json_object_set_new(s, "seeds", jstr(meta->seed_note));
    json_object_set_new(s, "wall_seconds", json_real(isfinite(meta->total_seconds) ? meta->total_seconds : 0));
    json_object_set_new(s, "cpu_seconds", json_real(sf_outcome_cpu_total(o, n)));
    json_object_set_new(s, "near_edge_threshold", json_real(SF_NEAR_EDGE));
    json_object_set_new(s, "baseline", baseline ? jstr(baseline) : json_null());

    json_t *j = json_object();
    json_object_set_new(j, "schema", json_string(SF_RESULTS_SCHEMA));
    json_object_set_new(j, "tool", json_string("slipfield"));
    json_object_set_new(j, "version", json_string(SF_VERSION));
    json_object_set_new(j, "git_revision", json_string(SF_GIT_REV));
    json_object_set_new(j, "gsl", json_string(GSL_VERSION));
    json_object_set_new(j, "fftw", jstr(fftw_version));
    json_object_set_new(j, "summary", s);
    json_object_set_new(j, "claims", tally);
    json_object_set_new(j, "cases", cases);
    char path[1100];
    snprintf(path, sizeof path, "%s/results.json", meta->root);
    int rc = dump_file(j, path, err, errlen);
    json_decref(j);
    return rc;
}
