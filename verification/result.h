/* slipfield verification: what a check produces.
 *
 * A check fills an sf_result with rows of a measured-vs-expected table
 * (each row decides pass/fail against its own tolerance), free-form
 * findings (Markdown), and plots (data + labels; rendered by gnuplot in
 * report.c).  The case passes only when every row passes and the check
 * returned SF_SUCCESS; a check that adds no row is an error, not a pass
 * (a check that cannot fail is a defect).
 */
#ifndef SF_RESULT_H
#define SF_RESULT_H

#include <stddef.h>
#include <stdio.h>

typedef struct sf_result sf_result;
typedef struct sf_plot sf_plot;

/* The longest row label (quantity) or sample label kept whole: a check's
 * own label buffers are this long too, so no label is cut. */
#define SF_LABEL_LEN 512

typedef struct {
    char quantity[SF_LABEL_LEN];
    double measured, expected;  /* expected may be NAN (no single value) */
    char criterion[96];         /* e.g. "|diff| <= 1e-13", "p >= 1e-3" */
    double ratio;               /* how much of the tolerance is used: > 1 fails */
    int pass;
    /* what the row compares, for reports/results.json and the drift page:
     * which sf_check_* made it (SF_ROW_*), its tolerance, bound or alpha
     * in the units of the criterion, and the sample size of a p-value */
    int test;
    double limit;
    size_t n;
    /* > 0: a statistical row (a p-value, a claim's verdict) and the share
     * of the case's alpha it spends; the runner may replicate it (budget.h) */
    double alpha;
} sf_row;

/* sf_row.test: abs, rel, le, ge are exact rows (a tolerance or bound),
 * pvalue a statistical row (alpha), true a boolean property. */
enum { SF_ROW_ABS = 1, SF_ROW_REL, SF_ROW_LE, SF_ROW_GE, SF_ROW_PVALUE, SF_ROW_TRUE };

sf_result *sf_result_alloc(void);
void sf_result_free(sf_result *r);

/* Rows.  Each returns the row's pass flag. */
int sf_check_abs(sf_result *r, const char *quantity, double measured, double expected, double tol);
int sf_check_rel(sf_result *r, const char *quantity, double measured, double expected, double tol);
int sf_check_le(sf_result *r, const char *quantity, double measured, double bound);
int sf_check_ge(sf_result *r, const char *quantity, double measured, double bound);
/* A statistical test: passes when p >= alpha. n = sample size. */
int sf_check_pvalue(sf_result *r, const char *test, double p, double alpha, size_t n);
/* A boolean property with a short explanation of what was found. */
int sf_check_true(sf_result *r, const char *quantity, int ok, const char *found);
/* The same for a statistical verdict (a claim confirmed or contradicted by
 * a test at alpha): a boolean row that spends alpha of the case's budget. */
int sf_check_verdict(sf_result *r, const char *quantity, int ok, const char *found, double alpha);
/* Mark the last row statistical: it decides a test at alpha (e.g. a
 * p-value against a bound made with sf_check_le), so it spends alpha of
 * the case's budget and may be replicated (budget.h). */
void sf_result_mark_statistical(sf_result *r, double alpha);

/* Non-finite values fail (docs/design.md sec. 7.6).  The result counts every NaN/Inf
 * among its rows' measured values and its plotted series (the plots are
 * the check's data), and among arrays handed to sf_result_data: those a
 * check aggregates (max, mean, test statistic) but does not plot.  `what`
 * names the array in the message.  x is not const: under the test-only
 * poison of stats.h the k-th element becomes NaN before the check
 * aggregates it.  The runner calls sf_result_gate_nonfinite after the
 * check: it appends the gated row "non-finite values = 0" (so no check
 * has to remember it) and returns its pass flag. */
void sf_result_data(sf_result *r, const char *what, size_t n, double *x);
size_t sf_result_nonfinite(const sf_result *r);
int sf_result_gate_nonfinite(sf_result *r);

/* A claim of the paper and our verdict on it, as data (the case report,
 * the index and reports/paper.md list them).  `id` is short and stable
 * (e.g. "fig11-std-large"); `text` quotes or paraphrases the paper;
 * `measured` is our estimate with its (1 - alpha) confidence interval
 * [ci_lo, ci_hi] (NAN when there is none); `how` names the test and the
 * sample size; `note` explains a contradiction or what would decide it.
 * A claim is not a row: a check gates the claims it expects to hold (or to
 * fail) with rows of its own. */
enum { SF_CLAIM_CONFIRMED = 0, SF_CLAIM_CONTRADICTED = 1, SF_CLAIM_UNDECIDED = 2, SF_CLAIM_WITHIN = 3 };
/* The verdict about the model (docs/design.md sec. 7.7): a sequential
 * design's at N up to a budget (claims_sequential_decide).  status: -1
 * none (the case runs no model verdicts), SF_CLAIM_CONFIRMED /
 * _CONTRADICTED, SF_CLAIM_WITHIN (no effect beyond the claim's margin
 * either way), SF_CLAIM_UNDECIDED (the budget reached); n the
 * realisations a point it took, budget the most it could; est [lo, hi]
 * and mde at the look it stopped at, alpha the model verdict's own share
 * over its looks, margin its indifference margin (NAN: none). */
typedef struct {
    int status;
    size_t n, budget;
    double est, lo, hi, mde, alpha, margin;
} sf_claim_model;
typedef struct {
    char id[48], text[320], how[200], note[800];
    char defs[400];   /* the verdict under other QoI definitions (sf_claim_defs) */
    int status;
    double measured, ci_lo, ci_hi, alpha;
    sf_claim_model model;
} sf_claim_row;
void sf_claim(sf_result *r, const char *id, const char *text, int status, double measured, double ci_lo,
              double ci_hi, double alpha, const char *how, const char *note);
/* The last claim's verdicts under alternative QoI definitions (docs/design.md
 * sec. 5.3), e.g. "t_skip 0 s: confirmed; window stick fraction: confirmed". */
void sf_claim_defs(sf_result *r, const char *defs);
/* The model verdict of the last claim recorded with this id (nothing when
 * there is none). */
void sf_claim_set_model(sf_result *r, const char *id, const sf_claim_model *m);
/* "confirmed", "contradicted", "within margin", "budget reached" (a model
 * verdict's status), "none" for -1 */
const char *sf_claim_model_name(int status);
size_t sf_result_nclaims(const sf_result *r);
const sf_claim_row *sf_result_claim(const sf_result *r, size_t i);
const char *sf_claim_status_name(int status);

/* A statistic over realisations that a check reports or gates on: how
 * many values it used and how many it excluded (non-finite: a realisation
 * the QoI's definition cannot measure).  results.json lists them per case
 * ("samples"), so that no excluded realisation goes unsaid. */
typedef struct {
    char what[SF_LABEL_LEN];
    size_t n_used, n_excluded;
} sf_sample_row;
void sf_result_sample(sf_result *r, const char *what, size_t n_used, size_t n_excluded);
size_t sf_result_nsamples(const sf_result *r);
const sf_sample_row *sf_result_sample_at(const sf_result *r, size_t i);

/* One QoI of one sweep point, as `slipfield sweep --diagnostics` states it:
 * the values used and excluded, mean, std, Monte Carlo standard error,
 * the Student interval at `level`, and u_num, the numerical error of the
 * mean (NAN: not estimated), estimated on realisations 0 .. u_num_subset
 * - 1 (0: not estimated), u_num_used of them finite.  results.json lists
 * them per case ("sweep") and the report tabulates them. */
typedef struct {
    char param[48], qoi[32], unit[8];
    double value;
    size_t n_used, n_excluded;
    double mean, std, se, ci_lo, ci_hi, level, u_num;
    size_t u_num_subset, u_num_used;
} sf_sweep_row;
void sf_result_sweep(sf_result *r, const sf_sweep_row *row);
size_t sf_result_nsweep(const sf_result *r);
const sf_sweep_row *sf_result_sweep_at(const sf_result *r, size_t i);

/* Findings: Markdown appended to the report (printf-style). */
void sf_note(sf_result *r, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

size_t sf_result_nrows(const sf_result *r);
const sf_row *sf_result_row(const sf_result *r, size_t i);
const char *sf_result_notes(const sf_result *r);
int sf_result_passed(const sf_result *r);
/* The row to quote in one line: the first failing, else the most used. */
const sf_row *sf_result_key_row(const sf_result *r);

/* Plots.  `stem` names the PNG (letters, digits, _ and -). */
/* SF_STYLE_DASHED: a dashed line (the paper's deterministic reference). */
enum { SF_STYLE_LINES = 0, SF_STYLE_POINTS = 1, SF_STYLE_LINESPOINTS = 2, SF_STYLE_STEPS = 3, SF_STYLE_DASHED = 4 };
sf_plot *sf_result_plot(sf_result *r, const char *stem, const char *title,
                        const char *xlabel, const char *ylabel);
void sf_plot_log(sf_plot *p, int logx, int logy);
void sf_plot_series(sf_plot *p, const char *label, int style, size_t n,
                    const double *x, const double *y);
/* A shaded band between lo and hi (tolerance or confidence band). */
void sf_plot_band(sf_plot *p, const char *label, size_t n, const double *x,
                  const double *lo, const double *hi);
void sf_plot_hline(sf_plot *p, const char *label, double y);
/* Points y with error bars from lo to hi (a confidence interval). */
void sf_plot_errorbars(sf_plot *p, const char *label, size_t n, const double *x, const double *y,
                       const double *lo, const double *hi);
/* The gnuplot commands that draw p into the PNG at path (sf_result_render_plots
 * feeds them to gnuplot; a test may run them itself).  why gets the reason
 * when the plot would be empty or a series draws nothing. */
void sf_plot_write_script(FILE *g, const sf_plot *p, const char *path, char *why, size_t whylen);

size_t sf_result_nplots(const sf_result *r);
sf_plot *sf_result_get_plot(const sf_result *r, size_t i);
const char *sf_plot_stem(const sf_plot *p);
const char *sf_plot_title(const sf_plot *p);

/* Render all plots of r into dir (PNG via gnuplot, through a pipe; files
 * written under a temporary name and renamed).  A plot that gnuplot warns
 * about (its stderr is read back, plot by plot), or that would be empty
 * or hold a series with no point to draw, adds a failing row naming it:
 * render before the verdict.  Returns 0, the number of such plots (err:
 * the first), or -1 when gnuplot could not run (err says why). */
int sf_result_render_plots(sf_result *r, const char *dir, char *err, size_t errlen);

#endif
