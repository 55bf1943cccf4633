/* slipfield: a two-level Monte Carlo estimator of a sweep point's ratio
 * means (sweep.h: sf_sweep_run_mlmc).
 *
 *   E[Q_f] = E[Q_c] + E[Q_f - Q_c]
 *
 * Q_f: a realisation on the scene's plan (numplan.h); Q_c: the same
 * scene on a coarse plan (sf_mlmc_coarse_plan) whose COF draw is the
 * fine plan's, so a pair (fine, coarse) runs on ONE field.  Level 0: n0
 * coarse realisations on fields of their own (stream seed0 =
 * sf_mc_seed(seed, SF_MLMC_LEVEL0_STREAM)); level 1: n1 pairs on the
 * streams plain Monte Carlo uses (realisation i: sf_mc_seed(seed, i)), so
 * level 1's fine values are plain Monte Carlo's first n1.  Both terms are
 * unbiased whatever the coupling; the coupling only makes Var(Q_f - Q_c)
 * small.
 *
 * Sample sizes (Giles' allocation, N_l ~ sqrt(V_l / C_l)): the first
 * n_pilot pairs give, per ratio, V_1 = Var(Q_f - Q_c) and Var Q_f and the
 * costs C_0, C_1, level 0's first n_pilot samples V_0 (Var Q_c, or on a
 * derived field the variance of its pairs' means); the target variance
 * of each ratio mean is Var Q_f / n_plain (plain Monte Carlo's at
 * n_plain; sweep.h: sf_sweep_run_estimator_se takes a standard error
 * instead), and
 *   N_l = ceil( sqrt(V_l / C_l) (sqrt(V_0 C_0) + sqrt(V_1 C_1)) / target ),
 * the largest over the ratios, n_pilot <= n1 <= n_plain and
 * n_pilot <= n0 <= SF_MLMC_N0_CAP n_plain, with each V_l taken per
 * sample drawn (V_l n_l / m_l where m_l are usable), so that the sizes
 * bound the estimate's own sum V_l / m_l.  The pilots are the levels'
 * first samples (as in Giles' algorithm).  The sizes are reached in
 * stages, as in Giles' algorithm too (sf_mlmc_stage): each stage
 * recomputes them from every sample so far and at most doubles a level,
 * so a pilot's noisy
 * variance (10 pairs of a heavy-tailed ratio) neither commits the whole
 * run to 4x plain's samples nor stops it at the pilot; the stages stop
 * when no level asks for more.  Every decision is a function of the
 * values in index order: the same bits for any thread count.
 *
 * Costs are a work model, not a clock, so that the sizes (and every byte)
 * do not depend on the machine or the thread count: a run's wrench
 * evaluations x quadrature cells, plus a draw's strip points x
 * SF_MLMC_DRAW_WORK (per the generator), plus SF_MLMC_RUN_WORK per run.
 * Measured at Table 1, T = 100 s: 1.5-2.6 ns per cell evaluation (0.1 to
 * 1000 l/R), a circulant lognormal draw 2.2-2.7e-7 s a strip point, a
 * cell-average draw (one real FFT) 4.0-4.2e-8 s, ~1 ms of fixed cost a
 * run (the bench section `estimators` prints the draw's share it gives). */
#ifndef SF_MLMC_H
#define SF_MLMC_H
#ifdef __cplusplus
extern "C" {
#endif

#include "numplan.h"
#include "sweep.h"

/* The coarse plan: half the fine plan's rings or cells per diameter (at
 * least 2) for the point model, the same cells for cell averages (their
 * cells are the field's boxes: the draw is tied to them), and the
 * stepper's rtol raised to SF_MLMC_RTOL.  Measured (Table 1, T = 100 s,
 * 12 fields per l/R): Var(Q_f - Q_c) / Var Q_f <= 0.05 for every ratio at
 * l/R = 0.01 to 1000, while rtol = 1e-4 already decouples the pair (a
 * stick phase found in one run and missed in the other: ratio > 1). */
#define SF_MLMC_RTOL 1e-5
void sf_mlmc_coarse_plan(const sf_plan *fine, sf_plan *coarse);

/* The two levels (est: SF_EST_MLMC, SF_EST_MLMC_BOXES or SF_EST_MLMC_SUB)
 * at standard-error targets tse[q] (sweep.h: sf_sweep_run_estimator_se,
 * which checks them). */
int sf_mlmc_run_se(const sf_scene *s, int est, const double *tse, size_t n_pilot, size_t n_max, int threads,
                   const char *label, sf_sweep_point *out, char *err, size_t errlen);

/* A stage's size for a level of n samples whose estimate from them asks
 * for want: want, at most 2 n, never below n. */
size_t sf_mlmc_stage(size_t n, size_t want);

/* The work model (above), in cell evaluations. */
#define SF_MLMC_DRAW_WORK_POINT 140.0   /* a circulant or tiled lognormal strip point */
#define SF_MLMC_DRAW_WORK_CELL 25.0     /* a cell-average strip point (one real FFT) */
#define SF_MLMC_RUN_WORK 6e5            /* a run's fixed cost */
double sf_mlmc_draw_work(const sf_cof_plan_info *info);

/* A Monte Carlo workspace (montecarlo.h's ws_alloc / ws_free) for the
 * estimators that run more than one solve per draw (this one and
 * antithetic.h): ctx is an sf_mlmc_ws with w's scene and fine plan set;
 * each thread's copy has its own COF plan and the work of its draw. */
typedef struct {
    sf_sweep_ws w;            /* the sweep's: scene, fine plan, COF plan */
    const sf_plan *coarse;    /* two levels: the coarse plan (NULL otherwise) */
    double draw;              /* a draw's work */
    /* boxes of boxes (sf_sweep_run_mlmc_boxes; 0 and NULL otherwise):
     * level 1's coarse field is the fine one's b x b box means, level 0
     * draws its own from cdraw (this thread's cplan) in antithetic pairs */
    size_t b;
    int sub;                  /* 1: level 1's coarse field is every b-th node instead (sf_sweep_run_mlmc_sub) */
    const sf_plan *cdraw;
    struct sf_cof_plan *cplan;
    double cdraw_work;        /* a level-0 draw's work */
} sf_mlmc_ws;
void *sf_mlmc_ws_alloc(void *ctx);
void sf_mlmc_ws_free(void *ws);

/* Two levels on boxes of boxes (cof.h: sf_cof_box_means), for a scene
 * whose plan draws cell averages: the fine plan takes the plan's cells
 * per diameter rounded up to a multiple of SF_MLMC_BOX (59 -> 60 at
 * Table 1: another fine model, no less accurate by numplan.c's error
 * model) and a strip SF_MLMC_BOX_PAD nodes wider each side (the coarse
 * grid's nodes sit inside the fine one's); the coarse run has cells / b
 * cells, whose boxes are the coarse field's, and the stepper's rtol
 * raised as above.  Level 1: a pair runs the fine plan on a drawn field
 * and the coarse plan on its box means (the same law as level 0's own
 * draw, exactly, up to each circulant embedding's own error: cof.h);
 * level 0: antithetic pairs (G, -G) of coarse
 * runs on fields drawn on the coarse grid (stream as above), a sample
 * being the pair's mean.  Sizes as above, level 0's variance (of its
 * pair means) and cost from a pilot of its own: its first n_pilot pairs,
 * reused as its first samples; its cost a coarse-grid draw and two
 * coarse runs.
 * Measured (the coupling bench, 60 fields, two seeds): Var(Q_f - Q_c) /
 * Var Q_f 0.07 (l/R = 0.01 and 0.03). */
#define SF_MLMC_BOX 4
#define SF_MLMC_BOX_PAD 8
/* The fine, coarse-run and level-0 draw plans of boxes of boxes from
 * scene s (SF_EINVAL with the reason where s's plan is not cell
 * averages). */
int sf_mlmc_box_plans(const sf_scene *s, sf_plan *fine, sf_plan *coarse, sf_plan *cdraw, char *err, size_t errlen);

/* Two levels on every k-th node (cof.h: sf_cof_subsample), for a scene
 * whose plan draws point values on the circulant strip: the fine plan is
 * the scene's (level 1's fine values are plain Monte Carlo's first n1,
 * bit for bit); level 1's coarse run (the coarse plan above) is on the
 * fine field at every SF_MLMC_SUB-th node, level 0's on fields drawn on
 * that coarser grid (the same law, exactly, up to each circulant
 * embedding's own error), in antithetic pairs sized from a pilot of its
 * own, as boxes of boxes.  Measured (the coupling bench): Var(Q_f - Q_c)
 * / Var Q_f 0.015 at l/R = 0.2, 0.08-0.21 at 0.5-2 for k = 2. */
#define SF_MLMC_SUB 2
/* Its fine, coarse-run and level-0 draw plans (SF_EINVAL with the
 * reason where s's plan draws cell averages, tiles or no field). */
int sf_mlmc_sub_plans(const sf_scene *s, sf_plan *fine, sf_plan *coarse, sf_plan *cdraw, char *err, size_t errlen);

#define SF_MLMC_N0_CAP 4                /* n0 <= 4 n_plain */
#define SF_MLMC_LEVEL0_STREAM ((size_t)-1)

/* The sizes Giles' rule asks for at target variances target[q] of the
 * ratio means (above), unclamped; a ratio whose target or variances are
 * not finite, or target not > 0, asks for none (0). */
void sf_mlmc_want(const double *v0, const double *v1, const double *target, int nq, double c0, double c1,
                  double *m0, double *m1);

/* The sample sizes from the pilot's per-ratio variances v0[q], v1[q],
 * vf[q] (nq <= SF_SWEEP_NQ) and the costs c0, c1 (the rule above, at
 * target vf[q] / n_plain); a ratio whose variance is not finite and
 * positive sets no size. */
void sf_mlmc_sizes(const double *v0, const double *v1, const double *vf, int nq, double c0, double c1,
                   size_t n_plain, size_t n_pilot, size_t *n0, size_t *n1);

/* The stage rule above as a function of the samples alone (what the sweep
 * runs, and what cases/montecarlo/coverage-estimators.md replays on
 * stored samples): level 1's pair i has its fine QoIs at
 * pairs[i stride + q] and its coarse at pairs[i stride + off + q], level
 * 0's sample i at lev0[i stride0 + q] (q < SF_SWEEP_NQ), det[q] the
 * deterministic values the ratios divide by, c0 and c1 the levels' mean
 * work per sample; from the first n0, n1, the next stage's sizes *g0,
 * *g1 (both unchanged: stop) and *capped (a size asked for is above its
 * cap: n_plain, SF_MLMC_N0_CAP n_plain).  tse as sf_anti_stage's. */
int sf_mlmc_next(const double *pairs, size_t stride, size_t off, size_t n1, const double *lev0, size_t stride0,
                 size_t n0, const double *det, double c0, double c1, size_t n_pilot, size_t n_plain,
                 const double *tse, size_t *g0, size_t *g1, int *capped);

/* The two-level estimate and interval of ratio q from those samples
 * (sweep.h: sf_sweep_ml; boxes: level 0 on a derived field, its values
 * pair means, var_fine the pairs' own): m, var, var_fine, mean, se, the
 * Welch-Satterthwaite df and the Student interval at it; e->vrf NaN (it
 * needs the work: the sweep sets it). */
int sf_mlmc_interval(const double *pairs, size_t stride, size_t off, size_t n1, const double *lev0, size_t stride0,
                     size_t n0, const double *det, int q, int boxes, sf_sweep_ml *e);

#ifdef __cplusplus
}
#endif
#endif
