/* The Monte Carlo aggregation, recomputed from what a sweep prints.
 *
 * A sweep is run, written as `slipfield sweep` writes it (the
 * per-realisation table, the summary and the diagnostics, sweep.h), and
 * read back as text; every statistic of the diagnostics and every
 * estimate of the summary (a plain sweep's: the ratio means and their
 * Student intervals) is then recomputed here from the per-realisation
 * rows alone with GSL (gsl_stats_mean, gsl_stats_sd,
 * gsl_cdf_tdist_Pinv), not with the solver's aggregation.  The validation
 * cases gate on the same statistics through sf_sweep_point: those are
 * compared too.  So is the numerical error of each mean (unum.h): from
 * the companions' QoIs and rho the per-realisation table carries.
 *
 * What the table cannot show, whose realisation a companion solved, is
 * the second check's (mc_unum_own_field, at the end). */
#include "checks.h"
#include "common.h"
#include "cof.h"
#include "mlmc.h"
#include "montecarlo.h"
#include "numplan.h"
#include "sweep.h"
#include "unum.h"
#include "sf_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NQ SF_SWEEP_NQ
#define MAXCOL 160   /* the diagnostics have 122 columns (3 QoIs x 15, the design's, the control variate's, the
                        two-level estimator's, the antithetic pairs' and the estimator's name) */
#define FS 3.0       /* u_num_mean's safety factor, as documented: 3 (|num_bias| + t se) */
static const char *const qn[NQ] = { "pv_x", "pv_F", "stick_fraction" };

/* A TSV table read back: the header's names and the cells as numbers
 * (strtod: %.17g reads back to the same bits; "nan", "inf" too). */
typedef struct {
    size_t ncol, nrow;
    char name[MAXCOL][48];
    char **key;       /* nrow: "param\tvalue" of the row */
    double *cell;     /* nrow x ncol (text columns: NAN) */
} table;

static int table_read(const char *text, table *t)
{
    memset(t, 0, sizeof *t);
    size_t lines = 0;
    for (const char *p = text; *p; p++)
        lines += *p == '\n';
    char *buf = check_alloc(strlen(text) + 1), *save = NULL;
    strcpy(buf, text);
    t->key = check_alloc((lines ? lines : 1) * sizeof *t->key);
    t->cell = check_alloc((lines ? lines : 1) * MAXCOL * sizeof *t->cell);
    int rc = SF_SUCCESS;
    for (char *ln = strtok_r(buf, "\n", &save); ln; ln = strtok_r(NULL, "\n", &save)) {
        char *s2 = NULL, *c = strtok_r(ln, "\t", &s2);
        size_t k = 0;
        if (!t->ncol) {   /* the header */
            for (; c && k < MAXCOL; c = strtok_r(NULL, "\t", &s2), k++)
                snprintf(t->name[k], sizeof t->name[k], "%s", c);
            t->ncol = k;
            if (c)   /* more columns than the reader holds */
                rc = SF_EPARSE;
            continue;
        }
        double *row = t->cell + t->nrow * MAXCOL;
        char key[160] = "";
        for (; c && k < t->ncol; c = strtok_r(NULL, "\t", &s2), k++) {
            char *end;
            row[k] = strtod(c, &end);
            if (k < 2)   /* param, value: the row's point, as printed */
                snprintf(key + strlen(key), sizeof key - strlen(key), "%s%s", k ? "\t" : "", c);
            else if (*end && strcmp(t->name[k], "stop") && strcmp(t->name[k], "estimator"))   /* its text columns */
                rc = SF_EPARSE;
        }
        if (k != t->ncol || c)
            rc = SF_EPARSE;
        t->key[t->nrow] = check_alloc(strlen(key) + 1);
        strcpy(t->key[t->nrow++], key);
    }
    free(buf);
    return rc;
}

static void table_free(table *t)
{
    for (size_t i = 0; i < t->nrow; i++)
        free(t->key[i]);
    free(t->key);
    free(t->cell);
}

/* The column called `name` (its index), or -1. */
static int col(const table *t, const char *name)
{
    for (size_t k = 0; k < t->ncol; k++)
        if (!strcmp(t->name[k], name))
            return (int)k;
    return -1;
}

/* Row i's cell in the column called name; NAN and *missing set when the
 * table has no such column. */
static double cell(const table *t, size_t i, const char *name, int *missing)
{
    int k = col(t, name);
    if (k < 0) {
        *missing = 1;
        return NAN;
    }
    return t->cell[i * MAXCOL + (size_t)k];
}

/* The column whose name starts with pre and ends with post; the text in
 * between into mid (e.g. the interval's level "95" of pv_x_ci95_lo[m]). */
static int col_around(const table *t, const char *pre, const char *post, char *mid, size_t len)
{
    size_t a = strlen(pre), b = strlen(post);
    for (size_t k = 0; k < t->ncol; k++) {
        size_t n = strlen(t->name[k]);
        if (n > a + b && !strncmp(t->name[k], pre, a) && !strcmp(t->name[k] + n - b, post)) {
            snprintf(mid, len, "%.*s", (int)(n - a - b), t->name[k] + a);
            return (int)k;
        }
    }
    return -1;
}

/* Worst discrepancies, each over its round-off allowance. */
typedef struct {
    double count;      /* |printed - counted|, realisations */
    int missing;       /* a column the diagnostics or the summary should have is not there */
    double mean, sd, se, ci, rmean, rsd, rse;   /* |diff| / allowance */
    size_t ratio_bits; /* ratio cells that are not value / det to the bit */
    /* the numerical error of the means: the companion rows against the
     * documented subset (realisations), sf_sweep_point's bias, its se and
     * u_num_mean (|diff| / allowance), the printed ones (|diff| / half a
     * unit of the third digit) */
    double num_rows, num_bias, num_se, num_u, num_printed;
    size_t num_compared, num_excluded;
    /* the summary: its estimate, se and interval ends against the
     * recomputed ratio mean, se and Student interval (|diff| /
     * allowance), its u_num against the recomputed u_num_mean / det
     * (printed: |diff| / half a unit of the third digit), n against the
     * rows */
    double sum_est, sum_se, sum_ci, sum_u, sum_n;
} worst;

/* The diagnostics and the summary print the numerical error with %.3g: 0 when the printed
 * cell is x printed the same way; else (x and the solver's value apart by
 * round-off on either side of a rounding edge) |printed - x| over half a
 * unit in the third significant digit of x plus x's round-off allowance.
 * Equal non-finite values agree. */
static double off3(double printed, double x, size_t n, double scale)
{
    if (!isfinite(printed) || !isfinite(x))
        return (isnan(printed) && isnan(x)) || printed == x ? 0 : INFINITY;
    char text[32];
    snprintf(text, sizeof text, "%.3g", x);
    if (strtod(text, NULL) == printed)
        return 0;
    double half = x != 0 ? 0.5 * pow(10, floor(log10(fabs(x))) - 2) : 0;
    double tol = half + 8 * (double)(n ? n : 1) * DBL_EPSILON * scale;
    return printed == x ? 0 : tol > 0 ? fabs(printed - x) / tol : INFINITY;
}

static void upd(double *w, double x)
{
    if (!(x <= *w))
        *w = x;
}

/* The recomputation of one (point, QoI) from the finite values of column
 * cx of the rows rows[0..n). */
static check_recomp recompute(const table *tv, const size_t *rows, size_t n, int cx, double level, double *buf)
{
    size_t used = 0;
    for (size_t i = 0; i < n; i++) {
        double x = tv->cell[rows[i] * MAXCOL + (size_t)cx];
        if (isfinite(x))
            buf[used++] = x;
    }
    return check_recomp_of(buf, used, level);
}

/* The numerical error of QoI column cx's mean over rows[0..n), from the
 * companion columns (ccx its QoI's, crho, capr): the realisations that
 * have a companion must be 0 .. m - 1, m = ceil(n / 4) but at least 2
 * (all of n < 2) as documented; e_i = (Q_c,i - Q_i) / (rho_i - 1), the
 * finite ones' statistics (e: bias = e.mean, its se), u_num_mean = 3
 * (|bias| + t se) + a-priori(row 0) |mean|. */
typedef struct {
    check_recomp e;
    double u, scale_u;
    size_t sub, off_subset;
} renum;

static renum recompute_num(const table *tv, const size_t *rows, size_t n, int cx, int ccx, int crho, int capr,
                           double mean, double mean_scale, double level, double *buf)
{
    renum o = { .u = NAN };
    size_t want = n < 2 ? n : (n + 3) / 4 < 2 ? 2 : (n + 3) / 4, used = 0;
    double apr = NAN;
    for (size_t i = 0; i < n; i++) {
        const double *row = tv->cell + rows[i] * MAXCOL;
        int has = isfinite(row[crho]);
        o.off_subset += has != (i < want);
        if (!has)
            continue;
        if (!o.sub++)
            apr = row[capr];
        double e = (row[ccx] - row[cx]) / (row[crho] - 1);
        if (isfinite(e))
            buf[used++] = e;
    }
    o.e = check_recomp_of(buf, used, level);
    if (used > 1) {
        o.u = FS * (fabs(o.e.mean) + o.e.t * o.e.se) + apr * fabs(mean);
        o.scale_u = FS * (o.e.scale + o.e.t * o.e.dscale) + fabs(apr) * mean_scale;
    }
    return o;
}

/* Compare point k's diagnostics (ts) and summary (tw) rows with the
 * recomputation from its rows. */
static void compare_point(sf_result *r, const table *tv, const table *ts, const table *tw, size_t srow,
                          const sf_sweep_point *pt, const char *lv, worst *w, size_t *excluded, double *maxratio)
{
    size_t *rows = check_alloc((tv->nrow ? tv->nrow : 1) * sizeof *rows), n = 0;
    double *buf = check_alloc((tv->nrow ? tv->nrow : 1) * sizeof *buf);
    for (size_t i = 0; i < tv->nrow; i++)
        if (!strcmp(tv->key[i], ts->key[srow]))
            rows[n++] = i;
    /* realisations 0 .. n-1, each once, as many as the diagnostics' and the summary's n */
    size_t seen = 0;
    for (size_t i = 0; i < n; i++)
        seen += cell(tv, rows[i], "realisation", &w->missing) == (double)i;
    upd(&w->count, fabs(cell(ts, srow, "n", &w->missing) - (double)n) + (double)(n - seen));
    upd(&w->count, fabs((double)pt->n - (double)n));
    upd(&w->sum_n, fabs(cell(tw, srow, "n", &w->missing) - (double)n));
    if (strcmp(tw->key[srow], ts->key[srow]))   /* the two tables' rows in the same order */
        w->sum_n = INFINITY;
    double level = atof(lv) / 100;
    const char *units[NQ] = { "m", "N", "-" };
    char point[160];
    snprintf(point, sizeof point, "%s", ts->key[srow]);
    char *tab = strchr(point, '\t');
    if (tab)
        *tab = '=';
    for (int q = 0; q < NQ; q++) {
        char nm[96], rn[64];
        snprintf(nm, sizeof nm, "%s[%s]", qn[q], units[q]);
        snprintf(rn, sizeof rn, "%s_ratio", qn[q]);
        int cx = col(tv, nm), crt = col(tv, rn);
        if (cx < 0 || crt < 0) {
            w->missing = 1;
            break;
        }
        check_recomp a = recompute(tv, rows, n, cx, level, buf), b = recompute(tv, rows, n, crt, level, buf);
        char cn[96];
        snprintf(cn, sizeof cn, "%s_coarse[%s]", qn[q], units[q]);
        int ccx = col(tv, cn), crho = col(tv, "unum_rho[-]"), capr = col(tv, "unum_apriori[-]");
        if (ccx < 0 || crho < 0 || capr < 0) {
            w->missing = 1;
            break;
        }
        renum e = recompute_num(tv, rows, n, cx, ccx, crho, capr, a.mean, a.scale, level, buf);
        /* the diagnostics' cells for this QoI: "n_used" -> pv_x_n_used, "mean[%s]" -> pv_x_mean[m] */
#define S(field) (snprintf(nm, sizeof nm, "%s_" field, qn[q], units[q]), cell(ts, srow, nm, &w->missing))
        double used = S("n_used%.0s"), excl = S("n_excluded%.0s");
        upd(&w->count, fabs(used - (double)a.used) + fabs(excl - (double)(n - a.used)));
        upd(&w->count, fabs(used - (double)b.used));   /* a ratio is finite exactly when its value is */
        upd(&w->count, fabs((double)pt->stat[q].n_used - (double)a.used));
        *excluded += n - a.used;
        double mean = S("mean[%s]"), sd = S("std[%s]"), se = S("se[%s]"), det = S("det[%s]");
        upd(&w->mean, check_roundoff(mean, a.mean, a.used, a.scale));
        upd(&w->sd, check_roundoff(sd, a.sd, a.used, a.dscale));
        upd(&w->se, check_roundoff(se, a.se, a.used, a.dscale));
        char ci[96];
        snprintf(ci, sizeof ci, "%s_ci%s_lo[%s]", qn[q], lv, units[q]);
        upd(&w->ci, check_roundoff(cell(ts, srow, ci, &w->missing), a.lo, a.used, a.scale));
        snprintf(ci, sizeof ci, "%s_ci%s_hi[%s]", qn[q], lv, units[q]);
        upd(&w->ci, check_roundoff(cell(ts, srow, ci, &w->missing), a.hi, a.used, a.scale));
        double rmean = S("ratio_mean[-]%.0s"), rse = S("ratio_se[-]%.0s");
        upd(&w->rmean, check_roundoff(rmean, b.mean, b.used, b.scale));
        upd(&w->rsd, check_roundoff(S("ratio_std[-]%.0s"), b.sd, b.used, b.dscale));
        upd(&w->rse, check_roundoff(rse, b.se, b.used, b.dscale));
        /* the numerical error of the mean: sf_sweep_point's (results.json
         * and the reports read it) to round-off, the printed to its digits */
        const sf_sweep_num *num = &pt->num[q];
        upd(&w->num_rows, (double)e.off_subset + fabs((double)num->n_sub - (double)e.sub));
        upd(&w->num_rows, fabs((double)num->n_used - (double)e.e.used));
        upd(&w->num_rows, fabs(S("num_n%.0s") - (double)e.e.used));
        int est = num->n_sub > 0;
        upd(&w->num_bias, check_roundoff(est ? num->bias : NAN, e.e.mean, e.e.used, e.e.scale));
        upd(&w->num_se, check_roundoff(est ? num->bias_se : NAN, e.e.se, e.e.used, e.e.dscale));
        upd(&w->num_u, check_roundoff(est ? num->u_mean : NAN, e.u, e.e.used, e.scale_u));
        upd(&w->num_printed, off3(S("num_bias[%s]"), e.e.mean, e.e.used, e.e.scale));
        upd(&w->num_printed, off3(S("num_bias_se[%s]"), e.e.se, e.e.used, e.e.dscale));
        double u_printed = S("u_num_mean[%s]");
        upd(&w->num_printed, off3(u_printed, e.u, e.e.used, e.scale_u));
        w->num_compared += e.e.used;
        w->num_excluded += e.sub - e.e.used;
        /* the summary: a plain sweep's estimate is the ratio mean, its Student interval */
#define W(field) (snprintf(nm, sizeof nm, "%s_ratio_" field "[-]", qn[q]), cell(tw, srow, nm, &w->missing))
        upd(&w->sum_est, check_roundoff(W("estimate"), b.mean, b.used, b.scale));
        upd(&w->sum_se, check_roundoff(W("se"), b.se, b.used, b.dscale));
        snprintf(ci, sizeof ci, "%s_ratio_ci%s_lo[-]", qn[q], lv);
        upd(&w->sum_ci, check_roundoff(cell(tw, srow, ci, &w->missing), b.lo, b.used, b.scale));
        snprintf(ci, sizeof ci, "%s_ratio_ci%s_hi[-]", qn[q], lv);
        upd(&w->sum_ci, check_roundoff(cell(tw, srow, ci, &w->missing), b.hi, b.used, b.scale));
        upd(&w->sum_u, off3(W("u_num"), e.u / det, e.e.used, e.scale_u / det));
#undef W
#undef S
        /* what the validation cases read: sf_sweep_point's ratio statistics */
        upd(&w->rmean, check_roundoff(pt->mean[q], b.mean, b.used, b.scale));
        upd(&w->rsd, check_roundoff(pt->std[q], b.sd, b.used, b.dscale));
        upd(&w->rse, check_roundoff(pt->rstat[q].se, b.se, b.used, b.dscale));
        for (size_t i = 0; i < n; i++) {
            double x = tv->cell[rows[i] * MAXCOL + (size_t)cx], y = tv->cell[rows[i] * MAXCOL + (size_t)crt];
            double want = x / det;
            w->ratio_bits += !(y == want || (isnan(y) && isnan(want)));
            if (isfinite(y))
                *maxratio = fmax(*maxratio, y);
        }
        sf_note(r, "| %s | %s | %.0f / %.0f | %.6g | %.6g | %.4g | %.4g | [%.6g, %.6g] | %.6g +- %.3g | %zu / %zu | %.3g | "
                   "%.3g |", point, qn[q], used, excl, mean, a.mean, sd, se, a.lo, a.hi, rmean, rse, e.e.used, e.sub,
                e.e.mean, u_printed);
    }
    free(rows);
    free(buf);
}

/* The point `base` with defects of the data planted: a realisation
 * without PV_x (NaN), one with an infinite stick fraction, one with no
 * QoI at all, and one (the first finite after them) whose PV_F is 100
 * times its value (an extreme ratio); its companions with an a-priori
 * relative error 1e-3 higher (the case's point plan has none). */
static int plant(const sf_sweep_point *base, sf_sweep_point *p)
{
    if (base->n < 6)
        return SF_EINVAL;
    *p = *base;
    size_t n = base->n * NQ;
    p->qoi = check_alloc(n * sizeof *p->qoi);
    p->ratio = check_alloc(n * sizeof *p->ratio);
    memcpy(p->qoi, base->qoi, n * sizeof *p->qoi);
    p->qoi[1 * NQ + SF_SWEEP_PVX] = NAN;
    p->qoi[2 * NQ + SF_SWEEP_SF] = INFINITY;
    for (int q = 0; q < NQ; q++)
        p->qoi[3 * NQ + q] = NAN;
    size_t i = 4;   /* the first realisation after those with a finite PV_F */
    while (i < base->n && !isfinite(p->qoi[i * NQ + SF_SWEEP_PVF]))
        i++;
    if (i < base->n)
        p->qoi[i * NQ + SF_SWEEP_PVF] *= 100;
    p->companion = NULL;
    p->num_qc = p->num_rho = p->num_apriori = NULL;   /* the same companions, the point's own copy */
    if (base->num_m) {
        p->num_qc = check_alloc(base->num_m * NQ * sizeof *p->num_qc);
        p->num_rho = check_alloc(base->num_m * sizeof *p->num_rho);
        p->num_apriori = check_alloc(base->num_m * sizeof *p->num_apriori);
        memcpy(p->num_qc, base->num_qc, base->num_m * NQ * sizeof *p->num_qc);
        memcpy(p->num_rho, base->num_rho, base->num_m * sizeof *p->num_rho);
        for (size_t k = 0; k < base->num_m; k++)   /* as a cell-average plan's: the a-priori part counts */
            p->num_apriori[k] = base->num_apriori[k] + 1e-3;
    }
    int rc = sf_sweep_point_stats(p);
    return rc ? rc : sf_unum_sweep_num(p);
}

static int chk_sweep_aggregation(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param)
        return SF_EINVAL;
    sf_sweep_point *pt = check_alloc((K + 1) * sizeof *pt);
    char err[256] = "";
    int rc = SF_SUCCESS;
    size_t made = 0;
    for (; made < K && !rc; made++) {
        sf_scene s = *s0;
        memset(&pt[made], 0, sizeof pt[made]);
        rc = sf_sweep_set(&s, c->spec.sweep_param, c->spec.sweep.v[made], err, sizeof err);
        if (!rc)
            rc = sf_sweep_run(&s, s0->samples, 0, NULL, 0, NULL, &pt[made], err, sizeof err);
        if (!rc)   /* the numerical error of the means, as `sweep --summary` / `--diagnostics` make it */
            rc = sf_unum_sweep(&s, &pt[made], 0, err, sizeof err);
        if (rc)
            sf_note(r, "**Sweep failed at %s = %g:** %s", c->spec.sweep_param, c->spec.sweep.v[made], err);
    }
    size_t natural = 0;
    for (size_t k = 0; k < made && !rc; k++)
        for (int q = 0; q < NQ; q++)
            natural += pt[k].stat[q].n_excluded;
    for (size_t k = 0; k < made && !rc; k++)   /* results.json and the report's sweep table */
        check_sweep_record(r, c->spec.sweep_param, c->spec.sweep.v[k], &pt[k]);
    if (!rc && (rc = plant(&pt[K - 1], &pt[K])) == SF_SUCCESS)
        made++;
    /* the three tables, as `slipfield sweep --out --summary --diagnostics` writes them (a plain sweep: no work
       column) */
    char *tv_text = NULL, *ts_text = NULL, *tw_text = NULL;
    size_t tv_len = 0, ts_len = 0, tw_len = 0;
    FILE *fv = open_memstream(&tv_text, &tv_len), *fs = open_memstream(&ts_text, &ts_len),
         *fw = open_memstream(&tw_text, &tw_len);
    if (!fv || !fs || !fw)
        rc = SF_ENOMEM;
    if (!rc) {
        sf_sweep_write_header(fv);
        sf_sweep_diagnostics_header(fs);
        sf_sweep_summary_header(fw, 0);
        for (size_t k = 0; k <= K; k++) {
            const char *param = k < K ? c->spec.sweep_param : "planted";
            sf_sweep_write_rows(fv, param, c->spec.sweep.v[k < K ? k : K - 1], &pt[k]);
            sf_sweep_diagnostics_row(fs, param, c->spec.sweep.v[k < K ? k : K - 1], &pt[k]);
            sf_sweep_summary_row(fw, param, c->spec.sweep.v[k < K ? k : K - 1], &pt[k], 0);
        }
    }
    if (fv)
        fclose(fv);
    if (fs)
        fclose(fs);
    if (fw)
        fclose(fw);
    table tv = { 0 }, ts = { 0 }, tw = { 0 };
    char lv[16] = "";
    if (!rc && (table_read(tv_text, &tv) || table_read(ts_text, &ts) || table_read(tw_text, &tw) ||
                ts.nrow != K + 1 || tw.nrow != K + 1 || col_around(&ts, "pv_x_ci", "_lo[m]", lv, sizeof lv) < 0)) {
        sf_note(r, "**The tables do not read back** (%zu diagnostics and %zu summary rows for %zu points).", ts.nrow,
                tw.nrow, K + 1);
        rc = SF_EFAIL;
    }
    if (!rc) {
        worst w = { 0 };
        size_t excluded = 0;
        double maxratio = 0;
        sf_note(r, "| point | QoI | used / excluded | mean printed | mean recomputed | std | se | %s%% interval "
                   "recomputed | ratio mean +- se | num. error: estimates used / companions | bias recomputed | "
                   "u_num_mean printed |\n|---|---|---|---|---|---|---|---|---|---|---|---|", lv);
        for (size_t k = 0; k <= K; k++)
            compare_point(r, &tv, &ts, &tw, k, &pt[k], lv, &w, &excluded, &maxratio);
        double level = atof(lv) / 100;
        sf_check_true(r, "the diagnostics state their interval's level (in the header)", level > 0 && level < 1, lv);
        /* the summary: the documented columns, none all-NaN, every point plain and fixed */
        char want[1024] = "param\tvalue";
        for (int q = 0; q < NQ; q++)
            snprintf(want + strlen(want), sizeof want - strlen(want),
                     "\t%s_ratio_estimate[-]\t%s_ratio_se[-]\t%s_ratio_ci%s_lo[-]\t%s_ratio_ci%s_hi[-]\t%s_ratio_u_num[-]",
                     qn[q], qn[q], qn[q], lv, qn[q], lv, qn[q]);
        snprintf(want + strlen(want), sizeof want - strlen(want), "\tn\testimator\tstop\n");
        sf_check_true(r, "the summary's header: param, value, per ratio estimate, se, interval, u_num; n, estimator, "
                         "stop (a plain sweep: no work column)",
                      !strncmp(tw_text, want, strlen(want)),
                      !strncmp(tw_text, want, strlen(want)) ? "as documented" : "other columns");
        size_t allnan = 0, plain = 0;
        for (size_t j = 2; j + 2 < tw.ncol; j++) {   /* the numeric columns */
            size_t finite = 0;
            for (size_t i = 0; i < tw.nrow; i++)
                finite += isfinite(tw.cell[i * MAXCOL + j]) != 0;
            allnan += !finite;
        }
        for (const char *p = tw_text; (p = strstr(p, "\tplain\tfixed\n")); p++)
            plain++;
        sf_check_le(r, "summary columns that are NaN at every point", (double)allnan, 0);
        sf_check_le(r, "summary rows that are not estimator plain, stop fixed", (double)(K + 1 - plain), 0);
        sf_check_le(r, "summary: n against the rows (and the diagnostics' row order): largest |diff|", w.sum_n, 0);
        sf_check_le(r, "summary: each ratio's estimate against the recomputed ratio mean: largest |diff| / allowance",
                    w.sum_est, 1);
        sf_check_le(r, "summary: its se against the recomputed ratio standard error: largest |diff| / allowance",
                    w.sum_se, 1);
        sf_check_le(r, "summary: its interval ends against the recomputed Student interval of the ratio: largest "
                       "|diff| / allowance", w.sum_ci, 1);
        sf_check_le(r, "summary: u_num against the recomputed u_num_mean / det, printed %.3g: largest |diff| / half a "
                       "unit of the third digit", w.sum_u, 1);
        sf_check_true(r, "every column the comparison reads is in the tables", !w.missing,
                      w.missing ? "some missing" : "all there");
        sf_check_le(r, "realisations: largest |printed - counted| (n; used and excluded per QoI vs the finite and "
                       "non-finite rows; sf_sweep_point's counts)", w.count, 0);
        sf_check_le(r, "mean of each QoI: largest |printed - recomputed| / (8 n eps max|x|)", w.mean, 1);
        sf_check_le(r, "std (n - 1): largest |printed - recomputed| / (8 n eps max|x - mean|)", w.sd, 1);
        sf_check_le(r, "standard error of the mean: same allowance as the std", w.se, 1);
        sf_check_le(r, "interval ends (mean -+ t se, Student t): largest |printed - recomputed| / (8 n eps max|x|)",
                    w.ci, 1);
        sf_check_le(r, "ratio columns that are not value / det to the bit", (double)w.ratio_bits, 0);
        sf_check_le(r, "ratio mean (printed, and sf_sweep_point's): largest |diff| / allowance", w.rmean, 1);
        sf_check_le(r, "ratio std (printed, and sf_sweep_point's): largest |diff| / allowance", w.rsd, 1);
        sf_check_le(r, "ratio standard error (printed, and sf_sweep_point's): largest |diff| / allowance", w.rse, 1);
        sf_check_le(r, "numerical error: rows with a companion that are not realisations 0 .. max(2, ceil(n/4)) - 1, "
                       "and |printed or held - recomputed| estimate counts", w.num_rows, 0);
        sf_check_le(r, "numerical error: bias (mean of (Q_c - Q) / (rho - 1)), sf_sweep_point's: largest |diff| / "
                       "(8 n eps max|e|)", w.num_bias, 1);
        sf_check_le(r, "numerical error: the bias's standard error, sf_sweep_point's: largest |diff| / (8 n eps "
                       "max|e - bias|)", w.num_se, 1);
        sf_check_le(r, "numerical error: u_num_mean = 3 (|bias| + t se) + a-priori |mean|, sf_sweep_point's: "
                       "largest |diff| / allowance", w.num_u, 1);
        sf_check_le(r, "numerical error: printed bias, se, u_num_mean (%.3g): cells that are not the recomputed value "
                       "printed so, largest |diff| / half a unit of the third digit", w.num_printed, 1);
        /* what the comparison covered: it must have seen exclusions and an extreme value */
        sf_check_ge(r, "excluded (non-finite) values among the rows compared", (double)excluded, 5);
        sf_check_ge(r, "largest ratio among the rows compared (an extreme realisation is included)", maxratio, 20);
        sf_check_ge(r, "numerical error: companion estimates compared", (double)w.num_compared, 20);
        sf_check_ge(r, "numerical error: non-finite estimates excluded among them (the planted point's)",
                    (double)w.num_excluded, 4);
        sf_note(r, "\n%zu points of %zu realisations (%s = the case's sweep) and one planted point (the last "
                   "point's values with a NaN PV_x, an infinite stick fraction, a realisation with no QoI and a PV_F "
                   "100 times its value). The sweep itself excluded %zu values (realisations without a complete "
                   "cycle after t_skip). Recomputed from the per-realisation table alone: GSL's gsl_stats_mean and "
                   "gsl_stats_sd over the finite values, se = sd / sqrt(n_used), the interval mean -+ t se with t "
                   "= gsl_cdf_tdist_Pinv((1 + level) / 2, n_used - 1) at the level the header states.\n",
                K, s0->samples, c->spec.sweep_param, natural);
        /* plot: per point, the PV_F mean held, and printed with its interval */
        double *x = check_alloc((K + 1) * sizeof *x), *mp = check_alloc((K + 1) * sizeof *mp),
               *mr = check_alloc((K + 1) * sizeof *mr), *lo = check_alloc((K + 1) * sizeof *lo),
               *hi = check_alloc((K + 1) * sizeof *hi);
        char clo[48], chi[48];
        snprintf(clo, sizeof clo, "pv_F_ci%s_lo[N]", lv);
        snprintf(chi, sizeof chi, "pv_F_ci%s_hi[N]", lv);
        int miss = 0;
        for (size_t k = 0; k <= K; k++) {
            x[k] = (double)k;
            mp[k] = pt[k].stat[SF_SWEEP_PVF].mean;
            mr[k] = cell(&ts, k, "pv_F_mean[N]", &miss);
            lo[k] = cell(&ts, k, clo, &miss);
            hi[k] = cell(&ts, k, chi, &miss);
        }
        sf_plot *pl = sf_result_plot(r, "pvf_means", "PV_F mean per point: printed, with its interval, and held",
                                     "point (the last: planted) [-]", "PV_F [N]");
        sf_plot_band(pl, "printed interval", K + 1, x, lo, hi);
        sf_plot_series(pl, "printed mean", SF_STYLE_POINTS, K + 1, x, mr);
        sf_plot_series(pl, "sf_sweep_point mean", SF_STYLE_LINES, K + 1, x, mp);
        for (size_t k = 0; k <= K; k++) {   /* the mean -+ its printed numerical error u_num_mean */
            double u = cell(&ts, k, "pv_F_u_num_mean[N]", &miss);
            lo[k] = mr[k] - u;
            hi[k] = mr[k] + u;
        }
        sf_plot_errorbars(pl, "printed mean -+ u_num_mean (numerical error)", K + 1, x, mr, lo, hi);
        free(x); free(mp); free(mr); free(lo); free(hi);
        /* the sweep's ratios as the validation cases plot them (the planted point aside) */
        char xl[96];
        snprintf(xl, sizeof xl, "%s [-]", c->spec.sweep_param);
        sf_plot *pr = sf_result_plot(r, "ratios", "Ratio means: 95% Monte Carlo intervals and numerical errors", xl,
                                     "ratio to the deterministic model [-]");
        sf_plot_log(pr, 1, 0);
        check_plot_sweep_bands(pr, K, c->spec.sweep.v, pt);
        sf_plot_hline(pr, "1 (deterministic)", 1);
    }
    table_free(&tv);
    table_free(&ts);
    table_free(&tw);
    free(tv_text);
    free(ts_text);
    free(tw_text);
    for (size_t k = 0; k < made; k++)
        sf_sweep_point_free(&pt[k]);
    free(pt);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

/* ---- u_num's companions solve their rows' own realisations.
 *
 * For each estimator at each point of the case's sweep, the rows that
 * have a companion (realisations 0 .. num_m - 1) are made again here as
 * `run --summary` makes one realisation: the COF drawn from stream
 * sf_mc_seed(seed, i) (check_draw) by the COF plan of the plan the
 * estimator's rows are documented to run on (sweep.h, mlmc.h: the
 * scene's, sf_plan_make; mlmc-boxes' fine plan, sf_mlmc_box_plans), the
 * run on that plan, and sf_unum_estimate's companion of that run.  The
 * row's QoIs and the sweep's companion (its QoIs, rho, a-priori part)
 * must be these to the bit: the same operations on the same inputs.
 * Nothing here reads the plan a point records (sf_sweep_point.plan). */
enum { UE_PLAIN, UE_CV, UE_ANTI, UE_MLMC, UE_SUB, UE_BOXES, UE_AUTO, UE_N };
static const char *const ue_name[UE_N] = { "plain", "control-variate", "antithetic", "mlmc", "mlmc-sub",
                                           "mlmc-boxes", "auto" };
#define UE_PILOT 4   /* the paired estimators' pilot: --pilot 4 */

/* the SF_EST_* that estimator e of the list runs at scene s (auto: its rule, as `sweep --estimator auto`) */
static int ue_est(const sf_scene *s, int e)
{
    static const int est[UE_N] = { SF_EST_PLAIN, SF_EST_CV, SF_EST_ANTITHETIC, SF_EST_MLMC, SF_EST_MLMC_SUB,
                                   SF_EST_MLMC_BOXES, -1 };
    return e == UE_AUTO ? sf_sweep_estimator_auto(s) : est[e];
}

/* whether the scene's plan sp admits estimator est (boxes: cell averages;
 * every 2nd node: point values on the circulant strip) */
static int ue_admits(const sf_plan *sp, int est)
{
    int field = sp->cof.kind == SF_COF_FIELD;
    if (est == SF_EST_MLMC_BOXES)
        return field && sp->num.cell_average;
    if (est == SF_EST_MLMC_SUB)
        return field && !sp->num.cell_average && sp->cof.generator != SF_COFGEN_TILES;
    return 1;
}

/* estimator est's point at scene s: n realisations (the paired ones:
 * plain's variance at n, the pilot UE_PILOT), as `slipfield sweep` runs
 * it, on one thread: the bits are those of any thread count
 * (montecarlo.h), and each thread builds its own COF plan, most of the
 * work of so small a point */
static int ue_run(const sf_scene *s, int est, size_t n, sf_sweep_point *p, char *err, size_t errlen)
{
    switch (est) {
    case SF_EST_CV: return sf_sweep_run_cv(s, n, 1, NULL, 0, NULL, p, err, errlen);
    case SF_EST_ANTITHETIC: return sf_sweep_run_antithetic(s, n, UE_PILOT, 1, NULL, p, err, errlen);
    case SF_EST_MLMC: return sf_sweep_run_mlmc(s, n, UE_PILOT, 1, NULL, p, err, errlen);
    case SF_EST_MLMC_SUB: return sf_sweep_run_mlmc_sub(s, n, UE_PILOT, 1, NULL, p, err, errlen);
    case SF_EST_MLMC_BOXES: return sf_sweep_run_mlmc_boxes(s, n, UE_PILOT, 1, NULL, p, err, errlen);
    default: return sf_sweep_run(s, n, 1, NULL, 0, NULL, p, err, errlen);
    }
}

/* the plan estimator est's rows run on, as documented (not as recorded) */
static int ue_rows_plan(const sf_scene *s, int est, sf_plan *pl, char *err, size_t errlen)
{
    sf_plan coarse, cdraw;
    if (est == SF_EST_MLMC_BOXES)
        return sf_mlmc_box_plans(s, pl, &coarse, &cdraw, err, errlen);
    int rc = sf_plan_make(s, pl, err, errlen);
    pl->history = 0;
    return rc;
}

/* FNV-1a of a gridded COF: its geometry and values (0: not a grid) */
static unsigned long ue_field_hash(const sf_cof *cof)
{
    size_t m, n;
    double g[4];
    const double *mu;
    if (sf_cof_grid_view(cof, &m, &n, &g[0], &g[1], &g[2], &g[3], &mu))
        return 0;
    unsigned long h = sf_mc_hash(&m, sizeof m, 0);
    h = sf_mc_hash(&n, sizeof n, h);
    h = sf_mc_hash(g, sizeof g, h);
    return sf_mc_hash(mu, m * n * sizeof *mu, h);
}

/* a and b the same bits (NaN: the same outcome, no QoI formed) */
static int ue_same(double a, double b)
{
    return (isnan(a) && isnan(b)) || !memcmp(&a, &b, sizeof a);
}

typedef struct {
    size_t rows, row_bits, comp, comp_bits, hash_differ, boxes_other_field;
    double *xq, *yq;   /* the plot: companion PV_x against its row's (finite ones) */
    size_t nplot, cap;
} ue_tally;

/* point p of estimator est at scene s against the rows made here; one
 * line of the table.  SF_SUCCESS, or the failure noted. */
static int ue_compare(FILE *tab, const sf_scene *s, double lr, const char *name, int est, const sf_sweep_point *p,
                      ue_tally *t)
{
    char err[256] = "";
    sf_plan rp, sp;
    sf_cof_plan *cp = NULL, *scp = NULL;
    int rc = ue_rows_plan(s, est, &rp, err, sizeof err);
    int own = est == SF_EST_MLMC_BOXES;   /* the rows' plan is not the scene's */
    if (!rc && own)
        rc = sf_plan_make(s, &sp, err, sizeof err);
    if (!rc)
        rc = sf_cof_plan_build(s, &rp, &cp, err, sizeof err);
    if (!rc && own)
        rc = sf_cof_plan_build(s, &sp, &scp, err, sizeof err);
    size_t rows_bad = 0, comp_bad = 0;
    unsigned long h0 = 0, hs = 0;
    for (size_t i = 0; !rc && i < p->num_m; i++) {
        sf_cof *cof = NULL, *scof = NULL;
        double q[NQ];
        sf_unum u;
        rc = check_draw(cp, s->seed, i, &cof);
        if (!rc)
            rc = sf_sweep_solve(s, &rp, cof, q, NULL);
        if (!rc) {
            sf_osc_result res;
            memset(&res, 0, sizeof res);
            res.pv_x = q[SF_SWEEP_PVX];
            res.pv_F = q[SF_SWEEP_PVF];
            res.stick_fraction = q[SF_SWEEP_SF];
            rc = sf_unum_estimate(s, cof, &rp.num, &res, &u, err, sizeof err);
        }
        if (!rc && (!own || (rc = check_draw(scp, s->seed, i, &scof)) == SF_SUCCESS)) {
            unsigned long h = ue_field_hash(cof), hsc = own ? ue_field_hash(scof) : h;
            if (!i) {
                h0 = h;
                hs = hsc;
            }
            t->hash_differ += h != hsc;
        }
        if (!rc) {
            int bad = 0, cbad = 0;
            for (int k = 0; k < NQ; k++) {
                bad += !ue_same(q[k], p->qoi[i * NQ + k]);
                cbad += !ue_same(u.qc[k], p->num_qc[i * NQ + k]);
            }
            cbad += !ue_same(u.rho, p->num_rho[i]);
            cbad += !ue_same(u.cell_average ? rp.num.err_quad : 0, p->num_apriori[i]);
            rows_bad += bad > 0;
            comp_bad += cbad > 0;
            t->row_bits += (size_t)bad;
            t->comp_bits += (size_t)cbad;
            double a = p->qoi[i * NQ + SF_SWEEP_PVX], b = p->num_qc[i * NQ + SF_SWEEP_PVX];
            if (isfinite(a) && isfinite(b) && t->nplot < t->cap) {
                t->xq[t->nplot] = a;
                t->yq[t->nplot++] = b;
            }
        }
        sf_cof_free(cof);
        sf_cof_free(scof);
    }
    sf_cof_plan_free(cp);
    sf_cof_plan_free(scp);
    if (rc) {
        fprintf(tab, "| %g | %s | the reconstruction failed: %s |||||||\n", lr, name, *err ? err : sf_strerror(rc));
        return rc;
    }
    t->rows += p->n;
    t->comp += p->num_m;
    if (est == SF_EST_MLMC_BOXES)
        t->boxes_other_field += h0 != hs;
    char other[40] = "(the scene's plan)";
    if (own)
        snprintf(other, sizeof other, "%016lx%s", hs, h0 == hs ? " (the same)" : "");
    fprintf(tab, "| %g | %s | %zu | %zu | %zu, %zu x %zu | %016lx | %s | %zu | %zu |\n", lr, name, p->n, p->num_m,
            rp.num.cells, rp.cof.nx, rp.cof.ny, h0, other, rows_bad, comp_bad);
    return SF_SUCCESS;
}

static int chk_unum_own_field(const sf_case *c, sf_result *r)
{
    size_t K = c->spec.sweep.n;
    if (!K || !*c->spec.sweep_param || c->scene.samples < UE_PILOT)
        return SF_EINVAL;
    ue_tally t = { 0 };
    t.cap = K * UE_N * sf_unum_sweep_subset(c->scene.samples);   /* a point has at most samples rows */
    t.xq = check_alloc(t.cap * sizeof *t.xq);
    t.yq = check_alloc(t.cap * sizeof *t.yq);
    int rc = SF_SUCCESS, seen[UE_N] = { 0 };
    char err[256] = "";
    char *text = NULL;   /* the table, one note */
    size_t len = 0;
    FILE *tab = open_memstream(&text, &len);
    if (!tab) {
        free(t.xq);
        free(t.yq);
        return SF_ENOMEM;
    }
    fprintf(tab, "| %s | estimator | rows | companions | rows' plan: cells, strip | row 0's field (FNV-1a) | the "
                 "scene's plan, same stream | rows not reproduced | companions not reproduced |\n"
                 "|---|---|---|---|---|---|---|---|---|\n", c->spec.sweep_param);
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene s = c->scene;
        sf_plan sp;
        if ((rc = sf_sweep_set(&s, c->spec.sweep_param, c->spec.sweep.v[k], err, sizeof err)) ||
            (rc = sf_plan_make(&s, &sp, err, sizeof err))) {
            sf_note(r, "**%s = %g cannot be planned:** %s\n", c->spec.sweep_param, c->spec.sweep.v[k], err);
            break;
        }
        int done[UE_N] = { 0 };   /* the estimators of the list compared at this point */
        for (int e = 0; e < UE_N && !rc; e++) {
            int est = ue_est(&s, e);
            char name[64];
            snprintf(name, sizeof name, e == UE_AUTO ? "auto (%s)" : "%s",
                     e == UE_AUTO ? sf_sweep_estimator_name(est) : ue_name[e]);
            if (!ue_admits(&sp, est)) {
                fprintf(tab, "| %g | %s | its plan's model does not admit it |||||||\n", c->spec.sweep.v[k], name);
                continue;
            }
            int twin = -1;   /* auto runs one of the above: the same call, its point compared above */
            for (int f = 0; e == UE_AUTO && f < UE_AUTO; f++)
                if (done[f] && ue_est(&s, f) == est)
                    twin = f;
            if (twin >= 0) {
                fprintf(tab, "| %g | %s | the %s point above (sf_sweep_estimator_auto's choice) |||||||\n",
                        c->spec.sweep.v[k], name, ue_name[twin]);
                seen[e] += seen[twin] > 0;
                continue;
            }
            sf_sweep_point p;
            memset(&p, 0, sizeof p);
            *err = 0;
            rc = ue_run(&s, est, s.samples, &p, err, sizeof err);
            if (!rc)   /* the numerical error of the means, as `sweep --summary` makes it */
                rc = sf_unum_sweep(&s, &p, 1, err, sizeof err);
            if (rc)
                fprintf(tab, "| %g | %s | the sweep failed: %s |||||||\n", c->spec.sweep.v[k], name,
                        *err ? err : sf_strerror(rc));
            else if (!(rc = ue_compare(tab, &s, c->spec.sweep.v[k], name, est, &p, &t))) {
                seen[e] += p.num_m >= 2;
                done[e] = 1;
            }
            sf_sweep_point_free(&p);
        }
    }
    fclose(tab);
    sf_note(r, "%s", text);
    free(text);
    size_t kinds = 0;
    for (int e = 0; e < UE_N; e++)
        kinds += seen[e] > 0;
    if (!rc) {
        sf_check_le(r, "row QoIs unlike this check's run of stream i on the rows' documented plan (bits)",
                    (double)t.row_bits, 0);
        sf_check_le(r, "companion QoIs, rho, a-priori parts unlike run --summary's companion of that run (bits)",
                    (double)t.comp_bits, 0);
        sf_check_ge(r, "estimators checked on 2 companions or more (plain, control-variate, antithetic, mlmc, "
                       "mlmc-sub, mlmc-boxes, auto)", (double)kinds, UE_N);
        sf_check_ge(r, "companions compared", (double)t.comp, 2.0 * UE_N);
        sf_check_true(r, "mlmc-boxes' row 0 on another field than the scene's plan draws from its stream (told apart)",
                      t.boxes_other_field > 0,
                      t.boxes_other_field ? "another field" : "the same field, or no mlmc-boxes point");
        sf_note(r, "\n%zu rows, %zu of them with a companion; %zu of those fields differ from the scene's plan's "
                   "on the same stream (mlmc-boxes': its cells rounded up to a multiple of %d, a finer strip %d "
                   "nodes wider each side). Row 0's field is hashed with its grid's geometry (sf_cof_grid_view).\n",
                t.rows, t.comp, t.hash_differ, SF_MLMC_BOX, SF_MLMC_BOX_PAD);
        sf_plot *pl = sf_result_plot(r, "companions", "u_num's companion against its row: PV_x, every estimator",
                                     "row PV_x [m]", "companion PV_x [m]");
        sf_plot_series(pl, "companions", SF_STYLE_POINTS, t.nplot, t.xq, t.yq);
        sf_plot_series(pl, "y = x", SF_STYLE_LINES, t.nplot, t.xq, t.xq);
    }
    free(t.xq);
    free(t.yq);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

const sf_check_def sf_checks_sweepstats[] = {
    { "mc_sweep_aggregation", chk_sweep_aggregation,
      "sweep summary and diagnostics: every estimate and statistic recomputed from the per-realisation table" },
    { "mc_unum_own_field", chk_unum_own_field,
      "sweep u_num: every estimator's companion solves its row's own realisation (bits)" },
    { NULL, NULL, NULL }
};
