/* slipfield verification: each case's CPU-time limit, scaled from its
 * recorded CPU time.
 *
 * A case that takes SF_CASETIME_FACTOR times its usual time is already
 * failing (a hang, a stepper stuck at its minimum step): its process gets
 * a CPU-time limit (RLIMIT_CPU) of max(SF_CASETIME_FLOOR, FACTOR x
 * recorded), so a spinning hang costs a minute, not the runner's wall
 * limit.  CPU time, not wall time: on a loaded machine (two cores shared
 * by many jobs) a case's wall time grew 20x while its CPU time did not.
 * A process blocked without using CPU still meets the wall limit
 * (`verify --timeout`, default 900 s).  The recorded times ship with the
 * catalogue, in <catalogue>/times.tsv next to the family folders
 * (cases/times.tsv: "id<TAB>CPU seconds" lines, # comments), so a fresh
 * clone has them; `sh scripts/times.sh reports/results.json` rewrites the
 * table from a run.  A case without a recorded time has no CPU limit. */
#ifndef SF_CASETIME_H
#define SF_CASETIME_H

#define SF_CASETIME_FLOOR 60.0
#define SF_CASETIME_FACTOR 20.0

/* The recorded CPU time [s] of case `id` whose file is case_path (the
 * table is read from the folder above the case's family folder), or a
 * negative value when there is none. */
double sf_casetime_recorded(const char *case_path, const char *id);

/* The case's CPU-time limit [s] scaled from its recorded time; 0 (none)
 * when it has none. */
unsigned sf_casetime_limit(const char *case_path, const char *id);

#endif
