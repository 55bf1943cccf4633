/* The references the cell-average checks (cellavg.c) rest on, computed
 * without the solver's cell-average code: the box-averaged lognormal
 * covariance by quadrature, and the exact box average of a bilinear grid
 * (check_cellavg_filter, also used by design.c). */
#include "common.h"
#include "cellavg_oracle.h"
#include "cof.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_integration.h>

/* ---- the oracle: Cov(mu_h(0), mu_h(dx, dy)) =
 * (1/h^4) int_{-h}^{h} int_{-h}^{h} (h - |u|)(h - |v|) Cov_mu(dx + u, dy + v) du dv,
 * Gauss-Legendre (GSL, 20 points) on pieces of at most l/2 split at the
 * triangle's kink; Cov_mu from the oracle's own Nataf parameters. */

static double cov_mu(const oracle_par *o, double x, double y)
{
    return o->mean * o->mean * expm1(o->s2 * exp(-(x * x + y * y) / (o->l * o->l)));
}

size_t cellavg_nodes_1d(double h, double l, const gsl_integration_glfixed_table *gl, double *u, double *w)
{
    size_t pieces = (size_t)ceil(h / (l / 2)), n = 0;
    for (int side = -1; side <= 1; side += 2)
        for (size_t p = 0; p < pieces; p++) {
            double a = h * (double)p / (double)pieces, b = h * (double)(p + 1) / (double)pieces;
            for (size_t k = 0; k < gl->n; k++) {
                double x, wk;
                gsl_integration_glfixed_point(a, b, k, &x, &wk, gl);
                u[n] = side * x;
                w[n++] = wk * (h - x) / (h * h);
            }
        }
    return n;
}

double cellavg_oracle_cov(const oracle_par *o, double h, double dx, double dy, const double *u, const double *w,
                          size_t n)
{
    /* boxes more than 10 l apart along an axis: every value of the
     * integrand is below mubar^2 sG^2 e^-100, zero in double precision */
    if (fabs(dx) - h > 10 * o->l || fabs(dy) - h > 10 * o->l)
        return 0;
    double s = 0;
    for (size_t j = 0; j < n; j++) {
        double r = 0;
        for (size_t i = 0; i < n; i++)
            r += w[i] * cov_mu(o, dx + u[i], dy + u[j]);
        s += w[j] * r;
    }
    return s;
}

/* ---- the exact box average of a bilinear grid: the interpolant is a sum
 * of tensor-product hat functions, so its integral over an axis-aligned
 * box is separable; the weight of node i along an axis is the integral
 * of its hat over the box's interval.  Nodes off the grid are dropped and
 * the weights renormalised (only at the strip's edge, which the disc never
 * reaches: the strip bound B of cof.h). */
static double hat_prim(double t)
{
    if (t <= -1)
        return 0;
    if (t <= 0)
        return 0.5 * (t + 1) * (t + 1);
    if (t <= 1)
        return 1 - 0.5 * (1 - t) * (1 - t);
    return 1;
}

/* weights of fine nodes i0.. for the interval [a, b] on a lattice x0 + i dx, m nodes */
static size_t box_weights(double a, double b, double x0, double dx, size_t m, size_t *i0, double *w, size_t cap)
{
    long lo = (long)floor((a - x0) / dx) - 1, hi = (long)ceil((b - x0) / dx) + 1;
    lo = lo < 0 ? 0 : lo;
    hi = hi > (long)m - 1 ? (long)m - 1 : hi;
    size_t n = 0;
    double sum = 0;
    for (long i = lo; i <= hi && n < cap; i++) {
        double xi = x0 + (double)i * dx;
        w[n] = hat_prim((b - xi) / dx) - hat_prim((a - xi) / dx);
        sum += w[n++];
    }
    for (size_t k = 0; k < n; k++)
        w[k] /= sum;
    *i0 = (size_t)lo;
    return n;
}

/* The cell-average COF of the fine grid `fine` on the effective grid of
 * scene sc (spacing box/3, marked with its box), its deviations from the
 * mean times `scale` (1: the exact box averages).  A tiled fine field
 * (cof_generator = tiles: a window of the belt that slides) is made to
 * hold each coarse column's support in turn (sf_cof_follow: its node
 * values are a function of the realisation and the lattice point alone,
 * so the averages are those of the one field the point model sees); the
 * columns are visited towards -x, the way the window's slack points. */
sf_cof *check_cellavg_filter(const sf_cof *fine, const sf_scene *sc, double box, double scale, sf_result *r)
{
    size_t m, n, mc, nc;
    double x0, y0, dx, dy;
    const double *g;
    sf_cof_grid_view(fine, &m, &n, &x0, &y0, &dx, &dy, &g);
    /* the effective grid the plan would draw on */
    char err[256] = "";
    sf_cof_plan *cp;
    if (sf_cof_plan_alloc(sc, &cp, err, sizeof err)) {
        sf_note(r, "**Cannot plan the cell-average model:** %s", err);
        return NULL;
    }
    sf_cof_plan_info in = *sf_cof_plan_get_info(cp);
    sf_cof_plan_free(cp);
    mc = in.nx;
    nc = in.ny;
    size_t cap = (size_t)ceil(box / fmin(dx, dy)) + 6;
    double *wv = check_alloc(cap * sizeof *wv);
    double *tmp = check_alloc(n * mc * sizeof *tmp), *out = check_alloc(mc * nc * sizeof *out);
    int rc = SF_SUCCESS;
    for (size_t ii = mc; ii-- > 0 && !rc;) {   /* along x, every fine row */
        double c = in.x0 + (double)ii * in.dx;
        size_t i = ii;
        if ((rc = sf_cof_follow(fine, c - box / 2 - 2 * dx, c + box / 2 + 2 * dx)) ||
            (rc = sf_cof_grid_view(fine, &m, &n, &x0, &y0, &dx, &dy, &g))) {
            sf_note(r, "**The fine field cannot hold the box at x = %g m:** %s.", c, sf_strerror(rc));
            break;
        }
        size_t i0, k = box_weights(c - box / 2, c + box / 2, x0, dx, m, &i0, wv, cap);
        for (size_t j = 0; j < n; j++) {
            double s = 0;
            for (size_t q = 0; q < k; q++)
                s += wv[q] * g[i0 + q + m * j];
            tmp[i + mc * j] = s;
        }
    }
    for (size_t j = 0; j < nc; j++) {   /* along y */
        double c = in.y0 + (double)j * in.dy;
        size_t j0, k = box_weights(c - box / 2, c + box / 2, y0, dy, n, &j0, wv, cap);
        for (size_t i = 0; i < mc; i++) {
            double s = 0;
            for (size_t q = 0; q < k; q++)
                s += wv[q] * tmp[i + mc * (j0 + q)];
            out[i + mc * j] = s;
        }
    }
    if (scale != 1)   /* the model's spread about the mean (model_scale) */
        for (size_t k = 0; k < mc * nc; k++)
            out[k] = sc->mu_mean + scale * (out[k] - sc->mu_mean);
    sf_cof *cof = NULL;
    if (!rc && !sf_cof_alloc_grid(mc, nc, in.x0, in.y0, in.dx, in.dy, out, &cof))
        sf_cof_set_box(cof, box);
    free(wv);
    free(tmp);
    free(out);
    return cof;
}
