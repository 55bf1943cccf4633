#include "cli.h"
#include "sf_error.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int sf_cli_load_scene(const char *cmd, const char *path, sf_scene *s)
{
    char err[512];
    sf_scene_default(s);
    int rc = sf_scene_read_file(s, path, err, sizeof err);
    if (rc) {
        fprintf(stderr, "slipfield %s: %s\n", cmd, err);
        return SF_EXIT_USAGE;
    }
    return SF_EXIT_OK;
}

int sf_cli_open(const char *cmd, const char *path, sf_out *o)
{
    memset(o, 0, sizeof *o);
    if (!strcmp(path, "-")) {
        o->f = stdout;
        o->is_stdout = 1;
        return SF_EXIT_OK;
    }
    if (strlen(path) >= sizeof o->final) {
        fprintf(stderr, "slipfield %s: output path too long\n", cmd);
        return SF_EXIT_USAGE;
    }
    snprintf(o->final, sizeof o->final, "%s", path);
    snprintf(o->tmp, sizeof o->tmp, "%s.tmp%ld", path, (long)getpid());
    o->f = fopen(o->tmp, "w");
    if (!o->f) {
        fprintf(stderr, "slipfield %s: cannot write %s: %s\n", cmd, o->tmp, strerror(errno));
        return SF_EXIT_USAGE;
    }
    return SF_EXIT_OK;
}

int sf_cli_close(const char *cmd, sf_out *o, int ok)
{
    if (o->is_stdout)
        return fflush(stdout) == 0 && ok ? SF_EXIT_OK : SF_EXIT_INTERNAL;
    int bad = ferror(o->f);
    if (fclose(o->f) != 0)
        bad = 1;
    if (!ok || bad) {
        unlink(o->tmp);
        if (bad)
            fprintf(stderr, "slipfield %s: error writing %s\n", cmd, o->final);
        return SF_EXIT_INTERNAL;
    }
    if (rename(o->tmp, o->final) != 0) {
        fprintf(stderr, "slipfield %s: cannot rename to %s: %s\n", cmd, o->final, strerror(errno));
        unlink(o->tmp);
        return SF_EXIT_INTERNAL;
    }
    return SF_EXIT_OK;
}

int sf_cli_size(const char *cmd, const char *opt, const char *v, size_t lo, size_t hi, size_t *out)
{
    char *end;
    errno = 0;
    unsigned long long x = v ? strtoull(v, &end, 10) : 0;
    if (!v || !*v || *end || errno || v[0] == '-' || x < lo || x > hi) {
        fprintf(stderr, "slipfield %s: %s takes a whole number from %zu to %zu\n", cmd, opt, lo, hi);
        return SF_EXIT_USAGE;
    }
    *out = (size_t)x;
    return SF_EXIT_OK;
}

int sf_cli_double(const char *cmd, const char *opt, const char *v, double *out)
{
    char *end;
    double x = v ? strtod(v, &end) : NAN;
    if (!v || !*v || *end || !isfinite(x)) {
        fprintf(stderr, "slipfield %s: %s takes a finite number\n", cmd, opt);
        return SF_EXIT_USAGE;
    }
    *out = x;
    return SF_EXIT_OK;
}

int sf_cli_parse(const char *cmd, int argc, char **argv, const sf_opt *opts, size_t nopts,
                 const char **scene, void (*usage)(FILE *))
{
    *scene = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return SF_CLI_HELP;
        }
        const sf_opt *o = NULL;
        for (size_t k = 0; k < nopts; k++)
            if (!strcmp(a, opts[k].name))
                o = &opts[k];
        if (o && o->kind == SF_OPT_FLAG) {
            *(int *)o->dst = 1;
            continue;
        }
        if (o && v) {
            int bad = 0;
            if (o->kind == SF_OPT_SIZE)
                bad = sf_cli_size(cmd, a, v, o->lo, o->hi, o->dst);
            else if (o->kind == SF_OPT_DOUBLE)
                bad = sf_cli_double(cmd, a, v, o->dst);
            else
                *(const char **)o->dst = v;
            if (bad)
                return SF_EXIT_USAGE;
            i++;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "slipfield %s: unknown option or missing value: %s\n", cmd, a);
            usage(stderr);
            return SF_EXIT_USAGE;
        } else if (!*scene) {
            *scene = a;
        } else {
            fprintf(stderr, "slipfield %s: more than one scene given\n", cmd);
            return SF_EXIT_USAGE;
        }
    }
    if (!*scene) {
        usage(stderr);
        return SF_EXIT_USAGE;
    }
    return SF_EXIT_OK;
}
