/* The QoIs the paper's claims compare, from one run's result and history,
 * under every definition at once (claims.h: ours, the paper's Sec. 3.1
 * ones and the sensitivity column's alternatives); claims_engine.c runs
 * the sweep and judges the claims on them. */
#include "claims_qoi.h"
#include "oscillator.h"
#include "../stats.h"

#include <math.h>
#include <stdlib.h>

/* The extremum of x between two history rows where vx changes sign: the
 * cubic Hermite interpolant of (x, vx) at both ends, its stationary point
 * (the rows are step ends; the solver's own extrema are events that are
 * not rows: without this, PV_x from rows is 0.1-0.4% short). */
static double hermite_extremum(double t0, double x0, double v0, double t1, double x1, double v1)
{
    double h = t1 - t0;
    double a = 6 * x0 + 3 * h * v0 - 6 * x1 + 3 * h * v1, b = -6 * x0 - 4 * h * v0 + 6 * x1 - 2 * h * v1, c = h * v0;
    double sr[2];
    int nr = 0;
    if (fabs(a) < 1e-300) {
        if (b != 0)
            sr[nr++] = -c / b;
    } else {
        double d = b * b - 4 * a * c;
        if (d >= 0) {
            double q = -0.5 * (b + copysign(sqrt(d), b));
            sr[nr++] = q / a;
            if (q != 0)
                sr[nr++] = c / q;
        }
    }
    for (int i = 0; i < nr; i++) {
        double u = sr[i];
        if (u > 0 && u < 1) {
            double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
                   h11 = u * u * (u - 1);
            return h00 * x0 + h10 * h * v0 + h01 * x1 + h11 * h * v1;
        }
    }
    return fabs(v0) < fabs(v1) ? x0 : x1;
}

/* Stick time inside [t0, T] from the transitions: every stick span,
 * complete or not (the paper's t_sk). */
static double window_stick(const double *ts, size_t ns, const double *tl, size_t nl, double t0, double T)
{
    double st = 0;
    size_t il = 0;
    for (size_t i = 0; i < ns; i++) {
        while (il < nl && tl[il] <= ts[i])
            il++;
        double a = fmax(ts[i], t0), b = fmin(il < nl ? tl[il] : T, T);
        if (b > a)
            st += b - a;
    }
    return st;
}

/* Mean and (n - 1) variance of v[i] over the i with t[i] >= t0; *m the count. */
static void mean_after(const double *v, const double *t, size_t n, double t0, double *mean, double *var, size_t *m)
{
    double s = 0, q = 0;
    *m = 0;
    for (size_t i = 0; i < n; i++)
        if (t[i] >= t0) {
            s += v[i];
            (*m)++;
        }
    *mean = *m ? s / (double)*m : NAN;
    for (size_t i = 0; i < n; i++)
        if (t[i] >= t0)
            q += (v[i] - *mean) * (v[i] - *mean);
    *var = *m > 1 ? q / (double)(*m - 1) : NAN;
}

/* See claims_qoi.h. */
void claims_raw_qoi(const sf_osc_result *res, const check_hist *h, double T, double tskip, double tlate,
                    double *out)
{
    for (size_t i = 0; i < NOUT; i++)
        out[i] = NAN;
    size_t nt = res->ntrans, ns = 0, nl = 0;
    double *ts = check_alloc((nt + 1) * sizeof *ts), *tl = check_alloc((nt + 1) * sizeof *tl);
    double *xs = check_alloc((nt + 1) * sizeof *xs);
    for (size_t i = 0; i < nt; i++) {
        if (res->trans_kind[i] == SF_OSC_STICK_ONSET) {
            xs[ns] = res->trans_x[i];
            ts[ns++] = res->trans_t[i];
        } else {
            tl[nl++] = res->trans_t[i];
        }
    }
    /* the solver's cycles (t_skip = 0): cycle i runs from stick onset i to i + 1 */
    int cyc_ok = ns >= 1 && res->ncycles == ns - 1;
    double *cf = check_alloc((res->ncycles + 1) * sizeof *cf);   /* per-cycle stick fractions */
    for (size_t i = 0; i < res->ncycles; i++)
        cf[i] = res->cycle_stick[i] / res->cycle_period[i];
    const double tsk[4] = { tskip, 0, tlate, tskip };
    const int dd[4] = { D_OURS, D_TSKIP0, D_TSKIP_LATE, D_CYCLES };
    for (int k = 0; k < 4; k++) {
        double *o = out + dd[k] * NQ, v;
        size_t m;
        /* stick per cycle (every definition's Q_TSTK; the cycles' stick fraction) */
        double st = 0, sp = 0;
        size_t mc = 0;
        for (size_t i = 0; cyc_ok && i < res->ncycles; i++)
            if (ts[i] >= tsk[k]) {
                st += res->cycle_stick[i];
                sp += res->cycle_period[i];
                mc++;
            }
        o[Q_TSTK] = mc ? st / (double)mc : NAN;
        o[Q_TSK] = window_stick(ts, ns, tl, nl, tsk[k], T);
        size_t no = 0, nslide = 0;
        for (size_t i = 0; i < res->nosc; i++)
            if (res->osc_t[i] >= tsk[k]) {
                no++;
                nslide += res->osc_stick[i] == 0;
            }
        o[Q_SLIDE] = no ? (double)nslide / (double)no : NAN;
        if (dd[k] == D_CYCLES) {   /* PV per complete cycle, stick over the cycles */
            mean_after(res->cycle_pv_x, ts, cyc_ok ? res->ncycles : 0, tsk[k], &o[Q_PVX], &v, &m);
            mean_after(res->cycle_pv_F, ts, cyc_ok ? res->ncycles : 0, tsk[k], &o[Q_PVF], &v, &m);
            o[Q_SF] = o[Q_SFABS] = mc ? st / sp : NAN;
        } else {   /* the paper's: PV per oscillation, T_sk over the window */
            mean_after(res->osc_pv_x, res->osc_t, res->nosc, tsk[k], &o[Q_PVX], &v, &m);
            if (k == 0)
                out[ND_RAW * NQ + 0] = v;
            mean_after(res->osc_pv_F, res->osc_t, res->nosc, tsk[k], &o[Q_PVF], &v, &m);
            if (k == 0)
                out[ND_RAW * NQ + 1] = v;
            o[Q_SF] = o[Q_SFABS] = T > tsk[k] ? o[Q_TSK] / (T - tsk[k]) : NAN;
            if (k == 0) {
                double mm;
                mean_after(cf, ts, cyc_ok ? res->ncycles : 0, tsk[k], &mm, &v, &m);
                out[ND_RAW * NQ + 2] = v;
            }
        }
        size_t nb;
        double bv;
        mean_after(xs, ts, ns, tsk[k], &o[Q_BIFMEAN], &bv, &nb);
        o[Q_BIFSD] = o[Q_BIFREL] = sqrt(bv);
        o[Q_BIFN] = (double)nb;
    }
    /* cycles cut at slip onset, from the history rows: cycle j runs from
     * slip onset j (its first slip row) to slip onset j + 1 (its last
     * stick row); its stick phase is the one that ends at j + 1 */
    {
        double sx = 0, sF = 0, st = 0, sp = 0;
        size_t m = 0, r0 = 0;
        for (size_t j = 0; j + 1 < nl; j++) {
            if (tl[j] < tskip)
                continue;
            double xmn = INFINITY, xmx = -INFINITY, Fmn = INFINITY, Fmx = -INFINITY;
            while (r0 < h->n && (h->t[r0] < tl[j] || (h->t[r0] == tl[j] && h->stick[r0])))
                r0++;
            for (size_t r = r0; r < h->n && h->t[r] <= tl[j + 1]; r++) {
                if (h->t[r] == tl[j + 1] && !h->stick[r])
                    break;
                xmn = sf_min(xmn, h->x[r]);
                xmx = sf_max(xmx, h->x[r]);
                if (r + 1 < h->n && h->t[r + 1] <= tl[j + 1] && !h->stick[r] && !h->stick[r + 1] &&
                    h->t[r + 1] > h->t[r] && (h->vx[r] > 0) != (h->vx[r + 1] > 0)) {
                    double xe = hermite_extremum(h->t[r], h->x[r], h->vx[r], h->t[r + 1], h->x[r + 1], h->vx[r + 1]);
                    xmn = sf_min(xmn, xe);
                    xmx = sf_max(xmx, xe);
                }
                Fmn = sf_min(Fmn, h->Fx[r]);
                Fmx = sf_max(Fmx, h->Fx[r]);
            }
            double on = NAN;   /* the last stick onset inside the cycle */
            for (size_t i = 0; i < ns; i++)
                if (ts[i] > tl[j] && ts[i] < tl[j + 1])
                    on = ts[i];
            if (!isfinite(on) || !isfinite(xmx))
                continue;
            sx += xmx - xmn;
            sF += Fmx - Fmn;
            st += tl[j + 1] - on;
            sp += tl[j + 1] - tl[j];
            m++;
        }
        double *o = out + D_SLIPCUT * NQ;
        for (int q = 0; q < NQ; q++)
            o[q] = out[D_CYCLES * NQ + q];
        o[Q_PVX] = o[Q_PVF] = o[Q_SF] = o[Q_SFABS] = o[Q_TSTK] = NAN;
        if (m) {
            o[Q_PVX] = sx / (double)m;
            o[Q_PVF] = sF / (double)m;
            o[Q_SF] = o[Q_SFABS] = st / sp;
            o[Q_TSTK] = st / (double)m;
        }
    }
    for (int q = 0; q < NQ; q++)   /* pooled: the per-realisation values are ours */
        out[D_POOLED * NQ + q] = out[D_OURS * NQ + q];
    free(cf);
    free(ts);
    free(tl);
    free(xs);
}
