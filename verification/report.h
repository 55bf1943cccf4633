/* slipfield verification: report writers.  Everything is written under a
 * temporary name and renamed, so an interrupted run never leaves a
 * half-written file that looks complete. */
#ifndef SF_REPORT_H
#define SF_REPORT_H

#include "case.h"
#include "outcome.h"
#include "result.h"

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

#endif
