/* The independent 3-DOF oracle: see ref3dof.h for what it does its own
 * way and why. */
#include "ref3dof.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

/* Events are bisected to this width [s] (the solver's own goal is 1e-12 s:
 * a tenth of it keeps the oracle's share of a transition-time gap small). */
#define REF_TIME_TOL 1e-13
/* Interior points at which a step near the threshold is scanned. */
#define REF_NSCAN 32

struct ref3dof {
    /* physics, read from the scene */
    double m, k, vb, R, N, J, wn, ratio, eps, delta, T, t_skip;
    double init[REF_N];
    /* COF: a constant, or the nodal values of a grid */
    int grid;
    double mu, mu_max;   /* the constant, and the largest nodal value */
    size_t gm, gn;
    double gx0, gy0, gdx, gdy;
    const double *g;
    /* quadrature: offsets [m] and weights [N] (sum N) */
    size_t nq;
    double *qx, *qy, *qw;
    /* the disc average's own rule (weights sum to 1): 4x the wrench's
     * nodes each way -- it runs only at stick tests, and a stick onset
     * near the circle's edge is decided by it */
    size_t nm;
    double *mx, *my, *mw;
    double dt;
    double tol, hnext;   /* > 0: step doubling at this tolerance (ref3dof_alloc_nodes); the next trial step */
    double sc[REF_N];    /* the state's scales for it */
};

/* Own bilinear interpolation of the nodal values (clamped at the edges). */
static double cof_at(const ref3dof *o, double xb, double yb)
{
    if (!o->grid)
        return o->mu;
    double fx = (xb - o->gx0) / o->gdx, fy = (yb - o->gy0) / o->gdy;
    double lx = (double)(o->gm - 1), ly = (double)(o->gn - 1);
    fx = fx < 0 ? 0 : (fx > lx ? lx : fx);
    fy = fy < 0 ? 0 : (fy > ly ? ly : fy);
    size_t i = (size_t)fx, j = (size_t)fy;
    if (i > o->gm - 2)
        i = o->gm - 2;
    if (j > o->gn - 2)
        j = o->gn - 2;
    double a = fx - (double)i, b = fy - (double)j;
    const double *p = o->g + i + o->gm * j;
    return (1 - a) * (1 - b) * p[0] + a * (1 - b) * p[1] + (1 - a) * b * p[o->gm] + a * b * p[o->gm + 1];
}

/* Gauss-Legendre in r on [0, R] (exact for the area weight r dr) x the
 * trapezoid (midpoint-offset) rule in angle: nodes r (cos a, sin a),
 * weights scale r w_r (2 pi / na). */
static int disc_rule(double R, size_t nr, size_t na, double scale, size_t *n, double **x, double **y, double **w)
{
    *n = nr * na;
    *x = malloc(*n * sizeof **x);
    *y = malloc(*n * sizeof **y);
    *w = malloc(*n * sizeof **w);
    gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(nr);
    if (!*x || !*y || !*w || !tab) {
        if (tab)
            gsl_integration_glfixed_table_free(tab);
        return SF_ENOMEM;
    }
    for (size_t i = 0; i < nr; i++) {
        double r, wr;
        gsl_integration_glfixed_point(0, R, i, &r, &wr, tab);
        for (size_t j = 0; j < na; j++) {
            double a = 2 * M_PI * ((double)j + 0.5) / (double)na;
            size_t q = i * na + j;
            (*x)[q] = r * cos(a);
            (*y)[q] = r * sin(a);
            (*w)[q] = scale * r * wr * 2 * M_PI / (double)na;
        }
    }
    gsl_integration_glfixed_table_free(tab);
    return SF_SUCCESS;
}

/* The physics and the COF of scene s, no quadrature yet. */
static int oracle_new(const sf_scene *s, const sf_cof *cof, double dt, ref3dof **out)
{
    *out = NULL;
    if (s->dof != SF_DOF_3 || !s->velocity_jump || !(dt > 0))
        return SF_EINVAL;
    if (sf_cof_window_margin(cof) > 0)   /* a tiled window slides under the solver's runs: no fixed grid to read */
        return SF_EINVAL;
    ref3dof *o = calloc(1, sizeof *o);
    if (!o)
        return SF_ENOMEM;
    o->m = s->m;
    o->k = s->k;
    o->vb = s->v_b;
    o->R = s->R;
    o->N = s->m * s->g;
    o->J = s->m * s->R * s->R / 2;   /* Eq. 5: J = m R^2 / 2 */
    o->wn = sqrt(s->k / s->m);
    o->ratio = s->mu_k_ratio;        /* Eq. 1 */
    o->eps = s->eps_lambda;
    o->delta = s->eps_lambda * o->wn * s->R;   /* Eq. 14's jump in m/s */
    o->T = s->T;
    o->t_skip = s->t_skip;
    double init[REF_N] = { s->x0, s->y0, s->phi0, s->vx0, s->vy0, s->w0 };
    memcpy(o->init, init, sizeof init);
    o->dt = dt;
    if (sf_cof_grid_view(cof, &o->gm, &o->gn, &o->gx0, &o->gy0, &o->gdx, &o->gdy, &o->g) == SF_SUCCESS) {
        o->grid = 1;
        for (size_t i = 0; i < o->gm * o->gn; i++)
            o->mu_max = fmax(o->mu_max, o->g[i]);
    } else
        o->mu = o->mu_max = sf_cof_eval(cof, 0, 0);
    *out = o;
    return SF_SUCCESS;
}

int ref3dof_alloc(const sf_scene *s, const sf_cof *cof, double dt, size_t nr, size_t na, ref3dof **out)
{
    *out = NULL;
    if (nr < 1 || na < 3)
        return SF_EINVAL;
    ref3dof *o;
    int rc = oracle_new(s, cof, dt, &o);
    if (rc)
        return rc;
    /* wrench: weights P dS [N]; disc average: dS / (pi R^2) */
    if (disc_rule(s->R, nr, na, o->N / (M_PI * s->R * s->R), &o->nq, &o->qx, &o->qy, &o->qw) ||
        disc_rule(s->R, 4 * nr, 4 * na, 1 / (M_PI * s->R * s->R), &o->nm, &o->mx, &o->my, &o->mw)) {
        ref3dof_free(o);
        return SF_ENOMEM;
    }
    *out = o;
    return SF_SUCCESS;
}

int ref3dof_alloc_nodes(const sf_scene *s, const sf_cof *cof, double dt, double tol, size_t n, const double *rx,
                        const double *ry, const double *w, ref3dof **out)
{
    *out = NULL;
    double sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += w[i];
    if (n < 1 || !(sum > 0) || !isfinite(sum) || !(tol >= 0))
        return SF_EINVAL;
    ref3dof *o;
    int rc = oracle_new(s, cof, dt, &o);
    if (rc)
        return rc;
    o->tol = tol;
    double xs = o->mu_max * o->N / o->k;   /* the stick distance, and its speed, angle and spin */
    double sc[REF_N] = { xs, xs, xs / o->R, xs * o->wn, xs * o->wn, xs * o->wn / o->R };
    memcpy(o->sc, sc, sizeof sc);
    o->nq = o->nm = n;
    o->qx = malloc(n * sizeof *o->qx);
    o->qy = malloc(n * sizeof *o->qy);
    o->qw = malloc(n * sizeof *o->qw);
    o->mx = malloc(n * sizeof *o->mx);
    o->my = malloc(n * sizeof *o->my);
    o->mw = malloc(n * sizeof *o->mw);
    if (!o->qx || !o->qy || !o->qw || !o->mx || !o->my || !o->mw) {
        ref3dof_free(o);
        return SF_ENOMEM;
    }
    for (size_t i = 0; i < n; i++) {   /* the same rule for both: weights P dS [N] and dS / (pi R^2) */
        o->qx[i] = o->mx[i] = rx[i];
        o->qy[i] = o->my[i] = ry[i];
        o->qw[i] = o->N * w[i] / sum;
        o->mw[i] = w[i] / sum;
    }
    *out = o;
    return SF_SUCCESS;
}

void ref3dof_free(ref3dof *o)
{
    if (!o)
        return;
    free(o->qx);
    free(o->qy);
    free(o->qw);
    free(o->mx);
    free(o->my);
    free(o->mw);
    free(o);
}

/* Eqs. 7-8 with the kinetic COF: a disc point at offset (rx, ry) slips at
 * v_p = (u - w ry, v + w rx) relative to the belt; the force on the disc
 * is -P mu_k v_p/|v_p| dS, its moment r x (that force). */
void ref3dof_wrench(const ref3dof *o, double t, const double s[REF_N], double out[3])
{
    double xb = s[REF_X] - o->vb * t, yb = s[REF_Y];
    double u = s[REF_VX] - o->vb, v = s[REF_VY], w = s[REF_W];
    double F[3] = { 0, 0, 0 };
    for (size_t q = 0; q < o->nq; q++) {
        double rx = o->qx[q], ry = o->qy[q];
        double px = u - w * ry, py = v + w * rx, sp = sqrt(px * px + py * py);
        if (!(sp > 0))
            continue;
        double c = o->ratio * cof_at(o, xb + rx, yb + ry) * o->qw[q] / sp;
        F[0] -= c * px;
        F[1] -= c * py;
        F[2] -= c * (rx * py - ry * px);
    }
    memcpy(out, F, sizeof F);
}

/* Disc-averaged static COF at belt point (xb, yb): the equatorial radius
 * of the limit surface (Eq. 11 at theta = 0 for a uniform field; the
 * paper's stick criterion). */
double ref3dof_mean_cof(const ref3dof *o, double xb, double yb)
{
    if (!o->grid)
        return o->mu;
    double a = 0;
    for (size_t q = 0; q < o->nm; q++)
        a += o->mw[q] * cof_at(o, xb + o->mx[q], yb + o->my[q]);
    return a;
}

/* Eq. 9: the dimensionless relative speed. */
static double lambda(const ref3dof *o, const double s[REF_N])
{
    double a = (s[REF_VX] - o->vb) / (o->wn * o->R), b = s[REF_VY] / (o->wn * o->R), c = s[REF_W] / o->wn;
    return sqrt(a * a + b * b + c * c);
}

/* Stick admissible at (t, s): the stick force (k x, k y) (Eq. 6) strictly
 * inside the equatorial circle of radius mu_bar m g. */
static int admissible(const ref3dof *o, double t, const double s[REF_N])
{
    double mb = ref3dof_mean_cof(o, s[REF_X] - o->vb * t, s[REF_Y]);
    return o->k * sqrt(s[REF_X] * s[REF_X] + s[REF_Y] * s[REF_Y]) < mb * o->N;
}

/* The slip-to-stick predicate (Sec. 2.4): lambda < eps and admissible. */
static int to_stick(const ref3dof *o, double t, const double s[REF_N])
{
    return lambda(o, s) < o->eps && admissible(o, t, s);
}

/* Eq. 5 in slip: m x'' = -k x + Fx, m y'' = -k y + Fy, J phi'' = T. */
static void deriv(const ref3dof *o, double t, const double s[REF_N], double d[REF_N])
{
    double F[3];
    ref3dof_wrench(o, t, s, F);
    d[REF_X] = s[REF_VX];
    d[REF_Y] = s[REF_VY];
    d[REF_PHI] = s[REF_W];
    d[REF_VX] = (-o->k * s[REF_X] + F[0]) / o->m;
    d[REF_VY] = (-o->k * s[REF_Y] + F[1]) / o->m;
    d[REF_W] = F[2] / o->J;
}

/* One classical RK4 step of length h from (t, s) into out. */
static void rk4(const ref3dof *o, double t, const double s[REF_N], double h, double out[REF_N])
{
    double k1[REF_N], k2[REF_N], k3[REF_N], k4[REF_N], tmp[REF_N];
    deriv(o, t, s, k1);
    for (int i = 0; i < REF_N; i++)
        tmp[i] = s[i] + 0.5 * h * k1[i];
    deriv(o, t + 0.5 * h, tmp, k2);
    for (int i = 0; i < REF_N; i++)
        tmp[i] = s[i] + 0.5 * h * k2[i];
    deriv(o, t + 0.5 * h, tmp, k3);
    for (int i = 0; i < REF_N; i++)
        tmp[i] = s[i] + h * k3[i];
    deriv(o, t + h, tmp, k4);
    for (int i = 0; i < REF_N; i++)
        out[i] = s[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
}

/* One step of at most hmax from (t, s) into out by step doubling: a step
 * h against two of h/2, their difference / 15 (RK4's local error of the
 * pair, Richardson) in the scales sc at most tol, else h shrinks; the two
 * half steps are kept.  A kink or a jump of the wrench (a cell's point
 * crossing a grid line of the COF, the pole of the slip field crossing a
 * point) inside a step is met by shorter steps there, so the error keeps
 * falling with tol where fixed steps lose their order.  Returns the step
 * taken. */
static double rk4_doubling(ref3dof *o, double t, const double s[REF_N], double hmax, double out[REF_N],
                           unsigned long *count)
{
    double h = fmin(o->hnext, hmax), a[REF_N], m[REF_N], b[REF_N];
    for (;;) {
        rk4(o, t, s, h, a);
        rk4(o, t, s, 0.5 * h, m);
        rk4(o, t + 0.5 * h, m, 0.5 * h, b);
        *count += 3;
        double err = 0;
        for (int i = 0; i < REF_N; i++)
            err = fmax(err, fabs(b[i] - a[i]) / (15 * o->sc[i]));
        double f = err > 0 ? 0.9 * pow(o->tol / err, 0.2) : 4;
        if (err <= o->tol || isnan(err) || h < 1e-13) {   /* NaN: the run's finiteness test stops it */
            memcpy(out, b, sizeof b);
            o->hnext = h * fmin(f, 4);
            return h;
        }
        h *= fmax(f, 0.2);
    }
}

/* ---- QoI accumulation (definitions of oscillator.h, own code) */
typedef struct {
    ref3dof_result *r;
    size_t cap_e, cap_c;
    int open;
    double t0, xmin, xmax, Fmin, Fmax, stick, stick_total, cycle_total;
    /* the paper's oscillation since the last maximum of x in the window
     * (osc: one is open), its ranges [lo, hi] of x and F; the sums of
     * the closed ones' PVs */
    int osc;
    double ox[2], oF[2], sum_x, sum_F;
} qacc;

static void widen(double range[2], double v)
{
    if (v < range[0]) range[0] = v;
    if (v > range[1]) range[1] = v;
}

static void seen(qacc *a, double x, double F)
{
    if (a->osc) {
        widen(a->ox, x);
        widen(a->oF, F);
    }
    if (!a->open)
        return;
    if (x < a->xmin) a->xmin = x;
    if (x > a->xmax) a->xmax = x;
    if (F < a->Fmin) a->Fmin = F;
    if (F > a->Fmax) a->Fmax = F;
}

/* A maximum of x at t (seen() has taken it): inside the window it ends
 * the open oscillation, if any, and starts the next one there. */
static void x_max(const ref3dof *o, qacc *a, double t, double x, double F)
{
    if (!(t >= o->t_skip && t <= o->T))
        return;
    if (a->osc) {
        a->r->nosc++;
        a->sum_x += a->ox[1] - a->ox[0];
        a->sum_F += a->oF[1] - a->oF[0];
    }
    a->osc = 1;
    a->ox[0] = a->ox[1] = x;
    a->oF[0] = a->oF[1] = F;
}

/* The part of the stick span [t0, t1] inside [t_skip, T]. */
static double in_window(const ref3dof *o, double t0, double t1)
{
    double lo = t0 > o->t_skip ? t0 : o->t_skip, hi = t1 < o->T ? t1 : o->T;
    return hi > lo ? hi - lo : 0;
}

static int event(const ref3dof *o, qacc *a, int kind, double t, const double pre[REF_N], const double post[REF_N])
{
    ref3dof_result *r = a->r;
    if (r->nev == a->cap_e) {
        a->cap_e = a->cap_e ? 2 * a->cap_e : 32;
        void *p = realloc(r->ev, a->cap_e * sizeof *r->ev);
        if (!p)
            return SF_ENOMEM;
        r->ev = p;
    }
    ref3dof_event *e = &r->ev[r->nev++];
    e->t = t;
    e->kind = kind;
    memcpy(e->pre, pre, sizeof e->pre);
    memcpy(e->post, post, sizeof e->post);
    if (kind != REF_STICK_ONSET)
        return SF_SUCCESS;
    if (a->open) {
        if (r->ncycles == a->cap_c) {
            a->cap_c = a->cap_c ? 2 * a->cap_c : 32;
            double **arr[] = { &r->cycle_pv_x, &r->cycle_pv_F, &r->cycle_stick };
            for (int i = 0; i < 3; i++) {
                void *p = realloc(*arr[i], a->cap_c * sizeof(double));
                if (!p)
                    return SF_ENOMEM;
                *arr[i] = p;
            }
        }
        r->cycle_pv_x[r->ncycles] = a->xmax - a->xmin;
        r->cycle_pv_F[r->ncycles] = a->Fmax - a->Fmin;
        r->cycle_stick[r->ncycles] = a->stick;
        r->ncycles++;
        a->stick_total += a->stick;
        a->cycle_total += t - a->t0;
    }
    a->open = t >= o->t_skip;
    a->t0 = t;
    a->xmin = a->xmax = post[REF_X];
    a->Fmin = a->Fmax = o->k * post[REF_X];
    a->stick = 0;
    return SF_SUCCESS;
}

/* Earliest h' in (0, h] where pred holds along the RK4 step from (t, s)
 * (it holds at h, not at 0): bisection to REF_TIME_TOL; state into out. */
typedef int (*pred_fn)(const ref3dof *o, double t, const double s[REF_N], const double s0[REF_N]);

static double bisect(const ref3dof *o, double t, const double s[REF_N], double h, pred_fn pred, double out[REF_N],
                     unsigned long *count)
{
    double lo = 0, hi = h, tmp[REF_N];
    while (hi - lo > REF_TIME_TOL) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break;
        rk4(o, t, s, mid, tmp);
        (*count)++;
        if (pred(o, t + mid, tmp, s))
            hi = mid;
        else
            lo = mid;
    }
    rk4(o, t, s, hi, out);
    return hi;
}

static int pred_stick(const ref3dof *o, double t, const double s[REF_N], const double s0[REF_N])
{
    (void)s0;
    return to_stick(o, t, s);
}

static int pred_vx0(const ref3dof *o, double t, const double s[REF_N], const double s0[REF_N])
{
    (void)o;
    (void)t;
    return s[REF_VX] * (s0[REF_VX] > 0 ? 1 : -1) <= 0;
}

static void samples_slip(const ref3dof *o, ref3dof_result *r, size_t *next, double t, const double s[REF_N],
                         double t1)
{
    while (*next < r->nsamples && (double)*next * r->sample_dt <= t1) {
        double tk = (double)*next * r->sample_dt, tmp[REF_N];
        if (tk <= t)
            r->x_samples[*next] = s[REF_X];
        else {
            rk4(o, t, s, tk - t, tmp);
            r->x_samples[*next] = tmp[REF_X];
        }
        (*next)++;
    }
}

int ref3dof_run(ref3dof *o, double sample_dt, ref3dof_result *res)
{
    memset(res, 0, sizeof *res);
    qacc a = { .r = res };
    size_t next = 0;
    if (sample_dt > 0) {
        res->sample_dt = sample_dt;
        res->nsamples = (size_t)floor(o->T / sample_dt) + 1;
        res->x_samples = calloc(res->nsamples, sizeof(double));
        if (!res->x_samples)
            return SF_ENOMEM;
    }
    double t = 0, s[REF_N], pre[REF_N];
    memcpy(s, o->init, sizeof s);
    o->hnext = o->dt;   /* a run does not depend on the one before */
    int stick = to_stick(o, 0, s), armed = lambda(o, s) > o->eps, rc = SF_SUCCESS;
    if (stick) {   /* Eq. 12 at t = 0 */
        memcpy(pre, s, sizeof pre);
        s[REF_VX] = o->vb;
        s[REF_VY] = 0;
        s[REF_W] = 0;
        if ((rc = event(o, &a, REF_STICK_ONSET, 0, pre, s)))
            return rc;
    }
    while (t < o->T && !rc) {
        if (stick) {
            /* exact belt motion: the belt point under the disc is fixed,
             * so is mu_bar; break when k |(x + v_b tau, y)| reaches
             * mu_bar m g (bisection, bracket by doubling) */
            double mb = ref3dof_mean_cof(o, s[REF_X] - o->vb * t, s[REF_Y]), lim = mb * o->N;
            double x0 = s[REF_X], y0 = s[REF_Y], span = o->T - t, tau;
#define BREAKS(tt) (o->k * sqrt((x0 + o->vb * (tt)) * (x0 + o->vb * (tt)) + y0 * y0) >= lim)
            if (BREAKS(0.0))
                tau = 0;
            else {
                double lo = 0, hi = 1e-3;
                while (hi < span && !BREAKS(hi)) {
                    lo = hi;
                    hi *= 2;
                }
                if (hi >= span && !BREAKS(span))
                    tau = span;   /* stick to the end of the run */
                else {
                    if (hi > span)
                        hi = span;
                    while (hi - lo > REF_TIME_TOL && 0.5 * (lo + hi) > lo && 0.5 * (lo + hi) < hi) {
                        double mid = 0.5 * (lo + hi);
                        if (BREAKS(mid))
                            hi = mid;
                        else
                            lo = mid;
                        res->bisections++;
                    }
                    tau = hi;
                }
            }
#undef BREAKS
            seen(&a, x0, o->k * x0);
            while (next < res->nsamples && (double)next * res->sample_dt <= t + tau) {
                res->x_samples[next] = x0 + o->vb * ((double)next * res->sample_dt - t);
                next++;
            }
            s[REF_X] = x0 + o->vb * tau;
            if (a.open)
                a.stick += tau;
            res->stick_time += in_window(o, t, t + tau);
            t += tau;
            seen(&a, s[REF_X], o->k * s[REF_X]);
            if (tau >= span)
                break;
            /* Eq. 14: relative velocity delta opposite the stick force */
            memcpy(pre, s, sizeof pre);
            double psi = atan2(o->k * s[REF_Y], o->k * s[REF_X]);
            s[REF_VX] = o->vb - o->delta * cos(psi);
            s[REF_VY] = -o->delta * sin(psi);
            s[REF_W] = 0;
            if ((rc = event(o, &a, REF_SLIP_ONSET, t, pre, s)))
                break;
            double F[3];
            ref3dof_wrench(o, t, s, F);
            seen(&a, s[REF_X], F[0]);
            stick = 0;
            armed = 0;
            continue;
        }
        /* RK4 at dt, shortened near the threshold: as the relative speed
         * V = lambda omega_n R falls, friction damps the slip direction
         * on the time scale m V / (mu_k m g) (stiff: RK4 is stable only
         * below about 2.8 of it), so the step keeps below that scale,
         * down to its value at V = eps_lambda omega_n R */
        double V = fmax(lambda(o, s), o->eps) * o->wn * o->R;
        double h = fmin(fmin(o->dt, o->m * V / (o->ratio * o->mu_max * o->N)), o->T - t), s1[REF_N];
        if (o->tol > 0)
            h = rk4_doubling(o, t, s, h, s1, &res->bisections);
        else
            rk4(o, t, s, h, s1);
        res->steps++;
        for (int i = 0; i < REF_N; i++)
            if (!isfinite(s1[i]))
                rc = SF_EFAIL;
        if (rc)
            break;
        int st = armed && to_stick(o, t + h, s1);
        /* lambda can dip below eps inside a step and rise again (a V
         * narrower than the step where the relative velocity passes
         * zero): a step whose ends are within the largest change lambda
         * can make over it (|acceleration| bound / (omega_n R), spin part
         * likewise) of the threshold is scanned at interior points */
        double rate = (o->k * sqrt(s[REF_X] * s[REF_X] + s[REF_Y] * s[REF_Y]) + o->ratio * o->mu_max * o->N) /
                          (o->m * o->wn * o->R) +
                      o->ratio * o->mu_max * o->N * o->R / (o->J * o->wn);
        if (armed && !st && fmin(lambda(o, s), lambda(o, s1)) < o->eps + h * rate) {
            for (int j = 1; j < REF_NSCAN && !st; j++) {
                double hj = h * j / REF_NSCAN, sj[REF_N];
                rk4(o, t, s, hj, sj);
                res->bisections++;
                if (to_stick(o, t + hj, sj)) {
                    st = 1;
                    h = hj;
                    memcpy(s1, sj, sizeof sj);
                }
            }
        }
        if (st)
            h = bisect(o, t, s, h, pred_stick, s1, &res->bisections);
        if (s[REF_VX] * s1[REF_VX] < 0) {   /* an extremum of x inside the step */
            double sx[REF_N], F[3], hx = bisect(o, t, s, h, pred_vx0, sx, &res->bisections);
            ref3dof_wrench(o, t + hx, sx, F);
            seen(&a, sx[REF_X], F[0]);
            if (s[REF_VX] > 0)   /* vx from + to -: a maximum */
                x_max(o, &a, t + hx, sx[REF_X], F[0]);
        }
        samples_slip(o, res, &next, t, s, t + h);
        double F[3];
        ref3dof_wrench(o, t + h, s1, F);
        seen(&a, s1[REF_X], F[0]);
        t = (h == o->T - t) ? o->T : t + h;
        memcpy(s, s1, sizeof s);
        if (!st) {
            if (lambda(o, s) > o->eps)
                armed = 1;
            continue;
        }
        /* Eq. 12 */
        memcpy(pre, s, sizeof pre);
        s[REF_VX] = o->vb;
        s[REF_VY] = 0;
        s[REF_W] = 0;
        stick = 1;
        rc = event(o, &a, REF_STICK_ONSET, t, pre, s);
    }
    while (!rc && next < res->nsamples)   /* t = T exactly */
        res->x_samples[next++] = s[REF_X];
    memcpy(res->end, s, sizeof s);
    if (res->ncycles) {
        double sx = 0, sF = 0;
        for (size_t i = 0; i < res->ncycles; i++) {
            sx += res->cycle_pv_x[i];
            sF += res->cycle_pv_F[i];
        }
        res->pv_x = sx / (double)res->ncycles;
        res->pv_F = sF / (double)res->ncycles;
        res->stick_fraction = a.stick_total / a.cycle_total;
    } else
        res->pv_x = res->pv_F = res->stick_fraction = NAN;
    res->osc_pv_x = res->nosc ? a.sum_x / (double)res->nosc : NAN;
    res->osc_pv_F = res->nosc ? a.sum_F / (double)res->nosc : NAN;
    res->win_stick_fraction = o->T > o->t_skip ? res->stick_time / (o->T - o->t_skip) : NAN;
    return rc;
}

void ref3dof_result_free(ref3dof_result *r)
{
    if (!r)
        return;
    free(r->ev);
    free(r->cycle_pv_x);
    free(r->cycle_pv_F);
    free(r->cycle_stick);
    free(r->x_samples);
    memset(r, 0, sizeof *r);
}

double ref3dof_eq15(const double *a, const double *b, size_t n, double dt)
{
    double e = 0;
    for (size_t i = 1; i < n; i++)
        e += (a[i] - b[i]) * (a[i] - b[i]) * dt;
    return e;
}
