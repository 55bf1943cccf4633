/* The claims engine (claims_engine.c) as the validation checks call it:
 * a sweep judged against a table of claim_spec (claims.h), and a single
 * claim judged from an estimate the check computed itself. */
#ifndef SF_CHECKS_CLAIMS_ENGINE_H
#define SF_CHECKS_CLAIMS_ENGINE_H

#include "common.h"
#include "claims.h"
#include "cof.h"

/* A Monte Carlo worker's state (sf_mc_ops alloc / free; ctx is a
 * claims_ws whose plan is ignored): the scene and a COF plan of its own. */
typedef struct {
    const sf_scene *s;    /* the run's scene (t_skip = 0) */
    double tskip, tlate;
    sf_cof_plan *plan;
} claims_ws;
void *claims_ws_alloc(void *ctx);
void claims_ws_free(void *p);
/* The body of an sf_mc_ops realise on a claims_ws worker p: draws the
 * realisation's COF from the worker's plan, gives it to run, frees it. */
typedef int (*claims_ws_run_fn)(const claims_ws *w, const sf_cof *cof, double *out);
int claims_ws_realise(void *p, gsl_rng *rng, double *out, claims_ws_run_fn run);

/* Runs the case's sweep (c->spec.sweep over c->spec.sweep_param), notes
 * its table, judges and gates every claim of spec (NULL-id ended) whose
 * points it has, and plots the figure fig (x label xl, log x if logx).
 * On success *out holds the K = *Kout points for the caller's own checks
 * (free with claims_free); SF_EFAIL or SF_EINVAL otherwise. */
int claims_sweep(const sf_case *c, sf_result *r, const claim_spec *spec, const char *fig, const char *xl,
                 int logx, cpoint **out, size_t *Kout);
void claims_free(cpoint *pt, size_t K);

/* Records and gates the claim cs of the table all (for its alpha share)
 * from an estimate est with standard error se (df degrees of freedom) on
 * the test's scale; how and defs describe the test for the report. */
void claims_judge_one(const sf_case *c, sf_result *r, const claim_spec *all, const claim_spec *cs, double est,
                      double se, double df, const char *how, const char *defs);

/* The engine's verdict rule, pure (what claims_judge_one and the sweep's
 * judgement use; claims-engine-synthetic drives it on synthetic claims):
 * the verdict (SF_CLAIM_*) of the claim cs (its kind, dir, lo, hi) from
 * an estimate est with standard error se on df degrees of freedom
 * (Student's t quantile; the normal one above df = 1e6), each one-sided
 * test at alpha; its one-sided (1 - alpha) bounds into *lo, *hi (either
 * may be NULL).  Linear scale (the log-scale kinds pass logs). */
int claims_decide(const claim_spec *cs, double est, double se, double df, double alpha, double *lo, double *hi);
/* The verdict about the model (claims_engine.c: the design, its
 * spending function and its citation).  claims_model_looks: the looks'
 * realisations a point, N[0] = n1 doubling up to the last = budget (at
 * most CLAIMS_MAX_LOOKS); returns L.  claims_look_alpha: look j's level
 * (j = 0 .. L-1) of the total alpha under the spending function spend;
 * the levels sum to alpha.  claims_sequential_decide: the design's
 * verdict from the first m of its L looks' estimates est, standard errors
 * se, degrees of freedom df (the test's scale: logs with logscale, the
 * claim's thresholds and margin then factors; margin on that scale, NAN
 * or 0 for none): at each look the claim's verdict at its level
 * (claims_decide), or SF_CLAIM_WITHIN when a directional claim's two
 * one-sided tests against its threshold -+ margin both reject; the first
 * decided look into *look with its bounds (*lo, *hi, either may be NULL);
 * SF_CLAIM_UNDECIDED with the last look given when none decides. */
#define CLAIMS_MAX_LOOKS 12
enum { CLAIMS_SPEND_POCOCK, CLAIMS_SPEND_OBF };
size_t claims_model_looks(size_t n1, size_t budget, size_t *N);
double claims_look_alpha(double alpha, const size_t *N, size_t L, size_t j, int spend);
/* Per-point budgets pb[0 .. npb-1] (npb = 0: none, valid) for K sweep
 * points with n1 realisations at look 1 and the case's budget: valid when
 * npb = K, each is n1 x a power of 2 and the largest is budget (the looks
 * of claims that share a point are then nested).  1 when valid. */
int claims_budgets_ok(size_t n1, size_t budget, const double *pb, size_t npb, size_t K);
int claims_sequential_decide(const claim_spec *cs, const size_t *N, size_t L, size_t m, const double *est,
                             const double *se, const double *df, double alpha, double margin, int logscale,
                             int spend, size_t *look, double *lo, double *hi);
/* A directional claim's indifference margin on its test's scale: its
 * spec's hi when set (log of a factor for the std kinds), otherwise 2% of
 * scale (the statistic's deterministic scale: 1 for a ratio) for a mean,
 * log 1.1 for a std; NAN for the equivalence kinds and the F test. */
double claims_margin_of(const claim_spec *cs, double scale);
/* The alpha each claim of the table spec (NULL-id ended) is tested at in
 * case c: c's alpha / the claims judged / the looks (Bonferroni). */
double claims_alpha(const sf_case *c, const claim_spec *spec);
/* The power every minimum detectable effect is stated at, and that
 * effect for a test of standard error se at alpha: (z_alpha +
 * z_(1 - power)) se (a factor, exp of it, when logscale). */
#define CLAIM_MDE_POWER 0.99
double claims_mde(double se, double alpha, int logscale);

#endif
