/* slipfield command line: shared helpers for the subcommands. */
#ifndef SF_CLI_H
#define SF_CLI_H

#include <stdio.h>
#include "options.h"
#include "scene.h"
#include "cof.h"
#include "sf_error.h"   /* SF_EXIT_* */

/* Read a scene file with Table 1 defaults; on error print it and return
 * SF_EXIT_USAGE.  Keys the scene sets that the command does not read
 * (samples, u, v, w, ntheta, npsi outside their commands) are reported on
 * stderr. */
int sf_cli_load_scene(const char *cmd, const char *path, sf_scene *s);
/* The commands that read scene key `key` when cmd is not one of them
 * (samples: field sweep; u, v, w: wrench; ntheta, npsi: surface); NULL
 * when cmd reads it (every other key is read by every command that runs
 * the scene). */
const char *sf_cli_key_ignored(const char *cmd, const char *key);
/* A command option opt given and the scene sets key, its default: say the
 * key is ignored. */
void sf_cli_key_overridden(const char *cmd, const char *path, const sf_scene *s, const char *key, const char *opt);

/* The exit status of a solver error code: the scene's to fix (its values,
 * its size, a run that left its strip or did not converge: 2), except an
 * allocation that failed (3). */
int sf_cli_status(int rc);

/* A COF plan whose circulant embedding reached its padding cap: say so on
 * stderr (the plan is usable, but its covariance is not Eq. 2's). */
void sf_cli_warn_truncated(const char *cmd, const char *path, const sf_scene *s, const sf_cof_plan *p);

/* An output file.  A new path or a regular file is written under a
 * temporary name in its folder and renamed over it on success (removed on
 * failure: nothing half-written); anything else (a character device such
 * as /dev/null, a FIFO, a symbolic link such as /dev/stdout) is opened and
 * written in place and never replaced; "-" is stdout.  An output that is
 * the input scene itself (same file) is refused. */
typedef struct {
    FILE *f;
    char final[1024], tmp[1100];
    int is_stdout, in_place;
} sf_out;
/* input: the scene path (NULL: none).  Returns SF_EXIT_OK or SF_EXIT_USAGE
 * after printing why. */
int sf_cli_open(const char *cmd, const char *path, const char *input, sf_out *o);
/* ok = 0: the command failed, its output is discarded (SF_EXIT_INTERNAL
 * returned: the caller says why and picks the status).  Returns
 * SF_EXIT_OK, or SF_EXIT_USAGE after printing why the output could not be
 * written (with the system's reason: a full disk, stdout on /dev/full). */
int sf_cli_close(const char *cmd, sf_out *o, int ok);

/* A signal (SIGINT, SIGTERM, SIGHUP) removes the temporary files and
 * prints "slipfield: interrupted" and then hint (e.g. ": rerun with
 * --resume"). */
void sf_cli_interrupt_hint(const char *hint);

/* A subcommand's options (options.h: the one parser of every command):
 * sf_cli_parse() fills them, takes one positional SCENE argument, prints
 * usage on -h/--help (returns SF_CLI_HELP) and errors naming the option
 * (returns SF_EXIT_USAGE). */
#define SF_CLI_HELP SF_OPT_DONE
int sf_cli_parse(const char *cmd, int argc, char **argv, const sf_opt *opts, size_t nopts,
                 const char **scene, void (*usage)(FILE *));

int sf_cmd_field(int argc, char **argv);
int sf_cmd_surface(int argc, char **argv);
int sf_cmd_wrench(int argc, char **argv);
int sf_cmd_run(int argc, char **argv);
int sf_cmd_sweep(int argc, char **argv);
int sf_cmd_evaluate(int argc, char **argv);
int sf_cmd_sensitivity(int argc, char **argv);

#endif
