/* slipfield: the command-line entry.  Dispatches to the solver commands
 * (cli/cmd_*.c) and to the verification harness (verification/). */
#include "cli.h"
#include "case.h"
#include "runner.h"
#include "version.h"

#include "field.h"
#include "montecarlo.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fftw3.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_version.h>

typedef struct {
    const char *name;
    int (*fn)(int, char **);
    const char *summary;
} command;

static int cmd_help(int argc, char **argv);

static const command commands[] = {
    { "verify", sf_verify_main, "run literate verification cases and write reports" },
    { "field", sf_cmd_field, "sample lognormal COF random fields to TSV" },
    { "run", sf_cmd_run, "integrate the stick-slip oscillator: history TSV and QoI summary" },
    { "sweep", sf_cmd_sweep, "Monte Carlo sweep over a parameter: QoI ratios to the deterministic model" },
    { "evaluate", sf_cmd_evaluate, "the model at each row of a design (TSV): QoIs, ratios, u_num" },
    { "sensitivity", sf_cmd_sensitivity, "Sobol' indices of the QoI ratios over l/R, CV, v_b and the mean COF" },
    { "surface", sf_cmd_surface, "the static limit surface (Eq. 11) to TSV" },
    { "wrench", sf_cmd_wrench, "the friction force and torque at one motion (Eqs. 7-8)" },
    { "help", cmd_help, "help on a command or on scene keys: 'slipfield help run', 'help scene'" },
};
#define NCMD (sizeof commands / sizeof commands[0])

static void usage(FILE *f)
{
    fprintf(f, "usage: slipfield COMMAND [options]\n"
               "Stick-slip oscillator with a random-field friction coefficient, and its\n"
               "verification suite (Hu, Batou & Ouyang, MSSP 183 (2023) 109572).\n\ncommands:\n");
    for (size_t i = 0; i < NCMD; i++)
        fprintf(f, "  %-11s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\noptions:\n"
               "  -h, --help  this text ('slipfield help COMMAND' or 'slipfield COMMAND --help':\n"
               "              a command's options)\n"
               "  --version   version, git revision, GSL and FFTW versions\n"
               "Options may follow the positional arguments; '--opt=value' is '--opt value';\n"
               "'--' ends the options.\n"
               "Scenes are 'key = value' files in SI units; defaults are the paper's Table 1.\n"
               "Exit status: 0 ok, 1 a check failed, 2 bad input or usage, 3 internal error,\n"
               "130 interrupted by SIGINT (Ctrl-C; SIGTERM 143, SIGHUP 129: 128 + the signal),\n"
               "its partial outputs removed (an interrupted sweep: rerun with --resume).\n"
               "Environment: SLIPFIELD_FFTW_WISDOM=FILE keeps FFTW wisdom for scenes with\n"
               "fftw_planner = measure (imported before a command, saved after it).\n");
}

static int cmd_help(int argc, char **argv)
{
    if (argc > 2) {
        fprintf(stderr, "slipfield help: one topic at a time\n");
        return SF_EXIT_USAGE;
    }
    if (argc < 2 || !strcmp(argv[1], "help") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(stdout);
        return SF_EXIT_OK;
    }
    if (!strcmp(argv[1], "scene")) {
        sf_case_print_keys(stdout);   /* the solver's keys, then the case's */
        return SF_EXIT_OK;
    }
    for (size_t i = 0; i < NCMD; i++)
        if (!strcmp(argv[1], commands[i].name) && commands[i].fn != cmd_help) {
            char *args[] = { argv[1], "--help", NULL };
            return commands[i].fn(2, args);
        }
    fprintf(stderr, "slipfield help: no help on '%s': topics are scene and the commands\n", argv[1]);
    usage(stderr);
    return SF_EXIT_USAGE;
}

/* SLIPFIELD_FFTW_WISDOM=FILE: FFTW wisdom imported before the command and
 * saved after it (rank 0 only), so scenes with fftw_planner = measure plan
 * once per machine and every process that imports the file makes the same
 * plans (so the same bits). */
static int with_wisdom(const command *c, int argc, char **argv)
{
    const char *w = getenv("SLIPFIELD_FFTW_WISDOM");
    if (w && *w && sf_field_wisdom_import(w)) {
        fprintf(stderr, "slipfield: SLIPFIELD_FFTW_WISDOM=%s: not an FFTW wisdom file\n", w);
        return SF_EXIT_USAGE;
    }
    int rc = c->fn(argc, argv);
    if (w && *w && sf_mc_rank(NULL) == 0 && sf_field_wisdom_export(w))
        fprintf(stderr, "slipfield: cannot save FFTW wisdom to %s\n", w);
    return rc;
}

static int dispatch(int argc, char **argv)
{
    sf_init();   /* GSL statuses are returned, not abort()ed on (sf_error.h) */
    if (argc < 2) {
        usage(stderr);
        return SF_EXIT_USAGE;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(stdout);
        return SF_EXIT_OK;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("slipfield %s (%s)\nGSL %s, %s\n", SF_VERSION, SF_GIT_REV, GSL_VERSION, fftw_version);
        return SF_EXIT_OK;
    }
    for (size_t i = 0; i < NCMD; i++)
        if (!strcmp(argv[1], commands[i].name))
            return with_wisdom(&commands[i], argc - 1, argv + 1);
    fprintf(stderr, "slipfield: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return SF_EXIT_USAGE;
}

#ifdef SF_MPI
#include <mpi.h>
#endif

int main(int argc, char **argv)
{
#ifdef SF_MPI
    /* make MPI=1: `mpirun -np P slipfield sweep ...` spreads realisations
       over ranks (solver/stats/montecarlo.h); other commands run on each rank */
    MPI_Init(&argc, &argv);
    int rc = dispatch(argc, argv);
    MPI_Finalize();
    return rc;
#else
    return dispatch(argc, argv);
#endif
}
