/* The cell-average COF model (cof_model = cell_average, solver/field/cellavg.h;
 * docs/design.md sec. 4.4): the plan's shortcut at small l/R
 * against the full computation.  The references these checks rest on (the
 * covariance oracle, the exact box average) are in cellavg_oracle.c.
 *  - cellavg_covariance: the effective field's produced covariance
 *    against an independent oracle of the box-averaged lognormal
 *    covariance (2-D Gauss-Legendre quadrature of Cov_mu = mubar^2
 *    (exp(sG^2 exp(-r^2/l^2)) - 1) against the triangle weights of two
 *    boxes: no series, no erf), and its marginal mean and variance
 *    (statistical, independent points of drawn fields).
 *  - cellavg_vs_point: on the SAME fine field (point model, spacing l/8),
 *    the cell-average quadrature fed with the exact box averages of that
 *    field against the point model's quadrature: the achieved QoI error.
 *  - cellavg_distribution: the QoI distributions of the two models at the
 *    switching l/R (two-sample Kolmogorov-Smirnov). */
#include "checks.h"
#include "common.h"
#include "cellavg_oracle.h"
#include "../stats.h"
#include "cellavg.h"
#include "cof.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "sf_error.h"
#include "sweep.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

enum { NQ = 3 };
static const char *const qname[NQ] = { "PV_x", "PV_F", "stick fraction" };

static void qois(const sf_osc_result *res, double *q)
{
    q[0] = res->pv_x;
    q[1] = res->pv_F;
    q[2] = res->stick_fraction;
}

/* Node patches of the effective field against the oracle's covariance:
 * whitened likelihood-ratio test of Cov = Sigma (common.c: check_wlrt). */
enum { PATCH = 4 };
typedef struct { size_t N; double stat, tr; } lrt_note;

/* The oracle's covariance of a PATCH x PATCH patch of nodes at spacing d. */
static gsl_matrix *patch_sigma(const oracle_par *o, double h, double d, const double *u, const double *w, size_t nn)
{
    enum { P = PATCH * PATCH };
    double cl[PATCH][PATCH];   /* the oracle at lags (a d, b d); it is even in each */
    for (int a = 0; a < PATCH; a++)
        for (int b = 0; b < PATCH; b++)
            cl[a][b] = cellavg_oracle_cov(o, h, a * d, b * d, u, w, nn);
    gsl_matrix *m = gsl_matrix_alloc(P, P);
    for (int p = 0; p < P; p++)
        for (int q = 0; q < P; q++)
            gsl_matrix_set(m, p, q, cl[abs(p % PATCH - q % PATCH)][abs(p / PATCH - q / PATCH)]);
    return m;
}

/* Patches with corners at a lattice of stride `stride` nodes (their gaps
 * beyond the support: independent patches), mu_h - mean into the test. */
static void patch_lrt_add(check_wlrt *t, const double *mu, size_t nx, size_t ny, size_t stride, double mean)
{
    double y[PATCH * PATCH];
    for (size_t jy = 0; jy + PATCH <= ny; jy += stride)
        for (size_t ix = 0; ix + PATCH <= nx; ix += stride) {
            for (int q = 0; q < PATCH * PATCH; q++)
                y[q] = mu[ix + (size_t)(q % PATCH) + nx * (jy + (size_t)(q / PATCH))] - mean;
            check_wlrt_add(t, y);
        }
}

static int chk_covariance(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (!K || strcmp(c->spec.sweep_param, "l_over_R") || s0->cof_model != SF_COFMODEL_CELL || !s0->cells ||
        !s0->samples) {
        sf_note(r, "The scene must sweep l_over_R with cof_model = cell_average, cells and samples set.");
        return SF_EINVAL;
    }
    ref_ln_par lp = ref_lognormal_par(s0->mu_mean, s0->mu_std);
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(20);
    double *x = check_alloc(K * sizeof *x), *eo = check_alloc(K * sizeof *eo), *ee = check_alloc(K * sizeof *ee);
    int rc = SF_SUCCESS;
    size_t ntests = 3 * K;
    lrt_note *lrt_row = check_alloc(K * sizeof *lrt_row);
    sf_note(r, "Produced covariance of the effective field (circulant embedding, `sf_field_covariance` times the "
               "variance) against the oracle (2-D Gauss-Legendre quadrature of the lognormal covariance against two "
               "boxes' triangle weights), at lags (i d, j d), d = box/3, i in 0..12, j in {0, 1, 2, 5, 9}, and at the "
               "farthest lags of the grid along x and y (13 x 5 each: a circulant period too short wraps there); marginal: "
               "%zu drawn fields, values on a sub-lattice spaced beyond the covariance's support (independent), mean "
               "(z test, variance known) and variance (chi-square, mean known), each at alpha / %zu (Bonferroni).\n\n"
               "| l/R | box/l | sd(mu_h) | max error vs oracle / var | embedding cov_error | points | mean p | "
               "variance p | lognormal-fit skewness |\n|---|---|---|---|---|---|---|---|---|",
            s0->samples, ntests);
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        if (sf_sweep_set(&s, "l_over_R", c->spec.sweep.v[k], err, sizeof err)) {
            sf_note(r, "**Bad sweep value:** %s", err);
            rc = SF_EINVAL;
            break;
        }
        sf_cof_plan *p;
        if ((rc = sf_cof_plan_alloc(&s, &p, err, sizeof err))) {
            sf_note(r, "**Cannot plan the effective field at l/R = %g:** %s", s.l / s.R, err);
            break;
        }
        const sf_cof_plan_info *in = sf_cof_plan_get_info(p);
        sf_field *f = sf_cof_plan_cell_field(p);
        if ((rc = sf_field_measure_covariance(f))) {   /* deferred by the run's plan */
            sf_note(r, "**Cannot measure the effective field's covariance at l/R = %g:** %s", s.l / s.R,
                    sf_strerror(rc));
            sf_cof_plan_free(p);
            break;
        }
        double cov_err = sf_field_get_info(f)->cov_error;   /* before the plan is freed */
        double h = 2 * s.R / (double)s.cells, d = in->dx, sd = sf_cof_plan_cell_std(p), var = sd * sd;
        oracle_par o = { s.mu_mean, lp.sigma * lp.sigma, s.l };
        size_t cap = 2 * 20 * ((size_t)ceil(h / (s.l / 2)) + 1);
        double *u = check_alloc(cap * sizeof *u), *w = check_alloc(cap * sizeof *w);
        size_t nn = cellavg_nodes_1d(h, s.l, gl, u, w);
        double *cov = check_alloc(in->nx * in->ny * sizeof *cov);
        sf_field_covariance(f, cov);
        double ov = cellavg_oracle_cov(&o, h, 0, 0, u, w, nn), emax = 0;
        /* near lags, and the farthest ones along x and y (where a circulant
         * period too short for the covariance's support wraps its tail) */
        static const int js[] = { 0, 1, 2, 5, 9 };
        for (int far = 0; far < 3; far++)
            for (size_t a = 0; a < sizeof js / sizeof js[0]; a++)
                for (int i = 0; i <= 12; i++) {
                    size_t ii = (size_t)i, jj = (size_t)js[a];
                    if (far == 1)
                        ii = in->nx - 1 - ii;
                    if (far == 2) {
                        jj = in->ny - 1 - jj;
                        ii = (size_t)js[a];
                    }
                    if (ii >= in->nx || jj >= in->ny)
                        continue;
                    double produced = var * cov[ii + in->nx * jj];
                    double oracle = cellavg_oracle_cov(&o, h, (double)ii * d, (double)jj * d, u, w, nn);
                    emax = sf_max(emax, fabs(produced - oracle) / ov);
                }
        free(cov);
        /* the marginal: independent points (lags beyond the support) of drawn fields */
        size_t step = (size_t)ceil((h + 9 * s.l) / d) + 1, npt = 0;
        double sum = 0, ss = 0, cap_n = (double)s.samples * (double)(in->nx / step + 1) * (double)(in->ny / step + 1);
        double *vals = check_alloc((size_t)cap_n * sizeof *vals);
        check_wlrt pl;
        int lrt_ok = !check_wlrt_init(&pl, patch_sigma(&o, h, d, u, w, nn));   /* else: p-value NaN, the row fails */
        free(u);
        free(w);
        for (size_t i = 0; i < s.samples && !rc; i++) {
            sf_cof *cof = NULL;
            rc = check_draw(p, s.seed, i, &cof);
            const double *mu;
            if (!rc && !(rc = sf_cof_grid_view(cof, NULL, NULL, NULL, NULL, NULL, NULL, &mu))) {
                for (size_t jy = 0; jy < in->ny; jy += step)
                    for (size_t ix = 0; ix < in->nx; ix += step)
                        vals[npt++] = mu[ix + in->nx * jy];
                if (lrt_ok)
                    patch_lrt_add(&pl, mu, in->nx, in->ny, step + PATCH - 1, s.mu_mean);
            }
            sf_cof_free(cof);
        }
        sf_cof_plan_free(p);
        double lrt_stat = NAN, lrt_tr = NAN;
        size_t lrt_n = lrt_ok ? pl.N : 0;
        double plrt = lrt_ok ? check_wlrt_done(&pl, &lrt_stat, &lrt_tr) : NAN;
        if (rc)
            break;
        for (size_t i = 0; i < npt; i++)
            sum += vals[i];
        double mean = sum / (double)npt;
        for (size_t i = 0; i < npt; i++)
            ss += (vals[i] - s.mu_mean) * (vals[i] - s.mu_mean);
        free(vals);
        /* the oracle's variance: the model claims Var(mu_h) exactly */
        double pm = sf_z_pvalue((mean - s.mu_mean) / sqrt(ov / (double)npt));
        double pv = sf_var_pvalue(ss / (double)npt, ov, npt, 1);
        double cvh = sqrt(ov) / s.mu_mean;
        x[k] = s.l / s.R;
        eo[k] = fmax(emax, 1e-17);
        ee[k] = fmax(cov_err, 1e-17);
        sf_note(r, "| %g | %.3g | %.4g | %.2e | %.2e | %zu | %.3g | %.3g | %.3f |", x[k], h / s.l, sqrt(ov), emax,
                ee[k], npt, pm, pv, 3 * cvh + cvh * cvh * cvh);
        char t[160];
        snprintf(t, sizeof t, "l/R = %g: produced covariance vs oracle, max |error| / Var(mu_h)", x[k]);
        sf_check_le(r, t, emax, c->spec.tolerance);
        snprintf(t, sizeof t, "l/R = %g: embedding vs its target on every grid lag (cov_error, correlation)", x[k]);
        sf_check_le(r, t, cov_err, c->spec.tolerance);
        snprintf(t, sizeof t, "l/R = %g: mean of mu_h = mubar (z test)", x[k]);
        sf_check_pvalue(r, t, pm, c->spec.alpha / (double)ntests, npt);
        snprintf(t, sizeof t, "l/R = %g: variance of mu_h = the box-averaged variance (chi-square)", x[k]);
        sf_check_pvalue(r, t, pv, c->spec.alpha / (double)ntests, npt);
        snprintf(t, sizeof t, "l/R = %g: covariance of %d x %d node patches = the oracle's (whitened LRT, chi2 %d dof)",
                 x[k], PATCH, PATCH, PATCH * PATCH * (PATCH * PATCH + 1) / 2);
        sf_check_pvalue(r, t, plrt, c->spec.alpha / (double)ntests, lrt_n);
        lrt_row[k] = (lrt_note){ lrt_n, lrt_stat, lrt_tr };
    }
    gsl_integration_glfixed_table_free(gl);
    if (!rc) {
        sf_note(r, "\nCovariance in distribution (the sampler itself: amplitudes, Hermitian noise, the real FFT): "
                   "node patches of %d x %d at the grid spacing, patches spaced beyond the covariance's support "
                   "(independent), mu_h - mubar whitened by the Cholesky factor of the oracle's covariance of the "
                   "patch; S = (1/N) sum z z^T against the identity, Bartlett * N (tr S - ln det S - p) ~ chi2 "
                   "(known mean).\n\n| l/R | patches N | LRT statistic | tr(S)/p |\n|---|---|---|---|",
                PATCH, PATCH);
        for (size_t k = 0; k < K; k++)
            sf_note(r, "| %g | %zu | %.1f | %.5f |", x[k], lrt_row[k].N, lrt_row[k].stat, lrt_row[k].tr);
        sf_plot *pl = sf_result_plot(r, "cellavg-cov", "Effective field: produced covariance vs oracle", "l/R [-]",
                                     "max |error| / Var(mu_h) [-]");
        sf_plot_log(pl, 1, 1);
        sf_plot_series(pl, "produced vs oracle quadrature", SF_STYLE_LINESPOINTS, K, x, eo);
        sf_plot_series(pl, "embedding vs its target (cov_error)", SF_STYLE_LINESPOINTS, K, x, ee);
        sf_plot_hline(pl, "tolerance", c->spec.tolerance);
    }
    free(x);
    free(eo);
    free(ee);
    free(lrt_row);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

/* ---- the real sampler (field.h: sample_real), exactly: a draw against
 * the sum that defines it, written here from its documented contract.
 * Normals in row-major order over the stored half (kx <= px/2): one at
 * a self-conjugate point, none at a point whose mirror row in the columns
 * kx = 0 and px/2 came first (its conjugate), two (a, b) elsewhere,
 * xi = (a + ib)/sqrt 2; the whole spectrum Hermitian, Y_k = sqrt(lambda_k /
 * M) xi_k; X_j = sum_k Y_k exp(2 pi i (jx kx/px + jy ky/py)) by direct
 * summation (no FFT), from the plan's eigenvalues (sf_field_eigenvalues:
 * their FFT-vs-direct agreement is eigenvalues-fft-vs-direct's and
 * test_cellavg's). */
static int chk_sampler_dft(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (!s->cells || !(s->mu_std > 0)) {
        sf_note(r, "The scene must set cells and mu_std > 0.");
        return SF_EINVAL;
    }
    double box = 2 * s->R / (double)s->cells;
    sf_cellavg ca;
    if (sf_cellavg_init(&ca, s->mu_mean, s->mu_std, s->l, box))
        return SF_EINVAL;
    double d = sf_cellavg_grid_spacing(box);
    /* grids whose periods are odd and even along each axis (the columns
     * kx = px/2 exist only for even px; self-conjugate rows ky = py/2 only
     * for even py) */
    static const size_t grid[][2] = { { 40, 12 }, { 37, 19 }, { 37, 12 }, { 40, 19 } };
    enum { NG = sizeof grid / sizeof grid[0] };
    double worst = 0, xs[NG], es[NG];
    int rc = SF_SUCCESS, parity = 0;   /* bits: odd px, even px, odd py, even py seen */
    sf_note(r, "Draws of the real sampler (sf_field_sample_fresh, sample_real = 1) on the effective field's kernel "
               "(box %.4g m, spacing %.4g m) against the direct sum of their definition with the same normals.\n\n"
               "| grid | periods px x py | max abs error | sum of |Y_k| | error / sum |\n|---|---|---|---|---|",
            box, d);
    for (int g = 0; g < NG && !rc; g++) {
        sf_field_spec sp;
        sf_field_spec_default(&sp, grid[g][0], grid[g][1], d, d, s->l);
        sp.sep_terms = ca.nterms;
        sp.sep_fn = sf_cellavg_septerm;
        sp.sep_params = &ca;
        sp.support = sf_cellavg_support(&ca);
        sp.sample_real = 1;
        sf_field *f;
        if (!sf_usable(rc = sf_field_alloc(&sp, &f)))
            break;
        rc = SF_SUCCESS;
        const sf_field_info *in = sf_field_get_info(f);
        size_t px = in->px, py = in->py, M = px * py, hx = px / 2 + 1, m = sp.m, n = sp.n;
        parity |= (px % 2 ? 1 : 2) | (py % 2 ? 4 : 8);
        double *lam = check_alloc(M * sizeof *lam), *v = check_alloc(m * n * sizeof *v);
        double complex *Y = check_alloc(M * sizeof *Y);
        sf_field_eigenvalues(f, lam);
        gsl_rng *r1 = sf_case_rng(c), *r2 = sf_case_rng(c);
        rc = sf_field_sample_fresh(f, r1, v);
        for (size_t ky = 0; ky < py; ky++)
            for (size_t kx = 0; kx < hx; kx++) {
                size_t my = (py - ky) % py;
                int own = kx == 0 || 2 * kx == px;
                double a = sqrt(fmax(lam[kx + px * ky], 0) / (double)M);
                if (own && my == ky)
                    Y[kx + px * ky] = a * gsl_ran_gaussian_ziggurat(r2, 1.0);
                else if (!(own && my < ky)) {
                    double re = gsl_ran_gaussian_ziggurat(r2, 1.0), im = gsl_ran_gaussian_ziggurat(r2, 1.0);
                    Y[kx + px * ky] = a * (re + I * im) / sqrt(2.0);
                }
            }
        for (size_t ky = 0; ky < py; ky++)   /* Hermitian: Y_{-k} = conj Y_k */
            for (size_t kx = 0; kx < px; kx++) {
                size_t mx = (px - kx) % px, my = (py - ky) % py;
                int stored = kx < hx && !((kx == 0 || 2 * kx == px) && my < ky);
                if (!stored)
                    Y[kx + px * ky] = conj(Y[mx + px * my]);
            }
        double err = 0, ysum = 0;
        for (size_t k = 0; k < M; k++)
            ysum += cabs(Y[k]);
        for (size_t j = 0; j < n && !rc; j++)
            for (size_t i = 0; i < m; i++) {
                double complex x = 0;
                for (size_t ky = 0; ky < py; ky++)
                    for (size_t kx = 0; kx < px; kx++)
                        x += Y[kx + px * ky] * cexp(2 * M_PI * I * ((double)(i * kx % px) / (double)px +
                                                                  (double)(j * ky % py) / (double)py));
                err = sf_max(err, fabs(creal(x) - v[i + m * j]));
                err = sf_max(err, fabs(cimag(x)));   /* the construction is Hermitian: a real field */
            }
        sf_note(r, "| %zu x %zu | %zu x %zu | %.3g | %.4g | %.3g |", m, n, px, py, err, ysum, err / ysum);
        xs[g] = (double)g;
        es[g] = fmax(err / ysum, 1e-18);
        worst = sf_max(worst, err / ysum);
        gsl_rng_free(r1);
        gsl_rng_free(r2);
        free(lam);
        free(v);
        free(Y);
        sf_field_free(f);
    }
    if (rc)
        return SF_EFAIL;
    sf_check_le(r, "max |draw - direct sum| / sum_k |Y_k| over the grids", worst, c->spec.tolerance);
    sf_check_abs(r, "periods odd and even along each axis (the grids cover every branch of the draw)",
                 (double)parity, 15, 0);
    sf_plot *pl = sf_result_plot(r, "sampler-dft", "Real sampler vs its direct sum", "grid index [-]",
                                 "max error / sum |Y_k| [-]");
    sf_plot_log(pl, 0, 1);
    sf_plot_series(pl, "draw vs direct sum", SF_STYLE_LINESPOINTS, NG, xs, es);
    sf_plot_hline(pl, "tolerance", c->spec.tolerance);
    return SF_SUCCESS;
}

/* One realisation i on the same fine field (plan cp, stream (seed, i)):
 * the cell-average run sc fed with the exact box averages of the fine
 * field (deviations times `scale`, check_cellavg_filter), and the point runs
 * sp[0..L) on that field.  The field is drawn
 * afresh for each use (the box filter slides a tiled window along the
 * whole strip; a run follows the disc).  QoIs: qc (its event structure in
 * *hc) and qr[3 l + q] (structure hr[l]). */
static int pair_runs(sf_cof_plan *cp, unsigned long seed, size_t i, const sf_scene *sc, double box, double scale,
                     const sf_scene *sp, size_t L, double *qc, check_qoi_shape *hc, double *qr, check_qoi_shape *hr,
                     sf_result *r)
{
    sf_cof *fine = NULL, *coarse = NULL;
    int rc = check_draw(cp, seed, i, &fine);
    if (!rc && !(coarse = check_cellavg_filter(fine, sc, box, scale, r)))
        rc = SF_EFAIL;
    sf_cof_free(fine);
    if (!rc)
        rc = check_qoi_run(sc, coarse, qc, hc, r);
    sf_cof_free(coarse);
    for (size_t l = 0; l < L && !rc; l++) {
        if (!(rc = check_draw(cp, seed, i, &fine)))
            rc = check_qoi_run(&sp[l], fine, qr + 3 * l, hr + l, r);
        sf_cof_free(fine);
    }
    return rc;
}

/* The scenes of one l/R of a comparison on the same fine field: sc the
 * cell-average run (plan: the accuracy plan's cells and rtol for the
 * scene's qoi_tol, cof_model = auto must choose the cell averages; else
 * the scene's cells and rtol), sp the point reference (rings `rings`, the
 * run's rtol / rdiv; the fine field's generator).  0 or an error (noted). */
static int pair_scenes(const sf_case *c, size_t k, int plan, size_t rings, double rdiv, sf_scene *sc, sf_scene *sp,
                       sf_numplan *pl, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    char err[256] = "";
    *sp = *s0;
    if (sf_sweep_set(sp, c->spec.sweep_param, c->spec.sweep.v[k], err, sizeof err)) {
        sf_note(r, "**Bad sweep value:** %s", err);
        return SF_EINVAL;
    }
    *sc = *sp;
    if (plan) {
        int rc = sf_numplan_make(sc, 1, pl, err, sizeof err);
        if (rc) {
            sf_note(r, "**No plan at l/R = %g:** %s", c->spec.sweep.v[k], err);
            return rc;
        }
        char t[160];
        snprintf(t, sizeof t, "l/R = %g: the plan takes the cell averages (cof_model = auto)", c->spec.sweep.v[k]);
        sf_check_true(r, t, pl->cell_average, pl->cell_average ? "cell_average" : "point");
        if (!pl->cell_average) {
            sf_note(r, "**At l/R = %g the plan keeps the point model:** nothing to verify there.", c->spec.sweep.v[k]);
            return SF_EFAIL;
        }
        sc->cells = pl->cells;
        sc->rtol = pl->rtol;
    }
    sp->rtol = sc->rtol / rdiv;
    sp->cof_model = SF_COFMODEL_POINT;
    sp->cof_generator = s0->cof_generator == SF_COFGEN_TILES ? SF_COFGEN_TILES : SF_COFGEN_CIRCULANT;
    sp->cells = rings;
    sc->cof_model = SF_COFMODEL_CELL;
    return SF_SUCCESS;
}

/* Two uses of one comparison on the same fine field (point model,
 * spacing l/8; the circulant strip, or the tiles when the scene pins
 * cof_generator = tiles):
 *  - pinned (cellavg_vs_point): the cell-average model at the scene's
 *    `cells` against the point model at the rings of sweep2, both at the
 *    scene's rtol; gate: achieved / sf_numplan_err_cell <= tolerance; the
 *    sweep is over l_over_R, or over another key at one l/R (mu_std: the
 *    COF's CV; v_b);
 *  - plan (cellavg_plan_qoi_tol): the tested run is the accuracy plan's
 *    own choice for the scene's qoi_tol (cof_model = auto, cells and rtol
 *    left to the plan: it must choose the cell averages), the reference
 *    the point model at the rings of sweep2 and the plan's rtol / 100
 *    (sweep2 may give three rings per l/R, coarse to fine: the finest is
 *    the reference, the others show its convergence); gates: the plan's
 *    prediction (cell averages + time stepping) <= qoi_tol (what the plan
 *    promises), each realisation's error <= tolerance, and over two or
 *    more realisations the RMS error <= qoi_tol and <= the prediction
 *    (deterministic; a one-sided test at the case's alpha when it sets
 *    one: the RMS over fields is what the plan's model predicts). */
static int vs_point(const sf_case *c, sf_result *r, int plan)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, n = s0->samples, L = K ? c->spec.sweep2.n / K : 0;
    int by_lr = !strcmp(c->spec.sweep_param, "l_over_R");
    const char *lab = by_lr ? "l/R" : c->spec.sweep_param;
    if (!K || !(by_lr || !plan) || !n || !(L == 1 || (plan && L == 3)) ||
        c->spec.sweep2.n != L * K || (!plan && (!s0->cells || !(s0->rtol > 0))) ||
        (plan && (s0->cells || s0->rtol > 0 || s0->cof_model != SF_COFMODEL_AUTO))) {
        sf_note(r, plan ? "The scene must sweep l_over_R, set sweep2 (the reference's rings per l/R: one, or three "
                          "from coarse to fine) and samples, and leave cells, rtol and cof_model to the plan."
                        : "The scene must sweep a key (l_over_R; or mu_std, v_b, ... at one l/R), set cells "
                          "(cell-average cells per diameter), sweep2 (the point model's rings per sweep value), rtol "
                          "and samples.");
        return SF_EINVAL;
    }
    int stat = n >= 2 && sf_case_spec_declared_alpha(&c->spec) > 0;
    /* Bonferroni over the RMS tests: two per sweep value (qoi_tol and the
     * prediction) for the plan, one (the prediction) for the comparison */
    double arow = c->spec.alpha / (double)((plan ? 2 : 1) * K);
    int tiles = s0->cof_generator == SF_COFGEN_TILES;
    double *x = check_alloc(K * sizeof *x), *ach = check_alloc(K * sizeof *ach);
    double *worst = check_alloc(K * sizeof *worst), *pred = check_alloc(K * sizeof *pred);
    double *e = check_alloc(n * L * sizeof *e), *g = check_alloc(n * L * sizeof *g);
    double *qr = check_alloc(3 * L * sizeof *qr);
    check_qoi_shape *hr = check_alloc(L * sizeof *hr);
    double *ek = check_alloc(K * n * sizeof *ek);   /* each value's per-realisation errors, listed after the table */
    sf_scene *sp = check_alloc(L * sizeof *sp);
    if (plan)
        sf_note(r, "On the same fine field (point model, spacing l/8, %s): the reference is the point model's polar "
                   "quadrature at the rings pinned per l/R (sweep2%s) and the plan's rtol / 100; the tested run is what "
                   "the accuracy plan chooses for qoi_tol = %g (cof_model = auto: cell averages, its cells per diameter "
                   "and rtol), fed with the exact box averages of the fine field's bilinear interpolant on its own grid "
                   "(spacing box/3); %zu realisations per l/R (streams sf_mc_seed(seed, i)); error: the largest relative "
                   "difference of PV_x, PV_F and stick fraction. The reference's own error (the plan's models at its "
                   "rings and rtol) is listed: it adds to the achieved difference.\n\n| l/R | plan: cells | box/l | "
                   "plan: rtol | reference rings | reference's predicted error | predicted (plan) | achieved (RMS) | "
                   "worst realisation | CPU [s] |\n|---|---|---|---|---|---|---|---|---|---|",
                tiles ? "tiles of white noise, generated as the window follows the disc" : "circulant strip",
                L > 1 ? "; the finest of three, the others show its convergence" : "", s0->qoi_tol, n);
    else
        sf_note(r, "On the same fine field (point model, spacing l/8, %s): the point model's polar "
                   "quadrature (rings pinned per l/R) against the cell-average model (%zu Cartesian cells per diameter) "
                   "fed with the exact box averages of that field's bilinear interpolant on its own grid (spacing "
                   "box/3); rtol %g for both; %zu realisations per l/R (streams sf_mc_seed(seed, i)); error: the largest "
                   "relative difference of PV_x, PV_F and stick fraction.\n\n| l/R | CV | box/l | point rings | "
                   "predicted (plan) | achieved (RMS) | worst realisation |\n|---|---|---|---|---|---|---|",
                tiles ? "tiles of white noise, generated as the window follows the disc" : "circulant strip", s0->cells,
                s0->rtol, n);
    int rc = SF_SUCCESS, short_k = 0;
    size_t kd = 0;   /* values of the sweep compared */
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene sc;
        sf_numplan pl;
        for (size_t l = 0; l < L && !rc; l++)
            rc = pair_scenes(c, k, plan, (size_t)c->spec.sweep2.v[k * L + l], plan ? 100 : 1, &sc, &sp[l], &pl, r);
        if (rc)
            break;
        double box = 2 * sc.R / (double)sc.cells;
        double lr = by_lr ? c->spec.sweep.v[k] : sc.l / sc.R;
        x[k] = c->spec.sweep.v[k];
        pred[k] = plan ? pl.err_total : sf_numplan_err_cell(&sc, sc.cells);
        sf_cof_plan *cp;
        char err[256] = "";
        if ((rc = sf_cof_plan_alloc(&sp[L - 1], &cp, err, sizeof err))) {
            sf_note(r, "**Cannot plan the fine field at %s = %g:** %s", lab, c->spec.sweep.v[k], err);
            break;
        }
        /* as in plan.c's qoi_tol check: a field on which no run forms a QoI
         * (no complete cycle in the window: at a slow belt, a long stick)
         * or on which the runs count different events (check_qoi_shape: a
         * cycle or a stick at the window's edge, a grazing maximum of x:
         * the per-realisation QoI jumps there, at any accuracy) is replaced
         * by the next stream, up to 4n draws, and counted in the findings */
        double e2 = 0, ew = 0, t0 = check_cpu_seconds();
        size_t used = 0, none = 0, edge = 0;
        for (size_t i = 0; used < n && i < 4 * n && !rc; i++) {
            double qc[3];
            check_qoi_shape hc;
            if ((rc = pair_runs(cp, s0->seed, i, &sc, box, 1, sp, L, qc, &hc, qr, hr, r)))
                break;
            /* by the runs' event structures (common.h: kind, oscillations,
             * cycles), not by the gaps: an infinite gap between runs of one
             * structure is a disagreement, and fails the case below */
            int differ = 0;
            for (size_t l = 0; l < L; l++)
                differ |= check_qoi_shape_differ(&hr[l], &hc);
            if (differ || !hc.kind) {
                *(differ ? &edge : &none) += 1;
                continue;
            }
            for (size_t l = 0; l < L; l++) {
                e[l * n + used] = check_qoi_gap_of(qc, hc.ncycles, qr + 3 * l);
                g[l * n + used] = check_qoi_gap_of(qr + 3 * l, 1, qr + 3 * (L - 1));
            }
            double ei = e[(L - 1) * n + used++];
            e2 += ei * ei / (double)n;
            ew = sf_max(ew, ei);
        }
        sf_cof_plan_free(cp);
        if (rc)
            break;
        check_replaced_notes(r, lab, c->spec.sweep.v[k], none, edge, NULL);
        if (used < n) {   /* fails; no row to plot, the later values are not run */
            check_fields_row(r, lab, c->spec.sweep.v[k], used, n);
            short_k = 1;
            break;
        }
        sf_result_data(r, "QoI errors", n * L, e);
        memcpy(ek + k * n, e + (L - 1) * n, n * sizeof *ek);
        ach[k] = fmax(sqrt(e2), 1e-17);
        worst[k] = fmax(ew, 1e-17);
        kd++;
        char t[224];
        const sf_scene *ref = &sp[L - 1];
        if (plan) {
            sf_note(r, "| %g | %zu | %.3g | %.2g | %zu | %.2g | %.2g | %.2g | %.2g | %.1f |", x[k], sc.cells, box / sc.l,
                    sc.rtol, ref->cells,
                    sf_numplan_err_quad(x[k], ref->mu_std / ref->mu_mean, ref->cells) + sf_numplan_err_time(ref->rtol),
                    pred[k], ach[k], worst[k], check_cpu_seconds() - t0);
            /* what the plan promises (--explain: "within qoi_tol") */
            snprintf(t, sizeof t, "l/R = %g: the plan's predicted error (cell averages + time stepping) <= qoi_tol", x[k]);
            sf_check_le(r, t, pred[k], s0->qoi_tol);
            snprintf(t, sizeof t, "l/R = %g: each realisation's QoI error vs the point reference <= tolerance", x[k]);
            sf_check_le(r, t, worst[k], c->spec.tolerance);
            if (stat) {
                snprintf(t, sizeof t, "l/R = %g: RMS QoI error <= qoi_tol (one-sided t test on the squares)", x[k]);
                sf_check_pvalue(r, t, sf_rms_le_pvalue(e + (L - 1) * n, n, s0->qoi_tol), arow, n);
                snprintf(t, sizeof t, "l/R = %g: RMS QoI error <= the plan's prediction (one-sided t test)", x[k]);
                sf_check_pvalue(r, t, sf_rms_le_pvalue(e + (L - 1) * n, n, pred[k]), arow, n);
            } else if (n >= 2) {
                snprintf(t, sizeof t, "l/R = %g: RMS QoI error of the plan's cell averages vs the point reference <= "
                                      "qoi_tol", x[k]);
                sf_check_le(r, t, ach[k], s0->qoi_tol);
                snprintf(t, sizeof t, "l/R = %g: RMS QoI error / the plan's predicted error", x[k]);
                sf_check_le(r, t, ach[k] / pred[k], 1);
            }
        } else {
            sf_note(r, "| %g | %.3g | %.3g | %zu | %.2g | %.2g | %.2g |", lr, sc.mu_std / sc.mu_mean,
                    box / sc.l, ref->cells, pred[k], ach[k], worst[k]);
            if (stat) {   /* the RMS over a few fields is itself random: test it, at alpha */
                snprintf(t, sizeof t, "%s = %g: RMS QoI difference (cell averages vs point values, same field) <= "
                                      "tolerance x predicted (one-sided t test on the squares)", lab, x[k]);
                sf_check_pvalue(r, t, sf_rms_le_pvalue(e + (L - 1) * n, n, c->spec.tolerance * pred[k]), arow, n);
            } else {
                snprintf(t, sizeof t,
                         "%s = %g: RMS QoI difference (cell averages vs point values, same field) / predicted", lab,
                         x[k]);
                sf_check_le(r, t, ach[k] / pred[k], c->spec.tolerance);
            }
        }
        check_fields_row(r, lab, c->spec.sweep.v[k], used, n);
        if (L > 1) {
            sf_note(r, "\nl/R = %g, the reference's convergence on the same fields (rtol %.2g): RMS over the %zu "
                       "realisations.\n\n| rings | cell / l | reference's predicted error | RMS error of the plan's run "
                       "against it | RMS gap to the finest reference |\n|---|---|---|---|---|",
                    x[k], ref->rtol, n);
            for (size_t l = 0; l < L; l++) {
                double se2 = 0, sg2 = 0;
                for (size_t i = 0; i < n; i++) {
                    se2 += e[l * n + i] * e[l * n + i] / (double)n;
                    sg2 += g[l * n + i] * g[l * n + i] / (double)n;
                }
                sf_note(r, "| %zu | %.3g | %.2g | %.2g | %.2g |", sp[l].cells, 2 * sc.R / (double)sp[l].cells / sc.l,
                        sf_numplan_err_quad(x[k], sc.mu_std / sc.mu_mean, sp[l].cells) + sf_numplan_err_time(ref->rtol),
                        sqrt(se2), sqrt(sg2));
                if (l == L - 2) {
                    /* the reference must be converged well inside what it judges */
                    snprintf(t, sizeof t, "l/R = %g: RMS gap of the middle reference to the finest <= qoi_tol / 2", x[k]);
                    sf_check_le(r, t, sqrt(sg2), 0.5 * s0->qoi_tol);
                }
            }
        }
    }
    if (!rc) {   /* short of fields at some value: the values before it, and its prediction */
        char xl[96];
        const char *u = sf_scene_key_unit(c->spec.sweep_param);
        snprintf(xl, sizeof xl, "%s [%s]", lab, by_lr || !u || !strcmp(u, "1") ? "-" : u);
        sf_plot *p = sf_result_plot(r, plan ? "cellavg-plan" : "cellavg-vs-point",
                                    plan ? "The plan's cell averages vs the point reference, same fine field"
                                         : "Cell-average model vs point model, same fine field",
                                    xl, "relative QoI difference [-]");
        sf_plot_log(p, 1, 1);
        if (kd) {
            sf_plot_series(p, "achieved (RMS over realisations)", SF_STYLE_LINESPOINTS, kd, x, ach);
            sf_plot_series(p, "worst realisation", SF_STYLE_POINTS, kd, x, worst);
        }
        sf_plot_series(p, "predicted by the plan", SF_STYLE_LINESPOINTS, kd + (size_t)short_k, x, pred);
        if (plan)
            sf_plot_hline(p, "qoi_tol", s0->qoi_tol);
        else
            sf_plot_hline(p, "qoi_tol = 1e-3 (default)", 1e-3);
    }
    if (!plan && kd)   /* the per-field data behind each RMS (scripts/cellavg-data.sh stores them) */
        check_list_errors(r, lab, kd, x, n, ek);
    free(x);
    free(ach);
    free(worst);
    free(pred);
    free(e);
    free(ek);
    free(g);
    free(qr);
    free(hr);
    free(sp);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

static int chk_vs_point(const sf_case *c, sf_result *r) { return vs_point(c, r, 0); }
static int chk_plan_qoi_tol(const sf_case *c, sf_result *r) { return vs_point(c, r, 1); }

/* ---- cellavg_calibration: sf_numplan_err_cell against stored, held-out
 * measurements (scripts/cellavg-data.sh: cellavg_vs_point's per-field
 * errors at the points of a fixed design, seeds never used to fit the
 * model).  No solve: each stored error is divided by err_cell recomputed
 * for its point's scene.  err_cell is a bound on the RMS over fields at
 * each point (the plan picks its cells from it), so the gate is the
 * largest point's RMS / err_cell <= tolerance, exact on the fixed data
 * (pin_seed); the report adds each point's one-sided t test of H0 'RMS <=
 * err_cell' (how far a regeneration at other seeds may move it) and the
 * pooled ratio.  Columns: point, seed, l/R, CV, v_b, mean COF, cells,
 * rings, T, field, error. */
enum { CC_COLS = 11, CC_PT = 0, CC_LR = 2, CC_CV = 3, CC_VB = 4, CC_MU = 5, CC_CELLS = 6, CC_RINGS = 7, CC_T = 8,
       CC_ERR = 10 };
#define CC_MAX_PTS 64

static int chk_calibration(const sf_case *c, sf_result *r)
{
    char path[600], hdr[1200] = "";
    if (check_data_path(c, path, sizeof path))
        return SF_EINVAL;
    FILE *f = fopen(path, "r");
    if (!f) {
        sf_note(r, "**Stored data missing:** cannot read %s: regenerate it with `sh scripts/cellavg-data.sh holdout > %s`.",
                path, path);
        return SF_EIO;
    }
    size_t cap = 0, lineno = 0, rows = 0, npt = 0, nonfinite = 0, undecided = 0;
    char *line = NULL;
    while (getline(&line, &cap, f) > 0)
        rows++;
    rewind(f);
    double *z = check_alloc((rows + 1) * sizeof *z);   /* (error / err_cell)^2 per stored field */
    double *e = check_alloc((rows + 1) * sizeof *e);
    struct { double v[CC_COLS], pred, ref, beta; size_t first, n; } pt[CC_MAX_PTS];
    int rc = SF_SUCCESS;
    rows = 0;
    while (getline(&line, &cap, f) > 0) {
        lineno++;
        line[strcspn(line, "\r\n")] = 0;
        if (line[0] == '#') {
            size_t k = strlen(hdr);
            snprintf(hdr + k, sizeof hdr - k, "> %s\n", line + 1 + (line[1] == ' '));
            undecided += !strncmp(line, "# point ", 8);   /* no field formed a QoI there (scripts/cellavg-data.sh) */
            continue;
        }
        if (!line[0] || !strncmp(line, "point\t", 6))
            continue;
        double v[CC_COLS];
        size_t nf = 0;
        int ok = 1;
        for (char *t = line, *tab; ok && t; t = tab ? tab + 1 : NULL, nf++) {
            if ((tab = strchr(t, '\t')))
                *tab = 0;
            ok = nf < CC_COLS && check_parse_num(t, &v[nf]);   /* "nan" parses: the gate counts it */
        }
        ok = ok && nf == CC_COLS && v[CC_LR] > 0 && v[CC_CV] > 0 && v[CC_CELLS] >= 1;
        if (ok && (!npt || v[CC_PT] != pt[npt - 1].v[CC_PT])) {   /* a new point */
            ok = npt < CC_MAX_PTS;
            if (ok) {
                memcpy(pt[npt].v, v, sizeof v);
                sf_scene sc = c->scene;   /* the point's scene: its l/R, CV, v_b and mean COF on the case's */
                sc.l = v[CC_LR] * sc.R;
                sc.mu_mean = v[CC_MU];
                sc.mu_std = v[CC_CV] * v[CC_MU];
                sc.v_b = v[CC_VB];
                pt[npt].pred = sf_numplan_err_cell(&sc, (size_t)v[CC_CELLS]);
                pt[npt].beta = sf_numplan_belt_number(&sc);
                pt[npt].ref = sf_numplan_err_quad(v[CC_LR], v[CC_CV], (size_t)v[CC_RINGS]) + sf_numplan_err_time(1e-9);
                pt[npt].first = rows;
                pt[npt++].n = 0;
            }
        }
        if (!ok) {
            sf_note(r, "**%s:%zu: not a stored field** (%d tab-separated numbers, a positive l/R and CV, at most %d "
                       "points, each point's fields together).", path, lineno, CC_COLS, CC_MAX_PTS);
            rc = SF_EPARSE;
            break;
        }
        e[rows] = v[CC_ERR];
        z[rows] = pow(v[CC_ERR] / pt[npt - 1].pred, 2);
        nonfinite += !isfinite(z[rows]);
        rows++;
        pt[npt - 1].n++;
    }
    free(line);
    fclose(f);
    if (!rc) {
        sf_note(r, "Stored data: %s, %zu fields at %zu design points; %zu more points without a field that forms a "
                   "QoI in the window (its header and comments:)\n\n%s", path, rows, npt, undecided, hdr);
        sf_check_le(r, "stored fields with a non-finite error", (double)nonfinite, 0);
        sf_check_ge(r, "stored fields", (double)rows, 2);
    }
    if (!rc && rows >= 2) {   /* a point with a non-finite error is listed, not plotted (its row above fails) */
        double tol = c->spec.tolerance, worst = 0;
        double *xs = check_alloc(npt * sizeof *xs), *ys = check_alloc(npt * sizeof *ys);
        size_t kw = 0, few = 0, np = 0;
        sf_note(r, "\nPer point: err_cell recomputed by the code under test; the reference's own predicted error "
                   "(the point model at its rings, rtol 1e-9: sf_numplan_err_quad + err_time) adds to the measured "
                   "difference; p: the one-sided t test of H0 'RMS <= err_cell' on the squares (not a gate: the "
                   "chance, were the model exact at the point, of data this far above it).\n\n| point | l/R | CV | "
                   "v_b [m/s] | mean COF | beta | cells | rings | T [s] | fields | err_cell | reference's predicted "
                   "error | RMS error | RMS / err_cell | worst field | p |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (size_t k = 0; k < npt; k++) {
            const double *v = pt[k].v, *ek = e + pt[k].first;
            double m2 = 0, w = 0;
            for (size_t i = 0; i < pt[k].n; i++) {
                m2 += ek[i] * ek[i] / (double)pt[k].n;
                w = fmax(w, ek[i]);
            }
            few += pt[k].n < 2;
            if (isfinite(m2)) {
                xs[np] = pt[k].pred;
                ys[np++] = fmax(sqrt(m2), 1e-17);
            }
            if (sqrt(m2) / pt[k].pred > worst) {
                worst = sqrt(m2) / pt[k].pred;
                kw = k;
            }
            sf_note(r, "| %g | %g | %g | %g | %g | %.3f | %g | %g | %g | %zu | %.3g | %.2g | %.3g | %.3f | %.3g | %.2g |",
                    v[CC_PT], v[CC_LR], v[CC_CV], v[CC_VB], v[CC_MU], pt[k].beta, v[CC_CELLS], v[CC_RINGS], v[CC_T],
                    pt[k].n, pt[k].pred, pt[k].ref, sqrt(m2), sqrt(m2) / pt[k].pred, w,
                    pt[k].n >= 2 ? sf_rms_le_pvalue(ek, pt[k].n, pt[k].pred) : 1.0);
        }
        double mz = gsl_stats_mean(z, 1, rows), sez = gsl_stats_sd(z, 1, rows) / sqrt((double)rows);
        sf_note(r, "\nPooled over the %zu fields (not a gate: err_cell bounds each point, not their average): mean "
                   "(error / err_cell)^2 = %.3f (standard error %.3f), RMS ratio %.3f. The worst point, %g, sets the "
                   "verdict: an err_cell scaled by any factor below %.3f fails on these data.", rows, mz, sez,
                sqrt(mz), pt[kw].v[CC_PT], worst / tol);
        sf_check_le(r, "design points with fewer than 2 stored fields", (double)few, 0);
        sf_check_le(r, "largest RMS over a point's fields / err_cell", worst, tol);
        double lo = 1e-4, hi = 1e-1;
        if (np)
            gsl_stats_minmax(&lo, &hi, xs, 1, np);
        check_plot_vs_predicted(r, "cellavg-calibration", "Cell-average error: predicted against measured (held out)",
                                "err_cell, predicted [-]", "RMS relative QoI error over a point's fields [-]",
                                "stored design points", "measured = predicted", np, xs, ys, lo / 2, hi * 2);
        free(xs);
        free(ys);
    }
    free(z);
    free(e);
    return rc;
}

/* ---- the cell-average model's effect on the QoI statistics, paired on
 * the same fine fields: per l/R and QoI, the ratio of the means and of the
 * stds (cell averages / point model) on the log scale, with standard
 * errors from the influence functions of the pairs (delta method, no
 * normality: u_i = (x_i - xbar) / xbar - (y_i - ybar) / ybar for the mean,
 * v_i = ((x_i - xbar)^2 / s_x^2 - (y_i - ybar)^2 / s_y^2) / 2 for the std;
 * se = sd / sqrt(n)).  Gate: the interval null |log ratio| <=
 * log(1 + tolerance) (sf_interval_null_p) at the case's alpha split over
 * the rows; beside it the TOST verdict (both one-sided (1 - alpha) bounds
 * inside the margin) and the minimum detectable shift at power 0.99,
 * margin + (t_alpha + t_0.01) se, gated <= 5% (the design's power) at
 * QSTATS_POWER_N pairs or more. */
#define QSTATS_MDE 0.05
#define QSTATS_POWER_N 50   /* the power is gated from this many pairs on (a smoke run reports it) */
static void qstats_row(sf_result *r, double lr, const char *qn, const char *what, double est, const double *u, size_t n,
                       double margin, double alpha)
{
    double se = gsl_stats_sd(u, 1, n) / sqrt((double)n), df = (double)n - 1, m = log1p(margin);
    double p = sf_interval_null_p(est, se, m, df), tq = gsl_cdf_tdist_Qinv(alpha, df);
    double mde = expm1(m + (tq + gsl_cdf_tdist_Qinv(0.01, df)) * se);
    int tost = est - tq * se > -m && est + tq * se < m;
    sf_note(r, "| %g | %s | %s | %.4f | %.2g | [%.4f, %.4f] | %s | %.3g |", lr, qn, what, exp(est), se,
            exp(est - tq * se), exp(est + tq * se), tost ? "shown" : "not shown", mde);
    char t[160];
    snprintf(t, sizeof t, "l/R = %g, %s: |%s ratio - 1| <= %g (interval null, paired)", lr, qn, what, margin);
    sf_check_pvalue(r, t, p, alpha, n);
    if (n >= QSTATS_POWER_N) {
        snprintf(t, sizeof t, "l/R = %g, %s, %s: minimum detectable shift at power 0.99", lr, qn, what);
        sf_check_le(r, t, mde, QSTATS_MDE);
    }
}

/* The cell-average model's std (the generator's scale, cof.h:
 * sf_cof_plan_cell_std) over the oracle's std of the box average (the
 * quadrature, cellavg_oracle.c): 1 up to the quadrature's error when the
 * model is right.  The paired runs feed the box averages with their deviations
 * times this ratio, so the model's own variance enters them as it enters
 * a drawn effective field.  NaN when the cell-average COF cannot be
 * planned. */
static double model_scale(const sf_scene *sc, double box)
{
    sf_cof_plan *cp;
    char err[256];
    if (sf_cof_plan_alloc(sc, &cp, err, sizeof err))
        return NAN;
    double sd = sf_cof_plan_cell_std(cp);
    sf_cof_plan_free(cp);
    ref_ln_par lp = ref_lognormal_par(sc->mu_mean, sc->mu_std);
    oracle_par o = { sc->mu_mean, lp.sigma * lp.sigma, sc->l };
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(20);
    size_t cap = 2 * 20 * ((size_t)ceil(box / (sc->l / 2)) + 1);
    double *u = check_alloc(cap * sizeof *u), *w = check_alloc(cap * sizeof *w);
    size_t nn = cellavg_nodes_1d(box, sc->l, gl, u, w);
    double ov = cellavg_oracle_cov(&o, box, 0, 0, u, w, nn);
    free(u);
    free(w);
    gsl_integration_glfixed_table_free(gl);
    return sd / sqrt(ov);
}

static int chk_qoi_stats(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n, n = s0->samples;
    if (!K || strcmp(c->spec.sweep_param, "l_over_R") || c->spec.sweep2.n != K || n < 4 || s0->cells ||
        s0->rtol > 0 || s0->cof_model != SF_COFMODEL_AUTO || !(c->spec.tolerance > 0)) {
        sf_note(r, "The scene must sweep l_over_R, set sweep2 (the point model's rings per l/R), samples >= 4 and "
                   "tolerance (the equivalence margin), and leave cells, rtol and cof_model to the plan.");
        return SF_EINVAL;
    }
    double alpha = c->spec.alpha / (double)(K * NQ * 2);
    double *q = check_alloc(2 * NQ * n * sizeof *q), *u = check_alloc(n * sizeof *u);
    double *x = check_alloc(K * sizeof *x), *rs = check_alloc(K * sizeof *rs);
    sf_note(r, "On the same fine field (tiles, point model spacing l/8): the cell-average model as the accuracy plan "
               "takes it for qoi_tol = %g (its cells and rtol; fed with the exact box averages of the fine field, read "
               "through the bilinear interpolant of its box/3 grid as in a run) against the point model at the rings of "
               "sweep2 and the same rtol; %zu realisations per l/R (streams sf_mc_seed(seed, i)). Ratio: cell average / "
               "point; se of its log from the pairs' influence functions; margin %g; alpha %.3g per row (the case's %g "
               "over %zu rows); MDS: the minimum detectable shift at power 0.99 (gated <= %g).\n\n| l/R | QoI | "
               "statistic | ratio | se (log) | %g%% interval | TOST within the margin | MDS |\n|---|---|---|---|---|---|"
               "---|---|",
            s0->qoi_tol, n, c->spec.tolerance, alpha, c->spec.alpha, K * NQ * 2, QSTATS_MDE, 100 * (1 - 2 * alpha));
    int rc = SF_SUCCESS;
    for (size_t k = 0; k < K && !rc; k++) {
        sf_scene sc, sp;
        sf_numplan pl;
        if ((rc = pair_scenes(c, k, 1, (size_t)c->spec.sweep2.v[k], 1, &sc, &sp, &pl, r)))
            break;
        double box = 2 * sc.R / (double)sc.cells, scale = model_scale(&sc, box);
        sf_note(r, "| %g | (the model's cell-average std / the oracle's: %.9f; cells %zu, rtol %.2g, point rings %zu) "
                   "|||||||", c->spec.sweep.v[k], scale, sc.cells, sc.rtol, sp.cells);
        sf_cof_plan *cp;
        char err[256] = "";
        if ((rc = sf_cof_plan_alloc(&sp, &cp, err, sizeof err))) {
            sf_note(r, "**Cannot plan the fine field at l/R = %g:** %s", c->spec.sweep.v[k], err);
            break;
        }
        for (size_t i = 0; i < n && !rc; i++) {
            double qc[3], qp[3];
            check_qoi_shape hc, hp;
            rc = pair_runs(cp, s0->seed, i, &sc, box, scale, &sp, 1, qc, &hc, qp, &hp, r);
            for (int j = 0; j < NQ && !rc; j++) {
                q[j * n + i] = qc[j];
                q[(NQ + j) * n + i] = qp[j];
            }
        }
        sf_cof_plan_free(cp);
        if (rc)
            break;
        sf_result_data(r, "QoIs", 2 * NQ * n, q);
        x[k] = c->spec.sweep.v[k];
        for (int j = 0; j < NQ; j++) {
            const double *a = q + j * n, *b = q + (NQ + j) * n;
            double ma = gsl_stats_mean(a, 1, n), mb = gsl_stats_mean(b, 1, n);
            double sa = gsl_stats_sd_m(a, 1, n, ma), sb = gsl_stats_sd_m(b, 1, n, mb);
            for (size_t i = 0; i < n; i++)
                u[i] = (a[i] - ma) / ma - (b[i] - mb) / mb;
            qstats_row(r, x[k], qname[j], "mean", log(ma / mb), u, n, c->spec.tolerance, alpha);
            for (size_t i = 0; i < n; i++)
                u[i] = 0.5 * ((a[i] - ma) * (a[i] - ma) / (sa * sa) - (b[i] - mb) * (b[i] - mb) / (sb * sb));
            qstats_row(r, x[k], qname[j], "std", log(sa / sb), u, n, c->spec.tolerance, alpha);
            if (j == 1)
                rs[k] = sa / sb;
        }
    }
    if (!rc) {
        sf_plot *p = sf_result_plot(r, "cellavg-qoi-stats", "The std of PV_F, cell-average / point model, same fields",
                                    "l/R [-]", "std ratio [-]");
        sf_plot_log(p, 1, 0);
        sf_plot_series(p, "std(PV_F) ratio", SF_STYLE_LINESPOINTS, K, x, rs);
        sf_plot_hline(p, "1 - margin", 1 - c->spec.tolerance);
        sf_plot_hline(p, "1 + margin", 1 + c->spec.tolerance);
    }
    free(q);
    free(u);
    free(x);
    free(rs);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

/* ---- the QoI distributions of the two models (independent fields) */
static int chk_distribution(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t n = s0->samples;
    if (n < 8 || !s0->cells || c->spec.sweep.n != 1 || !(s0->rtol > 0)) {
        sf_note(r, "The scene must set samples >= 8, cells (cell-average), rtol and sweep = (the point model's rings).");
        return SF_EINVAL;
    }
    double *q[2][NQ];
    for (int m = 0; m < 2; m++)
        for (int k = 0; k < NQ; k++)
            q[m][k] = check_alloc(n * sizeof(double));
    int rc = SF_SUCCESS;
    for (int m = 0; m < 2 && !rc; m++) {
        sf_scene s = *s0;
        s.cof_model = m ? SF_COFMODEL_CELL : SF_COFMODEL_POINT;
        if (!m)
            s.cells = (size_t)c->spec.sweep.v[0];
        char err[256] = "";
        sf_cof_plan *cp;
        if ((rc = sf_cof_plan_alloc(&s, &cp, err, sizeof err))) {
            sf_note(r, "**Cannot plan the COF:** %s", err);
            break;
        }
        for (size_t i = 0; i < n && !rc; i++) {
            gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
            gsl_rng_set(g, sf_mc_seed(s0->seed + (unsigned long)m, i));   /* independent streams per model */
            sf_cof *cof = NULL;
            rc = sf_cof_plan_draw(cp, g, &cof);
            gsl_rng_free(g);
            sf_osc_result a;
            if (!rc && !(rc = check_osc_run(&s, NULL, cof, 0, &a, NULL, NULL, r))) {
                double v[NQ];
                qois(&a, v);
                for (int k = 0; k < NQ; k++)
                    q[m][k][i] = v[k];
                sf_osc_result_free(&a);
            }
            sf_cof_free(cof);
        }
        sf_cof_plan_free(cp);
    }
    if (!rc) {
        sf_note(r, "%zu realisations per model at l/R = %g (independent streams), point model at %g rings, cell-average "
                   "model at %zu cells per diameter; two-sample KS per QoI at alpha / 3 (Bonferroni); z: the difference of "
                   "the means over its Monte Carlo standard error (information).\n\n| QoI | mean (point) | mean (cell "
                   "average) | z | KS D | p |\n|---|---|---|---|---|---|",
                n, s0->l / s0->R, c->spec.sweep.v[0], s0->cells);
        for (int k = 0; k < NQ; k++) {
            double m0 = 0, m1 = 0, v0 = 0, v1 = 0, D;
            for (size_t i = 0; i < n; i++) {
                m0 += q[0][k][i] / (double)n;
                m1 += q[1][k][i] / (double)n;
            }
            for (size_t i = 0; i < n; i++) {
                v0 += (q[0][k][i] - m0) * (q[0][k][i] - m0) / (double)(n - 1);
                v1 += (q[1][k][i] - m1) * (q[1][k][i] - m1) / (double)(n - 1);
            }
            double pv = sf_ks2_test(q[0][k], n, q[1][k], n, &D);
            sf_note(r, "| %s | %.5g | %.5g | %.2f | %.3f | %.3g |", qname[k], m0, m1, (m1 - m0) / sqrt((v0 + v1) / (double)n),
                    D, pv);
            char t[96];
            snprintf(t, sizeof t, "%s: same distribution (two-sample KS)", qname[k]);
            sf_check_pvalue(r, t, pv, c->spec.alpha / NQ, n);
        }
        double idx[2] = { 0, 1 };
        sf_plot *p = sf_result_plot(r, "cellavg-dist", "QoI means, point vs cell-average model", "model (0: point, 1: "
                                    "cell average) [-]", "stick fraction [-]");
        double mm[2] = { 0, 0 };
        for (size_t i = 0; i < n; i++) {
            mm[0] += q[0][2][i] / (double)n;
            mm[1] += q[1][2][i] / (double)n;
        }
        sf_plot_series(p, "mean stick fraction", SF_STYLE_LINESPOINTS, 2, idx, mm);
    }
    for (int m = 0; m < 2; m++)
        for (int k = 0; k < NQ; k++)
            free(q[m][k]);
    return rc ? SF_EFAIL : SF_SUCCESS;
}

const sf_check_def sf_checks_cellavg[] = {
    { "cellavg_covariance", chk_covariance, "cell-averaged COF: produced covariance vs oracle quadrature, marginal moments" },
    { "cellavg_vs_point", chk_vs_point, "cell-average quadrature vs point quadrature on the same fine field" },
    { "cellavg_plan_qoi_tol", chk_plan_qoi_tol,
      "the plan's cell-average choice for qoi_tol vs the point model at high resolution, same fine field" },
    { "cellavg_qoi_stats", chk_qoi_stats,
      "the cell-average model's effect on the QoI means and stds, paired with the point model on the same fine fields" },
    { "cellavg_distribution", chk_distribution, "QoI distributions of the cell-average and point models (KS)" },
    { "cellavg_calibration", chk_calibration,
      "the cell-average error model err_cell against stored held-out measurements (no solve)" },
    { "cellavg_sampler_dft", chk_sampler_dft, "the real sampler's draws against the direct sum that defines them" },
    { NULL, NULL, NULL },
};
