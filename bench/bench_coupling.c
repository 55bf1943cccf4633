/* Two couplings that could make a realisation of the Fig. 11 grid cheaper
 * to average (Table 1, T = 100 s), measured, not estimators of the
 * product: per l/R, NF fields drawn as a sweep draws them.
 *
 * Antithetic fields: each drawn COF and its antithetic, the field of -G
 * (exp(2 mu_g) / mu for the lognormal map mu = exp(mu_g + sigma_g G);
 * 2 mubar - mu for cell averages, mubar + sd G), run on the scene's plan;
 * rho = corr(Q(G), Q(-G)) per ratio and the CPU a pair mean saves against
 * plain Monte Carlo at the same variance, 2 (d + r) / ((d + 2r)(1 + rho)),
 * d a draw's CPU, r a run's.
 *
 * A coarser field: the drawn field at every k-th node (exactly the law of
 * the field drawn on the k-times coarser grid), run on the two-level
 * estimator's coarse plan (mlmc.h); Var(Q_f - Q_c) / Var Q_f per ratio,
 * the coarse draw's CPU (a COF plan on that grid) and run's, and Giles'
 * cost ratio against plain, Var Q_f C_f / (sqrt(V_0 C_0) + sqrt(V_1
 * C_1))^2 (the spreads taken as exact, no pilot).  CPU of this thread. */
#include "bench.h"
#include "cof.h"
#include "lognormal.h"
#include "mlmc.h"
#include "montecarlo.h"
#include "scene.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

enum { NPTS = BENCH_FIG11_NPTS, NF = 30, NK = 3, NQ = SF_SWEEP_NQ, NPLAIN = 100 };
static const size_t kf[NK] = { 2, 4, 8 };

/* the subsample of grid COF f at every k-th node, or its antithetic (k = 0) */
static int derived(const sf_cof *f, size_t k, const sf_lognormal *ln, double mubar, sf_cof **out)
{
    size_t m, n;
    double x0, y0, dx, dy;
    const double *mu;
    if (sf_cof_grid_view(f, &m, &n, &x0, &y0, &dx, &dy, &mu))
        return 1;
    size_t s = k ? k : 1, mc = (m + s - 1) / s, nc = (n + s - 1) / s;
    double *v = malloc(mc * nc * sizeof *v), box = sf_cof_box(f);
    if (!v)
        return 1;
    for (size_t j = 0; j < nc; j++)
        for (size_t i = 0; i < mc; i++) {
            double x = mu[s * i + m * s * j];
            v[i + mc * j] = k ? x : box > 0 ? 2 * mubar - x : exp(2 * ln->mu_g) / x;
        }
    int rc = sf_cof_alloc_grid(mc, nc, x0, y0, s * dx, s * dy, v, out);
    free(v);
    return rc || (box > 0 && sf_cof_set_box(*out, box));
}

static double var_of(const double *x, size_t m) { return m > 1 ? gsl_stats_variance(x, 1, m) : NAN; }

int bench_coupling(FILE *f, const char *dir)
{
    (void)dir;
    sf_scene s0;
    bench_fig11_scene(&s0);
    fprintf(f, "## Couplings for a cheaper estimator (Fig. 11 grid)\n\n"
               "Table 1, T = 100 s; %d fields per l/R, drawn as a sweep draws them; CPU of one thread. "
               "Antithetic: rho = corr(Q(G), Q(-G)) of each ratio (PV_x's 95%% Fisher interval), d a draw's CPU, "
               "r a run's, the CPU a pair mean saves at plain's variance, 2 (d + r) / ((d + 2r)(1 + rho)), worst "
               "ratio, and at rho = 0 (the shared draw alone). Coarser field: the field at every k-th node, run "
               "on the two-level coarse plan; Var(Q_f - Q_c) / Var Q_f (worst ratio), the coarse draw + run CPU, "
               "Giles' cost ratio against plain (worst ratio). Grid: plain's CPU is %d (d + r) a point.\n\n"
               "| l/R | d [s] | r [s] | rho PV_x | rho PV_F | rho T_sk | antithetic | (rho = 0) |",
            NF, NPLAIN);
    for (int k = 0; k < NK; k++)
        fprintf(f, " k = %zu: V1/Vf | draw + run [s] | ratio |", kf[k]);
    fprintf(f, "\n|---|---|---|---|---|---|---|---|");
    for (int k = 0; k < NK; k++)
        fprintf(f, "---|---|---|");
    fputc('\n', f);
    double t_plain = 0, t_anti = 0, t_coarse = 0;
    int rc = 0;
    for (int p = 0; p < NPTS && !rc; p++) {
        sf_scene s = s0;
        char err[256] = "";
        double det[NQ];
        sf_plan pl, plc;
        memset(&pl, 0, sizeof pl);
        sf_cof_plan *cp = NULL, *cc[NK] = { NULL };
        sf_lognormal ln;
        rc = sf_sweep_set(&s, "l_over_R", bench_fig11_lr[p], err, sizeof err) || sf_sweep_det(&s, det, err, sizeof err) ||
             sf_plan_make(&s, &pl, err, sizeof err) || sf_lognormal_init(&ln, s.mu_mean, s.mu_std);
        pl.history = 0;
        sf_mlmc_coarse_plan(&pl, &plc);
        rc = rc || sf_cof_plan_build(&s, &pl, &cp, err, sizeof err);
        int nk = 0;   /* the k whose coarse grid keeps 4 x 4 nodes */
        for (int k = 0; k < NK && !rc; k++) {   /* the field drawn on the coarser grid itself */
            sf_plan pk = pl;
            const sf_cof_plan_info *in = sf_cof_plan_get_info(cp);
            if (in->nx < 4 * kf[k] || in->ny < 4 * kf[k])
                break;
            nk = k + 1;
            pk.cof.nx = (in->nx + kf[k] - 1) / kf[k];
            pk.cof.ny = (in->ny + kf[k] - 1) / kf[k];
            pk.cof.dx = kf[k] * in->dx;
            pk.cof.dy = kf[k] * in->dy;
            rc = sf_cof_plan_build(&s, &pk, &cc[k], err, sizeof err);
        }
        double *qf = calloc(NF * NQ, sizeof *qf), *qa = calloc(NF * NQ, sizeof *qa);
        double *qc = calloc(NK * NF * NQ, sizeof *qc);
        double td = 0, tr = 0, tdc[NK] = { 0 }, trc[NK] = { 0 };
        gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
        rc = rc || !qf || !qa || !qc || !g;
        if (!rc && sf_cof_plan_get_info(cp)->generator == SF_COFGEN_TILES) {
            fprintf(stderr, "bench: coupling: l/R = %g: a tiled field (no grid to negate or subsample)\n", bench_fig11_lr[p]);
            rc = 1;
        }
        for (int i = 0; i < NF && !rc; i++) {
            sf_cof *c = NULL, *a = NULL;
            gsl_rng_set(g, sf_mc_seed(s.seed, (size_t)i));
            double t0 = bench_cpu();
            rc = sf_cof_plan_draw(cp, g, &c);
            td += bench_cpu() - t0;
            rc = rc || derived(c, 0, &ln, s.mu_mean, &a);
            t0 = bench_cpu();
            rc = rc || sf_sweep_solve(&s, &pl, c, qf + i * NQ, NULL);
            tr += bench_cpu() - t0;
            rc = rc || sf_sweep_solve(&s, &pl, a, qa + i * NQ, NULL);
            sf_cof_free(a);
            for (int k = 0; k < nk && !rc; k++) {
                sf_cof *sub = NULL, *own = NULL;
                rc = derived(c, kf[k], &ln, s.mu_mean, &sub);
                t0 = bench_cpu();
                rc = rc || sf_sweep_solve(&s, &plc, sub, qc + (k * NF + i) * NQ, NULL);
                trc[k] += bench_cpu() - t0;
                t0 = bench_cpu();
                rc = rc || sf_cof_plan_draw(cc[k], g, &own);
                tdc[k] += bench_cpu() - t0;
                sf_cof_free(sub);
                sf_cof_free(own);
            }
            sf_cof_free(c);
        }
        if (!rc) {
            double d = td / NF, r = tr / NF, worst = INFINITY, z = gsl_cdf_ugaussian_Pinv(0.975);
            fprintf(f, "| %g | %.4f | %.4f |", bench_fig11_lr[p], d, r);
            for (int q = 0; q < NQ; q++) {
                double x[NF], y[NF];
                size_t m = 0;
                for (int i = 0; i < NF; i++)
                    if (isfinite(qf[i * NQ + q]) && isfinite(qa[i * NQ + q])) {
                        x[m] = qf[i * NQ + q] / det[q];
                        y[m++] = qa[i * NQ + q] / det[q];
                    }
                double rho = m > 3 ? gsl_stats_correlation(x, 1, y, 1, m) : NAN, h = z / sqrt((double)m - 3);
                worst = fmin(worst, 2 * (d + r) / ((d + 2 * r) * (1 + rho)));
                if (q == 0)
                    fprintf(f, " %.2f [%.2f, %.2f] |", rho, tanh(atanh(rho) - h), tanh(atanh(rho) + h));
                else
                    fprintf(f, " %.2f |", rho);
            }
            double best = 1;   /* the coarser field's best k, plain where none pays */
            fprintf(f, " %.2f | %.2f |", worst, 2 * (d + r) / (d + 2 * r));
            for (int k = 0; k < nk; k++) {
                double c0 = (tdc[k] + trc[k]) / NF, c1 = d + r + trc[k] / NF, v1max = 0, gk = INFINITY;
                for (int q = 0; q < NQ; q++) {
                    double df[NF], vf[NF], vc[NF];
                    size_t m = 0;
                    for (int i = 0; i < NF; i++) {
                        double a = qf[i * NQ + q] / det[q], b = qc[(k * NF + i) * NQ + q] / det[q];
                        if (isfinite(a) && isfinite(b)) {
                            df[m] = a - b;
                            vf[m] = a;
                            vc[m++] = b;
                        }
                    }
                    double v0 = var_of(vc, m), v1 = var_of(df, m), vq = var_of(vf, m);
                    v1max = fmax(v1max, v1 / vq);
                    gk = fmin(gk, vq * (d + r) / pow(sqrt(v0 * c0) + sqrt(v1 * c1), 2));
                }
                best = fmax(best, gk);
                fprintf(f, " %.2g | %.4f + %.4f | %.2f |", v1max, tdc[k] / NF, trc[k] / NF, gk);
            }
            for (int k = nk; k < NK; k++)   /* a grid too small for this k */
                fputs(" - | - | - |", f);
            fputc('\n', f);
            t_plain += NPLAIN * (d + r);
            t_anti += NPLAIN * (d + r) / fmax(worst, 1);
            t_coarse += NPLAIN * (d + r) / best;
            fprintf(stderr, "bench: coupling: l/R = %g: d %.3f s, r %.3f s, antithetic %.2fx, coarser field %.2fx\n",
                    bench_fig11_lr[p], d, r, worst, best);
        } else {
            fprintf(stderr, "bench: coupling: l/R = %g: %s\n", bench_fig11_lr[p], err);
        }
        gsl_rng_free(g);
        free(qf);
        free(qa);
        free(qc);
        sf_cof_plan_free(cp);
        for (int k = 0; k < NK; k++)
            sf_cof_plan_free(cc[k]);
    }
    if (rc) {
        fprintf(f, "\nThe measurement failed (see stderr).\n");
        return 1;
    }
    fprintf(f, "\nWhole grid, projected from the per-point ratios (plain where a coupling does not pay): plain %.1f s, "
               "antithetic %.1f s (%.2fx), a coarser field's two levels at each point's best k %.1f s (%.2fx).\n",
            t_plain, t_anti, t_plain / t_anti, t_coarse, t_plain / t_coarse);
    return 0;
}
