/* slipfield: the static COF the disc sees (cof.h): uniform, one random
 * variable or a field on a grid, the windows that follow the disc over a
 * tiled or belt-noise field, and the COF plan that draws them from the
 * scene's plan (numplan.h). */
#include "cof.h"
#include "cellavg.h"
#include "field.h"
#include "numplan.h"
#include "lnfield.h"
#include "lognormal.h"
#include "sf_alloc.h"
#include "sf_error.h"
#include "noise.h"
#include "tiles.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_randist.h>

/* A tiled field's Gaussian columns kept for its antithetic partner
 * (sf_cof_plan_antithetic): the lattice columns [lo, lo + ncol), n values
 * each (column-major), have[k] set once made.  Shared by the two windows
 * of a pair (refs), so the partner's window copies the columns the first
 * one made instead of making them again: the same bits, one draw.  At
 * most COLS_MAX_VALUES values: beyond, columns are made as without it. */
#define COLS_MAX_VALUES ((size_t)1 << 22)
typedef struct {
    long lo;
    size_t ncol, n;
    double *g;
    unsigned char *have;
    int refs;
} col_store;

struct sf_cof {
    sf_cof_kind kind;
    double mu;                 /* uniform / variable value */
    size_t m, n;
    double x0, y0, dx, dy;
    double *grid;              /* m*n values, x fastest */
    unsigned long outside;     /* evaluations clamped to the grid edge */
    double mu_max;             /* largest value held (grid or window) */
    /* a window on a tiled field (cof_generator = tiles): grid column c is
     * lattice column i_lo + c, x0 = i_lo dx; the values are a function of
     * (key, lattice point) alone, so the window is a cache of the field */
    sf_tiles *tiles;
    sf_noise *noise;           /* belt noise (NULL: the tiles' own): column i at x = (i + 1/2) dx */
    double x_off;              /* lattice column i lies at x = (i + x_off) dx: 0, or 1/2 on belt noise */
    sf_lognormal ln;
    uint64_t key;              /* the realisation's key (sf_tiles_set_key) */
    double sign;               /* +1; -1 for the antithetic window: the Nataf map of -G */
    long i_lo;
    int filled;
    size_t slack_r;            /* columns kept ahead on the +x side when sliding */
    double margin;             /* M [m] (sf_cof_window_margin) */
    unsigned long slides;
    size_t columns_made;
    double box;                /* > 0: the values are cell averages over boxes of this side [m] (cellavg.h) */
    col_store *cols;           /* a tiled pair's shared columns (NULL: none kept) */
    /* box averages on belt noise (box > 0 with tiles): the grid's nodes
     * are every bs-th noise cell (dx = bs h, h the tiles' spacing): grid
     * column c is the box centred on the tiles' column bs (i_lo + c), row
     * j on their row bs j + be (they hold be rows more each side); bw the
     * 2 be + 1 weights of the 1-D filter (sf_cellavg_cubic_weights) */
    double *bw;
    size_t be, bs;
    double *fb, *yb;           /* scratch: fine lognormal values, their y-filtered rows */
    size_t fcap;               /* columns the scratch holds */
};

static void cols_release(col_store *st)
{
    if (st && --st->refs == 0) {
        free(st->g);
        free(st->have);
        free(st);
    }
}

/* 1 when every lattice column of [i, i + cnt) is kept */
static int cols_have(const col_store *st, long i, size_t cnt)
{
    if (!st || i < st->lo || i - st->lo + (long)cnt > (long)st->ncol)
        return 0;
    for (size_t k = 0; k < cnt; k++)
        if (!st->have[(size_t)(i - st->lo) + k])
            return 0;
    return 1;
}

/* Keep lattice columns [i, i + cnt) of the Gaussian values g (grid
 * layout: row j at g + ld j): the range grows to hold them, up to
 * COLS_MAX_VALUES (beyond, they are not kept: the partner makes its
 * own); SF_ENOMEM when the growth fails. */
static int cols_put(col_store *st, long i, size_t cnt, const double *g, size_t ld)
{
    long lo = st->ncol ? (i < st->lo ? i : st->lo) : i;
    long hi = st->ncol ? (i + (long)cnt > st->lo + (long)st->ncol ? i + (long)cnt : st->lo + (long)st->ncol)
                       : i + (long)cnt;
    size_t nc = (size_t)(hi - lo);
    if (nc > COLS_MAX_VALUES / st->n)
        return SF_SUCCESS;
    if (nc != st->ncol) {
        double *ng = sf_malloc(nc * st->n * sizeof *ng);
        unsigned char *nh = sf_calloc(nc, 1);
        if (!ng || !nh) {
            free(ng);
            free(nh);
            return SF_ENOMEM;
        }
        if (st->ncol) {
            size_t off = (size_t)(st->lo - lo);
            memcpy(ng + off * st->n, st->g, st->ncol * st->n * sizeof *ng);
            memcpy(nh + off, st->have, st->ncol);
        }
        free(st->g);
        free(st->have);
        st->g = ng;
        st->have = nh;
        st->lo = lo;
        st->ncol = nc;
    }
    for (size_t k = 0; k < cnt; k++) {
        double *col = st->g + ((size_t)(i - st->lo) + k) * st->n;
        for (size_t j = 0; j < st->n; j++)
            col[j] = g[k + ld * j];
        st->have[(size_t)(i - st->lo) + k] = 1;
    }
    return SF_SUCCESS;
}

static sf_cof *cof_new(sf_cof_kind kind)
{
    sf_cof *c = sf_calloc(1, sizeof *c);
    if (c)
        c->kind = kind;
    return c;
}

int sf_cof_alloc_uniform(double mu_s, sf_cof **out)
{
    *out = NULL;
    if (!(mu_s >= 0) || !isfinite(mu_s))
        return SF_EINVAL;
    sf_cof *c = cof_new(SF_COF_UNIFORM);
    if (!c)
        return SF_ENOMEM;
    c->mu = c->mu_max = mu_s;
    *out = c;
    return SF_SUCCESS;
}

/* A gridded COF whose m*n values the caller writes, then grid_done. */
static int grid_new(size_t m, size_t n, double x0, double y0, double dx, double dy, sf_cof **out)
{
    *out = NULL;
    if (m < 2 || n < 2 || !(dx > 0) || !(dy > 0) || m > INT_MAX / n)
        return SF_EINVAL;   /* int indices (sf_cof_view) */
    sf_cof *c = cof_new(SF_COF_FIELD);
    if (!c)
        return SF_ENOMEM;
    c->grid = sf_malloc(m * n * sizeof *c->grid);
    if (!c->grid) {
        free(c);
        return SF_ENOMEM;
    }
    c->m = m;
    c->n = n;
    c->x0 = x0;
    c->y0 = y0;
    c->dx = dx;
    c->dy = dy;
    *out = c;
    return SF_SUCCESS;
}

static void grid_done(sf_cof *c)
{
    double mx = c->grid[0];
    for (size_t i = 1; i < c->m * c->n; i++) {   /* fmax's value (a NaN is skipped), without its call per point */
        double v = c->grid[i];
        if (v > mx || isnan(mx))
            mx = v;
    }
    c->mu_max = mx;
}

int sf_cof_alloc_grid(size_t m, size_t n, double x0, double y0,
                      double dx, double dy, const double *mu_s, sf_cof **out)
{
    *out = NULL;
    if (!mu_s)
        return SF_EINVAL;
    int rc = grid_new(m, n, x0, y0, dx, dy, out);
    if (rc)
        return rc;
    memcpy((*out)->grid, mu_s, m * n * sizeof *mu_s);
    grid_done(*out);
    return SF_SUCCESS;
}

void sf_cof_free(sf_cof *c)
{
    if (!c)
        return;
    free(c->grid);
    sf_tiles_free(c->tiles);
    sf_noise_free(c->noise);
    cols_release(c->cols);
    free(c->bw);
    free(c->fb);
    free(c->yb);
    free(c);
}

double sf_cof_box(const sf_cof *c) { return c->box; }
uint64_t sf_cof_key(const sf_cof *c) { return c->tiles ? c->key : 0; }

int sf_cof_set_box(sf_cof *c, double box)
{
    if (c->kind != SF_COF_FIELD || !(box >= 0) || !isfinite(box))
        return SF_EINVAL;
    c->box = box;
    return SF_SUCCESS;
}

double sf_cof_max(const sf_cof *c) { return c->kind == SF_COF_FIELD ? c->mu_max : c->mu; }
double sf_cof_window_margin(const sf_cof *c) { return c->tiles ? c->margin : 0; }
size_t sf_cof_points_held(const sf_cof *c) { return c->kind == SF_COF_FIELD ? c->m * c->n : 0; }
unsigned long sf_cof_slides(const sf_cof *c) { return c->slides; }
size_t sf_cof_columns_made(const sf_cof *c) { return c->columns_made; }

/* Box averages (belt noise, cellavg.h): the boxes of grid columns
 * i .. i + cnt - 1 (centred on the tiles' columns bs i ...) into grid
 * columns [c0, c0 + cnt), in blocks of at most BOX_BLOCK columns: the
 * fine Gaussian columns they need (be more each side), the Nataf map
 * pointwise, the filter along y at every bs-th row, then along x at
 * every bs-th column.  Each value is the same sums in the same order
 * wherever the block starts: a function of (key, box centre) alone. */
#define BOX_BLOCK 256
static int window_make_box(sf_cof *c, long i, size_t c0, size_t cnt)
{
    size_t E = c->be, nw = 2 * E + 1, ny = c->n, S = c->bs, nyf = S * (ny - 1) + nw;
    const double *w = c->bw;
    for (size_t done = 0; done < cnt; done += BOX_BLOCK) {
        size_t nb = cnt - done < BOX_BLOCK ? cnt - done : BOX_BLOCK, nf = S * (nb - 1) + nw;
        if (nf > c->fcap) {
            size_t cap = S * (BOX_BLOCK - 1) + nw;
            free(c->fb);
            free(c->yb);
            c->fb = sf_malloc(cap * nyf * sizeof *c->fb);
            c->yb = sf_malloc(cap * ny * sizeof *c->yb);
            c->fcap = c->fb && c->yb ? cap : 0;
            if (!c->fcap)
                return SF_ENOMEM;
        }
        double *f = c->fb, *y = c->yb;
        int rc = sf_tiles_fill(c->tiles, (long)S * (i + (long)done) - (long)E, nf, f, nf);
        if (rc)
            return rc;
        c->columns_made += nf;
        for (size_t k = 0; k < nf * nyf; k++)
            f[k] = sf_lognormal_map(&c->ln, c->sign * f[k]);
        for (size_t j = 0; j < ny; j++) {   /* y: row j of the boxes from fine rows S j .. S j + 2E */
            double *yr = y + nf * j;
            for (size_t k = 0; k < nf; k++)
                yr[k] = 0;
            for (size_t q = 0; q < nw; q++) {
                const double *src = f + nf * (S * j + q);
                double wq = w[q];
                for (size_t k = 0; k < nf; k++)
                    yr[k] += wq * src[k];
            }
        }
        for (size_t j = 0; j < ny; j++) {   /* x: box column k from fine columns S k .. S k + 2E */
            const double *yr = y + nf * j;
            double *g = c->grid + c0 + done + c->m * j;
            for (size_t k = 0; k < nb; k++)
                g[k] = 0;
            for (size_t q = 0; q < nw; q++) {   /* term by term across the row: the same order per value */
                double wq = w[q];
                for (size_t k = 0; k < nb; k++)
                    g[k] += wq * yr[S * k + q];
            }
        }
    }
    return SF_SUCCESS;
}

/* Lattice columns [i, i + cnt) into grid columns [c0, c0 + cnt): the
 * Gaussian values, then the Nataf map pointwise. */
static int window_make(sf_cof *c, long i, size_t c0, size_t cnt)
{
    if (c->bw)
        return window_make_box(c, i, c0, cnt);
    if (cols_have(c->cols, i, cnt)) {   /* made by the pair's other window */
        const col_store *st = c->cols;
        for (size_t k = 0; k < cnt; k++) {
            const double *col = st->g + ((size_t)(i - st->lo) + k) * st->n;
            for (size_t j = 0; j < c->n; j++)
                c->grid[c0 + k + c->m * j] = col[j];
        }
    } else {
        int rc = sf_tiles_fill(c->tiles, i, cnt, c->grid + c0, c->m);
        if (rc)
            return rc;
        if (c->cols && (rc = cols_put(c->cols, i, cnt, c->grid + c0, c->m)))
            return rc;
        c->columns_made += cnt;
    }
    for (size_t j = 0; j < c->n; j++) {
        double *g = c->grid + c0 + c->m * j;
        for (size_t k = 0; k < cnt; k++)
            g[k] = sf_lognormal_map(&c->ln, c->sign * g[k]);
    }
    return SF_SUCCESS;
}

/* Move the window so that grid column 0 is lattice column lo: the
 * columns both windows hold are moved, the others made. */
static int window_slide(sf_cof *c, long lo)
{
    size_t m = c->m;
    int rc = SF_SUCCESS;
    long shift = c->filled ? c->i_lo - lo : (long)m;   /* > 0: the window moves towards -x */
    if (shift >= (long)m || shift <= -(long)m) {
        rc = window_make(c, lo, 0, m);
    } else if (shift > 0) {
        size_t d = (size_t)shift;
        for (size_t j = 0; j < c->n; j++)
            memmove(c->grid + c->m * j + d, c->grid + c->m * j, (m - d) * sizeof *c->grid);
        rc = window_make(c, lo, 0, d);
    } else if (shift < 0) {
        size_t d = (size_t)-shift;
        for (size_t j = 0; j < c->n; j++)
            memmove(c->grid + c->m * j, c->grid + c->m * j + d, (m - d) * sizeof *c->grid);
        rc = window_make(c, lo + (long)(m - d), m - d, d);
    }
    if (rc) {
        c->filled = 0;
        return rc;
    }
    c->filled = 1;
    c->i_lo = lo;
    c->x0 = ((double)lo + c->x_off) * c->dx;
    double mx = c->grid[0];
    for (size_t i = 1; i < m * c->n; i++)
        mx = c->grid[i] > mx ? c->grid[i] : mx;
    c->mu_max = mx;
    c->slides++;
    return SF_SUCCESS;
}

int sf_cof_follow(const sf_cof *cc, double xlo, double xhi)
{
    sf_cof *c = (sf_cof *)cc;   /* the window is a cache: the field it shows does not change */
    if (!c->tiles)
        return SF_SUCCESS;
    if (!(xlo <= xhi) || !isfinite(xlo) || !isfinite(xhi))
        return SF_EINVAL;
    double h = c->dx;
    if (c->filled && xlo >= c->x0 && xhi <= c->x0 + h * (double)(c->m - 1))
        return SF_SUCCESS;
    if (!(fabs(xhi / h) < 1e15))
        return SF_EINVAL;
    long hi = (long)ceil(xhi / h - c->x_off) + (long)c->slack_r, lo = hi - (long)(c->m - 1);
    if (((double)lo + c->x_off) * h > xlo)
        return SF_ETOOBIG;   /* wider than the window */
    return window_slide(c, lo);
}

sf_cof_kind sf_cof_get_kind(const sf_cof *c) { return c->kind; }
unsigned long sf_cof_outside(const sf_cof *c) { return c->outside; }

int sf_cof_grid_view(const sf_cof *c, size_t *m, size_t *n, double *x0, double *y0, double *dx, double *dy,
                     const double **mu)
{
    if (!c || c->kind != SF_COF_FIELD)
        return SF_EINVAL;
    if (m) *m = c->m;
    if (n) *n = c->n;
    if (x0) *x0 = c->x0;
    if (y0) *y0 = c->y0;
    if (dx) *dx = c->dx;
    if (dy) *dy = c->dy;
    if (mu) *mu = c->grid;
    return SF_SUCCESS;
}

int sf_cof_covers(const sf_cof *c, double xb, double yb, double r)
{
    if (c->kind != SF_COF_FIELD)
        return 1;
    return xb - r >= c->x0 && xb + r <= c->x0 + c->dx * (double)(c->m - 1) && yb - r >= c->y0 &&
           yb + r <= c->y0 + c->dy * (double)(c->n - 1);
}

int sf_cof_get_view(const sf_cof *c, sf_cof_view *v)
{
    if (c->kind != SF_COF_FIELD)   /* a grid has fewer than INT_MAX points: sf_cof_alloc_grid */
        return 0;
    *v = (sf_cof_view){ c->grid, (int)c->m, (int)c->n, c->x0, c->y0, 1 / c->dx, 1 / c->dy };
    return 1;
}

void sf_cof_count_outside(const sf_cof *c, unsigned long n)
{
    ((sf_cof *)c)->outside += n;   /* a diagnostic counter, not state */
}

double sf_cof_eval(const sf_cof *c, double xb, double yb)
{
    sf_cof_view v;
    if (!sf_cof_get_view(c, &v))
        return c->mu;
    double clamped;
    double mu = sf_cof_view_eval(&v, xb, yb, &clamped);
    if (clamped != 0)
        sf_cof_count_outside(c, 1);
    return mu;
}

/* ---- plans */

struct sf_cof_plan {
    sf_cof_plan_info info;
    sf_lognormal ln;
    double mu_mean;
    sf_lnfield *field;
    double l, R;               /* tiles: correlation length, disc radius [m] */
    sf_cellavg ca;             /* cell averages: the box-averaged covariance */
    sf_field *cfield;          /* cell averages: its Gaussian field (circulant embedding) */
    double *bw;                /* cell averages on belt noise: the box filter's weights (cellavg.h) */
    size_t nbw;
    int truncated;             /* the embedding reached pad_cap (SF_ETRUNC): sf_cof_plan_truncated */
    int keep_cols;             /* tiles: each window keeps its columns for an antithetic partner */
};

void sf_cof_plan_keep_columns(sf_cof_plan *p, int on) { p->keep_cols = !!on; }

void sf_cof_strip_bounds(const sf_scene *s, double *B0, double *W0) { sf_plan_strip_bounds(s, B0, W0); }
double sf_cof_strip_points(const sf_scene *s, double h) { return sf_plan_strip_points(s, h); }

/* The effective field of cof_model = cell_average (cellavg.h): a
 * Gaussian field with the exact covariance of the lognormal field averaged
 * over boxes of side info.box, on the plan's strip grid (spacing box/3),
 * by circulant embedding of its separable-sum kernel (field.h). */
static int build_cell_average(sf_cof_plan *p, const sf_scene *s, char *err, size_t errlen)
{
    double box = p->info.box, d = p->info.dx;
    int rc = sf_cellavg_init(&p->ca, s->mu_mean, s->mu_std, s->l, box);
    if (rc)   /* a plan made from another scene */
        return sf_seterr(err, errlen, rc, "invalid cell-average model (l = %g m, box = %g m)", s->l, box);
    sf_field_spec fs;
    sf_field_spec_default(&fs, p->info.nx, p->info.ny, d, d, s->l);
    fs.sep_terms = p->ca.nterms;
    fs.sep_fn = sf_cellavg_septerm;
    fs.sep_params = &p->ca;
    fs.support = sf_cellavg_support(&p->ca);
    fs.pad_cap = s->pad_cap;
    fs.eig_rel_tol = s->eig_tol;
    fs.measure = s->fftw_planner;
    fs.defer_covariance = 1;   /* a run only samples: sf_cof_plan_cell_field's users measure it */
    fs.sample_real = 1;        /* one field per draw (sf_cof_plan_draw): a real FFT, half the work */
    rc = sf_field_alloc(&fs, &p->cfield);
    if (!sf_usable(rc))
        return sf_seterr(err, errlen, rc, "cannot plan the %zu x %zu cell-averaged strip field", p->info.nx,
                         p->info.ny);
    p->truncated = rc == SF_ETRUNC;
    return SF_SUCCESS;
}

/* The circulant strip of the point model, on the plan's grid. */
static int build_strip(sf_cof_plan *p, const sf_scene *s, char *err, size_t errlen)
{
    sf_scene gs = *s;
    gs.nx = p->info.nx;
    gs.ny = p->info.ny;
    gs.dx = gs.dy = p->info.dx;
    int rc = sf_lnfield_alloc_sampler(&gs, &p->field);
    if (rc == SF_ETOOBIG)   /* the embedding is over its own cap */
        return sf_seterr(err, errlen, SF_ETOOBIG,
                         "the %zu x %zu grid points of the belt strip need a circulant embedding above its cap "
                         "of 2^25 points; raise l, lower v_b T or set strip_halfwidth", p->info.nx, p->info.ny);
    if (!sf_usable(rc))
        return sf_seterr(err, errlen, rc, "cannot plan the %zu x %zu strip field", p->info.nx, p->info.ny);
    p->truncated = rc == SF_ETRUNC;
    return SF_SUCCESS;
}

int sf_cof_plan_build(const sf_scene *s, const sf_plan *pl, sf_cof_plan **out, char *err, size_t errlen)
{
    *out = NULL;
    sf_cof_plan *p = sf_calloc(1, sizeof *p);
    if (!p)
        return SF_ENOMEM;
    p->info = pl->cof;
    p->mu_mean = s->mu_mean;
    int rc = sf_lognormal_init(&p->ln, s->mu_mean, s->mu_std);
    if (rc) {   /* a plan made from another scene */
        free(p);
        return sf_seterr(err, errlen, rc, "invalid COF marginal (mean %g, std %g)", s->mu_mean, s->mu_std);
    }
    if (p->info.kind == SF_COF_FIELD && p->info.box > 0 && p->info.generator != SF_COFGEN_TILES)
        rc = build_cell_average(p, s, err, errlen);
    else if (p->info.kind == SF_COF_FIELD && p->info.generator == SF_COFGEN_TILES) {
        p->l = s->l;
        p->R = s->R;
        if (p->info.box > 0) {   /* box averages on belt noise: the filter of boxes of box / dx cells */
            double beta = p->info.box / (p->info.dx / (double)p->info.box_step);
            p->nbw = sf_cellavg_cubic_weights(beta, NULL, 0);
            if (!p->nbw || !p->info.belt_noise || p->info.box_step < 1)
                rc = sf_seterr(err, errlen, SF_EINVAL, "invalid box averages on belt noise (box %g m, cells of %g m)",
                               p->info.box, p->info.dx);
            else if (!(p->bw = sf_malloc(p->nbw * sizeof *p->bw)))
                rc = SF_ENOMEM;
            else
                sf_cellavg_cubic_weights(beta, p->bw, p->nbw);
        }
    } else if (p->info.kind == SF_COF_FIELD)
        rc = build_strip(p, s, err, errlen);
    if (rc) {
        sf_cof_plan_free(p);
        return rc;
    }
    *out = p;
    return SF_SUCCESS;
}

int sf_cof_plan_alloc(const sf_scene *s, sf_cof_plan **out, char *err, size_t errlen)
{
    sf_plan pl;
    *out = NULL;
    int rc = sf_plan_cof(s, &pl, err, errlen);
    return rc ? rc : sf_cof_plan_build(s, &pl, out, err, errlen);
}

void sf_cof_plan_free(sf_cof_plan *p)
{
    if (!p)
        return;
    sf_lnfield_free(p->field);
    sf_field_free(p->cfield);
    free(p->bw);
    free(p);
}

const sf_cof_plan_info *sf_cof_plan_get_info(const sf_cof_plan *p) { return &p->info; }
int sf_cof_plan_truncated(const sf_cof_plan *p) { return p->truncated; }
double sf_cof_plan_cell_std(const sf_cof_plan *p) { return p->cfield ? sqrt(sf_cellavg_var(&p->ca)) : 0; }
struct sf_field *sf_cof_plan_cell_field(const sf_cof_plan *p) { return p->cfield; }

static const double *noise_column(void *z, long i) { return sf_noise_column(z, i); }

/* The window's tiles draw from the white noise of the belt (noise.h):
 * window row 0 is the noise's row j0, y0 = (j0 + 1/2) dy; the tiles read
 * Ky rows beyond each side. */
static int belt_noise(sf_cof *c, const sf_cof_plan_info *in)
{
    size_t ky, nr = sf_tiles_noise_rows(c->tiles, &ky);
    double h = in->dy / (double)c->bs;   /* the noise's cells (box averages: bs of them a grid step) */
    long j0 = lround(in->y0 / h - 0.5) - (long)c->be;   /* box averages: be fine rows more each side */
    int rc = sf_noise_alloc(in->noise_level, j0 - (long)ky, nr, &c->noise);
    if (rc)
        return rc;
    sf_tiles_set_noise(c->tiles, noise_column, c->noise);
    c->x_off = 0.5 / (double)c->bs;
    return SF_SUCCESS;
}

/* A tiled realisation of key `key` (sign -1: of -G, the antithetic);
 * the window starts over the disc at the origin. */
/* cols: the store to share (the pair's first window's), or NULL: a new
 * one when the plan keeps columns, else none */
static int window_of_key(const sf_cof_plan *p, uint64_t key, double sign, col_store *cols, sf_cof **out)
{
    const sf_cof_plan_info *in = &p->info;
    sf_cof *c = cof_new(SF_COF_FIELD);
    if (!c)
        return SF_ENOMEM;
    c->m = in->nx;
    c->n = in->ny;
    c->dx = in->dx;
    c->dy = in->dy;
    c->y0 = in->y0;
    c->ln = p->ln;
    c->key = key;
    c->sign = sign;
    c->margin = in->margin;
    c->slack_r = (size_t)ceil(in->margin / in->dx);
    int rc = SF_SUCCESS;
    c->bs = 1;
    if (p->bw) {   /* box averages: the filter, no shared columns (they hold point values) */
        c->box = in->box;
        c->be = (p->nbw - 1) / 2;
        c->bs = in->box_step;
        if ((c->bw = sf_malloc(p->nbw * sizeof *c->bw)))
            memcpy(c->bw, p->bw, p->nbw * sizeof *c->bw);
        else
            rc = SF_ENOMEM;
        cols = NULL;
    }
    double hf = in->dx / (double)c->bs;
    sf_tiles_spec ts = { c->bs * (in->ny - 1) + 2 * c->be + 1, hf, hf, p->l, 0, 0 };
    if (!rc)
        rc = sf_tiles_alloc(&ts, &c->tiles);
    if (!rc && in->belt_noise)
        rc = belt_noise(c, in);
    if (!rc && !(c->grid = sf_malloc(c->m * c->n * sizeof *c->grid)))
        rc = SF_ENOMEM;
    if (!rc && !cols && p->keep_cols && !p->bw) {
        if ((cols = sf_calloc(1, sizeof *cols)))
            cols->n = c->n;
        else
            rc = SF_ENOMEM;
    }
    if (!rc && cols) {
        c->cols = cols;
        cols->refs++;
    }
    if (!rc) {
        sf_tiles_set_key(c->tiles, key);
        if (c->noise)
            sf_noise_set_key(c->noise, key);
        rc = sf_cof_follow(c, -p->R - in->margin, p->R + in->margin);
        c->slides = 0;   /* the first fill is not a slide */
    }
    if (rc) {
        sf_cof_free(c);
        return rc;
    }
    *out = c;
    return SF_SUCCESS;
}

/* A tiled realisation's key: 64 bits from rng (two 32-bit draws). */
static uint64_t draw_key(gsl_rng *rng)
{
    uint64_t key = (uint64_t)gsl_rng_get(rng) << 32;
    return key ^ (uint64_t)gsl_rng_get(rng);
}

static int draw_window(const sf_cof_plan *p, gsl_rng *rng, sf_cof **out)
{
    if (!rng)
        return SF_EINVAL;
    return window_of_key(p, draw_key(rng), 1, NULL, out);
}

int sf_cof_plan_point(const sf_cof_plan *p, gsl_rng *rng, double xb, double yb, double *mu)
{
    const sf_cof_plan_info *in = &p->info;
    if (!rng || !in->belt_noise || in->box > 0 || !isfinite(xb) || !isfinite(yb) || !(fabs(xb / in->dx) < 1e15) ||
        !(fabs(yb / in->dy) < 1e15))
        return SF_EINVAL;
    double h = in->dx;
    long i0 = (long)floor(xb / h - 0.5), j0 = (long)floor(yb / h - 0.5);   /* the cell centres around (xb, yb) */
    sf_cof c = { .kind = SF_COF_FIELD, .m = 2, .n = 2, .dx = h, .dy = h, .bs = 1, .x0 = ((double)i0 + 0.5) * h,
                 .y0 = ((double)j0 + 0.5) * h, .ln = p->ln };
    sf_cof_plan_info one = *in;
    one.ny = 2;
    one.y0 = c.y0;
    sf_tiles_spec ts = { 2, h, h, p->l, 0, 0 };
    double g[4];
    int rc = sf_tiles_alloc(&ts, &c.tiles);
    if (!rc)
        rc = belt_noise(&c, &one);
    if (!rc) {
        uint64_t key = draw_key(rng);
        sf_tiles_set_key(c.tiles, key);
        sf_noise_set_key(c.noise, key);
        rc = sf_tiles_fill(c.tiles, i0, 2, g, 2);
    }
    sf_tiles_free(c.tiles);
    sf_noise_free(c.noise);
    if (rc)
        return rc;
    for (int k = 0; k < 4; k++)
        g[k] = sf_lognormal_map(&p->ln, g[k]);
    sf_cof_view v = { g, 2, 2, c.x0, c.y0, 1 / h, 1 / h };   /* sf_cof_get_view's, of this 2 x 2 grid */
    *mu = sf_cof_view_at(&v, sf_cof_view_gx(&v, xb), sf_cof_view_gy(&v, yb));
    return SF_SUCCESS;
}

int sf_cof_plan_draw(sf_cof_plan *p, gsl_rng *rng, sf_cof **out)
{
    *out = NULL;
    switch (p->info.kind) {
    case SF_COF_UNIFORM:
        return sf_cof_alloc_uniform(p->mu_mean, out);
    case SF_COF_VARIABLE: {
        if (!rng)
            return SF_EINVAL;
        int rc = sf_cof_alloc_uniform(sf_lognormal_map(&p->ln, gsl_ran_gaussian_ziggurat(rng, 1.0)), out);
        if (*out)
            (*out)->kind = SF_COF_VARIABLE;
        return rc;
    }
    case SF_COF_FIELD: {
        if (p->info.generator == SF_COFGEN_TILES)
            return draw_window(p, rng, out);
        /* the strip drawn straight into the COF's grid, a function of the
         * rng state alone (sf_field_sample_fresh) */
        const sf_cof_plan_info *i = &p->info;
        sf_cof *c;
        int rc = grid_new(i->nx, i->ny, i->x0, i->y0, i->dx, i->dy, &c);
        if (rc)
            return rc;
        rc = p->cfield ? sf_field_sample_fresh(p->cfield, rng, c->grid) : sf_lnfield_sample_fresh(p->field, rng, c->grid);
        if (rc) {
            sf_cof_free(c);
            return rc;
        }
        if (p->cfield) {   /* cell averages: mubar + sd G, G of the box-averaged correlation */
            double sd = sf_cof_plan_cell_std(p);
            for (size_t k = 0; k < i->nx * i->ny; k++)
                c->grid[k] = p->ca.mubar + sd * c->grid[k];
            c->box = i->box;
        }
        grid_done(c);
        *out = c;
        return SF_SUCCESS;
    }
    }
    return SF_EINVAL;
}

int sf_cof_plan_antithetic(const sf_cof_plan *p, const sf_cof *c, sf_cof **out)
{
    *out = NULL;
    if (!c || c->kind != p->info.kind ||
        (c->kind == SF_COF_FIELD &&
         (!!c->tiles != (p->info.generator == SF_COFGEN_TILES) || (c->box > 0) != (p->info.box > 0))))
        return SF_EINVAL;
    /* exp(mu_g - sigma_g G) = exp(2 mu_g) / exp(mu_g + sigma_g G) */
    double e2 = exp(2 * p->ln.mu_g);
    switch (c->kind) {
    case SF_COF_UNIFORM:
        return sf_cof_alloc_uniform(c->mu, out);
    case SF_COF_VARIABLE: {
        int rc = sf_cof_alloc_uniform(e2 / c->mu, out);
        if (*out)
            (*out)->kind = SF_COF_VARIABLE;
        return rc;
    }
    case SF_COF_FIELD: {
        if (c->tiles)   /* the same key, the Gaussian values negated (box averages: of the map of -G) */
            return window_of_key(p, c->key, -c->sign, c->cols, out);
        sf_cof *a;
        int rc = grid_new(c->m, c->n, c->x0, c->y0, c->dx, c->dy, &a);
        if (rc)
            return rc;
        size_t np = c->m * c->n;
        if (c->box > 0) {   /* cell averages: mubar + sd G -> mubar - sd G */
            for (size_t k = 0; k < np; k++)
                a->grid[k] = 2 * p->ca.mubar - c->grid[k];
            a->box = c->box;
        } else {
            for (size_t k = 0; k < np; k++)
                a->grid[k] = e2 / c->grid[k];
        }
        grid_done(a);
        *out = a;
        return SF_SUCCESS;
    }
    }
    return SF_EINVAL;
}

/* the box grid of m x n cell-average nodes from (x0, y0) at spacing d */
static int box_grid_of(size_t m, size_t n, double x0, double y0, double d, size_t b, sf_cof_plan_info *c)
{
    size_t o = 3 * (b - 1);   /* the span of a big box's fine centres, in nodes */
    if (b < 2 || m < o + 2 || n < o + 2 || !(d > 0))
        return SF_EINVAL;
    c->nx = (m - 1 - o) / b + 1;
    c->ny = (n - 1 - o) / b + 1;
    c->x0 = x0 + 0.5 * (double)o * d;
    c->y0 = y0 + 0.5 * (double)o * d;
    c->dx = c->dy = (double)b * d;
    return SF_SUCCESS;
}

int sf_cof_box_grid(const sf_cof_plan_info *fine, size_t b, sf_cof_plan_info *coarse)
{
    if (fine->kind != SF_COF_FIELD || !(fine->box > 0) || fine->generator == SF_COFGEN_TILES)
        return SF_EINVAL;
    sf_cof_plan_info c = *fine;
    int rc = box_grid_of(fine->nx, fine->ny, fine->x0, fine->y0, fine->dx, b, &c);
    if (rc)
        return rc;
    c.box = (double)b * fine->box;
    *coarse = c;
    return SF_SUCCESS;
}

int sf_cof_box_means(const sf_cof *f, size_t b, sf_cof **out)
{
    *out = NULL;
    if (f->kind != SF_COF_FIELD || !(f->box > 0) || f->tiles)
        return SF_EINVAL;
    sf_cof_plan_info g;
    int rc = box_grid_of(f->m, f->n, f->x0, f->y0, f->dx, b, &g);
    sf_cof *c;
    if (rc || (rc = grid_new(g.nx, g.ny, g.x0, g.y0, g.dx, g.dy, &c)))
        return rc;
    size_t m = f->m;
    double w = 1.0 / (double)(b * b);
    for (size_t J = 0; J < g.ny; J++)
        for (size_t I = 0; I < g.nx; I++) {
            double sum = 0;
            for (size_t v = 0; v < b; v++)
                for (size_t u = 0; u < b; u++)
                    sum += f->grid[b * I + 3 * u + m * (b * J + 3 * v)];
            c->grid[I + g.nx * J] = sum * w;
        }
    c->box = (double)b * f->box;
    grid_done(c);
    *out = c;
    return SF_SUCCESS;
}

int sf_cof_sub_grid(const sf_cof_plan_info *fine, size_t k, sf_cof_plan_info *coarse)
{
    if (fine->kind != SF_COF_FIELD || fine->box > 0 || fine->generator == SF_COFGEN_TILES || k < 2 ||
        fine->nx < k + 1 || fine->ny < k + 1)
        return SF_EINVAL;
    sf_cof_plan_info c = *fine;
    c.nx = (fine->nx - 1) / k + 1;
    c.ny = (fine->ny - 1) / k + 1;
    c.dx = (double)k * fine->dx;
    c.dy = (double)k * fine->dy;
    *coarse = c;
    return SF_SUCCESS;
}

int sf_cof_subsample(const sf_cof *f, size_t k, sf_cof **out)
{
    *out = NULL;
    if (f->kind != SF_COF_FIELD || f->box > 0 || f->tiles || k < 2 || f->m < k + 1 || f->n < k + 1)
        return SF_EINVAL;
    size_t mc = (f->m - 1) / k + 1, nc = (f->n - 1) / k + 1;
    sf_cof *c;
    int rc = grid_new(mc, nc, f->x0, f->y0, (double)k * f->dx, (double)k * f->dy, &c);
    if (rc)
        return rc;
    for (size_t j = 0; j < nc; j++)
        for (size_t i = 0; i < mc; i++)
            c->grid[i + mc * j] = f->grid[k * i + f->m * k * j];
    grid_done(c);
    *out = c;
    return SF_SUCCESS;
}

int sf_cof_from_scene(const sf_scene *s, gsl_rng *rng, sf_cof **out)
{
    sf_cof_plan *p;
    *out = NULL;
    int rc = sf_cof_plan_alloc(s, &p, NULL, 0);
    if (rc)
        return rc;
    rc = sf_cof_plan_draw(p, rng, out);
    sf_cof_plan_free(p);
    return rc;
}

int sf_cof_plan_alloc_mt(const sf_scene *s, sf_cof_plan **out, char *err, size_t errlen)
{
    int rc;
#pragma omp critical(sf_fftw_plan)
    rc = sf_cof_plan_alloc(s, out, err, errlen);
    return rc;
}

int sf_cof_plan_build_mt(const sf_scene *s, const sf_plan *pl, sf_cof_plan **out, char *err, size_t errlen)
{
    int rc;
#pragma omp critical(sf_fftw_plan)
    rc = sf_cof_plan_build(s, pl, out, err, errlen);
    return rc;
}

void sf_cof_plan_free_mt(sf_cof_plan *p)
{
#pragma omp critical(sf_fftw_plan)
    sf_cof_plan_free(p);
}
