/* The COF the dynamics sees: the field family's tests run on
 * realisations drawn by the COF plan (sf_cof_plan_alloc/sf_cof_plan_draw)
 * at the plan's own strip, spacing and bilinear interpolation, read through
 * sf_cof_grid_view and sf_cof_eval.  The oracle is written here and shares
 * no code with the solver: the strip geometry from the rule documented in
 * cof.h, the correlation of Eq. 2 through the Nataf map (docs/design.md sec. 4.1:
 * the Gaussian field has Eq. 2, ln H ~ N(mu_g, sigma_g^2)), and the bilinear
 * weights.  The same battery runs on the circulant strip (one grid per
 * draw) and on the tiled window (cof_generator = tiles: a window that
 * follows the disc along the belt and slides, read window after window). */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "cof.h"
#include "sf_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

typedef struct { double x0, y0, dx, dy; size_t m, n; } grid_geom;

/* The strip the plan must sample, from its documented rule (cof.h):
 * h = l/8; xb in [-v_b T - B, B], yb in [-W, W]; B = R + 2 mu_hi m g/k + 2h,
 * mu_hi = mean + 4 std; W = strip_halfwidth + R + 2h (0: W = B). */
static grid_geom documented_strip(const sf_scene *s)
{
    grid_geom d;
    double h = s->l / 8;
    double mu_hi = s->mu_mean + 4 * s->mu_std;
    double B0 = s->R + 2 * mu_hi * s->m * s->g / s->k;
    double W0 = s->strip_halfwidth > 0 ? s->strip_halfwidth + s->R : B0;
    double B = B0 + 2 * h, W = W0 + 2 * h;
    d.dx = d.dy = h;
    d.x0 = -s->v_b * s->T - B;
    d.y0 = -W;
    d.m = (size_t)ceil((s->v_b * s->T + 2 * B) / h) + 1;
    d.n = (size_t)ceil(2 * W / h) + 1;
    return d;
}

/* Bilinear weights of point (x, y) on grid g: nodes (ii[k], jj[k]). */
static void bilinear(const grid_geom *g, double x, double y, long ii[4], long jj[4], double w[4])
{
    double sx = (x - g->x0) / g->dx, sy = (y - g->y0) / g->dy;
    double fi = fmin(fmax(floor(sx), 0), (double)g->m - 2), fj = fmin(fmax(floor(sy), 0), (double)g->n - 2);
    double tx = sx - fi, ty = sy - fj;
    long i = (long)fi, j = (long)fj;
    ii[0] = i; jj[0] = j; w[0] = (1 - tx) * (1 - ty);
    ii[1] = i + 1; jj[1] = j; w[1] = tx * (1 - ty);
    ii[2] = i; jj[2] = j + 1; w[2] = (1 - tx) * ty;
    ii[3] = i + 1; jj[3] = j + 1; w[3] = tx * ty;
}

static double ln_cdf(double h, void *params)
{
    const ref_ln_par *p = params;
    return h <= 0 ? 0.0 : gsl_cdf_gaussian_P(log(h) - p->mu, p->sigma);
}

/* z test of a mean of iid values against `expect`, standard error from
 * the data (CLT): two-sided p-value. */
static double clt_pvalue(double sum, double sum2, size_t N, double expect, double *z)
{
    double Nd = (double)N, mean = sum / Nd, var = (sum2 - sum * sum / Nd) / (Nd - 1);
    *z = (mean - expect) / sqrt(var / Nd);
    return sf_z_pvalue(*z);
}

#define NBIN 10

/* ---- the battery: node patches of a x b nodes at stride st (st h = l/2,
 * where Eq. 2 moves most with l: correlations 0.78, 0.37, 0.11 at lags
 * l/2, l, 3l/2), each with an interpolation cluster at its centre.  The
 * caller lays the patches >= 6 l apart (Gaussian correlation <= exp(-36)),
 * so they are independent. */
typedef struct {
    double h, l, mu, var_h, rc;
    ref_ln_par par;
    size_t st, a, b, p, npair, q, cap;
    check_wlrt lrt;
    gsl_rng *geo;
    gsl_matrix *Sq;
    gsl_vector *zq;
    double *ks, *gv;
    double acc[4], acc2[4];
    double sm, sm2, sv, sv2, sQ, sQ2, sR, sR2, id_err;
    double bin_s[NBIN], bin_s2[NBIN];
    size_t bin_n[NBIN], bad, rejected, N;
} battery;

/* cap: patches at most; SF_EFAIL when Eq. 2's patch covariance is not
 * positive definite. */
static int battery_init(battery *t, const sf_case *c, size_t b, size_t cap)
{
    const sf_scene *s = &c->scene;
    memset(t, 0, sizeof *t);
    t->h = s->l / 8;
    t->l = s->l;
    t->mu = s->mu_mean;
    t->var_h = s->mu_std * s->mu_std;
    t->par = ref_lognormal_par(s->mu_mean, s->mu_std);
    t->st = 4;
    t->a = 4;
    t->b = b;
    t->p = t->a * b;
    t->cap = cap;
    /* Eq. 2 at the documented lags, and its Cholesky factor */
    gsl_matrix *sigma = gsl_matrix_alloc(t->p, t->p);
    for (size_t u = 0; u < t->p; u++)
        for (size_t v = 0; v < t->p; v++)
            gsl_matrix_set(sigma, u, v,
                           ref_sq_exp(((double)(u % t->a) - (double)(v % t->a)) * (double)t->st * t->h,
                                      ((double)(u / t->a) - (double)(v / t->a)) * (double)t->st * t->h, t->l));
    if (check_wlrt_init(&t->lrt, sigma))
        return SF_EFAIL;
    /* Interpolation clusters: 4 pairs of points in a disc of radius
     * rc = min(R, 3l/4) at the patch centre (under the disc: at l/R = 10
     * the whole disc).  Close pairs are where the bilinear weights show:
     * two pairs at distance U(0.05, 1) h in a random direction (their
     * contrast is the interpolant's slope), two astride a cell edge (along
     * y and along x) at distance U(0.04, 0.06) h: the interpolant is
     * continuous, so their exact contrast has sd ~ 0.05 of a node
     * difference, and a weight off by 5% opens a jump as large.  (A wider
     * range of distances makes the statistic heavy-tailed under a wrong
     * weight and costs power.) */
    t->npair = 4;
    t->q = 2 * t->npair;
    t->rc = fmin(s->R, 0.75 * t->l);
    t->geo = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(t->geo, s->seed + 7919);   /* point positions: a stream of their own */
    t->Sq = gsl_matrix_alloc(t->q, t->q);
    t->zq = gsl_vector_alloc(t->q);
    t->ks = check_alloc(cap * sizeof *t->ks);
    t->gv = check_alloc(t->p * sizeof *t->gv);
    return SF_SUCCESS;
}

/* One patch: its a x b nodes from the view (mv, vm columns) at view
 * indices (I0 + i st, J0 + j st); doc is the documented grid of the same
 * nodes (positions, lags and bilinear weights of the oracle), v the view's
 * own geometry (the exact identity of sf_cof_eval). */
static void battery_patch(battery *t, sf_result *r, const grid_geom *doc, const grid_geom *v, const double *mv,
                          const sf_cof *cof, size_t I0, size_t J0)
{
    const size_t a = t->a, b = t->b, st = t->st, p = t->p, vm = v->m, npair = t->npair, q = t->q;
    const double h = t->h, mu = t->mu, var_h = t->var_h, l = t->l;
    double *gv = t->gv;
    if (t->N == t->cap)
        return;
    double hm = 0, hv = 0;
    for (size_t j = 0; j < b; j++)
        for (size_t i = 0; i < a; i++) {
            double H = mv[I0 + i * st + vm * (J0 + j * st)];
            hm += H;
            hv += (H - mu) * (H - mu);
            gv[i + a * j] = (log(H) - t->par.mu) / t->par.sigma;   /* oracle's inverse Nataf map */
        }
    t->ks[t->N++] = mv[I0 + vm * J0];
    hm /= (double)p;
    hv /= (double)p;
    t->sm += hm; t->sm2 += hm * hm;
    t->sv += hv; t->sv2 += hv * hv;
    for (size_t lag = 0; lag < a; lag++) {
        double e = 0;
        for (size_t j = 0; j < b; j++)
            for (size_t i = 0; i + lag < a; i++)
                e += gv[i + a * j] * gv[i + lag + a * j];
        e /= (double)(b * (a - lag));
        t->acc[lag] += e;
        t->acc2[lag] += e * e;
    }
    check_wlrt_add(&t->lrt, gv);

    /* the interpolated COF at an off-node cluster */
    const double spx = (double)((a - 1) * st), spy = (double)((b - 1) * st);
    double xc = doc->x0 + ((double)I0 + 0.5 * spx) * h;
    double yc = doc->y0 + ((double)J0 + 0.5 * spy) * h;
    double px[16], py[16], delta[8];
    gsl_rng *geo = t->geo;
    for (int tries = 0;; tries++) {
        if (tries == 100) {
            sf_note(r, "**No well-conditioned point set in 100 tries.**");
            t->bad++;
            break;
        }
        for (size_t k = 0; k < npair; k++) {
            double rad = t->rc * sqrt(gsl_rng_uniform(geo)), th = 2 * M_PI * gsl_rng_uniform(geo);
            double ax = xc + rad * cos(th), ay = yc + rad * sin(th);
            if (k < 2) {   /* inside a cell or two: the slope */
                double dl = h * (0.05 + 0.95 * gsl_rng_uniform(geo)), ph = 2 * M_PI * gsl_rng_uniform(geo);
                px[2 * k] = ax;
                py[2 * k] = ay;
                px[2 * k + 1] = ax + dl * cos(ph);
                py[2 * k + 1] = ay + dl * sin(ph);
                delta[k] = dl / h;
            } else {       /* astride a cell edge (k = 2: y = const, 3: x = const): continuity */
                double eps = h * (0.02 + 0.01 * gsl_rng_uniform(geo));
                if (k == 2)
                    ay = doc->y0 + round((ay - doc->y0) / h) * h;
                else
                    ax = doc->x0 + round((ax - doc->x0) / h) * h;
                px[2 * k] = ax - (k == 3 ? eps : 0);
                py[2 * k] = ay - (k == 2 ? eps : 0);
                px[2 * k + 1] = ax + (k == 3 ? eps : 0);
                py[2 * k + 1] = ay + (k == 2 ? eps : 0);
                delta[k] = 2 * eps / h;
            }
        }
        /* exact covariance of the interpolants: a finite sum of node
         * covariances (Eq. 2 through the Nataf map) with the bilinear
         * weights of the documented grid */
        long ii[16][4], jj[16][4];
        double w[16][4];
        int off = 0;
        for (size_t u = 0; u < q; u++) {
            bilinear(doc, px[u], py[u], ii[u], jj[u], w[u]);
            off |= px[u] < doc->x0 || py[u] < doc->y0 || px[u] > doc->x0 + (double)(doc->m - 1) * h ||
                   py[u] > doc->y0 + (double)(doc->n - 1) * h;
        }
        for (size_t u = 0; u < q; u++)
            for (size_t k = 0; k <= u; k++) {
                double cv = 0;
                for (int e = 0; e < 4; e++)
                    for (int f = 0; f < 4; f++)
                        cv += w[u][e] * w[k][f] * var_h *
                              ref_rho_h(t->par.sigma, ref_sq_exp((double)(ii[u][e] - ii[k][f]) * h,
                                                                 (double)(jj[u][e] - jj[k][f]) * h, l));
                gsl_matrix_set(t->Sq, u, k, cv);
                gsl_matrix_set(t->Sq, k, u, cv);
            }
        double vpair[8];
        for (size_t k = 0; k < npair; k++)
            vpair[k] = gsl_matrix_get(t->Sq, 2 * k, 2 * k) + gsl_matrix_get(t->Sq, 2 * k + 1, 2 * k + 1) -
                       2 * gsl_matrix_get(t->Sq, 2 * k, 2 * k + 1);
        /* geometry-only rejection (never looks at the field): off the
         * grid, or a covariance too close to singular for round-off in the
         * field to stay negligible */
        double dmax = 0;
        for (size_t u = 0; u < q; u++)
            dmax = fmax(dmax, gsl_matrix_get(t->Sq, u, u));
        if (off || gsl_linalg_cholesky_decomp1(t->Sq)) {
            t->rejected++;
            continue;
        }
        double pmin = INFINITY;
        for (size_t u = 0; u < q; u++)
            pmin = fmin(pmin, gsl_matrix_get(t->Sq, u, u) * gsl_matrix_get(t->Sq, u, u));
        if (pmin < 1e-9 * dmax) {
            t->rejected++;
            continue;
        }
        double yv[16];
        for (size_t u = 0; u < q; u++) {
            double e = sf_cof_eval(cof, px[u], py[u]);
            /* exact: the view's nodes with the oracle's weights */
            long vi[4], vj[4];
            double vw[4], o = 0;
            bilinear(v, px[u], py[u], vi, vj, vw);
            for (int f = 0; f < 4; f++)
                o += vw[f] * mv[vi[f] + (long)vm * vj[f]];
            /* round-off bound: the grid coordinate s = (x - x0)/dx
             * computed another way (a product with 1/dx) moves by up to
             * 2 eps s, which moves the value by that times the cell's node
             * difference; the four-term sum adds a few ulp of the values */
            double gx = fabs(px[u] - v->x0) / v->dx, gy = fabs(py[u] - v->y0) / v->dy, dn = 0, vmax = 0;
            for (int f = 0; f < 4; f++) {
                double nv = mv[vi[f] + (long)vm * vj[f]];
                vmax = sf_max(vmax, fabs(nv));
                for (int f2 = 0; f2 < 4; f2++)
                    dn = sf_max(dn, fabs(nv - mv[vi[f2] + (long)vm * vj[f2]]));
            }
            double bound = 2 * DBL_EPSILON * (gx + gy + 2) * dn + 8 * DBL_EPSILON * vmax;
            double de = fabs(e - o) / bound;
            if (!(de <= t->id_err)) t->id_err = de;   /* NaN propagates */
            yv[u] = e - mu;
            gsl_vector_set(t->zq, u, yv[u]);
        }
        gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, t->Sq, t->zq);
        double Q;
        gsl_blas_ddot(t->zq, t->zq, &Q);
        t->sQ += Q;
        t->sQ2 += Q * Q;
        double rp = 0;
        for (size_t k = 0; k < npair; k++) {
            double D = yv[2 * k + 1] - yv[2 * k], ratio = D * D / vpair[k];
            rp += ratio / (double)npair;
            size_t bi = (size_t)(delta[k] * NBIN);
            if (bi >= NBIN) bi = NBIN - 1;
            t->bin_s[bi] += ratio;
            t->bin_s2[bi] += ratio * ratio;
            t->bin_n[bi]++;
        }
        t->sR += rp;
        t->sR2 += rp * rp;
        break;
    }
}

/* The statistical rows (alpha split equally, Bonferroni), the findings
 * and the plots; frees the battery.  scale: also the whitened sum of
 * squares against chi2(N p) (the patch LRT's scale direction on its own). */
static void battery_report(battery *t, sf_result *r, const sf_case *c, int scale)
{
    const size_t N = t->N, a = t->a, b = t->b, p = t->p, q = t->q, npair = t->npair;
    const double h = t->h, l = t->l;
    char s[200];
    sf_check_le(r, "max |sf_cof_eval - bilinear formula on the view's nodes| / its round-off bound [-]", t->id_err,
                c->spec.tolerance);
    double al = c->spec.alpha / (scale ? 7 : 6), stat, trp, zm, zv, zq, zr, D;
    double p_lrt = check_wlrt_done(&t->lrt, &stat, &trp);
    snprintf(s, sizeof s, "LRT: Gaussianised %zu x %zu node patch (stride l/2) has Eq. 2 covariance, chi2(%zu)", a, b,
             p * (p + 1) / 2);
    sf_check_pvalue(r, s, p_lrt, al, N);
    if (scale) {
        /* under the null the N p whitened values are iid N(0, 1) */
        double p_sc = sf_var_pvalue(trp, 1.0, N * p, 1);
        snprintf(s, sizeof s, "whitened patch values: sum of squares / (N p) = %.4f vs 1, chi2(N p = %zu), two-sided",
                 trp, N * p);
        sf_check_pvalue(r, s, p_sc, al, N);
    }
    double p_m = clt_pvalue(t->sm, t->sm2, N, t->mu, &zm);
    double p_v = clt_pvalue(t->sv, t->sv2, N, t->var_h, &zv);
    snprintf(s, sizeof s, "mean COF at the patch nodes = %.4g (z test, per-patch averages)", t->mu);
    sf_check_pvalue(r, s, p_m, al, N);
    snprintf(s, sizeof s, "mean square deviation at the patch nodes = std^2 = %.4g (z test)", t->var_h);
    sf_check_pvalue(r, s, p_v, al, N);
    double p_ks = sf_ks_test(t->ks, N, ln_cdf, (void *)&t->par, &D);
    sf_check_pvalue(r, "KS of the COF at one node per patch vs the oracle lognormal", p_ks, al, N);
    double p_q = clt_pvalue(t->sQ, t->sQ2, N, (double)q, &zq);
    snprintf(s, sizeof s, "interpolated COF at %zu off-node points: E[y^T Sigma_interp^-1 y] = %zu (z test)", q, q);
    sf_check_pvalue(r, s, p_q, al, N);
    /* the same covariance seen pair by pair: E[D^2] = Var_exact(D) exactly
     * (E[D] = 0: the weights sum to 1), and a contrast's ratio is not
     * amplified by the other points as the whitened form's can be, so its
     * mean stays light-tailed under a wrong weight */
    double p_r = clt_pvalue(t->sR, t->sR2, N, 1.0, &zr);
    snprintf(s, sizeof s, "interpolated COF: %zu close pairs per patch, mean D^2 / Var_exact(D) = 1 (z test)", npair);
    sf_check_pvalue(r, s, p_r, al, N);

    sf_note(r, "LRT statistic %.1f on %zu dof (tr S / p = %.4f). Mean COF z = %.2f; mean square deviation "
               "z = %.2f (observed %.5g, target %.5g). KS D = %.4f. Interpolation: mean quadratic form %.4f "
               "(expected %zu), z = %.2f; close-pair contrast variance ratio %.4f (expected 1), z = %.2f; %zu point "
               "sets rejected on geometry alone. Largest |eval - bilinear| %.3g.\n",
            stat, p * (p + 1) / 2, trp, zm, zv, t->sv / (double)N, t->var_h, D, t->sQ / (double)N, q, zq,
            t->sR / (double)N, zr, t->rejected, t->id_err);

    /* plot 1: Gaussianised correlation along x vs Eq. 2 and two moderate alternatives */
    double x[4], em[4], lo[4], hi[4], xf[65], e0[65], e1[65], e2[65];
    for (size_t lag = 0; lag < a; lag++) {
        x[lag] = (double)(lag * t->st) * h;
        em[lag] = t->acc[lag] / (double)N;
        double se = sqrt(fmax(0, t->acc2[lag] / (double)N - em[lag] * em[lag]) / (double)N);
        lo[lag] = em[lag] - 3 * se;
        hi[lag] = em[lag] + 3 * se;
    }
    for (int i = 0; i <= 64; i++) {
        xf[i] = x[a - 1] * 1.1 * i / 64.0;
        e0[i] = ref_sq_exp(xf[i], 0, l);
        e1[i] = ref_sq_exp(xf[i], 0, 1.1 * l);
        e2[i] = ref_sq_exp(xf[i] * 8 / 7.3, 0, l);
    }
    sf_plot *pl = sf_result_plot(r, "strip_correlation", "Gaussianised strip COF: correlation along x vs Eq. 2",
                                 "lag (documented spacing l/8 x node index) [m]", "correlation [-]");
    sf_plot_band(pl, "empirical +-3 standard errors", a, x, lo, hi);
    sf_plot_series(pl, "Eq. 2, exp(-r^2/l^2)", SF_STYLE_LINES, 65, xf, e0);
    sf_plot_series(pl, "alternative: l x 1.1", SF_STYLE_LINES, 65, xf, e1);
    sf_plot_series(pl, "alternative: spacing l/7.3", SF_STYLE_LINES, 65, xf, e2);
    sf_plot_series(pl, "empirical mean", SF_STYLE_POINTS, a, x, em);

    /* plot 2: normalised contrast variance of the interpolant vs pair distance */
    double bx[NBIN], by[NBIN], blo[NBIN], bhi[NBIN];
    size_t nb = 0;
    for (size_t i = 0; i < NBIN; i++) {
        if (t->bin_n[i] < 2)
            continue;
        double nn = (double)t->bin_n[i], mm = t->bin_s[i] / nn;
        double se = sqrt(fmax(0, t->bin_s2[i] / nn - mm * mm) / nn);
        bx[nb] = ((double)i + 0.5) / NBIN;
        by[nb] = mm;
        blo[nb] = mm - 3 * se;
        bhi[nb] = mm + 3 * se;
        nb++;
    }
    sf_plot *p2 = sf_result_plot(r, "interpolant_contrast",
                                 "Interpolated COF: sampled / exact variance of H(b) - H(a) for close pairs",
                                 "pair distance / node spacing [-]", "sample mean of D^2 / Var_exact(D) [-]");
    sf_plot_band(p2, "+-3 standard errors", nb, bx, blo, bhi);
    sf_plot_series(p2, "sampled", SF_STYLE_POINTS, nb, bx, by);
    sf_plot_hline(p2, "exact (finite sum over node covariances)", 1.0);

    free(t->ks);
    free(t->gv);
    gsl_vector_free(t->zq);
    gsl_matrix_free(t->Sq);
    gsl_rng_free(t->geo);
}

/* Patch rows across n nodes: how many (npy), the pitch and the first
 * row's index, patches of b rows at stride st with gap nodes between. */
static size_t patch_rows(size_t n, size_t b, size_t st, size_t gap, size_t *pity, size_t *oy)
{
    size_t spy = (b - 1) * st, npy = (n - 1 - spy) / (spy + gap) + 1;
    *pity = spy + gap;
    *oy = (n - 1 - (npy - 1) * *pity - spy) / 2;
    return npy;
}

static int chk_cof_strip(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (s->cof != SF_COF_FIELD || s->precorrect || !(s->mu_std > 0) || s->samples < 50)
        return SF_EINVAL;   /* the oracle is the paper's map: Eq. 2 in the Gaussian field */
    char err[256] = "";
    sf_cof_plan *plan;
    if (sf_cof_plan_alloc(s, &plan, err, sizeof err)) {
        sf_note(r, "**The COF plan was refused:** %s", err);
        return SF_EFAIL;
    }
    const grid_geom doc = documented_strip(s);
    const double h = doc.dx, l = s->l;

    /* The layout uses the view's node counts (valid indices); positions
     * and lags the documented spacing, so a spacing error moves the lags
     * the oracle expects. */
    const size_t st = 4, a = 4, gap = (size_t)ceil(6 * l / h);
    const sf_cof_plan_info *in = sf_cof_plan_get_info(plan);
    size_t vm = in->nx, vn = in->ny;
    if (in->kind != SF_COF_FIELD || vm < 2 || vn < 2) {
        sf_note(r, "**The plan did not plan a strip field** (kind %d).", (int)in->kind);
        sf_cof_plan_free(plan);
        return SF_EFAIL;
    }
    size_t b = (vn - 1) / st + 1 < a ? (vn - 1) / st + 1 : a;
    if (vm - 1 < (a - 1) * st || b < 2) {
        sf_cof_plan_free(plan);
        return SF_EINVAL;
    }
    size_t spx = (a - 1) * st, pitx = spx + gap, pity, oy;
    size_t npy = patch_rows(vn, b, st, gap, &pity, &oy);
    size_t npx = (vm - 1 - spx) / pitx + 1, per = npx * npy;
    size_t ox = (vm - 1 - (npx - 1) * pitx - spx) / 2;
    size_t draws = (s->samples + per - 1) / per;

    battery t;
    if (battery_init(&t, c, b, draws * per)) {
        sf_cof_plan_free(plan);
        return SF_EFAIL;
    }
    gsl_rng *rng = sf_case_rng(c);
    size_t geom_bad = 0;
    for (size_t d = 0; d < draws; d++) {
        sf_cof *cof = NULL;
        if (sf_cof_plan_draw(plan, rng, &cof)) {
            sf_note(r, "**A draw failed.**");
            t.bad++;
            break;
        }
        grid_geom v;
        const double *mv;
        if (sf_cof_grid_view(cof, &v.m, &v.n, &v.x0, &v.y0, &v.dx, &v.dy, &mv) || v.m != vm || v.n != vn ||
            v.dx != in->dx || v.dy != in->dy || v.x0 != in->x0 || v.y0 != in->y0) {
            geom_bad++;
            sf_cof_free(cof);
            continue;
        }
        for (size_t i = 0; i < v.m * v.n; i++)
            if (!(mv[i] > 0) || !isfinite(mv[i]))
                t.bad++;
        for (size_t U = 0; U < npx; U++)
            for (size_t V = 0; V < npy; V++)
                battery_patch(&t, r, &doc, &v, mv, cof, ox + U * pitx, oy + V * pity);
        sf_cof_free(cof);
    }

    /* geometry: the plan's strip against its documented rule (exact) */
    sf_check_rel(r, "strip spacing dx vs l/8 (cof.h rule) [m]", in->dx, h, 1e-12);
    sf_check_rel(r, "strip spacing dy vs l/8 (cof.h rule) [m]", in->dy, h, 1e-12);
    char txt[200];
    int gok = geom_bad == 0 && vm == doc.m && vn == doc.n && fabs(in->x0 - doc.x0) <= 1e-12 * fabs(doc.x0) &&
              fabs(in->y0 - doc.y0) <= 1e-12 * fabs(doc.y0);
    snprintf(txt, sizeof txt, "plan: %zu x %zu nodes from (%.6g, %.6g) m; rule: %zu x %zu from (%.6g, %.6g) m", vm, vn,
             in->x0, in->y0, doc.m, doc.n, doc.x0, doc.y0);
    sf_check_true(r, "strip origin and node counts vs the documented rule; every draw's grid is the plan's", gok, txt);
    snprintf(txt, sizeof txt, "COF nodes <= 0, not finite, or failed draws (of %zu draws of %zu nodes)", draws, vm * vn);
    sf_check_le(r, txt, (double)t.bad, 0);

    /* statistics: six tests share alpha (Bonferroni) */
    sf_note(r, "Plan: strip %zu x %zu nodes, spacing %.6g m (l/%.4g), origin (%.6g, %.6g) m. %zu draws from the "
               "case's seed; %zu patches per draw (%zu x %zu nodes at stride %zu, %zu nodes = %.3g l apart), "
               "N = %zu independent patches.\n",
            vm, vn, in->dx, l / in->dx, in->x0, in->y0, draws, per, a, b, st, gap, (double)gap * h / l, t.N);
    battery_report(&t, r, c, 0);
    gsl_rng_free(rng);
    sf_cof_plan_free(plan);
    return SF_SUCCESS;
}

/* ---- the tiled window (cof_generator = tiles): the grid is a window of
 * the lattice x = i l/8 that follows the disc (cof.h).  The window rule
 * (cof.c): the disc's footprint 2R, a margin M = max(R/4, 2h) each side
 * and a slack R towards -x, so nx = ceil((3R + 3M)/h) + 1; the oscillator
 * asks it to hold [xb - R - M, xb + R + M] before every step and moves
 * the disc by less than M/2 per step (oscillator.c). */
typedef struct {
    const sf_cof_plan_info *in;
    grid_geom doc;             /* the documented strip: y0, ny, h */
    double R, M, step;
    size_t spx, pitx, pity, oy, npy;
    size_t windows, win_bad, nodes_bad, follow_bad, after_slide, straddle, compared, mismatched;
} window_run;

/* The current window, checked against the documented lattice; 1 when it
 * can be read (*lo: its first lattice column). */
static int window_look(window_run *w, const sf_cof *cof, double xlo, double xhi, grid_geom *v, const double **mv,
                       long *lo)
{
    const double h = w->doc.dx;
    if (sf_cof_grid_view(cof, &v->m, &v->n, &v->x0, &v->y0, &v->dx, &v->dy, mv)) {
        w->win_bad++;
        return 0;
    }
    *lo = lround(v->x0 / h);
    int ok = v->m == w->in->nx && v->n == w->doc.n && fabs(v->dx - h) <= 1e-12 * h && fabs(v->dy - h) <= 1e-12 * h &&
             fabs(v->y0 - w->doc.y0) <= 1e-12 * fabs(w->doc.y0) &&
             fabs(v->x0 - (double)*lo * h) <= 1e-12 * fmax(fabs(v->x0), h) && v->x0 <= xlo &&
             v->x0 + (double)(v->m - 1) * h >= xhi;
    if (!ok) {
        w->win_bad++;
        return 0;
    }
    for (size_t i = 0; i < v->m * v->n; i++)
        if (!((*mv)[i] > 0) || !isfinite((*mv)[i]))
            w->nodes_bad++;
    return 1;
}

/* One trip of the disc towards -x (where the belt carries it) from belt
 * x = x1, in steps of 0.45 M, the window following as the oscillator makes
 * it.  Patch columns at lattice columns I, I - pitx, ... (I: the rightmost
 * that the first window holds whole) are read each from the first window
 * that holds it whole: ncols of them.  Then the window is compared, value
 * by value, with one made afresh at the same place from the same key
 * (kr: the rng state before the draw). */
static void window_trip(window_run *w, battery *t, sf_result *r, const sf_cof_plan *plan, sf_cof *cof,
                        const gsl_rng *kr, double x1, size_t ncols)
{
    const double h = w->doc.dx;
    double xb = x1, xlo = 0, xhi = 0;
    long inext = 0, lprev = 0;
    size_t got = 0, nwin = 0;
    while (got < ncols) {
        xlo = xb - w->R - w->M;
        xhi = xb + w->R + w->M;
        if (sf_cof_follow(cof, xlo, xhi)) {
            w->follow_bad++;
            return;
        }
        grid_geom v;
        const double *mv;
        long lo;
        if (!window_look(w, cof, xlo, xhi, &v, &mv, &lo))
            return;
        if (nwin == 0 || lo != lprev) {   /* a window not seen yet */
            w->windows++;
            long shift = nwin ? lprev - lo : 0;   /* new columns: view indices [0, shift) */
            if (nwin == 0) {
                inext = lo + (long)v.m - 1 - (long)w->spx;
            } else if (shift > 0) {
                /* a patch astride the seam between moved and newly made
                 * columns, where it keeps its distance from the last */
                long sx = lprev - 1 - (long)floor(gsl_rng_uniform(t->geo) * (double)w->spx);
                inext = sx < inext ? sx : inext;
            }
            while (got < ncols && inext >= lo && inext + (long)w->spx <= lo + (long)v.m - 1) {
                grid_geom dw = { (double)lo * h, w->doc.y0, h, h, w->in->nx, w->doc.n };
                for (size_t V = 0; V < w->npy; V++)
                    battery_patch(t, r, &dw, &v, mv, cof, (size_t)(inext - lo), w->oy + V * w->pity);
                w->after_slide += nwin ? w->npy : 0;
                w->straddle += shift > 0 && inext - lo < shift && inext - lo + (long)w->spx >= shift ? w->npy : 0;
                got++;
                inext -= (long)w->pitx;
            }
            nwin++;
            lprev = lo;
        }
        xb -= w->step;
    }
    /* the same window made afresh: a draw from the same key, one follow */
    gsl_rng *k2 = gsl_rng_clone(kr);
    sf_cof *ref = NULL;
    grid_geom v, vr;
    const double *mv, *mr;
    if (sf_cof_plan_draw((sf_cof_plan *)plan, k2, &ref) || sf_cof_follow(ref, xlo, xhi) ||
        sf_cof_grid_view(ref, &vr.m, &vr.n, &vr.x0, &vr.y0, &vr.dx, &vr.dy, &mr) ||
        sf_cof_grid_view(cof, &v.m, &v.n, &v.x0, &v.y0, &v.dx, &v.dy, &mv) || v.m != vr.m || v.n != vr.n ||
        v.x0 != vr.x0) {
        w->follow_bad++;
    } else {
        for (size_t i = 0; i < v.m * v.n; i++)
            w->mismatched += mv[i] != mr[i];   /* bits (a NaN counts) */
        w->compared += v.m * v.n;
    }
    sf_cof_free(ref);
    gsl_rng_free(k2);
}

static int chk_cof_window(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    if (s->cof != SF_COF_FIELD || s->precorrect || !(s->mu_std > 0) || s->samples < 50 ||
        s->cof_generator == SF_COFGEN_CIRCULANT || !(s->strip_halfwidth > 0))
        return SF_EINVAL;   /* the oracle is Eq. 2 through the Nataf map, on the tiled window */
    const sf_scene gs = check_gen_scene(c);   /* a power run's alternative: the generator only */
    char err[256] = "";
    sf_cof_plan *plan;
    if (sf_cof_plan_alloc(&gs, &plan, err, sizeof err)) {
        sf_note(r, "**The COF plan was refused:** %s", err);
        return SF_EFAIL;
    }
    window_run w;
    memset(&w, 0, sizeof w);
    w.in = sf_cof_plan_get_info(plan);
    w.doc = documented_strip(s);
    const double h = w.doc.dx, l = s->l, L = s->v_b * s->T;
    w.R = s->R;
    w.M = fmax(s->R / 4, 2 * h);
    w.step = 0.45 * w.M;
    const size_t st = 4, a = 4, gap = (size_t)ceil(6 * l / h), nxr = (size_t)ceil((3 * w.R + 3 * w.M) / h) + 1;
    if (w.in->kind != SF_COF_FIELD || w.in->generator != SF_COFGEN_TILES) {
        sf_note(r, "**The plan did not plan a tiled window** (kind %d, generator %d).", (int)w.in->kind,
                w.in->generator);
        sf_cof_plan_free(plan);
        return SF_EFAIL;
    }
    size_t b = (w.doc.n - 1) / st + 1 < a ? (w.doc.n - 1) / st + 1 : a;
    w.spx = (a - 1) * st;
    w.pitx = w.spx + gap;
    w.npy = patch_rows(w.doc.n, b, st, gap, &w.pity, &w.oy);
    /* two trips per draw, of ncols patch columns each: from the origin,
     * and from a start drawn over [-L/2, -L] (far along the belt, a jump:
     * the window made whole), each >= 6 l from the other */
    double reach = 3 * (w.R + w.M) + 6 * l;   /* belt a trip holds beyond its patch columns [m] */
    double room = L / 2 - reach;
    /* a trip's patch columns take at most pitx + spx columns each (a
     * patch put astride a seam goes up to spx further) */
    if (nxr - 1 < w.spx + 2 || b < 2 || !(room >= (double)(w.pitx + w.spx) * h)) {
        sf_cof_plan_free(plan);
        return SF_EINVAL;
    }
    size_t ncols = (size_t)floor(room / ((double)(w.pitx + w.spx) * h)), per_min = 4;
    size_t want = (s->samples + 2 * w.npy * per_min - 1) / (2 * w.npy * per_min);
    ncols = want < ncols ? want : ncols;
    ncols = ncols ? ncols : 1;
    size_t per = 2 * ncols * w.npy, draws = (s->samples + per - 1) / per;

    battery t;
    if (battery_init(&t, c, b, draws * per)) {
        sf_cof_plan_free(plan);
        return SF_EFAIL;
    }
    gsl_rng *rng = sf_case_rng(c);
    for (size_t d = 0; d < draws; d++) {
        gsl_rng *kr = gsl_rng_clone(rng);   /* the key's source, for the window made afresh */
        sf_cof *cof = NULL;
        if (sf_cof_plan_draw(plan, rng, &cof)) {
            sf_note(r, "**A draw failed.**");
            t.bad++;
            gsl_rng_free(kr);
            break;
        }
        double D = (double)(ncols * w.pitx) * h, x2 = -L / 2 - (w.R + w.M) - gsl_rng_uniform(t.geo) * (room - D);
        window_trip(&w, &t, r, plan, cof, kr, 0, ncols);
        window_trip(&w, &t, r, plan, cof, kr, x2, ncols);
        sf_cof_free(cof);
        gsl_rng_free(kr);
    }

    /* geometry (exact): the window against its documented rule */
    sf_check_rel(r, "window spacing dx vs l/8 (cof.h rule) [m]", w.in->dx, h, 1e-12);
    sf_check_rel(r, "window spacing dy vs l/8 (cof.h rule) [m]", w.in->dy, h, 1e-12);
    char txt[240];
    int rule = w.in->nx == nxr && w.in->ny == w.doc.n && w.in->margin == w.M;
    snprintf(txt, sizeof txt, "plan: %zu x %zu nodes, M = %.6g m; rule: %zu x %zu, M = %.6g m", w.in->nx, w.in->ny,
             w.in->margin, nxr, w.doc.n, w.M);
    sf_check_true(r, "window size vs its rule: nx = ceil((3R + 3M)/h) + 1, M = max(R/4, 2h), ny of the strip", rule,
                  txt);
    snprintf(txt, sizeof txt, "windows off the lattice x = i l/8, not nx x ny from y = -W, or not holding the footprint "
                              "+ M asked for (of %zu windows read)", w.windows);
    sf_check_le(r, txt, (double)w.win_bad, 0);
    snprintf(txt, sizeof txt, "COF nodes <= 0 or not finite (all nodes of %zu windows), failed draws or follows",
             w.windows);
    sf_check_le(r, txt, (double)(w.nodes_bad + w.follow_bad + t.bad), 0);
    snprintf(txt, sizeof txt, "window after a trip vs one made afresh there from the same key: values that differ "
                              "(of %zu compared, bits)", w.compared);
    sf_check_le(r, txt, (double)(w.mismatched + (w.compared == 0)), 0);

    /* statistics: seven tests share alpha (Bonferroni) */
    sf_note(r, "Plan: tiled window %zu x %zu nodes, spacing %.6g m (l/%.4g), y0 = %.6g m, margin %.4g m. %zu draws "
               "from the case's seed, two trips each (from the origin; from a start over [%.4g, %.4g] m) of %zu "
               "patch columns x %zu rows (%zu x %zu nodes at stride %zu, %zu nodes = %.3g l apart); %zu windows "
               "read. N = %zu independent patches: %zu read after the trip's first window, %zu of them straddling "
               "the seam between moved and newly made columns.\n",
            w.in->nx, w.in->ny, w.in->dx, l / w.in->dx, w.in->y0, w.in->margin, draws, -L, -L / 2, ncols, w.npy, a,
            b, st, gap, (double)gap * h / l, w.windows, t.N, w.after_slide, w.straddle);
    battery_report(&t, r, c, 1);
    gsl_rng_free(rng);
    sf_cof_plan_free(plan);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_cofstrip[] = {
    { "cof_strip_field_tests", chk_cof_strip,
      "field tests on COF plan draws: strip rule, LRT, moments, marginal, interpolant covariance" },
    { "cof_window_field_tests", chk_cof_window,
      "the same on the tiled window the plan slides along the belt: window rule, slides vs fresh windows" },
    { NULL, NULL, NULL }
};
