/* The command-line option parser every command shares (options.h):
 * options and positional arguments, typed and range-checked values, and
 * the usage message on a bad one. */
#include "options.h"
#include "sf_error.h"   /* SF_EXIT_* */

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int opt_size(const char *cmd, const char *opt, const char *v, size_t lo, size_t hi, size_t *out)
{
    char *end;
    errno = 0;
    unsigned long long x = strtoull(v, &end, 10);
    if (!*v || *end || errno || v[0] == '-' || x < lo || x > hi) {
        fprintf(stderr, "slipfield %s: %s takes a whole number from %zu to %zu\n", cmd, opt, lo, hi);
        return SF_EXIT_USAGE;
    }
    *out = (size_t)x;
    return SF_EXIT_OK;
}

static int opt_double(const char *cmd, const char *opt, const char *v, double *out)
{
    char *end;
    double x = strtod(v, &end);
    if (!*v || *end || !isfinite(x)) {
        fprintf(stderr, "slipfield %s: %s takes a finite number\n", cmd, opt);
        return SF_EXIT_USAGE;
    }
    *out = x;
    return SF_EXIT_OK;
}

/* Option o with value v (NULL when none follows); *used: v was consumed;
 * inline: v came as --name=v.  Returns SF_EXIT_OK, SF_OPT_DONE or an exit
 * status. */
static int take(const sf_optspec *sp, const sf_opt *o, const char *v, int inline_v, int *used)
{
    *used = 0;
    if (inline_v && (o->kind == SF_OPT_FLAG || o->kind == SF_OPT_ACTION)) {
        fprintf(stderr, "slipfield %s: %s takes no value\n", sp->cmd, o->name);
        return SF_EXIT_USAGE;
    }
    switch (o->kind) {
    case SF_OPT_FLAG:
        *(int *)o->dst = 1;
        return SF_EXIT_OK;
    case SF_OPT_ACTION: {
        int rc = o->fn(sp->cmd, NULL, o->dst);
        return rc ? rc : SF_OPT_DONE;
    }
    default:
        break;
    }
    if (!v) {
        fprintf(stderr, "slipfield %s: %s needs a value\n", sp->cmd, o->name);
        sp->usage(stderr);
        return SF_EXIT_USAGE;
    }
    *used = !inline_v;
    switch (o->kind) {
    case SF_OPT_SIZE: return opt_size(sp->cmd, o->name, v, o->lo, o->hi, o->dst);
    case SF_OPT_DOUBLE: return opt_double(sp->cmd, o->name, v, o->dst);
    case SF_OPT_FN: return o->fn(sp->cmd, v, o->dst);
    default: *(const char **)o->dst = v; return SF_EXIT_OK;
    }
}

/* The option named a[0..len) ("--name" of "--name=value"). */
static const sf_opt *find_opt(const sf_optspec *sp, const char *a, size_t len)
{
    for (size_t k = 0; k < sp->nopts; k++)
        if (strlen(sp->opts[k].name) == len && !strncmp(a, sp->opts[k].name, len))
            return &sp->opts[k];
    return NULL;
}

int sf_opt_parse(const sf_optspec *sp, int argc, char **argv, const char **pos, size_t *npos)
{
    *npos = 0;
    int only_pos = 0;   /* after "--" */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!only_pos && !strcmp(a, "--")) {
            only_pos = 1;
            continue;
        }
        if (only_pos || a[0] != '-' || !a[1]) {
            if (sp->max_pos && *npos == sp->max_pos) {
                fprintf(stderr, "slipfield %s: %s\n", sp->cmd, sp->too_many);
                return SF_EXIT_USAGE;
            }
            pos[(*npos)++] = a;
            continue;
        }
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            sp->usage(stdout);
            return SF_OPT_DONE;
        }
        const char *eq = strncmp(a, "--", 2) ? NULL : strchr(a, '=');
        const sf_opt *o = find_opt(sp, a, eq ? (size_t)(eq - a) : strlen(a));
        if (!o) {
            fprintf(stderr, "slipfield %s: unknown option: %.*s\n", sp->cmd, eq ? (int)(eq - a) : (int)strlen(a), a);
            sp->usage(stderr);
            return SF_EXIT_USAGE;
        }
        int used, rc = take(sp, o, eq ? eq + 1 : i + 1 < argc ? argv[i + 1] : NULL, eq != NULL, &used);
        if (rc)
            return rc;
        i += used;
    }
    if (*npos == 0) {
        if (sp->none)
            fprintf(stderr, "slipfield %s: %s\n", sp->cmd, sp->none);
        sp->usage(stderr);
        return SF_EXIT_USAGE;
    }
    return SF_EXIT_OK;
}
