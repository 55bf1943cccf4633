/* slipfield verification: report writers.  Everything is written under a
 * temporary name and renamed, so an interrupted run never leaves a
 * half-written file that looks complete. */
#ifndef SF_REPORT_H
#define SF_REPORT_H

#include "budget.h"
#include "case.h"
#include "result.h"

enum { SF_VERDICT_PASS = 0, SF_VERDICT_FAIL = 1, SF_VERDICT_ERROR = 2 };

typedef struct sf_outcome {
    char id[128], family[64], path[512], title[256];
    int tier, vv;
    int verdict;
    double seconds;
    char key[320];       /* one line: the quantity, measured value, criterion */
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

/* Write <root>/<id>/report.md and its plots.  `error` (may be NULL) is a
 * message when the check could not complete. */
int sf_report_case(const char *root, const sf_case *c, const sf_result *r,
                   const sf_outcome *o, const char *error, char *err, size_t errlen);

/* A report for a case whose process died (crash, abort, time-out). */
int sf_report_crash(const char *root, const sf_case *c, const sf_outcome *o,
                    char *err, size_t errlen);

/* reports/index.md, reports/index.html and reports/junit.xml. */
int sf_report_index(const sf_run_meta *meta, const sf_outcome *o, size_t n,
                    char *err, size_t errlen);

/* mkdir -p */
int sf_mkdirs(const char *path);

const char *sf_verdict_name(int verdict);

#endif
