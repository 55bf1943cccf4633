/* slipfield-bench DIR [SECTION...]: run the benchmark sections (all by
 * default: field, contact, dynamics, fftw, sweep,
 * memory, realisation; `plan`, the accuracy plan's calibration,
 * `fig11`, `estimators` and `coupling` (minutes each) only when named) and write DIR/report.md (temporary
 * name, renamed when complete) with the plots beside it. */
#include "bench.h"
#include "version.h"
#include "sf_error.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <gsl/gsl_version.h>
#include <fftw3.h>

enum { MAX_TARGETS = 32 };
static struct { char target[160], measured[200]; int met; } targets[MAX_TARGETS];
static int ntargets;

void bench_target(const char *target, int met, const char *measured, ...)
{
    if (ntargets == MAX_TARGETS)
        return;
    va_list ap;
    va_start(ap, measured);
    snprintf(targets[ntargets].target, sizeof targets[ntargets].target, "%s", target);
    vsnprintf(targets[ntargets].measured, sizeof targets[ntargets].measured, measured, ap);
    va_end(ap);
    targets[ntargets++].met = met;
}

int main(int argc, char **argv)
{
    sf_init();   /* GSL statuses are returned, not abort()ed on (sf_error.h) */
    const char *dir = argc > 1 ? argv[1] : "reports/bench";
    char buf[600];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *q = buf + 1; *q; q++)
        if (*q == '/') { *q = 0; mkdir(buf, 0777); *q = '/'; }
    mkdir(buf, 0777);
    char path[700], tmp[720];
    snprintf(path, sizeof path, "%s/report.md", dir);
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "bench: cannot write %s: %s\n", tmp, strerror(errno));
        return 3;
    }
    fprintf(f, "# slipfield benchmarks\n\nslipfield %s, GSL %s, %s. Times are wall-clock medians on this machine; "
               "only ratios measured in this run are claims.\n\n", SF_VERSION, GSL_VERSION, fftw_version);
    /* Report order; `memory` runs first, while this process is small: a
     * forked child's peak RSS (wait4) counts the parent's pages it was
     * copied with until its exec. */
    struct { const char *name; int (*fn)(FILE *, const char *); int first; char *text; size_t len; int named; } sec[] = {
        { "field", bench_field, 0, NULL, 0, 0 },   { "contact", bench_contact, 0, NULL, 0, 0 },
        { "dynamics", bench_dynamics, 0, NULL, 0, 0 }, { "fftw", bench_fftw, 0, NULL, 0, 0 },
        { "sweep", bench_sweep, 0, NULL, 0, 0 },   { "memory", bench_memory, 1, NULL, 0, 0 },
        { "belt", bench_belt, 1, NULL, 0, 0 },
        { "realisation", bench_realisation, 0, NULL, 0, 0 },
        { "unum", bench_unum, 0, NULL, 0, 0 },
        { "plan", bench_plan, 0, NULL, 0, 1 },   /* the plan's calibration (minutes): only when named */
        { "fig11", bench_fig11, 0, NULL, 0, 1 },   /* Fig. 11 time estimate (minutes): only when named */
        { "estimators", bench_estimators, 0, NULL, 0, 1 },   /* plain MC vs control variate and two levels, Fig. 11 grid (minutes) */
        { "coupling", bench_coupling, 0, NULL, 0, 1 },   /* antithetic and coarser fields, Fig. 11 grid (minutes) */
    };
    enum { NSEC = sizeof sec / sizeof sec[0] };
    int rc = 0;
    for (int pass = 1; pass >= 0; pass--)
        for (size_t i = 0; i < NSEC; i++) {
            int want = argc <= 2 && !sec[i].named;
            for (int a = 2; a < argc; a++)
                want |= !strcmp(argv[a], sec[i].name);
            if (!want || sec[i].first != pass)
                continue;
            FILE *m = open_memstream(&sec[i].text, &sec[i].len);
            if (!m)
                return 3;
            fprintf(stderr, "bench: %s\n", sec[i].name);
            rc |= sec[i].fn(m, dir);
            fputc('\n', m);
            fclose(m);
        }
    if (ntargets) {
        fprintf(f, "## Targets\n\nEach measured in this run by the section named; ratios are of times measured in "
                   "the same run.\n\n| target | measured | status |\n|---|---|---|\n");
        for (int i = 0; i < ntargets; i++)
            fprintf(f, "| %s | %s | %s |\n", targets[i].target, targets[i].measured,
                    targets[i].met ? "met" : "**NOT met**");
        fputc('\n', f);
    }
    for (size_t i = 0; i < NSEC; i++) {
        if (sec[i].text)
            fwrite(sec[i].text, 1, sec[i].len, f);
        free(sec[i].text);
    }
    if (fclose(f) || rename(tmp, path)) {
        unlink(tmp);
        return 3;
    }
    printf("bench report: %s\n", path);
    return rc ? 1 : 0;
}
