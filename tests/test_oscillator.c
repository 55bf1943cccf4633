/* Unit tests: 1-D closed forms and the oscillator's edge cases. */
#include "test_util.h"
#include "cycle1d.h"
#include "qoi.h"
#include "oscillator.h"
#include "cof.h"
#include "scene.h"
#include "sf_error.h"

#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>

static void closed_form_table1(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    sf_cycle1d c;
    assert_int_equal(sf_cycle1d_init(&c, &s, 0), SF_SUCCESS);
    /* docs/design.md sec. 4.7: the Table 1 numbers */
    assert_close(c.pv_x, 0.400328, 1e-6);
    assert_close(c.pv_F, 9.81, 1e-12);
    assert_close(c.t_stick, 1.635, 1e-12);
    assert_close(c.t_slip, 2.523826, 1e-6);
    assert_close(c.stick_fraction, 0.393140, 1e-6);
    /* transitions alternate, one period apart */
    assert_close(sf_cycle1d_transition(&c, 3) - sf_cycle1d_transition(&c, 1), c.period, 1e-12);
    assert_close(sf_cycle1d_transition(&c, 2) - sf_cycle1d_transition(&c, 1), c.t_slip, 1e-12);
    /* no cycle: the belt is faster than the first slip can reach */
    s.v_b = 10;
    assert_int_equal(sf_cycle1d_init(&c, &s, 0), SF_EINVAL);
}

/* Table 1 as the 1-D model with a uniform COF at this rtol. */
static void scene_1d(sf_scene *s, double rtol)
{
    sf_scene_default(s);
    s->cof = SF_COF_UNIFORM;
    s->dof = SF_DOF_1;
    s->rtol = rtol;
}

static int run(sf_scene *s, sf_osc_result *r, char *err)
{
    sf_cof *cof;
    sf_cof_alloc_uniform(s->mu_mean, &cof);
    sf_osc *o;
    int rc = sf_osc_alloc(s, cof, &o, err, 200);
    if (!rc)
        rc = sf_osc_run(o, NULL, NULL, 0.01, r, err, 200);
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc;
}

/* The step budget (max_steps): a cell of COF 30 on a field of 0.3 under
 * the disc's centre of rotation holds it (a sliding mode of the point
 * quadrature: steps of ~3e-9 s), and the budget stops the run there and
 * names the cell; a stop where no cell holds it says so; a closed-form
 * wrench has no cell. */
static int budget_run(double mu_spike, size_t max_steps, int shortcut, sf_osc_result *r, char *err, size_t errlen)
{
    sf_scene s;
    sf_scene_default(&s);
    s.cells = 8;
    s.rtol = 1e-10;
    s.T = 1;
    s.t_skip = 0;
    s.cof_model = SF_COFMODEL_POINT;
    s.max_steps = max_steps;
    /* polar cell 152 of 8 rings is at (rx, ry) from the centre: start with
     * the centre of rotation on it, (u, v) = w (ry, -rx) */
    const double rx = -0.03065, ry = -0.44812, w = 1;
    s.w0 = w;
    s.vx0 = s.v_b + w * ry;
    s.vy0 = -w * rx;
    enum { M = 321, N = 81 };
    double *g = malloc(M * N * sizeof *g);
    assert_non_null(g);
    for (size_t j = 0; j < N; j++)
        for (size_t i = 0; i < M; i++) {
            double x = -4 + 0.025 * (double)i, y = -1 + 0.025 * (double)j;
            g[i + M * j] = fabs(x - rx) < 0.06 && fabs(y - ry) < 0.03 ? mu_spike : 0.3;
        }
    sf_cof *cof;
    if (shortcut) {
        s.cof = SF_COF_UNIFORM;
        assert_int_equal(sf_cof_alloc_uniform(0.3, &cof), SF_SUCCESS);
    } else
        assert_int_equal(sf_cof_alloc_grid(M, N, -4, -1, 0.025, 0.025, g, &cof), SF_SUCCESS);
    free(g);
    sf_osc *o;
    assert_int_equal(sf_osc_alloc(&s, cof, &o, err, errlen), SF_SUCCESS);
    int rc = sf_osc_run(o, NULL, NULL, 0, r, err, errlen);
    sf_osc_free(o);
    sf_cof_free(cof);
    return rc;
}

static void step_budget(void **state)
{
    (void)state;
    char err[300];
    sf_osc_result r;
    assert_int_equal(budget_run(30, 2000, 0, &r, err, sizeof err), SF_EMAXITER);
    assert_int_equal(r.held_cell, 152);
    assert_true(r.held_slip < SF_OSC_HELD_SLIP);
    assert_int_equal(r.steps, 2001);
    assert_non_null(strstr(err, "max_steps = 2000"));
    assert_non_null(strstr(err, "holds the centre of rotation"));
    assert_true(fabs(r.energy_residual) < 1e-9);   /* the run up to its stop is kept, balanced */
    sf_osc_result_free(&r);
    /* no spike: the disc slides on to stick (54 steps); a budget of 10 stops it
     * where no cell holds the centre of rotation */
    assert_int_equal(budget_run(0.3, 2000, 0, &r, err, sizeof err), SF_SUCCESS);
    assert_int_equal(r.held_cell, -1);
    sf_osc_result_free(&r);
    assert_int_equal(budget_run(0.3, 10, 0, &r, err, sizeof err), SF_EMAXITER);
    assert_true(r.held_cell >= 0 && r.held_slip > 1e-3);
    assert_null(strstr(err, "holds"));
    sf_osc_result_free(&r);
    /* a closed-form wrench: no cell to name */
    assert_int_equal(budget_run(0.3, 3, 1, &r, err, sizeof err), SF_EMAXITER);
    assert_int_equal(r.held_cell, -1);
    assert_true(isnan(r.held_slip));
    assert_null(strstr(err, "cell"));
    sf_osc_result_free(&r);
}

/* Both QoI definitions: a disc sliding on (v_b above x_e omega) has no
 * stick cycle, so the per-cycle values are NaN, but the paper's are
 * finite (PV per oscillation, T_sk = 0), and qoi_def picks which the
 * headline fields carry; on the Table 1 cycle the stick time in the
 * window is the closed form's, and PVs agree between the definitions. */
static void qoi_definitions(void **state)
{
    (void)state;
    sf_scene s;
    scene_1d(&s, 1e-10);
    s.T = 40;
    s.v_b = 3;
    sf_osc_result r;
    char err[200];
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_int_equal(r.ncycles, 0);
    assert_true(isnan(r.cyc_pv_x) && isnan(r.cyc_stick_fraction));
    assert_true(r.nosc > 0);
    assert_true(isfinite(r.pv_x) && isfinite(r.pv_F));
    assert_true(r.stick_fraction == 0 && r.stick_time == 0);
    sf_osc_result_free(&r);
    s.qoi_def = SF_QOI_CYCLES;
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_true(isnan(r.pv_x) && isnan(r.stick_fraction));
    assert_true(isfinite(r.osc_pv_x_mean));
    sf_osc_result_free(&r);
    scene_1d(&s, 1e-11);
    sf_cycle1d c;
    assert_int_equal(sf_cycle1d_init(&c, &s, s.eps_lambda), SF_SUCCESS);
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_close(r.stick_time, sf_cycle1d_stick_time(&c, s.t_skip, s.T), 1e-7);
    assert_close(r.win_stick_fraction, r.stick_time / (s.T - s.t_skip), 1e-15);
    assert_close(r.osc_pv_x_mean, r.cyc_pv_x, 1e-8);
    assert_close(r.osc_pv_F_mean, r.cyc_pv_F, 1e-8);
    assert_true(r.pv_x == r.osc_pv_x_mean && r.stick_fraction == r.win_stick_fraction);
    sf_osc_result_free(&r);
    s.t_skip = s.T;   /* an empty window: T_sk cannot be formed */
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_true(isnan(r.stick_fraction) && r.nosc == 0 && isnan(r.pv_x));
    sf_osc_result_free(&r);
}

/* The x extrema located on the step's interpolant (one trial step each),
 * on the 1-D Table 1 cycle with the threshold (eps-corrected closed form):
 * each oscillation's PV_x is 2 A, and the maxima are one period apart.
 * Tolerances: measured 2e-12 m and 6e-8 s (rk8pd's steps of ~0.3 s: the
 * interpolant's velocity errs by O(h^5), the root by that over |ax|); a
 * root off by dt moves x by ~omega^2 A dt^2 / 2 and the spacing by dt, so
 * 1e-9 m and 1e-6 s catch dt above ~5e-5 s and 1e-6 s. */
static void extrema_on_closed_form(void **state)
{
    (void)state;
    sf_scene s;
    scene_1d(&s, 1e-11);
    sf_cycle1d c;
    assert_int_equal(sf_cycle1d_init(&c, &s, s.eps_lambda), SF_SUCCESS);
    sf_osc_result r;
    char err[200];
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_true(r.nosc >= 10);
    double ex = 0, et = 0;
    for (size_t i = 0; i < r.nosc; i++) {
        ex = fmax(ex, fabs(r.osc_pv_x[i] - c.pv_x));
        if (i)
            et = fmax(et, fabs(r.osc_t[i] - r.osc_t[i - 1] - c.period));
    }
    assert_true(ex <= 1e-9);
    assert_true(et <= 1e-6);
    sf_osc_result_free(&r);
}

/* PV_F on a belt whose COF varies along it (a sinusoid of 4 m, 30% of
 * the mean) so fast that the disc never sticks: the friction force's
 * extrema lie inside slip steps, and PV_F (the continuous force's) at
 * rtol 1e-6 stays within 3e-5 of rtol 1e-11: 1.5e-6 measured, 4.7e-3
 * with the force taken at the step ends alone (~ |F''| h^2 / 8). */
static double wavy_pv_F(double rtol, size_t *nosc)
{
    sf_scene s;
    sf_scene_default(&s);
    s.cells = 6;
    s.rtol = rtol;
    s.v_b = 3;
    s.T = 25;
    s.t_skip = 2;
    s.cof_model = SF_COFMODEL_POINT;
    enum { M = 3201, N = 81 };
    double *g = malloc(M * N * sizeof *g);
    assert_non_null(g);
    for (size_t j = 0; j < N; j++)
        for (size_t i = 0; i < M; i++)
            g[i + M * j] = 0.5 * (1 + 0.3 * sin(2 * M_PI * (-78 + 0.025 * (double)i) / 4));
    sf_cof *cof;
    assert_int_equal(sf_cof_alloc_grid(M, N, -78, -1, 0.025, 0.025, g, &cof), SF_SUCCESS);
    free(g);
    sf_osc *o;
    sf_osc_result r;
    char err[200];
    assert_int_equal(sf_osc_alloc(&s, cof, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
    double pv = r.pv_F;
    *nosc = r.nosc;
    assert_int_equal(r.ntrans, 0);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(cof);
    return pv;
}

static void force_extrema_in_steps(void **state)
{
    (void)state;
    size_t n1, n2;
    double loose = wavy_pv_F(1e-6, &n1), ref = wavy_pv_F(1e-11, &n2);
    assert_true(n1 >= 5 && n1 == n2);   /* pure slip: no transition (asserted per run) */
    assert_true(fabs(loose / ref - 1) <= 3e-5);
}

/* dof = 1 with a field is refused with a reason; a belt slower than the
 * threshold starts in stick; T shorter than the first stick ends cleanly. */
static void edges(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    char err[200] = "";
    double g[4] = { 0.5, 0.5, 0.5, 0.5 };
    sf_cof *grid;
    sf_cof_alloc_grid(2, 2, -100, -100, 200, 200, g, &grid);
    sf_osc *o = (sf_osc *)1;
    s.dof = SF_DOF_1;
    assert_int_equal(sf_osc_alloc(&s, grid, &o, err, sizeof err), SF_EINVAL);
    assert_null(o);
    assert_non_null(strstr(err, "dof = 1"));
    sf_cof_free(grid);
    sf_osc_result r;
    s.cof = SF_COF_UNIFORM;
    s.v_b = 1e-4;   /* lambda at rest = v_b/(omega_n R) < eps: stick from t = 0 */
    s.T = 5;
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_true(r.ntrans >= 1);
    assert_int_equal(r.trans_kind[0], SF_OSC_STICK_ONSET);
    assert_close(r.trans_t[0], 0, 0);
    assert_close(r.x_max, 5e-4, 1e-12);   /* moved with the belt */
    sf_osc_result_free(&r);
    s.v_b = 0.2;
    s.T = 1;
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_int_equal(r.ncycles, 0);
    assert_true(isnan(r.pv_x));
    assert_int_equal(r.nsamples, 101);
    sf_osc_result_free(&r);
    sf_osc_result_free(NULL);
}

/* Eq. 15 between a run and itself is 0; against a shorter or differently
 * sampled run it is NaN rather than a silent number. */
static void eq15(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.T = 10;
    char err[200];
    sf_osc_result a, b;
    assert_int_equal(run(&s, &a, err), SF_SUCCESS);
    assert_int_equal(run(&s, &b, err), SF_SUCCESS);
    assert_close(sf_osc_error_eq15(&a, &b), 0, 0);
    b.sample_dt = 0.02;
    assert_true(isnan(sf_osc_error_eq15(&a, &b)));
    sf_osc_result_free(&a);
    sf_osc_result_free(&b);
}

/* A sine of known frequency: the periodogram peaks in its bin, and
 * Parseval holds (sum p df = variance). */
static void periodogram(void **state)
{
    (void)state;
    size_t n = 1000;
    double dt = 0.01, x[1000], f[501], p[501], var = 0;
    for (size_t i = 0; i < n; i++) {
        x[i] = 3 + 0.5 * sin(2 * M_PI * 5.0 * (double)i * dt);
        var += 0.25 * sin(2 * M_PI * 5.0 * (double)i * dt) * sin(2 * M_PI * 5.0 * (double)i * dt);
    }
    var /= (double)n;
    assert_int_equal(sf_periodogram(x, n, dt, f, p), SF_SUCCESS);
    size_t kmax = 0;
    double sum = 0;
    for (size_t k = 0; k <= n / 2; k++) {
        if (p[k] > p[kmax])
            kmax = k;
        sum += p[k] / ((double)n * dt);
    }
    assert_close(f[kmax], 5.0, 1e-12);
    assert_close(sum, var, 1e-10);
    assert_close(p[0], 0, 1e-20);   /* mean removed */
    assert_int_equal(sf_periodogram(x, 1, dt, f, p), SF_EINVAL);
}

/* A disc whose accepted path leaves the COF grid fails with a reason; on
 * a grid that covers the path the run succeeds, whatever trial stages of
 * rejected steps looked up (sf_cof_covers judges the accepted path). */
static void leaves_strip(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.T = 30;
    s.cells = 4;
    double g[4 * 4];
    for (int i = 0; i < 16; i++)
        g[i] = 0.5;
    char err[256] = "";
    sf_cof *small, *big;
    /* stick keeps the patch under the disc; slips move it back by about one
     * cycle's belt travel (v_b x 4.2 s): a 3 m grid is left within 30 s */
    assert_int_equal(sf_cof_alloc_grid(4, 4, -1.5, -1.5, 1.0, 1.0, g, &small), SF_SUCCESS);
    assert_int_equal(sf_cof_alloc_grid(4, 4, -20, -10, 10.0, 10.0, g, &big), SF_SUCCESS);
    assert_true(sf_cof_covers(big, -2, 0, s.R));
    assert_false(sf_cof_covers(small, -2, 0, s.R));
    sf_osc *o;
    sf_osc_result r;
    assert_int_equal(sf_osc_alloc(&s, small, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_EFAIL);
    assert_non_null(strstr(err, "left the belt strip"));
    assert_true(r.off_strip > 0);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    assert_int_equal(sf_osc_alloc(&s, big, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
    assert_int_equal(r.off_strip, 0);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(small);
    sf_cof_free(big);
}

/* Every stepper choice runs the same model: the 1-D Table 1 cycle from
 * rk8pd, rkck (forced), adaptive and RK4 agree with each other. */
static void stepper_choices(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.T = 30;
    s.rtol = 1e-10;
    s.cof = SF_COF_UNIFORM;
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &u), SF_SUCCESS);
    const int integ[4] = { SF_INTEG_ADAPTIVE, SF_INTEG_RK8PD, SF_INTEG_RKCK, SF_INTEG_RK4 };
    double pv[4];
    for (int k = 0; k < 4; k++) {
        sf_scene t = s;
        t.integrator = integ[k];
        char err[256] = "";
        sf_osc *o;
        sf_osc_result r;
        assert_int_equal(sf_osc_alloc(&t, u, &o, err, sizeof err), SF_SUCCESS);
        assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
        pv[k] = r.pv_x;
        sf_osc_result_free(&r);
        sf_osc_free(o);
    }
    assert_close(pv[1], pv[0], 0);      /* adaptive with a closed form is rk8pd */
    assert_close(pv[2], pv[0], 1e-8);
    assert_close(pv[3], pv[0], 1e-8);
    sf_cof_free(u);
}

/* The manufactured-source hook (cases/mms): the source reaches rows x, y
 * and phi as S/m, S/m, S/J and nothing else; removing it restores the
 * plan's bits; the fixed-step slip integrator refuses bad arguments and
 * reports a non-finite state. */
static void src_const(void *ctx, double t, double S[3])
{
    (void)t;
    memcpy(S, ctx, 3 * sizeof *S);
}

static void source_hook(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.integrator = SF_INTEG_RK4;
    s.T = 20;
    sf_cof *u;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &u), SF_SUCCESS);
    char err[256] = "";
    sf_osc *o;
    assert_int_equal(sf_osc_alloc(&s, u, &o, err, sizeof err), SF_SUCCESS);
    double y[SF_OSC_NSTATE] = { 0.01, -0.02, 0.3, 0.05, 0.04, 0.2, 0 }, f0[SF_OSC_NSTATE], f1[SF_OSC_NSTATE];
    double q0[3], q1[3], S[3] = { 1.5, -2.0, 0.25 }, J = 0.5 * s.m * s.R * s.R;
    sf_osc_slip_rhs(o, 1.0, y, f0, q0);
    sf_osc_set_source(o, src_const, S);
    sf_osc_slip_rhs(o, 1.0, y, f1, q1);
    for (int i = 0; i < 3; i++)
        assert_close(q1[i], q0[i], 0);   /* the source is not friction */
    assert_close(f1[SF_OSC_X], f0[SF_OSC_X], 0);
    assert_close(f1[SF_OSC_Y], f0[SF_OSC_Y], 0);
    assert_close(f1[SF_OSC_PHI], f0[SF_OSC_PHI], 0);
    assert_close(f1[SF_OSC_VX] - f0[SF_OSC_VX], S[0] / s.m, 1e-15);
    assert_close(f1[SF_OSC_VY] - f0[SF_OSC_VY], S[1] / s.m, 1e-15);
    assert_close(f1[SF_OSC_W] - f0[SF_OSC_W], S[2] / J, 1e-15);
    assert_close(f1[SF_OSC_WORK], f0[SF_OSC_WORK], 0);
    /* fixed steps: bad arguments, a non-finite state */
    double y1[SF_OSC_NSTATE];
    assert_int_equal(sf_osc_slip_integrate(o, 1, y, 1, 0.1, y1), SF_EINVAL);
    assert_int_equal(sf_osc_slip_integrate(o, 0, y, 1, 0, y1), SF_EINVAL);
    assert_int_equal(sf_osc_slip_integrate(o, 0, y, 1, 0.3, y1), SF_SUCCESS);
    double bad[3] = { NAN, 0, 0 };
    sf_osc_set_source(o, src_const, bad);
    /* a NaN state reaches GSL's elliptic integrals: an error, not an
     * abort, since main() called sf_init() */
    assert_int_equal(sf_osc_slip_integrate(o, 0, y, 1, 0.3, y1), SF_EFAIL);
    /* removed: the run is the plan's own, bit for bit */
    sf_osc_set_source(o, NULL, NULL);
    sf_osc_result a, b;
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &a, err, sizeof err), SF_SUCCESS);
    sf_osc *o2;
    assert_int_equal(sf_osc_alloc(&s, u, &o2, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o2, NULL, NULL, 0, &b, err, sizeof err), SF_SUCCESS);
    assert_int_equal(a.ntrans, b.ntrans);
    assert_memory_equal(a.trans_t, b.trans_t, a.ntrans * sizeof *a.trans_t);
    assert_close(a.friction_work, b.friction_work, 0);
    sf_osc_result_free(&a);
    sf_osc_result_free(&b);
    sf_osc_free(o2);
    sf_osc_free(o);
    /* the grid view: refused for a non-grid COF, the values as given */
    size_t m, n;
    double x0, y0, dx, dy, g[6] = { 1, 2, 3, 4, 5, 6 };
    const double *mu;
    assert_int_equal(sf_cof_grid_view(u, &m, &n, &x0, &y0, &dx, &dy, &mu), SF_EINVAL);
    sf_cof *gr;
    assert_int_equal(sf_cof_alloc_grid(3, 2, -1, 2, 0.5, 0.25, g, &gr), SF_SUCCESS);
    assert_int_equal(sf_cof_grid_view(gr, &m, &n, &x0, &y0, &dx, &dy, &mu), SF_SUCCESS);
    assert_int_equal(m, 3);
    assert_int_equal(n, 2);
    assert_close(x0, -1, 0);
    assert_close(y0, 2, 0);
    assert_close(dx, 0.5, 0);
    assert_close(dy, 0.25, 0);
    assert_memory_equal(mu, g, sizeof g);
    sf_cof_free(gr);
    sf_cof_free(u);
}

/* The scene's initial state (x0 ... w0): a state at belt speed inside the
 * stick set starts in stick (Eq. 12 sets the rest of the velocity, its
 * energy booked as a jump) and breaks where the closed form says; a
 * sliding, spinning start keeps the energy balance; dof = 1 refuses a
 * lateral or rotational start; the grid view returns the nodal values. */
static void initial_state(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.T = 10;
    s.rtol = 1e-10;
    s.x0 = 0.5;
    s.vx0 = s.v_b;
    s.w0 = 1e-4;   /* lambda = w0 / omega_n = 5.8e-5 < eps_lambda: stick */
    sf_osc_result r;
    char err[256] = "";
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_true(r.ntrans >= 2);
    assert_int_equal(r.trans_kind[0], SF_OSC_STICK_ONSET);
    assert_true(r.trans_t[0] == 0 && r.trans_x[0] == 0.5);
    /* break at x_s = mu_s m g / k, reached at belt speed */
    assert_close(r.trans_t[1], (s.mu_mean * s.m * s.g / s.k - 0.5) / s.v_b, 1e-12);
    assert_true(fabs(r.energy_residual) < 1e-7 * fabs(r.friction_work));
    sf_osc_result_free(&r);
    /* sliding and spinning: slip from the start, balance from E(0) */
    s.x0 = 0.2;
    s.y0 = -0.1;
    s.vx0 = 0;
    s.vy0 = 0.1;
    s.w0 = 2;
    assert_int_equal(run(&s, &r, err), SF_SUCCESS);
    assert_int_equal(r.trans_kind[0], SF_OSC_STICK_ONSET);
    assert_true(r.trans_t[0] > 0);
    assert_true(fabs(r.energy_residual) < 1e-7 * fabs(r.friction_work));
    sf_osc_result_free(&r);
    s.dof = SF_DOF_1;
    assert_int_equal(run(&s, &r, err), SF_EINVAL);
    assert_non_null(strstr(err, "y0"));
    /* the grid view */
    double g[6] = { 1, 2, 3, 4, 5, 6 }, x0, y0, dx, dy;
    size_t m, n;
    const double *mu;
    sf_cof *c;
    assert_int_equal(sf_cof_alloc_grid(3, 2, -1, -2, 0.5, 0.25, g, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_grid_view(c, &m, &n, &x0, &y0, &dx, &dy, &mu), SF_SUCCESS);
    assert_true(m == 3 && n == 2 && x0 == -1 && y0 == -2 && dx == 0.5 && dy == 0.25 && mu[5] == 6);
    sf_cof_free(c);
    assert_int_equal(sf_cof_alloc_uniform(0.5, &c), SF_SUCCESS);
    assert_int_equal(sf_cof_grid_view(c, &m, &n, &x0, &y0, &dx, &dy, &mu), SF_EINVAL);
    sf_cof_free(c);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closed_form_table1),
        cmocka_unit_test(edges),
        cmocka_unit_test(qoi_definitions),
        cmocka_unit_test(extrema_on_closed_form),
        cmocka_unit_test(force_extrema_in_steps),
        cmocka_unit_test(eq15),
        cmocka_unit_test(periodogram),
        cmocka_unit_test(leaves_strip),
        cmocka_unit_test(stepper_choices),
        cmocka_unit_test(source_hook),
        cmocka_unit_test(initial_state),
        cmocka_unit_test(step_budget),
    };
    return cmocka_run_group_tests_name("oscillator", tests, NULL, NULL);
}
