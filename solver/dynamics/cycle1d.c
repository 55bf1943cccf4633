/* slipfield: the closed-form 1-D stick-slip cycle of Eqs. 3-4
 * (cycle1d.h; docs/design.md sec. 4.7). */
#include "cycle1d.h"
#include "sf_error.h"

#include <math.h>
#include <gsl/gsl_math.h>

int sf_cycle1d_init(sf_cycle1d *c, const sf_scene *s, double eps)
{
    double N = s->m * s->g;
    c->omega = sqrt(s->k / s->m);
    c->xs = s->mu_mean * N / s->k;
    c->xe = s->mu_k_ratio * s->mu_mean * N / s->k;
    c->d = c->xs - c->xe;
    c->delta = eps * c->omega * s->R;
    double vr = s->v_b - c->delta;   /* disc speed when slip ends (and starts) */
    if (!(vr > 0) || !(vr < c->xe * c->omega) || !(c->d > 0))
        return SF_EINVAL;
    c->A = hypot(c->d, vr / c->omega);
    c->t_stick = 2 * c->d / s->v_b;
    c->t_slip = (M_PI + 2 * atan(vr / (c->omega * c->d))) / c->omega;
    c->period = c->t_stick + c->t_slip;
    c->pv_x = 2 * c->A;
    c->pv_F = 2 * (1 - s->mu_k_ratio) * s->mu_mean * N;
    c->stick_fraction = c->t_stick / c->period;
    /* from rest: x = x_e (1 - cos w t), xdot = x_e w sin w t reaches vr */
    c->t_first_stick = asin(vr / (c->xe * c->omega)) / c->omega;
    c->x_first_stick = c->xe * (1 - cos(c->omega * c->t_first_stick));
    c->t_first_slip = c->t_first_stick + (c->xs - c->x_first_stick) / s->v_b;
    return SF_SUCCESS;
}

double sf_cycle1d_transition(const sf_cycle1d *c, unsigned n)
{
    if (n == 0)
        return c->t_first_stick;
    /* n odd: slip onsets, n even: stick onsets, one period apart */
    unsigned k = (n - 1) / 2;
    double t = c->t_first_slip + (double)k * c->period;
    return n % 2 ? t : t + c->t_slip;
}

double sf_cycle1d_stick_time(const sf_cycle1d *c, double t0, double t1)
{
    double st = 0;
    for (unsigned j = 0;; j++) {
        double a = sf_cycle1d_transition(c, 2 * j), b = sf_cycle1d_transition(c, 2 * j + 1);
        if (a >= t1)
            return st;
        st += fmax(0, fmin(b, t1) - fmax(a, t0));
    }
}
