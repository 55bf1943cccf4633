/* Helpers shared by the check families. */
#ifndef SF_CHECKS_COMMON_H
#define SF_CHECKS_COMMON_H

#include <math.h>
#include "../case.h"
#include "../result.h"
#include "field.h"
#include "sweep.h"
#include <gsl/gsl_rng.h>

/* The oracle's own Eq. 2, written independently of the solver. */
double ref_sq_exp(double hx, double hy, double l);

/* The oracle's own Contensou closed forms (docs/design.md sec. 4.5), written from
 * the formulas with GSL's complete elliptic integrals of modulus k
 * (gsl_sf_ellint_Kcomp, Ecomp) and sharing no code with sf_contensou:
 * a uniformly pressed disc of radius R under uniform COF mu, centre slip U
 * and spin w, eps = U/(|w| R) >= 0 (INFINITY: no spin): |F| = mu N f(eps),
 * |T| = mu N R t(eps).  The eps > 1 torque bracket cancels like eps^-4:
 * about 1e-16 eps^4 relative error, so keep eps below ~100. */
void ref_contensou(double eps, double *f, double *t);

typedef struct {
    double xs, xe, d, omega, vr;        /* [m], [m], [m], [1/s], [m/s] */
    double t_stick, t_slip, pv_x, pv_F; /* [s], [s], [m], [N] */
    double sf;                          /* stick fraction [-] */
} ref_cycle1d;

/* The oracle's 1-D limit cycle at static COF mu (Eqs. 3-4, 1, 12, 14),
 * written from the equations, sharing no code with solver/dynamics/cycle1d.c: see
 * common.c for the derivation.  0, or -1 when there is no cycle. */
int ref_cycle(const sf_scene *s, double mu, ref_cycle1d *c);

/* Eq. 14's jump speed eps_lambda omega_n R [m/s], the relative speed at
 * which the disc leaves stick (the checks' own, not the solver's). */
double check_jump_speed(const sf_scene *s);

/* Power runs (docs/reports.md, `make power`): the scene the DATA GENERATOR draws from -- the
 * case's scene with the alternative of `slipfield verify --alternative`
 * applied (unchanged in a normal run).  Oracles use c->scene, never this. */
sf_scene check_gen_scene(const sf_case *c);
/* Gaussian samples as the generator draws them: sf_field_sample /
 * sf_field_sample_pair, then the generator-only alternatives (field_std
 * scales the field; re_im_corr mixes Re into Im at each point).  n is
 * the number of grid points. */
int check_field_sample(const sf_case *c, sf_field *f, gsl_rng *rng, double *g, size_t n);
int check_field_sample_pair(const sf_case *c, sf_field *f, gsl_rng *rng, double *re, double *im, size_t n);

/* The oracle's Nataf map (docs/design.md sec. 4.1), written from the target
 * moments independently of solver/field/lognormal.c: ln H ~ N(mu, sigma^2) with
 * E[H] = mean, sd[H] = std. */
typedef struct { double mu, sigma; } ref_ln_par;
ref_ln_par ref_lognormal_par(double mean, double std);
/* Oracle distortion: corr of exp(s G1), exp(s G2) with corr(G1, G2) = rho
 * is (e^{s^2 rho} - 1)/(e^{s^2} - 1), from the bivariate normal moment
 * generating function. */
double ref_rho_h(double sigma, double rho);

/* Likelihood-ratio (Wishart) test that N whitened vectors z of length p
 * have covariance I (known mean 0): S = (1/N) sum z z^T (lower triangle
 * read), statistic Bartlett * N (tr S - ln det S - p) ~ chi2(p(p+1)/2).
 * Returns the p-value (0 when S is not positive definite); *stat and
 * *trace (tr S / p) when non-NULL. */
#include <gsl/gsl_matrix.h>
double check_lrt_identity(const gsl_matrix *S, size_t N, double *stat, double *trace);

/* The same test of Cov = Sigma for sample vectors y of length p with known
 * mean 0, accumulated one vector at a time: each is whitened by the
 * Cholesky factor of Sigma (z = L^-1 y) and S += z z^T.
 * check_wlrt_init takes sigma (p x p) and factors it in place (it then
 * belongs to the test): SF_EFAIL when it is not positive definite, and
 * the test is then freed.  check_wlrt_done frees the test and returns the
 * p-value of check_lrt_identity (NaN when no vector was added). */
#include <gsl/gsl_vector.h>
typedef struct {
    gsl_matrix *L, *S;
    gsl_vector *z;
    size_t N;
} check_wlrt;
int check_wlrt_init(check_wlrt *t, gsl_matrix *sigma);
void check_wlrt_add(check_wlrt *t, const double *y);
double check_wlrt_done(check_wlrt *t, double *stat, double *trace);

/* Build the Gaussian field plan a case's (generator) scene asks for; note the
 * embedding facts in the findings.  Returns SF_SUCCESS or SF_ETRUNC (plan
 * usable) or an error (plan NULL). */
int check_field_plan(const sf_case *c, sf_result *r, sf_field **out);

/* Allocate or die (exit 3): checks run in their own process. */
void *check_alloc(size_t n);

/* Observed order: the least-squares slope of log y against log x over n
 * points (GSL gsl_fit_linear); NaN when the fit fails. */
double check_loglog_slope(const double *x, const double *y, size_t n);

/* Direct (no FFT) circulant eigenvalues of the squared-exponential
 * embedding of period (px, py) for spacings dx, dy: the oracle for the
 * FFT path.  lam has px*py entries, index kx + px*ky. O((px py)^2)/sep. */
void ref_eigenvalues(size_t px, size_t py, double dx, double dy, double l, double *lam);

/* Covariance at grid lags (i < m, j < n) produced by clamped eigenvalues,
 * by a direct inverse DFT. */
void ref_produced_cov(const double *lam, size_t px, size_t py, size_t m, size_t n, double *cov);

/* A lognormal COF (or a uniform one when cof = uniform or mu_std = 0) on
 * a square grid covering a disc of radius R centred at the origin.  Grid
 * spacing l/8 (bilinear RMS error ~ 7e-3 std, cases/contact/interpolation)
 * and at least 4 nodes across the disc, so a long l gets a coarse grid
 * instead of an embedding it cannot pad.  The Gaussian plan is made on the
 * first call and kept in *st; a truncated embedding is refused (NULL). */
#include "cof.h"
#include "lnfield.h"
typedef struct { sf_lnfield *lf; sf_scene gs; } check_disc_field;
sf_cof *check_disc_cof(const sf_scene *s, gsl_rng *rng, check_disc_field *st);
void check_disc_field_free(check_disc_field *st);

/* Run the oscillator for a scene: the COF drawn from the scene's plan with
 * rng (NULL for a constant COF), or the given cof.  On failure the reason
 * is noted in r and an error returned. */
#include "oscillator.h"
/* A history collector for sf_osc_run (every row, or one in `every`). */
typedef struct {
    size_t n, cap, every, seen;
    double *t, *x, *y, *phi, *vx, *Fx;
    int *stick;
    double y_absmax, phi_absmax;
} check_hist;
void check_hist_row(void *ctx, const sf_osc_row *row);
void check_hist_free(check_hist *h);

/* One COF realisation of the scene from the case's stream (kept across
 * runs that must share it); NULL with the reason noted when the plan is
 * refused. */
sf_cof *check_case_cof(const sf_case *c, const sf_scene *s, sf_result *r);

/* This thread's CPU time [s] (CLOCK_THREAD_CPUTIME_ID): the cost of a
 * check's own runs, for its report, whatever else the process runs. */
double check_cpu_seconds(void);

int check_osc_run(const sf_scene *s, gsl_rng *rng, const sf_cof *cof, double sample_dt, sf_osc_result *res,
                  sf_osc_row_fn row, void *ctx, sf_result *r);

/* Realisation i of plan p from its own stream (seed, i) (sf_mc_seed), as
 * a Monte Carlo sweep draws it: the same field whoever asks and when. */
int check_draw(sf_cof_plan *p, unsigned long seed, size_t i, sf_cof **out);

/* The cell-average COF (cof_model = cell_average) of scene sc, boxes of
 * side box [m] on the plan's effective grid (spacing box/3), computed as
 * the exact box averages of the fine point field `fine` (a tiled window
 * is slid along the strip for each column); deviations from the mean
 * times `scale` (1: exact).  NULL with the reason noted.  One realisation
 * at two models: a point reference and the cell averages the plan would
 * run, on the same field (cellavg.c). */
sf_cof *check_cellavg_filter(const sf_cof *fine, const sf_scene *sc, double box, double scale, sf_result *r);

/* The largest relative QoI gap over PV_x, PV_F and the stick fraction of
 * run (s, cof) against the reference run (sref, cref): max_q |q - q_ref| /
 * |q_ref| (0 where they are equal, 0 included); +inf when one run has a
 * complete cycle and the other none, or q_ref = 0 and q is not, so
 * such a realisation fails a gate instead of passing it; NaN when neither
 * has one (no QoI to compare: a caller may draw another realisation). */
int check_qoi_gap(const sf_scene *s, const sf_cof *cof, const sf_scene *sref, const sf_cof *cref, double *gap,
                  int *shapes_differ, sf_result *r);
/* What a run's QoI triple shows, to pair the runs of one field: 0 no QoI
 * (PV_x undefined: no oscillation in the window), 1 QoIs without a stick
 * (stick fraction 0), 2 QoIs with one. */
int check_qoi_kind(const double q[3]);
/* A run's event structure in the window [t_skip, T]: its kind, its
 * oscillations (maxima of x) and its complete stick cycles.  The paper's
 * per-realisation QoIs are means and sums over these events, so they jump
 * where two runs of one field count different events: a cycle or a stick
 * that starts or ends at the window's edge in one run only, or a maximum
 * of x that grazes vx = 0 inside a long slip (one run finds the extremum,
 * the other passes it; seen at 2 of 400 fields at l/R = 0.3, jumps of 9%
 * and 0.9%).  Runs at any accuracy meet such a jump, with a probability
 * that shrinks with their error: its size measures no accuracy, so the
 * comparisons count such a field and replace it by the next stream. */
typedef struct {
    int kind;
    size_t nosc, ncycles;
} check_qoi_shape;
int check_qoi_shape_differ(const check_qoi_shape *a, const check_qoi_shape *b);
/* One run's PV_x, PV_F and stick fraction (its event structure in *shape,
 * when not NULL), and the gap of check_qoi_gap of such a run (q, its
 * complete cycles) against a reference triple. */
int check_qoi_run(const sf_scene *s, const sf_cof *cof, double q[3], check_qoi_shape *shape, sf_result *r);
double check_qoi_gap_of(const double q[3], size_t ncycles, const double qref[3]);

/* The row of a comparison that replaces fields without a comparable QoI by
 * the next streams: at least n of the (at most 4n) fields drawn compared.
 * A requirement met or not (sf_check_true), not a margin: at used = n it is
 * not "near the edge". */
void check_fields_row(sf_result *r, const char *lab, double x, size_t used, size_t n);
/* The findings' account of the fields replaced at lab = x: `none` that
 * formed no QoI in either run, `edge` whose runs count different events
 * (check_qoi_shape_differ), with their QoI gaps (`jumps`, may be NULL). */
void check_replaced_notes(sf_result *r, const char *lab, double x, size_t none, size_t edge, const char *jumps);
/* The per-realisation errors behind each RMS of a sweep, after its table:
 * a line "- lab = x[k]: e..." per value, e[k * n + i] in stream order. */
void check_list_errors(sf_result *r, const char *lab, size_t K, const double *x, size_t n, const double *e);

/* A sweep point's statistics of each QoI (its values, in their units:
 * sf_sweep_point.stat, num) recorded for results.json and the report's
 * sweep table (result.h: sf_sweep_row). */
void check_sweep_record(sf_result *r, const char *param, double value, const sf_sweep_point *p);
/* One QoI's row of such a table: its statistics a (sf_sweep_stat_of) and
 * the numerical error of its mean e (NULL or e->n_sub = 0: not estimated),
 * qoi and unit as results.json names them. */
void check_sweep_stat_record(sf_result *r, const char *param, double value, const char *qoi, const char *unit,
                             const sf_sweep_stat *a, const sf_sweep_num *e);

/* The statistics of the finite values buf[0..used) recomputed with GSL
 * (gsl_stats_mean, gsl_stats_sd, gsl_cdf_tdist_Pinv), apart from the
 * solver's aggregation: mean, sd, se, the Student interval [lo, hi] =
 * mean -+ t se at level; scale = max|x|, dscale = max|x - mean| for the
 * round-off allowances of check_roundoff. */
typedef struct {
    double mean, sd, se, lo, hi, t;
    size_t used;
    double scale, dscale;
} check_recomp;
check_recomp check_recomp_of(const double *buf, size_t used, double level);
/* |a - b| / (8 n eps scale): a sum of n terms taken in another order
 * moves by at most n eps times the sum of their magnitudes; the factor 8
 * covers the square root, the division and the t quantile's product.
 * Equal non-finite values (no statistic formed) agree (0); one non-finite,
 * the other not: INFINITY. */
double check_roundoff(double a, double b, size_t n, double scale);
/* A recorded sweep row against its recomputation from the values x[0],
 * x[stride], ... x[(n - 1) stride] (the non-finite ones excluded): the
 * largest check_roundoff over mean, std, se and the interval's ends, and
 * INFINITY when the counts used / excluded differ.  buf holds n values. */
double check_sweep_row_off(const sf_sweep_row *row, const double *x, size_t stride, size_t n, double *buf);

/* The ratio means of a sweep's K points (param values x) with their
 * Student intervals as error bars and, where estimated, mean -+ u_num / det
 * as a band (points without an estimate are left out of the band), all
 * three QoIs, on plot p. */
void check_plot_sweep_bands(sf_plot *p, size_t K, const double *x, const sf_sweep_point *pt);

/* A log-log scatter of measured against predicted errors on a new plot
 * of r (points labelled `what`), with the identity line (labelled `line`)
 * over [lo, hi]: how a case shows an error model against its
 * measurements. */
void check_plot_vs_predicted(sf_result *r, const char *name, const char *title, const char *xlabel,
                             const char *ylabel, const char *what, const char *line, size_t n, const double *pred,
                             const double *meas, double lo, double hi);

/* A stored-data case's file beside it: NAME.tsv for NAME.md (SF_EINVAL
 * when the case's path does not end in .md). */
int check_data_path(const sf_case *c, char *buf, size_t len);
/* The file above opened for reading; NULL, *rc set and a note saying how
 * to regenerate it (the command `regen`) when it cannot be read. */
FILE *check_data_open(const sf_case *c, sf_result *r, char *buf, size_t len, const char *regen, int *rc);
/* t is a whole number (strtod's syntax, nothing after it): 1, and *x. */
int check_parse_num(const char *t, double *x);

#endif
