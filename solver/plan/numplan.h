/* slipfield: the plan of a run, made from the scene before anything is
 * built (sf_plan, at the end: the COF model and generator, the strip, the
 * numerical settings, what is skipped), and its accuracy-driven numerical
 * part ("fast by default", docs/design.md sec. 6): ONE place decides the numerical
 * settings of the oscillator from the scene's `qoi_tol`: the relative
 * error wanted in a realisation's quantities of interest (PV_x, PV_F,
 * stick fraction).
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

typedef enum { SF_COF_UNIFORM = 0, SF_COF_VARIABLE = 1, SF_COF_FIELD = 2 } sf_cof_kind;

/* ---- The COF of a run: what cof.c builds and draws (sf_cof_plan_alloc).
 *
 * The plan decides what a scene needs (one place): cof = uniform draws
 * nothing; variable draws one lognormal value; field samples a lognormal
 * field on the belt strip the disc can visit during [0, T] (by circulant
 * embedding of the whole strip; or, cof_generator = tiles or auto above
 * SF_COF_AUTO_POINTS strip points, in a window of it that follows the
 * disc: see below):
 *   xb in [-v_b T - B, B],  yb in [-W, W],
 *   B = R + 2 mu_hi m g / k + 2 h,  W = strip_halfwidth + R + 2 h (0: W = B),
 * where 2 mu_hi m g / k (mu_hi = mu_mean + 4 mu_std) bounds the spring
 * excursion |r| (the spring force never exceeds twice the largest
 * friction force it balances).  Grid spacing h = l/8: bilinear
 * interpolation then costs 0.7% of the field's std, RMS
 * (cases/contact/interpolation).  A grid above SF_COF_MAX_POINTS is
 * refused with SF_ETOOBIG and the reason in err.
 * Shortcut: when the strip's diagonal E is so short against l that any
 * two of its points have correlation >= 1 - 1e-6 ((E/l)^2 <= 1e-6), the
 * field is one random variable over the run and the plan draws one
 * (kind SF_COF_VARIABLE; info.shortcut = 1); so it does when mu_std = 0.
 * A scene with shortcuts = false gets the field whatever l and E
 * (cases/plan verify the shortcut against it). */
#define SF_COF_SHORTCUT_E2 1e-6
typedef struct {
    sf_cof_kind kind;
    double x0, y0, dx, dy;   /* strip origin and spacing [m] */
    size_t nx, ny;           /* strip grid points */
    double bound;            /* B [m] */
    int shortcut;            /* 1: a field scene planned as one variable */
    double strip_diag;       /* E: diagonal of the strip the disc can visit [m] (field scenes) */
    double strip_points;     /* grid points of the whole strip (field scenes) */
    int generator;           /* SF_COFGEN_CIRCULANT or SF_COFGEN_TILES (field scenes) */
    double margin;           /* tiles: M [m]; nx x ny is then the window, x0 the strip's start */
    double box;              /* > 0: cof_model = cell_average, the cells' side [m] (cellavg.h) */
    int belt_noise;          /* 1: cof_generator = belt_noise (generator TILES on noise.h's white noise, lattice
                                x = (i + 1/2) dx, y = (j + 1/2) dy, dx = dy its cells' side) */
    int noise_level;         /* belt_noise: the noise's level (noise.h) */
    size_t box_step;         /* belt_noise with box > 0: noise cells per grid step (the box centres' spacing dx =
                                box_step cells, at most box/3; cellavg.h); 0 otherwise */
} sf_cof_plan_info;

/* The strip's bounds B0 and W0 [m] before the grid's margin (above:
 * B = B0 + 2 h, W = W0 + 2 h), and the points of a strip grid of spacing
 * h [m] over [0, T] (the accuracy plan sizes the cell-averaged strip
 * with it). */
void sf_plan_strip_bounds(const sf_scene *s, double *B0, double *W0);
double sf_plan_strip_points(const sf_scene *s, double h);

/* cof_generator = auto takes the tiles above this many strip points.  The
 * circulant's memory grows with v_b T / l^2 (286 MB at 1.7e6 strip points,
 * l = 0.05 m, Table 1, T = 100 s; 1.1 GB at 6.8e6, l = 0.025 m), and its
 * strip is sized by the spring-excursion bound, about 3x the belt the
 * disc visits at Table 1: at l/R = 0.05-0.2 the tiles (the same law,
 * noise only where the window goes) make a realisation 2.2-2.6x cheaper
 * in a sweep, at l/R = 0.5-1 0.7-0.9x (docs/design.md sec. 6.1).  2^20
 * takes them below about l = 0.064 m (l/R = 0.13) at Table 1; Table 1's
 * own l = 0.1 m (0.43e6 points) stays on the circulant, where the tiles
 * would also pay, because it would redraw the field of most cases.
 * Until 2026-11-27 the threshold was 2^21, set for memory only. */
#define SF_COF_AUTO_POINTS ((size_t)1 << SF_COF_AUTO_LOG2)

/* The largest number of strip (or window) grid points a plan accepts. */
#define SF_COF_MAX_POINTS ((size_t)1 << 24)

/* Cells per correlation length below which a quadrature is warned about. */
#define SF_PLAN_CELLS_PER_L 1.0
/* The largest ring count the plan chooses by itself. */
#define SF_PLAN_MAX_RINGS 128
/* The loosest rtol the plan chooses: above it stick onsets are missed at
 * some fields (numplan.c (5)). */
#define SF_PLAN_MAX_RTOL 1e-6
/* The largest CV = mu_std / mu_mean the plan's error models were
 * calibrated on (the quadrature's CV factor, the time model's and the
 * cell-average model's designs, err_pred's fit: CV 0.05-1, numplan.c;
 * cases/plan/design-quick) and the lognormal map's marginals are verified
 * at (cases/lognormal/marginal-ks-cv10); `run --explain` warns above it. */
#define SF_PLAN_CV_MAX 1.0

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
/* On belt noise the box averages are made in a window that follows the
 * disc (no strip to hold, cof.c): auto takes them up to this many cells
 * per diameter (the error model beyond 82 cells is checked by
 * cases/plan/beltbox-qoi.md at 121 cells; docs/design.md sec. 4.4). */
#define SF_PLAN_CELLAVG_BELT_MAX_CELLS 160
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

/* The predicted relative QoI error of the cell-average model for scene s
 * (its l/R, the COF's CV, its belt-speed number) at `cells` per diameter
 * (numplan.c has the measurements). */
double sf_numplan_err_cell(const sf_scene *s, size_t cells);
/* The belt-speed number v_b omega_n / (mu_mean g), omega_n = sqrt(k/m)
 * (dimensionless): the belt speed against the slip-speed scale of a
 * stick-slip cycle; 0.071 at Table 1. */
double sf_numplan_belt_number(const sf_scene *s);

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
    double err_total;        /* err_quad + err_time: the budget the settings are chosen on (an envelope) */
    double err_pred;         /* the predicted QoI error: below it for 95% of realisations (fitted on a design,
                                numplan.c); err_total outside the fit's box; NaN for rk4 */
    int pred_fitted;         /* 1: err_pred is the fit's (inside its box) */
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

/* The constants of the predicted error inside its box (numplan.c):
 *   err_pred = err_total factor (l/R)^-lr_exp exp(cv_coef CV + mu_coef mu_mean),
 * for the check that refits them from their stored design data. */
typedef struct {
    double factor, lr_exp, cv_coef, mu_coef;
} sf_numplan_pred_model;
void sf_numplan_pred_model_get(sf_numplan_pred_model *m);

/* ---- The plan of a run: one value, made from the scene before anything
 * is built.  The builders take it: the COF plan (cof.h:
 * sf_cof_plan_build: the field generator, its grid), the oscillator
 * (oscillator.h: sf_osc_alloc_plan: the quadrature, the stepper) and
 * what the run skips; `slipfield run --explain` prints it
 * (sf_plan_explain).  The flow runs one way, scene -> plan -> builders:
 * this module includes none of theirs (make layering). */
enum {   /* the COF model: what the wrench sees */
    SF_PLAN_MODEL_UNIFORM = 0,     /* one value, no draw */
    SF_PLAN_MODEL_VARIABLE = 1,    /* one value per realisation (cof = variable, or the one-variable shortcut) */
    SF_PLAN_MODEL_POINT = 2,       /* the field's values at the quadrature's points */
    SF_PLAN_MODEL_CELL_AVERAGE = 3 /* the field averaged over the quadrature's cells (cellavg.h) */
};
enum { SF_PLAN_STICK_EQUATORIAL = 0, SF_PLAN_STICK_SECTION = 1 };   /* the stick test (scene key exact_section) */

typedef struct sf_plan {
    int cof_model;           /* SF_PLAN_MODEL_* */
    sf_cof_plan_info cof;    /* the COF: kind, generator, strip grid and bounds (what cof.c builds) */
    double cell_std;         /* cell averages: the effective field's std sqrt(Var mu_h) [-]; 0 otherwise */
    sf_numplan num;          /* quadrature, cells, stepper, rtol, predicted errors */
    int history;             /* 1: the run streams its time history; 0: only the QoIs, accumulated online
                                (scene key history; a caller asking for a statistic only clears it) */
    int stick_test;          /* SF_PLAN_STICK_*: the limit surface is never computed in full */
} sf_plan;

/* The plan of scene s (all of it): SF_EINVAL or SF_ETOOBIG with the reason
 * in err for a scene that cannot be planned (an invalid COF marginal, a
 * cell-average model it does not support, a strip or window above
 * SF_COF_MAX_POINTS, qoi_tol outside (0, 1)). */
int sf_plan_make(const sf_scene *s, sf_plan *p, char *err, size_t errlen);
/* Its COF part only (cof_model, cof, cell_std; the rest zero): what
 * sf_cof_plan_alloc needs, with the same refusals. */
int sf_plan_cof(const sf_scene *s, sf_plan *p, char *err, size_t errlen);
/* The plan's record for `slipfield run --explain`: the COF, each numerical
 * choice with its predicted error (sf_numplan_explain), what is skipped. */
void sf_plan_explain(const sf_plan *p, const sf_scene *s, FILE *f);

#ifdef __cplusplus
}
#endif
#endif
