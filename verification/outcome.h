/* slipfield verification: a case's outcome and a run's identity, as the
 * runner collects them and every summary writer reads them (report.h,
 * results.h, paper.h, drift.h).  A header of its own, so that the writers
 * depend on the data and not on each other. */
#ifndef SF_OUTCOME_H
#define SF_OUTCOME_H

#include <stddef.h>
#include "budget.h"

enum { SF_VERDICT_PASS = 0, SF_VERDICT_FAIL = 1, SF_VERDICT_ERROR = 2 };

typedef struct sf_outcome {
    char id[128], family[64], path[512], title[256];
    int tier, vv;
    int verdict;
    double seconds;
    char key[768];       /* one line: the quantity (a whole label), measured value, criterion */
    /* results.json (results.h) */
    unsigned long seed;  /* the seed the case ran with */
    char check[64];
    double margin;       /* the tightest row's margin; NAN when none */
    int near_edge;       /* passed with margin >= SF_NEAR_EDGE */
    double cpu_seconds;  /* CPU time of the case process (runner) */
    sf_budget_entry budget;   /* its share of the tier's false-alarm budget (budget.h) */
} sf_outcome;

struct sf_drift_summary;     /* drift.h */

typedef struct {
    const char *root;        /* report folder, e.g. "reports" */
    const char *seed_note;   /* "fixed (per case)" or the override */
    const char *tier_name;
    double total_seconds;
    size_t skipped;          /* selected cases not run (other tier) */
    const struct sf_drift_summary *drift;  /* NULL: no baseline given */
} sf_run_meta;

/* The CPU time of the run's case processes [s], summed (a case without
 * one counts 0): the tier's cost, which a busy machine hardly changes. */
double sf_outcome_cpu_total(const sf_outcome *o, size_t n);

/* "PASS", "FAIL" or "ERROR". */
const char *sf_verdict_name(int verdict);

#endif
