/* Estimators against plain Monte Carlo on the Fig. 11 grid (11 l/R
 * points, T = 100 s, Table 1): per point, plain Monte Carlo with N = 100
 * sets the ratio means' 95% half-widths; the control-variate estimator
 * (sweep.h: sf_sweep_run_cv) then takes a pilot of 20 realisations, reads
 * each ratio's variance reduction factor from it, and runs the N that
 * reaches the plain half-widths (N = ceil(100 / min vrf), 20 <= N <=
 * 100; where the field is a window of tiles there is no companion and the
 * estimator is plain Monte Carlo: its time is the plain time).  CPU time
 * of this process (one thread), each estimator measured in this run; the
 * half-widths each reached are reported beside.  The two-level estimator
 * (mlmc.h) is given plain's standard error of each ratio mean as its
 * target (sweep.h: sf_sweep_run_estimator_se: the half-widths plain
 * reaches, not the variance the estimator would guess for plain from its
 * own level 1), from a pilot of 10 pairs and its stages, at most 100
 * pairs; its CPU includes the pilot.  Per point also where plain's CPU
 * goes: CPU per realisation, the draw's share of it (the work model of
 * mlmc.h) and each ratio's std.  Antithetic pairs (antithetic.h): the
 * same targets, pilot and cap; CPU includes the pilot.
 * Two levels on boxes of boxes (sweep.h: sf_sweep_run_mlmc_boxes,
 * mlmc.h) where the plan draws cell averages, the same target and pilot;
 * and the grid with an estimator chosen by that rule, fixed before this
 * run from the coupling section's measurements: boxes of boxes where the
 * plan draws cell averages, antithetic pairs elsewhere.  Coverage is
 * checked by cases/montecarlo/cv-unbiased*.md, mlmc-unbiased.md,
 * mlmc-boxes-unbiased*.md, anti-unbiased*.md and stein-coverage.md at
 * fresh seeds. */
#include "bench.h"
#include "scene.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NPTS = BENCH_FIG11_NPTS, NPLAIN = 100, NPILOT = 20, NPILOT_ML = 10 };

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *const qn[SF_SWEEP_NQ] = { "PV_x", "PV_F", "T_sk" };

const double bench_fig11_lr[BENCH_FIG11_NPTS] = { 0.01, 0.03, 0.1, 0.2, 0.5, 1, 2, 5, 10, 100, 1000 };

size_t bench_env_size(const char *name, size_t dflt)
{
    const char *e = getenv(name);
    char *end;
    unsigned long v = e ? strtoul(e, &end, 10) : 0;
    return e && *e && !*end && v > 0 ? (size_t)v : dflt;
}

void bench_fig11_scene(sf_scene *s)
{
    sf_scene_default(s);   /* Table 1, the paper's T = 100 s */
    s->cof = SF_COF_FIELD;
    s->T = 100;
    s->t_skip = 10;
}

int bench_estimators(FILE *f, const char *dir)
{
    (void)dir;
    const double *lr = bench_fig11_lr;
    sf_scene s0;
    bench_fig11_scene(&s0);
    s0.seed = (unsigned long)bench_env_size("SF_BENCH_SEED", s0.seed);   /* other fields: a held-out run */
    fprintf(f, "## Estimators against plain Monte Carlo (Fig. 11 grid)\n\n"
               "Table 1, T = 100 s, 11 l/R points (seed %lu; SF_BENCH_SEED=N for other fields); CPU time of one "
               "thread, every estimator in this run. Plain: "
               "N = %d, its 95%% half-widths of the PV_x, PV_F and T_sk ratio means are the targets. Control "
               "variate (`sweep --control-variate`): a pilot of %d gives each ratio's variance reduction factor, "
               "then N = ceil(%d / min factor) (at least %d) realisations; no companion for a tiled field "
               "(plain there). The other estimators are given plain's standard error of each ratio mean as "
               "their target (`sweep --estimator E --target-se X`, X per ratio): a pilot of %d pairs, then "
               "stages that recompute the sizes from every sample so far and at most double a level, at most %d "
               "pairs (level 0: 4x). Two levels (`sweep --estimator mlmc`): n0 coarse realisations and n1 pairs "
               "(fine and coarse plan on one field). Antithetic pairs (`sweep --estimator antithetic`): the field "
               "and its antithetic, -G. Two levels on a derived coarse field "
               "where `sweep --estimator auto` takes one (mlmc-boxes where the plan draws cell averages, mlmc-sub, "
               "every 2nd node, where it draws point values on the circulant strip at l/R < 0.5): the same pilot "
               "and target. "
               "Half-widths reached: the estimator's over plain's, worst QoI.\n\n"
               "| l/R | plain N | plain CPU [s] | per realisation [s] | draw share | std PV_x / PV_F / T_sk | "
               "cv N | cv CPU [s] (pilot + run) | min factor | half-width cv/plain (worst) | CPU ratio cv | "
               "mlmc n0 / n1 | mlmc CPU [s] | half-width mlmc/plain (worst) | CPU ratio mlmc | "
               "anti pairs | rho PV_x / PV_F / T_sk | anti CPU [s] | half-width anti/plain (worst) | CPU ratio anti | "
               "derived n0 / n1 | derived CPU [s] | half-width derived/plain (worst) | CPU ratio derived |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
            s0.seed, NPLAIN, NPILOT, NPLAIN, NPILOT, NPILOT_ML, NPLAIN);
    double tp_all = 0, tc_all = 0, tm_all = 0, tm_matched = 0, ta_all = 0, ta_matched = 0, tr_all = 0, tr_matched = 0;
    int rc = 0;
    for (int k = 0; k < NPTS && !rc; k++) {
        sf_scene s = s0;
        char err[256] = "";
        sf_sweep_point p, pilot, cv;
        if ((rc = sf_sweep_set(&s, "l_over_R", lr[k], err, sizeof err)))
            break;
        double t0 = cpu_now();
        rc = sf_sweep_run(&s, NPLAIN, 1, NULL, 0, NULL, &p, err, sizeof err);
        double tp = cpu_now() - t0;
        if (rc) {
            fprintf(stderr, "bench: estimators: l/R = %g: %s\n", lr[k], err);
            sf_sweep_point_free(&p);
            break;
        }
        t0 = cpu_now();
        rc = sf_sweep_run_cv(&s, NPILOT, 1, NULL, 0, NULL, &pilot, err, sizeof err);
        double tpil = cpu_now() - t0, vmin = INFINITY;
        for (int q = 0; q < SF_SWEEP_NQ && !rc; q++)
            vmin = isnan(pilot.cv[q].vrf) || isnan(vmin) ? NAN : fmin(vmin, pilot.cv[q].vrf);
        sf_sweep_point_free(&pilot);
        size_t n = NPLAIN;
        double tc = tp, worst = 1;
        if (!rc && isfinite(vmin)) {
            n = (size_t)ceil(NPLAIN / fmax(vmin, 1));
            n = n < NPILOT ? NPILOT : n > NPLAIN ? NPLAIN : n;
            t0 = cpu_now();
            rc = sf_sweep_run_cv(&s, n, 1, NULL, 0, NULL, &cv, err, sizeof err);
            tc = tpil + cpu_now() - t0;
            worst = 0;
            for (int q = 0; q < SF_SWEEP_NQ && !rc; q++)
                worst = fmax(worst, (cv.cv[q].ci_hi - cv.cv[q].ci_lo) / (p.rstat[q].ci_hi - p.rstat[q].ci_lo));
            sf_sweep_point_free(&cv);
        } else if (!rc) {
            tc = tp + tpil;   /* the pilot found no companion: plain, plus the pilot spent */
        }
        /* the estimators' targets: plain's standard errors, ratio by ratio */
        double tse[SF_SWEEP_NQ];
        for (int q = 0; q < SF_SWEEP_NQ; q++)
            tse[q] = p.rstat[q].se;
        sf_sweep_point ml;
        double tm = 0, wm = 0;
        if (!rc) {
            t0 = cpu_now();
            rc = sf_sweep_run_estimator_se(&s, SF_EST_MLMC, tse, NPILOT_ML, NPLAIN, 1, NULL, &ml, err, sizeof err);
            tm = cpu_now() - t0;
            for (int q = 0; q < SF_SWEEP_NQ && !rc; q++)
                wm = fmax(wm, (ml.ml.q[q].ci_hi - ml.ml.q[q].ci_lo) / (p.rstat[q].ci_hi - p.rstat[q].ci_lo));
        }
        sf_sweep_point an;
        double ta = 0, wa = 0;
        memset(&an, 0, sizeof an);
        if (!rc) {
            t0 = cpu_now();
            rc = sf_sweep_run_estimator_se(&s, SF_EST_ANTITHETIC, tse, NPILOT_ML, NPLAIN, 1, NULL, &an, err, sizeof err);
            ta = cpu_now() - t0;
            for (int q = 0; q < SF_SWEEP_NQ && !rc; q++)
                wa = fmax(wa, (an.anti.q[q].ci_hi - an.anti.q[q].ci_lo) / (p.rstat[q].ci_hi - p.rstat[q].ci_lo));
        }
        sf_sweep_point bx;
        double tb = NAN, wb = NAN;
        memset(&bx, 0, sizeof bx);
        int ae = rc ? -1 : sf_sweep_estimator_auto(&s);   /* `--estimator auto`'s rule */
        int cells = ae == SF_EST_MLMC_BOXES || ae == SF_EST_MLMC_SUB;   /* a derived coarse field */
        if (cells) {
            t0 = cpu_now();
            rc = sf_sweep_run_estimator_se(&s, ae, tse, NPILOT_ML, NPLAIN, 1, NULL, &bx, err, sizeof err);
            tb = cpu_now() - t0;
            wb = 0;
            for (int q = 0; q < SF_SWEEP_NQ && !rc; q++)
                wb = fmax(wb, (bx.ml.q[q].ci_hi - bx.ml.q[q].ci_lo) / (p.rstat[q].ci_hi - p.rstat[q].ci_lo));
        }
        if (rc) {
            fprintf(stderr, "bench: estimators: l/R = %g: %s\n", lr[k], err);
            sf_sweep_point_free(&p);
            sf_sweep_point_free(&an);
            sf_sweep_point_free(&bx);
            break;
        }
        /* `--estimator auto`'s choice (sf_sweep_estimator_auto) */
        double tr = cells ? tb : ae == SF_EST_MLMC ? tm : ta, wr = cells ? wb : ae == SF_EST_MLMC ? wm : wa;
        tr_all += tr;
        tr_matched += tr * wr * wr;
        /* the draw's share of a plain realisation (the work model) */
        double share = (ml.ml.cost_fine - (ml.ml.cost[1] - ml.ml.cost[0])) / ml.ml.cost_fine;
        tp_all += tp;
        tc_all += tc;
        tm_all += tm;
        tm_matched += tm * wm * wm;   /* the CPU that would match plain's worst half-width */
        ta_all += ta;
        ta_matched += ta * wa * wa;
        fprintf(f, "| %g | %d | %.2f | %.4f | %.2f | %.4f / %.4f / %.4f | %zu | %.2f | %.3g | %.2f | %.2f | %zu / %zu | "
                   "%.2f | %.2f | %.2f | %zu | %.2f / %.2f / %.2f | %.2f | %.2f | %.2f | %zu / %zu | %.2f | %.2f | %.2f |\n",
                lr[k], NPLAIN, tp, tp / NPLAIN, share, p.rstat[0].std, p.rstat[1].std, p.rstat[2].std, n, tc, vmin,
                worst, tp / tc, ml.ml.n[0], ml.ml.n[1], tm, wm, tp / tm, an.anti.n, an.anti.q[0].rho,
                an.anti.q[1].rho, an.anti.q[2].rho, ta, wa, tp / ta, bx.ml.n[0], bx.ml.n[1], tb, wb, tp / tb);
        fprintf(stderr, "bench: estimators: l/R = %g: plain %.2f s, cv %.2f s (N %zu), mlmc %.2f s (n0 %zu, n1 %zu), "
                        "antithetic %.2f s (%zu pairs), derived %.2f s\n",
                lr[k], tp, tc, n, tm, ml.ml.n[0], ml.ml.n[1], ta, an.anti.n, tb);
        sf_sweep_point_free(&an);
        sf_sweep_point_free(&bx);
        sf_sweep_point_free(&p);
        sf_sweep_point_free(&ml);
    }
    if (rc) {
        fprintf(f, "\nThe sweep failed (see stderr).\n");
        return 1;
    }
    double ratio = tp_all / tc_all, rml = tp_all / tm_all;
    fprintf(f, "\nWhole grid: plain %.1f s, control variate %.1f s of CPU: %.2fx less. The companion (the COF "
               "averaged over the disc's nominal path) follows the QoIs only where the field varies little over "
               "the path (large l/R); where the path spans many correlation lengths the QoIs and the companion "
               "average the field differently and the factor is about 1, and there (small l/R) the realisations "
               "cost the most.\n", tp_all, tc_all, ratio);
    fprintf(f, "\nTwo levels: %.1f s of CPU, %.2fx less than plain (%.2fx with each point's CPU scaled by its "
               "worst half-width ratio squared, what matching plain's half-widths exactly would cost). The coarse "
               "level shares the field's draw with the fine one, and every coarse realisation needs a field of its "
               "own: where the draw is most of a realisation's CPU (the draw share above) no coupled coarse plan "
               "can save more than the run's part.\n", tm_all, rml, tp_all / tm_matched);
    double ran = tp_all / ta_all;
    fprintf(f, "\nAntithetic pairs: %.1f s of CPU, %.2fx less than plain (%.2fx scaled by the worst half-width ratio "
               "squared). A pair draws one field for two runs, and where the QoIs follow the field's sign (rho < 0) "
               "its mean varies less than two independent values'; where rho > 0 it varies more, and the pilot "
               "asks for more pairs.\n", ta_all, ran, tp_all / ta_matched);
    double rr = tp_all / tr_all;
    fprintf(f, "\nBy `--estimator auto`'s rule (boxes of boxes where the plan draws cell averages; on the circulant "
               "strip every 2nd node at l/R < 0.5, two levels on the same field at 0.5 <= l/R < 5; antithetic pairs "
               "on tiles and at l/R >= 5; chosen from the runs at the default seed): %.1f s of CPU, %.2fx less than plain (%.2fx scaled by the worst half-width "
               "ratio squared).\n", tr_all, rr, tp_all / tr_matched);
    (void)qn;
    bench_target("Fig. 11 grid at plain N = 100 half-widths: >= 5x less CPU than plain Monte Carlo (section "
                 "estimators)", fmax(fmax(ratio, rml), fmax(ran, rr)) >= 5, "%.2fx control variate, %.2fx two "
                 "levels, %.2fx antithetic, %.2fx by the plan's rule (plain %.0f s, control variate %.0f s, two "
                 "levels %.0f s, antithetic %.0f s, by the rule %.0f s)", ratio, rml, ran, rr, tp_all, tc_all, tm_all,
                 ta_all, tr_all);
    return 0;
}
