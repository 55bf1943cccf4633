/* Unit tests: the paper's claims as data (result.h sf_claim) and their
 * trip through claims.tsv into the index section (paper.h). */
#include "test_util.h"
#include "result.h"
#include "report.h"
#include "paper.h"
#include "scene.h"

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
    assert_non_null(strstr(md, "1 confirmed, 1 contradicted, 0 not decidable"));
    free(md);
    sf_run_meta meta = { root, "fixed", "quick", 1.0, 0, NULL };
    char err[256] = "";
    assert_int_equal(sf_paper_report(&meta, &o, 1, err, sizeof err), 0);
    char p[160];
    snprintf(p, sizeof p, "%s/paper.md", root);
    f = fopen(p, "r");
    assert_non_null(f);
    char buf[8192];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    assert_non_null(strstr(buf, "ok-claim"));
    assert_non_null(strstr(buf, "bad-claim"));
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(claim_records_and_nan_is_undecided),
        cmocka_unit_test(claims_tsv_reach_the_index),
        cmocka_unit_test(contradicted_claims_say_why),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
