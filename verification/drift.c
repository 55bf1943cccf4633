/* The "changed since baseline" page: see drift.h for the rules.  Both runs
 * are read as JSON (jansson): the baseline before the run starts, this
 * run's results.json after it is written. */
#include "drift.h"
#include "html.h"
#include "sf_error.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <gsl/gsl_cdf.h>
#include <jansson.h>

struct sf_baseline {
    json_t *root;
};

#define EXACT_ULPS 10.0          /* "10x their round-off" */
/* a chaotic trajectory amplifies a change of round-off: about 1e-7 in
   PV_x over 40 s (measured); 1e-6 of the values' scale is 10x that */
#define CHAOS_SCALE 1e-6
#define Z_MOVE (2.0 * 1.4142135623730951)   /* 2 sampling errors of a difference of two N(0,1) */
#define TIME_FACTOR 2.0
#define TIME_FLOOR 0.5           /* s */

int sf_drift_exact_moved(double m0, double m1, double expected)
{
    if (!isfinite(m0) || !isfinite(m1)) {
        /* moved unless both are the same non-finite value */
        if (isnan(m0) && isnan(m1)) return 0;
        return !(m0 == m1);
    }
    /* the operands of an error metric are of order one (SI or
       dimensionless), so a value near zero still carries their round-off */
    double scale = fmax(fmax(fabs(m0), fabs(m1)), 1.0);
    if (isfinite(expected))
        scale = fmax(scale, fabs(expected));
    return fabs(m1 - m0) > EXACT_ULPS * DBL_EPSILON * scale;
}

static double pz(double p)
{
    /* p in [0, 1].  p >= 0.5 is far from any alpha, and a Bonferroni p
     * is clamped at 1 (not uniform there): the upper half counts as 0.5
     * (z = 0), which only makes the rule more conservative.  The lower end
     * is clamped so z stays finite (37). */
    p = fmin(fmax(p, 1e-300), 0.5);
    return gsl_cdf_ugaussian_Qinv(p);
}

int sf_drift_pvalue_moved(double p0, double p1)
{
    if (!isfinite(p0) || !isfinite(p1)) {
        if (isnan(p0) && isnan(p1)) return 0;
        return !(p0 == p1);
    }
    return fabs(pz(p1) - pz(p0)) > Z_MOVE;
}

int sf_drift_chaotic_moved(double m0, double m1, double expected)
{
    if (!isfinite(m0) || !isfinite(m1))
        return sf_drift_exact_moved(m0, m1, expected);
    double scale = fmax(fmax(fabs(m0), fabs(m1)), 1.0);
    if (isfinite(expected))
        scale = fmax(scale, fabs(expected));
    return fabs(m1 - m0) > CHAOS_SCALE * scale;
}

int sf_drift_pvalue_coupled_moved(double p0, double p1, int chaotic)
{
    if (!isfinite(p0) || !isfinite(p1))
        return sf_drift_pvalue_moved(p0, p1);
    double k = chaotic ? CHAOS_SCALE : EXACT_ULPS * DBL_EPSILON;
    return fabs(p1 - p0) > k * fmax(fabs(p0), fabs(p1));
}

int sf_drift_chaotic_family(const char *family)
{
    static const char *const fam[] = { "dynamics", "validation", "plan", "stress", "limits" };
    for (size_t k = 0; k < sizeof fam / sizeof *fam; k++)
        if (!strcmp(family, fam[k]))
            return 1;
    return 0;
}

int sf_drift_time_grew(double t0, double t1)
{
    return t1 > TIME_FACTOR * t0 && t1 - t0 > TIME_FLOOR;
}

int sf_baseline_load(const char *path, sf_baseline **out, char *err, size_t errlen)
{
    json_error_t je;
    *out = NULL;
    json_t *j = json_load_file(path, 0, &je);
    if (!j) {
        if (je.line < 0)
            snprintf(err, errlen, "baseline %s: %s", path, je.text);
        else
            snprintf(err, errlen, "baseline %s:%d: %s", path, je.line, je.text);
        return je.line < 0 ? SF_EIO : SF_EPARSE;
    }
    const char *schema = json_string_value(json_object_get(j, "schema"));
    if (!json_is_object(j) || !schema || strncmp(schema, "slipfield-results/", 18) ||
        !json_is_array(json_object_get(j, "cases"))) {
        snprintf(err, errlen, "baseline %s: not a slipfield results.json (no \"schema\": \"slipfield-results/N\" and \"cases\")", path);
        json_decref(j);
        return SF_EPARSE;
    }
    sf_baseline *b = malloc(sizeof *b);
    if (!b) {
        json_decref(j);
        snprintf(err, errlen, "out of memory");
        return SF_EIO;
    }
    b->root = j;
    *out = b;
    return SF_SUCCESS;
}

void sf_baseline_free(sf_baseline *b)
{
    if (!b) return;
    json_decref(b->root);
    free(b);
}

/* A number of a row: its value, or the non-finite value it stood for
 * (null plus the "nonfinite" flag), or NAN when there is none. */
static double num(json_t *obj, const char *key, int *absent)
{
    json_t *v = json_object_get(obj, key);
    if (absent) *absent = 0;
    if (json_is_number(v))
        return json_number_value(v);
    const char *w = json_string_value(json_object_get(json_object_get(obj, "nonfinite"), key));
    if (w)
        return !strcmp(w, "inf") ? INFINITY : !strcmp(w, "-inf") ? -INFINITY : NAN;
    if (absent) *absent = 1;
    return NAN;
}

static const char *str(json_t *obj, const char *key)
{
    const char *s = json_string_value(json_object_get(obj, key));
    return s ? s : "";
}

static json_t *find_case(json_t *cases, const char *id)
{
    size_t i;
    json_t *c;
    json_array_foreach(cases, i, c)
        if (!strcmp(str(c, "id"), id))
            return c;
    return NULL;
}

static void fmt(char *b, size_t n, double x, int absent)
{
    if (absent) snprintf(b, n, "—");
    else if (isnan(x)) snprintf(b, n, "NaN");
    else if (isinf(x)) snprintf(b, n, x > 0 ? "inf" : "-inf");
    else snprintf(b, n, "%.17g", x);
}

/* The tolerance in the units of measured, for "change / tolerance". */
static double tol_units(json_t *row)
{
    const char *t = str(row, "test");
    double tol = num(row, "tolerance", NULL);
    if (!strcmp(t, "abs")) return tol;
    if (!strcmp(t, "rel")) return tol * fabs(num(row, "expected", NULL));
    if (!strcmp(t, "le") || !strcmp(t, "ge")) return fabs(tol);
    return NAN;
}

typedef struct {
    FILE *verdicts, *moved, *slower, *cases, *rows, *seeds;
} sections;

static void compare_rows(json_t *c0, json_t *c1, const char *id, sections *sec, sf_drift_summary *s)
{
    json_t *r0 = json_object_get(c0, "rows"), *r1 = json_object_get(c1, "rows");
    size_t n0 = json_array_size(r0), n1 = json_array_size(r1);
    /* same seed: both runs drew the same data, which a change of code
       moves only by round-off (amplified on a chaotic trajectory) */
    int coupled = json_integer_value(json_object_get(c0, "seed")) == json_integer_value(json_object_get(c1, "seed"));
    int chaotic = sf_drift_chaotic_family(str(c1, "family"));
    char *used = calloc(n1 ? n1 : 1, 1);
    if (!used) return;
    for (size_t i = 0; i < n0; i++) {
        json_t *a = json_array_get(r0, i), *b = NULL;
        const char *q = str(a, "quantity");
        for (size_t k = 0; k < n1; k++)
            if (!used[k] && !strcmp(str(json_array_get(r1, k), "quantity"), q)) {
                used[k] = 1;
                b = json_array_get(r1, k);
                break;
            }
        if (!b) {
            s->rows_removed++;
            fprintf(sec->rows, "| [%s](%s/report.md) | removed | ", id, id);
            sf_md_text(sec->rows, q);
            fprintf(sec->rows, " |\n");
            continue;
        }
        int ab0, ab1;
        double m0 = num(a, "measured", &ab0), m1 = num(b, "measured", &ab1);
        const char *kind = str(b, "kind");
        int moved;
        char thr[96] = "", share[64] = "—";
        if (ab0 != ab1) {
            moved = 1;
        } else if (!strcmp(kind, "statistical") && !coupled) {
            moved = sf_drift_pvalue_moved(m0, m1);
            snprintf(thr, sizeof thr, "independent draws: \\|dz\\| > %.2f", Z_MOVE);
            if (isfinite(m0) && isfinite(m1))
                snprintf(share, sizeof share, "dz = %+.2f", pz(m1) - pz(m0));
        } else if (!strcmp(kind, "statistical")) {
            moved = sf_drift_pvalue_coupled_moved(m0, m1, chaotic);
            double u = (chaotic ? CHAOS_SCALE : EXACT_ULPS * DBL_EPSILON) * fmax(fabs(m0), fabs(m1));
            snprintf(thr, sizeof thr, "same draws, %s: %.2g", chaotic ? "chaotic" : "round-off", u);
            if (isfinite(m0) && isfinite(m1))
                snprintf(share, sizeof share, "dz = %+.2f", pz(m1) - pz(m0));
        } else if (!strcmp(kind, "boolean")) {
            moved = json_is_true(json_object_get(a, "pass")) != json_is_true(json_object_get(b, "pass")) ||
                    sf_drift_exact_moved(m0, m1, NAN);
            snprintf(thr, sizeof thr, "any change");
        } else {
            double e = num(b, "expected", NULL);
            moved = chaotic ? sf_drift_chaotic_moved(m0, m1, e) : sf_drift_exact_moved(m0, m1, e);
            double sc = fmax(fmax(fmax(fabs(m0), fabs(m1)), isfinite(e) ? fabs(e) : 0), 1.0);
            snprintf(thr, sizeof thr, "%s: %.2g", chaotic ? "chaotic" : "round-off",
                     (chaotic ? CHAOS_SCALE : EXACT_ULPS * DBL_EPSILON) * sc);
            double t = tol_units(b);
            if (isfinite(t) && t > 0 && isfinite(m0) && isfinite(m1))
                snprintf(share, sizeof share, "%.3g", fabs(m1 - m0) / t);
        }
        if (!moved)
            continue;
        s->moved++;
        char b0[48], b1[48], d[48];
        fmt(b0, sizeof b0, m0, ab0);
        fmt(b1, sizeof b1, m1, ab1);
        if (isfinite(m0) && isfinite(m1)) snprintf(d, sizeof d, "%+.3g", m1 - m0);
        else snprintf(d, sizeof d, "—");
        fprintf(sec->moved, "| [%s](%s/report.md) | ", id, id);
        sf_md_text(sec->moved, q);
        fprintf(sec->moved, " | %s | %s | %s | %s | %s | %s |\n", kind, b0, b1, d, thr, share);
    }
    for (size_t k = 0; k < n1; k++)
        if (!used[k]) {
            s->rows_added++;
            fprintf(sec->rows, "| [%s](%s/report.md) | added | ", id, id);
            sf_md_text(sec->rows, str(json_array_get(r1, k), "quantity"));
            fprintf(sec->rows, " |\n");
        }
    free(used);
}

/* The Markdown with its case links pointing at report.html (the HTML
 * page sits beside the HTML reports); NULL when out of memory. */
static char *html_links(const char *md)
{
    static const char from[] = "/report.md)", to[] = "/report.html)";
    size_t n = 0;
    for (const char *p = md; (p = strstr(p, from)); p += sizeof from - 1)
        n++;
    char *out = malloc(strlen(md) + n * (sizeof to - sizeof from) + 1), *o = out;
    if (!out)
        return NULL;
    for (const char *p = md, *q; ; p = q + sizeof from - 1) {
        q = strstr(p, from);
        size_t k = q ? (size_t)(q - p) : strlen(p);
        memcpy(o, p, k);
        o += k;
        if (!q)
            break;
        memcpy(o, to, sizeof to - 1);
        o += sizeof to - 1;
    }
    *o = '\0';
    return out;
}

static char *take(FILE *f, char **buf)
{
    fclose(f);
    return *buf;
}

int sf_drift_write(const sf_baseline *bl, const char *root, sf_drift_summary *s,
                   char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    char path[1100];
    snprintf(path, sizeof path, "%s/results.json", root);
    json_error_t je;
    json_t *now = json_load_file(path, 0, &je);
    if (!now) {
        snprintf(err, errlen, "cannot read %s: %s", path, je.text);
        return SF_EIO;
    }
    json_t *c0s = json_object_get(bl->root, "cases"), *c1s = json_object_get(now, "cases");
    char *buf[6] = { 0 };
    size_t len[6];
    FILE *fs[6];
    for (int k = 0; k < 6; k++)
        if (!(fs[k] = open_memstream(&buf[k], &len[k]))) {
            for (int q = 0; q < k; q++) { fclose(fs[q]); free(buf[q]); }
            json_decref(now);
            snprintf(err, errlen, "open_memstream failed");
            return SF_EIO;
        }
    sections sec = { fs[0], fs[1], fs[2], fs[3], fs[4], fs[5] };
    size_t i;
    json_t *c1;
    json_array_foreach(c1s, i, c1) {
        const char *id = str(c1, "id");
        json_t *c0 = find_case(c0s, id);
        if (!c0) {
            s->added++;
            fprintf(sec.cases, "| [%s](%s/report.md) | added | %s |\n", id, id, str(c1, "verdict"));
            continue;
        }
        const char *v0 = str(c0, "verdict"), *v1 = str(c1, "verdict");
        if (strcmp(v0, v1)) {
            s->verdicts++;
            int worse = strcmp(v1, "pass") != 0 && !strcmp(v0, "pass");
            s->to_fail += worse;
            fprintf(sec.verdicts, "| [%s](%s/report.md) | %s | **%s** | ", id, id, v0, v1);
            sf_md_text(sec.verdicts, str(c1, "message"));
            fprintf(sec.verdicts, " |\n");
        }
        json_t *sd0 = json_object_get(c0, "seed"), *sd1 = json_object_get(c1, "seed");
        if (json_integer_value(sd0) != json_integer_value(sd1)) {
            s->seeds++;
            fprintf(sec.seeds, "| [%s](%s/report.md) | %lld | %lld |\n", id, id, (long long)json_integer_value(sd0),
                    (long long)json_integer_value(sd1));
        }
        /* CPU time when both runs have it (it does not depend much on
           the load of the machine), else wall time */
        int cpu = num(c0, "cpu_seconds", NULL) > 0 && num(c1, "cpu_seconds", NULL) > 0;
        const char *tk = cpu ? "cpu_seconds" : "seconds";
        double t0 = num(c0, tk, NULL), t1 = num(c1, tk, NULL);
        if (sf_drift_time_grew(t0, t1)) {
            s->slower++;
            fprintf(sec.slower, "| [%s](%s/report.md) | %s | %.2f | %.2f | %.1fx |\n", id, id, cpu ? "CPU" : "wall", t0, t1,
                    t0 > 0 ? t1 / t0 : INFINITY);
        }
        compare_rows(c0, c1, id, &sec, s);
    }
    json_t *c0;
    json_array_foreach(c0s, i, c0)
        if (!find_case(c1s, str(c0, "id"))) {
            s->removed++;
            fprintf(sec.cases, "| %s | not run now | %s |\n", str(c0, "id"), str(c0, "verdict"));
        }
    for (int k = 0; k < 6; k++)
        take(fs[k], &buf[k]);

    const char *bpath = json_string_value(json_object_get(json_object_get(now, "summary"), "baseline"));
    snprintf(s->baseline, sizeof s->baseline, "%s", bpath ? bpath : "?");
    char *md = NULL;
    size_t mdlen = 0;
    FILE *f = open_memstream(&md, &mdlen);
    int rc = SF_SUCCESS;
    if (!f) {
        snprintf(err, errlen, "open_memstream failed");
        rc = SF_EIO;
        goto out;
    }
    fprintf(f, "# Changed since baseline\n\n");
    fprintf(f, "- Baseline: `%s` (git %s, %zu cases); this run: git %s, %zu cases\n", s->baseline,
            str(bl->root, "git_revision"), json_array_size(c0s), str(now, "git_revision"), json_array_size(c1s));
    if (!sf_drift_any(s))
        fprintf(f, "- **No drift**: same verdicts, no metric moved beyond its round-off or sampling error, "
                   "no run time grew by more than 2x\n");
    else
        fprintf(f, "- %zu verdict change%s (%zu to FAIL or ERROR), %zu metric%s moved, %zu run time%s grew, "
                   "%zu case%s added, %zu removed, %zu row%s added, %zu removed, %zu seed%s differ\n",
                s->verdicts, s->verdicts == 1 ? "" : "s", s->to_fail, s->moved, s->moved == 1 ? "" : "s",
                s->slower, s->slower == 1 ? "" : "s", s->added, s->added == 1 ? "" : "s", s->removed,
                s->rows_added, s->rows_added == 1 ? "" : "s", s->rows_removed, s->seeds, s->seeds == 1 ? "" : "s");
    fprintf(f, "- Only a verdict that changed to FAIL or ERROR fails the run (it fails anyway); the rest is for review.\n\n");
    fprintf(f, "How a change is decided (cases matched by id, rows by quantity); each row against its own "
               "uncertainty (the threshold column):\n\n"
               "- *exact* rows (a tolerance or bound): the measured value moved by more than its round-off, "
               "|m1 - m0| > 10 eps max(|m0|, |m1|, |expected|, 1) with eps = 2.2e-16 (the 1: an error metric near "
               "zero still carries the round-off of its operands, which are of order one); in a case whose data "
               "pass through a chaotic trajectory (families dynamics, validation, plan, stress, limits), by more "
               "than that round-off amplified by the dynamics, 1e-6 max(|m0|, |m1|, |expected|, 1) (a change of "
               "round-off moves PV_x by about 1e-7 over 40 s). The last column gives the move as a share of the "
               "tolerance.\n"
               "- *statistical* rows (p-value against alpha): with the same seed in both runs the p-values come "
               "from the same draws, so they may move only as the exact rows do: |p1 - p0| > k max(p0, p1), k = "
               "10 eps or 1e-6 (chaotic); with different seeds the draws are independent, z = Phi^-1(1 - p) is "
               "N(0, 1) under the null hypothesis, two runs differ by N(0, 2), and a move counts when |z1 - z0| > "
               "2 sqrt(2) = %.2f.\n"
               "- *boolean* rows: any change. Run times: the CPU time of the case process (wall time when "
               "a run lacks it) grew by more than 2x and by more than 0.5 s.\n\n", Z_MOVE);
    if (s->verdicts)
        fprintf(f, "## Verdict changes\n\n| case | baseline | now | key metric now |\n|---|---|---|---|\n%s\n", buf[0]);
    if (s->moved)
        fprintf(f, "## Metrics that moved\n\n| case | quantity | kind | baseline | now | change | threshold (the row's uncertainty) | change / tolerance |\n"
                   "|---|---|---|---|---|---|---|---|\n%s\n", buf[1]);
    if (s->slower)
        fprintf(f, "## Run times that grew\n\n| case | time | baseline [s] | now [s] | ratio |\n|---|---|---|---|---|\n%s\n", buf[2]);
    if (s->added || s->removed)
        fprintf(f, "## Cases in one run only\n\n| case | | verdict |\n|---|---|---|\n%s\n", buf[3]);
    if (s->rows_added || s->rows_removed)
        fprintf(f, "## Rows in one run only\n\n| case | | quantity |\n|---|---|---|\n%s\n", buf[4]);
    if (s->seeds)
        fprintf(f, "## Seeds that differ\n\nTheir exact rows can move with the random stream alone.\n\n"
                   "| case | baseline | now |\n|---|---|---|\n%s\n", buf[5]);
    fclose(f);

    snprintf(path, sizeof path, "%s/drift.md", root);
    char tmp[1200];
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", path, (long)getpid());
    FILE *g = fopen(tmp, "w");
    if (!g || fputs(md, g) < 0 || fclose(g) != 0 || rename(tmp, path) != 0) {
        snprintf(err, errlen, "cannot write %s", path);
        unlink(tmp);
        rc = SF_EIO;
    } else {
        snprintf(path, sizeof path, "%s/drift.html", root);
        char *html_md = html_links(md);
        if (!html_md || sf_html_write(path, "slipfield: changed since baseline", html_md, err, errlen) != 0)
            rc = SF_EIO;
        free(html_md);
    }
    free(md);
out:
    for (int k = 0; k < 6; k++) free(buf[k]);
    json_decref(now);
    return rc;
}

int sf_drift_any(const sf_drift_summary *s)
{
    return s->verdicts || s->moved || s->slower || s->added || s->removed || s->rows_added ||
           s->rows_removed || s->seeds;
}

void sf_drift_index_line(FILE *f, const sf_drift_summary *s, const char *page)
{
    const char *link = strstr(page, ".html") ? "drift.html" : "drift.md";
    if (!sf_drift_any(s))
        fprintf(f, "- [Changed since baseline](%s): **no drift** against `%s`\n", link, s->baseline);
    else
        fprintf(f, "- [Changed since baseline](%s): %zu verdict change%s (%zu to FAIL or ERROR), "
                   "%zu metric%s moved, %zu run time%s grew (against `%s`)\n", link, s->verdicts,
                s->verdicts == 1 ? "" : "s", s->to_fail, s->moved, s->moved == 1 ? "" : "s", s->slower,
                s->slower == 1 ? "" : "s", s->baseline);
}
