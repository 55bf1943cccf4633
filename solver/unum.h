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

enum { SF_UNUM_PVX = 0, SF_UNUM_PVF = 1, SF_UNUM_SF = 2, SF_UNUM_NQ = 3 };

#define SF_UNUM_FS 3.0          /* the GCI's safety factor for an assumed order */
#define SF_UNUM_MAX_RTOL 1e-5   /* numplan.c: above it the stick onsets are missed */

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

#ifdef __cplusplus
}
#endif
#endif
