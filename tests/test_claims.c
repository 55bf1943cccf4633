/* Unit tests: the paper's claims as data (result.h sf_claim), their
 * trip through claims.tsv into the index (paper.h), the escaping of
 * generated text in the Markdown they are written into (html.h), and the
 * sweep rows the claims cases report with the exact recomputation that
 * gates them (checks/common.h). */
#include "test_util.h"
#include "result.h"
#include "report.h"
#include "paper.h"
#include "html.h"
#include "scene.h"
#include "sweep.h"
#include "checks/common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void claim_records_and_nan_is_undecided(void **state)
{
    (void)state;
    sf_result *r = sf_result_alloc();
    sf_claim(r, "a", "text a", SF_CLAIM_CONFIRMED, 0.2, 0.18, 0.22, 0.01, "how", "note");
    sf_claim_defs(r, "DEPENDS ON THE DEFINITION: t_skip 0: contradicted");
    /* a NaN estimate cannot confirm or contradict anything */
    sf_claim(r, "b", "text b", SF_CLAIM_CONTRADICTED, NAN, NAN, NAN, 0.01, NULL, NULL);
    assert_int_equal(sf_result_nclaims(r), 2);
    const sf_claim_row *a = sf_result_claim(r, 0), *b = sf_result_claim(r, 1);
    assert_string_equal(a->id, "a");
    assert_int_equal(a->status, SF_CLAIM_CONFIRMED);
    assert_true(strstr(a->defs, "DEPENDS") == a->defs);
    assert_int_equal(b->status, SF_CLAIM_UNDECIDED);
    assert_string_equal(sf_claim_status_name(SF_CLAIM_CONTRADICTED), "contradicted");
    /* claims are not rows: a result with claims only has no row */
    assert_int_equal(sf_result_nrows(r), 0);
    sf_result_free(r);
}

static void claims_tsv_reach_the_index(void **state)
{
    (void)state;
    char root[] = "/tmp/sf-claims-XXXXXX";
    assert_non_null(mkdtemp(root));
    char dir[128];
    snprintf(dir, sizeof dir, "%s/validation", root);
    assert_int_equal(sf_mkdirs(dir), 0);
    snprintf(dir, sizeof dir, "%s/validation/x", root);
    assert_int_equal(sf_mkdirs(dir), 0);
    sf_result *r = sf_result_alloc();
    sf_claim(r, "ok-claim", "holds\twith a tab", SF_CLAIM_CONFIRMED, 1, 0.9, 1.1, 0.01, "t", "");
    sf_claim(r, "bad-claim", "fails | with a bar", SF_CLAIM_CONTRADICTED, 1.46, 1.3, 1.6, 0.01, "t", "why");
    /* a verdict about the model on the first (the second has none) */
    sf_claim_model mv = { SF_CLAIM_WITHIN, 400, 800, 0.995, 0.985, 1.005, 0.012, 0.01, 0.02 };
    sf_claim_set_model(r, "ok-claim", &mv);
    assert_int_equal(sf_result_claim(r, 1)->model.status, -1);
    assert_int_equal(sf_paper_write_tsv(dir, r), 0);
    sf_outcome o;
    memset(&o, 0, sizeof o);
    snprintf(o.id, sizeof o.id, "validation/x");
    snprintf(o.title, sizeof o.title, "X");
    char *md = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&md, &len);
    sf_paper_index_section(f, root, &o, 1, 0);
    fclose(f);
    /* the contradicted claim is listed, the confirmed one only counted */
    assert_non_null(strstr(md, "bad-claim"));
    assert_non_null(strstr(md, "fails \\| with a bar"));
    assert_null(strstr(md, "ok-claim"));
    free(md);
    /* the tally the index opens with: a zero count is not emphasised (the
     * HTML colours emphasised verdict words) */
    f = open_memstream(&md, &len);
    sf_paper_index_tally(f, root, &o, 1, 1);
    fclose(f);
    assert_non_null(strstr(md, "(2): **1 confirmed**, **1 contradicted**, 0 not decidable"));
    /* the model verdict's trip through claims.tsv: counted apart */
    assert_non_null(strstr(md, "0 confirmed, 0 contradicted, **1 within margin**, 0 without a verdict (budget "
                               "reached), 1 not run"));
    assert_non_null(strstr(md, "[paper.html](paper.html)"));
    free(md);
    sf_run_meta meta = { root, "fixed", "quick", 1.0, 0, NULL };
    char err[256] = "";
    assert_int_equal(sf_paper_report(&meta, &o, 1, err, sizeof err), 0);
    char p[160];
    snprintf(p, sizeof p, "%s/paper.md", root);
    f = fopen(p, "r");
    assert_non_null(f);
    char buf[65536];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    assert_non_null(strstr(buf, "ok-claim"));
    assert_non_null(strstr(buf, "bad-claim"));
    assert_non_null(strstr(buf, "**within margin** at N = 400 (0.995 [0.985, 1.005]); MDE 0.012; margin 0.02"));
    assert_non_null(strstr(buf, "**Tally** (2 claims)"));
    sf_result_free(r);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s", root);
    assert_int_equal(system(cmd), 0);
}

/* A contradicted claim always carries a reason in the tables: its note,
 * however long (a note of 700 characters survives claims.tsv whole), or a
 * flag that none was recorded. */
static void contradicted_claims_say_why(void **state)
{
    (void)state;
    char root[] = "/tmp/sf-claims-XXXXXX";
    assert_non_null(mkdtemp(root));
    char dir[128];
    snprintf(dir, sizeof dir, "%s/validation/y", root);
    assert_int_equal(sf_mkdirs(dir), 0);
    char longnote[701];
    for (int i = 0; i < 700; i++)
        longnote[i] = (char)('a' + i % 26);
    longnote[699] = 'Z';
    longnote[700] = '\0';
    sf_result *r = sf_result_alloc();
    sf_claim(r, "silent", "no note", SF_CLAIM_CONTRADICTED, 2, 1.9, 2.1, 0.01, "t", NULL);
    sf_claim(r, "verbose", "long note", SF_CLAIM_CONTRADICTED, 2, 1.9, 2.1, 0.01, "t", longnote);
    assert_int_equal(sf_paper_write_tsv(dir, r), 0);
    sf_outcome o;
    memset(&o, 0, sizeof o);
    snprintf(o.id, sizeof o.id, "validation/y");
    char *md = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&md, &len);
    sf_paper_index_section(f, root, &o, 1, 0);
    fclose(f);
    assert_non_null(strstr(md, "no explanation recorded"));
    assert_non_null(strstr(md, longnote));
    free(md);
    sf_result_free(r);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s", root);
    assert_int_equal(system(cmd), 0);
}

/* Text a check generates is literal in Markdown: a star in a path is no
 * emphasis, a tag no HTML, a bar no cell break; what cannot change the
 * rendering (PV_x, p <= alpha) is left readable. */
static void generated_text_stays_literal(void **state)
{
    (void)state;
    static const struct { const char *in, *out; } t[] = {
        { "cases/dynamics/*, cases/deterministic/*", "cases/dynamics/\\*, cases/deterministic/\\*" },
        { "PV_x and mu_s", "PV_x and mu_s" },
        { "_lead and trail_", "\\_lead and trail\\_" },
        { "p <= 1e-3 | x < 2", "p <= 1e-3 \\| x < 2" },
        { "<b>bold</b> & &amp; [link](x) `code`", "\\<b>bold\\</b> & \\&amp; [link\\](x) \\`code\\`" },
        { "T [N m], [a][b], [c]: d", "T [N m], [a\\][b], [c\\]: d" },
        { "two\nlines\tand a tab", "two lines and a tab" },
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        char *md = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&md, &len);
        sf_md_text(f, t[i].in);
        fclose(f);
        assert_string_equal(md, t[i].out);
        free(md);
    }
}

/* The HTML colours a claim's verdict like a case's: confirmed and passed
 * as PASS, contradicted as FAIL, not decidable as ERROR; other bold text
 * stays plain. */
static void verdicts_are_coloured(void **state)
{
    (void)state;
    char path[] = "/tmp/sf-colour-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    char err[256] = "";
    assert_int_equal(sf_html_write(path, "t", "**3 confirmed**, **1 contradicted**, **2 not decidable**, **PASS**, "
                                              "**4 passed**, **Error:** x\n", err, sizeof err), 0);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char buf[65536];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    unlink(path);
    assert_non_null(strstr(buf, "<strong class=\"pass\">3 confirmed</strong>"));
    assert_non_null(strstr(buf, "<strong class=\"fail\">1 contradicted</strong>"));
    assert_non_null(strstr(buf, "<strong class=\"error\">2 not decidable</strong>"));
    assert_non_null(strstr(buf, "<strong class=\"pass\">PASS</strong>"));
    assert_non_null(strstr(buf, "<strong class=\"pass\">4 passed</strong>"));
    assert_non_null(strstr(buf, "<strong>Error:</strong>"));
}

/* A sweep row as the claims cases record it (sf_sweep_stat_of, no u_num)
 * agrees with its recomputation from the values to round-off; an se or an
 * interval end 6% off, or a count off by one, does not. */
static void sweep_rows_recomputed_exactly(void **state)
{
    (void)state;
    const double x[6] = { 1.1, 0.9, NAN, 1.3, 1.05, 0.97 };
    double buf[6];
    sf_sweep_stat st;
    assert_int_equal(sf_sweep_stat_of(x, 1, 6, &st), SF_SUCCESS);
    sf_result *r = sf_result_alloc();
    check_sweep_stat_record(r, "l_over_R", 1, "pv_x_ratio", "-", &st, NULL);
    assert_int_equal(sf_result_nsweep(r), 1);
    sf_sweep_row row = *sf_result_sweep_at(r, 0);
    assert_string_equal(row.qoi, "pv_x_ratio");
    assert_int_equal(row.n_used, 5);
    assert_int_equal(row.n_excluded, 1);
    assert_close(row.level, SF_SWEEP_CI_LEVEL, 0);
    assert_true(isnan(row.u_num));
    assert_int_equal(row.u_num_subset, 0);
    assert_true(check_sweep_row_off(&row, x, 1, 6, buf) <= 1);
    sf_sweep_row bad = row;
    bad.se *= 1.06;
    assert_true(check_sweep_row_off(&bad, x, 1, 6, buf) > 1);
    bad = row;
    bad.ci_hi = row.mean + 1.06 * (row.ci_hi - row.mean);
    assert_true(check_sweep_row_off(&bad, x, 1, 6, buf) > 1);
    bad = row;
    bad.n_used--;
    assert_true(isinf(check_sweep_row_off(&bad, x, 1, 6, buf)));
    /* a value the row left out: the mean moves */
    const double y[6] = { 1.1, 0.9, 1.2, 1.3, 1.05, 0.97 };
    assert_true(check_sweep_row_off(&row, y, 1, 6, buf) > 1);
    sf_result_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(claim_records_and_nan_is_undecided),
        cmocka_unit_test(claims_tsv_reach_the_index),
        cmocka_unit_test(contradicted_claims_say_why),
        cmocka_unit_test(generated_text_stays_literal),
        cmocka_unit_test(verdicts_are_coloured),
        cmocka_unit_test(sweep_rows_recomputed_exactly),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
