/* Unit tests: the numerical error estimate of a run (unum.h): the
 * companion's settings and assumed ratio for each kind of plan, the
 * estimate equal to its formula on a companion that reruns bit for bit,
 * and the summary lines. */
#include "test_util.h"
#include "cof.h"
#include "mlmc.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "sf_error.h"
#include "sweep.h"
#include "unum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void companion_settings(void **state)
{
    (void)state;
    sf_scene s, c;
    sf_scene_default(&s);
    double rho;
    sf_numplan p = { 0 };
    p.quadrature = 1;   /* point model, 16 rings: 11, rho = (16/11)^2, rtol x rho^2 */
    p.cells = 16;
    p.rtol = 1e-8;
    p.integrator = SF_INTEG_RKCK;
    sf_unum_companion(&s, &p, &c, &rho);
    assert_int_equal(c.cells, 11);
    assert_true(fabs(rho - (16.0 / 11) * (16.0 / 11)) < 1e-15);
    assert_true(fabs(c.rtol - rho * rho * 1e-8) < 1e-22);
    assert_int_equal(c.integrator, SF_INTEG_RKCK);
    p.cell_average = 1;   /* cell averages: the same boxes, rtol x 16 */
    sf_unum_companion(&s, &p, &c, &rho);
    assert_int_equal(c.cells, 16);
    assert_int_equal(c.cof_model, SF_COFMODEL_CELL);
    assert_true(fabs(rho - 4) < 1e-15 && fabs(c.rtol - 16e-8) < 1e-22);
    p.cell_average = 0;   /* no quadrature; rtol near the cap: x4 at least */
    p.quadrature = 0;
    p.cells = 0;
    p.rtol = 5e-7;   /* 16 x 5e-7 is above SF_UNUM_MAX_RTOL = 1e-6 */
    sf_unum_companion(&s, &p, &c, &rho);
    assert_true(fabs(c.rtol - 2e-6) < 1e-21 && fabs(rho - 2) < 1e-15);
    p.integrator = SF_INTEG_RK4;   /* fixed step: 2 dt, order 4 */
    s.dt = 1e-3;
    sf_unum_companion(&s, &p, &c, &rho);
    assert_true(c.dt == 2e-3 && rho == 16);
}

static void estimate_is_its_formula(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.T = 30;
    sf_cof *cof = NULL;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &cof), SF_SUCCESS);
    sf_osc *o = NULL;
    char err[256];
    sf_osc_result r, rc;
    assert_int_equal(sf_osc_alloc(&s, cof, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
    sf_unum u;
    assert_int_equal(sf_unum_estimate(&s, cof, sf_osc_get_plan(o), &r, &u, err, sizeof err), SF_SUCCESS);
    /* the companion, run by hand, gives the same bits */
    sf_scene c;
    double rho;
    sf_unum_companion(&s, sf_osc_get_plan(o), &c, &rho);
    sf_osc *oc = NULL;
    assert_int_equal(sf_osc_alloc(&c, cof, &oc, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(oc, NULL, NULL, 0, &rc, err, sizeof err), SF_SUCCESS);
    double q[3] = { r.pv_x, r.pv_F, r.stick_fraction }, qc[3] = { rc.pv_x, rc.pv_F, rc.stick_fraction };
    assert_true(u.rho == rho && u.cells == 0 && u.cells_c == 0 && !u.cell_average);
    for (int k = 0; k < 3; k++) {
        assert_true(u.q[k] == q[k] && u.qc[k] == qc[k] && u.apriori[k] == 0);
        assert_true(u.u[k] == SF_UNUM_FS * fabs(q[k] - qc[k]) / (rho - 1));
        assert_true(isfinite(u.u[k]) && u.u[k] > 0);   /* two rtols: the QoIs differ */
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    sf_unum_write(&u, f);
    fclose(f);
    assert_non_null(strstr(buf, "\nu_pv_x = "));
    assert_non_null(strstr(buf, "\nu_stick_fraction = "));
    assert_non_null(strstr(buf, "\ncompanion_rtol = "));
    assert_null(strstr(buf, "u_apriori_"));
    free(buf);
    sf_osc_result_free(&r);
    sf_osc_result_free(&rc);
    sf_osc_free(o);
    sf_osc_free(oc);
    sf_cof_free(cof);
}

/* the estimate's bookkeeping for a quadrature plan (point or cell
 * averages) on a fixed-step run: its cells, step sizes and the a-priori
 * cell-average term (the plan is given by hand; the COF is uniform, so the
 * companion runs whatever the cells) */
static void estimate_bookkeeping(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.T = 20;
    s.integrator = SF_INTEG_RK4;
    s.dt = 1e-3;
    sf_cof *cof = NULL;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &cof), SF_SUCCESS);
    sf_osc *o = NULL;
    char err[256];
    sf_osc_result r;
    assert_int_equal(sf_osc_alloc(&s, cof, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
    sf_numplan p = *sf_osc_get_plan(o);
    p.quadrature = 1;
    p.cells = 16;
    p.err_quad = 1e-4;
    for (int ca = 0; ca < 2; ca++) {
        p.cell_average = ca;
        sf_unum u;
        int rc = sf_unum_estimate(&s, cof, &p, &r, &u, err, sizeof err);
        assert_int_equal(rc, SF_SUCCESS);
        assert_true(u.fixed_step && u.rtol == 1e-3 && u.rtol_c == 2e-3);
        assert_int_equal(u.cells, 16);
        assert_int_equal(u.cells_c, ca ? 16 : 11);
        assert_int_equal(u.cell_average, ca);
        for (int k = 0; k < 3; k++)
            assert_true(u.apriori[k] == (ca ? 1e-4 * fabs(u.q[k]) : 0));
    }
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(cof);
}

/* the other summary forms, and a companion that cannot run */
static void write_forms_and_refusal(void **state)
{
    (void)state;
    sf_unum u;
    memset(&u, 0, sizeof u);
    u.cell_average = 1;
    u.rtol = 1e-8;
    u.rtol_c = 1.6e-7;
    u.rho = 4;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    sf_unum_write(&u, f);
    u.cell_average = 0;
    u.fixed_step = 1;
    sf_unum_write(&u, f);
    fclose(f);
    assert_non_null(strstr(buf, "\nu_apriori_pv_F = "));
    assert_non_null(strstr(buf, "rk4 at 2 dt"));
    assert_non_null(strstr(buf, "\ncompanion_dt = "));
    free(buf);
    sf_scene s;
    sf_scene_default(&s);
    s.dof = SF_DOF_1;   /* the 1-D model refuses a field COF */
    double v[4] = { 0.5, 0.5, 0.5, 0.5 };
    sf_cof *g = NULL;
    assert_int_equal(sf_cof_alloc_grid(2, 2, -1, -1, 2, 2, v, &g), SF_SUCCESS);
    sf_numplan p = { 0 };
    p.rtol = 1e-8;
    p.integrator = SF_INTEG_RK8PD;
    sf_osc_result r;
    memset(&r, 0, sizeof r);
    char err[256] = "";
    assert_int_equal(sf_unum_estimate(&s, g, &p, &r, &u, err, sizeof err), SF_EINVAL);
    assert_true(*err != 0);
    sf_cof_free(g);
}

/* the sweep's subset: a quarter, at least 2, all of a smaller sweep */
static void sweep_subset(void **state)
{
    (void)state;
    size_t n[] = { 0, 1, 2, 3, 5, 8, 9, 100 }, m[] = { 0, 1, 2, 2, 2, 2, 3, 25 };
    for (size_t i = 0; i < sizeof n / sizeof *n; i++)
        assert_int_equal(sf_unum_sweep_subset(n[i]), m[i]);
}

/* the mean's statistics: non-finite estimates left out, the standard
 * error and the bound from two on, the a-priori part added */
static void sweep_stats(void **state)
{
    (void)state;
    sf_sweep_num num;
    double e[8] = { 1, -7, 2, -7, NAN, -7, 3, -7 };   /* stride 2: 1, 2, nan, 3 */
    assert_int_equal(sf_unum_sweep_stats(e, 2, 4, 0.5, &num), SF_SUCCESS);
    assert_true(num.n_sub == 4 && num.n_used == 3 && num.bias == 2);
    assert_true(fabs(num.bias_se - 1 / sqrt(3.0)) < 1e-15);
    double t = 4.3026527297;   /* Student t, 2 degrees of freedom, 0.975 */
    assert_true(fabs(num.u_mean - (SF_UNUM_FS * (2 + t / sqrt(3.0)) + 0.5)) < 1e-9);
    assert_int_equal(sf_unum_sweep_stats(e, 2, 1, 0, &num), SF_SUCCESS);   /* one: a bias, no bound */
    assert_true(num.n_used == 1 && num.bias == 1 && isnan(num.bias_se) && isnan(num.u_mean));
    assert_int_equal(sf_unum_sweep_stats(e + 4, 2, 1, 0, &num), SF_SUCCESS);   /* none finite */
    assert_true(num.n_sub == 1 && num.n_used == 0 && isnan(num.bias) && isnan(num.u_mean));
    assert_int_equal(sf_unum_sweep_stats(e, 2, 0, 0, &num), SF_SUCCESS);
    assert_true(num.n_sub == 0 && isnan(num.bias));
}

/* point p's per-realisation table (which 0), diagnostics (1) or summary
 * (2) as text, T = 30 */
static char *table_text(const sf_sweep_point *p, int which)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_non_null(f);
    if (which == 2) {
        sf_sweep_summary_header(f, 0);
        sf_sweep_summary_row(f, "T", 30, p, 0);
    } else if (which) {
        sf_sweep_diagnostics_header(f);
        sf_sweep_diagnostics_row(f, "T", 30, p);
    } else {
        sf_sweep_write_header(f);
        sf_sweep_write_rows(f, "T", 30, p);
    }
    fclose(f);
    return buf;
}

/* a sweep point's estimate: on a uniform COF every realisation is the
 * same run, so the bias is that run's own estimate (Q_c - Q) / (rho - 1)
 * with standard error 0; the same bits at 1 and 2 threads; the summary
 * row carries it; a companion that cannot run leaves it unestimated */
static void sweep_estimate(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_UNIFORM;
    s.T = 30;
    char err[256] = "";
    sf_sweep_point p;
    assert_int_equal(sf_sweep_run(&s, 5, 1, NULL, 0, NULL, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_unum_sweep(&s, &p, 1, err, sizeof err), SF_SUCCESS);
    sf_cof *cof = NULL;
    assert_int_equal(sf_cof_alloc_uniform(s.mu_mean, &cof), SF_SUCCESS);
    sf_osc *o = NULL;
    sf_osc_result r;
    assert_int_equal(sf_osc_alloc(&s, cof, &o, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_osc_run(o, NULL, NULL, 0, &r, err, sizeof err), SF_SUCCESS);
    sf_unum u;
    assert_int_equal(sf_unum_estimate(&s, cof, sf_osc_get_plan(o), &r, &u, err, sizeof err), SF_SUCCESS);
    sf_sweep_num two[SF_SWEEP_NQ];
    memcpy(two, p.num, sizeof two);
    assert_int_equal(sf_unum_sweep(&s, &p, 2, err, sizeof err), SF_SUCCESS);
    for (int k = 0; k < SF_SWEEP_NQ; k++) {
        const sf_sweep_num *e = &p.num[k];
        assert_true(e->n_sub == 2 && e->n_used == 2);
        assert_true(e->bias == (u.qc[k] - u.q[k]) / (u.rho - 1) && e->bias != 0 && e->bias_se == 0);
        assert_true(e->u_mean == SF_UNUM_FS * fabs(e->bias));
        assert_memory_equal(&two[k], e, sizeof *e);
        /* what it is made of, kept: realisations 0, 1's companions */
        assert_true(p.num_m == 2 && p.num_qc[SF_SWEEP_NQ + k] == u.qc[k] && p.num_rho[1] == u.rho);
        assert_true(p.num_apriori[0] == 0);
    }
    /* num recomputed from what the point keeps: the same bits; nothing
     * kept (or more than the point has): not estimated */
    assert_int_equal(sf_unum_sweep_num(&p), SF_SUCCESS);
    assert_memory_equal(two, p.num, sizeof two);
    p.num_m = p.n + 1;
    assert_int_equal(sf_unum_sweep_num(&p), SF_SUCCESS);
    assert_true(p.num[0].n_sub == 0);
    p.num_m = 2;
    assert_int_equal(sf_unum_sweep_num(&p), SF_SUCCESS);
    /* the per-realisation table carries the companions: realisation 1's
     * row its pv_x_coarse .. unum_apriori, realisation 2's nan */
    char *tv = table_text(&p, 0);
    assert_non_null(strstr(tv, "\tstick_fraction[-]\tpv_x_coarse[m]\tpv_F_coarse[N]\tstick_fraction_coarse[-]\tunum_rho[-]"
                               "\tunum_apriori[-]\n"));
    char want[128];   /* realisation 1's row ends with rho and the a-priori 0 */
    snprintf(want, sizeof want, "\t%.17g\t0\nT\t30\t2\t", u.rho);
    assert_non_null(strstr(tv, want));
    assert_non_null(strstr(tv, "\tnan\tnan\tnan\tnan\tnan\nT\t30\t3\t"));
    free(tv);
    char *buf = table_text(&p, 1);
    assert_non_null(strstr(buf, "\tpv_F_u_num_mean[N]"));
    /* every numerical-error cell is estimated (the control variate's and
     * the two-level estimator's and the antithetic pairs', not asked
     * for, are the row's only nan) */
    char *save = NULL, *head = strtok_r(buf, "\n", &save), *row = strtok_r(NULL, "\n", &save);
    char *sh = NULL, *sr = NULL;
    size_t nnum = 0;
    for (char *h = strtok_r(head, "\t", &sh), *c = strtok_r(row, "\t", &sr); h && c;
         h = strtok_r(NULL, "\t", &sh), c = strtok_r(NULL, "\t", &sr))
        if (strstr(h, "_num_") || strstr(h, "_u_num_mean")) {
            nnum++;
            assert_null(strstr(c, "nan"));
        } else if (strstr(c, "nan")) {
            assert_true(strstr(h, "_cv_") || strstr(h, "ml_") || strstr(h, "anti_"));
        }
    assert_int_equal(nnum, 4 * SF_SWEEP_NQ);
    free(buf);
    /* the summary: u_num in ratio units, u_num_mean / det */
    buf = table_text(&p, 2);
    assert_non_null(strstr(buf, "\tpv_F_ratio_u_num[-]\t"));
    snprintf(want, sizeof want, "\t%.3g\t5\tplain\tfixed\n", p.num[2].u_mean / p.det[2]);
    assert_non_null(strstr(buf, want));
    free(buf);
    s.dof = SF_DOF_1;   /* the 1-D model refuses a quadrature plan's companion: unestimated */
    s.cof = SF_COF_FIELD;
    p.planned = 0;   /* (the rows' own plan would draw their uniform COF: the scene's is taken) */
    assert_int_equal(sf_unum_sweep(&s, &p, 1, err, sizeof err), SF_EINVAL);
    assert_true(p.num[0].n_sub == 0 && *err && !p.num_qc && !p.num_m);
    assert_int_equal(sf_unum_sweep_num(&p), SF_SUCCESS);   /* nothing kept: not estimated */
    assert_true(p.num[0].n_sub == 0);
    assert_int_equal(sf_unum_sweep(&s, &p, 1, NULL, 0), SF_EINVAL);   /* no message wanted */
    buf = table_text(&p, 1);
    assert_non_null(strstr(buf, "\t0\tnan\tnan\tnan"));
    free(buf);
    p.n = 0;   /* an empty point: nothing to estimate */
    assert_int_equal(sf_unum_sweep(&s, &p, 1, err, sizeof err), SF_SUCCESS);
    sf_sweep_point_free(&p);
    sf_osc_result_free(&r);
    sf_osc_free(o);
    sf_cof_free(cof);
}

/* row i of point p (scene s) against its realisation made here as `run
 * --summary` makes one: the COF the rows' plan draws from stream
 * sf_mc_seed(seed, i), run on that plan (row i to the bit), and its
 * companion (sf_unum_estimate on that plan): the sweep's to the bit */
static void rows_own_companions(const sf_scene *s, const sf_sweep_point *p)
{
    assert_true(p->planned && p->num_m >= 2);
    sf_cof_plan *cp = NULL;
    assert_int_equal(sf_cof_plan_build(s, &p->plan, &cp, NULL, 0), SF_SUCCESS);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    assert_non_null(rng);
    for (size_t i = 0; i < p->num_m; i++) {
        sf_cof *cof = NULL;
        gsl_rng_set(rng, sf_mc_seed(s->seed, i));
        assert_int_equal(sf_cof_plan_draw(cp, rng, &cof), SF_SUCCESS);
        double q[SF_SWEEP_NQ];
        assert_int_equal(sf_sweep_solve(s, &p->plan, cof, q, NULL), SF_SUCCESS);
        assert_memory_equal(q, p->qoi + i * SF_SWEEP_NQ, sizeof q);
        sf_osc_result r;
        memset(&r, 0, sizeof r);
        r.pv_x = q[SF_SWEEP_PVX];
        r.pv_F = q[SF_SWEEP_PVF];
        r.stick_fraction = q[SF_SWEEP_SF];
        sf_unum u;
        assert_int_equal(sf_unum_estimate(s, cof, &p->plan.num, &r, &u, NULL, 0), SF_SUCCESS);
        assert_memory_equal(u.qc, p->num_qc + i * SF_SWEEP_NQ, sizeof u.qc);
        assert_true(u.rho == p->num_rho[i]);
        sf_cof_free(cof);
    }
    gsl_rng_free(rng);
    sf_cof_plan_free(cp);
}

/* each estimator records the plan its rows were solved on and the
 * companions solve the rows' own realisations: mlmc-boxes' plan is not
 * the scene's (cells a multiple of 4, a finer strip 8 nodes wider each side:
 * the same stream draws another field there); a point with no plan
 * recorded takes the scene's, which may refuse */
static void sweep_own_realisation(void **state)
{
    (void)state;
    sf_scene s;
    sf_scene_default(&s);
    s.cof = SF_COF_FIELD;
    s.l = 0.03 * s.R;   /* cell averages */
    s.T = 30;
    s.t_skip = 10;
    char err[256] = "";
    sf_plan sp;
    assert_int_equal(sf_plan_make(&s, &sp, err, sizeof err), SF_SUCCESS);
    assert_true(sp.num.cell_average && sp.num.cells % 4 != 0);   /* so boxes round the cells */
    sf_sweep_point p, b;
    assert_int_equal(sf_sweep_run(&s, 4, 1, NULL, 0, NULL, &p, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_unum_sweep(&s, &p, 1, err, sizeof err), SF_SUCCESS);
    assert_true(p.plan.num.cells == sp.num.cells && p.plan.cof.nx == sp.cof.nx);
    rows_own_companions(&s, &p);
    assert_int_equal(sf_sweep_run_mlmc_boxes(&s, 4, 2, 1, NULL, &b, err, sizeof err), SF_SUCCESS);
    assert_int_equal(sf_unum_sweep(&s, &b, 2, err, sizeof err), SF_SUCCESS);
    assert_true(b.plan.num.cells % 4 == 0 && b.plan.num.cells > sp.num.cells);
    assert_true(b.plan.cof.nx > sp.cof.nx + 2 * SF_MLMC_BOX_PAD && b.plan.cof.box < sp.cof.box);
    assert_true(b.num_apriori[0] == b.plan.num.err_quad && b.plan.num.err_quad != sp.num.err_quad);
    rows_own_companions(&s, &b);
    /* no plan recorded: the scene's, the same companions as plain's own */
    double qc[2 * SF_SWEEP_NQ];
    memcpy(qc, p.num_qc, sizeof qc);
    p.planned = 0;
    assert_int_equal(sf_unum_sweep(&s, &p, 1, err, sizeof err), SF_SUCCESS);
    assert_memory_equal(qc, p.num_qc, sizeof qc);
    s.qoi_tol = 0;   /* ... and a scene that cannot be planned: unestimated, with the reason */
    *err = 0;
    assert_int_equal(sf_unum_sweep(&s, &p, 1, err, sizeof err), SF_EINVAL);
    assert_true(*err && !p.num_m && p.num[0].n_sub == 0);
    sf_sweep_point_free(&p);
    sf_sweep_point_free(&b);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(companion_settings),
        cmocka_unit_test(estimate_is_its_formula),
        cmocka_unit_test(estimate_bookkeeping),
        cmocka_unit_test(write_forms_and_refusal),
        cmocka_unit_test(sweep_subset),
        cmocka_unit_test(sweep_stats),
        cmocka_unit_test(sweep_estimate),
        cmocka_unit_test(sweep_own_realisation),
    };
    return cmocka_run_group_tests_name("unum", tests, NULL, NULL);
}
