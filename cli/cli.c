#include "cli.h"
#include "sf_error.h"

#include <errno.h>
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

int sf_cli_parse(const char *cmd, int argc, char **argv, const sf_opt *opts, size_t nopts,
                 const char **scene, void (*usage)(FILE *))
{
    sf_optspec sp = { cmd, opts, nopts, usage, 0, 1, "more than one scene given", NULL };
    size_t n;
    *scene = NULL;
    return sf_opt_parse(&sp, argc, argv, scene, &n);
}
