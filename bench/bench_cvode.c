/* SUNDIALS CVODE peer of the 1-D stick-slip integrator: see cvode_peer.h
 * for the model and how it matches solver/oscillator.c. */
#include "cvode_peer.h"

#if SF_HAVE_CVODE

#include "oscillator.h"

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

struct sf_cvpeer {
    sf_scene s;
    int method;
    double rtol;
    double mu, muk, N, wn, delta, xs;   /* static COF, kinetic COF, m g, omega_n, eps omega_n R, mu m g / k */
    SUNContext ctx;
    N_Vector y, atol;
    SUNMatrix A;
    SUNLinearSolver LS;
    SUNNonlinearSolver NLS;
    void *mem;
    char msg[200];   /* CVODE's last error message */
};

static int seterr(char *err, size_t n, const char *what, const char *detail)
{
    if (err && n)
        snprintf(err, n, "CVODE peer: %s%s%s", what, detail && *detail ? ": " : "", detail ? detail : "");
    return 1;
}

/* Eqs. 3-4 */
static int rhs(sunrealtype t, N_Vector yv, N_Vector fv, void *ud)
{
    const sf_cvpeer *p = ud;
    const double *y = N_VGetArrayPointer(yv);
    double *f = N_VGetArrayPointer(fv), u = y[1] - p->s.v_b;
    double Fx = u > 0 ? -p->muk * p->N : (u < 0 ? p->muk * p->N : 0);
    (void)t;
    f[0] = y[1];
    f[1] = (-p->s.k * y[0] + Fx) / p->s.m;
    return 0;
}

/* The exact Jacobian (the friction force is piecewise constant). */
static int jac(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2, N_Vector t3)
{
    const sf_cvpeer *p = ud;
    (void)t, (void)y, (void)fy, (void)t1, (void)t2, (void)t3;
    SM_ELEMENT_D(J, 0, 0) = 0;
    SM_ELEMENT_D(J, 0, 1) = 1;
    SM_ELEMENT_D(J, 1, 0) = -p->s.k / p->s.m;
    SM_ELEMENT_D(J, 1, 1) = 0;
    return 0;
}

/* The solver's slip-to-stick switching function (g_stick in
 * oscillator.c, 1-D: lambda = |vx - v_b| / (omega_n R)). */
static double g_stick(const sf_cvpeer *p, const double *y)
{
    double c = fabs(y[1] - p->s.v_b) / (p->wn * p->s.R) - p->s.eps_lambda;
    if (c >= 0)
        return c;
    double margin = p->mu * p->N - p->s.k * fabs(y[0]);
    return fmax(c, -margin / p->N);
}

static int root(sunrealtype t, N_Vector yv, sunrealtype *g, void *ud)
{
    (void)t;
    g[0] = g_stick(ud, N_VGetArrayPointer(yv));
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
    if (p->ctx)
        SUNContext_Free(&p->ctx);
    free(p);
}

int sf_cvpeer_alloc(const sf_scene *s, const sf_cof *cof, int method, double rtol, sf_cvpeer **out, char *err,
                    size_t errlen)
{
    *out = NULL;
    if (s->dof != SF_DOF_1 || sf_cof_get_kind(cof) == SF_COF_FIELD)
        return seterr(err, errlen, "only the 1-D model (dof = 1) with a constant COF", NULL);
    sf_cvpeer *p = calloc(1, sizeof *p);
    if (!p)
        return seterr(err, errlen, "out of memory", NULL);
    p->s = *s;
    p->method = method;
    p->rtol = rtol;
    p->mu = sf_cof_eval(cof, 0, 0);
    p->muk = s->mu_k_ratio * p->mu;
    p->N = s->m * s->g;
    p->wn = sqrt(s->k / s->m);
    p->delta = s->eps_lambda * p->wn * s->R;
    p->xs = p->mu * p->N / s->k;
    int rc = 0;
    if (SUNContext_Create(NULL, &p->ctx) || !(p->y = N_VNew_Serial(2, p->ctx)) ||
        !(p->atol = N_VNew_Serial(2, p->ctx)) ||
        !(p->mem = CVodeCreate(method == SF_CVPEER_ADAMS ? CV_ADAMS : CV_BDF, p->ctx))) {
        sf_cvpeer_free(p);
        return seterr(err, errlen, "cannot create the context, vectors or solver memory", NULL);
    }
    double *y = N_VGetArrayPointer(p->y), *a = N_VGetArrayPointer(p->atol);
    y[0] = y[1] = 0;
    /* the solver's scales: x_s for x, x_s omega_n for vx */
    double xs = fmax((s->mu_mean + s->mu_std) * p->N / s->k, 1e-300);
    a[0] = rtol * xs;
    a[1] = rtol * xs * p->wn;
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
        p->A = SUNDenseMatrix(2, 2, p->ctx);
        p->LS = p->A ? SUNLinSol_Dense(p->y, p->A, p->ctx) : NULL;
        rc |= !p->LS || CVodeSetLinearSolver(p->mem, p->LS, p->A);
        rc |= CVodeSetJacFn(p->mem, jac);
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
}

int sf_cvpeer_run(sf_cvpeer *p, sf_cvpeer_result *r, char *err, size_t errlen)
{
    const sf_scene *s = &p->s;
    memset(r, 0, sizeof *r);
    size_t cap = 0;
    double t = 0, *y = N_VGetArrayPointer(p->y);
    y[0] = y[1] = 0;
    int stick = g_stick(p, y) < 0;
    if (stick) {   /* a belt slower than eps_lambda omega_n R: stick from the start (Eq. 12) */
        y[1] = s->v_b;
        if (record(r, &cap, SF_OSC_STICK_ONSET, 0))
            return seterr(err, errlen, "out of memory", NULL);
    }
    while (t < s->T) {
        if (stick) {   /* exact motion with the belt, closed-form break */
            double tau = y[0] >= p->xs ? 0 : (p->xs - y[0]) / s->v_b, t1 = fmin(t + tau, s->T);
            y[0] += s->v_b * (t1 - t);
            t = t1;
            if (t >= s->T)
                break;
            if (record(r, &cap, SF_OSC_SLIP_ONSET, t))
                return seterr(err, errlen, "out of memory", NULL);
            if (s->velocity_jump)   /* Eq. 14, as the solver writes it for 1-D */
                y[1] = s->v_b - p->delta * cos(atan2(0.0, s->k * y[0]));
            stick = 0;
            continue;
        }
        if (CVodeReInit(p->mem, t, p->y) || CVodeSetStopTime(p->mem, s->T))
            return seterr(err, errlen, "CVodeReInit failed", p->msg);
        sunrealtype tr = t;
        int flag = CVode(p->mem, s->T, p->y, &tr, CV_NORMAL);
        count(p, r);
        if (flag < 0) {
            char m[300];
            snprintf(m, sizeof m, "CVode failed at t = %.9g s (flag %d) %s", (double)tr, flag, p->msg);
            return seterr(err, errlen, m, NULL);
        }
        t = tr;
        if (flag == CV_ROOT_RETURN) {   /* slip -> stick: Eq. 12 */
            y[1] = s->v_b;
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
