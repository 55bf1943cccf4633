/* A verdict's name and a run's CPU time in reports and results (outcome.h). */
#include "outcome.h"

#include <math.h>

double sf_outcome_cpu_total(const sf_outcome *o, size_t n)
{
    double t = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(o[i].cpu_seconds) && o[i].cpu_seconds > 0)
            t += o[i].cpu_seconds;
    return t;
}

const char *sf_verdict_name(int v)
{
    return v == SF_VERDICT_PASS ? "PASS" : v == SF_VERDICT_FAIL ? "FAIL" : "ERROR";
}
