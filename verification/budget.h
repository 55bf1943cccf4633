/* slipfield verification: the tier's false-alarm budget.
 *
 * One run of a tier at fresh seeds must fail, when the code is right,
 * with probability at most SF_BUDGET_TIER (family-wise over every case and
 * row; Bonferroni: the sum of the cases' shares bounds it).
 *
 * A case's alpha is its own family-wise false-alarm rate (its check splits
 * it over its rows, Bonferroni).  Its statistical rows (p-values and claim
 * verdicts, sf_row.alpha > 0) are gated in two stages, as GSL, TestU01
 * and dieharder do: a row whose p-value lies below its alpha but not below
 * SF_BUDGET_FLOOR times it is *suspect*, and a case whose only failures
 * are suspect rows is run once more on a fresh stream (seed
 * sf_budget_replica_seed); it fails only if that replication fails too.
 * Under the null a case then fails with probability at most
 *
 *     share = (a - A) + FLOOR A + A a,      a = max(alpha, A),
 *
 * A the alpha its statistical rows spend: below the floor at once, or
 * suspect and then any failure of the independent replication; the rest
 * of its alpha (a - A: a bound from a confidence interval, a deterministic
 * tolerance whose data depend on the seed, counted at a measured rate)
 * fails at once, unless the case sets `replicate`: then a failure of those
 * rows is confirmed by the replication too, and they spend (a - A) a, not
 * a - A (a tolerance on an estimate from a few realisations, which a
 * defect fails at every seed and chance at a measured rate).  A case that
 * draws no random numbers, or whose
 * tolerance holds at every seed (`seed_proof = REASON`), or that checks
 * one pinned realisation (`pin_seed`), spends nothing.  A defect still
 * fails: a p-value below the floor at once, a moderate one with the
 * square of the row's power at worst.
 */
#ifndef SF_BUDGET_H
#define SF_BUDGET_H

#include "case.h"
#include "result.h"

#include <stdio.h>

#define SF_BUDGET_TIER 0.01    /* family-wise false-alarm probability of one run of a tier */
#define SF_BUDGET_FLOOR 0.01   /* a p-value below FLOOR x its alpha fails without replication */

/* A case's entry in the ledger (sf_outcome.budget). */
enum { SF_BUDGET_NONE = 0, SF_BUDGET_STAT, SF_BUDGET_SEED_PROOF, SF_BUDGET_PINNED };
typedef struct {
    int kind;              /* SF_BUDGET_*: how the case draws on the budget */
    double alpha;          /* the declared alpha (0 when the case sets none) */
    size_t nstat;          /* its statistical rows (p-values and verdicts) */
    double row_alpha;      /* the alpha they spend (sum) */
    int replicated;        /* 1: this run's verdict is the replication's */
    int replicate;         /* the case's `replicate`: its deterministic rows are confirmed too */
} sf_budget_entry;

/* The declared part, from the case (the runner fills it for every case). */
void sf_budget_entry_init(sf_budget_entry *e, const sf_case *c);
/* The measured part, from the check's rows. */
void sf_budget_entry_rows(sf_budget_entry *e, const sf_result *r);
/* The entry's share of the tier's budget (see above). */
double sf_budget_share(const sf_budget_entry *e);

/* Should the case run once more on a fresh stream?  Yes when it failed
 * only in suspect rows (statistical rows with p >= FLOOR x alpha, claim
 * verdicts; with `replicate`, its deterministic rows too), has no
 * non-finite data and is not pinned. */
int sf_budget_suspect(const sf_case *c, const sf_result *r);
/* The replication's seed: a fresh stream derived from the case's seed. */
unsigned long sf_budget_replica_seed(unsigned long seed);
/* A Markdown note on the first run's suspect rows (for the replication's
 * report), into buf. */
void sf_budget_replica_note(const sf_result *first, unsigned long seed, unsigned long seed2, char *buf, size_t len);

/* Serialise the measured part for the runner's pipe ("nstat row_alpha
 * replicated", no tab) and read it back; read returns 0 on a bad line. */
void sf_budget_entry_format(const sf_budget_entry *e, char *buf, size_t len);
int sf_budget_entry_scan(sf_budget_entry *e, const char *s);

/* The index's budget section: the tier's budget, the table of how it is
 * spent (case, statistical rows, alpha, share) and its sum over the n
 * outcomes of the run; page is "report.md" or "report.html". */
struct sf_outcome;
void sf_budget_index_section(FILE *f, const char *tier_name, const struct sf_outcome *o, size_t n, const char *page);

#endif
