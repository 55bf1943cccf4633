/* Each case's CPU-time limit from its recorded CPU time (casetime.h). */
#include "casetime.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* <dir of case_path>/../times.tsv into buf; 0 when it does not fit */
static int table_path(const char *case_path, char *buf, size_t len)
{
    const char *slash = strrchr(case_path, '/');
    int n = slash ? snprintf(buf, len, "%.*s/../times.tsv", (int)(slash - case_path), case_path)
                  : snprintf(buf, len, "../times.tsv");
    return n > 0 && (size_t)n < len;
}

double sf_casetime_recorded(const char *case_path, const char *id)
{
    char path[1100], line[512];
    if (!table_path(case_path, path, sizeof path))
        return -1;
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    double t = -1;
    size_t idlen = strlen(id);
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, id, idlen) && line[idlen] == '\t') {
            char *end;
            double v = strtod(line + idlen + 1, &end);
            if (end != line + idlen + 1 && isfinite(v) && v >= 0)
                t = v;
            break;
        }
    fclose(f);
    return t;
}

unsigned sf_casetime_limit(const char *case_path, const char *id)
{
    double t = sf_casetime_recorded(case_path, id);
    if (t < 0)
        return 0;
    /* the self-tests (SF_SELFTEST=1) may lower the floor, to see a
       spinning case stopped in a second rather than a minute */
    double floor_s = SF_CASETIME_FLOOR;
    const char *st = getenv("SF_SELFTEST"), *fl = getenv("SF_CASETIME_FLOOR");
    if (st && !strcmp(st, "1") && fl && atof(fl) >= 1)
        floor_s = atof(fl);
    double lim = ceil(fmax(floor_s, SF_CASETIME_FACTOR * t));
    return lim < 1e6 ? (unsigned)lim : 1000000u;
}
