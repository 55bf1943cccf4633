/* Couplings that could make a realisation of the Fig. 11 grid cheaper to
 * average (Table 1, T = 100 s), measured, not estimators of the product:
 * per l/R, 2 nf fields drawn as a sweep draws them (nf = 30, or
 * SF_BENCH_FIELDS: the cheapest estimator is chosen on one nf and measured
 * on the other; the scene's seed, or SF_BENCH_SEED, for a second run at
 * other seeds).
 *
 * Antithetic fields: each drawn COF and its antithetic, the field of -G
 * (exp(2 mu_g) / mu for the lognormal map mu = exp(mu_g + sigma_g G);
 * 2 mubar - mu for cell averages, mubar + sd G), run on the scene's plan;
 * rho = corr(Q(G), Q(-G)) per ratio and the CPU a pair mean saves against
 * plain Monte Carlo at the same variance, 2 (d + r) / ((d + 2r)(1 + rho)),
 * d a draw's CPU, r a run's.
 *
 * Coarse levels for a two-level estimator, each run on the two-level
 * estimator's coarse plan (mlmc.h: rtol raised) on a field derived from
 * the fine one, whose law is exactly that of a field the coarse level can
 * draw on its own (so both levels' terms are unbiased):
 *  - the same field (k = 1: the built estimator, mlmc.h);
 *  - every k-th node (k = 2, 4, 8): the law of the field drawn on the
 *    k-times coarser grid (the same covariance at the same points);
 *  - b x b boxes (cell averages only, b = 2, 4): the mean of the b^2 fine
 *    box averages that tile a box of side b h is that box's average, so
 *    the coarse values have exactly the covariance of the cell-average
 *    model at box b h (cellavg.h: the covariance is linear in the field),
 *    on a grid of spacing b h / 3 (the model's own) whose nodes are the
 *    centres of the b x b fine boxes; the coarse run's Cartesian
 *    quadrature has cells / b cells per diameter (oscillator.c: the
 *    boxes are the cells, box = 2R / cells), so the fine plan here takes
 *    CA_CELLS = 60 cells (the plan's 59 is not a multiple of 4), and a
 *    strip CA_PAD nodes wider on each side (the coarse grid's nodes sit
 *    inside the fine one's).
 * Per coarse level: Var(Q_f - Q_c) / Var Q_f per ratio, the coarse
 * level's own draw (a COF plan on the coarse grid: its CPU; the same
 * field's draw for k = 1) and run, and the cost ratio against plain of
 * Giles' sizes (cost_ratio), C_0 = coarse draw + run, C_1 = fine draw +
 * run + the derivation + coarse run.  Antithetic pairs inside the two
 * levels: a level's sample is then a pair on G and -G (the derived field
 * of -G is the antithetic of the derived field of G), variance V_l (1 +
 * rho_l) / 2 at the cost of one draw and two runs, at level 0, 1 or both.
 * Per point the cheapest estimator of all, chosen on one half of the
 * fields and measured on the other, and the whole grid's ratio.  CPU of
 * this thread.  Every point's field is the circulant strip (negating or
 * subsampling needs the whole strip), so at l/R = 0.1, where
 * `cof_generator = auto` now takes the tiles, plain here is the
 * circulant's, not the product's (bench_estimators has that). */
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

enum { NPTS = BENCH_FIG11_NPTS, NJ = 6, NQ = SF_SWEEP_NQ, NPLAIN = 100, CA_CELLS = 60, CA_PAD = 8, NMIN = 10,
       NCAND = 2 + 4 * NJ };
/* the coarse levels: subsample stride k (1: the field itself), or b x b boxes */
static const struct { size_t k, b; } cpl[NJ] = { { 1, 0 }, { 2, 0 }, { 4, 0 }, { 8, 0 }, { 0, 2 }, { 0, 4 } };

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

/* coarse level j's field derived from fine field f (k = 1: f itself, *own = 0) */
static int coarse_of(const sf_cof *f, int j, const sf_lognormal *ln, double mubar, const sf_cof **c, sf_cof **own)
{
    *own = NULL;
    if (cpl[j].k == 1) {
        *c = f;
        return 0;
    }
    int rc = cpl[j].b ? sf_cof_box_means(f, cpl[j].b, own) : derived(f, cpl[j].k, ln, mubar, own);
    *c = *own;
    return rc;
}

/* the std of a grid COF's node values (0 for a failed draw) */
static double grid_sd(const sf_cof *c)
{
    size_t m, n;
    const double *mu;
    return c && !sf_cof_grid_view(c, &m, &n, NULL, NULL, NULL, NULL, &mu) ? gsl_stats_sd(mu, 1, m * n) : 0;
}

static const char *level_name(int j, char *buf, size_t len)
{
    if (cpl[j].b)
        snprintf(buf, len, "%u x %u boxes", (unsigned)cpl[j].b, (unsigned)cpl[j].b);
    else if (cpl[j].k == 1)
        snprintf(buf, len, "the same field");
    else
        snprintf(buf, len, "every %u-th node", (unsigned)cpl[j].k);
    return buf;
}

/* per coarse level: what one point measured */
typedef struct {
    int on;                      /* measured at this point */
    sf_plan run;                 /* the coarse run's plan */
    sf_cof_plan *draw;           /* the coarse level's own draw (NULL: the fine draw, k = 1) */
    double *qc, *qca;            /* Q_c on the derived field of G, of -G: nf x NQ */
    double tdc, trc, tder;       /* CPU sums: own draw, coarse run, derivation */
    double sd[2];                /* sums of the node values' std: derived field, own draw */
} level;

/* What a point measured, for the estimators' cost ratios over fields
 * [i0, i1): fine values on G and -G, each level's coarse values, the mean
 * CPU of a fine draw d and run r. */
typedef struct {
    const double *qf, *qa, *det;
    const level *lv;
    double d, r, td;   /* td: the fine draws' CPU sum (k = 1's own draw) */
    size_t nf;   /* fields measured (the mean costs) */
} point;

/* Candidates: 0 plain, 1 antithetic, 2 + 4 j + design: two levels on
 * coarse level j, design bit 1 = antithetic pairs at level 0, bit 2 at
 * level 1 (a level's sample is then a pair on G and -G: variance V_l (1 +
 * rho_l) / 2, one draw and two runs).  The cost ratio against plain at
 * N = NPLAIN: each level's size by Giles' rule for plain's variance of
 * each ratio mean, N_l = NPLAIN sqrt(V_l / C_l) (sum_l sqrt(V_l C_l)) /
 * Var Q_f, the largest over the ratios, at least NMIN (the built
 * estimator's pilot); the spreads taken as measured.  NAN where the
 * candidate was not measured.  v1max, r0, r1 (may be NULL): the worst
 * Var(Q_f - Q_c) / Var Q_f, the largest rho_0, rho_1 over the ratios. */
static double cost_ratio(const point *P, int cand, size_t i0, size_t i1, double *w, double *v1max, double *r0,
                         double *r1)
{
    int j = cand >= 2 ? (cand - 2) / 4 : -1, a0 = (cand - 2) & 1, a1 = ((cand - 2) >> 1) & 1;
    const level *L = j >= 0 ? &P->lv[j] : NULL;
    if (L && !L->on)
        return NAN;
    double nf = (double)P->nf, tdc = L && cpl[j].k == 1 ? P->td : L ? L->tdc : 0;
    double c[2][2] = { { 0, 0 }, { P->d + P->r, P->d + 2 * P->r } };   /* [level][antithetic] */
    if (L) {
        c[0][0] = (tdc + L->trc) / nf;
        c[0][1] = (tdc + 2 * L->trc) / nf;
        c[1][0] = P->d + P->r + (L->tder + L->trc) / nf;
        c[1][1] = P->d + 2 * P->r + 2 * (L->tder + L->trc) / nf;
    }
    double n[2] = { 0, 0 }, wv = 0, x0 = -1, x1 = -1;
    size_t cap = i1 - i0;
    for (int q = 0; q < NQ; q++) {
        double *x = w, *xa = w + cap, *y = w + 2 * cap, *ya = w + 3 * cap, *dy = w + 4 * cap, *dya = w + 5 * cap;
        size_t m = 0;
        for (size_t i = i0; i < i1; i++) {
            double v[4] = { P->qf[i * NQ + q], P->qa[i * NQ + q], L ? L->qc[i * NQ + q] : 0,
                            L ? L->qca[i * NQ + q] : 0 };
            if (!isfinite(v[0] + v[1] + v[2] + v[3]))
                continue;
            x[m] = v[0] / P->det[q];
            xa[m] = v[1] / P->det[q];
            y[m] = v[2] / P->det[q];
            ya[m] = v[3] / P->det[q];
            dy[m] = x[m] - y[m];
            dya[m] = xa[m] - ya[m];
            m++;
        }
        if (m < 4)
            return NAN;
        double vf = gsl_stats_variance(x, 1, m);
        if (!L) {   /* plain, or antithetic pairs of fine runs */
            double rho = gsl_stats_correlation(x, 1, xa, 1, m);
            n[1] = fmax(n[1], cand ? NPLAIN * (1 + rho) / 2 : NPLAIN);
            continue;
        }
        double rho0 = gsl_stats_correlation(y, 1, ya, 1, m), rho1 = gsl_stats_correlation(dy, 1, dya, 1, m);
        double v[2] = { gsl_stats_variance(y, 1, m), gsl_stats_variance(dy, 1, m) };
        wv = fmax(wv, v[1] / vf);
        x0 = fmax(x0, rho0);
        x1 = fmax(x1, rho1);
        v[0] *= a0 ? (1 + rho0) / 2 : 1;
        v[1] *= a1 ? (1 + rho1) / 2 : 1;
        double cl[2] = { c[0][a0], c[1][a1] }, sum = sqrt(v[0] * cl[0]) + sqrt(v[1] * cl[1]);
        for (int l = 0; l < 2; l++)
            n[l] = fmax(n[l], NPLAIN * sqrt(v[l] / cl[l]) * sum / vf);
    }
    if (v1max)
        *v1max = wv;
    if (r0)
        *r0 = x0;
    if (r1)
        *r1 = x1;
    double cost = L ? fmax(ceil(n[0]), NMIN) * c[0][a0] + fmax(ceil(n[1]), NMIN) * c[1][a1]
                    : fmax(ceil(n[1]), cand ? NMIN : NPLAIN) * c[1][cand];
    return NPLAIN * (P->d + P->r) / cost;
}

static void cand_name(int cand, char *buf, size_t len)
{
    static const char *const dn[4] = { "", ", antithetic at level 0", ", antithetic at level 1",
                                       ", antithetic at both" };
    char nm[40];
    if (cand < 2)
        snprintf(buf, len, "%s", cand ? "antithetic" : "plain");
    else
        snprintf(buf, len, "two levels, %s%s", level_name((cand - 2) / 4, nm, sizeof nm), dn[(cand - 2) & 3]);
}

int bench_coupling(FILE *f, const char *dir)
{
    (void)dir;
    sf_scene s0;
    bench_fig11_scene(&s0);
    const size_t nf = bench_env_size("SF_BENCH_FIELDS", 30), nt = 2 * nf;
    s0.seed = (unsigned long)bench_env_size("SF_BENCH_SEED", s0.seed);
    char *tb = NULL, *tc = NULL;
    size_t lb = 0, lc = 0;
    FILE *fb = open_memstream(&tb, &lb), *fc = open_memstream(&tc, &lc);
    if (!fb || !fc)
        return 1;
    fprintf(f, "## Couplings for a cheaper estimator (Fig. 11 grid)\n\n"
               "Table 1, T = 100 s; %zu fields per l/R (seed %lu), drawn as a sweep draws them; CPU of one thread. "
               "At the cell-average points (l/R <= 0.03) the fine plan has %d cells per diameter (the plan's own "
               "is 59; b x b boxes need a multiple of b) and a strip %d nodes wider each side. "
               "Antithetic: rho = corr(Q(G), Q(-G)) of each ratio (PV_x's 95%% Fisher interval), d a draw's CPU, "
               "r a run's, the CPU a pair mean saves at plain's variance, 2 (d + r) / ((d + 2r)(1 + rho)), worst "
               "ratio, and at rho = 0 (the shared draw alone). Grid: plain's CPU is %d (d + r) a point.\n\n"
               "| l/R | d [s] | r [s] | rho PV_x | rho PV_F | rho T_sk | antithetic | (rho = 0) |\n"
               "|---|---|---|---|---|---|---|---|\n",
            nt, s0.seed, CA_CELLS, CA_PAD, NPLAIN);
    fprintf(fb, "\nCoarse levels (two levels, the coarse run on the two-level estimator's coarse plan, on a field "
                "derived from the fine one with the law of the coarse level's own draw): Var(Q_f - Q_c) / Var Q_f "
                "(worst ratio), the coarse level's own draw + run CPU, the cost ratio against plain (Giles' sizes "
                "as in the next table, all fields); rho_0 = corr(Q_c(G), Q_c(-G)) and rho_1 = corr(Y(G), Y(-G)), Y = "
                "Q_f - Q_c (the largest over the ratios), and the ratios with antithetic pairs inside (at level "
                "0 / 1 / both); the node values' std of the derived field over that of the coarse level's own draw "
                "(the law's check; few correlation lengths at l/R >= 1).\n\n"
                "| l/R | coarse level | V1/Vf | draw + run [s] | two levels | rho_0 | rho_1 | "
                "antithetic inside, level 0 / 1 / both | node std, derived / own draw |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    fprintf(fc, "\nThe cheapest estimator per point: plain, antithetic, or two levels on a coarse level above "
                "with or without antithetic pairs inside, each level's size by Giles' rule for plain's variance at "
                "N = %d (the largest over the ratios, at least %d: the built estimator's pilot), the ratio of plain's "
                "CPU to its CPU; chosen on fields 0-%zu (A) and measured on fields %zu-%zu (B), and the other way "
                "round (a choice among %d noisy ratios overstates the winner's on the fields that chose it).\n\n"
                "| l/R | chosen on A | ratio on A | ratio on B | chosen on B | ratio on B | ratio on A | plain CPU, "
                "N = %d [s] |\n|---|---|---|---|---|---|---|---|\n",
            NPLAIN, NMIN, nf - 1, nf, nt - 1, NCAND, NPLAIN);
    double t_plain = 0, t_anti = 0, t_sub = 0, t_best[2] = { 0, 0 };
    int rc = 0;
    for (int p = 0; p < NPTS && !rc; p++) {
        sf_scene s = s0;
        char err[256] = "";
        double det[NQ];
        sf_plan pl, plc;
        memset(&pl, 0, sizeof pl);
        sf_cof_plan *cp = NULL;
        sf_lognormal ln;
        level lv[NJ];
        memset(lv, 0, sizeof lv);
        s.cof_generator = SF_COFGEN_CIRCULANT;   /* the couplings negate or subsample a whole strip */
        rc = sf_sweep_set(&s, "l_over_R", bench_fig11_lr[p], err, sizeof err) ||
             sf_plan_make(&s, &pl, err, sizeof err);
        int ca = !rc && pl.cof_model == SF_PLAN_MODEL_CELL_AVERAGE;
        if (ca) {   /* a fine plan b x b boxes can coarsen */
            s.cof_model = SF_COFMODEL_CELL;
            s.cells = CA_CELLS;
            rc = sf_plan_make(&s, &pl, err, sizeof err);
            pl.cof.x0 -= CA_PAD * pl.cof.dx;
            pl.cof.y0 -= CA_PAD * pl.cof.dy;
            pl.cof.nx += 2 * CA_PAD;
            pl.cof.ny += 2 * CA_PAD;
        }
        rc = rc || sf_sweep_det(&s, det, err, sizeof err) || sf_lognormal_init(&ln, s.mu_mean, s.mu_std);
        pl.history = 0;
        sf_mlmc_coarse_plan(&pl, &plc);
        rc = rc || sf_cof_plan_build(&s, &pl, &cp, err, sizeof err);
        if (!rc && sf_cof_plan_get_info(cp)->generator == SF_COFGEN_TILES) {
            fprintf(stderr, "bench: coupling: l/R = %g: a tiled field (no grid to negate or subsample)\n",
                    bench_fig11_lr[p]);
            rc = 1;
        }
        for (int j = 0; j < NJ && !rc; j++) {   /* each coarse level's own draw and run plan */
            const sf_cof_plan_info *in = sf_cof_plan_get_info(cp);
            sf_plan pk = pl;
            level *L = &lv[j];
            L->run = plc;
            if (cpl[j].b) {
                if (!ca)
                    continue;
                if (sf_cof_box_grid(in, cpl[j].b, &pk.cof))
                    continue;
                L->run.num.cells = CA_CELLS / cpl[j].b;
                L->run.num.cell_size = pk.cof.box;
                L->run.num.box_over_l = pk.cof.box / s.l;
            } else if (cpl[j].k > 1) {
                if (in->nx < 4 * cpl[j].k || in->ny < 4 * cpl[j].k)   /* keep 4 x 4 nodes */
                    continue;
                pk.cof.nx = (in->nx + cpl[j].k - 1) / cpl[j].k;
                pk.cof.ny = (in->ny + cpl[j].k - 1) / cpl[j].k;
                pk.cof.dx = (double)cpl[j].k * in->dx;
                pk.cof.dy = (double)cpl[j].k * in->dy;
            }
            L->on = 1;
            L->qc = calloc(2 * nt * NQ, sizeof *L->qc);
            L->qca = L->qc + nt * NQ;
            rc = !L->qc || (cpl[j].k != 1 && sf_cof_plan_build(&s, &pk, &L->draw, err, sizeof err));
        }
        double *qf = calloc(2 * nt * NQ, sizeof *qf), *qa = qf + nt * NQ;
        double *w = malloc(6 * nt * sizeof *w);   /* per-ratio workspace */
        double td = 0, tr = 0;
        gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
        rc = rc || !qf || !w || !g;
        for (size_t i = 0; i < nt && !rc; i++) {
            sf_cof *c = NULL, *a = NULL;
            gsl_rng_set(g, sf_mc_seed(s.seed, i));
            double t0 = bench_cpu();
            rc = sf_cof_plan_draw(cp, g, &c);
            td += bench_cpu() - t0;
            rc = rc || derived(c, 0, &ln, s.mu_mean, &a);
            t0 = bench_cpu();
            rc = rc || sf_sweep_solve(&s, &pl, c, qf + i * NQ, NULL);
            tr += bench_cpu() - t0;
            rc = rc || sf_sweep_solve(&s, &pl, a, qa + i * NQ, NULL);
            for (int j = 0; j < NJ && !rc; j++) {
                level *L = &lv[j];
                if (!L->on)
                    continue;
                const sf_cof *sub, *suba;
                sf_cof *own = NULL, *owna = NULL, *drawn = NULL;
                t0 = bench_cpu();
                rc = coarse_of(c, j, &ln, s.mu_mean, &sub, &own);
                L->tder += bench_cpu() - t0;
                rc = rc || coarse_of(a, j, &ln, s.mu_mean, &suba, &owna);
                t0 = bench_cpu();
                rc = rc || sf_sweep_solve(&s, &L->run, sub, L->qc + i * NQ, NULL);
                L->trc += bench_cpu() - t0;
                rc = rc || sf_sweep_solve(&s, &L->run, suba, L->qca + i * NQ, NULL);
                if (L->draw) {
                    t0 = bench_cpu();
                    rc = rc || sf_cof_plan_draw(L->draw, g, &drawn);
                    L->tdc += bench_cpu() - t0;
                    L->sd[0] += grid_sd(sub);   /* the law's check: the spread of the nodes */
                    L->sd[1] += grid_sd(drawn);
                }
                sf_cof_free(own);
                sf_cof_free(owna);
                sf_cof_free(drawn);
            }
            sf_cof_free(a);
            sf_cof_free(c);
        }
        if (!rc) {
            double d = td / (double)nt, r = tr / (double)nt, worst = INFINITY, z = gsl_cdf_ugaussian_Pinv(0.975);
            fprintf(f, "| %g | %.4f | %.4f |", bench_fig11_lr[p], d, r);
            for (int q = 0; q < NQ; q++) {
                double *x = w, *y = w + nt;
                size_t m = 0;
                for (size_t i = 0; i < nt; i++)
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
            fprintf(f, " %.2f | %.2f |\n", worst, 2 * (d + r) / (d + 2 * r));
            point P = { qf, qa, det, lv, d, r, td, nt };
            double sub = 1;   /* two levels on every k-th node, the best k (all fields) */
            char nm[40], bn[2][128];
            for (int j = 0; j < NJ; j++) {
                if (!lv[j].on)
                    continue;
                double v1, r0, r1, g0 = cost_ratio(&P, 2 + 4 * j, 0, nt, w, &v1, &r0, &r1), ga[4];
                for (int dsg = 1; dsg < 4; dsg++)
                    ga[dsg] = cost_ratio(&P, 2 + 4 * j + dsg, 0, nt, w, NULL, NULL, NULL);
                fprintf(fb, "| %g | %s | %.2g | %.4f + %.4f | %.2f | %.2f | %.2f | %.2f / %.2f / %.2f | %.4f |\n",
                        bench_fig11_lr[p], level_name(j, nm, sizeof nm), v1,
                        (cpl[j].k == 1 ? td : lv[j].tdc) / (double)nt, lv[j].trc / (double)nt, g0, r0, r1, ga[1],
                        ga[2], ga[3], cpl[j].k == 1 ? 1.0 : lv[j].sd[0] / lv[j].sd[1]);
                if (cpl[j].k > 1)
                    sub = fmax(sub, g0);
            }
            /* the cheapest estimator chosen on one half of the fields and
             * measured on the other (a choice among many noisy ratios
             * overstates the winner's on the fields that chose it) */
            double got[2];
            fprintf(fc, "| %g |", bench_fig11_lr[p]);
            for (int h = 0; h < 2; h++) {
                size_t c0 = h ? nf : 0, m0 = h ? 0 : nf;
                int pick = 0;
                double top = 1;
                for (int cand = 1; cand < NCAND; cand++) {
                    double g = cost_ratio(&P, cand, c0, c0 + nf, w, NULL, NULL, NULL);
                    if (g > top) {
                        top = g;
                        pick = cand;
                    }
                }
                got[h] = cost_ratio(&P, pick, m0, m0 + nf, w, NULL, NULL, NULL);
                cand_name(pick, bn[h], sizeof bn[h]);
                fprintf(fc, " %s | %.2f | %.2f |", bn[h], top, got[h]);
                t_best[h] += NPLAIN * (d + r) / got[h];
            }
            double tp = NPLAIN * (d + r);
            fprintf(fc, " %.1f |\n", tp);
            t_plain += tp;
            t_anti += tp / fmax(worst, 1);
            t_sub += tp / sub;
            fprintf(stderr, "bench: coupling: l/R = %g: d %.3f s, r %.3f s, antithetic %.2fx, cheapest %.2fx (%s), "
                            "%.2fx (%s)\n", bench_fig11_lr[p], d, r, worst, got[0], bn[0], got[1], bn[1]);
        } else {
            fprintf(stderr, "bench: coupling: l/R = %g: %s\n", bench_fig11_lr[p], err);
        }
        gsl_rng_free(g);
        free(qf);
        free(w);
        sf_cof_plan_free(cp);
        for (int j = 0; j < NJ; j++) {
            free(lv[j].qc);
            sf_cof_plan_free(lv[j].draw);
        }
    }
    fclose(fb);
    fclose(fc);
    if (!rc) {
        fwrite(tb, 1, lb, f);
        fwrite(tc, 1, lc, f);
        fprintf(f, "\nWhole grid, projected from the per-point ratios (plain where nothing pays; all %zu fields): "
                   "plain %.1f s, antithetic %.1f s (%.2fx), two levels on every k-th node at each point's best k "
                   "%.1f s (%.2fx). The cheapest estimator per point, chosen on A and measured on B: %.1f s "
                   "(%.2fx); chosen on B and measured on A: %.1f s (%.2fx).\n",
                nt, t_plain, t_anti, t_plain / t_anti, t_sub, t_plain / t_sub, t_best[0], t_plain / t_best[0],
                t_best[1], t_plain / t_best[1]);
        double worst = fmin(t_plain / t_best[0], t_plain / t_best[1]);
        bench_target("Fig. 11 grid: >= 5x less CPU than plain Monte Carlo (coupling: the cheapest estimator per "
                     "point, chosen on half the fields, measured on the other half, projected)", worst >= 5,
                     "%.2fx and %.2fx (%zu + %zu fields a point)", t_plain / t_best[0], t_plain / t_best[1], nf, nf);
    } else {
        fprintf(f, "\nThe measurement failed (see stderr).\n");
    }
    free(tb);
    free(tc);
    return rc ? 1 : 0;
}
