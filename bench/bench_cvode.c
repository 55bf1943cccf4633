/* SUNDIALS CVODE peer of the stick-slip integrator: see cvode_peer.h for
 * the model (the solver's own pieces, oscillator.h) and how it matches
 * solver/dynamics/oscillator.c. */
#include "cvode_peer.h"

#if SF_HAVE_CVODE

#include "oscillator.h"
#include "sf_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

/* CVODE's components in the solver's state vector: 1-D integrates (x, vx)
 * only (y, phi, vy, w stay 0 in that model, and a 2-vector keeps CVODE's
 * error norm on the two components that move); 3-DOF all of it. */
static const int comp_1d[2] = { SF_OSC_X, SF_OSC_VX };
static const int comp_3d[SF_OSC_NSTATE] = { SF_OSC_X,  SF_OSC_Y, SF_OSC_PHI,  SF_OSC_VX,
                                            SF_OSC_VY, SF_OSC_W, SF_OSC_WORK };

struct sf_cvpeer {
    sf_scene s;
    int method, n;           /* n components integrated by CVODE, comp[0 .. n) of the state */
    const int *comp;
    double rtol;
    sf_osc *o;               /* the solver's plan: the model */
    double full[SF_OSC_NSTATE];   /* the solver's state vector (1-D: scratch of rhs and root too) */
    SUNContext ctx;
    N_Vector y, atol, dky;
    SUNMatrix A;
    SUNLinearSolver LS;
    SUNNonlinearSolver NLS;
    void *mem;
    char msg[200];   /* CVODE's last error message */
};

static int seterr(char *err, size_t n, const char *what, const char *detail)
{
    return sf_seterr(err, n, 1, "CVODE peer: %s%s%s", what, detail && *detail ? ": " : "", detail ? detail : "");
}

/* CVODE's vector y into the solver's state vector full and back */
static void to_full(const sf_cvpeer *p, const double *y, double *full)
{
    for (int i = 0; i < p->n; i++)
        full[p->comp[i]] = y[i];
}

static void from_full(const sf_cvpeer *p, const double *full, double *y)
{
    for (int i = 0; i < p->n; i++)
        y[i] = full[p->comp[i]];
}

/* The solver's slip right-hand side (3-DOF: CVODE's vector is the state
 * vector, no copies). */
static int rhs(sunrealtype t, N_Vector yv, N_Vector fv, void *ud)
{
    sf_cvpeer *p = ud;
    const double *y = N_VGetArrayPointer(yv);
    double *f = N_VGetArrayPointer(fv);
    if (p->comp == comp_3d) {
        sf_osc_slip_rhs(p->o, t, y, f, NULL);
        return 0;
    }
    double ff[SF_OSC_NSTATE];
    to_full(p, y, p->full);   /* the frozen components stay as they are */
    sf_osc_slip_rhs(p->o, t, p->full, ff, NULL);
    from_full(p, ff, f);
    return 0;
}

/* 1-D only: the exact Jacobian of (x, vx)' = (vx, (-k x + Fx) / m), the
 * friction force Fx being piecewise constant. */
static int jac_1d(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2,
                  N_Vector t3)
{
    const sf_cvpeer *p = ud;
    (void)t, (void)y, (void)fy, (void)t1, (void)t2, (void)t3;
    SM_ELEMENT_D(J, 0, 0) = 0;
    SM_ELEMENT_D(J, 0, 1) = 1;
    SM_ELEMENT_D(J, 1, 0) = -p->s.k / p->s.m;
    SM_ELEMENT_D(J, 1, 1) = 0;
    return 0;
}

/* The solver's slip-to-stick switching function. */
static int root(sunrealtype t, N_Vector yv, sunrealtype *g, void *ud)
{
    sf_cvpeer *p = ud;
    const double *y = N_VGetArrayPointer(yv);
    if (p->comp == comp_3d) {
        g[0] = sf_osc_g_stick(p->o, t, y);
        return 0;
    }
    to_full(p, y, p->full);
    g[0] = sf_osc_g_stick(p->o, t, p->full);
    return 0;
}

static void on_error(int code, const char *module, const char *function, char *msg, void *ud)
{
    sf_cvpeer *p = ud;
    snprintf(p->msg, sizeof p->msg, "%s %s (%d): %s", module, function, code, msg);
}

void sf_cvpeer_free(sf_cvpeer *p)
{
    if (!p)
        return;
    if (p->mem)
        CVodeFree(&p->mem);
    if (p->LS)
        SUNLinSolFree(p->LS);
    if (p->NLS)
        SUNNonlinSolFree(p->NLS);
    if (p->A)
        SUNMatDestroy(p->A);
    if (p->y)
        N_VDestroy(p->y);
    if (p->atol)
        N_VDestroy(p->atol);
    if (p->dky)
        N_VDestroy(p->dky);
    if (p->ctx)
        SUNContext_Free(&p->ctx);
    sf_osc_free(p->o);
    free(p);
}

int sf_cvpeer_alloc(const sf_scene *s, const sf_cof *cof, int method, double rtol, sf_cvpeer **out, char *err,
                    size_t errlen)
{
    *out = NULL;
    sf_cvpeer *p = calloc(1, sizeof *p);
    if (!p)
        return seterr(err, errlen, "out of memory", NULL);
    p->s = *s;
    p->method = method;
    p->rtol = rtol;
    int d1 = s->dof == SF_DOF_1;
    p->comp = d1 ? comp_1d : comp_3d;
    p->n = d1 ? 2 : SF_OSC_NSTATE;
    char e[200] = "";
    if (sf_osc_alloc(s, cof, &p->o, e, sizeof e)) {
        sf_cvpeer_free(p);
        return seterr(err, errlen, "the solver's plan", e);
    }
    int rc = 0;
    if (SUNContext_Create(NULL, &p->ctx) || !(p->y = N_VNew_Serial(p->n, p->ctx)) ||
        !(p->atol = N_VNew_Serial(p->n, p->ctx)) || !(p->dky = N_VNew_Serial(p->n, p->ctx)) ||
        !(p->mem = CVodeCreate(method == SF_CVPEER_ADAMS ? CV_ADAMS : CV_BDF, p->ctx))) {
        sf_cvpeer_free(p);
        return seterr(err, errlen, "cannot create the context, vectors or solver memory", NULL);
    }
    double sc[SF_OSC_NSTATE], *a = N_VGetArrayPointer(p->atol);
    N_VConst(0, p->y);
    sf_osc_scales(p->o, sc);
    for (int i = 0; i < p->n; i++)
        a[i] = rtol * sc[p->comp[i]];
    int dir = -1;   /* slip -> stick only: the switching function falls through zero */
    rc |= CVodeSetErrHandlerFn(p->mem, on_error, p);
    rc |= CVodeInit(p->mem, rhs, 0, p->y);
    rc |= CVodeSetUserData(p->mem, p);
    rc |= CVodeSVtolerances(p->mem, rtol, p->atol);
    rc |= CVodeSetMaxNumSteps(p->mem, 10000000L);
    rc |= CVodeRootInit(p->mem, 1, root);
    rc |= CVodeSetRootDirection(p->mem, &dir);
    rc |= CVodeSetNoInactiveRootWarn(p->mem);
    if (method == SF_CVPEER_ADAMS) {
        p->NLS = SUNNonlinSol_FixedPoint(p->y, 0, p->ctx);
        rc |= !p->NLS || CVodeSetNonlinearSolver(p->mem, p->NLS);
    } else {
        p->A = SUNDenseMatrix(p->n, p->n, p->ctx);
        p->LS = p->A ? SUNLinSol_Dense(p->y, p->A, p->ctx) : NULL;
        rc |= !p->LS || CVodeSetLinearSolver(p->mem, p->LS, p->A);
        if (d1)
            rc |= CVodeSetJacFn(p->mem, jac_1d);
    }
    if (rc) {
        seterr(err, errlen, "set-up failed", p->msg);
        sf_cvpeer_free(p);
        return 1;
    }
    *out = p;
    return 0;
}

void sf_cvpeer_result_free(sf_cvpeer_result *r)
{
    if (!r)
        return;
    free(r->trans_t);
    free(r->trans_kind);
    free(r->x_samples);
    memset(r, 0, sizeof *r);
}

static int record(sf_cvpeer_result *r, size_t *cap, int kind, double t)
{
    if (r->ntrans == *cap) {
        size_t c = *cap ? 2 * *cap : 64;
        double *tt = realloc(r->trans_t, c * sizeof *tt);
        if (tt)
            r->trans_t = tt;
        int *kk = realloc(r->trans_kind, c * sizeof *kk);
        if (kk)
            r->trans_kind = kk;
        if (!tt || !kk)
            return 1;
        *cap = c;
    }
    r->trans_t[r->ntrans] = t;
    r->trans_kind[r->ntrans] = kind;
    r->ntrans++;
    return 0;
}

/* Add CVODE's counters of the slip phase just ended (CVodeReInit resets them). */
static void count(sf_cvpeer *p, sf_cvpeer_result *r)
{
    long n;
    if (!CVodeGetNumSteps(p->mem, &n)) r->steps += n;
    if (!CVodeGetNumRhsEvals(p->mem, &n)) r->fevals += n;
    if (!CVodeGetNumGEvals(p->mem, &n)) r->gevals += n;
    if (!CVodeGetNumErrTestFails(p->mem, &n)) r->err_fails += n;
    if (!CVodeGetNumNonlinSolvConvFails(p->mem, &n)) r->nl_fails += n;
    if (p->method == SF_CVPEER_BDF && !CVodeGetNumJacEvals(p->mem, &n)) r->jevals += n;
    if (p->method == SF_CVPEER_BDF && !CVodeGetNumLinRhsEvals(p->mem, &n)) r->fevals += n;
}

/* The samples due up to t1 in a slip phase (the earlier ones are taken):
 * CVODE's interpolant of its last step (CVodeGetDky; x is component 0 in
 * both layouts). */
static int sample_slip(sf_cvpeer *p, sf_cvpeer_result *r, size_t *next, double t1)
{
    while (*next < r->nsamples && (double)*next * r->sample_dt <= t1) {
        if (CVodeGetDky(p->mem, (double)*next * r->sample_dt, 0, p->dky))
            return 1;
        r->x_samples[(*next)++] = N_VGetArrayPointer(p->dky)[0];
    }
    return 0;
}

/* ... and of a stick phase from (t0, x0): the exact motion with the belt */
static void sample_stick(const sf_cvpeer *p, sf_cvpeer_result *r, size_t *next, double t0, double x0, double t1)
{
    while (*next < r->nsamples && (double)*next * r->sample_dt <= t1) {
        r->x_samples[*next] = x0 + p->s.v_b * ((double)*next * r->sample_dt - t0);
        (*next)++;
    }
}

int sf_cvpeer_run(sf_cvpeer *p, double sample_dt, sf_cvpeer_result *r, char *err, size_t errlen)
{
    const sf_scene *s = &p->s;
    memset(r, 0, sizeof *r);
    size_t cap = 0, next = 0;
    if (sample_dt > 0) {   /* the solver's grid (sf_osc_run) */
        r->sample_dt = sample_dt;
        r->nsamples = (size_t)floor(s->T / sample_dt) + 1;
        if (!(r->x_samples = calloc(r->nsamples, sizeof *r->x_samples)))
            return seterr(err, errlen, "out of memory", NULL);
        r->x_samples[next++] = 0;
    }
    /* one step per call when sampling (the interpolant is the last step's) */
    int mode = sample_dt > 0 ? CV_ONE_STEP : CV_NORMAL;
    double t = 0, *y = N_VGetArrayPointer(p->y), *full = p->full;
    memset(full, 0, sizeof p->full);
    int stick = sf_osc_g_stick(p->o, 0, full) < 0;
    if (stick) {   /* a belt slower than eps_lambda omega_n R: stick from the start (Eq. 12) */
        sf_osc_stick_onset(p->o, full);
        if (record(r, &cap, SF_OSC_STICK_ONSET, 0))
            return seterr(err, errlen, "out of memory", NULL);
    }
    while (t < s->T) {
        if (stick) {   /* exact motion with the belt, the solver's break */
            double t1 = fmin(t + sf_osc_stick_duration(p->o, t, full), s->T);
            sample_stick(p, r, &next, t, full[SF_OSC_X], t1);
            sf_osc_stick_move(p->o, full, t1 - t);
            t = t1;
            if (t >= s->T)
                break;
            if (record(r, &cap, SF_OSC_SLIP_ONSET, t))
                return seterr(err, errlen, "out of memory", NULL);
            sf_osc_slip_onset(p->o, full);   /* Eq. 14 */
            stick = 0;
            continue;
        }
        from_full(p, full, y);
        if (CVodeReInit(p->mem, t, p->y) || CVodeSetStopTime(p->mem, s->T))
            return seterr(err, errlen, "CVodeReInit failed", p->msg);
        int flag;
        do {
            sunrealtype tr = t;
            flag = CVode(p->mem, s->T, p->y, &tr, mode);
            if (flag < 0) {
                char m[300];
                count(p, r);
                snprintf(m, sizeof m, "CVode failed at t = %.9g s (flag %d) %s", (double)tr, flag, p->msg);
                return seterr(err, errlen, m, NULL);
            }
            t = tr;
            if (sample_slip(p, r, &next, t))
                return seterr(err, errlen, "CVodeGetDky failed", p->msg);
        } while (flag == CV_SUCCESS && t < s->T);
        count(p, r);
        to_full(p, y, full);
        if (flag == CV_ROOT_RETURN) {   /* slip -> stick: Eq. 12 */
            sf_osc_stick_onset(p->o, full);
            stick = 1;
            if (record(r, &cap, SF_OSC_STICK_ONSET, t))
                return seterr(err, errlen, "out of memory", NULL);
        } else {
            t = s->T;   /* CV_TSTOP_RETURN (or CV_SUCCESS at tout = T) */
        }
    }
    return 0;
}

#else
typedef int sf_cvpeer_absent;   /* ISO C: a translation unit must declare something */
#endif
