/* Sweep throughput: the Fig. 11 quick sweep (the scene of
 * cases/validation/fig11-correlation-length at fewer realisations) with 1
 * and with 2 OpenMP threads, alternated, realisations per second.  The
 * outputs of the two thread counts must be the same bits (the sweep's
 * reproducibility promise), so the bench checks that too. */
#include "bench.h"
#include "scene.h"
#include "sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>

enum { NPTS = 4, NREAL = 8, ROUNDS = 2 };

/* One whole sweep; returns its wall time, the ratios in out[NPTS][NREAL*3]. */
static double one_sweep(const sf_scene *s0, const double *lr, int threads, double *out, int *rc)
{
    double t0 = now();
    for (int k = 0; k < NPTS && !*rc; k++) {
        sf_scene s = *s0;
        char err[256] = "";
        sf_sweep_point pt;
        if ((*rc = sf_sweep_set(&s, "l_over_R", lr[k], err, sizeof err)) ||
            (*rc = sf_sweep_run(&s, NREAL, threads, NULL, 0, NULL, &pt, err, sizeof err))) {
            fprintf(stderr, "bench: sweep failed: %s\n", err);
            return NAN;
        }
        memcpy(out + (size_t)k * NREAL * SF_SWEEP_NQ, pt.ratio, NREAL * SF_SWEEP_NQ * sizeof *out);
        sf_sweep_point_free(&pt);
    }
    return now() - t0;
}

int bench_sweep(FILE *f, const char *dir)
{
    (void)dir;
    sf_scene s;
    sf_scene_default(&s);   /* the fig11 case's scene, fewer points and realisations */
    s.cells = 16;
    s.rtol = 1e-6;
    s.T = 40;
    s.t_skip = 10;
    const double lr[NPTS] = { 0.3, 1, 10, 1000 };
    static double out[2][NPTS * NREAL * SF_SWEEP_NQ];
    double best[2] = { INFINITY, INFINITY };
    int rc = 0;
    for (int round = 0; round < ROUNDS && !rc; round++)
        for (int th = 1; th <= 2 && !rc; th++) {
            double t = one_sweep(&s, lr, th, out[th - 1], &rc);
            fprintf(stderr, "bench: sweep, %d thread%s: %.2f s\n", th, th > 1 ? "s" : "", t);
            best[th - 1] = fmin(best[th - 1], t);
        }
    if (rc) {
        fprintf(f, "## Sweep throughput\n\nThe sweep failed (see stderr).\n");
        return 1;
    }
    int same = !memcmp(out[0], out[1], sizeof out[0]);
    double n = NPTS * NREAL, r1 = n / best[0], r2 = n / best[1], sp = r2 / r1;
    fprintf(f, "## Sweep throughput, 1 vs 2 threads\n\n"
               "The Fig. 11 quick sweep: the scene of `cases/validation/fig11-correlation-length` (field COF, 16 "
               "rings, rtol 1e-6, T = 40 s) at l/R = 0.3, 1, 10, 1000 with %d realisations each (%g in all), "
               "OpenMP over realisations (`sf_sweep_run`, dynamic schedule, one COF plan per thread). Best of %d "
               "alternated rounds per thread count; this machine has %d processors.\n\n"
               "| threads | wall time [s] | realisations per second |\n|---|---|---|\n"
               "| 1 | %.2f | %.2f |\n| 2 | %.2f | %.2f |\n\n"
               "Speed-up 2 threads / 1 thread: **%.2f** (target: 2 within 15%%, i.e. >= 1.70: %s). "
               "Outputs of the two thread counts bit-identical: **%s**.\n",
            NREAL, n, ROUNDS, omp_get_num_procs(), best[0], r1, best[1], r2, sp, sp >= 1.7 ? "met" : "missed",
            same ? "yes" : "NO");
    if (sp < 1.7)
        fprintf(f, "\nMissed by %.0f%% of the ideal. Causes to weigh: the serial part of each point (the "
                   "deterministic reference run and the per-thread plans), the tail of the last realisations "
                   "(%d per point over 2 threads), and a shared machine (the other core may be busy).\n",
                100 * (2 - sp) / 2, NREAL);
    return same ? 0 : 1;
}
