/* slipfield verification: report writers.  Everything is written under a
 * temporary name and renamed, so an interrupted run never leaves a
 * half-written file that looks complete. */
#ifndef SF_REPORT_H
#define SF_REPORT_H

#include "case.h"
#include "outcome.h"
#include "result.h"

/* Stage <root>/<id>'s report in a temporary folder and render r's plots
 * there.  Call it before the verdict: a plot gnuplot warns about, or an
 * empty one, adds a failing row naming it (sf_result_render_plots).
 * SF_SUCCESS, or SF_EIO when gnuplot could not run (err says why). */
int sf_report_plots(const char *root, const sf_case *c, sf_result *r, char *err, size_t errlen);

/* Write <root>/<id>/report.md (with the plots sf_report_plots staged) and
 * swap the folder in.  `error` (may be NULL) is a message when the check
 * could not complete. */
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
