/* slipfield: the cell-averaged COF field's covariance (cellavg.h): the
 * box terms of the squared-exponential kernel averaged over a cell, their
 * variance, correlation and separable-sum terms. */
#include "cellavg.h"
#include "sf_error.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_math.h>

int sf_cellavg_init(sf_cellavg *c, double mubar, double std, double l, double h)
{
    memset(c, 0, sizeof *c);
    if (!(mubar > 0) || !(std >= 0) || !(l > 0) || !(h > 0) || !isfinite(mubar) || !isfinite(std) ||
        !isfinite(l) || !isfinite(h))
        return SF_EINVAL;
    double cv = std / mubar;
    c->mubar = mubar;
    c->s2 = log1p(cv * cv);
    c->l = l;
    c->h = h;
    /* sG^{2n}/n!: until a term is below 1e-17 of the first (round-off of
     * the sum); 64 terms reach that for sG^2 up to about 6 (CV ~ 20) */
    double t = c->s2;
    int n = 0;
    while (n < 64 && t > 0) {
        c->a[n++] = t;
        if (t < 1e-17 * c->s2)
            break;
        t *= c->s2 / (double)(n + 1);
    }
    c->nterms = n;
    c->var = sf_cellavg_cov(c, 0, 0);
    for (int k = 0; k < n; k++)
        c->rs[k] = sqrt(c->a[k] * mubar * mubar / c->var);
    return SF_SUCCESS;
}

double sf_cellavg_box1(const sf_cellavg *c, int n, double d)
{
    double h = c->h, a = (double)n / (c->l * c->l), sa = sqrt(a), k = 0.5 * M_SQRTPI / sa;
    d = fabs(d);   /* B_n is even */
    double xp = d + h, x0 = d, xm = d - h;
    double g = (exp(-a * xp * xp) - 2 * exp(-a * x0 * x0) + exp(-a * xm * xm)) / (2 * a);
    double lin;
    if (d >= h)   /* x erf = x - x erfc: the linear parts' second difference is 0 */
        lin = -k * (xp * erfc(sa * xp) - 2 * x0 * erfc(sa * x0) + xm * erfc(sa * xm));
    else
        lin = k * (xp * erf(sa * xp) - 2 * x0 * erf(sa * x0) + xm * erf(sa * xm));
    return (lin + g) / (h * h);
}

double sf_cellavg_cov(const sf_cellavg *c, double dx, double dy)
{
    double s = 0;
    for (int n = c->nterms; n >= 1; n--)   /* smallest terms first */
        s += c->a[n - 1] * sf_cellavg_box1(c, n, dx) * sf_cellavg_box1(c, n, dy);
    return c->mubar * c->mubar * s;
}

double sf_cellavg_var(const sf_cellavg *c) { return c->var; }

double sf_cellavg_corr(double dx, double dy, void *params)
{
    const sf_cellavg *c = params;
    return sf_cellavg_cov(c, dx, dy) / c->var;
}

double sf_cellavg_septerm(int t, double d, void *params)
{
    const sf_cellavg *c = params;
    return c->rs[t] * sf_cellavg_box1(c, t + 1, d);
}

double sf_cellavg_grid_spacing(double h) { return h / 3; }

double sf_cellavg_support(const sf_cellavg *c) { return c->h + 9 * c->l; }

/* The 4-point Lagrange basis on nodes -1, 0, 1, 2 at x in [0, 1]. */
static double lagrange4(int q, double x)
{
    static const double node[4] = { -1, 0, 1, 2 };
    double r = 1;
    for (int p = 0; p < 4; p++)
        if (p != q)
            r *= (x - node[p]) / (node[q] - node[p]);
    return r;
}

size_t sf_cellavg_cubic_weights(double beta, double *w, size_t cap)
{
    if (!(beta > 0) || !(beta < 1e6))
        return 0;
    double B = beta / 2;
    long K = (long)floor(B);
    size_t E = (size_t)K + 2, n = 2 * E + 1;   /* nodes -E .. E */
    if (!w)
        return n;
    if (cap < n)
        return 0;
    for (size_t k = 0; k < n; k++)
        w[k] = 0;
    /* interval [j, j + 1] of the lattice, its part inside [-B, B]: the
     * cubic through nodes j - 1 .. j + 2 integrated exactly by 2-point
     * Gauss-Legendre */
    const double g0 = 0.5 - 0.5 / M_SQRT3, g1 = 0.5 + 0.5 / M_SQRT3;
    for (long j = -K - 1; j <= K; j++) {
        double a = fmax((double)j, -B), b = fmin((double)j + 1, B);
        if (!(b > a))
            continue;
        for (int q = 0; q < 4; q++) {
            double s = 0.5 * (b - a) * (lagrange4(q, a + (b - a) * g0 - (double)j) +
                                        lagrange4(q, a + (b - a) * g1 - (double)j));
            w[(size_t)(j - 1 + q + (long)E)] += s / beta;
        }
    }
    return n;
}
