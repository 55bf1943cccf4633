/* slipfield: the accuracy-driven numerical plan of a dynamics run (issue
 * 14, "fast by default").  ONE place decides the numerical settings of
 * sf_osc_alloc from the scene's `qoi_tol`: the relative error wanted in a
 * realisation's quantities of interest (PV_x, PV_F, stick fraction).
 *
 *  - quadrature resolution (`cells`: polar rings, or Cartesian cells per
 *    diameter), from l/R and the tolerance;
 *  - the stepper (`integrator`) and its `rtol`, from the tolerance.
 *
 * A key the scene sets explicitly (cells > 0, rtol > 0, integrator other
 * than adaptive) overrides the plan's choice; the plan then predicts the
 * error of that setting instead.  A quadrature whose cells are coarse
 * against l (cell size above l / SF_PLAN_CELLS_PER_L) is reported in
 * `warning` with the reason (the run goes on: explicit keys are obeyed).
 * The strip grid spacing (l/8, cof.h) is not a knob here: a solution
 * verification compares runs on the same strip field, and the field's own
 * interpolation error is cof.h's concern (cases/contact/interpolation).
 *
 * The rule and its calibration (bench section `plan`, error vs rings and
 * rtol across l/R on the same fields) are in numplan.c. */
#ifndef SF_NUMPLAN_H
#define SF_NUMPLAN_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdio.h>
#include "scene.h"

/* Cells per correlation length below which a quadrature is warned about. */
#define SF_PLAN_CELLS_PER_L 1.0
/* The largest ring count the plan chooses by itself. */
#define SF_PLAN_MAX_RINGS 128

enum { SF_PLAN_CHOSEN = 0, SF_PLAN_SCENE = 1 };   /* where a setting came from */

/* The COF model (scene key cof_model, cellavg.h).  point: the quadrature
 * samples the field at its cells (cells resolving l).  cell_average: a
 * Cartesian quadrature of SF_PLAN_CELLAVG_CELLS to _MAX_CELLS cells per
 * diameter (the plan's choice from qoi_tol, or `cells`) whose cells see the effective field, the lognormal field
 * averaged over a cell (exact box-averaged covariance, Gaussian marginal
 * matched in mean and variance).  auto takes cell_average below
 * l/R = SF_PLAN_CELLAVG_LR for a field COF (not pre-corrected, std > 0,
 * shortcuts on, `cells` not set, its strip at most
 * SF_PLAN_CELLAVG_MAX_POINTS) where its predicted error
 * (sf_numplan_err_cell) is within 3/4 of qoi_tol with at most
 * _MAX_CELLS cells (below l/R = 0.044 at Table 1 and qoi_tol = 1e-3, 59
 * or 60 cells per diameter): there the point model needs ~3.8
 * (R/l)^0.71 rings (49k cells at l/R = 0.01) while the random part of the
 * wrench is only ~CV l/R of it.  numplan.c has the measurements. */
#define SF_PLAN_CELLAVG_LR 0.05
#define SF_PLAN_CELLAVG_CELLS 32
#define SF_PLAN_CELLAVG_MAX_CELLS 60   /* within the error model's measured range, 16..82 (numplan.c) */
/* auto takes cell averages only while their strip (one circulant over
 * [0, T], ~64 bytes a point) has at most this many points: 2^22, ~270 MB;
 * at Table 1, 32 cells, up to T ~ 1000 s.  Longer runs get the point
 * model's tiles (memory set by the disc, not by v_b T). */
#define SF_PLAN_CELLAVG_MAX_POINTS 4194304.0

/* 1 when scene s runs the cell-average model; then *cells (cells per
 * diameter) and *box (the cell side 2R/cells [m]); 0 (point model)
 * otherwise.  Called by the COF plan (which draws the effective field)
 * and by sf_numplan_make (which sets the quadrature): one rule. */
int sf_numplan_cell_average(const sf_scene *s, size_t *cells, double *box);

/* The predicted relative QoI error of the cell-average model at l/R with
 * coefficient of variation cv and `cells` per diameter (numplan.c). */
double sf_numplan_err_cell(double l_over_R, double cv, size_t cells);

typedef struct {
    double qoi_tol;          /* requested relative QoI error [-] */
    int quadrature;          /* 1: the slip wrench is a quadrature (field COF, or shortcuts off) */
    double l_over_R;         /* [-] */
    size_t cells;            /* resolution (rings or cells per diameter); 0 without quadrature */
    int cells_from;
    double cell_size;        /* typical cell size [m]: R / rings (polar), 2R / cells (Cartesian) */
    int cell_average;        /* 1: cof_model cell_average (Cartesian cells = the boxes) */
    int cof_model_from;
    double box_over_l;       /* cell side / l (cell averages) [-] */
    int layout;              /* the quadrature's layout (sf_layout): the scene's, Cartesian for cell averages */
    double err_quad;         /* predicted relative QoI error of the quadrature [-] */
    double rtol;             /* the stepper's relative tolerance [-] */
    int rtol_from;
    int integrator;          /* SF_INTEG_RK8PD, _RKCK or _RK4: the stepper that runs */
    int integrator_from;
    double err_time;         /* predicted relative QoI error of the time integration [-] */
    double err_total;        /* err_quad + err_time */
    char warning[240];       /* empty, or why a setting cannot meet qoi_tol or resolve l */
} sf_numplan;

/* The plan for scene s; quadrature: whether the wrench is a quadrature
 * (sf_osc_alloc knows: field COF, or shortcuts = false on a constant one).
 * SF_EINVAL with the reason in err for an impossible request. */
int sf_numplan_make(const sf_scene *s, int quadrature, sf_numplan *p, char *err, size_t errlen);

/* The plan's record, one line per choice with its predicted error (for
 * `slipfield run --explain`). */
void sf_numplan_explain(const sf_numplan *p, FILE *f);

/* The predicted relative QoI errors of the plan's models (numplan.c), for
 * the checks that verify them; cv = mu_std / mu_mean). */
double sf_numplan_err_quad(double l_over_R, double cv, size_t rings);
double sf_numplan_err_time(double rtol);

#ifdef __cplusplus
}
#endif
#endif
