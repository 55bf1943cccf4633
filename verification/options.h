/* slipfield: one command-line option parser for every command.  The CLI's
 * subcommands (cli/) and `slipfield verify` (verification/runner.c) declare
 * their options in a table and call sf_opt_parse; it lives here because
 * verification/ must not include cli/ and cli/ may include verification/.
 *
 * getopt_long's conventions: options and positional arguments mix in any
 * order, `--name=value` is `--name value`, "--" ends the options (what
 * follows is positional), and "-" is a positional argument (stdout or
 * stdin as a path).  Messages go to stderr as "slipfield CMD: ...", usage
 * errors return SF_EXIT_USAGE (2). */
#ifndef SF_OPTIONS_H
#define SF_OPTIONS_H

#include <stddef.h>
#include <stdio.h>

/* SF_OPT_SIZE: `--name N`, a whole number in [lo, hi] (size_t *dst).
 * SF_OPT_DOUBLE: `--name X`, a finite number (double *dst).
 * SF_OPT_STRING: `--name TEXT` (const char **dst).
 * SF_OPT_FLAG: `--name` (int *dst set to 1).
 * SF_OPT_FN: `--name VALUE`, fn parses VALUE into dst; on bad input it
 *   prints its own message and returns an exit status.
 * SF_OPT_ACTION: `--name` runs fn(cmd, NULL, dst) and ends the parse
 *   (like --help): sf_opt_parse returns SF_OPT_DONE. */
enum { SF_OPT_SIZE, SF_OPT_DOUBLE, SF_OPT_STRING, SF_OPT_FLAG, SF_OPT_FN, SF_OPT_ACTION };
typedef struct {
    const char *name;   /* e.g. "--samples" */
    int kind;
    void *dst;
    size_t lo, hi;      /* SF_OPT_SIZE range */
    int (*fn)(const char *cmd, const char *value, void *dst);   /* SF_OPT_FN, SF_OPT_ACTION */
} sf_opt;

/* A command's options and positional arguments. */
typedef struct {
    const char *cmd;            /* "run", "verify": messages say "slipfield CMD: ..." */
    const sf_opt *opts;
    size_t nopts;
    void (*usage)(FILE *);      /* -h, --help: to stdout; after an unknown option: to stderr */
    size_t max_pos;             /* at most this many positional arguments (0: any number) */
    const char *too_many;       /* the message when there are more */
    const char *none;           /* the message (before the usage) when there is none; NULL: usage only */
} sf_optspec;

/* -h/--help printed, or an action ran: the command exits 0. */
#define SF_OPT_DONE (-1)

/* Parse argv[1..argc): options into their destinations, positional
 * arguments into pos[0..*npos) (room for max_pos entries; argc when
 * max_pos is 0).  Returns
 * SF_EXIT_OK, SF_OPT_DONE, or an exit status after printing why. */
int sf_opt_parse(const sf_optspec *sp, int argc, char **argv, const char **pos, size_t *npos);

#endif
