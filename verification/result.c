/* What a check produces (result.h): its rows and their verdicts, notes,
 * claims, samples and plots, and the plots' rendering by gnuplot. */
#include "result.h"
#include "stats.h"
#include "sf_error.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct {
    char label[96];
    int style;       /* SF_STYLE_*, or -1 band, -2 hline, -3 error bars */
    size_t n;
    double *x, *y, *y2, *y3;   /* band: y..y2; error bars: y from y2 to y3 */
} series;

struct sf_plot {
    sf_result *owner;   /* counts the plotted values (a plot is the check's data) */
    char stem[64], title[160], xlabel[96], ylabel[96];
    int logx, logy;
    series *s;
    size_t ns;
};

struct sf_result {
    sf_row *rows;
    size_t nrows;
    char *notes;
    size_t notes_len;
    sf_plot **plots;
    size_t nplots;
    /* non-finite values seen in the check's data: rows' measured values,
     * plotted series and arrays given to sf_result_data */
    size_t nonfinite, nvalues;
    char first_bad[128];   /* where the first one was seen */
    sf_claim_row *claims;
    size_t nclaims;
    sf_sample_row *samples;
    size_t nsamples;
    sf_sweep_row *sweep;
    size_t nsweep;
};

static void count_values(sf_result *r, const char *where, size_t n, const double *x)
{
    if (!x)
        return;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]) && r->nonfinite++ == 0)
            snprintf(r->first_bad, sizeof r->first_bad, "%.60s [%zu] = %g", where, i, x[i]);
    r->nvalues += n;
}

static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n);
    if (!q) {
        fputs("slipfield: out of memory\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    return q;
}

sf_result *sf_result_alloc(void)
{
    sf_result *r = calloc(1, sizeof *r);
    if (!r) {
        fputs("slipfield: out of memory\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    return r;
}

void sf_result_free(sf_result *r)
{
    if (!r)
        return;
    for (size_t i = 0; i < r->nplots; i++) {
        sf_plot *p = r->plots[i];
        for (size_t j = 0; j < p->ns; j++) {
            free(p->s[j].x);
            free(p->s[j].y);
            free(p->s[j].y2);
            free(p->s[j].y3);
        }
        free(p->s);
        free(p);
    }
    free(r->plots);
    free(r->claims);
    free(r->samples);
    free(r->sweep);
    free(r->rows);
    free(r->notes);
    free(r);
}

static sf_row *add_row(sf_result *r, const char *q, double measured)
{
    count_values(r, q, 1, &measured);
    r->rows = xrealloc(r->rows, (r->nrows + 1) * sizeof *r->rows);
    sf_row *row = &r->rows[r->nrows++];
    memset(row, 0, sizeof *row);
    snprintf(row->quantity, sizeof row->quantity, "%s", q);
    row->expected = NAN;
    row->measured = measured;
    return row;
}

/* What the row compares (results.json, drift). */
static void set_limit(sf_row *row, int test, double limit, size_t n)
{
    row->test = test;
    row->limit = limit;
    row->n = n;
}

/* NaN measured values always fail: comparisons below are written so that
 * a NaN makes the predicate false. */
int sf_check_abs(sf_result *r, const char *q, double m, double e, double tol)
{
    sf_row *row = add_row(r, q, m);
    row->expected = e;
    double d = fabs(m - e);
    snprintf(row->criterion, sizeof row->criterion, "|diff| <= %.3g", tol);
    row->ratio = tol > 0 ? d / tol : (d == 0 ? 0 : INFINITY);
    row->pass = d <= tol;
    set_limit(row, SF_ROW_ABS, tol, 0);
    return row->pass;
}

int sf_check_rel(sf_result *r, const char *q, double m, double e, double tol)
{
    sf_row *row = add_row(r, q, m);
    row->expected = e;
    double d = fabs(m - e), b = tol * fabs(e);
    snprintf(row->criterion, sizeof row->criterion, "|rel diff| <= %.3g", tol);
    row->ratio = b > 0 ? d / b : (d == 0 ? 0 : INFINITY);
    row->pass = d <= b;
    set_limit(row, SF_ROW_REL, tol, 0);
    return row->pass;
}

int sf_check_le(sf_result *r, const char *q, double m, double bound)
{
    sf_row *row = add_row(r, q, m);
    snprintf(row->criterion, sizeof row->criterion, "<= %.3g", bound);
    row->ratio = bound != 0 ? m / bound : (m <= 0 ? 0 : INFINITY);
    row->pass = m <= bound;
    set_limit(row, SF_ROW_LE, bound, 0);
    return row->pass;
}

int sf_check_ge(sf_result *r, const char *q, double m, double bound)
{
    sf_row *row = add_row(r, q, m);
    snprintf(row->criterion, sizeof row->criterion, ">= %.3g", bound);
    row->ratio = m != 0 ? bound / m : INFINITY;
    if (bound <= 0 && m >= bound)
        row->ratio = 0;
    row->pass = m >= bound;
    set_limit(row, SF_ROW_GE, bound, 0);
    return row->pass;
}

int sf_check_pvalue(sf_result *r, const char *test, double p, double alpha, size_t n)
{
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "%s (n = %zu): p-value", test, n);
    sf_row *row = add_row(r, q, p);
    snprintf(row->criterion, sizeof row->criterion, "p >= alpha = %.3g", alpha);
    row->ratio = p > 0 ? alpha / p : INFINITY;
    row->pass = p >= alpha;
    set_limit(row, SF_ROW_PVALUE, alpha, n);
    row->alpha = alpha;
    return row->pass;
}

int sf_check_true(sf_result *r, const char *q, int ok, const char *found)
{
    sf_row *row = add_row(r, q, ok ? 1 : 0);
    row->expected = 1;
    snprintf(row->criterion, sizeof row->criterion, "%s", found ? found : "holds");
    row->ratio = ok ? 0 : INFINITY;
    row->pass = ok != 0;
    set_limit(row, SF_ROW_TRUE, NAN, 0);
    return row->pass;
}

void sf_result_mark_statistical(sf_result *r, double alpha)
{
    if (r->nrows)
        r->rows[r->nrows - 1].alpha = alpha;
}

int sf_check_verdict(sf_result *r, const char *q, int ok, const char *found, double alpha)
{
    int pass = sf_check_true(r, q, ok, found);
    sf_result_mark_statistical(r, alpha);
    return pass;
}

void sf_result_data(sf_result *r, const char *what, size_t n, double *x)
{
    sf_poison_array(x, n);
    count_values(r, what, n, x);
}

size_t sf_result_nonfinite(const sf_result *r) { return r->nonfinite; }

int sf_result_gate_nonfinite(sf_result *r)
{
    char found[160];
    if (r->nonfinite)
        snprintf(found, sizeof found, "none may be NaN/Inf; first: %s", r->first_bad);
    else
        snprintf(found, sizeof found, "all %zu values finite", r->nvalues);
    sf_row *row = add_row(r, "non-finite values in the check's data (rows, plots, aggregated arrays)", (double)r->nonfinite);
    row->expected = 0;
    snprintf(row->criterion, sizeof row->criterion, "= 0 (%.70s)", found);
    row->ratio = r->nonfinite ? INFINITY : 0;
    row->pass = r->nonfinite == 0;
    return row->pass;
}

void sf_note(sf_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
        return;
    r->notes = xrealloc(r->notes, r->notes_len + (size_t)n + 2);
    va_start(ap, fmt);
    vsnprintf(r->notes + r->notes_len, (size_t)n + 1, fmt, ap);
    va_end(ap);
    r->notes_len += (size_t)n;
    r->notes[r->notes_len++] = '\n';
    r->notes[r->notes_len] = '\0';
}

void sf_claim(sf_result *r, const char *id, const char *text, int status, double measured, double ci_lo,
              double ci_hi, double alpha, const char *how, const char *note)
{
    r->claims = xrealloc(r->claims, (r->nclaims + 1) * sizeof *r->claims);
    sf_claim_row *c = &r->claims[r->nclaims++];
    memset(c, 0, sizeof *c);
    snprintf(c->id, sizeof c->id, "%s", id);
    snprintf(c->text, sizeof c->text, "%s", text);
    snprintf(c->how, sizeof c->how, "%s", how ? how : "");
    snprintf(c->note, sizeof c->note, "%s", note ? note : "");
    /* a claim whose estimate is not a number cannot be decided */
    c->status = isfinite(measured) ? status : SF_CLAIM_UNDECIDED;
    c->measured = measured;
    c->ci_lo = ci_lo;
    c->ci_hi = ci_hi;
    c->alpha = alpha;
    c->model.status = -1;
    c->model.est = c->model.lo = c->model.hi = c->model.mde = c->model.alpha = c->model.margin = NAN;
}

void sf_claim_set_model(sf_result *r, const char *id, const sf_claim_model *m)
{
    for (size_t i = r->nclaims; i-- > 0;)
        if (!strcmp(r->claims[i].id, id)) {
            r->claims[i].model = *m;
            return;
        }
}

const char *sf_claim_model_name(int s)
{
    return s == SF_CLAIM_CONFIRMED ? "confirmed" : s == SF_CLAIM_CONTRADICTED ? "contradicted"
         : s == SF_CLAIM_WITHIN ? "within margin" : s == SF_CLAIM_UNDECIDED ? "budget reached" : "none";
}

void sf_claim_defs(sf_result *r, const char *defs)
{
    if (r->nclaims)
        snprintf(r->claims[r->nclaims - 1].defs, sizeof r->claims[0].defs, "%s", defs);
}

void sf_result_sample(sf_result *r, const char *what, size_t n_used, size_t n_excluded)
{
    r->samples = xrealloc(r->samples, (r->nsamples + 1) * sizeof *r->samples);
    sf_sample_row *s = &r->samples[r->nsamples++];
    snprintf(s->what, sizeof s->what, "%s", what);
    s->n_used = n_used;
    s->n_excluded = n_excluded;
}

size_t sf_result_nsamples(const sf_result *r) { return r->nsamples; }
const sf_sample_row *sf_result_sample_at(const sf_result *r, size_t i) { return &r->samples[i]; }

void sf_result_sweep(sf_result *r, const sf_sweep_row *row)
{
    r->sweep = xrealloc(r->sweep, (r->nsweep + 1) * sizeof *r->sweep);
    r->sweep[r->nsweep++] = *row;
}

size_t sf_result_nsweep(const sf_result *r) { return r->nsweep; }
const sf_sweep_row *sf_result_sweep_at(const sf_result *r, size_t i) { return &r->sweep[i]; }

size_t sf_result_nclaims(const sf_result *r) { return r->nclaims; }
const sf_claim_row *sf_result_claim(const sf_result *r, size_t i) { return &r->claims[i]; }
const char *sf_claim_status_name(int s)
{
    return s == SF_CLAIM_CONFIRMED ? "confirmed" : s == SF_CLAIM_CONTRADICTED ? "contradicted" : "not decidable at this N";
}

size_t sf_result_nrows(const sf_result *r) { return r->nrows; }
const sf_row *sf_result_row(const sf_result *r, size_t i) { return &r->rows[i]; }
const char *sf_result_notes(const sf_result *r) { return r->notes ? r->notes : ""; }

int sf_result_passed(const sf_result *r)
{
    if (r->nrows == 0)
        return 0;
    for (size_t i = 0; i < r->nrows; i++)
        if (!r->rows[i].pass)
            return 0;
    return 1;
}

const sf_row *sf_result_key_row(const sf_result *r)
{
    const sf_row *best = NULL;
    for (size_t i = 0; i < r->nrows; i++) {
        if (!r->rows[i].pass)
            return &r->rows[i];
        if (!best || r->rows[i].ratio > best->ratio)
            best = &r->rows[i];
    }
    return best;
}

/* ---- plots ---- */

static void copy_clean(char *dst, size_t n, const char *src)
{
    /* gnuplot strings are written inside double quotes: drop quotes,
     * backslashes and control characters rather than trying to escape. */
    size_t j = 0;
    for (size_t i = 0; src && src[i] && j + 1 < n; i++) {
        unsigned char c = (unsigned char)src[i];
        if (c < 32 || c == '"' || c == '\\' || c == '`')
            continue;
        dst[j++] = (char)c;
    }
    dst[j] = '\0';
}

sf_plot *sf_result_plot(sf_result *r, const char *stem, const char *title,
                        const char *xlabel, const char *ylabel)
{
    sf_plot *p = calloc(1, sizeof *p);
    if (!p) {
        fputs("slipfield: out of memory\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    size_t j = 0;
    for (size_t i = 0; stem[i] && j + 1 < sizeof p->stem; i++) {
        char c = stem[i];
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-')
            p->stem[j++] = c;
    }
    p->stem[j] = '\0';
    if (!j)
        snprintf(p->stem, sizeof p->stem, "plot%zu", r->nplots);
    p->owner = r;
    copy_clean(p->title, sizeof p->title, title);
    copy_clean(p->xlabel, sizeof p->xlabel, xlabel);
    copy_clean(p->ylabel, sizeof p->ylabel, ylabel);
    r->plots = xrealloc(r->plots, (r->nplots + 1) * sizeof *r->plots);
    r->plots[r->nplots++] = p;
    return p;
}

void sf_plot_log(sf_plot *p, int logx, int logy)
{
    p->logx = logx;
    p->logy = logy;
}

static series *add_series(sf_plot *p, const char *label, int style, size_t n)
{
    p->s = xrealloc(p->s, (p->ns + 1) * sizeof *p->s);
    series *s = &p->s[p->ns++];
    memset(s, 0, sizeof *s);
    copy_clean(s->label, sizeof s->label, label);
    s->style = style;
    s->n = n;
    if (n) {
        s->x = xrealloc(NULL, n * sizeof *s->x);
        s->y = xrealloc(NULL, n * sizeof *s->y);
    }
    return s;
}

/* A series' columns copied in (y2, y3 may be NULL: not that kind), each
 * counted among the check's data. */
static void fill(sf_plot *p, series *s, const double *x, const double *y, const double *y2, const double *y3)
{
    const double *src[4] = { x, y, y2, y3 };
    double **dst[4] = { &s->x, &s->y, &s->y2, &s->y3 };
    for (int k = 0; k < 4 && s->n; k++) {
        if (!src[k])
            continue;
        if (!*dst[k])
            *dst[k] = xrealloc(NULL, s->n * sizeof **dst[k]);
        memcpy(*dst[k], src[k], s->n * sizeof *src[k]);
        count_values(p->owner, s->label, s->n, src[k]);
    }
}

void sf_plot_series(sf_plot *p, const char *label, int style, size_t n,
                    const double *x, const double *y)
{
    fill(p, add_series(p, label, style, n), x, y, NULL, NULL);
}

void sf_plot_band(sf_plot *p, const char *label, size_t n, const double *x,
                  const double *lo, const double *hi)
{
    fill(p, add_series(p, label, -1, n), x, lo, hi, NULL);
}

void sf_plot_errorbars(sf_plot *p, const char *label, size_t n, const double *x, const double *y,
                       const double *lo, const double *hi)
{
    fill(p, add_series(p, label, -3, n), x, y, lo, hi);
}

void sf_plot_hline(sf_plot *p, const char *label, double y)
{
    series *s = add_series(p, label, -2, 1);
    s->x[0] = 0;
    s->y[0] = y;
    count_values(p->owner, s->label, 1, &y);
}

size_t sf_result_nplots(const sf_result *r) { return r->nplots; }
sf_plot *sf_result_get_plot(const sf_result *r, size_t i) { return r->plots[i]; }
const char *sf_plot_stem(const sf_plot *p) { return p->stem; }
const char *sf_plot_title(const sf_plot *p) { return p->title; }

/* The shared look of every plot: verification/plot-style.gp, compiled in
 * as sf_plot_style[] (generated header). */
#include "plot_style.h"

static int finite_for(const sf_plot *p, double x, double y)
{
    if (!isfinite(x) || !isfinite(y))
        return 0;
    if (p->logx && x <= 0) return 0;
    if (p->logy && y <= 0) return 0;
    return 1;
}

/* Write one plot's gnuplot commands.  A single x value (one sweep point)
 * gets an x range around it, and its one-point lines and bands are drawn
 * as points and error bars (a line through one point draws nothing).
 * `why` gets a reason when the plot would be empty, or a series would
 * draw nothing: a check that plots nothing shows no evidence. */
void sf_plot_write_script(FILE *g, const sf_plot *p, const char *path, char *why, size_t whylen)
{
    why[0] = '\0';
    fprintf(g, "reset session\n%s", sf_plot_style);
    fprintf(g, "set output \"%s\"\n", path);
    fprintf(g, "set title \"%s\"\nset xlabel \"%s\"\nset ylabel \"%s\"\n",
            p->title, p->xlabel, p->ylabel);
    fprintf(g, p->logx ? "set logscale x\nset format x '%%.0e'\n" : "unset logscale x\n");
    fprintf(g, p->logy ? "set logscale y\nset format y '%%.0e'\n" : "unset logscale y\n");
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (size_t j = 0; j < p->ns; j++) {
        const series *s = &p->s[j];
        for (size_t i = 0; i < s->n; i++)
            if (s->style == -2 ? finite_for(p, 1, s->y[i]) : finite_for(p, s->x[i], s->y[i])) {
                ylo = fmin(ylo, s->y[i]);
                yhi = fmax(yhi, s->y[i]);
                if (s->style != -2) {
                    xlo = fmin(xlo, s->x[i]);
                    xhi = fmax(xhi, s->x[i]);
                }
                if ((s->style == -1 || s->style == -3) && finite_for(p, s->x[i], s->y2[i])) {
                    ylo = fmin(ylo, s->y2[i]);
                    yhi = fmax(yhi, s->y2[i]);
                }
                if (s->style == -3 && finite_for(p, s->x[i], s->y3[i])) {
                    ylo = fmin(ylo, s->y3[i]);
                    yhi = fmax(yhi, s->y3[i]);
                }
            }
    }
    /* a flat plot (e.g. a measured value equal to the exact one): give
     * gnuplot a range around it instead of letting it warn and guess */
    if (isfinite(ylo) && yhi - ylo <= 1e-9 * fmax(fabs(ylo), fabs(yhi)) && !p->logy) {
        double mid = 0.5 * (ylo + yhi), h = fmax(1e-3 * fabs(mid), 1e-12);
        fprintf(g, "set yrange [%.10g:%.10g]\n", mid - h, mid + h);
    }
    int one_x = isfinite(xlo) && xhi - xlo <= 1e-9 * fmax(fabs(xlo), fabs(xhi));
    if (one_x) {
        double mid = 0.5 * (xlo + xhi), h = fabs(mid) > 0 ? 0.5 * fabs(mid) : 1;
        if (p->logx)
            fprintf(g, "set xrange [%.10g:%.10g]\n", mid / 3, mid * 3);
        else
            fprintf(g, "set xrange [%.10g:%.10g]\n", mid - h, mid + h);
    }
    /* a log x axis: gnuplot's autoscale widens it to whole decades (data at
     * l/R 0.25 and 1 drawn from 0.1); the data's own range instead, 4% of
     * it beyond each end, its ends labelled when it spans under 2 decades */
    if (p->logx && !one_x && isfinite(xlo)) {
        /* in logs: a range of 1e-300 .. 1e300 overflows xhi / xlo */
        double lr = 0.04 * (log(xhi) - log(xlo)), a = exp(log(xlo) - lr), b = exp(log(xhi) + lr);
        if (a > 0 && isfinite(b))
            fprintf(g, "set xrange [%.10g:%.10g]\n", a, b);
        if (xhi / xlo < 100)
            fprintf(g, "set format x '%%g'\nset xtics add ('%g' %.10g, '%g' %.10g)\n", xlo, xlo, xhi, xhi);
    }
    /* error bars at the first and last x, or at the top, would sit on the
     * frame, half drawn: a margin of 3% of the axes around the data */
    int has_bars = 0;
    for (size_t j = 0; j < p->ns; j++)
        has_bars |= p->s[j].style == -3;
    if (has_bars && !one_x)
        fprintf(g, "set offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03\n");
    size_t *written = xrealloc(NULL, (p->ns + 1) * sizeof *written);
    int any = 0;
    for (size_t j = 0; j < p->ns; j++) {
        const series *s = &p->s[j];
        fprintf(g, "$d%zu << EOD\n", j);
        written[j] = 0;
        for (size_t i = 0; i < s->n; i++) {
            if (s->style == -2) break;
            if (!finite_for(p, s->x[i], s->y[i])) continue;
            if (s->style == -1) {
                if (!finite_for(p, s->x[i], s->y2[i])) continue;
                fprintf(g, "%.10g %.10g %.10g\n", s->x[i], s->y[i], s->y2[i]);
            } else if (s->style == -3) {
                if (!finite_for(p, s->x[i], s->y2[i]) || !finite_for(p, s->x[i], s->y3[i])) continue;
                fprintf(g, "%.10g %.10g %.10g %.10g\n", s->x[i], s->y[i], s->y2[i], s->y3[i]);
            } else {
                fprintf(g, "%.10g %.10g\n", s->x[i], s->y[i]);
            }
            written[j]++;
        }
        fprintf(g, "EOD\n");
        if (written[j] && s->style != -2)
            any = 1;
        else if (s->style != -2 && !*why)
            snprintf(why, whylen, "series '%.60s' has no point to draw (%zu values, none finite%s)", s->label, s->n,
                     p->logx || p->logy ? " and positive on the log axis" : "");
    }
    if (!any) {
        if (!*why)
            snprintf(why, whylen, "no finite data to plot");
        fprintf(g, "unset logscale\nset label 1 \"no finite data to plot\" at graph 0.5, graph 0.5 center\n"
                   "plot [0:1][0:1] NaN title ''\n");
        free(written);
        return;
    }
    fprintf(g, "plot ");
    int first = 1;
    /* bands first so lines are drawn on top */
    for (int pass = 0; pass < 2; pass++) {
        for (size_t j = 0; j < p->ns; j++) {
            const series *s = &p->s[j];
            int isband = s->style == -1;
            if ((pass == 0) != isband) continue;
            if (s->style != -2 && written[j] == 0) continue;
            if (!first) fprintf(g, ", \\\n     ");
            first = 0;
            /* a line through one point is invisible: mark the point */
            const char *lines = written[j] == 1 ? "linespoints" : "lines";
            switch (s->style) {
            case -1:
                if (written[j] == 1)
                    fprintf(g, "$d%zu using 1:(($2+$3)/2):2:3 with yerrorbars lc rgb '#888888' pt 0 title \"%s\"", j,
                            s->label);
                else
                    fprintf(g, "$d%zu using 1:2:3 with filledcurves fc rgb '#bbbbbb' fs transparent solid 0.5 title \"%s\"",
                            j, s->label);
                break;
            case -2:
                fprintf(g, "%.10g with lines dt 2 lw 1.5 lc rgb '#555555' title \"%s\"", s->y[0], s->label);
                break;
            case -3:
                fprintf(g, "$d%zu using 1:2:3:4 with yerrorbars title \"%s\"", j, s->label);
                break;
            case SF_STYLE_POINTS:
                fprintf(g, "$d%zu using 1:2 with points title \"%s\"", j, s->label);
                break;
            case SF_STYLE_LINESPOINTS:
                fprintf(g, "$d%zu using 1:2 with linespoints title \"%s\"", j, s->label);
                break;
            case SF_STYLE_STEPS:
                fprintf(g, "$d%zu using 1:2 with %s title \"%s\"", j, written[j] == 1 ? "points" : "steps", s->label);
                break;
            case SF_STYLE_DASHED:
                fprintf(g, "$d%zu using 1:2 with %s dt 2 lw 2 lc rgb 'black'%s title \"%s\"", j, lines,
                        written[j] == 1 ? " pt 6 ps 1.5" : "", s->label);
                break;
            default:
                fprintf(g, "$d%zu using 1:2 with %s title \"%s\"", j, lines, s->label);
            }
        }
    }
    fprintf(g, "\n");
    free(written);
}

/* The file gnuplot reads its script from: the pipe (sf_result_render_plots). */
#define GP_SCRIPT "/dev/stdin"

/* Read gnuplot's messages (its stderr, in a temporary file) back: each
 * plot's script starts by printing a marker, so a message belongs to the
 * plot after the last marker.  msg[i] gets plot i's first message. */
static void read_messages(FILE *e, size_t nplots, char (*msg)[160])
{
    static const char mark[] = "@sf-plot ";
    static const char from[] = "\"" GP_SCRIPT "\" ";   /* what gnuplot puts before "line N:" */
    char line[512];
    size_t cur = 0;
    int echo = 0;   /* msg[cur] was taken from the line before */
    rewind(e);
    while (fgets(line, sizeof line, e)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (!strncmp(line, mark, sizeof mark - 1)) {
            cur = (size_t)strtoul(line + sizeof mark - 1, NULL, 10);
            echo = 0;
            continue;
        }
        /* a message about a command echoes it and marks the place ("^")
         * on the next line before saying what is wrong ("\"/dev/stdin\"
         * line 12: ..."): the echo is no message */
        char *t = line + strspn(line, " \t");
        if (*t == '^') {
            if (echo)
                msg[cur][0] = '\0';
            echo = 0;
            continue;
        }
        echo = 0;
        if (!strncmp(t, from, sizeof from - 1))
            t += sizeof from - 1;
        if (*t && cur < nplots && !msg[cur][0]) {
            snprintf(msg[cur], sizeof msg[cur], "%s", t);
            echo = 1;
        }
    }
}

int sf_result_render_plots(sf_result *r, const char *dir, char *err, size_t errlen)
{
    if (r->nplots == 0)
        return 0;
    FILE *e = tmpfile();   /* gnuplot's stderr: a file cannot fill up and stall it */
    int fd[2];
    if (!e || pipe(fd) != 0) {
        snprintf(err, errlen, "%s: %s", e ? "pipe" : "tmpfile", strerror(errno));
        if (e)
            fclose(e);
        return -1;
    }
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(err, errlen, "fork: %s", strerror(errno));
        close(fd[0]);
        close(fd[1]);
        fclose(e);
        return -1;
    }
    if (pid == 0) {
        /* gnuplot reads the script from the pipe; no shell, no
         * interpolated command line.  Named as a file, not left as
         * stdin: gnuplot reads stdin a byte per system call (it may be a
         * terminal), 6x slower on a trajectory's inline data, and a file
         * stops at its first error */
        dup2(fd[0], 0);
        dup2(fileno(e), 2);
        close(fd[0]);
        close(fd[1]);
        execlp("gnuplot", "gnuplot", GP_SCRIPT, (char *)NULL);
        _exit(127);
    }
    close(fd[0]);
    FILE *g = fdopen(fd[1], "w");
    if (!g) {
        close(fd[1]);
        waitpid(pid, NULL, 0);
        fclose(e);
        snprintf(err, errlen, "fdopen failed");
        return -1;
    }
    char path[1024];
    char (*msg)[160] = xrealloc(NULL, r->nplots * sizeof *msg);
    for (size_t i = 0; i < r->nplots; i++) {
        snprintf(path, sizeof path, "%s/%s.png.tmp", dir, r->plots[i]->stem);
        fprintf(g, "print \"@sf-plot %zu\"\n", i);   /* print writes to stderr */
        sf_plot_write_script(g, r->plots[i], path, msg[i], sizeof msg[i]);
    }
    fprintf(g, "unset output\nexit\n");
    fclose(g);
    int status = 0;
    waitpid(pid, &status, 0);
    /* our own reasons first: gnuplot's message on an empty plot is vaguer */
    char (*said)[160] = xrealloc(NULL, r->nplots * sizeof *said);
    memset(said, 0, r->nplots * sizeof *said);
    read_messages(e, r->nplots, said);
    fclose(e);
    for (size_t i = 0; i < r->nplots; i++)
        if (!msg[i][0])
            memcpy(msg[i], said[i], sizeof msg[i]);
    free(said);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        /* gnuplot stops at an error: name the plot it stopped on */
        size_t k = 0;
        while (k + 1 < r->nplots && !msg[k][0])
            k++;
        snprintf(err, errlen, "gnuplot failed (status %d)%s%s%s%s", WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                 WIFEXITED(status) && WEXITSTATUS(status) == 127 ? ": gnuplot not found (run 'make deps')" : "",
                 msg[k][0] ? " on plot " : "", msg[k][0] ? r->plots[k]->stem : "", msg[k][0] ? ": " : "");
        size_t len = strlen(err);
        if (msg[k][0] && len + 1 < errlen)
            snprintf(err + len, errlen - len, "%s", msg[k]);
        free(msg);
        return -1;
    }
    int warned = 0;
    for (size_t i = 0; i < r->nplots; i++) {
        char fin[1024];
        snprintf(path, sizeof path, "%s/%s.png.tmp", dir, r->plots[i]->stem);
        snprintf(fin, sizeof fin, "%s/%s.png", dir, r->plots[i]->stem);
        if (rename(path, fin) != 0) {
            snprintf(err, errlen, "plot %s was not written", fin);
            free(msg);
            return -1;
        }
        if (msg[i][0]) {
            /* a message means a misdrawn plot: a failing row names it */
            char q[160];
            snprintf(q, sizeof q, "plot %s: drawn cleanly (no gnuplot message, no empty series)", r->plots[i]->stem);
            sf_check_true(r, q, 0, msg[i]);
            if (!warned++)
                snprintf(err, errlen, "plot %s: %s", r->plots[i]->stem, msg[i]);
        }
    }
    free(msg);
    return warned;
}
