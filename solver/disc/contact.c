/* slipfield: the friction wrench of the belt on the disc, Eqs. 7-8, by a
 * quadrature over the contact's cells (contact.h), and the Contensou
 * closed forms for a uniform COF. */
#include "contact.h"
#include "cof_x512.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_ellint.h>

struct sf_contact {
    sf_contact_spec spec;
    const sf_cof *cof;
    size_t n;
    double *rx, *ry;   /* cell offsets from the centre [m] */
    double *wt;        /* pressure x area of each cell [N]; sums to N */
};

/* The wrench sums its cells in SF_LANES interleaved partial sums (cell i
 * into lane i mod SF_LANES), added in a fixed order at the end: the loop
 * vectorises at any vector width (2 doubles with SSE2, 4 with AVX2, 8
 * with AVX-512: sf_contact_wrench is compiled for each and picks the
 * machine's at load time) and the bits stay the same whatever the width
 * (IEEE operations lane by lane; -std=c11 keeps a * b + c uncontracted). */
#define SF_LANES 8

/* One copy of sf_contact_wrench per vector width, chosen at load time.
 * -DSF_NO_CLONES (the coverage build only, Makefile COV_FLAGS): the same
 * source compiled once, so that gcov does not count the two copies this
 * machine never runs as uncovered. */
#ifdef SF_NO_CLONES
#define SF_WRENCH_CLONES
#else
#define SF_WRENCH_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#endif

/* Polar layout: Gauss-Legendre radii (exact for the polynomial radial
 * moments, so uniform translation and pure spin are exact), equal sectors
 * per ring, as many as keep the cells near-square, staggered by half a
 * sector from ring to ring. */
static int layout_polar(sf_contact *c)
{
    size_t nr = c->spec.cells;
    double R = c->spec.R;
    gsl_integration_glfixed_table *gl = SF_FALLIBLE(gsl_integration_glfixed_table_alloc(nr));
    if (!gl)
        return SF_ENOMEM;
    size_t *ns = sf_malloc(nr * sizeof *ns), total = 0;
    double *r = sf_malloc(nr * sizeof *r), *w = sf_malloc(nr * sizeof *w);
    if (!ns || !r || !w) {
        free(ns); free(r); free(w);
        gsl_integration_glfixed_table_free(gl);
        return SF_ENOMEM;
    }
    for (size_t j = 0; j < nr; j++) {
        gsl_integration_glfixed_point(0, R, j, &r[j], &w[j], gl);
        size_t k = (size_t)ceil(2 * M_PI * r[j] * (double)nr / R);
        ns[j] = k < 8 ? 8 : k;
        total += ns[j];
    }
    gsl_integration_glfixed_table_free(gl);
    c->rx = sf_malloc(total * sizeof *c->rx);
    c->ry = sf_malloc(total * sizeof *c->ry);
    c->wt = sf_malloc(total * sizeof *c->wt);
    if (!c->rx || !c->ry || !c->wt) {
        free(ns); free(r); free(w);
        return SF_ENOMEM;
    }
    double P = c->spec.normal_force / (M_PI * R * R);
    size_t i = 0;
    for (size_t j = 0; j < nr; j++) {
        double dphi = 2 * M_PI / (double)ns[j], off = (j % 2) ? 0.5 : 0.0;
        for (size_t k = 0; k < ns[j]; k++, i++) {
            double phi = ((double)k + off) * dphi;
            c->rx[i] = r[j] * cos(phi);
            c->ry[i] = r[j] * sin(phi);
            c->wt[i] = P * w[j] * r[j] * dphi;
        }
    }
    c->n = total;
    free(ns); free(r); free(w);
    return SF_SUCCESS;
}

/* Cartesian layout: square cells across the diameter; cells cut by the rim
 * are sub-sampled (16 x 16) for their area fraction and centroid.  The
 * weights are then scaled so that they carry exactly the load N. */
static int layout_cartesian(sf_contact *c)
{
    size_t nc = c->spec.cells, cap = nc * nc;
    double R = c->spec.R, h = 2 * R / (double)nc;
    c->rx = sf_malloc(cap * sizeof *c->rx);
    c->ry = sf_malloc(cap * sizeof *c->ry);
    c->wt = sf_malloc(cap * sizeof *c->wt);
    if (!c->rx || !c->ry || !c->wt)
        return SF_ENOMEM;
    const int S = 16;
    size_t n = 0;
    double sum = 0;
    for (size_t j = 0; j < nc; j++) {
        for (size_t i = 0; i < nc; i++) {
            double cx = -R + ((double)i + 0.5) * h, cy = -R + ((double)j + 0.5) * h;
            double far = hypot(fabs(cx) + h / 2, fabs(cy) + h / 2);
            double near = hypot(fmax(fabs(cx) - h / 2, 0), fmax(fabs(cy) - h / 2, 0));
            double a, px = cx, py = cy;
            if (near >= R)
                continue;
            if (far <= R) {
                a = h * h;
            } else {
                int in = 0;
                double sx = 0, sy = 0;
                for (int q = 0; q < S; q++)
                    for (int p = 0; p < S; p++) {
                        double x = cx - h / 2 + (p + 0.5) * h / S, y = cy - h / 2 + (q + 0.5) * h / S;
                        if (x * x + y * y < R * R) {
                            in++;
                            sx += x;
                            sy += y;
                        }
                    }
                if (!in)
                    continue;
                a = h * h * in / (double)(S * S);
                px = sx / in;
                py = sy / in;
            }
            c->rx[n] = px;
            c->ry[n] = py;
            c->wt[n] = a;
            sum += a;
            n++;
        }
    }
    for (size_t i = 0; i < n; i++)
        c->wt[i] *= c->spec.normal_force / sum;
    c->n = n;
    return SF_SUCCESS;
}

int sf_contact_alloc(const sf_contact_spec *spec, const sf_cof *cof, sf_contact **out)
{
    *out = NULL;
    if (!spec || !cof || !(spec->R > 0) || !(spec->normal_force >= 0) || !isfinite(spec->R) ||
        !isfinite(spec->normal_force) || spec->cells < 1 || spec->cells > 100000 ||
        (spec->layout != SF_LAYOUT_POLAR && spec->layout != SF_LAYOUT_CARTESIAN))
        return SF_EINVAL;
    sf_contact *c = sf_calloc(1, sizeof *c);
    if (!c)
        return SF_ENOMEM;
    c->spec = *spec;
    c->cof = cof;
    int rc = spec->layout == SF_LAYOUT_POLAR ? layout_polar(c) : layout_cartesian(c);
    if (rc) {
        sf_contact_free(c);
        return rc;
    }
    *out = c;
    return SF_SUCCESS;
}

void sf_contact_free(sf_contact *c)
{
    if (!c)
        return;
    free(c->rx);
    free(c->ry);
    free(c->wt);
    free(c);
}

size_t sf_contact_ncells(const sf_contact *c) { return c->n; }
const sf_cof *sf_contact_get_cof(const sf_contact *c) { return c->cof; }
double sf_contact_radius(const sf_contact *c) { return c->spec.R; }
double sf_contact_normal_force(const sf_contact *c) { return c->spec.normal_force; }

void sf_contact_cells(const sf_contact *c, const double **rx, const double **ry, const double **wt)
{
    *rx = c->rx;
    *ry = c->ry;
    *wt = c->wt;
}

/* The wrench cell by cell with hypot (safe at any speed): the reference
 * the fast loop falls back to where its scaling cannot be trusted. */
static void wrench_hypot(const sf_contact *c, double xb, double yb, double u, double v, double w, double acc[3])
{
    int uniform = sf_cof_get_kind(c->cof) != SF_COF_FIELD;
    double mu0 = uniform ? sf_cof_eval(c->cof, 0, 0) : 0;
    double fx = 0, fy = 0, t = 0;
    for (size_t i = 0; i < c->n; i++) {
        double rx = c->rx[i], ry = c->ry[i];
        double vx = u - w * ry, vy = v + w * rx, s = hypot(vx, vy);
        if (s == 0)   /* the pole sits on a node: no slip direction there */
            continue;
        double mu = uniform ? mu0 : sf_cof_eval(c->cof, xb + rx, yb + ry);
        /* unit direction first: wt mu / s underflows for a tiny COF at a
         * huge speed, and 1/s overflows for a subnormal speed */
        double a = c->wt[i] * mu, dx = vx / s, dy = vy / s;
        fx -= a * dx;
        fy -= a * dy;
        t -= a * (rx * dy - ry * dx);
    }
    acc[0] = fx;
    acc[1] = fy;
    acc[2] = t;
}

/* Below this scaled squared speed the fast loop hands the call over to
 * wrench_hypot (see sf_contact_wrench). */
#define SF_TINY2 0x1p-960

/* One cell's contribution at scaled speeds (us, vs, ws) with COF mu into
 * lane k; *s2min tracks the smallest scaled squared slip speed (a cell at
 * rest gives 1/0 here: the call is then redone, see sf_contact_wrench). */
__attribute__((always_inline)) static inline void cell_sum(double mu, double us, double vs, double ws, double rx,
                                                           double ry, double wt, size_t k, double *fx, double *fy,
                                                           double *tq, double *s2min)
{
    double ax = us - ws * ry, ay = vs + ws * rx, s2 = ax * ax + ay * ay;
    double r = 1 / sqrt(s2), a = wt * mu, dx = ax * r, dy = ay * r;
    fx[k] -= a * dx;
    fy[k] -= a * dy;
    tq[k] -= a * (rx * dy - ry * dx);
    s2min[k] = s2 < s2min[k] ? s2 : s2min[k];
}

/* The cell kernels, one per way a cell finds its COF, chosen once per call
 * outside the loop (wrench_lanes is inlined with a constant kernel, so
 * each copy of the loop holds one kernel inlined and no test of the mode:
 * no dead arms per copy).  *out counts clamped look-ups (cell_clamped). */
typedef void cell_fn(const sf_cof_view *v, double mu0, double xb, double yb, double us, double vs, double ws,
                     double rx, double ry, double wt, size_t k, double *fx, double *fy, double *tq, double *s2min,
                     double *out);

/* a uniform COF mu0 */
__attribute__((always_inline)) static inline void cell_const(const sf_cof_view *v, double mu0, double xb, double yb,
                                                             double us, double vs, double ws, double rx, double ry,
                                                             double wt, size_t k, double *fx, double *fy, double *tq,
                                                             double *s2min, double *out)
{
    (void)v, (void)xb, (void)yb, (void)out;
    cell_sum(mu0, us, vs, ws, rx, ry, wt, k, fx, fy, tq, s2min);
}

/* a grid that holds the whole disc (sf_cof_view_holds): no clamp */
__attribute__((always_inline)) static inline void cell_on_grid(const sf_cof_view *v, double mu0, double xb, double yb,
                                                               double us, double vs, double ws, double rx, double ry,
                                                               double wt, size_t k, double *fx, double *fy,
                                                               double *tq, double *s2min, double *out)
{
    (void)mu0, (void)out;
    cell_sum(sf_cof_view_eval_on(v, xb + rx, yb + ry), us, vs, ws, rx, ry, wt, k, fx, fy, tq, s2min);
}

/* a grid the disc may leave: clamped look-ups, counted */
__attribute__((always_inline)) static inline void cell_clamped(const sf_cof_view *v, double mu0, double xb, double yb,
                                                               double us, double vs, double ws, double rx, double ry,
                                                               double wt, size_t k, double *fx, double *fy,
                                                               double *tq, double *s2min, double *out)
{
    (void)mu0;
    double cl = 0, mu = sf_cof_view_eval(v, xb + rx, yb + ry, &cl);
    cell_sum(mu, us, vs, ws, rx, ry, wt, k, fx, fy, tq, s2min);
    out[k] += cl;   /* (x + 0.0 is not x for x = -0: the other kernels leave out alone) */
}

/* The end of a cell loop: cells b.. (fewer than SF_LANES) one by one
 * into lanes 0.., then the lanes summed in a fixed order.  Returns the
 * smallest scaled squared slip speed; *outside counts the clamped
 * look-ups (cell_clamped). */
__attribute__((always_inline)) static inline double lanes_finish(const sf_contact *c, cell_fn *cell,
                                                                 const sf_cof_view *v, double mu0, double xb,
                                                                 double yb, double us, double vs, double ws,
                                                                 size_t b, double *fx, double *fy, double *tq,
                                                                 double *s2min, double *out, double acc[3],
                                                                 double *outside)
{
    for (size_t k = 0; b + k < c->n; k++)
        cell(v, mu0, xb, yb, us, vs, ws, c->rx[b + k], c->ry[b + k], c->wt[b + k], k, fx, fy, tq, s2min, out);
    double m = INFINITY, no = 0;
    acc[0] = acc[1] = acc[2] = 0;
    for (size_t k = 0; k < SF_LANES; k++) {   /* fixed order */
        acc[0] += fx[k];
        acc[1] += fy[k];
        acc[2] += tq[k];
        m = s2min[k] < m ? s2min[k] : m;
        no += out[k];
    }
    *outside = no;
    return m;
}

/* The fast cell loop: cell i into lane i mod SF_LANES, whole blocks
 * vectorised (-fopt-info-vec), the tail cell by cell; lanes summed in a
 * fixed order.  Returns the smallest scaled squared slip speed; *outside
 * counts the clamped look-ups (cell_clamped). */
__attribute__((always_inline)) static inline double wrench_lanes(const sf_contact *c, cell_fn *cell,
                                                                 const sf_cof_view *cv, double mu0, double xb,
                                                                 double yb, double us, double vs, double ws,
                                                                 double acc[3], double *outside)
{
    double fx[SF_LANES] = { 0 }, fy[SF_LANES] = { 0 }, tq[SF_LANES] = { 0 }, out[SF_LANES] = { 0 };
    double s2min[SF_LANES] = { INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY };
    const double *restrict prx = c->rx, *restrict pry = c->ry, *restrict pwt = c->wt;
    const sf_cof_view v = *cv;   /* in registers: the loop's stores cannot alias it */
    size_t b = 0, n = c->n;
    for (; b + SF_LANES <= n; b += SF_LANES) {
#pragma omp simd
        for (size_t k = 0; k < SF_LANES; k++)
            cell(&v, mu0, xb, yb, us, vs, ws, prx[b + k], pry[b + k], pwt[b + k], k, fx, fy, tq, s2min, out);
    }
    return lanes_finish(c, cell, &v, mu0, xb, yb, us, vs, ws, b, fx, fy, tq, s2min, out, acc, outside);
}

#ifdef SF_COF_VIEW_X512
/* cell_sum at the width whose intrinsics' prefix is P (_mm512_ or
 * _mm256_), vector type T: the cells at offsets (rx, ry), weights wt and
 * COF mu into the partial sums fx, fy, tq and the smallest s2, s2m, lane
 * by lane in cell_sum's order (vus, vvs, vws and one in scope). */
#define SF_CELL_SUM_V(P, T, rx, ry, wt, mu, fx, fy, tq, s2m)                                      \
    do {                                                                                         \
        T ax_ = P##sub_pd(vus, P##mul_pd(vws, ry)), ay_ = P##add_pd(vvs, P##mul_pd(vws, rx));    \
        T s2_ = P##add_pd(P##mul_pd(ax_, ax_), P##mul_pd(ay_, ay_));                             \
        T r_ = P##div_pd(one, P##sqrt_pd(s2_)), a_ = P##mul_pd(wt, mu);                          \
        T dx_ = P##mul_pd(ax_, r_), dy_ = P##mul_pd(ay_, r_);                                    \
        (fx) = P##sub_pd(fx, P##mul_pd(a_, dx_));                                                \
        (fy) = P##sub_pd(fy, P##mul_pd(a_, dy_));                                                \
        (tq) = P##sub_pd(tq, P##mul_pd(a_, P##sub_pd(P##mul_pd(rx, dy_), P##mul_pd(ry, dx_)))); \
        (s2m) = P##min_pd(s2_, s2m);   /* s2 < s2m ? s2 : s2m */                                 \
    } while (0)

/* The on-grid loops' set-up at width P, T: the view in registers, the
 * cells' arrays, the scaled speeds and the belt point broadcast. */
#define SF_ON_GRID_SETUP_V(P, T)                                                                   \
    const sf_cof_view v = *cv;                                                                     \
    const double *prx = c->rx, *pry = c->ry, *pwt = c->wt;                                         \
    const T vus = P##set1_pd(us), vvs = P##set1_pd(vs), vws = P##set1_pd(ws);                      \
    const T vxb = P##set1_pd(xb), vyb = P##set1_pd(yb), one = P##set1_pd(1.0)

/* The on-grid loop in AVX-512 registers: one block of SF_LANES = 8 cells
 * per iteration, cell_on_grid's operations lane by lane in its order (the
 * same bits as wrench_lanes with cell_on_grid: tests/test_contact.c
 * checks both against a scalar sum), the look-up by pairs
 * (sf_cof_view_eval_on8); the tail and the sum as in wrench_lanes.  GCC
 * keeps wrench_lanes' partial sums in memory and assembles each nodal
 * value from a scalar load: this loop takes about 2/3 of its time on
 * AVX-512 hardware (make bench). */
__attribute__((target("avx512f"))) static double wrench_on_grid_x512(const sf_contact *c, const sf_cof_view *cv,
                                                                     double xb, double yb, double us, double vs,
                                                                     double ws, double acc[3], double *outside)
{
    SF_ON_GRID_SETUP_V(_mm512_, __m512d);
    __m512d fx = _mm512_setzero_pd(), fy = fx, tq = fx, s2m = _mm512_set1_pd(INFINITY);
    size_t b = 0, n = c->n;
    for (; b + SF_LANES <= n; b += SF_LANES) {
        __m512d rx = _mm512_loadu_pd(prx + b), ry = _mm512_loadu_pd(pry + b), wt = _mm512_loadu_pd(pwt + b);
        __m512d mu = sf_cof_view_eval_on8(&v, _mm512_add_pd(vxb, rx), _mm512_add_pd(vyb, ry));
        SF_CELL_SUM_V(_mm512_, __m512d, rx, ry, wt, mu, fx, fy, tq, s2m);
    }
    double lfx[SF_LANES], lfy[SF_LANES], ltq[SF_LANES], ls2[SF_LANES], out[SF_LANES] = { 0 };
    _mm512_storeu_pd(lfx, fx);
    _mm512_storeu_pd(lfy, fy);
    _mm512_storeu_pd(ltq, tq);
    _mm512_storeu_pd(ls2, s2m);
    return lanes_finish(c, cell_on_grid, &v, 0, xb, yb, us, vs, ws, b, lfx, lfy, ltq, ls2, out, acc, outside);
}

/* The on-grid loop in AVX2 registers (machines without AVX-512): a block
 * of SF_LANES = 8 cells as two halves of 4, lanes 0-3 and 4-7 each in its
 * own registers, so cell i still goes to lane i mod 8 and the bits are
 * wrench_lanes' (tests/test_contact.c); the look-up by pairs
 * (sf_cof_view_eval_on4), the partial sums in registers, the tail and the
 * sum as in wrench_lanes. */
__attribute__((target("avx2"))) static double wrench_on_grid_x256(const sf_contact *c, const sf_cof_view *cv,
                                                                  double xb, double yb, double us, double vs,
                                                                  double ws, double acc[3], double *outside)
{
    SF_ON_GRID_SETUP_V(_mm256_, __m256d);
    __m256d fx[2], fy[2], tq[2], s2m[2];
    for (int h = 0; h < 2; h++) {
        fx[h] = fy[h] = tq[h] = _mm256_setzero_pd();
        s2m[h] = _mm256_set1_pd(INFINITY);
    }
    size_t b = 0, n = c->n;
    for (; b + SF_LANES <= n; b += SF_LANES)
        for (int h = 0; h < 2; h++) {
            size_t o = b + 4 * (size_t)h;
            __m256d rx = _mm256_loadu_pd(prx + o), ry = _mm256_loadu_pd(pry + o), wt = _mm256_loadu_pd(pwt + o);
            __m256d mu = sf_cof_view_eval_on4(&v, _mm256_add_pd(vxb, rx), _mm256_add_pd(vyb, ry));
            SF_CELL_SUM_V(_mm256_, __m256d, rx, ry, wt, mu, fx[h], fy[h], tq[h], s2m[h]);
        }
    double lfx[SF_LANES], lfy[SF_LANES], ltq[SF_LANES], ls2[SF_LANES], out[SF_LANES] = { 0 };
    for (int h = 0; h < 2; h++) {
        _mm256_storeu_pd(lfx + 4 * h, fx[h]);
        _mm256_storeu_pd(lfy + 4 * h, fy[h]);
        _mm256_storeu_pd(ltq + 4 * h, tq[h]);
        _mm256_storeu_pd(ls2 + 4 * h, s2m[h]);
    }
    return lanes_finish(c, cell_on_grid, &v, 0, xb, yb, us, vs, ws, b, lfx, lfy, ltq, ls2, out, acc, outside);
}
#endif

/* Scaled speeds.  A cell at offset (rx, ry), |rx|, |ry| <= R, slips at
 * (u - w ry, v + w rx), each component below 2^e with
 *   e = max(ilogb u + 1, ilogb v + 1, ilogb w + ilogb R + 2),
 * so with (us, vs, ws) = 2^-e (u, v, w) (ldexp: exact unless ws is
 * subnormal) the scaled components (ax, ay) are the cell's slip velocity
 * times 2^-e exactly (scaling by a power of two commutes with rounding),
 * |ax|, |ay| < 2 and s2 = ax^2 + ay^2 < 8: no overflow whatever u, v, w.
 * Underflow: s2 >= SF_TINY2 = 2^-960 means the larger square is >= 2^-961,
 * a normal number, and the smaller one, if it underflows (< 2^-1022), is
 * below 2^-61 of it: lost below the rounding of s2 anyway.  So for
 * s2 >= 2^-960 the direction (ax, ay)/sqrt(s2) is as accurate as with
 * hypot, and r = 1/sqrt(s2) <= 2^480 keeps wt mu r finite.  When some cell
 * has s2 < 2^-960 (it lies within 2^-479 of the pole, relative to the
 * largest slip speed, or on it: then 1/0) the whole call is redone with
 * hypot (wrench_hypot: a cell on the pole adds nothing).  A subnormal ws
 * (|w| R below 2^-1021 of the largest speed) perturbs ax, ay by at most
 * 2^-1074 R, far below the 2^-480 they are trusted from. */
SF_WRENCH_CLONES
int sf_contact_wrench(const sf_contact *c, double xb, double yb,
                      double u, double v, double w, double ratio, double out[3])
{
    if (!isfinite(u) || !isfinite(v) || !isfinite(w) || !isfinite(xb) || !isfinite(yb))
        return SF_EINVAL;
    double acc[3] = { 0, 0, 0 };
    if (u != 0 || v != 0 || w != 0) {   /* all at rest: no slip anywhere, no force */
        int e = INT_MIN;
        if (u != 0)
            e = ilogb(u) + 1;
        if (v != 0 && ilogb(v) + 1 > e)
            e = ilogb(v) + 1;
        if (w != 0 && ilogb(w) + ilogb(c->spec.R) + 2 > e)
            e = ilogb(w) + ilogb(c->spec.R) + 2;
        double us = ldexp(u, -e), vs = ldexp(v, -e), ws = ldexp(w, -e);
        sf_cof_view cv = { 0 };
        int field = sf_cof_get_view(c->cof, &cv);   /* afresh: the grid may have moved */
        double mu0 = field ? 0 : sf_cof_eval(c->cof, 0, 0), outside = 0, s2min = 0;
        if (!field && sf_cof_get_kind(c->cof) == SF_COF_FIELD)   /* a field without a grid view: cell by cell */
            s2min = 0;
        else if (!field)
            s2min = wrench_lanes(c, cell_const, &cv, mu0, xb, yb, us, vs, ws, acc, &outside);
        else if (sf_cof_view_holds(&cv, xb, yb, c->spec.R))   /* the common case: no clamp */
#ifdef SF_COF_VIEW_X512
            s2min = __builtin_cpu_supports("avx512f") ? wrench_on_grid_x512(c, &cv, xb, yb, us, vs, ws, acc, &outside)
                  : __builtin_cpu_supports("avx2")    ? wrench_on_grid_x256(c, &cv, xb, yb, us, vs, ws, acc, &outside)
                                                      : wrench_lanes(c, cell_on_grid, &cv, mu0, xb, yb, us, vs, ws, acc,
                                                                     &outside);
#else
            s2min = wrench_lanes(c, cell_on_grid, &cv, mu0, xb, yb, us, vs, ws, acc, &outside);
#endif
        else
            s2min = wrench_lanes(c, cell_clamped, &cv, mu0, xb, yb, us, vs, ws, acc, &outside);
        if (!(s2min >= SF_TINY2))   /* near the pole, or no grid view */
            wrench_hypot(c, xb, yb, u, v, w, acc);   /* counts its own clamped look-ups */
        else if (outside > 0)
            sf_cof_count_outside(c->cof, (unsigned long)outside);
    }
    out[0] = ratio * acc[0];
    out[1] = ratio * acc[1];
    out[2] = ratio * acc[2];
    return SF_SUCCESS;
}

/* A slip phase's stick tests call this once per trial step near stick:
 * on a grid that holds the disc the look-up is inlined (sf_cof_view_eval_on:
 * the bits of sf_cof_eval there), in the same order of the sum. */
double sf_contact_mean_cof(const sf_contact *c, double xb, double yb)
{
    sf_cof_view v;
    if (!sf_cof_get_view(c->cof, &v))   /* uniform or one variable */
        return sf_cof_eval(c->cof, 0, 0);
    double s = 0;
    if (sf_cof_view_holds(&v, xb, yb, c->spec.R))
        for (size_t i = 0; i < c->n; i++)
            s += c->wt[i] * sf_cof_view_eval_on(&v, xb + c->rx[i], yb + c->ry[i]);
    else   /* near the grid's edge: clamped and counted look-ups */
        for (size_t i = 0; i < c->n; i++)
            s += c->wt[i] * sf_cof_eval(c->cof, xb + c->rx[i], yb + c->ry[i]);
    return s / c->spec.normal_force;
}

/* E + K - D (D = (K - E)/k^2, GSL's Dcomp) without cancellation: directly
 * for small k, as E + (E - (1 - k^2) K)/k^2 near k = 1. */
static double ekd(double k)
{
    double E = gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE);
    if (k < 0.5)
        return E + gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE) - gsl_sf_ellint_Dcomp(k, GSL_PREC_DOUBLE);
    return E + (E - (1 - k * k) * gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE)) / (k * k);
}

/* t for eps >= 2 (m = 1/eps^2 <= 1/4): the closed form's bracket cancels to
 * O(m^2), so sum its power series instead, built from the Maclaurin
 * coefficients of K, E and D in m: K = pi/2 sum a_n^2 m^n,
 * E = pi/2 sum -a_n^2/(2n-1) m^n, D = pi/2 sum a_{n+1}^2 (2n+2)/(2n+1) m^n,
 * a_n = (2n)!/(4^n n!^2).  t = 2/(9 eps) sum_{n>=1} g_n m^{n-1} with
 * g_n = 3 e_{n-1} - e_n + 2 d_n - 5 d_{n-1} + 3 d_{n-2}. */
static double t_large(double eps)
{
    double m = 1 / (eps * eps), a2[80], e[80], d[80];
    double a = 1;
    for (int n = 0; n < 80; n++) {
        if (n)
            a *= (2.0 * n - 1) / (2.0 * n);
        a2[n] = a * a;
        e[n] = n ? -a2[n] / (2.0 * n - 1) : 1;
    }
    for (int n = 0; n < 79; n++)
        d[n] = a2[n + 1] * (2.0 * n + 2) / (2.0 * n + 1);
    double sum = 0, mp = 1;
    for (int n = 1; n < 78; n++) {
        double g = 3 * e[n - 1] - e[n] + 2 * d[n] - 5 * d[n - 1] + (n >= 2 ? 3 * d[n - 2] : 0);
        double term = g * mp;
        sum += term;
        if (fabs(term) < 1e-18 * fabs(sum))
            break;
        mp *= m;
    }
    return 2 / (9 * eps) * sum;
}

void sf_contensou(double eps, double *f, double *t)
{
    eps = fabs(eps);
    if (eps == 0) {
        *f = 0;
        *t = 2.0 / 3.0;
        return;
    }
    if (isinf(eps)) {
        *f = 1;
        *t = 0;
        return;
    }
    if (eps == 1) {   /* (1 - k^2) K -> 0; GSL's K and E reject k = 1 */
        *f = 8 / (3 * M_PI);
        *t = 8 / (9 * M_PI);
        return;
    }
    if (eps < 1) {
        double k = eps, E = gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE);
        double K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE);
        *f = 4 * eps / (3 * M_PI) * ekd(k);
        *t = 4 / (9 * M_PI) * ((4 - 2 * k * k) * E - (1 - k * k) * K);
        return;
    }
    double k = 1 / eps;
    *f = 4 / (3 * M_PI) * ekd(k);
    if (eps >= 2) {
        *t = t_large(eps);
    } else {
        double E = gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE), K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE);
        *t = 4 * eps * eps * eps / (9 * M_PI) * ((1 - k * k) * (2 - 3 * k * k) * K + 2 * (2 * k * k - 1) * E);
    }
}
