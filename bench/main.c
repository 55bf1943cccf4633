/* slipfield-bench DIR [SECTION...]: run the benchmark sections (all by
 * default: field, contact, dynamics, fftw, sweep,
 * memory) and write DIR/report.md (temporary
 * name, renamed when complete) with the plots beside it. */
#include "bench.h"
#include "version.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <gsl/gsl_version.h>
#include <fftw3.h>

int main(int argc, char **argv)
{
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
    struct { const char *name; int (*fn)(FILE *, const char *); } sec[] = {
        { "field", bench_field },   { "contact", bench_contact }, { "dynamics", bench_dynamics },
        { "fftw", bench_fftw },     { "sweep", bench_sweep },     { "memory", bench_memory },
    };
    int rc = 0;
    for (size_t i = 0; i < sizeof sec / sizeof sec[0]; i++) {
        int want = argc <= 2;
        for (int a = 2; a < argc; a++)
            want |= !strcmp(argv[a], sec[i].name);
        if (!want)
            continue;
        fprintf(stderr, "bench: %s\n", sec[i].name);
        rc |= sec[i].fn(f, dir);
        fputc('\n', f);
    }
    if (fclose(f) || rename(tmp, path)) {
        unlink(tmp);
        return 3;
    }
    printf("bench report: %s\n", path);
    return rc ? 1 : 0;
}
