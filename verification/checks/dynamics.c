/* Checks of the 3-DOF stochastic stick-slip integrator (Eqs. 5-8, 12-15)
 * on lognormal COF fields: the threshold study of Fig. 7, the velocity
 * jump of Fig. 6, long runs, the baseline responses and phase portraits of
 * Figs. 9 and 14, the exact stick section against the equatorial circle,
 * the one-random-variable limit, reproducibility, and PV_F as the
 * continuous force's peak-to-valley. */
#include "checks.h"
#include "common.h"
#include "../stats.h"
#include "contact.h"
#include "surface.h"
#include "cycle1d.h"
#include "cof.h"
#include "oscillator.h"
#include "sf_error.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_statistics_double.h>

/* Fig. 7: Eq. 15 error against the eps_lambda = 1e-5 reference over T,
 * the same COF (one field realisation, or a uniform COF) for every run; it must fall monotonically with eps, at an
 * observed order of at least `tolerance` (x errors are first order in eps,
 * Eq. 15 squares them: 2 expected). */
static int chk_eps_study(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    size_t K = c->spec.sweep.n;
    if (K < 3)
        return SF_EINVAL;
    sf_cof *cof = check_case_cof(c, s0, r);
    if (!cof)
        return SF_EFAIL;
    const double dt = 1e-3;
    sf_scene sr = *s0;
    sr.eps_lambda = 1e-5;
    sf_osc_result ref;
    if (check_osc_run(&sr, NULL, cof, dt, &ref, NULL, NULL, r)) {
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    double *e = check_alloc(K * sizeof *e), *err = check_alloc(K * sizeof *err);
    int mono = 1;
    sf_note(r, "| eps_lambda | Eq. 15 error [m^2 s] | PV_x [m] | stick fraction | steps |\n|---|---|---|---|---|");
    sf_note(r, "| 1e-05 (reference) | 0 | %.6f | %.6f | %lu |", ref.pv_x, ref.stick_fraction, ref.steps);
    for (size_t k = 0; k < K; k++) {
        sf_scene s = *s0;
        s.eps_lambda = c->spec.sweep.v[k];
        sf_osc_result res;
        if (check_osc_run(&s, NULL, cof, dt, &res, NULL, NULL, r)) {
            sf_cof_free(cof);
            return SF_EFAIL;
        }
        e[k] = s.eps_lambda;
        err[k] = sf_osc_error_eq15(&res, &ref);
        if (k && !(err[k] < err[k - 1]))
            mono = 0;
        sf_note(r, "| %g | %.3e | %.6f | %.6f | %lu |", e[k], err[k], res.pv_x, res.stick_fraction, res.steps);
        sf_osc_result_free(&res);
    }
    double lx[64], ly[64], c0, c1, a, b, cc, ss;
    for (size_t k = 0; k < K; k++) {
        lx[k] = log(e[k]);
        ly[k] = log(err[k]);
    }
    gsl_fit_linear(lx, 1, ly, 1, K, &c0, &c1, &a, &b, &cc, &ss);
    sf_check_true(r, "Eq. 15 error falls monotonically as eps_lambda falls (the trend of Fig. 7)", mono,
                  mono ? "monotone" : "not monotone");
    sf_check_ge(r, "observed order of the Eq. 15 error in eps_lambda", c1, c->spec.tolerance);
    char cofd[96];
    if (s0->cof == SF_COF_FIELD)
        snprintf(cofd, sizeof cofd, "the same field realisation for every run (l = %g m, CV = %g)", s0->l,
                 s0->mu_std / s0->mu_mean);
    else if (s0->cof == SF_COF_VARIABLE)
        snprintf(cofd, sizeof cofd, "one random COF value, the same for every run");
    else
        snprintf(cofd, sizeof cofd, "uniform, mu = %g (no random input: the same numbers at every seed)", s0->mu_mean);
    sf_note(r, "\nCOF: %s; T = %g s, reference eps_lambda = 1e-5, Eq. 15 summed over samples every %g s. Observed "
               "order %.2f: the displacement error is first order in eps (cases/deterministic/eps-first-order), and "
               "Eq. 15 squares it. The paper's Fig. 7 shows the same monotone fall; its absolute values depend on its "
               "time step and field.\n",
            cofd, s0->T, dt, c1);
    sf_plot *p = sf_result_plot(r, "fig7", "Error vs threshold (Fig. 7), stochastic baseline", "eps_lambda [-]",
                                "Eq. 15 error [m^2 s]");
    sf_plot_log(p, 1, 1);
    sf_plot_series(p, "measured", SF_STYLE_LINESPOINTS, K, e, err);
    double *fit = check_alloc(K * sizeof *fit);
    for (size_t k = 0; k < K; k++)
        fit[k] = exp(c0 + c1 * lx[k]);
    sf_plot_series(p, "least-squares power law", SF_STYLE_LINES, K, e, fit);
    free(fit); free(e); free(err);
    sf_osc_result_free(&ref);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Fig. 6: with the velocity jump of Eq. 14 the slip starts with the full
 * kinetic friction; without it the relative velocity is zero at the
 * release, the slip direction undefined and the friction force drops to
 * zero: the drop the paper shows. */
typedef struct {
    check_hist h;
    const sf_scene *s;
    int prev_stick;
    double prev_t, prev_x, prev_y;
    double minF_after_break, maxF_after_break;
    size_t breaks;
    /* Eq. 14 at every release, recomputed from the rows: the slip row just
     * after the stick row of the same instant carries the jumped state */
    double mag_err, dir_err, spin_abs, sin_psi_max;
    size_t njump, cap;
    double *jt, *jmag, *jdir;
} jump_probe;

static void jump_row(void *ctx, const sf_osc_row *row)
{
    jump_probe *j = ctx;
    double F = hypot(row->Fx, row->Fy);
    if (j->prev_stick && !row->stick) {   /* first slip row: at the release */
        j->minF_after_break = sf_min(j->minF_after_break, F);
        j->maxF_after_break = sf_max(j->maxF_after_break, F);
        j->breaks++;
        /* Eq. 14: relative velocity eps_lambda omega_n R [m/s] along
         * -(cos psi, sin psi), psi = atan2(F_sy, F_sx) of the stick wrench
         * F_s = (k x, k y) (Eq. 6) at the break; spin 0 */
        const sf_scene *s = j->s;
        double delta = check_jump_speed(s);
        double u = row->vx - s->v_b, v = row->vy, fx = s->k * j->prev_x, fy = s->k * j->prev_y;
        double mag = fabs(hypot(u, v) / delta - 1);
        /* angle between (u, v) and -(F_sx, F_sy): atan2(|cross|, -dot) */
        double dir = atan2(fabs(u * fy - v * fx), -(u * fx + v * fy));
        if (row->t != j->prev_t || row->x != j->prev_x || row->y != j->prev_y)
            mag = dir = NAN;   /* the release must keep t and the position */
        j->mag_err = sf_max(j->mag_err, mag);
        j->dir_err = sf_max(j->dir_err, dir);
        j->spin_abs = sf_max(j->spin_abs, fabs(row->w));
        j->sin_psi_max = sf_max(j->sin_psi_max, fabs(fy) / hypot(fx, fy));
        if (j->njump == j->cap) {
            j->cap = j->cap ? 2 * j->cap : 64;
            double **a[] = { &j->jt, &j->jmag, &j->jdir };
            for (int i = 0; i < 3; i++)
                if (!(*a[i] = realloc(*a[i], j->cap * sizeof(double))))
                    exit(SF_EXIT_INTERNAL);
        }
        j->jt[j->njump] = row->t;
        j->jmag[j->njump] = fmax(mag, 1e-17);   /* log axis */
        j->jdir[j->njump] = fmax(dir, 1e-17);
        j->njump++;
    }
    j->prev_stick = row->stick;
    j->prev_t = row->t;
    j->prev_x = row->x;
    j->prev_y = row->y;
    check_hist_row(&j->h, row);
}

static int chk_velocity_jump(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    sf_cof *cof = check_case_cof(c, s0, r);
    if (!cof)
        return SF_EFAIL;
    sf_scene on = *s0, off = *s0;
    on.velocity_jump = 1;
    off.velocity_jump = 0;
    jump_probe a = { .h = { .every = 1 }, .s = s0, .minF_after_break = INFINITY }, b = a;
    sf_osc_result ra, rb;
    if (check_osc_run(&on, NULL, cof, 1e-3, &ra, jump_row, &a, r) || check_osc_run(&off, NULL, cof, 1e-3, &rb, jump_row, &b, r)) {
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    double N = s0->m * s0->g, lo = s0->mu_k_ratio * (s0->mu_mean - 4 * s0->mu_std) * N;
    sf_check_ge(r, "with the jump: smallest |F| at a release [N] (>= mu_k at mean - 4 std, times N)", a.minF_after_break, lo);
    sf_check_le(r, "without the jump: largest |F| at a release [N] (zero relative velocity: no direction)", b.maxF_after_break, 1e-9);
    /* Eq. 14, exactly: |v_rel| = delta, along -F_s, spin 0 at every
     * release of the run with the jump.  Round-off: vx = v_b - delta cos psi
     * is rounded at the scale of v_b, so u = vx - v_b (exact by Sterbenz)
     * carries up to ulp(v_b) against a length delta; cos, sin, atan2 add a
     * few ulp: bound 8 DBL_EPSILON (1 + v_b / delta), relative / radians. */
    double delta = check_jump_speed(s0), rb14 = 8 * DBL_EPSILON * (1 + s0->v_b / delta);
    sf_check_le(r, "Eq. 14 at every release: max | |(vx - v_b, vy)| / (eps_lambda omega_n R) - 1 |", a.mag_err, rb14);
    sf_check_le(r, "Eq. 14 at every release: max angle between (vx - v_b, vy) and -(k x, k y) [rad]", a.dir_err, rb14);
    sf_check_le(r, "Eq. 14 at every release: max |omega| just after it [rad/s]", a.spin_abs, 0);
    sf_check_ge(r, "releases checked against Eq. 14", (double)a.njump, 5);
    sf_check_ge(r, "max |sin psi| at the releases (lateral part of Eq. 14 exercised: a sign flip errs by 2 psi)",
                a.sin_psi_max, 1e3 * rb14);
    double e15 = sf_osc_error_eq15(&rb, &ra);
    sf_note(r, "%zu releases with the jump, %zu without. With the jump the disc leaves stick at relative speed "
               "eps omega_n R = %.3g m/s along the stick force, so the kinetic friction acts at once (|F| from %.4g "
               "to %.4g N at the releases). Without it the friction vanishes at the release and the spring alone "
               "accelerates the disc until a slip direction builds up: the sudden drop of Fig. 6(b). The two "
               "histories differ by %.3e m^2 s (Eq. 15) over %g s; PV_x %.6f m (jump) vs %.6f m (no jump).",
            a.breaks, b.breaks, delta, a.minF_after_break,
            a.maxF_after_break, e15, s0->T, ra.pv_x, rb.pv_x);
    sf_plot *p = sf_result_plot(r, "fig6_force", "Friction force with and without the velocity jump (Fig. 6b)",
                                "t [s]", "Fx [N]");
    sf_plot_series(p, "with the jump (Eq. 14)", SF_STYLE_LINES, a.h.n, a.h.t, a.h.Fx);
    sf_plot_series(p, "without the jump", SF_STYLE_LINES, b.h.n, b.h.t, b.h.Fx);
    sf_plot *p2 = sf_result_plot(r, "fig6_x", "Displacement with and without the velocity jump (Fig. 6a)", "t [s]", "x [m]");
    sf_plot_series(p2, "with the jump (Eq. 14)", SF_STYLE_LINES, a.h.n, a.h.t, a.h.x);
    sf_plot_series(p2, "without the jump", SF_STYLE_LINES, b.h.n, b.h.t, b.h.x);
    sf_note(r, "\nEq. 14 at the %zu releases with the jump: relative speed eps_lambda omega_n R = %.6g m/s to "
               "%.2e (relative), direction within %.2e rad of -(k x, k y) (round-off bound %.2e: v_b / delta = %.0f "
               "amplifies the rounding of vx), spin exactly 0; the stick force pointed up to asin(%.3e) off the "
               "x axis, so the lateral component's sign is resolved %.0e times over.",
            a.njump, delta, a.mag_err, a.dir_err, rb14, s0->v_b / delta, a.sin_psi_max,
            a.sin_psi_max / (rb14 > 0 ? rb14 : 1));
    sf_plot *p3 = sf_result_plot(r, "eq14_jump", "Eq. 14 at every release: magnitude and direction of the jump",
                                 "t [s]", "error [-, rad]");
    sf_plot_log(p3, 0, 1);
    sf_plot_series(p3, "| |v_rel| / (eps omega_n R) - 1 | [-]", SF_STYLE_POINTS, a.njump, a.jt, a.jmag);
    sf_plot_series(p3, "angle(v_rel, -F_stick) [rad]", SF_STYLE_POINTS, a.njump, a.jt, a.jdir);
    sf_plot_hline(p3, "round-off bound", rb14);
    free(a.jt); free(a.jmag); free(a.jdir); free(b.jt); free(b.jmag); free(b.jdir);
    check_hist_free(&a.h);
    check_hist_free(&b.h);
    sf_osc_result_free(&ra);
    sf_osc_result_free(&rb);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Eqs. 9 and 12 at every slip-to-stick instant, from the emitted rows.
 * sf_osc_run emits, at a slip-to-stick instant t_r, the slip row of the
 * located event (the state before Eq. 12) and then a stick row at the same
 * t_r (after it).  The check recomputes Eq. 9's lambda from the first,
 * lambda = |((vx - v_b)/(omega_n R), vy/(omega_n R), w/omega_n)|, which
 * must equal eps_lambda to the event tolerance, and asks the second (and
 * every later stick row) to be (v_b, 0, 0) exactly (Eq. 12). */
typedef struct {
    const sf_scene *s;
    sf_osc_row prev;
    int have_prev;
    size_t n, cap, stick_rows, pre_vy, pre_w;
    double lam_err, spin_max, reset_dev;
    double *t, *lerr, *spin;
} eq912_probe;

static void eq912_row(void *ctx, const sf_osc_row *row)
{
    eq912_probe *e = ctx;
    const sf_scene *s = e->s;
    double wn = sqrt(s->k / s->m), vr = wn * s->R;
    if (row->stick) {   /* Eq. 12: (vx, vy, w) = (v_b, 0, 0), exactly, in Eq. 9's units */
        double d = sf_max(fabs(row->vx - s->v_b) / vr, sf_max(fabs(row->vy) / vr, fabs(row->w) / wn));
        e->reset_dev = sf_max(e->reset_dev, d);
        e->stick_rows++;
    }
    if (e->have_prev && !e->prev.stick && row->stick && row->t == e->prev.t) {   /* slip -> stick at t_r */
        const sf_osc_row *p = &e->prev;
        double xs = (p->vx - s->v_b) / vr, ys = p->vy / vr, ps = p->w / wn;   /* Eq. 9's starred rates */
        double lam = sqrt(xs * xs + ys * ys + ps * ps), err = fabs(lam / s->eps_lambda - 1), spin = fabs(ps) / lam;
        if (row->x != p->x || row->y != p->y)
            err = NAN;   /* Eq. 12 resets velocities only */
        e->lam_err = sf_max(e->lam_err, err);
        e->spin_max = sf_max(e->spin_max, spin);
        e->pre_vy += p->vy != 0;
        e->pre_w += p->w != 0;
        if (e->n == e->cap) {
            e->cap = e->cap ? 2 * e->cap : 64;
            double **a[] = { &e->t, &e->lerr, &e->spin };
            for (int i = 0; i < 3; i++)
                if (!(*a[i] = realloc(*a[i], e->cap * sizeof(double))))
                    exit(SF_EXIT_INTERNAL);
        }
        e->t[e->n] = row->t;
        e->lerr[e->n] = fmax(err, 1e-17);   /* log axis */
        e->spin[e->n] = spin;
        e->n++;
    }
    e->prev = *row;
    e->have_prev = 1;
}

static int chk_eq9_eq12(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cof *cof = check_case_cof(c, s, r);
    if (!cof)
        return SF_EFAIL;
    eq912_probe e = { .s = s };
    sf_osc_result res;
    if (check_osc_run(s, NULL, cof, 0, &res, eq912_row, &e, r)) {
        free(e.t); free(e.lerr); free(e.spin);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    sf_check_le(r, "Eq. 9: max |lambda / eps_lambda - 1| at the slip-to-stick instants (lambda from the rows)",
                e.lam_err, c->spec.tolerance);
    sf_check_ge(r, "slip-to-stick instants examined", (double)e.n, 5);
    sf_check_ge(r, "Eq. 9: largest spin share |omega/omega_n| / lambda at those instants (spin matters)", e.spin_max, 0.1);
    sf_check_le(r, "Eq. 12: max over stick rows of |(vx - v_b, vy)/(omega_n R)|, |omega/omega_n| (exactly 0)",
                e.reset_dev, 0);
    sf_check_ge(r, "Eq. 12 exercised: instants with vy != 0 and with omega != 0 just before the reset (fewest of the two)",
                (double)(e.pre_vy < e.pre_w ? e.pre_vy : e.pre_w), (double)e.n);
    double sm = 0;
    for (size_t i = 0; i < e.n; i++)
        sm += e.spin[i];
    sf_note(r, "%zu slip-to-stick instants over T = %g s (field l = %g m, R = %g m, CV %g); %zu stick rows. "
               "lambda recomputed by the check from the pre-reset row: worst |lambda/eps - 1| = %.2e; the spin "
               "share |omega/omega_n|/lambda at those instants averages %.3f (largest %.3f), so a spin term of "
               "lambda wrong by a factor 1.1 would move the located lambda by about 0.1 x share^2 (%.1e at the "
               "largest share). Eq. 12 left no trace: the largest stick-row deviation from (v_b, 0, 0) is %.3g.",
            e.n, s->T, s->l, s->R, s->mu_std / s->mu_mean, e.stick_rows, e.lam_err, e.n ? sm / (double)e.n : NAN,
            e.spin_max, 0.1 * e.spin_max * e.spin_max, e.reset_dev);
    sf_plot *p = sf_result_plot(r, "eq9_lambda", "Eq. 9 at each slip-to-stick instant", "t [s]", "[-]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "|lambda / eps_lambda - 1|", SF_STYLE_POINTS, e.n, e.t, e.lerr);
    sf_plot_series(p, "spin share |omega/omega_n| / lambda", SF_STYLE_POINTS, e.n, e.t, e.spin);
    sf_plot_hline(p, "tolerance", c->spec.tolerance);
    free(e.t); free(e.lerr); free(e.spin);
    sf_osc_result_free(&res);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Long runs stay bounded: no NaN, |x| and |y| within the spring-excursion
 * bound 2 mu_hi m g / k, the energy balance holds, the disc stays on the
 * strip, stick-slip persists. */
static int chk_long_run(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    gsl_rng *rng = sf_case_rng(c);
    sf_osc_result res;
    check_hist h = { .every = 50 };
    int rc = check_osc_run(s, rng, NULL, 0, &res, check_hist_row, &h, r);
    gsl_rng_free(rng);
    if (rc)
        return SF_EFAIL;
    double bound = 2 * (s->mu_mean + 4 * s->mu_std) * s->m * s->g / s->k;
    sf_check_le(r, "max |x| [m] (bound 2 mu_hi m g / k)", sf_max(fabs(res.x_min), fabs(res.x_max)), bound);
    sf_check_le(r, "max |y| [m] (same bound)", res.y_absmax, bound);
    sf_check_le(r, "energy residual / energy turned over", fabs(res.energy_residual) /
                (fabs(res.friction_work) + fabs(res.energy_change)), c->spec.tolerance);
    sf_check_ge(r, "complete cycles after t_skip", (double)res.ncycles, 0.8 * (s->T - s->t_skip) / 4.4);
    sf_note(r, "T = %g s: %zu cycles, %zu transitions, %lu steps, %lu wrench evaluations; x in [%.4f, %.4f] m, "
               "max |y| %.3e m. Non-finite states stop the run with an error (none).",
            s->T, res.ncycles, res.ntrans, res.steps, res.wrench_evals, res.x_min, res.x_max, res.y_absmax);
    sf_plot *p = sf_result_plot(r, "long_run", "Long run: displacement", "t [s]", "x [m]");
    sf_plot_series(p, "x(t) (every 50th row)", SF_STYLE_LINES, h.n, h.t, h.x);
    sf_plot_hline(p, "bound 2 mu_hi m g / k", bound);
    check_hist_free(&h);
    sf_osc_result_free(&res);
    return SF_SUCCESS;
}

/* Figs. 9 and 14: deterministic and stochastic baseline responses and
 * phase portraits.  What must hold: stick rows move exactly with the belt
 * (vx = v_b); the deterministic response is a limit cycle (per-cycle PV_x
 * identical to the solver's tolerance); the stochastic one keeps
 * stick-slip and its cycles vary (randomness in time, Sec. 2.3.2). */
static int chk_baseline(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_scene sd = *s;
    sd.cof = SF_COF_UNIFORM;
    gsl_rng *rng = sf_case_rng(c);
    sf_osc_result rd, rs;
    check_hist hd = { .every = 1 }, hs = { .every = 1 };
    if (check_osc_run(&sd, NULL, NULL, 0, &rd, check_hist_row, &hd, r) ||
        check_osc_run(s, rng, NULL, 0, &rs, check_hist_row, &hs, r)) {
        gsl_rng_free(rng);
        return SF_EFAIL;
    }
    gsl_rng_free(rng);
    double vb_err = 0;
    for (size_t i = 0; i < hs.n; i++)
        if (hs.stick[i])
            vb_err = sf_max(vb_err, fabs(hs.vx[i] - s->v_b));
    for (size_t i = 0; i < hd.n; i++)
        if (hd.stick[i])
            vb_err = sf_max(vb_err, fabs(hd.vx[i] - s->v_b));
    double sd_det = gsl_stats_sd(rd.cycle_pv_x, 1, rd.ncycles), sd_sto = gsl_stats_sd(rs.cycle_pv_x, 1, rs.ncycles);
    sf_check_le(r, "stick rows: max |vx - v_b| [m/s]", vb_err, 0);
    sf_check_le(r, "deterministic: std of per-cycle PV_x [m] (a limit cycle)", sd_det, c->spec.tolerance);
    sf_check_ge(r, "stochastic: complete cycles after t_skip (stick-slip persists)", (double)rs.ncycles, 10);
    sf_check_ge(r, "stochastic: std of per-cycle PV_x [m] (cycles vary in time)", sd_sto, 100 * c->spec.tolerance);
    sf_note(r, "Deterministic (uniform COF %.2f): PV_x %.6f m, PV_F %.4f N, stick fraction %.4f over %zu cycles. "
               "Stochastic (one lognormal field, l = %g m, CV %.2g): PV_x %.4f +- %.4f m, PV_F %.4f +- %.4f N, "
               "stick fraction %.4f over %zu cycles; ratios PV_x %.4f, PV_F %.4f, stick fraction %.4f. The paper "
               "(Fig. 9) shows the same picture: a periodic deterministic cycle and a stochastic response whose "
               "cycles differ from one another.",
            s->mu_mean, rd.pv_x, rd.pv_F, rd.stick_fraction, rd.ncycles, s->l, s->mu_std / s->mu_mean, rs.pv_x,
            sd_sto, rs.pv_F, gsl_stats_sd(rs.cycle_pv_F, 1, rs.ncycles), rs.stick_fraction, rs.ncycles,
            rs.pv_x / rd.pv_x, rs.pv_F / rd.pv_F, rs.stick_fraction / rd.stick_fraction);
    sf_plot *p = sf_result_plot(r, "fig9_x", "Baseline responses: displacement (Fig. 9)", "t [s]", "x [m]");
    sf_plot_series(p, "deterministic", SF_STYLE_LINES, hd.n, hd.t, hd.x);
    sf_plot_series(p, "stochastic", SF_STYLE_LINES, hs.n, hs.t, hs.x);
    sf_plot *p2 = sf_result_plot(r, "fig9_F", "Baseline responses: friction force (Fig. 9)", "t [s]", "Fx [N]");
    sf_plot_series(p2, "deterministic", SF_STYLE_LINES, hd.n, hd.t, hd.Fx);
    sf_plot_series(p2, "stochastic", SF_STYLE_LINES, hs.n, hs.t, hs.Fx);
    /* phase portraits after the transient */
    size_t i0 = 0, j0 = 0;
    while (i0 < hd.n && hd.t[i0] < s->t_skip) i0++;
    while (j0 < hs.n && hs.t[j0] < s->t_skip) j0++;
    sf_plot *p3 = sf_result_plot(r, "fig14_phase", "Phase portraits after the transient (Fig. 14)", "x [m]", "vx [m/s]");
    sf_plot_series(p3, "deterministic", SF_STYLE_LINES, hd.n - i0, hd.x + i0, hd.vx + i0);
    sf_plot_series(p3, "stochastic", SF_STYLE_LINES, hs.n - j0, hs.x + j0, hs.vx + j0);
    check_hist_free(&hd);
    check_hist_free(&hs);
    sf_osc_result_free(&rd);
    sf_osc_result_free(&rs);
    return SF_SUCCESS;
}

/* The exact T = 0 section breaks stick no later than the equatorial
 * circle: at every release of the exact-section run, the circle's margin
 * mu_bar m g - k |r| is still >= 0 (cases/surface/section-vs-circle proves
 * rho <= mu_bar); the size of the difference is reported. */
static int chk_exact_section(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    sf_cof *cof = check_case_cof(c, s0, r);
    if (!cof)
        return SF_EFAIL;
    sf_scene se = *s0, sc = *s0;
    se.exact_section = 1;
    sc.exact_section = 0;
    check_hist h = { .every = 1 };
    sf_osc_result re, rc;
    if (check_osc_run(&se, NULL, cof, 0, &re, check_hist_row, &h, r) || check_osc_run(&sc, NULL, cof, 0, &rc, NULL, NULL, r)) {
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    sf_contact_spec spec = { s0->R, s0->m * s0->g, (sf_layout)s0->layout, s0->cells };
    sf_contact *ct;
    sf_contact_alloc(&spec, cof, &ct);
    double worst = INFINITY, sum = 0, on_section = 0, M = sf_cof_window_margin(cof);
    size_t n = 0, earlier = 0;
    unsigned long out0 = sf_cof_outside(cof);
    int follow_rc = 0;
    for (size_t i = 1; i < h.n; i++)
        if (h.stick[i - 1] && !h.stick[i] && h.t[i] == h.t[i - 1]) {   /* the release row pair */
            double m, me;
            double xb = h.x[i - 1] - s0->v_b * h.t[i - 1], fx = s0->k * h.x[i - 1], fy = s0->k * h.y[i - 1];
            /* a tiled COF holds a window of the belt, left where the last
             * run ended: bring the release's patch into it, as the
             * oscillator does before each step (a look-up outside is
             * clamped to the window's edge, counted below) */
            follow_rc |= sf_cof_follow(cof, xb - s0->R - M, xb + s0->R + M);
            sf_contact_stick_margin(ct, xb, h.y[i - 1], fx, fy, 0, &m);
            if (sf_contact_stick_margin(ct, xb, h.y[i - 1], fx, fy, 1, &me))
                me = NAN;
            worst = sf_min(worst, m);
            on_section = sf_max(on_section, fabs(me));
            earlier += m > c->spec.tolerance;
            sum += m;
            n++;
        }
    sf_check_ge(r, "min circle margin at the exact-section releases [N] (>= 0 up to event tolerance)", worst,
                -c->spec.tolerance);
    sf_check_le(r, "COF look-ups of the margins off the grid (clamped to its edge) or a window that would not follow",
                (double)(sf_cof_outside(cof) - out0) + (follow_rc ? 1 : 0), 0);
    sf_check_ge(r, "releases examined", (double)n, 10);
    /* The exact section was used: the break is ON it (consistency: the
     * solver's own section, not an independent oracle) and strictly inside
     * the circle at every release (a run that ignored exact_section would
     * break on the circle: margin 0 to the event tolerance). */
    sf_check_le(r, "max |exact-section margin| at the releases [N] (the break is on the T = 0 section)", on_section,
                c->spec.tolerance);
    sf_check_ge(r, "releases strictly before the circle's (circle margin > tolerance) (all of them)", (double)earlier,
                (double)n);
    sf_note(r, "%zu releases: the circle would still have held stick by %.3e N on average (worst %.3e N): the "
               "exact criterion releases earlier. Effect on the QoIs (same field): PV_x %.6f (exact) vs %.6f m "
               "(circle), PV_F %.5f vs %.5f N, stick fraction %.5f vs %.5f.",
            n, n ? sum / (double)n : NAN, worst, re.pv_x, rc.pv_x, re.pv_F, rc.pv_F, re.stick_fraction,
            rc.stick_fraction);
    sf_plot *p = sf_result_plot(r, "exact_vs_circle", "Stick force at the releases", "t [s]", "circle margin [N]");
    double *tt = check_alloc((n + 1) * sizeof *tt), *mm = check_alloc((n + 1) * sizeof *mm);
    size_t k = 0;
    for (size_t i = 1; i < h.n; i++)
        if (h.stick[i - 1] && !h.stick[i] && h.t[i] == h.t[i - 1]) {
            sf_contact_stick_margin(ct, h.x[i - 1] - s0->v_b * h.t[i - 1], h.y[i - 1], s0->k * h.x[i - 1],
                                    s0->k * h.y[i - 1], 0, &mm[k]);
            tt[k++] = h.t[i];
        }
    sf_plot_series(p, "mu_bar m g - k |r| at each exact-section release", SF_STYLE_POINTS, k, tt, mm);
    sf_plot_hline(p, "zero (the circle's own release)", 0);
    free(tt); free(mm);
    sf_contact_free(ct);
    check_hist_free(&h);
    sf_osc_result_free(&re);
    sf_osc_result_free(&rc);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* Farkas et al. (PRL 2003): a free uniform disc (J = m R^2/2) sliding and
 * spinning on a plane of uniform COF stops sliding and spinning at the same
 * instant, and its ratio eps = U/(|w| R) tends to eps_0 solving
 * f(eps_0) = 2 eps_0 t(eps_0) whatever the start.  With U' = -mu_k g f,
 * w' = -2 mu_k g t / R: d eps/dt = -(mu_k g/(w R)) (f - 2 eps t), an
 * attracting zero since f - 2 eps t < 0 below eps_0 (f ~ eps, 2 eps t ~
 * 4 eps/3) and > 0 above (f -> 1, 2 eps t -> 1/2).  The solver's slip
 * right-hand side (sf_osc_slip_rhs: Eq. 5's M and the closed-form
 * Contensou wrench of Eqs. 7-8 the 3-DOF model uses for a uniform COF) is
 * integrated here from (U0, 0, w0) with the springs idle (position held at
 * the origin, so -k x = 0) on a belt at rest (v_b = 0: the relative
 * velocity is the ground one, no cancellation as it falls to 1e-15 of U0).
 * Oracle: eps_0 from ref_contensou and GSL Brent (no solver code), and the
 * published 0.653. */
typedef struct { sf_osc *o; } free_disc;

static int free_disc_rhs(double t, const double *z, double *dz, void *p)
{
    const free_disc *fd = p;
    double y[SF_OSC_NSTATE] = { 0 }, f[SF_OSC_NSTATE];
    y[SF_OSC_VX] = z[0];
    y[SF_OSC_VY] = z[1];
    y[SF_OSC_W] = z[2];
    sf_osc_slip_rhs(fd->o, t, y, f, NULL);
    dz[0] = f[SF_OSC_VX];
    dz[1] = f[SF_OSC_VY];
    dz[2] = f[SF_OSC_W];
    return GSL_SUCCESS;
}

static double farkas_gap(double e, void *p)
{
    (void)p;
    double f, t;
    ref_contensou(e, &f, &t);
    return f - 2 * e * t;
}

/* Integrate the free disc from eps_start until |(U, w R)| falls to `stop` of
 * its start; the ratio's history goes into (lam, eps) (n points, cap). */
static double free_disc_run(sf_osc *o, const sf_scene *s, double eps_start, double stop, size_t cap, double *lam,
                            double *eps, size_t *n, double *t_end, double *reached)
{
    free_disc fd = { o };
    gsl_odeiv2_system sys = { free_disc_rhs, NULL, 3, &fd };
    gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 3);
    gsl_odeiv2_control *con = gsl_odeiv2_control_y_new(0, s->rtol);   /* relative only: the state falls by 1e15 */
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(3);
    double w0 = 1.0, U0 = eps_start * w0 * s->R, z[3] = { U0, 0, w0 }, t = 0, h = 1e-6, l0 = hypot(U0, w0 * s->R);
    double muk = s->mu_k_ratio * s->mu_mean, g = s->g;
    *n = 0;
    for (int it = 0; it < 100000; it++) {
        double U = hypot(z[0], z[1]), l = hypot(U, z[2] * s->R);
        if (*n < cap) {
            lam[*n] = l / l0;
            eps[*n] = U / (fabs(z[2]) * s->R);
            (*n)++;
        }
        if (!(l > stop * l0) || !(U > 0) || !(z[2] > 0))
            break;
        /* a step never reaches the common stop (the direction field is
         * singular there): at most a tenth of the time left */
        double left = fmin(U / (muk * g), fabs(z[2]) * s->R / (2 * muk * g * 2.0 / 3.0 + 1e-300));
        /* the system is autonomous: restart the clock every step, or t
         * (0.1 s) would stop resolving steps of 1e-17 s near the stop */
        double tl = 0;
        h = fmin(h, 0.1 * left);
        if (gsl_odeiv2_evolve_apply(ev, con, st, &sys, &tl, 0.1 * left, &h, z) != GSL_SUCCESS)
            break;
        t += tl;
    }
    *t_end = t;
    *reached = hypot(hypot(z[0], z[1]), z[2] * s->R) / l0;
    gsl_odeiv2_evolve_free(ev);
    gsl_odeiv2_control_free(con);
    gsl_odeiv2_step_free(st);
    return hypot(z[0], z[1]) / (fabs(z[2]) * s->R);
}

static int chk_free_disc(const sf_case *c, sf_result *r)
{
    sf_scene s = c->scene;
    if (s.cof != SF_COF_UNIFORM || s.dof != SF_DOF_3)
        return SF_EINVAL;
    s.v_b = 0;   /* a plane at rest (sf_osc_alloc takes any v_b; the belt point is irrelevant for a uniform COF) */
    sf_cof *cof;
    if (sf_cof_alloc_uniform(s.mu_mean, &cof))
        return SF_ENOMEM;
    char err[128];
    sf_osc *o;
    if (sf_osc_alloc(&s, cof, &o, err, sizeof err)) {
        sf_note(r, "**Cannot plan the run:** %s", err);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    /* the oracle: f(eps) = 2 eps t(eps) on (0.1, 0.99) (gap -0.03 and +0.1 at the ends) */
    gsl_function F = { farkas_gap, NULL };
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double e0 = NAN;
    if (rs && gsl_root_fsolver_set(rs, &F, 0.1, 0.99) == GSL_SUCCESS)
        for (int it = 0; it < 100; it++) {
            gsl_root_fsolver_iterate(rs);
            e0 = gsl_root_fsolver_root(rs);
            if (gsl_root_test_interval(gsl_root_fsolver_x_lower(rs), gsl_root_fsolver_x_upper(rs), 1e-15, 0) == GSL_SUCCESS)
                break;
        }
    if (rs)
        gsl_root_fsolver_free(rs);
    enum { NS = 2, CAP = 4096 };
    const double starts[NS] = { 0.2, 5.0 }, stop = 1e-15;
    double *lam[NS], *eps[NS], fin[NS], tend[NS], worst = 0, reached = 0;
    size_t n[NS];
    for (int k = 0; k < NS; k++) {
        lam[k] = check_alloc(CAP * sizeof(double));
        eps[k] = check_alloc(CAP * sizeof(double));
        double got;
        fin[k] = free_disc_run(o, &s, starts[k], stop, CAP, lam[k], eps[k], &n[k], &tend[k], &got);
        worst = sf_max(worst, fabs(fin[k] - e0));
        reached = sf_max(reached, got);
    }
    sf_check_abs(r, "oracle eps_0 (own closed form, Brent) vs the published 0.653 (Farkas et al. 2003)", e0, 0.653, 5e-4);
    sf_check_le(r, "max over both starts of |eps at the stop - eps_0| (3-DOF slip RHS, uniform COF)", worst, c->spec.tolerance);
    sf_check_le(r, "|(U, w R)| at the stop / at the start (both starts ran to the stop)", reached, stop);
    sf_note(r, "Free disc, uniform COF mu_k = %g (mu_s %g x %g), R = %g m, m = %g kg (J = m R^2/2 in the solver); "
               "starts at eps = %g and %g with spin 1 rad/s, integrated (GSL rk8pd, relative error %g) until "
               "|(U, w R)| fell to %g of its start: eps = %.12f and %.12f at t = %.4f and %.4f s, against the "
               "oracle eps_0 = %.12f (f(eps_0) = 2 eps_0 t(eps_0), closed form of docs/design.md sec. 4.5 evaluated "
               "by the check). Near the stop eps - eps_0 falls like w^(G'(eps_0)/(2 t(eps_0))) = w^0.615 (G = "
               "f - 2 eps t), so a start 0.45 or 4.3 off is about 1e-9 off after the speed has fallen by 1e15.",
            s.mu_k_ratio * s.mu_mean, s.mu_mean, s.mu_k_ratio, s.R, s.m, starts[0], starts[1], s.rtol, stop, fin[0],
            fin[1], tend[0], tend[1], e0);
    sf_plot *p = sf_result_plot(r, "farkas", "Free disc: the slide/spin ratio as both stop (Farkas et al. 2003)",
                                "|(U, w R)| / start [-]", "eps = U / (|w| R) [-]");
    sf_plot_log(p, 1, 0);
    char lab[64];
    for (int k = 0; k < NS; k++) {
        snprintf(lab, sizeof lab, "start eps = %g", starts[k]);
        sf_plot_series(p, lab, SF_STYLE_LINES, n[k], lam[k], eps[k]);
        free(lam[k]);
        free(eps[k]);
    }
    sf_plot_hline(p, "eps_0 (closed form)", e0);
    sf_osc_free(o);
    sf_cof_free(cof);
    return SF_SUCCESS;
}

/* One random variable (the large-l limit, docs/design.md sec. 4.8): every QoI of
 * the 3-DOF run is the 1-D closed-form cycle at the drawn mu_s. */
static int chk_variable_limit(const sf_case *c, sf_result *r)
{
    const sf_scene *s0 = &c->scene;
    gsl_rng *rng = sf_case_rng(c);
    size_t K = s0->samples;
    double worst = 0, *mu = check_alloc(K * sizeof *mu), *pv = check_alloc(K * sizeof *pv), *pvc = check_alloc(K * sizeof *pvc);
    for (size_t k = 0; k < K; k++) {
        char err[128];
        sf_cof_plan *p;
        sf_cof *cof;
        sf_cof_plan_alloc(s0, &p, err, sizeof err);
        sf_cof_plan_draw(p, rng, &cof);
        sf_cof_plan_free(p);
        sf_scene s = *s0;
        s.mu_mean = sf_cof_eval(cof, 0, 0);
        sf_cycle1d cf;
        sf_osc_result res;
        if (sf_cycle1d_init(&cf, &s, s.eps_lambda) || check_osc_run(s0, NULL, cof, 0, &res, NULL, NULL, r)) {
            sf_cof_free(cof);
            gsl_rng_free(rng);
            return SF_EFAIL;
        }
        double d = sf_max(sf_max(fabs(res.pv_x / cf.pv_x - 1), fabs(res.pv_F / cf.pv_F - 1)),
                        fabs(res.cyc_stick_fraction / cf.stick_fraction - 1));   /* the closed form's is per cycle */
        worst = sf_max(worst, d);
        mu[k] = s.mu_mean;
        pv[k] = res.pv_F;
        pvc[k] = cf.pv_F;
        sf_osc_result_free(&res);
        sf_cof_free(cof);
    }
    gsl_rng_free(rng);
    sf_check_le(r, "max relative gap to the 1-D closed form at the drawn mu_s (PV_x, PV_F, stick fraction)", worst,
                c->spec.tolerance);
    sf_note(r, "%zu realisations of cof = variable (mean %g, std %g). PV_F = 2 (1 - mu_k/mu_s) mu_s m g is linear "
               "in mu_s: over realisations the ratio PV_F / PV_F,det = mu_s / mean exactly, a lognormal with the "
               "field's CV (the large-l/R limit, docs/design.md sec. 4.8).", K, s0->mu_mean, s0->mu_std);
    sf_plot *p = sf_result_plot(r, "variable_limit", "One random variable: PV_F vs the drawn COF", "mu_s [-]", "PV_F [N]");
    sf_plot_series(p, "3-DOF runs", SF_STYLE_POINTS, K, mu, pv);
    sf_plot_series(p, "closed form 2 (1 - mu_k/mu_s) mu_s m g", SF_STYLE_LINES, K, mu, pvc);
    free(mu); free(pv); free(pvc);
    return SF_SUCCESS;
}

/* The same seed gives the same bytes; another seed another field. */
static int chk_reproducible(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_osc_result a, b, d;
    gsl_rng *r1 = sf_case_rng(c), *r2 = sf_case_rng(c), *r3 = sf_case_rng(c);
    gsl_rng_set(r3, s->seed + 1);
    int rc = check_osc_run(s, r1, NULL, 1e-2, &a, NULL, NULL, r) || check_osc_run(s, r2, NULL, 1e-2, &b, NULL, NULL, r) ||
             check_osc_run(s, r3, NULL, 1e-2, &d, NULL, NULL, r);
    gsl_rng_free(r1); gsl_rng_free(r2); gsl_rng_free(r3);
    if (rc)
        return SF_EFAIL;
    int same = a.nsamples == b.nsamples && !memcmp(a.x_samples, b.x_samples, a.nsamples * sizeof(double)) &&
               a.ntrans == b.ntrans && !memcmp(a.trans_t, b.trans_t, a.ntrans * sizeof(double));
    int differ = a.nsamples != d.nsamples || memcmp(a.x_samples, d.x_samples, a.nsamples * sizeof(double));
    sf_check_true(r, "same seed: identical x samples and transition times (bytes)", same, same ? "identical" : "differ");
    sf_check_true(r, "other seed: a different history", differ, differ ? "different" : "identical");
    /* the evidence: the two same-seed runs overlaid, the other seed beside
       them, and both differences from run 1 (the same-seed one is 0) */
    size_t n = a.nsamples < b.nsamples ? a.nsamples : b.nsamples;
    n = n < d.nsamples ? n : d.nsamples;
    double *t = check_alloc(3 * (n ? n : 1) * sizeof *t), *db = t + n, *dd = t + 2 * n;
    for (size_t i = 0; i < n; i++) {
        t[i] = (double)i * a.sample_dt;
        db[i] = b.x_samples[i] - a.x_samples[i];
        dd[i] = d.x_samples[i] - a.x_samples[i];
    }
    sf_plot *pl = sf_result_plot(r, "reproducible_runs", "Displacement of two runs with the same seed, and another seed",
                                 "time t [s]", "x [m]");
    sf_plot_series(pl, "run 1 (seed)", SF_STYLE_LINES, n, t, a.x_samples);
    sf_plot_series(pl, "run 2 (same seed)", SF_STYLE_POINTS, n, t, b.x_samples);
    sf_plot_series(pl, "other seed", SF_STYLE_LINES, n, t, d.x_samples);
    pl = sf_result_plot(r, "reproducible_difference", "Difference from run 1", "time t [s]", "x - x_run1 [m]");
    sf_plot_series(pl, "run 2 (same seed): must be 0", SF_STYLE_LINES, n, t, db);
    sf_plot_series(pl, "other seed", SF_STYLE_LINES, n, t, dd);
    free(t);
    sf_osc_result_free(&a); sf_osc_result_free(&b); sf_osc_result_free(&d);
    return SF_SUCCESS;
}

/* PV_F is the peak-to-valley of the continuous friction force (Sec. 3.1).
 * On a belt so fast that the disc slips nearly all the time, the force's
 * extrema lie inside slip steps, where the step ends alone miss them by
 * ~|F''| h^2 / 8;
 * each oscillation's PV_F at the scene's rtol must stay within
 * `tolerance` (relative) of the same field at rtol 1e-11. */
static int chk_force_extrema(const sf_case *c, sf_result *r)
{
    const sf_scene *s = &c->scene;
    sf_cof *cof = check_case_cof(c, s, r);
    if (!cof)
        return SF_EFAIL;
    sf_scene ref = *s;
    ref.rtol = 1e-11;
    sf_osc_result a, b;
    if (check_osc_run(s, NULL, cof, 0, &a, NULL, NULL, r)) {
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    if (check_osc_run(&ref, NULL, cof, 0, &b, NULL, NULL, r)) {
        sf_osc_result_free(&a);
        sf_cof_free(cof);
        return SF_EFAIL;
    }
    sf_cof_free(cof);
    char found[96];
    snprintf(found, sizeof found, "%zu and %zu oscillations", a.nosc, b.nosc);
    sf_check_true(r, "the same oscillations in both runs, at least 3", a.nosc == b.nosc && a.nosc >= 3, found);
    size_t n = a.nosc < b.nosc ? a.nosc : b.nosc;
    double worst = 0, *k = malloc((n ? n : 1) * sizeof *k), *d = malloc((n ? n : 1) * sizeof *d);
    if (!k || !d) {
        free(k);
        free(d);
        sf_osc_result_free(&a);
        sf_osc_result_free(&b);
        return SF_ENOMEM;
    }
    for (size_t i = 0; i < n; i++) {
        k[i] = (double)i;
        d[i] = fabs(a.osc_pv_F[i] / b.osc_pv_F[i] - 1);
        worst = fmax(worst, d[i]);
        d[i] = fmax(d[i], DBL_EPSILON);   /* the plot's log axis: equal values at one ulp */
    }
    char q[SF_LABEL_LEN];
    snprintf(q, sizeof q, "largest relative difference of an oscillation's PV_F, rtol %g against 1e-11", s->rtol);
    sf_check_le(r, q, worst, c->spec.tolerance);
    sf_check_rel(r, "PV_F [N], mean over the oscillations", a.pv_F, b.pv_F, c->spec.tolerance);
    sf_note(r, "rtol %g: %lu steps, %lu trial steps of event searches (x and force extrema), %zu transitions; rtol "
               "1e-11: %lu steps, %zu transitions.", s->rtol, a.steps, a.event_trials, a.ntrans, b.steps, b.ntrans);
    sf_plot *p = sf_result_plot(r, "force_extrema", "Each oscillation's PV_F: rtol against 1e-11",
                                "oscillation index [-]", "|PV_F / PV_F(1e-11) - 1| [-]");
    sf_plot_log(p, 0, 1);
    sf_plot_series(p, "relative difference", SF_STYLE_POINTS, n, k, d);
    sf_plot_hline(p, "tolerance", c->spec.tolerance);
    free(k);
    free(d);
    sf_osc_result_free(&a);
    sf_osc_result_free(&b);
    return SF_SUCCESS;
}

const sf_check_def sf_checks_dynamics[] = {
    { "dyn_eps_study", chk_eps_study, "Fig. 7: Eq. 15 error vs eps_lambda against eps = 1e-5" },
    { "dyn_velocity_jump", chk_velocity_jump, "Fig. 6: what the velocity jump of Eq. 14 prevents" },
    { "dyn_eq9_eq12", chk_eq9_eq12, "Eq. 9 lambda = eps_lambda at every slip-to-stick instant (with spin); Eq. 12 resets exactly" },
    { "dyn_long_run", chk_long_run, "long runs bounded, no NaN, energy balance" },
    { "dyn_baseline", chk_baseline, "Figs. 9 and 14: baseline responses and phase portraits" },
    { "dyn_exact_section", chk_exact_section, "exact T = 0 section releases no later than the circle" },
    { "dyn_free_disc", chk_free_disc, "free uniform disc: slide/spin ratio -> Farkas eps_0 = 0.653 (closed-form 3-DOF wrench)" },
    { "dyn_variable_limit", chk_variable_limit, "one random variable: the 1-D closed form at the drawn COF" },
    { "dyn_reproducible", chk_reproducible, "same seed, same bytes" },
    { "dyn_force_extrema", chk_force_extrema, "PV_F of the continuous force: extrema inside slip steps, rtol against 1e-11" },
    { NULL, NULL, NULL }
};
