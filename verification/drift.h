/* slipfield verification: what changed since a baseline run.
 *
 * `slipfield verify --baseline OLD/results.json` (make verify
 * BASELINE=...) compares this run's results.json with an older one and
 * writes <root>/drift.md and drift.html.  Cases are matched by id, rows by
 * quantity text (in order).  What counts as a change:
 *
 *  - a verdict that differs;
 *  - an exact row (abs, rel, le, ge: a tolerance or bound) whose measured
 *    value moved by more than its own uncertainty between two runs: the
 *    round-off of the values compared, 10 eps max(|m0|, |m1|, |expected|,
 *    1) (eps = DBL_EPSILON; the 1 because the suite's metrics are SI or
 *    dimensionless values on operands of order one, so an error metric
 *    near zero carries their round-off), or, for a case whose data pass
 *    through a chaotic trajectory (the families dynamics, validation,
 *    plan, stress, limits), that round-off amplified by the dynamics,
 *    1e-6 max(|m0|, |m1|, |expected|, 1) (a change of round-off moves PV_x
 *    by about 1e-7 over 40 s).  The page also gives the move as a share of
 *    the tolerance;
 *  - a statistical row (a p-value against alpha): with the same seed in
 *    both runs the two p-values come from the same draws, so the null is
 *    the exact rows' (a change of code moves the data only by round-off,
 *    amplified on a chaotic trajectory): |p1 - p0| > k max(p0, p1), k as
 *    above; with different seeds the draws are independent and
 *    z = Phi^-1(1 - p) is standard normal under the null hypothesis, so
 *    two runs differ by a N(0, 2) amount; a move counts when |z1 - z0| >
 *    2 sqrt(2) (a two-sided 5% test that both come from the same null
 *    distribution).  p above 0.5 counts as 0.5 (z = 0): far from alpha
 *    either way, and a Bonferroni-adjusted p is clamped at 1;
 *  - a boolean row whose outcome changed; a value that became or stopped
 *    being non-finite;
 *  - a run time that grew by more than 2x, and by more than 0.5 s (below
 *    that, scheduling noise).  The time compared is the CPU time of the
 *    case process (cpu_seconds), which a busy machine hardly changes;
 *    wall time only when a run lacks it;
 *  - cases and rows present in one run only, and seeds that differ.
 *
 * Case names link to their reports (report.md; report.html from
 * drift.html).
 *
 * Only a verdict that changed to FAIL or ERROR is a failure, and the run
 * already fails on it; drift never changes the exit status.
 */
#ifndef SF_DRIFT_H
#define SF_DRIFT_H

#include <stdio.h>
#include <stddef.h>

typedef struct sf_drift_summary {
    char baseline[512];
    size_t verdicts;     /* verdicts that changed */
    size_t to_fail;      /* ... to fail or error */
    size_t moved;        /* rows that moved */
    size_t slower;       /* cases whose run time grew */
    size_t added, removed;           /* cases in one run only */
    size_t rows_added, rows_removed; /* rows in one run only */
    size_t seeds;        /* cases run with another seed */
} sf_drift_summary;

typedef struct sf_baseline sf_baseline;

/* Read an older results.json (kept in memory: this run may overwrite
 * the file).  Returns SF_SUCCESS, or SF_EIO / SF_EPARSE with err set. */
int sf_baseline_load(const char *path, sf_baseline **out, char *err, size_t errlen);
void sf_baseline_free(sf_baseline *b);

/* The rules above, one value pair at a time. */
int sf_drift_exact_moved(double m0, double m1, double expected);
/* An exact row of a chaotic case: |m1 - m0| > 1e-6 max(|m0|, |m1|, |expected|, 1). */
int sf_drift_chaotic_moved(double m0, double m1, double expected);
/* A p-value from the same draws (same seed): |p1 - p0| > k max(p0, p1),
 * k = 1e-6 for a chaotic case, 10 eps otherwise. */
int sf_drift_pvalue_coupled_moved(double p0, double p1, int chaotic);
/* Do the cases of this family integrate chaotic trajectories? */
int sf_drift_chaotic_family(const char *family);
int sf_drift_pvalue_moved(double p0, double p1);
int sf_drift_time_grew(double t0, double t1);

/* Compare <root>/results.json with the baseline; write <root>/drift.md
 * and <root>/drift.html; fill *s. */
int sf_drift_write(const sf_baseline *b, const char *root, sf_drift_summary *s,
                   char *err, size_t errlen);

/* One Markdown list item for the index, linking drift.md or drift.html
 * (page is "report.md" or "report.html"). */
void sf_drift_index_line(FILE *f, const sf_drift_summary *s, const char *page);

/* Has anything changed? */
int sf_drift_any(const sf_drift_summary *s);

#endif
