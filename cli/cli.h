/* slipfield command line: shared helpers for the subcommands. */
#ifndef SF_CLI_H
#define SF_CLI_H

#include <stdio.h>
#include "options.h"
#include "scene.h"
#include "sf_error.h"   /* SF_EXIT_* */

/* Read a scene file with Table 1 defaults; on error print it and return
 * SF_EXIT_USAGE. */
int sf_cli_load_scene(const char *cmd, const char *path, sf_scene *s);

/* Output file written under a temporary name, renamed on sf_cli_close
 * (path "-" is stdout).  On failure the temporary file is removed. */
typedef struct {
    FILE *f;
    char final[1024], tmp[1100];
    int is_stdout;
} sf_out;
int sf_cli_open(const char *cmd, const char *path, sf_out *o);
int sf_cli_close(const char *cmd, sf_out *o, int ok);

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

#endif
