/* slipfield: Sobol' indices of the QoI ratios over the model's parameters
 * (sobol.h estimators, sweep.h QoIs).
 *
 * Inputs, independent and uniform on their ranges: log10 l/R, the COF's
 * CV (mu_std = CV mu_mean), the belt speed v_b [m/s], the mean COF
 * mu_mean; and the random field itself as a fifth input.
 *
 * The field input is a white noise fixed in belt coordinates (noise.h,
 * cof_generator = belt_noise), keyed by the design's row
 * (sf_sobol_source_row): evaluation e builds its field from the noise of
 * row r at its own parameters, G = k_l * W, H = exp(mu_g + sigma_g G).
 * A_B^(i) of a parameter keeps A's noise, A_B^(field) takes B's.  So a
 * parameter's small change moves the field by as little (the correlation
 * of two evaluations' fields at a belt point -> 1 as the change -> 0; v_b,
 * the CV and the mean COF leave G as it is), and an input held to a
 * narrow range gets a total index near 0.  The decomposition holds for
 * any fixed f(x, W) of independent inputs, but what the indices mean
 * depends on what W is: with a field redrawn whenever the grid that
 * carries it moves (a stream laid on a grid of spacing l/8), every
 * parameter's total index would hold the share of the field it redraws.
 * First-order indices do not depend on the choice (E[f | x_i] integrates
 * the field out); total indices of l/R do: with this W they hold the
 * interaction of l with the field, the change of the field's pattern when
 * its scale changes (docs/design.md sec. 7.8).
 *
 * QoIs: the ratios of PV_x, PV_F and the stick fraction to the
 * deterministic reference at the same parameters (sf_sweep_det: uniform
 * COF at mu_mean, same v_b, T, t_skip), as `slipfield sweep` defines them.
 * The evaluations run through sf_mc_run: bit-identical for any thread
 * count.
 */
#ifndef SF_SENSITIVITY_H
#define SF_SENSITIVITY_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
#include <stdio.h>
#include "scene.h"
#include "sobol.h"
#include "sweep.h"

enum { SF_SENS_LOGLR = 0, SF_SENS_CV, SF_SENS_VB, SF_SENS_MU, SF_SENS_NPAR, SF_SENS_FIELD = SF_SENS_NPAR, SF_SENS_D };

/* The name of input i ("log10_l_over_R", "cv", "v_b", "mu_mean", "field"). */
const char *sf_sens_input_name(int i);

/* The parameters' ranges [lo[i], hi[i]]. */
typedef struct {
    double lo[SF_SENS_NPAR], hi[SF_SENS_NPAR];
} sf_sens_ranges;

/* The paper's ranges: log10 l/R in [-2, 3] (Fig. 11's grid, 0.01 to
 * 1000), CV in [0.1, 0.3] (the paper holds it at 0.2; 0.3 is where it
 * bounds the Nataf map's use), v_b in [0.1, 0.6] m/s (Fig. 12), mu_mean
 * in [0.2, 1] (Fig. 13). */
void sf_sens_ranges_default(sf_sens_ranges *r);

/* Check r: finite, lo < hi, CV and v_b and mu_mean positive.  SF_EINVAL
 * with the reason. */
int sf_sens_ranges_check(const sf_sens_ranges *r, char *err, size_t errlen);

/* The scene of unit-cube point u (its first SF_SENS_NPAR entries), and
 * the parameters x[SF_SENS_NPAR] it sets (log10 l/R, CV, v_b, mu_mean). */
void sf_sens_scene(const sf_scene *base, const sf_sens_ranges *r, const double *u, sf_scene *s, double *x);

/* Evaluation e of design D over r from scene base: its scene *s (the
 * parameters of point e, the field generator belt_noise), the parameters
 * x[SF_SENS_NPAR], and field_rng set to the stream its field is drawn
 * from (the noise of the row its field column comes from). */
void sf_sens_point(const sf_scene *base, const sf_sens_ranges *r, const sf_sobol_design *D, size_t e, sf_scene *s,
                   double *x, gsl_rng *field_rng);

typedef struct {
    sf_sobol_design *D;      /* n rows, SF_SENS_D inputs */
    unsigned long inputs;    /* the A_B^(i) blocks run (sf_sobol_estimate_some's bit set) */
    double *x;               /* nevals x SF_SENS_NPAR: the parameters of each evaluation */
    double *y;               /* nevals x 2 SF_SWEEP_NQ: the ratios, then the QoIs in their units */
    sf_sobol_result res[SF_SWEEP_NQ];   /* of the ratios */
    /* first-order indices of the ratios on the parameters from given data
     * (sf_sobol_rank_s1 over blocks A and B, 2n independent rows: no
     * pick-freeze, so no coupling of the field enters them) */
    sf_sobol_rank_result rank[SF_SWEEP_NQ];
    double *boot[SF_SWEEP_NQ];          /* their bootstrap resamples (sf_sobol_estimate's boot) */
} sf_sens;

/* The study of scene base (cof = field) over r with n rows: n (SF_SENS_D
 * + 2) evaluations, then the indices of each ratio with nboot bootstrap
 * resamples at level.  threads 0: OpenMP's default; label: progress on a
 * terminal (NULL: none).  SF_EINVAL (bad ranges, n < 2, a scene without
 * a field) or an evaluation's error, with err set. */
int sf_sens_run(const sf_scene *base, const sf_sens_ranges *r, size_t n, size_t nboot, double level,
                int threads, const char *label, sf_sens **out, char *err, size_t errlen);
/* The same over blocks A, B and the A_B^(i) of `inputs` only (bit i for
 * input i, SF_SOBOL_ALL: sf_sens_run): n (2 + its bits) runs.  The
 * evaluations of the other blocks are not run (their x and y are NAN) and
 * the indices of the inputs left out are NAN; those of the inputs run are
 * the full study's (sf_sobol_estimate_some). */
int sf_sens_run_some(const sf_scene *base, const sf_sens_ranges *r, size_t n, unsigned long inputs, size_t nboot,
                     double level, int threads, const char *label, sf_sens **out, char *err, size_t errlen);
void sf_sens_free(sf_sens *S);

/* The indices as TSV: a header, then one row per QoI and input; the
 * given-data first-order index and its interval in the S1_rank columns
 * (NaN for the field, which has no column of values). */
void sf_sens_write_indices(FILE *f, const sf_sens *S);
/* The evaluations as TSV: block, row, the parameters, the ratios, the
 * QoIs (the evaluations run). */
void sf_sens_write_evals(FILE *f, const sf_sens *S);

#ifdef __cplusplus
}
#endif
#endif
