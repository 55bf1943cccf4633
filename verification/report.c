/* The report writers (report.h): each case's report and plots, a crashed
 * case's page, and the run's index, written under temporary names. */
#include "report.h"
#include "drift.h"
#include "html.h"
#include "results.h"
#include "paper.h"
#include "prose.h"
#include "sf_error.h"
#include "version.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <fftw3.h>
#include <gsl/gsl_version.h>

static const char *vv_name(int vv)
{
    return vv == 0 ? "code verification" : vv == 1 ? "solution verification" : "validation";
}

int sf_mkdirs(const char *path)
{
    char buf[1024];
    if (strlen(path) >= sizeof buf)
        return -1;
    strcpy(buf, path);
    for (char *p = buf + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return -1;
    return 0;
}

/* Remove the regular files of a directory we own, then the directory. */
static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    char p[1200];
    while ((e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        unlink(p);
    }
    closedir(d);
    rmdir(dir);
}

static void fmt_num(char *buf, size_t n, double x)
{
    if (isnan(x))
        snprintf(buf, n, "—");
    else
        snprintf(buf, n, "%.6g", x);
}

/* A one-case run in its own folder: into the run's own root it would
 * replace the index and results.json with a one-case summary. */
static void write_rerun(FILE *f, const sf_case *c)
{
    fprintf(f, "- Re-run: `build/slipfield verify %s --reports reports/rerun` (its report: "
               "`reports/rerun/%s/report.md`)\n", c->path, c->id);
}

/* Write into <root>/<family>/.<name>.tmpPID, then swap it in.  `fresh`
 * empties it first; otherwise what sf_report_plots staged there stays. */
static int open_tmp_dir(const char *root, const char *id, char *tmp, size_t tn,
                        char *fin, size_t fn, int fresh)
{
    const char *slash = strchr(id, '/');
    snprintf(fin, fn, "%s/%s", root, id);
    snprintf(tmp, tn, "%s/%.*s/.%s.tmp%ld", root, (int)(slash - id), id, slash + 1, (long)getpid());
    if (fresh)
        remove_dir(tmp);
    return sf_mkdirs(tmp);
}

static int commit_dir(const char *tmp, const char *fin)
{
    remove_dir(fin);
    return rename(tmp, fin);
}

/* Write a Markdown buffer as <dir>/report.md and render <dir>/report.html
 * from the same text. */
static int write_md_and_html(const char *dir, const char *title, const char *md,
                             char *err, size_t errlen)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/report.md", dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        return SF_EIO;
    }
    fputs(md, f);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        snprintf(err, errlen, "error writing %s", path);
        return SF_EIO;
    }
    snprintf(path, sizeof path, "%s/report.html", dir);
    return sf_html_write(path, title, md, err, errlen) == 0 ? SF_SUCCESS : SF_EIO;
}

/* The opening block a reviewer reads first (docs/reports.md): Claim, Why,
 * Test (the case's test and tolerance paragraphs, then the check, its
 * tolerance and its rows' criteria), Result; then the case's identity.  r
 * is NULL for a case that did not complete. */
static void write_header(FILE *f, const sf_case *c, const sf_result *r, const sf_outcome *o,
                         const sf_prose *p)
{
    fprintf(f, "# %s\n\n", c->title);
    if (*p->claim)
        fprintf(f, "%s%s\n", p->claim_labelled ? "" : "**Claim.** ", p->claim);
    if (p->why)
        fprintf(f, "%s\n", p->why);
    if (p->test)
        fprintf(f, "%s\n", p->test);
    if (p->tolerance)
        fprintf(f, "%s\n", p->tolerance);
    double alpha = sf_case_spec_declared_alpha(&c->spec);
    fprintf(f, "%s `%s`", p->test || p->tolerance ? "**Check.**" : "**Test.**", c->spec.check);
    if (c->spec.tolerance != 0 || alpha <= 0)
        fprintf(f, ", tolerance = %g", c->spec.tolerance);
    if (alpha > 0)
        fprintf(f, ", alpha = %g", alpha);
    size_t nrows = r ? sf_result_nrows(r) : 0, shown = 0;
    if (nrows) {
        enum { MAX_SHOWN = 6 };
        fprintf(f, "; %zu row%s, criteria: ", nrows, nrows == 1 ? "" : "s");
        size_t distinct = 0;
        for (size_t i = 0; i < nrows; i++) {
            const char *ci = sf_result_row(r, i)->criterion;
            int seen = 0;
            for (size_t j = 0; j < i && !seen; j++)
                seen = !strcmp(sf_result_row(r, j)->criterion, ci);
            if (seen)
                continue;
            if (shown < MAX_SHOWN) {
                fputs(shown ? "; " : "", f);
                sf_md_text(f, ci);
                shown++;
            }
            distinct++;
        }
        if (distinct > shown)
            fprintf(f, "; and %zu more (the results table)", distinct - shown);
    }
    fprintf(f, ".\n\n**Result.** **%s**: ", sf_verdict_name(o->verdict));
    sf_md_text(f, o->key);
    size_t at = 0;
    double m = r ? sf_result_margin(r, &at) : NAN;
    if (isinf(m))
        fprintf(f, ". Margin inf (a non-finite value)");
    else if (!isnan(m))
        fprintf(f, ". Margin %.3g%s (results row %zu; above 1 fails)", m,
                o->verdict == SF_VERDICT_PASS && m >= SF_NEAR_EDGE ? ", *near the edge*" : "", at + 1);
    fprintf(f, "; seed %lu; %.3f s.\n\n", o->seed, o->seconds);
    fprintf(f, "- Case: `%s` (`%s`)\n", c->id, c->path);
    fprintf(f, "- Kind: %s; tier: %s; check: `%s`\n", vv_name(c->spec.vv),
            sf_case_enum_name("tier", c->spec.tier), c->spec.check);
    write_rerun(f, c);
    fputc('\n', f);
}

/* After the evidence: the rest of the prose, the scene, the notes after
 * it, and the history (prose.h says which paragraphs are which). */
static void write_tail(FILE *f, const sf_case *c, const sf_prose *p)
{
    if (*p->rest_before)
        fprintf(f, "## The case in full\n\n%s\n", p->rest_before);
    fprintf(f, "## Scene\n\n```scene\n%s```\n\n", c->scene_text);
    if (*p->rest_after)
        fprintf(f, "## Notes from the case\n\n%s\n", p->rest_after);
    if (*p->history)
        fprintf(f, "## History and studies\n\n%s\n", p->history);
}

/* A report's Markdown in memory, and the case's prose in its parts
 * (prose.h); NULL with err set when either fails. */
static FILE *open_report(const sf_case *c, sf_prose *p, char **md, size_t *mdlen, char *err, size_t errlen)
{
    if (sf_prose_split(p, c->prose_before, c->prose_after) != 0) {
        snprintf(err, errlen, "out of memory splitting the prose of %s", c->id);
        return NULL;
    }
    FILE *f = open_memstream(md, mdlen);
    if (!f) {
        snprintf(err, errlen, "open_memstream: %s", strerror(errno));
        sf_prose_free(p);
    }
    return f;
}

int sf_report_plots(const char *root, const sf_case *c, sf_result *r, char *err, size_t errlen)
{
    char tmp[1024], fin[1024];
    if (open_tmp_dir(root, c->id, tmp, sizeof tmp, fin, sizeof fin, 1) != 0) {
        snprintf(err, errlen, "cannot create %s: %s", tmp, strerror(errno));
        return SF_EIO;
    }
    return sf_result_render_plots(r, tmp, err, errlen) < 0 ? SF_EIO : SF_SUCCESS;
}

/* The sweep's statistics per point and QoI (result.h: sf_sweep_row), as
 * results.json carries them. */
static void write_sweep_table(FILE *f, const sf_result *r)
{
    if (!sf_result_nsweep(r))
        return;
    fprintf(f, "## Sweep statistics\n\nPer point and QoI: the realisations used / excluded (a value the QoI's "
               "definition cannot form is excluded, never averaged), the mean, std (n - 1), Monte Carlo standard "
               "error, the Student confidence interval, and u_num, the numerical error of the mean (companion solves "
               "at a coarser setting on the first realisations: how many are given; — where not estimated).\n\n"
               "| point | QoI | used / excluded | mean | std | se | interval | u_num of the mean (on) |\n"
               "|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sf_result_nsweep(r); i++) {
        const sf_sweep_row *x = sf_result_sweep_at(r, i);
        char v[5][48];
        fmt_num(v[0], sizeof v[0], x->mean);
        fmt_num(v[1], sizeof v[1], x->std);
        fmt_num(v[2], sizeof v[2], x->se);
        fmt_num(v[3], sizeof v[3], x->ci_lo);
        fmt_num(v[4], sizeof v[4], x->ci_hi);
        fputs("| ", f);
        sf_md_text(f, x->param);
        fprintf(f, " = %g | ", x->value);
        sf_md_text(f, x->qoi);
        fprintf(f, " [%s] | %zu / %zu | %s | %s | %s | [%s, %s] (%g%%) | ", x->unit, x->n_used, x->n_excluded, v[0],
                v[1], v[2], v[3], v[4], 100 * x->level);
        if (x->u_num_subset && isfinite(x->u_num))
            fprintf(f, "%.3g (%zu of realisations 0-%zu) |\n", x->u_num, x->u_num_used, x->u_num_subset - 1);
        else
            fprintf(f, "— |\n");
    }
    fputc('\n', f);
}

int sf_report_case(const char *root, const sf_case *c, const sf_result *r,
                   const sf_outcome *o, const char *error, char *err, size_t errlen)
{
    char tmp[1024], fin[1024];
    if (open_tmp_dir(root, c->id, tmp, sizeof tmp, fin, sizeof fin, 0) != 0) {
        snprintf(err, errlen, "cannot create %s: %s", tmp, strerror(errno));
        return SF_EIO;
    }
    char *md = NULL;
    size_t mdlen = 0;
    sf_prose p;
    FILE *f = open_report(c, &p, &md, &mdlen, err, errlen);
    if (!f)
        return SF_EIO;
    write_header(f, c, r, o, &p);
    fprintf(f, "## Results\n\n| quantity | measured | expected | criterion | pass |\n|---|---|---|---|---|\n");
    for (size_t i = 0; i < sf_result_nrows(r); i++) {
        const sf_row *row = sf_result_row(r, i);
        char m[48], e[48];
        fmt_num(m, sizeof m, row->measured);
        fmt_num(e, sizeof e, row->expected);
        fputs("| ", f);
        sf_md_text(f, row->quantity);
        fprintf(f, " | %s | %s | ", m, e);
        sf_md_text(f, row->criterion);
        fprintf(f, " | %s |\n", row->pass ? "yes" : "**no**");
    }
    if (sf_result_nrows(r) == 0)
        fprintf(f, "| (no check row was produced: the case cannot pass) | | | | **no** |\n");
    fputc('\n', f);
    if (error && *error)
        fprintf(f, "**Error:** %s\n\n", error);
    write_sweep_table(f, r);
    sf_paper_case_claims(f, r);
    if (*sf_result_notes(r))
        fprintf(f, "## Findings\n\n%s\n", sf_result_notes(r));
    if (sf_result_nplots(r)) {
        fprintf(f, "## Plots\n\n");
        for (size_t i = 0; i < sf_result_nplots(r); i++) {
            const sf_plot *p = sf_result_get_plot(r, i);
            char png[1200];
            snprintf(png, sizeof png, "%s/%s.png", tmp, sf_plot_stem(p));
            if (access(png, F_OK) == 0)
                fprintf(f, "![%s](%s.png)\n\n", sf_plot_title(p), sf_plot_stem(p));
            else
                fprintf(f, "**Plot `%s` was not rendered** (see the error above).\n\n", sf_plot_stem(p));
        }
    }
    write_tail(f, c, &p);
    sf_prose_free(&p);
    fclose(f);
    int rc = write_md_and_html(tmp, c->title, md, err, errlen);
    free(md);
    if (rc == SF_SUCCESS)
        rc = sf_results_case_write(tmp, c, r, o, err, errlen);
    if (rc)
        return rc;
    if (sf_paper_write_tsv(tmp, r) != 0) {
        snprintf(err, errlen, "cannot write %s/claims.tsv", tmp);
        return SF_EIO;
    }
    if (commit_dir(tmp, fin) != 0) {
        snprintf(err, errlen, "cannot rename %s to %s: %s", tmp, fin, strerror(errno));
        return SF_EIO;
    }
    return SF_SUCCESS;
}

int sf_report_crash(const char *root, const sf_case *c, const sf_outcome *o,
                    char *err, size_t errlen)
{
    char tmp[1024], fin[1024];
    if (open_tmp_dir(root, c->id, tmp, sizeof tmp, fin, sizeof fin, 1) != 0) {
        snprintf(err, errlen, "cannot create %s", tmp);
        return SF_EIO;
    }
    char *md = NULL;
    size_t mdlen = 0;
    sf_prose p;
    FILE *f = open_report(c, &p, &md, &mdlen, err, errlen);
    if (!f)
        return SF_EIO;
    write_header(f, c, NULL, o, &p);
    fprintf(f, "## Results\n\n**The case did not complete:** %s\n\n", o->key);
    write_tail(f, c, &p);
    sf_prose_free(&p);
    fclose(f);
    int rc = write_md_and_html(tmp, c->title, md, err, errlen);
    free(md);
    if (rc == SF_SUCCESS)
        rc = sf_results_case_write(tmp, c, NULL, o, err, errlen);
    if (rc)
        return rc;
    return commit_dir(tmp, fin) == 0 ? SF_SUCCESS : SF_EIO;
}

static void xml_escape(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&apos;", f); break;
        default:
            if ((unsigned char)*s >= 32 || *s == '\n' || *s == '\t')
                fputc(*s, f);
        }
    }
}

static FILE *open_tmp(const char *fin, char *tmp, size_t n)
{
    snprintf(tmp, n, "%s.tmp%ld", fin, (long)getpid());
    return fopen(tmp, "w");
}

static void write_index(FILE *f, const sf_run_meta *meta, const sf_outcome *o, size_t n,
                        size_t np, size_t nf, size_t ne, const char *page)
{
    fprintf(f, "# slipfield verification report\n\n");
    sf_paper_index_tally(f, meta->root, o, n, strcmp(page, "report.html") == 0);
    fprintf(f, "- Cases: **%zu passed**, %zu failed, %zu errors, %zu skipped (of %zu selected)\n",
            np, nf, ne, meta->skipped, n + meta->skipped);
    fprintf(f, "- Tier: %s; seeds: %s; total wall time: %.1f s; CPU time of the cases: %.1f s\n", meta->tier_name,
            meta->seed_note, meta->total_seconds, sf_outcome_cpu_total(o, n));
    fprintf(f, "- slipfield %s (git %s); GSL %s; %s\n", SF_VERSION, SF_GIT_REV, GSL_VERSION, fftw_version);
    size_t nedge = 0;
    for (size_t i = 0; i < n; i++)
        nedge += o[i].near_edge != 0;
    fprintf(f, "- Margin: the share of its tolerance the case's tightest row uses (measured / tolerance, "
               "or alpha / p); above 1 fails. %zu passing case%s within %.0f%% of the tolerance %s "
               "flagged *near the edge* (not a failure).\n", nedge, nedge == 1 ? "" : "s",
            100 * (1 - SF_NEAR_EDGE), nedge == 1 ? "is" : "are");
    fprintf(f, "- Machine-readable: [results.json](results.json) (schema: `verification/results.schema.json`)\n");
    if (meta->drift)
        sf_drift_index_line(f, meta->drift, page);
    fprintf(f, "\n| case | family | kind | verdict | margin | key metric (measured, criterion) | time [s] |\n"
               "|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < n; i++) {
        char m[64];
        if (isnan(o[i].margin)) snprintf(m, sizeof m, "—");
        else if (isinf(o[i].margin)) snprintf(m, sizeof m, "inf");
        else snprintf(m, sizeof m, "%.3g", o[i].margin);
        fprintf(f, "| [%s](%s/%s) | %s | %s | **%s** | %s%s | ", o[i].id, o[i].id, page, o[i].family,
                vv_name(o[i].vv), sf_verdict_name(o[i].verdict), m, o[i].near_edge ? " *near the edge*" : "");
        sf_md_text(f, o[i].key);
        fprintf(f, " | %.2f |\n", o[i].seconds);
    }
    sf_budget_index_section(f, meta->tier_name, o, n, page);
    sf_paper_index_section(f, meta->root, o, n, strcmp(page, "report.html") == 0);
}

int sf_report_index(const sf_run_meta *meta, const sf_outcome *o, size_t n,
                    char *err, size_t errlen)
{
    size_t np = 0, nf = 0, ne = 0;
    for (size_t i = 0; i < n; i++) {
        if (o[i].verdict == SF_VERDICT_PASS) np++;
        else if (o[i].verdict == SF_VERDICT_FAIL) nf++;
        else ne++;
    }
    char fin[1024], tmp[1100];
    /* The same index twice: Markdown with links to report.md, and the HTML
     * page rendered from a copy whose links point at report.html. */
    for (int html = 0; html < 2; html++) {
        char *md = NULL;
        size_t mdlen = 0;
        FILE *f = open_memstream(&md, &mdlen);
        if (!f) {
            snprintf(err, errlen, "open_memstream failed");
            return SF_EIO;
        }
        write_index(f, meta, o, n, np, nf, ne, html ? "report.html" : "report.md");
        fclose(f);
        int rc = 0;
        if (html) {
            snprintf(fin, sizeof fin, "%s/index.html", meta->root);
            rc = sf_html_write(fin, "slipfield verification report", md, err, errlen);
        } else {
            snprintf(fin, sizeof fin, "%s/index.md", meta->root);
            FILE *g = open_tmp(fin, tmp, sizeof tmp);
            if (!g) {
                rc = -1;
            } else {
                fputs(md, g);
                rc = (fclose(g) != 0 || rename(tmp, fin) != 0) ? -1 : 0;
            }
            if (rc)
                snprintf(err, errlen, "cannot write %s", fin);
        }
        free(md);
        if (rc)
            return SF_EIO;
    }

    FILE *f;
    snprintf(fin, sizeof fin, "%s/junit.xml", meta->root);
    f = open_tmp(fin, tmp, sizeof tmp);
    if (!f) {
        snprintf(err, errlen, "cannot write %s", tmp);
        return SF_EIO;
    }
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f, "<testsuites name=\"slipfield verify\" tests=\"%zu\" failures=\"%zu\" errors=\"%zu\" time=\"%.3f\">\n",
            n, nf, ne, meta->total_seconds);
    /* one testsuite per family, in order of first appearance */
    for (size_t i = 0; i < n; i++) {
        int seen = 0;
        for (size_t j = 0; j < i; j++)
            if (!strcmp(o[j].family, o[i].family)) seen = 1;
        if (seen)
            continue;
        size_t t = 0, fl = 0, er = 0;
        double secs = 0;
        for (size_t j = i; j < n; j++)
            if (!strcmp(o[j].family, o[i].family)) {
                t++;
                fl += o[j].verdict == SF_VERDICT_FAIL;
                er += o[j].verdict == SF_VERDICT_ERROR;
                secs += o[j].seconds;
            }
        fprintf(f, "  <testsuite name=\"");
        xml_escape(f, o[i].family);
        fprintf(f, "\" tests=\"%zu\" failures=\"%zu\" errors=\"%zu\" skipped=\"0\" time=\"%.3f\">\n", t, fl, er, secs);
        for (size_t j = i; j < n; j++) {
            if (strcmp(o[j].family, o[i].family))
                continue;
            fprintf(f, "    <testcase classname=\"slipfield.");
            xml_escape(f, o[j].family);
            fprintf(f, "\" name=\"");
            xml_escape(f, o[j].id);
            fprintf(f, "\" time=\"%.3f\"", o[j].seconds);
            if (o[j].verdict == SF_VERDICT_PASS) {
                fprintf(f, "/>\n");
                continue;
            }
            fprintf(f, ">\n      <%s message=\"", o[j].verdict == SF_VERDICT_FAIL ? "failure" : "error");
            xml_escape(f, o[j].key);
            fprintf(f, "\" type=\"%s\">", o[j].verdict == SF_VERDICT_FAIL ? "CheckFailed" : "CaseError");
            xml_escape(f, o[j].key);
            fprintf(f, "\nSee %s/%s/report.md</%s>\n    </testcase>\n", meta->root, o[j].id,
                    o[j].verdict == SF_VERDICT_FAIL ? "failure" : "error");
        }
        fprintf(f, "  </testsuite>\n");
    }
    fprintf(f, "</testsuites>\n");
    if (fclose(f) != 0 || rename(tmp, fin) != 0) {
        snprintf(err, errlen, "cannot write %s", fin);
        return SF_EIO;
    }
    return SF_SUCCESS;
}
