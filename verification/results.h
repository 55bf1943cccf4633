/* slipfield verification: machine-readable results (reports/results.json).
 *
 * Each case process writes <root>/<id>/result.json next to its report: the
 * case's identity, verdict, seed, run time, git revision and every row of
 * its results table.  After the run the runner gathers them into
 * <root>/results.json with a run summary (the parent's view of verdict and
 * time wins: a case that crashed, or whose report could not be written,
 * has no rows).  The format is verification/results.schema.json; `make
 * test` validates a run against it.
 *
 * JSON has no NaN or infinity: a non-finite number is written as null and
 * named, with its value, in the row's "nonfinite" object.  Strings go
 * through jansson, which escapes them; bytes that are not UTF-8 become '?'.
 *
 * Margin: how much of its allowance a gated row uses -- measured over
 * tolerance (|diff| / tol, |diff| / (tol |expected|), measured / bound for
 * "<= bound" with bound > 0, bound / measured for ">= bound" with bound >
 * 0, and the mirror images for bounds <= 0; 0 when the value is on the
 * far side of zero) or alpha over p for a statistical row.  It is >= 0,
 * and above 1 exactly when the row fails.  A boolean row has none.  The
 * case's margin is its tightest row (the largest margin; a NaN counts as
 * +inf; rows whose margin cannot move are left out: sf_row_margin_fixed);
 * a case that passes with a margin >= SF_NEAR_EDGE is "near the
 * edge" (not a failure).
 */
#ifndef SF_RESULTS_H
#define SF_RESULTS_H

#include "case.h"
#include "outcome.h"
#include "result.h"

#include <stddef.h>

#define SF_NEAR_EDGE 0.9
#define SF_RESULTS_SCHEMA "slipfield-results/1"

/* The row's margin, or NAN when it has none (boolean rows, and rows made
 * without a tolerance).  May be +inf (e.g. a nonzero error against a zero
 * tolerance). */
double sf_row_margin(const sf_row *row);

/* 1: a passing row whose margin cannot move, so it says nothing of how
 * near the case is to failing: an exact equality (abs or rel at tolerance
 * 0: margin 0) or a count at its bound (le/ge, measured == bound, both
 * whole numbers: "13 of 13 releases >= 13", "rows excluded <= 0": margin 1
 * or 0 by construction, and the next step is a failure, not a drift). */
int sf_row_margin_fixed(const sf_row *row);

/* The case's tightest margin (largest row margin over the rows whose
 * margin can move, sf_row_margin_fixed; NAN when no row has one); *which
 * (may be NULL) gets that row's index. */
double sf_result_margin(const sf_result *r, size_t *which);

/* "abs", "rel", "le", "ge", "pvalue", "true" ("other" for a row made
 * without a sf_check_* function) and its kind: "exact", "statistical",
 * "boolean". */
const char *sf_row_test_name(int test);
const char *sf_row_kind_name(int test);

/* Write <dir>/result.json for one case; r may be NULL (no rows: the case
 * did not complete).  Returns SF_SUCCESS or SF_EIO with err set. */
int sf_results_case_write(const char *dir, const sf_case *c, const sf_result *r,
                          const sf_outcome *o, char *err, size_t errlen);

/* Gather <root>/<id>/result.json of the n outcomes into <root>/results.json
 * with the run summary; fills o[i].margin and o[i].near_edge.  baseline
 * (may be NULL) is recorded in the summary. */
int sf_results_write(const sf_run_meta *meta, sf_outcome *o, size_t n,
                     const char *baseline, char *err, size_t errlen);

#endif
