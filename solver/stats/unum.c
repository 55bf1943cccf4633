/* slipfield: the a-posteriori numerical error u_num of a run's QoIs from
 * a companion solve at a coarser setting (unum.h), for one run and for a
 * sweep. */
#include "unum.h"
#include "montecarlo.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sf_unum_companion(const sf_scene *s, const sf_numplan *p, sf_scene *c, double *rho)
{
    *c = *s;
    double rq = INFINITY, rt;
    if (p->quadrature && !p->cell_average) {
        c->cells = (2 * p->cells + 2) / 3;   /* ceil(2n/3): ~0.44 of the cells */
        rq = ((double)p->cells / (double)c->cells) * ((double)p->cells / (double)c->cells);
    } else {
        c->cells = p->cells;   /* cell averages: the boxes are the cells */
        if (p->cell_average)
            c->cof_model = SF_COFMODEL_CELL;
    }
    c->layout = p->layout;
    c->integrator = p->integrator;
    if (p->integrator == SF_INTEG_RK4) {
        c->rtol = p->rtol;
        c->dt = 2 * s->dt;
        rt = 16;   /* rk4's order 4 */
    } else {
        /* the same assumed ratio as the quadrature's (16 without one) */
        double f = isfinite(rq) ? rq * rq : 16;
        c->rtol = fmax(4 * p->rtol, fmin(f * p->rtol, SF_UNUM_MAX_RTOL));
        rt = sqrt(c->rtol / p->rtol);   /* err_time ~ sqrt(rtol) */
    }
    *rho = fmin(rq, rt);
}

int sf_unum_estimate(const sf_scene *s, const sf_cof *cof, const sf_numplan *p, const sf_osc_result *res, sf_unum *u,
                     char *err, size_t errlen)
{
    memset(u, 0, sizeof *u);
    sf_scene c;
    sf_unum_companion(s, p, &c, &u->rho);
    u->cells = p->quadrature ? p->cells : 0;
    u->cells_c = p->quadrature ? c.cells : 0;
    u->rtol = p->integrator == SF_INTEG_RK4 ? s->dt : p->rtol;
    u->rtol_c = p->integrator == SF_INTEG_RK4 ? c.dt : c.rtol;
    u->cell_average = p->quadrature && p->cell_average;
    u->fixed_step = p->integrator == SF_INTEG_RK4;
    sf_osc *o = NULL;
    sf_osc_result rc_res = { 0 };   /* freed also when the run fails */
    int rc = sf_osc_alloc(&c, cof, &o, err, errlen);
    if (!rc)
        rc = sf_osc_run(o, NULL, NULL, 0, &rc_res, err, errlen);
    sf_osc_free(o);
    if (rc) {
        sf_osc_result_free(&rc_res);
        return rc;
    }
    double q[SF_UNUM_NQ] = { res->pv_x, res->pv_F, res->stick_fraction };
    double qc[SF_UNUM_NQ] = { rc_res.pv_x, rc_res.pv_F, rc_res.stick_fraction };
    sf_osc_result_free(&rc_res);
    for (int k = 0; k < SF_UNUM_NQ; k++) {
        u->q[k] = q[k];
        u->qc[k] = qc[k];
        u->apriori[k] = u->cell_average ? p->err_quad * fabs(q[k]) : 0;
        u->u[k] = SF_UNUM_FS * fabs(q[k] - qc[k]) / (u->rho - 1) + u->apriori[k];
    }
    return SF_SUCCESS;
}

void sf_unum_write(const sf_unum *u, FILE *f)
{
    static const char *const key[SF_UNUM_NQ] = { "pv_x", "pv_F", "stick_fraction" };
    char knobs[160];
    if (u->fixed_step)
        snprintf(knobs, sizeof knobs, "rk4 at 2 dt, order 4");
    else
        snprintf(knobs, sizeof knobs, "%srtol x %.3g, err ~ sqrt(rtol)",
                 u->cells_c && !u->cell_average ? "2/3 of the rings, err ~ rings^-2; " : "", u->rtol_c / u->rtol);
    fprintf(f, "# numerical error u_num (ASME V&V 20) of each QoI, in its unit: two-level GCI against a coarser "
               "companion solve of the same realisation (%s), u = %g |Q - Q_c| / (rho - 1), rho = %.4g the "
               "companion's assumed error ratio%s\n",
            knobs, SF_UNUM_FS, u->rho,
            u->cell_average ? "; cell averages: the companion changes rtol only, plus the plan's a-priori cell-average "
                              "error |Q| err_cell (u_apriori_*)"
                            : "");
    for (int k = 0; k < SF_UNUM_NQ; k++)
        fprintf(f, "u_%s = %.3g\n", key[k], u->u[k]);
    if (u->cell_average)
        for (int k = 0; k < SF_UNUM_NQ; k++)
            fprintf(f, "u_apriori_%s = %.3g\n", key[k], u->apriori[k]);
    for (int k = 0; k < SF_UNUM_NQ; k++)
        fprintf(f, "companion_%s = %.17g\n", key[k], u->qc[k]);
    fprintf(f, "companion_cells = %zu\ncompanion_%s = %.6g\n", u->cells_c, u->fixed_step ? "dt" : "rtol", u->rtol_c);
}

size_t sf_unum_sweep_subset(size_t n)
{
    size_t m = (n + 3) / 4;
    return n < 2 ? n : m < 2 ? 2 : m;
}

int sf_unum_sweep_stats(const double *e, size_t stride, size_t m, double apriori, sf_sweep_num *num)
{
    sf_sweep_stat st;
    int rc = sf_sweep_stat_of(e, stride, m, &st);
    if (rc)
        return rc;
    num->n_sub = m;
    num->n_used = st.n_used;
    num->bias = st.mean;
    num->bias_se = st.se;
    /* ci_hi - mean = t se, the interval's half-width */
    num->u_mean = SF_UNUM_FS * (fabs(st.mean) + (st.ci_hi - st.mean)) + apriori;
    return SF_SUCCESS;
}

/* the companion of one realisation of a sweep point (ws: the sweep's
 * workspace on the rows' plan, its data the point): its QoIs (out[0..2]),
 * its rho (out[3]) and the plan's a-priori relative cell-average error
 * (out[4], 0 for the point model) */
enum { UNUM_RHO = SF_UNUM_NQ, UNUM_APRIORI, UNUM_NOUT };
static int unum_realise(void *p, size_t i, gsl_rng *rng, double *out)
{
    sf_sweep_ws *w = p;
    const sf_sweep_point *pt = w->data;
    const double *qoi = pt->qoi;
    sf_cof *cof;
    /* row i's field: the rows' COF plan on row i's stream (the same bits) */
    int rc = sf_cof_plan_draw(w->plan, rng, &cof);
    if (rc)
        return rc;
    const sf_numplan *np = &w->pl->num;   /* the row's numerical plan, which the companion coarsens */
    sf_osc_result r;
    memset(&r, 0, sizeof r);
    r.pv_x = qoi[i * SF_SWEEP_NQ + SF_SWEEP_PVX];
    r.pv_F = qoi[i * SF_SWEEP_NQ + SF_SWEEP_PVF];
    r.stick_fraction = qoi[i * SF_SWEEP_NQ + SF_SWEEP_SF];
    sf_unum u;
    rc = sf_unum_estimate(w->s, cof, np, &r, &u, NULL, 0);
    for (int k = 0; !rc && k < SF_UNUM_NQ; k++)
        out[k] = u.qc[k];
    out[UNUM_RHO] = u.rho;
    out[UNUM_APRIORI] = u.cell_average ? np->err_quad : 0;
    sf_cof_free(cof);
    return rc;
}

int sf_unum_sweep_num(sf_sweep_point *p)
{
    memset(p->num, 0, sizeof p->num);
    size_t m = p->num_m;
    if (!m || m > p->n)   /* (num_m > 0: the companion arrays are held) */
        return SF_SUCCESS;
    double *e = sf_malloc(m * sizeof *e);
    if (!e)
        return SF_ENOMEM;
    int rc = SF_SUCCESS;
    for (int k = 0; !rc && k < SF_UNUM_NQ; k++) {
        for (size_t i = 0; i < m; i++)   /* Richardson: the run's error from the companion's difference */
            e[i] = (p->num_qc[i * SF_SWEEP_NQ + k] - p->qoi[i * SF_SWEEP_NQ + k]) / (p->num_rho[i] - 1);
        rc = sf_unum_sweep_stats(e, 1, m, p->num_apriori[0] * fabs(p->stat[k].mean), &p->num[k]);
    }
    free(e);
    if (rc)
        memset(p->num, 0, sizeof p->num);
    return rc;
}

/* p's companion arrays freed and zeroed (not estimated) */
static void unum_clear(sf_sweep_point *p)
{
    free(p->num_qc);
    free(p->num_rho);
    free(p->num_apriori);
    p->num_qc = p->num_rho = p->num_apriori = NULL;
    p->num_m = 0;
    memset(p->num, 0, sizeof p->num);
}

int sf_unum_sweep(const sf_scene *s, sf_sweep_point *p, int threads, char *err, size_t errlen)
{
    unum_clear(p);
    size_t m = sf_unum_sweep_subset(p->n);
    if (!m)
        return SF_SUCCESS;
    double *e = sf_calloc(m * UNUM_NOUT, sizeof *e);
    if (!e)
        return SF_ENOMEM;
    /* the plan the rows were solved on: an estimator's own may differ from
       the scene's (mlmc-boxes': other cells, a wider strip, so another
       field from the same stream) */
    sf_plan pl;
    int rc = SF_SUCCESS;
    if (p->planned)
        pl = p->plan;
    else if ((rc = sf_plan_make(s, &pl, err, errlen))) {
        free(e);
        return rc;
    }
    pl.history = 0;
    sf_sweep_ws ctx = { s, &pl, p, NULL, 0 };
    sf_mc_spec spec = { m, UNUM_NOUT, s->seed, threads, NULL, 0, 0, "u_num" };
    sf_mc_ops ops = { sf_sweep_ws_alloc, sf_sweep_ws_free, unum_realise };
    if (err && errlen)
        *err = 0;
    rc = sf_mc_run(&spec, &ops, &ctx, e, NULL, err, errlen);
    if (rc && err && errlen && !*err)   /* a realisation's error comes without a message */
        snprintf(err, errlen, "a companion solve failed: %s", sf_strerror(rc));
    if (!rc) {
        p->num_qc = sf_malloc(m * SF_SWEEP_NQ * sizeof *p->num_qc);
        p->num_rho = sf_malloc(m * sizeof *p->num_rho);
        p->num_apriori = sf_malloc(m * sizeof *p->num_apriori);
        rc = p->num_qc && p->num_rho && p->num_apriori ? SF_SUCCESS : SF_ENOMEM;
    }
    for (size_t i = 0; !rc && i < m; i++) {
        for (int k = 0; k < SF_UNUM_NQ; k++)
            p->num_qc[i * SF_SWEEP_NQ + k] = e[i * UNUM_NOUT + k];
        p->num_rho[i] = e[i * UNUM_NOUT + UNUM_RHO];
        p->num_apriori[i] = e[i * UNUM_NOUT + UNUM_APRIORI];
    }
    free(e);
    if (!rc) {
        p->num_m = m;
        rc = sf_unum_sweep_num(p);
    }
    if (rc)
        unum_clear(p);
    return rc;
}
