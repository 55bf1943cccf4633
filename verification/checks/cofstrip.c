/* The COF the dynamics sees (issue 13): the field family's tests run on
 * realisations drawn by the COF plan (sf_cof_plan_alloc/sf_cof_plan_draw)
 * at the plan's own strip, spacing and bilinear interpolation, read through
 * sf_cof_grid_view and sf_cof_eval.  The oracle is written here and shares
 * no code with the solver: the strip geometry from the rule documented in
 * cof.h, the correlation of Eq. 2 through the Nataf map (DESIGN.md sec. 3:
 * the Gaussian field has Eq. 2, ln H ~ N(mu_g, sigma_g^2)), and the bilinear
 * weights. */
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
    const double h = doc.dx, l = s->l, mu = s->mu_mean, var_h = s->mu_std * s->mu_std;
    const ref_ln_par par = ref_lognormal_par(s->mu_mean, s->mu_std);

    /* Node patches: a x b nodes at stride st (st h = l/2, where Eq. 2 moves
     * most with l: correlations 0.78, 0.37, 0.11 at lags l/2, l, 3l/2),
     * patches >= 6 l apart (Gaussian correlation <= exp(-36)): independent.
     * The layout uses the view's node counts (valid indices); positions
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
    size_t spx = (a - 1) * st, spy = (b - 1) * st, pitx = spx + gap, pity = spy + gap;
    size_t npx = (vm - 1 - spx) / pitx + 1, npy = (vn - 1 - spy) / pity + 1, per = npx * npy;
    size_t ox = (vm - 1 - (npx - 1) * pitx - spx) / 2, oy = (vn - 1 - (npy - 1) * pity - spy) / 2;
    size_t draws = (s->samples + per - 1) / per, N = draws * per, p = a * b;

    /* Eq. 2 at the documented lags, and its Cholesky factor */
    gsl_matrix *sigma = gsl_matrix_alloc(p, p);
    for (size_t u = 0; u < p; u++)
        for (size_t v = 0; v < p; v++)
            gsl_matrix_set(sigma, u, v, ref_sq_exp(((double)(u % a) - (double)(v % a)) * (double)st * h,
                                                   ((double)(u / a) - (double)(v / a)) * (double)st * h, l));
    check_wlrt lrt;
    if (check_wlrt_init(&lrt, sigma)) {
        sf_cof_plan_free(plan);
        return SF_EFAIL;
    }

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
    const size_t npair = 4, q = 2 * npair;
    const double rc = fmin(s->R, 0.75 * l);

    gsl_rng *rng = sf_case_rng(c), *geo = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(geo, s->seed + 7919);   /* point positions: a stream of their own */
    gsl_matrix *Sq = gsl_matrix_alloc(q, q);
    gsl_vector *zq = gsl_vector_alloc(q);
    double *ks = check_alloc(N * sizeof *ks), *gv = check_alloc(p * sizeof *gv);
    double acc[4] = { 0 }, acc2[4] = { 0 };
    double sm = 0, sm2 = 0, sv = 0, sv2 = 0, sQ = 0, sQ2 = 0, sR = 0, sR2 = 0, id_err = 0;
    double bin_s[NBIN] = { 0 }, bin_s2[NBIN] = { 0 };
    size_t bin_n[NBIN] = { 0 }, bad = 0, geom_bad = 0, rejected = 0, k = 0;
    double px[16], py[16], delta[8];
    for (size_t d = 0; d < draws; d++) {
        sf_cof *cof = NULL;
        if (sf_cof_plan_draw(plan, rng, &cof)) {
            sf_note(r, "**A draw failed.**");
            bad++;
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
                bad++;
        for (size_t U = 0; U < npx; U++)
            for (size_t V = 0; V < npy; V++, k++) {
                size_t I0 = ox + U * pitx, J0 = oy + V * pity;
                double hm = 0, hv = 0;
                for (size_t j = 0; j < b; j++)
                    for (size_t i = 0; i < a; i++) {
                        double H = mv[I0 + i * st + vm * (J0 + j * st)];
                        hm += H;
                        hv += (H - mu) * (H - mu);
                        gv[i + a * j] = (log(H) - par.mu) / par.sigma;   /* oracle's inverse Nataf map */
                    }
                ks[k] = mv[I0 + vm * J0];
                hm /= (double)p;
                hv /= (double)p;
                sm += hm; sm2 += hm * hm;
                sv += hv; sv2 += hv * hv;
                for (size_t lag = 0; lag < a; lag++) {
                    double e = 0;
                    for (size_t j = 0; j < b; j++)
                        for (size_t i = 0; i + lag < a; i++)
                            e += gv[i + a * j] * gv[i + lag + a * j];
                    e /= (double)(b * (a - lag));
                    acc[lag] += e;
                    acc2[lag] += e * e;
                }
                check_wlrt_add(&lrt, gv);

                /* the interpolated COF at an off-node cluster */
                double xc = doc.x0 + ((double)I0 + 0.5 * (double)spx) * h;
                double yc = doc.y0 + ((double)J0 + 0.5 * (double)spy) * h;
                for (int tries = 0;; tries++) {
                    if (tries == 100) {
                        sf_note(r, "**No well-conditioned point set in 100 tries.**");
                        bad++;
                        break;
                    }
                    for (size_t t = 0; t < npair; t++) {
                        double rad = rc * sqrt(gsl_rng_uniform(geo)), th = 2 * M_PI * gsl_rng_uniform(geo);
                        double ax = xc + rad * cos(th), ay = yc + rad * sin(th);
                        if (t < 2) {   /* inside a cell or two: the slope */
                            double dl = h * (0.05 + 0.95 * gsl_rng_uniform(geo)), ph = 2 * M_PI * gsl_rng_uniform(geo);
                            px[2 * t] = ax;
                            py[2 * t] = ay;
                            px[2 * t + 1] = ax + dl * cos(ph);
                            py[2 * t + 1] = ay + dl * sin(ph);
                            delta[t] = dl / h;
                        } else {       /* astride a cell edge (t = 2: y = const, 3: x = const): continuity */
                            double eps = h * (0.02 + 0.01 * gsl_rng_uniform(geo));
                            if (t == 2)
                                ay = doc.y0 + round((ay - doc.y0) / h) * h;
                            else
                                ax = doc.x0 + round((ax - doc.x0) / h) * h;
                            px[2 * t] = ax - (t == 3 ? eps : 0);
                            py[2 * t] = ay - (t == 2 ? eps : 0);
                            px[2 * t + 1] = ax + (t == 3 ? eps : 0);
                            py[2 * t + 1] = ay + (t == 2 ? eps : 0);
                            delta[t] = 2 * eps / h;
                        }
                    }
                    /* exact covariance of the interpolants: a finite sum of
                     * node covariances (Eq. 2 through the Nataf map) with the
                     * bilinear weights of the documented grid */
                    long ii[16][4], jj[16][4];
                    double w[16][4];
                    int off = 0;
                    for (size_t u = 0; u < q; u++) {
                        bilinear(&doc, px[u], py[u], ii[u], jj[u], w[u]);
                        off |= px[u] < doc.x0 || py[u] < doc.y0 || px[u] > doc.x0 + (double)(doc.m - 1) * h ||
                               py[u] > doc.y0 + (double)(doc.n - 1) * h;
                    }
                    for (size_t u = 0; u < q; u++)
                        for (size_t t = 0; t <= u; t++) {
                            double cv = 0;
                            for (int e = 0; e < 4; e++)
                                for (int f = 0; f < 4; f++)
                                    cv += w[u][e] * w[t][f] * var_h *
                                          ref_rho_h(par.sigma, ref_sq_exp((double)(ii[u][e] - ii[t][f]) * h,
                                                                          (double)(jj[u][e] - jj[t][f]) * h, l));
                            gsl_matrix_set(Sq, u, t, cv);
                            gsl_matrix_set(Sq, t, u, cv);
                        }
                    double vpair[8];
                    for (size_t t = 0; t < npair; t++)
                        vpair[t] = gsl_matrix_get(Sq, 2 * t, 2 * t) + gsl_matrix_get(Sq, 2 * t + 1, 2 * t + 1) -
                                   2 * gsl_matrix_get(Sq, 2 * t, 2 * t + 1);
                    /* geometry-only rejection (never looks at the field):
                     * off the grid, or a covariance too close to singular
                     * for round-off in the field to stay negligible */
                    double dmax = 0;
                    for (size_t u = 0; u < q; u++)
                        dmax = fmax(dmax, gsl_matrix_get(Sq, u, u));
                    if (off || gsl_linalg_cholesky_decomp1(Sq)) {
                        rejected++;
                        continue;
                    }
                    double pmin = INFINITY;
                    for (size_t u = 0; u < q; u++)
                        pmin = fmin(pmin, gsl_matrix_get(Sq, u, u) * gsl_matrix_get(Sq, u, u));
                    if (pmin < 1e-9 * dmax) {
                        rejected++;
                        continue;
                    }
                    double yv[16];
                    for (size_t u = 0; u < q; u++) {
                        double e = sf_cof_eval(cof, px[u], py[u]);
                        /* exact: the view's nodes with the oracle's weights */
                        long vi[4], vj[4];
                        double vw[4], o = 0;
                        bilinear(&v, px[u], py[u], vi, vj, vw);
                        for (int f = 0; f < 4; f++)
                            o += vw[f] * mv[vi[f] + (long)vm * vj[f]];
                        /* round-off bound: the grid coordinate s = (x - x0)/dx
                         * computed another way (a product with 1/dx) moves by
                         * up to 2 eps s, which moves the value by that times
                         * the cell's node difference; the four-term sum adds
                         * a few ulp of the values */
                        double gx = fabs(px[u] - v.x0) / v.dx, gy = fabs(py[u] - v.y0) / v.dy, dn = 0, vmax = 0;
                        for (int f = 0; f < 4; f++) {
                            double nv = mv[vi[f] + (long)vm * vj[f]];
                            vmax = sf_max(vmax, fabs(nv));
                            for (int f2 = 0; f2 < 4; f2++)
                                dn = sf_max(dn, fabs(nv - mv[vi[f2] + (long)vm * vj[f2]]));
                        }
                        double bound = 2 * DBL_EPSILON * (gx + gy + 2) * dn + 8 * DBL_EPSILON * vmax;
                        double de = fabs(e - o) / bound;
                        if (!(de <= id_err)) id_err = de;   /* NaN propagates */
                        yv[u] = e - mu;
                        gsl_vector_set(zq, u, yv[u]);
                    }
                    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, Sq, zq);
                    double Q;
                    gsl_blas_ddot(zq, zq, &Q);
                    sQ += Q;
                    sQ2 += Q * Q;
                    double rp = 0;
                    for (size_t t = 0; t < npair; t++) {
                        double D = yv[2 * t + 1] - yv[2 * t], ratio = D * D / vpair[t];
                        rp += ratio / (double)npair;
                        size_t bi = (size_t)(delta[t] * NBIN);
                        if (bi >= NBIN) bi = NBIN - 1;
                        bin_s[bi] += ratio;
                        bin_s2[bi] += ratio * ratio;
                        bin_n[bi]++;
                    }
                    sR += rp;
                    sR2 += rp * rp;
                    break;
                }
            }
        sf_cof_free(cof);
    }
    N = k;

    /* geometry: the plan's strip against its documented rule (exact) */
    sf_check_rel(r, "strip spacing dx vs l/8 (cof.h rule) [m]", in->dx, h, 1e-12);
    sf_check_rel(r, "strip spacing dy vs l/8 (cof.h rule) [m]", in->dy, h, 1e-12);
    char t[200];
    int gok = geom_bad == 0 && vm == doc.m && vn == doc.n && fabs(in->x0 - doc.x0) <= 1e-12 * fabs(doc.x0) &&
              fabs(in->y0 - doc.y0) <= 1e-12 * fabs(doc.y0);
    snprintf(t, sizeof t, "plan: %zu x %zu nodes from (%.6g, %.6g) m; rule: %zu x %zu from (%.6g, %.6g) m", vm, vn,
             in->x0, in->y0, doc.m, doc.n, doc.x0, doc.y0);
    sf_check_true(r, "strip origin and node counts vs the documented rule; every draw's grid is the plan's", gok, t);
    snprintf(t, sizeof t, "COF nodes <= 0, not finite, or failed draws (of %zu draws of %zu nodes)", draws, vm * vn);
    sf_check_le(r, t, (double)bad, 0);
    sf_check_le(r, "max |sf_cof_eval - bilinear formula on the view's nodes| / its round-off bound [-]", id_err,
                c->spec.tolerance);

    /* statistics: six tests share alpha (Bonferroni) */
    double al = c->spec.alpha / 6, stat, trp, zm, zv, zq_, zr, D;
    double p_lrt = check_wlrt_done(&lrt, &stat, &trp);
    snprintf(t, sizeof t, "LRT: Gaussianised %zu x %zu node patch (stride l/2) has Eq. 2 covariance, chi2(%zu)", a, b,
             p * (p + 1) / 2);
    sf_check_pvalue(r, t, p_lrt, al, N);
    double p_m = clt_pvalue(sm, sm2, N, mu, &zm);
    double p_v = clt_pvalue(sv, sv2, N, var_h, &zv);
    snprintf(t, sizeof t, "mean COF at the patch nodes = %.4g (z test, per-patch averages)", mu);
    sf_check_pvalue(r, t, p_m, al, N);
    snprintf(t, sizeof t, "mean square deviation at the patch nodes = std^2 = %.4g (z test)", var_h);
    sf_check_pvalue(r, t, p_v, al, N);
    double p_ks = sf_ks_test(ks, N, ln_cdf, (void *)&par, &D);
    sf_check_pvalue(r, "KS of the COF at one node per patch vs the oracle lognormal", p_ks, al, N);
    double p_q = clt_pvalue(sQ, sQ2, N, (double)q, &zq_);
    snprintf(t, sizeof t, "interpolated COF at %zu off-node points: E[y^T Sigma_interp^-1 y] = %zu (z test)", q, q);
    sf_check_pvalue(r, t, p_q, al, N);
    /* the same covariance seen pair by pair: E[D^2] = Var_exact(D) exactly
     * (E[D] = 0: the weights sum to 1), and a contrast's ratio is not
     * amplified by the other points as the whitened form's can be, so its
     * mean stays light-tailed under a wrong weight */
    double p_r = clt_pvalue(sR, sR2, N, 1.0, &zr);
    snprintf(t, sizeof t, "interpolated COF: %zu close pairs per patch, mean D^2 / Var_exact(D) = 1 (z test)", npair);
    sf_check_pvalue(r, t, p_r, al, N);

    sf_note(r, "Plan: strip %zu x %zu nodes, spacing %.6g m (l/%.4g), origin (%.6g, %.6g) m. %zu draws from the "
               "case's seed; %zu patches per draw (%zu x %zu nodes at stride %zu, %zu nodes = %.3g l apart), "
               "N = %zu independent patches.\n",
            vm, vn, in->dx, l / in->dx, in->x0, in->y0, draws, per, a, b, st, gap, (double)gap * h / l, N);
    sf_note(r, "LRT statistic %.1f on %zu dof (tr S / p = %.4f). Mean COF z = %.2f; mean square deviation "
               "z = %.2f (observed %.5g, target %.5g). KS D = %.4f. Interpolation: mean quadratic form %.4f "
               "(expected %zu), z = %.2f; close-pair contrast variance ratio %.4f (expected 1), z = %.2f; %zu point "
               "sets rejected on geometry alone. Largest |eval - bilinear| %.3g.\n",
            stat, p * (p + 1) / 2, trp, zm, zv, sv / (double)N, var_h, D, sQ / (double)N, q, zq_, sR / (double)N, zr,
            rejected, id_err);

    /* plot 1: Gaussianised correlation along x vs Eq. 2 and two moderate alternatives */
    double x[4], em[4], lo[4], hi[4], xf[65], e0[65], e1[65], e2[65];
    for (size_t lag = 0; lag < a; lag++) {
        x[lag] = (double)(lag * st) * h;
        em[lag] = acc[lag] / (double)N;
        double se = sqrt(fmax(0, acc2[lag] / (double)N - em[lag] * em[lag]) / (double)N);
        lo[lag] = em[lag] - 3 * se;
        hi[lag] = em[lag] + 3 * se;
    }
    for (int i = 0; i <= 64; i++) {
        xf[i] = x[a - 1] * 1.1 * i / 64.0;
        e0[i] = ref_sq_exp(xf[i], 0, l);
        e1[i] = ref_sq_exp(xf[i], 0, 1.1 * l);
        e2[i] = ref_sq_exp(xf[i] * 8 / 7.3, 0, l);
    }
    sf_plot *pl = sf_result_plot(r, "strip_correlation",
                                 "Gaussianised strip COF: correlation along x vs Eq. 2",
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
        if (bin_n[i] < 2)
            continue;
        double nn = (double)bin_n[i], mm = bin_s[i] / nn;
        double se = sqrt(fmax(0, bin_s2[i] / nn - mm * mm) / nn);
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

    free(ks); free(gv);
    gsl_vector_free(zq);
    gsl_matrix_free(Sq);
    gsl_rng_free(rng); gsl_rng_free(geo);
    sf_cof_plan_free(plan);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_cofstrip[] = {
    { "cof_strip_field_tests", chk_cof_strip,
      "field tests on COF plan draws: strip rule, LRT, moments, marginal, interpolant covariance" },
    { NULL, NULL, NULL }
};
