/* make bench: one report (reports/bench/report.md), one section per
 * benchmark.  Ratios are measured in the same run, interleaved, medians. */
#ifndef SF_BENCH_H
#define SF_BENCH_H

#include <stdio.h>
#include <time.h>

static inline double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
#define now bench_now

/* Each section appends Markdown to f and may write plots into dir. */
int bench_field(FILE *f, const char *dir);
int bench_contact(FILE *f, const char *dir);
int bench_dynamics(FILE *f, const char *dir);

#endif
