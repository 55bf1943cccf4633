#include "cof.h"
#include "lnfield.h"
#include "lognormal.h"
#include "sf_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_randist.h>

struct sf_cof {
    sf_cof_kind kind;
    double mu;                 /* uniform / variable value */
    size_t m, n;
    double x0, y0, dx, dy;
    double *grid;              /* m*n values, x fastest */
    unsigned long outside;     /* evaluations clamped to the grid edge */
};

static sf_cof *cof_new(sf_cof_kind kind)
{
    sf_cof *c = calloc(1, sizeof *c);
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
    c->mu = mu_s;
    *out = c;
    return SF_SUCCESS;
}

int sf_cof_alloc_grid(size_t m, size_t n, double x0, double y0,
                      double dx, double dy, const double *mu_s, sf_cof **out)
{
    *out = NULL;
    if (m < 2 || n < 2 || !(dx > 0) || !(dy > 0) || !mu_s)
        return SF_EINVAL;
    sf_cof *c = cof_new(SF_COF_FIELD);
    if (!c)
        return SF_ENOMEM;
    c->grid = malloc(m * n * sizeof *c->grid);
    if (!c->grid) {
        free(c);
        return SF_ENOMEM;
    }
    memcpy(c->grid, mu_s, m * n * sizeof *c->grid);
    c->m = m;
    c->n = n;
    c->x0 = x0;
    c->y0 = y0;
    c->dx = dx;
    c->dy = dy;
    *out = c;
    return SF_SUCCESS;
}

void sf_cof_free(sf_cof *c)
{
    if (!c)
        return;
    free(c->grid);
    free(c);
}

sf_cof_kind sf_cof_get_kind(const sf_cof *c) { return c->kind; }
unsigned long sf_cof_outside(const sf_cof *c) { return c->outside; }

int sf_cof_covers(const sf_cof *c, double xb, double yb, double r)
{
    if (c->kind != SF_COF_FIELD)
        return 1;
    return xb - r >= c->x0 && xb + r <= c->x0 + c->dx * (double)(c->m - 1) && yb - r >= c->y0 &&
           yb + r <= c->y0 + c->dy * (double)(c->n - 1);
}

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

/* Cell index and local coordinate along one axis, clamped to the grid. */
static size_t locate(double x, double x0, double h, size_t n, double *t, int *clamped)
{
    double s = (x - x0) / h;
    if (!(s >= 0)) {            /* also catches NaN */
        *clamped = 1;
        *t = 0;
        return 0;
    }
    if (s >= (double)(n - 1)) {
        *clamped |= s > (double)(n - 1);
        *t = 1;
        return n - 2;
    }
    size_t i = (size_t)s;
    *t = s - (double)i;
    return i;
}

double sf_cof_eval(const sf_cof *c, double xb, double yb)
{
    if (c->kind != SF_COF_FIELD)
        return c->mu;
    int clamped = 0;
    double tx, ty;
    size_t i = locate(xb, c->x0, c->dx, c->m, &tx, &clamped);
    size_t j = locate(yb, c->y0, c->dy, c->n, &ty, &clamped);
    if (clamped)
        ((sf_cof *)c)->outside++;   /* a diagnostic counter, not state */
    const double *g = c->grid + i + c->m * j;
    double a = g[0] + tx * (g[1] - g[0]);
    double b = g[c->m] + tx * (g[c->m + 1] - g[c->m]);
    return a + ty * (b - a);
}

/* ---- plans */

struct sf_cof_plan {
    sf_cof_plan_info info;
    sf_lognormal ln;
    double mu_mean;
    sf_lnfield *field;
    double *buf;
};

static int plan_err(char *err, size_t n, int rc, const char *fmt, double a, double b)
{
    if (err && n)
        snprintf(err, n, fmt, a, b);
    return rc;
}

int sf_cof_plan_alloc(const sf_scene *s, sf_cof_plan **out, char *err, size_t errlen)
{
    *out = NULL;
    sf_cof_plan *p = calloc(1, sizeof *p);
    if (!p)
        return SF_ENOMEM;
    p->info.kind = (sf_cof_kind)s->cof;
    p->mu_mean = s->mu_mean;
    int rc = sf_lognormal_init(&p->ln, s->mu_mean, s->mu_std);
    if (rc) {
        free(p);
        return plan_err(err, errlen, rc, "invalid COF marginal (mean %g, std %g)", s->mu_mean, s->mu_std);
    }
    if (p->info.kind == SF_COF_FIELD) {
        double h = s->l / 8;
        double mu_hi = s->mu_mean + 4 * s->mu_std;
        double B0 = s->R + 2 * mu_hi * s->m * s->g / s->k;
        double W0 = s->strip_halfwidth > 0 ? s->strip_halfwidth + s->R : B0;
        double E = hypot(s->v_b * s->T + 2 * B0, 2 * W0);   /* the strip the disc can visit */
        double B = B0 + 2 * h, W = W0 + 2 * h, len = s->v_b * s->T + 2 * B;
        p->info.strip_diag = E;
        if (s->shortcuts && ((E / s->l) * (E / s->l) <= SF_COF_SHORTCUT_E2 || s->mu_std == 0)) {
            p->info.kind = SF_COF_VARIABLE;
            p->info.shortcut = 1;
            *out = p;
            return SF_SUCCESS;
        }
        double nx = ceil(len / h) + 1, ny = ceil(2 * W / h) + 1;
        if (!(nx * ny <= (double)SF_COF_MAX_POINTS)) {
            free(p);
            return plan_err(err, errlen, SF_ECAP,
                            "the belt strip needs %.3g grid points (spacing l/8 = %.3g m): above the cap of 2^24; "
                            "raise l, lower v_b T or set strip_halfwidth", nx * ny, h);
        }
        p->info.nx = (size_t)nx;
        p->info.ny = (size_t)ny;
        p->info.dx = p->info.dy = h;
        p->info.x0 = -s->v_b * s->T - B;
        p->info.y0 = -W;
        p->info.bound = B;
        sf_scene gs = *s;
        gs.nx = p->info.nx;
        gs.ny = p->info.ny;
        gs.dx = gs.dy = h;
        rc = sf_lnfield_alloc(&gs, &p->field);
        if (rc == SF_ENOMEM) {   /* the embedding is over its own cap */
            free(p);
            return plan_err(err, errlen, SF_ECAP,
                            "the %.0f x %.0f grid points of the belt strip need a circulant embedding above its cap "
                            "of 2^25 points; raise l, lower v_b T or set strip_halfwidth", nx, ny);
        }
        if (rc && rc != SF_ECAP) {
            free(p);
            return plan_err(err, errlen, rc, "cannot plan the %g x %g strip field", nx, ny);
        }
        p->buf = malloc(p->info.nx * p->info.ny * sizeof *p->buf);
        if (!p->buf) {
            sf_cof_plan_free(p);
            return SF_ENOMEM;
        }
    }
    *out = p;
    return SF_SUCCESS;
}

void sf_cof_plan_free(sf_cof_plan *p)
{
    if (!p)
        return;
    sf_lnfield_free(p->field);
    free(p->buf);
    free(p);
}

const sf_cof_plan_info *sf_cof_plan_get_info(const sf_cof_plan *p) { return &p->info; }

int sf_cof_plan_draw(sf_cof_plan *p, gsl_rng *rng, sf_cof **out)
{
    *out = NULL;
    switch (p->info.kind) {
    case SF_COF_UNIFORM:
        return sf_cof_alloc_uniform(p->mu_mean, out);
    case SF_COF_VARIABLE: {
        int rc = sf_cof_alloc_uniform(sf_lognormal_map(&p->ln, gsl_ran_gaussian_ziggurat(rng, 1.0)), out);
        if (*out)
            (*out)->kind = SF_COF_VARIABLE;
        return rc;
    }
    case SF_COF_FIELD: {
        sf_field_discard(sf_lnfield_gaussian(p->field));
        int rc = sf_lnfield_sample(p->field, rng, NULL, p->buf);
        if (rc)
            return rc;
        const sf_cof_plan_info *i = &p->info;
        return sf_cof_alloc_grid(i->nx, i->ny, i->x0, i->y0, i->dx, i->dy, p->buf, out);
    }
    }
    return SF_EINVAL;
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
