/* Helpers shared by the check families (common.h): likelihood-ratio
 * tests, the generator's scene and fields, runs and their QoIs, sweep
 * rows and plots. */
#include "common.h"
#include "../stats.h"
#include "lnfield.h"
#include "montecarlo.h"
#include "sf_error.h"
#include "sweep.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_statistics_double.h>

double ref_sq_exp(double hx, double hy, double l)
{
    return exp(-(hx * hx + hy * hy) / (l * l));
}

void ref_contensou(double eps, double *f, double *t)
{
    eps = fabs(eps);
    if (eps == 0) {   /* pure spin */
        *f = 0;
        *t = 2.0 / 3.0;
    } else if (isinf(eps)) {   /* pure translation */
        *f = 1;
        *t = 0;
    } else if (eps == 1) {   /* (1 - eps^2) K -> 0 as k -> 1; K(1) is infinite */
        *f = 8 / (3 * M_PI);
        *t = 8 / (9 * M_PI);
    } else if (eps < 1) {   /* pole inside the disc, k = eps */
        double K = gsl_sf_ellint_Kcomp(eps, GSL_PREC_DOUBLE), E = gsl_sf_ellint_Ecomp(eps, GSL_PREC_DOUBLE);
        *f = 4 / (3 * M_PI * eps) * ((1 + eps * eps) * E - (1 - eps * eps) * K);
        *t = 4 / (9 * M_PI) * ((4 - 2 * eps * eps) * E - (1 - eps * eps) * K);
    } else {   /* pole outside, k = 1/eps */
        double k = 1 / eps, K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE), E = gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE);
        *f = 4 / (3 * M_PI) * ((eps * eps + 1) * E - (eps * eps - 1) * K);
        *t = 4 * eps * eps * eps / (9 * M_PI) * ((1 - k * k) * (2 - 3 * k * k) * K + 2 * (2 * k * k - 1) * E);
    }
}

ref_ln_par ref_lognormal_par(double mean, double std)
{
    double cv = std / mean;
    ref_ln_par p;
    p.sigma = sqrt(log(1.0 + cv * cv));
    p.mu = log(mean) - 0.5 * p.sigma * p.sigma;
    return p;
}

double ref_rho_h(double sigma, double rho)
{
    double s2 = sigma * sigma;
    return (exp(s2 * rho) - 1.0) / (exp(s2) - 1.0);
}

double check_lrt_identity(const gsl_matrix *S, size_t N, double *stat, double *trace)
{
    size_t p = S->size1;
    gsl_matrix *Sc = gsl_matrix_alloc(p, p);
    double tr = 0, logdet = 0;
    for (size_t a = 0; a < p; a++) {
        tr += gsl_matrix_get(S, a, a);
        for (size_t b = 0; b <= a; b++) {
            gsl_matrix_set(Sc, a, b, gsl_matrix_get(S, a, b));
            gsl_matrix_set(Sc, b, a, gsl_matrix_get(S, a, b));
        }
    }
    int bad = gsl_linalg_cholesky_decomp1(Sc);   /* GSL's abort handler is off (cli/main.c) */
    for (size_t a = 0; a < p && !bad; a++)
        logdet += 2.0 * log(gsl_matrix_get(Sc, a, a));
    gsl_matrix_free(Sc);
    double pd = (double)p, Nd = (double)N;
    double bart = 1.0 - (2 * pd * pd + 3 * pd - 1) / (6.0 * Nd * (pd + 1));
    double st = bad ? INFINITY : bart * Nd * (tr - logdet - pd);
    if (stat) *stat = st;
    if (trace) *trace = tr / pd;
    /* NaN data give a NaN statistic: p-value NaN, which fails the row */
    return bad ? 0.0 : sf_chisq_pvalue(st, pd * (pd + 1) / 2);
}

int check_wlrt_init(check_wlrt *t, gsl_matrix *sigma)
{
    memset(t, 0, sizeof *t);
    if (gsl_linalg_cholesky_decomp1(sigma)) {
        gsl_matrix_free(sigma);
        return SF_EFAIL;
    }
    t->L = sigma;
    t->S = gsl_matrix_calloc(sigma->size1, sigma->size1);
    t->z = gsl_vector_alloc(sigma->size1);
    if (!t->S || !t->z) {
        fputs("slipfield: out of memory in a check\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    return SF_SUCCESS;
}

void check_wlrt_add(check_wlrt *t, const double *y)
{
    for (size_t a = 0; a < t->z->size; a++)
        gsl_vector_set(t->z, a, y[a]);
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, t->L, t->z);
    gsl_blas_dsyr(CblasLower, 1.0, t->z, t->S);
    t->N++;
}

double check_wlrt_done(check_wlrt *t, double *stat, double *trace)
{
    double pv = NAN;
    if (stat) *stat = NAN;
    if (trace) *trace = NAN;
    if (t->N) {
        gsl_matrix_scale(t->S, 1.0 / (double)t->N);
        pv = check_lrt_identity(t->S, t->N, stat, trace);
    }
    gsl_matrix_free(t->L);
    gsl_matrix_free(t->S);
    gsl_vector_free(t->z);
    memset(t, 0, sizeof *t);
    return pv;
}

void *check_alloc(size_t n)
{
    void *p = calloc(n ? n : 1, 1);
    if (!p) {
        fputs("slipfield: out of memory in a check\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    return p;
}

double check_loglog_slope(const double *x, const double *y, size_t n)
{
    double *lx = check_alloc(n * sizeof *lx), *ly = check_alloc(n * sizeof *ly), c0, c1, a, b, c, ss;
    for (size_t i = 0; i < n; i++) {
        lx[i] = log(x[i]);
        ly[i] = log(y[i]);
    }
    int st = gsl_fit_linear(lx, 1, ly, 1, n, &c0, &c1, &a, &b, &c, &ss);
    free(lx);
    free(ly);
    return st ? NAN : c1;
}

/* The alternative of a power run, or NULL in a normal run. */
static int case_alt(const sf_case *c, sf_alt *a)
{
    char err[128];
    return c->alternative[0] && sf_alt_parse(c->alternative, a, err, sizeof err) == SF_SUCCESS;
}

sf_scene check_gen_scene(const sf_case *c)
{
    sf_scene s = c->scene;
    sf_alt a;
    if (case_alt(c, &a))
        sf_alt_apply(&a, &s);
    return s;
}

int check_field_sample(const sf_case *c, sf_field *f, gsl_rng *rng, double *g, size_t n)
{
    int rc = sf_field_sample(f, rng, g);
    sf_alt a;
    if (!rc && case_alt(c, &a) && sf_alt_field_std(&a) != 1.0) {
        for (size_t i = 0; i < n; i++)
            g[i] *= sf_alt_field_std(&a);
    }
    return rc;
}

int check_field_sample_pair(const sf_case *c, sf_field *f, gsl_rng *rng, double *re, double *im, size_t n)
{
    int rc = sf_field_sample_pair(f, rng, re, im);
    sf_alt a;
    if (!rc && case_alt(c, &a)) {
        double sd = sf_alt_field_std(&a), rho = sf_alt_re_im_corr(&a), q = sqrt(1 - rho * rho);
        for (size_t i = 0; i < n; i++) {
            im[i] = sd * (rho * re[i] + q * im[i]);   /* unit variance, corr(re, im) = rho */
            re[i] *= sd;
        }
    }
    return rc;
}

int check_field_plan(const sf_case *c, sf_result *r, sf_field **out)
{
    sf_field_spec spec;
    sf_scene gs = check_gen_scene(c);
    sf_field_spec_from_scene(&gs, &spec);
    int rc = sf_field_alloc(&spec, out);
    if (!sf_usable(rc))
        return rc;
    const sf_field_info *in = sf_field_get_info(*out);
    sf_note(r, "Embedding: %zu x %zu (minimal %zu x %zu, padding factor %.3g x %.3g), "
               "lambda_min/lambda_max = %.3g, %zu eigenvalues clamped, %s; produced-covariance "
               "error max|C - Sigma| = %.3g.\n",
            in->px, in->py, in->px_min, in->py_min,
            in->px_min ? (double)in->px / (double)in->px_min : 1.0,
            in->py_min ? (double)in->py / (double)in->py_min : 1.0,
            in->lambda_min / in->lambda_max, in->n_clamped,
            in->truncated ? "**truncated at the padding cap**" : "not truncated", in->cov_error);
    return rc;
}

/* 1-D even sequence DFT by direct sums: lambda(k) = sum_j c(j) cos(2 pi jk/P). */
static void eig1(size_t P, double d, double l, double *lam)
{
    for (size_t k = 0; k < P; k++) {
        double s = 0.0;
        for (size_t j = 0; j < P; j++) {
            size_t jj = j < P - j ? j : P - j;
            double h = (double)jj * d / l;
            s += exp(-h * h) * cos(2.0 * M_PI * (double)((j * k) % P) / (double)P);
        }
        lam[k] = s;
    }
}

void ref_eigenvalues(size_t px, size_t py, double dx, double dy, double l, double *lam)
{
    double *a = check_alloc(px * sizeof *a), *b = check_alloc(py * sizeof *b);
    eig1(px, dx, l, a);
    eig1(py, dy, l, b);
    for (size_t j = 0; j < py; j++)
        for (size_t i = 0; i < px; i++)
            lam[i + px * j] = a[i] * b[j];
    free(a);
    free(b);
}

void ref_produced_cov(const double *lam, size_t px, size_t py, size_t m, size_t n, double *cov)
{
    double M = (double)px * (double)py;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < m; i++) {
            double s = 0.0;
            for (size_t ky = 0; ky < py; ky++) {
                double cy = cos(2.0 * M_PI * (double)((ky * j) % py) / (double)py);
                double sy = sin(2.0 * M_PI * (double)((ky * j) % py) / (double)py);
                for (size_t kx = 0; kx < px; kx++) {
                    double l = lam[kx + px * ky];
                    if (l <= 0.0)
                        continue;
                    double ax = 2.0 * M_PI * (double)((kx * i) % px) / (double)px;
                    /* Re(e^{i(ax+ay)}) = cos ax cos ay - sin ax sin ay */
                    s += l * (cos(ax) * cy - sin(ax) * sy);
                }
            }
            cov[i + m * j] = s / M;
        }
}

sf_cof *check_disc_cof(const sf_scene *s, gsl_rng *rng, check_disc_field *st)
{
    sf_cof *cof = NULL;
    if (s->cof == SF_COF_UNIFORM || s->mu_std == 0) {
        sf_cof_alloc_uniform(s->mu_mean, &cof);
        return cof;
    }
    if (!st->lf) {
        st->gs = *s;
        double h = fmin(s->l / 8, 2.2 * s->R / 3);   /* scene arithmetic (validated, finite), not an aggregation of data */
        st->gs.dx = st->gs.dy = h;
        st->gs.nx = st->gs.ny = (size_t)ceil(2.2 * s->R / h) + 1;
        st->gs.pad_cap = 1e4;   /* the embedding-size cap still applies */
        if (sf_lnfield_alloc(&st->gs, &st->lf) != SF_SUCCESS) {
            sf_lnfield_free(st->lf);
            st->lf = NULL;
            return NULL;
        }
    }
    size_t n = st->gs.nx * st->gs.ny;
    double *h = check_alloc(n * sizeof *h);
    sf_lnfield_sample(st->lf, rng, NULL, h);
    double x0 = -0.5 * (double)(st->gs.nx - 1) * st->gs.dx;
    sf_cof_alloc_grid(st->gs.nx, st->gs.ny, x0, x0, st->gs.dx, st->gs.dy, h, &cof);
    free(h);
    return cof;
}

void check_disc_field_free(check_disc_field *st)
{
    sf_lnfield_free(st->lf);
    st->lf = NULL;
}

double check_cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int check_osc_run(const sf_scene *s, gsl_rng *rng, const sf_cof *cof, double sample_dt, sf_osc_result *res,
                  sf_osc_row_fn row, void *ctx, sf_result *r)
{
    char err[256] = "";
    sf_cof *own = NULL;
    int rc = SF_SUCCESS;
    memset(res, 0, sizeof *res);
    if (!cof) {
        sf_cof_plan *p;
        rc = sf_cof_plan_alloc(s, &p, err, sizeof err);
        if (!rc) {
            rc = sf_cof_plan_draw(p, rng, &own);
            sf_cof_plan_free(p);
        }
        cof = own;
    }
    sf_osc *o = NULL;
    if (!rc)
        rc = sf_osc_alloc(s, cof, &o, err, sizeof err);
    if (!rc)
        rc = sf_osc_run(o, row, ctx, sample_dt, res, err, sizeof err);
    if (rc)
        sf_note(r, "**The run %s:** %s (%s).", rc == SF_EMAXITER ? "stopped" : "failed", *err ? err : "", sf_strerror(rc));
    sf_osc_free(o);
    sf_cof_free(own);
    return rc;
}

void check_hist_row(void *ctx, const sf_osc_row *row)
{
    check_hist *h = ctx;
    h->y_absmax = sf_max(h->y_absmax, fabs(row->y));
    h->phi_absmax = sf_max(h->phi_absmax, fabs(row->phi));
    if (h->every > 1 && (h->seen++ % h->every))
        return;
    if (h->n == h->cap) {
        h->cap = h->cap ? 2 * h->cap : 1024;
        double **a[] = { &h->t, &h->x, &h->y, &h->phi, &h->vx, &h->Fx };
        for (int i = 0; i < 6; i++) {
            *a[i] = realloc(*a[i], h->cap * sizeof(double));
            if (!*a[i])
                exit(SF_EXIT_INTERNAL);
        }
        h->stick = realloc(h->stick, h->cap * sizeof(int));
        if (!h->stick)
            exit(SF_EXIT_INTERNAL);
    }
    h->t[h->n] = row->t;
    h->x[h->n] = row->x;
    h->y[h->n] = row->y;
    h->phi[h->n] = row->phi;
    h->vx[h->n] = row->vx;
    h->Fx[h->n] = row->Fx;
    h->stick[h->n] = row->stick;
    h->n++;
}

void check_hist_free(check_hist *h)
{
    free(h->t); free(h->x); free(h->y); free(h->phi); free(h->vx); free(h->Fx); free(h->stick);
    memset(h, 0, sizeof *h);
}

/* One COF realisation of the scene (kept across runs that must share it). */
sf_cof *check_case_cof(const sf_case *c, const sf_scene *s, sf_result *r)
{
    char err[256] = "";
    sf_cof_plan *p;
    sf_cof *cof = NULL;
    if (sf_cof_plan_alloc(s, &p, err, sizeof err)) {
        sf_note(r, "**Cannot plan the COF:** %s", err);
        return NULL;
    }
    gsl_rng *rng = sf_case_rng(c);
    sf_cof_plan_draw(p, rng, &cof);
    gsl_rng_free(rng);
    sf_cof_plan_free(p);
    return cof;
}

double check_jump_speed(const sf_scene *s)
{
    return s->eps_lambda * sqrt(s->k / s->m) * s->R;
}

/* The limit cycle of the 1-D model at static COF mu (Eqs. 3-4 with Eq. 1's
 * mu_k = r mu, Eq. 14's jump and Eq. 12's threshold).  Slip (u = v - v_b
 * < 0) is free harmonic motion about the kinetic equilibrium x_e = r mu N
 * / k at omega = sqrt(k/m).  It starts at the break point x_s = mu N / k
 * (where the spring force reaches the static limit) with the disc speed
 * v_r = v_b - eps omega R (Eq. 14 puts the relative speed at eps omega R)
 * and ends when the speed returns to v_r (Eq. 12's threshold): energy
 * conservation on the arc puts that at the mirror point x_e - d, d = x_s
 * - x_e, with the amplitude A = sqrt(d^2 + (v_r/omega)^2) and the phase
 * swept pi + 2 atan(v_r / (omega d)).  Stick carries the disc from x_e -
 * d to x_s at v_b: 2 d / v_b.  The friction force is k x in stick (the
 * disc does not accelerate) and r mu N in slip, so its range is from
 * k (x_e - d) at stick onset to k x_s at the break: 2 k d.  0 or -1 when
 * there is no cycle (d <= 0 or v_r <= 0). */
int ref_cycle(const sf_scene *s, double mu, ref_cycle1d *c)
{
    double N = s->m * s->g;
    c->omega = sqrt(s->k / s->m);
    c->xs = mu * N / s->k;
    c->xe = s->mu_k_ratio * mu * N / s->k;
    c->d = c->xs - c->xe;
    c->vr = s->v_b - check_jump_speed(s);
    if (!(c->d > 0) || !(c->vr > 0))
        return -1;
    c->t_stick = 2 * c->d / s->v_b;
    c->t_slip = (M_PI + 2 * atan2(c->vr, c->omega * c->d)) / c->omega;
    c->pv_x = 2 * sqrt(c->d * c->d + (c->vr / c->omega) * (c->vr / c->omega));
    c->pv_F = 2 * s->k * c->d;
    c->sf = c->t_stick / (c->t_stick + c->t_slip);
    return 0;
}

int check_qoi_run(const sf_scene *s, const sf_cof *cof, double q[3], check_qoi_shape *shape, sf_result *r)
{
    sf_osc_result a;
    int rc = check_osc_run(s, NULL, cof, 0, &a, NULL, NULL, r);
    if (rc)
        return rc;
    q[0] = a.pv_x;
    q[1] = a.pv_F;
    q[2] = a.stick_fraction;
    if (shape)
        *shape = (check_qoi_shape){ check_qoi_kind(q), a.nosc, a.ncycles };
    sf_osc_result_free(&a);
    return SF_SUCCESS;
}

double check_qoi_gap_of(const double q[3], size_t ncycles, const double qref[3])
{
    if (!ncycles && isnan(qref[0]))
        return NAN;
    double e = 0;
    for (int k = 0; k < 3; k++) {
        /* equal values agree even at 0 (a stick fraction of 0 in both:
         * no stick in the window), where the relative gap is 0 / 0 */
        double d = q[k] == qref[k] ? 0 : fabs(q[k] - qref[k]) / fabs(qref[k]);
        if (!(d <= e))   /* NaN (a complete cycle in one run only) too: it fails the case */
            e = isnan(d) ? INFINITY : d;
    }
    return e;
}

void check_list_errors(sf_result *r, const char *lab, size_t K, const double *x, size_t n, const double *e)
{
    size_t len = 64 + strlen(lab) + 16 * n;
    char *line = check_alloc(len);
    sf_note(r, "\nEach realisation's error, in the order of the streams used:\n");
    for (size_t k = 0; k < K; k++) {
        int o = snprintf(line, len, "- %s = %g:", lab, x[k]);
        for (size_t i = 0; i < n && o > 0 && (size_t)o < len; i++)
            o += snprintf(line + o, len - (size_t)o, " %.4g", e[k * n + i]);
        sf_note(r, "%s", line);
    }
    free(line);
}

void check_fields_row(sf_result *r, const char *lab, double x, size_t used, size_t n)
{
    char t[160], found[96];
    snprintf(t, sizeof t, "%s = %g: realisations with a QoI in every run, at least %zu (of at most %zu drawn)", lab, x,
             n, 4 * n);
    snprintf(found, sizeof found, "%zu compared", used);
    sf_check_true(r, t, used >= n, found);
}

int check_qoi_kind(const double q[3])
{
    return isnan(q[0]) ? 0 : q[2] > 0 ? 2 : 1;
}

void check_replaced_notes(sf_result *r, const char *lab, double x, size_t none, size_t edge, const char *jumps)
{
    if (none)
        sf_note(r, "%s = %g: %zu realisation(s) without a complete cycle in either run replaced by the next streams.",
                lab, x, none);
    if (edge)
        sf_note(r, "%s = %g: %zu realisation(s) on which the runs count different events (oscillations, cycles or a "
                   "stick at the window's edge, or a maximum of x grazing vx = 0: a jump of the per-realisation QoI, "
                   "not an accuracy error) replaced by the next streams%s%s",
                lab, x, edge, jumps ? "; their QoI gaps (the first 8):" : ".", jumps ? jumps : "");
}

int check_qoi_shape_differ(const check_qoi_shape *a, const check_qoi_shape *b)
{
    return a->kind != b->kind || a->nosc != b->nosc || a->ncycles != b->ncycles;
}

int check_qoi_gap(const sf_scene *s, const sf_cof *cof, const sf_scene *sref, const sf_cof *cref, double *gap,
                  int *shapes_differ, sf_result *r)
{
    double qa[3], qb[3];
    check_qoi_shape ha, hb;
    int rc = check_qoi_run(sref, cref, qa, &ha, r);
    if (!rc && !(rc = check_qoi_run(s, cof, qb, &hb, r))) {
        *gap = check_qoi_gap_of(qb, hb.ncycles, qa);
        *shapes_differ = check_qoi_shape_differ(&ha, &hb);
    }
    return rc;
}

int check_draw(sf_cof_plan *p, unsigned long seed, size_t i, sf_cof **out)
{
    *out = NULL;
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    if (!g)
        return SF_ENOMEM;
    gsl_rng_set(g, sf_mc_seed(seed, i));
    int rc = sf_cof_plan_draw(p, g, out);
    gsl_rng_free(g);
    return rc;
}

void check_sweep_stat_record(sf_result *r, const char *param, double value, const char *qoi, const char *unit,
                             const sf_sweep_stat *a, const sf_sweep_num *e)
{
    int est = e && e->n_sub;
    sf_sweep_row row = { .value = value, .n_used = a->n_used, .n_excluded = a->n_excluded, .mean = a->mean,
                         .std = a->std, .se = a->se, .ci_lo = a->ci_lo, .ci_hi = a->ci_hi,
                         .level = SF_SWEEP_CI_LEVEL, .u_num = est ? e->u_mean : NAN,
                         .u_num_subset = est ? e->n_sub : 0, .u_num_used = est ? e->n_used : 0 };
    snprintf(row.param, sizeof row.param, "%s", *param ? param : "point");
    snprintf(row.qoi, sizeof row.qoi, "%s", qoi);
    snprintf(row.unit, sizeof row.unit, "%s", unit);
    sf_result_sweep(r, &row);
}

void check_sweep_record(sf_result *r, const char *param, double value, const sf_sweep_point *p)
{
    static const char *const nm[SF_SWEEP_NQ] = { "pv_x", "pv_F", "stick_fraction" }, *const un[SF_SWEEP_NQ] = { "m", "N", "-" };
    for (int q = 0; q < SF_SWEEP_NQ; q++)
        check_sweep_stat_record(r, param, value, nm[q], un[q], &p->stat[q], &p->num[q]);
}

check_recomp check_recomp_of(const double *buf, size_t used, double level)
{
    check_recomp o = { NAN, NAN, NAN, NAN, NAN, NAN, used, 0, 0 };
    if (!used)
        return o;
    o.mean = gsl_stats_mean(buf, 1, used);
    for (size_t i = 0; i < used; i++) {
        o.scale = fmax(o.scale, fabs(buf[i]));
        o.dscale = fmax(o.dscale, fabs(buf[i] - o.mean));
    }
    if (used > 1) {
        o.sd = gsl_stats_sd(buf, 1, used);
        o.se = o.sd / sqrt((double)used);
        o.t = gsl_cdf_tdist_Pinv(0.5 * (1 + level), (double)(used - 1));
        o.lo = o.mean - o.t * o.se;
        o.hi = o.mean + o.t * o.se;
    }
    return o;
}

double check_roundoff(double a, double b, size_t n, double scale)
{
    if (!isfinite(a) || !isfinite(b))
        return (isnan(a) && isnan(b)) || a == b ? 0 : INFINITY;
    double tol = 8 * (double)(n ? n : 1) * DBL_EPSILON * scale;
    return a == b ? 0 : tol > 0 ? fabs(a - b) / tol : INFINITY;
}

double check_sweep_row_off(const sf_sweep_row *row, const double *x, size_t stride, size_t n, double *buf)
{
    size_t used = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i * stride]))
            buf[used++] = x[i * stride];
    if (row->n_used != used || row->n_excluded != n - used)
        return INFINITY;
    check_recomp a = check_recomp_of(buf, used, row->level);
    double w = check_roundoff(row->mean, a.mean, used, a.scale);
    w = fmax(w, check_roundoff(row->std, a.sd, used, a.dscale));
    w = fmax(w, check_roundoff(row->se, a.se, used, a.dscale));
    w = fmax(w, check_roundoff(row->ci_lo, a.lo, used, a.scale));
    return fmax(w, check_roundoff(row->ci_hi, a.hi, used, a.scale));
}

void check_plot_sweep_bands(sf_plot *p, size_t K, const double *x, const sf_sweep_point *pt)
{
    static const char *const nm[SF_SWEEP_NQ] = { "PV_x ratio", "PV_F ratio", "stick-fraction ratio" };
    double *m = check_alloc((K ? K : 1) * sizeof *m), *lo = check_alloc((K ? K : 1) * sizeof *lo),
           *hi = check_alloc((K ? K : 1) * sizeof *hi), *bx = check_alloc((K ? K : 1) * sizeof *bx);
    for (int q = 0; q < SF_SWEEP_NQ; q++) {
        size_t nb = 0;
        for (size_t k = 0; k < K; k++) {   /* the band: where u_num was estimated */
            double u = pt[k].num[q].u_mean / pt[k].det[q];
            if (pt[k].num[q].n_sub && isfinite(u) && isfinite(pt[k].mean[q])) {
                bx[nb] = x[k];
                lo[nb] = pt[k].mean[q] - u;
                hi[nb++] = pt[k].mean[q] + u;
            }
        }
        char lb[96];
        if (nb) {
            snprintf(lb, sizeof lb, "%s: mean -+ u_num (numerical error of the mean)", nm[q]);
            sf_plot_band(p, lb, nb, bx, lo, hi);
        }
        for (size_t k = 0; k < K; k++) {
            m[k] = pt[k].mean[q];
            lo[k] = pt[k].rstat[q].ci_lo;
            hi[k] = pt[k].rstat[q].ci_hi;
        }
        snprintf(lb, sizeof lb, "%s: mean, %g%% Monte Carlo interval", nm[q], 100 * SF_SWEEP_CI_LEVEL);
        sf_plot_errorbars(p, lb, K, x, m, lo, hi);
    }
    free(m); free(lo); free(hi); free(bx);
}

int check_data_path(const sf_case *c, char *buf, size_t len)
{
    size_t n = strlen(c->path);
    if (n < 3 || strcmp(c->path + n - 3, ".md"))
        return SF_EINVAL;
    snprintf(buf, len, "%.*s.tsv", (int)(n - 3), c->path);
    return SF_SUCCESS;
}

FILE *check_data_open(const sf_case *c, sf_result *r, char *buf, size_t len, const char *regen, int *rc)
{
    FILE *f = NULL;
    if ((*rc = check_data_path(c, buf, len)))
        return NULL;
    if (!(f = fopen(buf, "r"))) {
        sf_note(r, "**Stored data missing:** cannot read %s: regenerate it with `%s > %s`.", buf, regen, buf);
        *rc = SF_EIO;
    }
    return f;
}

int check_parse_num(const char *t, double *x)
{
    char *end;
    *x = strtod(t, &end);
    return end != t && !*end;
}

void check_plot_vs_predicted(sf_result *r, const char *name, const char *title, const char *xlabel,
                             const char *ylabel, const char *what, const char *line, size_t n, const double *pred,
                             const double *meas, double lo, double hi)
{
    sf_plot *p = sf_result_plot(r, name, title, xlabel, ylabel);
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, what, SF_STYLE_POINTS, n, pred, meas);
    double dx[2] = { lo, hi };
    sf_plot_series(p, line, SF_STYLE_LINES, 2, dx, dx);
}
