/* Unit tests: a case report's layout (verification/prose.c, report.c):
 * the opening block Claim, Why, Test, Result in that order, the rest of
 * the prose after the evidence, the history at the end; a case without a
 * **Claim** paragraph opens with its first paragraph. */
#include "test_util.h"
#include "case.h"
#include "prose.h"
#include "report.h"
#include "result.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void prose_parts(void **state)
{
    (void)state;
    const char *before =
        "**Claim.** It holds.\n"
        "Second line.\n\n"
        "**Why.** Because.\n\n"
        "**What would break it.** A defect.\n\n"
        "**Tolerance.** 1e-12:\n\n"
        "- round-off\n"
        "- nothing else\n\n"
        "```text\na fence\n\nwith a blank line\n```\n\n"
        "## History\n\n"
        "Measured at seeds 1..80 in 2026-11.\n\n"
        "### An earlier design\n\n"
        "It was slower.\n\n"
        "## Limits\n\n"
        "**History.** A labelled paragraph.\n\n"
        "It stays in the rest.\n";
    const char *after = "\nA note after the scene.\n\n**The test.** Late, but found.\n";
    sf_prose p;
    assert_int_equal(sf_prose_split(&p, before, after), 0);
    assert_true(p.claim_labelled);
    assert_string_equal(p.claim, "**Claim.** It holds.\nSecond line.\n");
    assert_string_equal(p.why, "**Why.** Because.\n");
    /* the list after the tolerance paragraph goes with it */
    assert_string_equal(p.tolerance, "**Tolerance.** 1e-12:\n\n- round-off\n- nothing else\n");
    assert_string_equal(p.test, "**The test.** Late, but found.\n");
    /* a fence is one block; the history section ends at ## Limits */
    assert_string_equal(p.rest_before, "**What would break it.** A defect.\n\n"
                                       "```text\na fence\n\nwith a blank line\n```\n\n"
                                       "## Limits\n\nIt stays in the rest.\n");
    assert_string_equal(p.rest_after, "A note after the scene.\n");
    assert_string_equal(p.history, "Measured at seeds 1..80 in 2026-11.\n\n### An earlier design\n\n"
                                   "It was slower.\n\n**History.** A labelled paragraph.\n");
    sf_prose_free(&p);

    /* no **Claim**: the first paragraph, not a heading; no why, test, tolerance */
    assert_int_equal(sf_prose_split(&p, "## A heading\n\nFirst paragraph.\n\nSecond.\n", NULL), 0);
    assert_false(p.claim_labelled);
    assert_string_equal(p.claim, "First paragraph.\n");
    assert_null(p.why);
    assert_null(p.test);
    assert_null(p.tolerance);
    assert_string_equal(p.rest_before, "## A heading\n\nSecond.\n");
    assert_string_equal(p.history, "");
    sf_prose_free(&p);

    /* no prose at all */
    assert_int_equal(sf_prose_split(&p, NULL, ""), 0);
    assert_string_equal(p.claim, "");
    assert_string_equal(p.rest_after, "");
    sf_prose_free(&p);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return buf;
}

/* the position of s in md, failing when absent */
static long at(const char *md, const char *s)
{
    const char *p = strstr(md, s);
    if (!p) {
        print_error("'%s' not in the report\n", s);
        fail();
    }
    return (long)(p - md);
}

static void write_report(const char *root, const char *text, const char *id_path, char *md, size_t n)
{
    sf_case c;
    char err[512];
    memset(&c, 0, sizeof c);
    assert_int_equal(sf_case_parse(&c, id_path, text, strlen(text), err, sizeof err), SF_SUCCESS);
    sf_result *r = sf_result_alloc();
    sf_check_le(r, "error", 0.5, 1.0);
    sf_outcome o;
    memset(&o, 0, sizeof o);
    o.verdict = SF_VERDICT_PASS;
    o.seed = c.scene.seed;
    o.seconds = 0.25;
    snprintf(o.key, sizeof o.key, "error = 0.5 (<= 1)");
    assert_int_equal(sf_report_case(root, &c, r, &o, NULL, err, sizeof err), SF_SUCCESS);
    char path[1200];
    snprintf(path, sizeof path, "%s/%s/report.md", root, c.id);
    snprintf(md, n, "%s", slurp(path));
    sf_result_free(r);
    sf_case_free(&c);
}

static void report_layout(void **state)
{
    (void)state;
    char root[] = "/tmp/sf-report-test.XXXXXX";
    assert_non_null(mkdtemp(root));
    static char md[1 << 16];
    const char *text =
        "# A case\n\n"
        "**Claim.** The claim.\n\n"
        "**Why.** The reason.\n\n"
        "**Oracle.** Stays in the rest.\n\n"
        "**Tolerance.** 1e-12, round-off.\n\n"
        "## History\n\n"
        "Fresh seeds 1..40, all pass (2026-11-30).\n\n"
        "```scene\ncheck = field_exact_covariance\nnx = 8\nny = 8\nl = 0.1\ntolerance = 1e-12\n```\n\n"
        "After the scene.\n";
    write_report(root, text, "cases/demo/layout.md", md, sizeof md);
    long title = at(md, "# A case\n\n**Claim.** The claim.");
    long why = at(md, "**Why.** The reason."), tol = at(md, "**Tolerance.** 1e-12");
    long check = at(md, "**Check.** `field_exact_covariance`, tolerance = 1e-12; 1 row, criteria: <= 1.");
    long result = at(md, "**Result.** **PASS**: error = 0.5 (<= 1). Margin 0.5");
    long results = at(md, "## Results"), rest = at(md, "## The case in full\n\n**Oracle.** Stays");
    long scene = at(md, "## Scene"), notes = at(md, "## Notes from the case\n\nAfter the scene.");
    long hist = at(md, "## History and studies\n\nFresh seeds 1..40");
    assert_true(title < why && why < tol && tol < check && check < result && result < results);
    assert_true(results < rest && rest < scene && scene < notes && notes < hist);
    /* the history is not also in the rest, and the report ends with it */
    assert_null(strstr(md + hist + 1, "## "));
    assert_int_equal(strstr(md, "Fresh seeds") - md, hist + (long)strlen("## History and studies\n\n"));

    /* no **Claim** paragraph: the first one is the claim; no Why, no Test
     * paragraph: the check line is the test */
    write_report(root, "# Bare\n\nIt just holds.\n\n```scene\ncheck = field_exact_covariance\nnx = 8\nny = 8\n"
                       "l = 0.1\ntolerance = 1e-12\n```\n", "cases/demo/bare.md", md, sizeof md);
    long c2 = at(md, "# Bare\n\n**Claim.** It just holds.\n\n**Test.** `field_exact_covariance`");
    assert_true(c2 < at(md, "**Result.** **PASS**"));
    assert_null(strstr(md, "**Why"));
    assert_null(strstr(md, "## History and studies"));
    assert_null(strstr(md, "## The case in full"));

    /* a case whose process died: the same opening block, no rows */
    sf_case c;
    char err[512];
    memset(&c, 0, sizeof c);
    assert_int_equal(sf_case_parse(&c, "cases/demo/crash.md", text, strlen(text), err, sizeof err), SF_SUCCESS);
    sf_outcome o;
    memset(&o, 0, sizeof o);
    o.verdict = SF_VERDICT_ERROR;
    snprintf(o.key, sizeof o.key, "crashed with signal 11");
    assert_int_equal(sf_report_crash(root, &c, &o, err, sizeof err), SF_SUCCESS);
    char path[1200];
    snprintf(path, sizeof path, "%s/%s/report.md", root, c.id);
    snprintf(md, sizeof md, "%s", slurp(path));
    assert_true(at(md, "**Claim.** The claim.") < at(md, "**Check.** `field_exact_covariance`, tolerance = 1e-12."));
    assert_true(at(md, "**Check.**") < at(md, "**Result.** **ERROR**: crashed with signal 11; seed"));
    assert_true(at(md, "**The case did not complete:**") < at(md, "## History and studies\n\nFresh seeds"));
    sf_case_free(&c);

    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", root);
    assert_int_equal(system(cmd), 0);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(prose_parts),
        cmocka_unit_test(report_layout),
    };
    return cmocka_run_group_tests_name("report", tests, NULL, NULL);
}
