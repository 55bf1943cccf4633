/* slipfield: the high-level calls: a scene in, a realisation's QoIs with
 * their numerical error out, through opaque handles any FFI can hold
 * (python/slipfield calls them with ctypes).
 *
 * Realisation i of a scene is the one `slipfield sweep` solves as its row
 * i, `slipfield run --realisation i` and `slipfield evaluate` (column
 * realisation = i) too: its COF is drawn from an MT19937 seeded by
 * sf_mc_stream(rng, seed, i) (montecarlo.h), seed the scene's. */
#ifndef SF_MODEL_H
#define SF_MODEL_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <gsl/gsl_rng.h>
#include "scene.h"
#include "sweep.h"

/* What a solve gives, in out[]: the QoIs pv_x [m], pv_F [N], stick
 * fraction [-]; their ratios to the deterministic model at the same
 * parameters [-] (sf_sweep_det); each QoI's u_num in its unit (unum.h;
 * NaN when not asked for or when its companion failed). */
enum {
    SF_MODEL_PVX = 0, SF_MODEL_PVF = 1, SF_MODEL_SF = 2,
    SF_MODEL_RATIO = 3,   /* + q */
    SF_MODEL_U = 6,       /* + q */
    SF_MODEL_NOUT = 9
};

/* ---- one solve at a time, with a cache: a workspace (a thread's own)
 * keeps the COF plan and the deterministic reference of the last scene
 * it solved and reuses them while scenes differ only in their seed (the
 * same bits: a draw is a function of the stream alone). */
typedef struct sf_model_ws sf_model_ws;
sf_model_ws *sf_model_ws_alloc(void);
void sf_model_ws_free(sf_model_ws *w);
/* Scene s on the COF drawn from rng: out[SF_MODEL_NOUT] (NaN where not
 * formed), u_num when unum != 0.  SF_SUCCESS (err may then hold a
 * warning: no u_num, with why), or the run's or the reference's error
 * with the reason in err (T not above t_skip: SF_EINVAL). */
int sf_model_ws_solve(sf_model_ws *w, const sf_scene *s, gsl_rng *rng, int unum, double *out, char *err,
                      size_t errlen);

/* ---- a sweep point by its estimator's name, as `slipfield sweep` runs
 * it: one dispatch for the CLI and the handle below. */
enum { SF_MODEL_PLAIN = 0, SF_MODEL_MLMC, SF_MODEL_MLMC_BOXES, SF_MODEL_MLMC_SUB, SF_MODEL_ANTITHETIC,
       SF_MODEL_AUTO };
/* The estimator named `name` (plain, mlmc, mlmc-boxes, mlmc-sub,
 * antithetic, auto; NULL: plain) into *by; SF_EINVAL for another name. */
int sf_model_estimator(const char *name, int *by);
typedef struct {
    int by;                  /* SF_MODEL_PLAIN ... SF_MODEL_AUTO */
    size_t n;                /* realisations (plain), plain's N the paired estimators match, the cap with a target */
    size_t pilot;            /* 0: the default (10 pairs; 20 realisations with a target; at most n) */
    double target_se;        /* NaN: none; else every ratio mean's target standard error [-] */
    int control_variate;     /* 1: plain with the control variate */
    int threads;             /* 0: OpenMP's default */
    const char *checkpoint;  /* plain, control variate, target: a checkpoint file (NULL: none) */
    int resume;
    const char *label;       /* progress on a terminal (NULL: none) */
} sf_model_spec;
/* The spec's refusals, with the reason in err (SF_EINVAL): a paired
 * estimator with the control variate or a resume, the control variate
 * with a target, a target not > 0, a pilot with plain and no target, a
 * pilot outside [2, n].  Sets the default pilot. */
int sf_model_spec_check(sf_model_spec *spec, char *err, size_t errlen);
/* The point of scene s by spec (checked); its u_num too when unum != 0
 * (sf_unum_sweep; its failure is a warning in err, SF_SUCCESS).  The
 * estimator's refusals and errors with the reason in err. */
int sf_model_point(const sf_scene *s, const sf_model_spec *spec, int unum, sf_sweep_point *p, char *err,
                   size_t errlen);

/* ---- the handle */
typedef struct sf_model sf_model;

/* A model of the scene in `text` (`key = value` lines; NULL or "": the
 * paper's Table 1 baseline), or of the scene file at path.  SF_EPARSE
 * with the reason (file:line) in err; SF_ENOMEM. */
int sf_model_new(const char *text, sf_model **out, char *err, size_t errlen);
int sf_model_load(const char *path, sf_model **out, char *err, size_t errlen);
void sf_model_free(sf_model *m);
/* Set one key as a scene line would (`key = value`, the key table's
 * bounds and messages), or l_over_R (l = value R).  SF_EPARSE. */
int sf_model_set(sf_model *m, const char *key, const char *value, char *err, size_t errlen);
/* The scene the model holds (its Table 1 defaults and the keys set). */
const sf_scene *sf_model_scene(const sf_model *m);
/* Realisation i: out[SF_MODEL_NOUT] as sf_model_ws_solve, u_num when
 * unum != 0. */
int sf_model_run(sf_model *m, size_t realisation, int unum, double *out, char *err, size_t errlen);

/* A sweep of the model's scene over param (a scene key or l_over_R) at
 * values[0..nv), each point by spec (sf_model_point, with u_num): the
 * answers of each point and QoI ratio (sweep.h: sf_sweep_estimate), read
 * with sf_model_sweep_answer.  The first point's error ends it (SF_*,
 * the reason in err, which names the value). */
typedef struct sf_model_sweep sf_model_sweep;
int sf_model_sweep_run(sf_model *m, const char *param, const double *values, size_t nv, const sf_model_spec *spec,
                       sf_model_sweep **out, char *err, size_t errlen);
size_t sf_model_sweep_points(const sf_model_sweep *w);
/* Point k, ratio q (0 pv_x, 1 pv_F, 2 stick fraction): f[0..6) =
 * estimate, se, ci95_lo, ci95_hi, u_num [-], n; the estimator's and the
 * stop rule's names (static strings).  SF_EINVAL for k or q out of range. */
int sf_model_sweep_answer(const sf_model_sweep *w, size_t k, int q, double *f, const char **estimator,
                          const char **stop);
void sf_model_sweep_free(sf_model_sweep *w);
/* The same answers in one call for an FFI that holds no struct: f[(k 3 +
 * q) 6 + c], and names[(k 3 + q) 2 + {0, 1}] the estimator's and stop's. */
int sf_model_sweep_table(const sf_model_sweep *w, double *f, const char **names);

#ifdef __cplusplus
}
#endif
#endif
