/* slipfield: the a-posteriori numerical error of one run's quantities of
 * interest (u_num of ASME V&V 20), from a companion solve.
 *
 * The companion is the same realisation (the same COF, the same scene) at
 * a COARSER numerical setting than the accuracy plan's (numplan.h):
 * ceil(2/3) of the quadrature's rings (or Cartesian cells per diameter),
 * rho_q = (cells / cells_c)^2 ~ 2.25, and rtol x rho_q^2 (x16 without a
 * coarsened quadrature; 4x at least, 1e-5 at most where that allows; a
 * fixed-step rk4 run: twice dt).  A coarser companion costs a fraction of
 * the run (0.04-0.45 of it, make bench BENCH_SECTIONS=unum: ~0.44 of the
 * cells, fewer steps, no field draw); a finer one would cost more than the
 * run.  If the errors behave as their models (numplan.c: the quadrature's
 * as rings^-2 or faster, the stepping's as sqrt(rtol) or faster), the
 * companion's error is at least rho times the run's, rho = the smaller of
 * rho_q and sqrt(rtol_c / rtol) (16 for rk4 at 2 dt), so the run's error
 * is about |Q - Q_c| / (rho - 1); the estimate reported is the two-level
 * grid convergence index with the safety factor of an order that is
 * assumed, not observed (Fs = 3, Roache; ASME V&V 20):
 *
 *     u_num(Q) = 3 |Q - Q_c| / (rho - 1)   (~ 2.4 |Q - Q_c| at rho = 2.25).
 *
 * The cell-average model (cellavg.h) cannot be coarsened on the same
 * realisation (its COF is the field averaged over the quadrature's own
 * cells), so its companion changes the stepping only and the quadrature's
 * part is the plan's a-priori model error (sf_numplan_err_cell) times |Q|,
 * added and flagged (`apriori`). */
#ifndef SF_UNUM_H
#define SF_UNUM_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdio.h>
#include "cof.h"
#include "numplan.h"
#include "oscillator.h"
#include "scene.h"
#include "sweep.h"

enum { SF_UNUM_PVX = 0, SF_UNUM_PVF = 1, SF_UNUM_SF = 2, SF_UNUM_NQ = 3 };

#define SF_UNUM_FS 3.0          /* the GCI's safety factor for an assumed order */
#define SF_UNUM_MAX_RTOL SF_PLAN_MAX_RTOL   /* the plan's cap: above it stick onsets are missed */

typedef struct {
    double q[SF_UNUM_NQ];       /* the run's pv_x [m], pv_F [N], stick fraction [-] */
    double qc[SF_UNUM_NQ];      /* the companion's */
    double u[SF_UNUM_NQ];       /* u_num, in the QoI's unit (NaN: a QoI without a complete cycle) */
    double apriori[SF_UNUM_NQ]; /* the a-priori part included in u (cell averages), else 0 */
    size_t cells, cells_c;      /* the run's and the companion's quadrature (0: closed form) */
    double rtol, rtol_c;        /* the run's and the companion's rtol (rk4: dt, dt_c) */
    double rho;                 /* the assumed ratio of the companion's error to the run's */
    int cell_average;           /* 1: the quadrature's part is a-priori */
    int fixed_step;             /* 1: rk4 at fixed dt (rtol, rtol_c hold dt, dt_c) */
} sf_unum;

/* The companion's scene for a run of scene s under plan p (the plan of
 * sf_osc_alloc for s); *rho receives the assumed error ratio. */
void sf_unum_companion(const sf_scene *s, const sf_numplan *p, sf_scene *c, double *rho);

/* Run the companion of a finished run (scene s, COF cof, its plan p and
 * its result res) and fill u.  SF_SUCCESS, or the companion's error code
 * with the reason in err. */
int sf_unum_estimate(const sf_scene *s, const sf_cof *cof, const sf_numplan *p, const sf_osc_result *res, sf_unum *u,
                     char *err, size_t errlen);

/* u as `key = value` lines (u_pv_x, u_pv_F, u_stick_fraction, the
 * companion's settings) after a comment that says what the estimate is. */
void sf_unum_write(const sf_unum *u, FILE *f);

/* The numerical error of a sweep point's means (sf_sweep_num, sweep.h).
 * The companion above runs on the first sf_unum_sweep_subset(n)
 * realisations, each the row's own: the COF the rows' plan (p->plan,
 * recorded by the estimator that made them: mlmc-boxes' is not the
 * scene's) draws from the row's stream, the same bits, and that plan's
 * numerical settings coarsened as above (realisations are exchangeable,
 * so the first ones are a random subset):
 * ceil(n / 4), at least 2 (all of them when n < 2).  Each gives the signed
 * Richardson estimate of its own error, e_i = (Q_c,i - Q_i) / (rho - 1);
 * the mean's numerical error is their mean (the random part of the errors
 * averages out over realisations, as the QoIs' own spread does), with its
 * standard error; u_mean = Fs (|bias| + t bias_se) bounds it with the
 * GCI's safety factor, plus, for cell averages, the a-priori part
 * err_cell |mean|.  Cost: ceil(n / 4) field draws and companions (a
 * companion 0.04-0.45 of a run): at most ~0.36 of the sweep.  The
 * companion's run is bit-identical for any thread count (montecarlo.h). */
size_t sf_unum_sweep_subset(size_t n);

/* Run the companions of the sweep point p of scene s (p->qoi, p->n,
 * p->stat and p->plan from sf_sweep_run or an estimator's run; a point
 * with no plan recorded, p->planned = 0, takes s's), keep them (p->num_m, num_qc, num_rho,
 * num_apriori: sweep.h) and fill p->num from them (sf_unum_sweep_num).
 * SF_SUCCESS, or the first companion's error code with the reason in err
 * (p->num is then left zero and no companion kept: not estimated). */
int sf_unum_sweep(const sf_scene *s, sf_sweep_point *p, int threads, char *err, size_t errlen);

/* p->num from the companions p keeps (and p->qoi, p->stat): per QoI the
 * estimates e_i = (Q_c,i - Q_i) / (rho_i - 1) of realisations 0 .. num_m
 * - 1 into sf_unum_sweep_stats, with the a-priori part num_apriori[0]
 * |stat.mean|.  Zero when p keeps none.  SF_SUCCESS or SF_ENOMEM. */
int sf_unum_sweep_num(sf_sweep_point *p);

/* The statistics of one QoI's estimates e[0], e[stride], ... (m of them,
 * non-finite ones left out) into *num; apriori: the a-priori part added
 * to u_mean (0 for the point model).  SF_SUCCESS or SF_ENOMEM. */
int sf_unum_sweep_stats(const double *e, size_t stride, size_t m, double apriori, sf_sweep_num *num);

#ifdef __cplusplus
}
#endif
#endif
