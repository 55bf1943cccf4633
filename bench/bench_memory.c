/* Peak memory and time of the skip decisions: `slipfield run` on a
 * deterministic scene (uniform COF: no field, closed forms), a
 * summary-only field scene (no history) and the same scene with the full
 * history streamed to a file.  Each run is a child process; its peak
 * resident set comes from wait4's rusage. */
#define _DEFAULT_SOURCE   /* wait4 */
#include "bench.h"
#include "numplan.h"

#include <errno.h>
#include <math.h>
#include <fcntl.h>
#include <libgen.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

typedef struct { const char *name, *scene, *what; int history; } job;

/* Run `exe run scene --summary sum [--out hist]`; wall time, peak RSS [KiB],
 * and (cpu not NULL) the child's CPU time, user + system [s]. */
static int run_child_cpu(const char *exe, const char *scene, const char *sum, const char *hist, double *t, long *kib,
                         double *cpu)
{
    double t0 = now();
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0)
            dup2(fd, 2);
        if (hist)
            execl(exe, exe, "run", scene, "--summary", sum, "--out", hist, (char *)NULL);
        else
            execl(exe, exe, "run", scene, "--summary", sum, (char *)NULL);
        _exit(127);
    }
    int st;
    struct rusage ru;
    if (wait4(pid, &st, 0, &ru) != pid)
        return -1;
    *t = now() - t0;
    *kib = ru.ru_maxrss;
    if (cpu)
        *cpu = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
               1e-6 * (double)ru.ru_stime.tv_usec;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static int run_child(const char *exe, const char *scene, const char *sum, const char *hist, double *t, long *kib)
{
    return run_child_cpu(exe, scene, sum, hist, t, kib, NULL);
}

int bench_memory(FILE *f, const char *dir)
{
    char self[512], exe[600];
    ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
    if (len <= 0) {
        fprintf(f, "## Peak memory\n\nCannot locate the slipfield binary (no /proc/self/exe).\n");
        return 1;
    }
    self[len] = 0;
    snprintf(exe, sizeof exe, "%s/slipfield", dirname(dirname(self)));   /* build/bench/x -> build/slipfield */
    const job jobs[] = {
        { "deterministic", "cof = uniform\n", "uniform COF: no field, no quadrature (closed forms)", 0 },
        { "summary-only", "cof = field\n", "Table 1 field, QoIs only: no history kept", 0 },
        { "full history", "cof = field\n", "Table 1 field, every step and event streamed to a TSV", 1 },
    };
    enum { NJ = 3, REPS = 3 };
    double tm[NJ][REPS];
    long kib[NJ] = { 0 };
    off_t hsize = 0;
    char scene[700], sum[700], hist[700];
    for (int j = 0; j < NJ; j++) {
        snprintf(scene, sizeof scene, "%s/mem-%d.scene", dir, j);
        FILE *s = fopen(scene, "w");
        if (!s || fputs(jobs[j].scene, s) < 0 || fclose(s)) {
            fprintf(stderr, "bench: cannot write %s: %s\n", scene, strerror(errno));
            return 1;
        }
    }
    snprintf(sum, sizeof sum, "%s/mem.summary", dir);
    snprintf(hist, sizeof hist, "%s/mem.history.tsv", dir);
    for (int r = 0; r < REPS; r++)   /* alternated, so noise hits all alike */
        for (int j = 0; j < NJ; j++) {
            snprintf(scene, sizeof scene, "%s/mem-%d.scene", dir, j);
            long k = 0;
            int rc = run_child(exe, scene, sum, jobs[j].history ? hist : NULL, &tm[j][r], &k);
            if (rc) {
                fprintf(stderr, "bench: %s run failed (exit %d)\n", exe, rc);
                fprintf(f, "## Peak memory and time of a run\n\n`%s run` failed (exit %d).\n", exe, rc);
                return 1;
            }
            if (k > kib[j])
                kib[j] = k;
            struct stat st;
            if (jobs[j].history && !stat(hist, &st))
                hsize = st.st_size;
        }
    fprintf(f, "## Peak memory and time of a run\n\n`slipfield run SCENE --summary FILE [--out FILE]`, Table 1 "
               "defaults (T = 100 s, 32 rings), each run a child process: peak resident set from `wait4` (largest "
               "of %d), wall time the median of %d alternated runs.\n\n"
               "| scene | what the plan computes | peak RSS [MiB] | wall time [s] |\n|---|---|---|---|\n",
            REPS, REPS);
    for (int j = 0; j < NJ; j++) {
        gsl_sort(tm[j], 1, REPS);
        double med = gsl_stats_median_from_sorted_data(tm[j], 1, REPS);
        fprintf(f, "| %s | %s | %.1f | %.3f |\n", jobs[j].name, jobs[j].what, (double)kib[j] / 1024, med);
    }
    fprintf(f, "\nThe history file was %.1f MB: it is streamed, so the full-history run's peak memory stays that "
               "of the summary-only run; the field scenes' memory is the strip field and its circulant embedding "
               "(`slipfield run SCENE --explain` gives the grid).\n", 1e-6 * (double)hsize);
    for (int j = 0; j < NJ; j++) {
        snprintf(scene, sizeof scene, "%s/mem-%d.scene", dir, j);
        unlink(scene);
    }
    unlink(sum);
    unlink(hist);
    return 0;
}

/* A realisation at l/R = 0.01 (tiles in a sliding window) against
 * l/R = 1 (circulant strip), peak RSS and wall time, Table 1 otherwise; and
 * l/R = 0.1 both ways, where the circulant strip was the largest it took. */
int bench_belt(FILE *f, const char *dir)
{
    char self[512], exe[600];
    ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
    if (len <= 0) {
        fprintf(f, "## A belt without end\n\nCannot locate the slipfield binary (no /proc/self/exe).\n");
        return 1;
    }
    self[len] = 0;
    snprintf(exe, sizeof exe, "%s/slipfield", dirname(dirname(self)));
    const job jobs[] = {
        { "l/R = 1", "l = 0.5\n", "circulant strip (auto)", 0 },
        { "l/R = 0.01", "l = 0.005\n", "the plan's choice (auto: cell averages)", 0 },
        { "l/R = 0.1, circulant", "l = 0.05\ncof_generator = circulant\n", "circulant strip (forced)", 0 },
        { "l/R = 0.1, tiles", "l = 0.05\ncof_generator = tiles\n", "tiles, sliding window (forced)", 0 },
        { "l/R = 1, speed plan", "l = 0.5\ncells = 12\nrtol = 1e-6\n", "circulant; 12 rings, rtol 1e-6", 0 },
        { "l/R = 0.01, speed plan", "l = 0.005\ncells = 12\nrtol = 1e-6\n", "tiles; 12 rings, rtol 1e-6", 0 },
        { "l/R = 0.03", "l = 0.015\n", "the plan's choice (auto)", 0 },
        { "l/R = 0.03, point values", "l = 0.015\ncof_model = point\n", "tiles, point model (forced)", 0 },
        { "l/R = 0.01, point values", "l = 0.005\ncof_model = point\n", "tiles, point model (forced)", 0 },
        /* 9..12: the belt noise (the Sobol' study's field input, T = 100 s, t_skip = 10 s) */
        { "l/R = 0.01, belt noise, point values", "l = 0.005\nT = 100\nt_skip = 10\ncof_generator = belt_noise\n"
          "cof_model = point\n", "belt noise, point model (forced)", 0 },
        { "l/R = 0.01, belt noise, cell averages", "l = 0.005\nT = 100\nt_skip = 10\ncof_generator = belt_noise\n",
          "belt noise, the plan's choice (auto: box averages)", 0 },
        { "l/R = 0.02, belt noise, point values", "l = 0.01\nT = 100\nt_skip = 10\ncof_generator = belt_noise\n"
          "cof_model = point\n", "belt noise, point model (forced)", 0 },
        { "l/R = 0.02, belt noise, cell averages", "l = 0.01\nT = 100\nt_skip = 10\ncof_generator = belt_noise\n",
          "belt noise, the plan's choice (auto: box averages)", 0 },
    };
    enum { NJ = sizeof jobs / sizeof jobs[0] };
    double tm[NJ], cpu[NJ];
    long kib[NJ];
    char scene[700], sum[700];
    snprintf(sum, sizeof sum, "%s/belt.summary", dir);
    for (int j = 0; j < NJ; j++) {
        snprintf(scene, sizeof scene, "%s/belt-%d.scene", dir, j);
        FILE *s = fopen(scene, "w");
        if (!s || fputs(jobs[j].scene, s) < 0 || fclose(s)) {
            fprintf(stderr, "bench: cannot write %s: %s\n", scene, strerror(errno));
            return 1;
        }
        int rc = run_child_cpu(exe, scene, sum, NULL, &tm[j], &kib[j], &cpu[j]);
        unlink(scene);
        if (rc) {
            fprintf(f, "## A belt without end\n\n`%s run` failed at %s (exit %d).\n", exe, jobs[j].name, rc);
            return 1;
        }
    }
    unlink(sum);
    /* jobs 6..8 */
    fprintf(f, "## A belt without end: the COF at small l/R\n\n`slipfield run SCENE --summary FILE`, Table 1 "
               "(T = 100 s, 32 rings, rtol 1e-8 unless said), one realisation each, a child process: peak resident "
               "set and CPU time (user + system) from `wait4`, and wall time, of one run. The ratios use CPU time: "
               "the machine is shared, and wall time counts the other processes.\n\n"
               "| scene | COF generator | peak RSS [MiB] | CPU time [s] | wall time [s] |\n|---|---|---|---|---|\n");
    for (int j = 0; j < NJ; j++)
        fprintf(f, "| %s | %s | %.1f | %.3f | %.3f |\n", jobs[j].name, jobs[j].what, (double)kib[j] / 1024, cpu[j],
                tm[j]);
    fprintf(f, "\nRatios measured in this run: l/R = 0.01 against l/R = 1, peak RSS %.2fx (%.1f MiB; target <= 256 "
               "MiB), CPU time %.1fx (target <= 10x); the tiled point model with the speed plan (12 rings, rtol 1e-6) "
               "%.1fx. At l/R = 0.1 the tiles hold %.3fx the circulant's peak RSS in %.2fx its CPU time. With point "
               "values at small l the time is the field (about 1e8 lattice points over 20 m of belt, each a 69-tap "
               "convolution along x and along y, SSE2), the ~5e4 cells resolving l and the several times more steps "
               "a rough field takes.\n",
            (double)kib[1] / (double)kib[0], (double)kib[1] / 1024, cpu[1] / cpu[0], cpu[5] / cpu[4],
            (double)kib[3] / (double)kib[2], cpu[3] / cpu[2]);
    bench_target("l/R = 0.01: peak RSS <= 256 MiB per thread (one `slipfield run`), section belt",
                 kib[1] <= 256 * 1024, "%.1f MiB (%.2f of the target)", (double)kib[1] / 1024,
                 (double)kib[1] / (256.0 * 1024));
    bench_target("l/R = 0.01: time <= 10x the time at l/R = 1 (one `slipfield run` each, CPU), section belt",
                 cpu[1] <= 10 * cpu[0], "%.1fx (%.3f s against %.3f s)", cpu[1] / cpu[0], cpu[1], cpu[0]);
    size_t ca_cells[2] = { 0, 0 };   /* the plan's cells per diameter at l/R = 0.01 and 0.03 (Table 1) */
    double ca_box[2] = { 0, 0 };
    for (int k = 0; k < 2; k++) {
        sf_scene ps;
        sf_numplan np;
        char perr[160];
        sf_scene_default(&ps);
        ps.l = (k ? 0.03 : 0.01) * ps.R;
        if (sf_numplan_make(&ps, 1, &np, perr, sizeof perr) == 0 && np.cell_average) {
            ca_cells[k] = np.cells;
            ca_box[k] = np.cell_size / ps.l;
        }
    }
    fprintf(f, "\nCell averages (`cof_model`, solver/field/cellavg.h; docs/design.md sec. 4.4): the plan's choice at l/R = 0.01 is the "
               "cell-average model (%zu Cartesian cells per diameter, of %.2f l, the effective field at spacing box/3 by "
               "circulant embedding, one real FFT per realisation); against the point model it would replace (forced, %.1f s CPU) it is %.0fx faster. "
               "Ratios to l/R = 1 in this run: l/R = 0.01 (auto) %.1fx CPU (target <= 10x), peak RSS %.1f MiB (target "
               "<= 256); l/R = 0.03 (auto: cell averages, %zu cells per diameter) %.1fx (target <= 10x); l/R = 0.03 "
               "with point values forced %.1fx.\n",
            ca_cells[0], ca_box[0], cpu[8], cpu[8] / cpu[1], cpu[1] / cpu[0], (double)kib[1] / 1024, ca_cells[1],
            cpu[6] / cpu[0], cpu[7] / cpu[0]);
    fprintf(f, "\nOn belt noise (cof_generator = belt_noise: the Sobol' study's field input, solver/field/noise.h): the "
               "plan's box averages of the noise's own lognormal field (one noise level coarser, the piecewise cubic "
               "interpolant's box average over the quadrature's cells; docs/design.md sec. 4.4) against the point "
               "model, one run each (T = 100 s, with the run's u_num companion): l/R = 0.01 point %.1f s, cell "
               "averages %.2f s CPU, %.1fx faster; l/R = 0.02 point %.2f s, cell averages %.2f s, %.1fx; peak RSS "
               "%.0f and %.0f MiB (cell averages), %.0f and %.0f MiB (point).\n",
            cpu[9], cpu[10], cpu[9] / cpu[10], cpu[11], cpu[12], cpu[11] / cpu[12], (double)kib[10] / 1024,
            (double)kib[12] / 1024, (double)kib[9] / 1024, (double)kib[11] / 1024);
    bench_target("belt noise at l/R = 0.01: the plan's cell averages >= 10x faster than the point model (CPU, one "
                 "`slipfield run` each), section belt",
                 cpu[9] >= 10 * cpu[10], "%.1fx (%.2f s against %.1f s)", cpu[9] / cpu[10], cpu[10], cpu[9]);
    return 0;
}

/* The paper's Fig. 11 at its own size (11 l/R from 1e-2 to 1e3, 100
 * realisations each, T = 100 s, 2 cores), estimated from one realisation's
 * CPU time per l/R (a `slipfield run` child: plan + draw + run). */
int bench_fig11(FILE *f, const char *dir)
{
    char self[512], exe[600];
    ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
    if (len <= 0) {
        fprintf(f, "## Fig. 11 estimate\n\nCannot locate the slipfield binary (no /proc/self/exe).\n");
        return 1;
    }
    self[len] = 0;
    snprintf(exe, sizeof exe, "%s/slipfield", dirname(dirname(self)));
    enum { NL = 11 };
    double cpu[NL], tm[NL], total = 0;
    long kib[NL];
    char scene[700], sum[700], text[128];
    snprintf(sum, sizeof sum, "%s/fig11.summary", dir);
    snprintf(scene, sizeof scene, "%s/fig11.scene", dir);
    fprintf(f, "## Fig. 11 at the paper's size, estimated\n\nOne realisation per l/R (Table 1, T = 100 s, the plan's "
               "defaults), `slipfield run` in a child: CPU time (user + system, plan and draw included) and peak RSS. "
               "Estimate: 100 x the sum of the CPU times / 2 cores.\n\n| l/R | CPU time [s] | peak RSS [MiB] |\n"
               "|---|---|---|\n");
    for (int k = 0; k < NL; k++) {
        double lr = pow(10, -2 + 0.5 * k);
        FILE *s = fopen(scene, "w");
        snprintf(text, sizeof text, "l = %.17g\n", lr * 0.5);
        if (!s || fputs(text, s) < 0 || fclose(s))
            return 1;
        int rc = run_child_cpu(exe, scene, sum, NULL, &tm[k], &kib[k], &cpu[k]);
        if (rc) {
            fprintf(f, "`%s run` failed at l/R = %g (exit %d).\n", exe, lr, rc);
            return 1;
        }
        total += cpu[k];
        fprintf(f, "| %.3g | %.3f | %.1f |\n", lr, cpu[k], (double)kib[k] / 1024);
    }
    unlink(scene);
    unlink(sum);
    bench_target("Fig. 11 at the paper's size (11 l/R, 100 realisations, T = 100 s) <= 15 min on 2 cores, "
                 "section fig11 (an upper estimate: one plan per realisation)", 100 * total / 2 <= 900,
                 "%.1f min (%.2f of the target)", 100 * total / 2 / 60, 100 * total / 2 / 900);
    fprintf(f, "\nEstimated Fig. 11 (11 l/R x 100 realisations) on 2 cores: %.0f s = %.1f min (target <= 15 min); "
               "a Monte Carlo sweep reuses each plan, so this counts the plans 100 times over.\n",
            100 * total / 2, 100 * total / 2 / 60);
    return 0;
}
