/* slipfield verification: the paper's claims across cases.
 *
 * A check records each claim of the paper it evaluates with sf_claim()
 * (result.h).  The case report lists them (sf_paper_case_claims), the
 * case folder keeps them as claims.tsv, and after a run the index lists
 * every claim that is not confirmed (a deviation is never hidden) and
 * reports/paper.md gathers all of them figure by figure, with the paper's
 * Sec. 2.4 claims that other families gate.
 */
#ifndef SF_PAPER_H
#define SF_PAPER_H

#include <stdio.h>
#include "outcome.h"
#include "result.h"

/* Markdown section "Claims of the paper" for a case report (nothing when
 * the result holds no claim). */
void sf_paper_case_claims(FILE *f, const sf_result *r);

/* <dir>/claims.tsv (nothing when there is no claim). 0 or -1. */
int sf_paper_write_tsv(const char *dir, const sf_result *r);

/* The index's opening line on the claims, read from the cases'
 * claims.tsv: how many are confirmed, contradicted, not decidable, and
 * the link to paper.md/.html.  Nothing without claims. */
void sf_paper_index_tally(FILE *f, const char *root, const sf_outcome *o, size_t n, int html);

/* Index section: every claim that is not confirmed.  Nothing when all
 * are. */
void sf_paper_index_section(FILE *f, const char *root, const sf_outcome *o, size_t n, int html);

/* <root>/paper.md and paper.html when any run case holds claims. */
int sf_paper_report(const sf_run_meta *meta, const sf_outcome *o, size_t n, char *err, size_t errlen);

#endif
