/* slipfield: Monte Carlo sweeps of the stochastic oscillator (Sec. 3).
 *
 * At each parameter value: the deterministic reference (uniform COF at
 * mu_mean, same T, t_skip, eps_lambda and stepper: the same QoI
 * definitions over the same window [t_skip, T], so ratios compare like
 * with like; under the default qoi_def = paper the stick-fraction ratio is
 * the paper's T_sk,s / T_sk,d), then N realisations
 * (montecarlo.h: realisation i has its own stream, OpenMP, checkpoint),
 * each giving pv_x [m], pv_F [N] and the stick fraction [-], and their
 * ratios to the deterministic values.
 *
 * Parameters: any numeric scene key, plus `l_over_R` (sets l = value x R,
 * dimensionless) and `mu_mean` at fixed CV (mu_std scales with it, as in
 * Fig. 13).
 */
#ifndef SF_SWEEP_H
#define SF_SWEEP_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdio.h>
#include <gsl/gsl_rng.h>
#include "cof.h"
#include "scene.h"

enum { SF_SWEEP_PVX = 0, SF_SWEEP_PVF = 1, SF_SWEEP_SF = 2, SF_SWEEP_NQ = 3 };

/* The estimators of a sweep point (sf_sweep_point.estimator; the
 * summary's and the diagnostics' estimator column, by
 * sf_sweep_estimator_name). */
enum { SF_EST_PLAIN = 0, SF_EST_CV, SF_EST_TARGET, SF_EST_MLMC, SF_EST_MLMC_BOXES, SF_EST_ANTITHETIC, SF_EST_MLMC_SUB };
const char *sf_sweep_estimator_name(int est);
/* The estimator `sweep --estimator auto` takes for scene s, by a rule
 * chosen from the estimators bench at its default seed and measured on
 * other fields (docs/design.md sec. 8): two levels on boxes of boxes
 * where s's plan draws cell averages (sf_sweep_run_mlmc_boxes); on the
 * circulant strip of point values, two levels on every 2nd node at l/R <
 * SF_SWEEP_AUTO_SUB_LR (sf_sweep_run_mlmc_sub: the draw is most of a
 * realisation there) and on the same field below SF_SWEEP_AUTO_ANTI_LR
 * (sf_sweep_run_mlmc); antithetic pairs elsewhere
 * (sf_sweep_run_antithetic: tiles, and l/R >= 5, where the disc spans a
 * fraction of a correlation length and the QoIs follow the sign of the
 * field, rho = corr(Q(G), Q(-G)) -0.5 to -1). */
#define SF_SWEEP_AUTO_SUB_LR 0.5
#define SF_SWEEP_AUTO_ANTI_LR 5.0
int sf_sweep_estimator_auto(const sf_scene *s);

/* The level of every confidence interval a sweep reports. */
#define SF_SWEEP_CI_LEVEL 0.95

/* One quantity over a point's realisations.  A non-finite value (a
 * realisation the QoI's definition cannot measure) is excluded and
 * counted, never averaged: n_used + n_excluded = n.  std divides by
 * n_used - 1; se = std / sqrt(n_used), the Monte Carlo standard error of
 * the mean; [ci_lo, ci_hi] = mean -+ t se, t the Student quantile at
 * (1 + SF_SWEEP_CI_LEVEL) / 2 with n_used - 1 degrees of freedom.  NAN
 * where too few values are used (mean: none; the rest: fewer than 2). */
typedef struct {
    size_t n_used, n_excluded;
    double mean, std, se, ci_lo, ci_hi;
} sf_sweep_stat;

/* The numerical error of one quantity's mean over a point's realisations
 * (unum.h, sf_unum_sweep): u_num's coarser companion on realisations
 * 0 .. n_sub - 1 (exchangeable with the rest), each giving the signed
 * error estimate e_i = (Q_c,i - Q_i) / (rho - 1) of its Q_i; bias = the
 * mean of the n_used finite e_i, bias_se its standard error, u_mean =
 * Fs (|bias| + t bias_se) (+ the a-priori cell-average part), t the
 * Student quantile at (1 + SF_SWEEP_CI_LEVEL) / 2.  n_sub = 0: not
 * estimated (the summary and the diagnostics write nan). */
typedef struct {
    size_t n_sub, n_used;
    double bias, bias_se, u_mean;
} sf_sweep_num;

/* One ratio's two-level estimate (sf_sweep_point.ml, below). */
typedef struct {
    size_t m[2];
    double var[2], var_fine, mean, se, df, ci_lo, ci_hi, vrf;
} sf_sweep_ml;

/* One ratio's antithetic estimate (sf_sweep_point.anti, below). */
typedef struct {
    size_t m;
    double rho, var_fine, mean, se, ci_lo, ci_hi, vrf;
} sf_sweep_anti;

typedef struct {
    double det[SF_SWEEP_NQ];    /* deterministic pv_x [m], pv_F [N], stick fraction [-] */
    double *qoi;                /* n x SF_SWEEP_NQ, realisation-major: the values, in their units */
    double *ratio;              /* n x SF_SWEEP_NQ: qoi / det */
    sf_sweep_stat stat[SF_SWEEP_NQ];    /* of the values */
    sf_sweep_stat rstat[SF_SWEEP_NQ];   /* of the ratios */
    double mean[SF_SWEEP_NQ], std[SF_SWEEP_NQ];   /* of the ratios: rstat[q].mean, rstat[q].std */
    size_t n, from_checkpoint;
    size_t n_valid;             /* realisations whose every QoI is finite */
    sf_sweep_num num[SF_SWEEP_NQ];   /* numerical error of stat[q].mean (zero: not estimated) */
    /* What num[] is made of (sf_unum_sweep; NULL and 0: not estimated):
     * realisations 0 .. num_m - 1 solved again at the coarser companion
     * setting, their QoIs num_qc (num_m x SF_SWEEP_NQ, in their units),
     * each companion's assumed error ratio num_rho and the plan's relative
     * a-priori cell-average error num_apriori (0 for the point model).
     * num_m > 0 exactly when the three arrays are held.  The
     * per-realisation table writes them, so num[] can be recomputed from
     * it. */
    size_t num_m;
    double *num_qc, *num_rho, *num_apriori;
    /* The plan the rows were solved on (numplan.h), which the estimator
     * that made them records: the scene's (sf_plan_make), or mlmc-boxes'
     * own fine plan (mlmc.h: sf_mlmc_box_plans: its cells rounded up to a
     * multiple of 4, a wider strip).  Row i is the run on this plan of the
     * COF its COF plan draws from stream sf_mc_seed(seed, i); u_num's
     * companion solves that realisation (unum.h).  planned = 0: none
     * recorded (a point made by hand), the scene's plan is taken. */
    int planned;
    sf_plan plan;
    /* The design: a fixed N (n_pilot 0, stop SF_MCSTOP_FIXED), or two
     * stages (mcstop.h: the first n_pilot realisations decide N; stop
     * says whether every target was met or N hit the cap).  [rci_lo,
     * rci_hi]: the ratio mean's interval at SF_SWEEP_CI_LEVEL that the
     * design guarantees: rstat's Student interval for a fixed N; Stein's,
     * mean -+ t_{m0-1} s0 / sqrt(n_used) with the pilot's s0 over its m0
     * finite ratios, for two stages. */
    size_t n_pilot;
    int stop;
    int estimator;              /* SF_EST_*: which estimator made the point */
    double rci_lo[SF_SWEEP_NQ], rci_hi[SF_SWEEP_NQ];
    /* The control variate (sf_sweep_run_cv; companion NULL otherwise):
     * companion[i] = C_i, realisation i's COF averaged over fixed belt
     * points on the disc's nominal path (sf_sweep_companion), whose mean
     * is known: mu_mean (cv_known), since every point of the field, and
     * every interpolation between its nodes, has that mean.  Per ratio,
     * cv[q] is the regression estimator: the intercept of the least-
     * squares line of the ratio on C - mu_mean (GSL gsl_fit_linear), its
     * standard error with the residual variance over m - 2 (the slope
     * costs a degree of freedom), the Student interval at m - 2, the
     * slope, and the variance reduction factor vrf = (plain se / cv se)^2
     * on the same m realisations.  NaN where C is not formed (a window
     * of tiles: no companion there) or m < 3. */
    double *companion;
    double cv_known;
    struct {
        size_t m;
        double mean, se, ci_lo, ci_hi, beta, vrf;
    } cv[SF_SWEEP_NQ];
    /* The two-level estimator (sf_sweep_run_mlmc; n[1] = 0 otherwise):
     * level 0, n[0] coarse realisations on fields of their own; level 1,
     * n[1] pairs (fine and coarse run on one field: the rows above are
     * their fine values).  cost[l]: a level's mean work per sample [cell
     * evaluations] (mlmc.h), cost_fine a plain realisation's; per ratio
     * var[l] the level's sample variance (coarse ratios; fine - coarse),
     * mean = level 0's mean + level 1's, se^2 = var[0]/m0 + var[1]/m1
     * over the m_l finite values, the Student interval at the
     * Welch-Satterthwaite degrees of freedom df, and vrf = the variance
     * plain Monte Carlo reaches at the same work over the estimator's
     * (var_fine cost_fine / (se^2 work)), var_fine = Var Q_f estimated
     * as var[0] + the pairs' (Var Q_f - Var Q_c): level 0's many values
     * carry the bulk, the few pairs only the small difference. */
    struct {
        size_t n[2];
        double *coarse0;        /* n[0] x SF_SWEEP_NQ: level 0's coarse QoIs, in their units */
        double *coarse1;        /* n[1] x SF_SWEEP_NQ: the pairs' coarse QoIs (their fine ones: qoi) */
        double cost[2], cost_fine, work;
        sf_sweep_ml q[SF_SWEEP_NQ];
    } ml;
    /* Antithetic pairs (sf_sweep_run_antithetic, antithetic.h; n = 0
     * otherwise): pair i runs realisation i's field G (the rows above:
     * plain Monte Carlo's first n, bit for bit) and its antithetic -G
     * (qoi_anti, n x SF_SWEEP_NQ, in their units).  cost: a pair's mean
     * work [cell evaluations] (mlmc.h's model), cost_fine a plain
     * realisation's; per ratio over the m pairs whose both members are
     * finite: rho = corr(Q(G), Q(-G)), the mean of the pair means, se =
     * their std / sqrt(m), the Student interval at m - 1 degrees of
     * freedom, var_fine the variance of the 2 m members' ratios and vrf
     * = var_fine cost_fine / (se^2 work), the variance plain Monte Carlo
     * reaches at the same work over this estimator's. */
    struct {
        size_t n;
        double *qoi_anti;
        double cost, cost_fine, work;
        sf_sweep_anti q[SF_SWEEP_NQ];
    } anti;
} sf_sweep_point;

/* A Monte Carlo workspace over a scene's COF draws (montecarlo.h's
 * ws_alloc / ws_free): ctx is an sf_sweep_ws with s and the caller's data
 * set; each thread gets a copy with its own COF plan. */
struct sf_cof_plan;
struct sf_plan;
typedef struct {
    const sf_scene *s;
    const struct sf_plan *pl;   /* the scene's plan, made once (numplan.h) */
    const void *data;
    struct sf_cof_plan *plan;
    int companion;              /* 1: out[SF_SWEEP_NQ] = sf_sweep_companion */
} sf_sweep_ws;
void *sf_sweep_ws_alloc(void *ctx);
void sf_sweep_ws_free(void *ws);

/* Apply parameter `name` = value to s (SF_EPARSE with the reason). */
int sf_sweep_set(sf_scene *s, const char *name, double value, char *err, size_t errlen);

/* The deterministic reference of s (uniform COF at mu_mean, same T,
 * t_skip, eps_lambda and stepper): det[q] for each QoI.  SF_EINVAL with the
 * reason when one is not positive (no ratio can be formed: raise T). */
int sf_sweep_det(const sf_scene *s, double det[SF_SWEEP_NQ], char *err, size_t errlen);

/* One realisation of s: a COF drawn from plan (made for s) with rng, the
 * run, its QoIs (pv_x [m], pv_F [N], stick fraction [-]) into out. */
int sf_sweep_realise(const sf_scene *s, sf_cof_plan *plan, gsl_rng *rng, double out[SF_SWEEP_NQ]);

/* Run one sweep point. checkpoint may be NULL. threads 0: default. */
int sf_sweep_run(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume,
                 const char *label, sf_sweep_point *out, char *err, size_t errlen);
void sf_sweep_point_free(sf_sweep_point *p);

/* A sweep point with the control variate above: n realisations, each
 * with its companion C (for a window of tiles, which keeps only the
 * stretch of belt under the disc, C is NaN and cv[] NaN). */
int sf_sweep_run_cv(const sf_scene *s, size_t n, int threads, const char *checkpoint, int resume, const char *label,
                    sf_sweep_point *out, char *err, size_t errlen);

/* The companion of a COF drawn for scene s: the mean of mu_s over
 * SF_SWEEP_CV_POINTS belt points on the nominal path of the disc's
 * centre line and two lines R/2 to its sides, xb = -v_b t for t evenly
 * spread over [t_skip, T]; NaN for a window (sf_cof_window_margin > 0). */
#define SF_SWEEP_CV_POINTS 600
double sf_sweep_companion(const sf_cof *cof, const sf_scene *s);

/* A two-level sweep point (mlmc.h): the ratio means at the variance
 * plain Monte Carlo reaches with n_plain realisations, from n_pilot pairs
 * (reused as level 1's first) that set each level's sample size. */
int sf_sweep_run_mlmc(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                      sf_sweep_point *out, char *err, size_t errlen);

/* The same on boxes of boxes (mlmc.h: SF_MLMC_BOX): for a scene whose
 * plan draws cell averages (SF_EINVAL with the reason otherwise). */
int sf_sweep_run_mlmc_boxes(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                            sf_sweep_point *out, char *err, size_t errlen);

/* The same on every k-th node (mlmc.h: SF_MLMC_SUB): for a scene whose
 * plan draws point values on the circulant strip (SF_EINVAL otherwise). */
int sf_sweep_run_mlmc_sub(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                          sf_sweep_point *out, char *err, size_t errlen);

/* An antithetic sweep point (antithetic.h): the ratio means at the
 * variance plain Monte Carlo reaches with n_plain realisations, from
 * n_pilot pairs (reused as the first) that set the number of pairs. */
int sf_sweep_run_antithetic(const sf_scene *s, size_t n_plain, size_t n_pilot, int threads, const char *label,
                            sf_sweep_point *out, char *err, size_t errlen);

/* An estimator's sweep point at standard errors target_se[q] [-] of the
 * ratio means (q as the QoIs; NaN: no target for that ratio) instead of
 * plain's variance: est is SF_EST_MLMC, SF_EST_MLMC_BOXES,
 * SF_EST_MLMC_SUB or SF_EST_ANTITHETIC, sized as that estimator is (a
 * pilot of n_pilot pairs, then stages), n_max the cap on level 1's pairs
 * (level 0: SF_MLMC_N0_CAP n_max); a ratio with a target whose variance
 * cannot be estimated yet (fewer than 2 usable samples) asks for the
 * caps.  out->stop: SF_MCSTOP_TARGET when no level's size was held at
 * its cap, SF_MCSTOP_CAP otherwise.  SF_EINVAL
 * for a target not finite and > 0, none at all, or another estimator. */
int sf_sweep_run_estimator_se(const sf_scene *s, int est, const double target_se[SF_SWEEP_NQ], size_t n_pilot,
                              size_t n_max, int threads, const char *label, sf_sweep_point *out, char *err,
                              size_t errlen);

/* One run of scene s on plan pl and a drawn cof: its QoIs into out and,
 * when work is not NULL, its work [cell evaluations] (wrench evaluations
 * x quadrature cells). */
int sf_sweep_solve(const sf_scene *s, const sf_plan *pl, const sf_cof *cof, double out[SF_SWEEP_NQ], double *work);

/* A two-stage sweep point (mcstop.h): n_pilot realisations (the floor),
 * then as many more as the pilot says every ratio mean needs for a
 * standard error of target_se [-] (each QoI's target in its unit:
 * target_se x its deterministic value), at most n_max in all.  The rest
 * as sf_sweep_run. */
int sf_sweep_run_target(const sf_scene *s, double target_se, size_t n_pilot, size_t n_max, int threads,
                        const char *checkpoint, int resume, const char *label, sf_sweep_point *out, char *err,
                        size_t errlen);

/* The statistics of x[0], x[stride], ... x[(n - 1) stride]. */
int sf_sweep_stat_of(const double *x, size_t stride, size_t n, sf_sweep_stat *st);

/* From p->qoi, p->det, p->n and p->n_pilot: the ratios and every statistic above
 * (sf_sweep_run calls it; so may a caller that changed p->qoi). */
int sf_sweep_point_stats(sf_sweep_point *p);

/* The shortest %g text of x that reads back to x (0.1, not
 * 0.10000000000000001). */
void sf_sweep_fmt(char *buf, size_t len, double x);

/* The answer of a sweep point for one ratio (sf_sweep_estimate): the
 * estimate of the ratio mean [-] that the estimator which ran makes, its
 * standard error and interval at SF_SWEEP_CI_LEVEL, whatever the
 * estimator:
 *   plain:           rstat[q]'s mean and se, [rci_lo, rci_hi] (Student);
 *   target-se:       the same mean and se, and the interval the two-stage
 *                    design guarantees ([rci_lo, rci_hi]: Stein's);
 *   control-variate: cv[q] (the regression estimate); where no companion
 *                    was formed (a window of tiles: every companion[i]
 *                    NaN) plain's, and estimator SF_EST_PLAIN;
 *   mlmc, mlmc-boxes, mlmc-sub: ml.q[q] (the two-level estimate);
 *   antithetic:      anti.q[q] (the pairs' estimate).
 * u_num: the numerical error of the mean in ratio units, num[q].u_mean /
 * det[q] (NaN: not estimated).  n: the field draws the estimate
 * averages: the realisations (plain, target-se, control-variate), level
 * 0's samples + level 1's pairs (ml.n[0] + ml.n[1]), the pairs (anti.n).
 * work: the estimator's work [cell evaluations] (ml.work, anti.work);
 * NaN for the estimators that do not record it (sf_sweep_estimator_work).
 * stop: p->stop (mcstop.h). */
typedef struct {
    int estimator;              /* SF_EST_*: the estimator whose estimate this is */
    double estimate, se, ci_lo, ci_hi, u_num;
    size_t n;
    double work;
    int stop;
} sf_sweep_answer;
/* SF_EINVAL (a NaN answer) for q not a QoI or an unknown estimator. */
int sf_sweep_estimate(const sf_sweep_point *p, int q, sf_sweep_answer *a);
/* 1 when estimator est records its work (the summary's work column):
 * mlmc, mlmc-boxes, mlmc-sub, antithetic. */
int sf_sweep_estimator_work(int est);

/* The sweep's tables (TSV, a header line, then the rows of each point):
 * per realisation (--out), the summary per point (--summary) and the
 * diagnostics per point (--diagnostics).  A realisation's row ends with
 * its companion's QoIs (pv_x_coarse[m], pv_F_coarse[N],
 * stick_fraction_coarse[-]), rho (unum_rho[-]) and the a-priori relative
 * error (unum_apriori[-]): nan where the realisation had no companion.
 *
 * The summary (wide): param, value, per ratio q of pv_x_ratio, pv_F_ratio,
 * stick_fraction_ratio the answer above, q_estimate[-], q_se[-],
 * q_ci95_lo[-], q_ci95_hi[-], q_u_num[-], then n, work (only with work
 * != 0: every point of the sweep then has it, or nan), estimator, stop.
 * Long: one row per point and ratio, param value qoi estimate se ci_lo
 * ci_hi u_num n estimator stop unit (unit: of estimate .. u_num, "-").
 * The diagnostics: every statistic of the point, the columns of each
 * estimator (nan without it). */
void sf_sweep_write_header(FILE *f);
void sf_sweep_write_rows(FILE *f, const char *param, double value, const sf_sweep_point *p);
void sf_sweep_summary_header(FILE *f, int work);
void sf_sweep_summary_row(FILE *f, const char *param, double value, const sf_sweep_point *p, int work);
void sf_sweep_summary_long_header(FILE *f);
void sf_sweep_summary_long_rows(FILE *f, const char *param, double value, const sf_sweep_point *p);
/* The estimator's tuples (--tuples): what each estimator's interval is
 * a function of, one row per sample, columns param, value, estimator,
 * level, index, a_pv_x a_pv_F a_stick_fraction, b_pv_x b_pv_F
 * b_stick_fraction (ratios [-], %.17g, nan where a level has no b):
 *   row     plain, target-se: a the ratios;
 *   cv      control-variate: a the ratios, b_pv_x the companion C [-]
 *           (a COF), b_pv_F its known mean mu_mean;
 *   pair    antithetic: a the G member's ratios, b the -G member's;
 *   level0  mlmc*: level 0's sample (a coarse run, or a coarse antithetic
 *           pair's mean on a derived field), in a;
 *   level1  mlmc*: a the pair's fine ratios, b its coarse;
 *   cost    mlmc*: a_pv_x, a_pv_F level 0's and level 1's mean work per
 *           sample; antithetic: a_pv_x a pair's [cell evaluations]
 *           (mlmc.h's work model).
 * The ratios are qoi / det as the estimators form them: an estimator's
 * stage rule and interval (antithetic.h: sf_anti_stage, sf_anti_interval;
 * mlmc.h: sf_mlmc_next, sf_mlmc_interval; sf_sweep_point_stats) give the
 * point's answer again from these rows with det = 1. */
void sf_sweep_tuples_header(FILE *f);
void sf_sweep_write_tuples(FILE *f, const char *param, double value, const sf_sweep_point *p);
void sf_sweep_diagnostics_header(FILE *f);
void sf_sweep_diagnostics_row(FILE *f, const char *param, double value, const sf_sweep_point *p);

#ifdef __cplusplus
}
#endif
#endif
