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

#ifdef __cplusplus
}
#endif
#endif
