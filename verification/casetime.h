/* slipfield verification: each case's time limit, scaled from its
 * recorded run time.
 *
 * A case that takes SF_CASETIME_FACTOR times its usual time is already
 * failing (a hang, a stepper stuck at its minimum step): its process is
 * stopped at max(SF_CASETIME_FLOOR, SF_CASETIME_FACTOR x recorded), so a
 * hang costs a minute, not the runner's global limit.  The recorded times
 * ship with the catalogue, in <catalogue>/times.tsv next to the family
 * folders (cases/times.tsv: "id<TAB>seconds" lines, # comments), so a
 * fresh clone has them; `sh scripts/times.sh reports/results.json`
 * rewrites the table from a run.  A case without a recorded time gets the
 * fallback (`verify --timeout`'s default). */
#ifndef SF_CASETIME_H
#define SF_CASETIME_H

#define SF_CASETIME_FLOOR 60.0
#define SF_CASETIME_FACTOR 20.0

/* The recorded wall time [s] of case `id` whose file is case_path (the
 * table is read from the folder above the case's family folder), or a
 * negative value when there is none. */
double sf_casetime_recorded(const char *case_path, const char *id);

/* The case's time limit [s]: scaled from its recorded time, else fallback. */
unsigned sf_casetime_limit(const char *case_path, const char *id, unsigned fallback);

#endif
