/* Shared helpers of the CLI's subcommands (cli.h): loading a scene and
 * warning on keys a command ignores, output files, exit statuses, and
 * the option parse. */
#include "cli.h"
#include "sf_error.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>

/* Scene keys that only some commands read (every other key is read by
 * every command that builds the scene's COF or runs it). */
static const struct {
    const char *key, *users;
} key_users[] = {
    { "samples", "field sweep" },   /* --samples, --realisations when not given */
    { "u", "wrench" }, { "v", "wrench" }, { "w", "wrench" },   /* --vx, --vy, --spin when not given */
    { "ntheta", "surface" }, { "npsi", "surface" },
};

static int is_user(const char *users, const char *cmd)
{
    size_t n = strlen(cmd);
    for (const char *p = strstr(users, cmd); p; p = strstr(p + 1, cmd))
        if ((p == users || p[-1] == ' ') && (p[n] == ' ' || !p[n]))
            return 1;
    return 0;
}

const char *sf_cli_key_ignored(const char *cmd, const char *key)
{
    for (size_t k = 0; k < sizeof key_users / sizeof key_users[0]; k++)
        if (!strcmp(key_users[k].key, key))
            return is_user(key_users[k].users, cmd) ? NULL : key_users[k].users;
    return NULL;
}

int sf_cli_load_scene(const char *cmd, const char *path, sf_scene *s)
{
    char err[512];
    sf_scene_default(s);
    int rc = sf_scene_read_file(s, path, err, sizeof err);
    if (rc) {
        fprintf(stderr, "slipfield %s: %s\n", cmd, err);
        return SF_EXIT_USAGE;
    }
    for (size_t k = 0; k < sizeof key_users / sizeof key_users[0]; k++)
        if (sf_scene_was_set(s, key_users[k].key) && !is_user(key_users[k].users, cmd))
            fprintf(stderr, "slipfield %s: %s: warning: key '%s' is ignored by %s (read by: %s)\n", cmd, path,
                    key_users[k].key, cmd, key_users[k].users);
    return SF_EXIT_OK;
}

void sf_cli_key_overridden(const char *cmd, const char *path, const sf_scene *s, const char *key, const char *opt)
{
    if (sf_scene_was_set(s, key))
        fprintf(stderr, "slipfield %s: %s: warning: key '%s' is ignored: %s given\n", cmd, path, key, opt);
}

void sf_cli_warn_truncated(const char *cmd, const char *path, const sf_scene *s, const sf_cof_plan *p)
{
    if (p && sf_cof_plan_truncated(p))
        fprintf(stderr, "slipfield %s: %s: warning: the COF field's circulant embedding reached its padding cap "
                        "(pad_cap = %g): negative eigenvalues clamped, its covariance is not Eq. 2's; raise pad_cap "
                        "(`slipfield field` measures the covariance error)\n", cmd, path, s->pad_cap);
}

int sf_cli_status(int rc)
{
    return rc == SF_SUCCESS ? SF_EXIT_OK : rc == SF_ENOMEM ? SF_EXIT_INTERNAL : SF_EXIT_USAGE;
}

/* The temporary files open now, removed if a signal ends the program
 * (written before the handler can run, cleared when closed). */
#define MAX_TMP 4
static char tmp_names[MAX_TMP][1100];
static volatile sig_atomic_t tmp_used[MAX_TMP];
static const char *interrupt_hint = "";

void sf_cli_interrupt_hint(const char *hint)
{
    interrupt_hint = hint;
}

/* Only async-signal-safe calls: unlink, write, signal, raise. */
static void on_signal(int sig)
{
    for (int k = 0; k < MAX_TMP; k++)
        if (tmp_used[k])
            unlink(tmp_names[k]);
    static const char msg[] = "slipfield: interrupted";
    ssize_t w = write(2, msg, sizeof msg - 1);
    w += write(2, interrupt_hint, strlen(interrupt_hint));
    w += write(2, "\n", 1);
    (void)w;
    signal(sig, SIG_DFL);
    raise(sig);   /* the status says which signal ended the run */
}

static void track_tmp(sf_out *o)
{
    static int trapped;
    if (!trapped) {
        trapped = 1;
        signal(SIGINT, on_signal);
        signal(SIGTERM, on_signal);
        signal(SIGHUP, on_signal);
    }
    for (int k = 0; k < MAX_TMP; k++)
        if (!tmp_used[k]) {
            memcpy(tmp_names[k], o->tmp, sizeof o->tmp);
            tmp_used[k] = 1;
            return;
        }
}

static void untrack_tmp(const sf_out *o)
{
    for (int k = 0; k < MAX_TMP; k++)
        if (tmp_used[k] && !strcmp(tmp_names[k], o->tmp))
            tmp_used[k] = 0;
}

int sf_cli_open(const char *cmd, const char *path, const char *input, sf_out *o)
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
    struct stat in, out, link;
    int exists = stat(path, &out) == 0;
    if (exists && input && stat(input, &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino) {
        fprintf(stderr, "slipfield %s: --out %s is the input scene %s: refusing to overwrite it\n", cmd, path, input);
        return SF_EXIT_USAGE;
    }
    struct stat so;
    if (exists && fstat(STDOUT_FILENO, &so) == 0 && so.st_dev == out.st_dev && so.st_ino == out.st_ino) {
        o->f = stdout;   /* /dev/stdout, or the file stdout already writes: share its offset */
        o->is_stdout = 1;
        return SF_EXIT_OK;
    }
    if (exists && S_ISDIR(out.st_mode)) {
        fprintf(stderr, "slipfield %s: cannot write %s: %s\n", cmd, path, strerror(EISDIR));
        return SF_EXIT_USAGE;
    }
    /* a device, a FIFO or a link (/dev/stdout) is written in place: a
       rename would replace it with a regular file */
    o->in_place = lstat(path, &link) == 0 && !S_ISREG(link.st_mode);
    if (o->in_place) {
        o->f = fopen(path, "w");
    } else {
        snprintf(o->tmp, sizeof o->tmp, "%s.tmp%ld", path, (long)getpid());
        o->f = fopen(o->tmp, "w");
        if (o->f)
            track_tmp(o);
    }
    if (!o->f) {
        fprintf(stderr, "slipfield %s: cannot write %s: %s\n", cmd, o->in_place ? path : o->tmp, strerror(errno));
        return SF_EXIT_USAGE;
    }
    return SF_EXIT_OK;
}

int sf_cli_close(const char *cmd, sf_out *o, int ok)
{
    /* a write error leaves errno set; flushing what is buffered says it
       again (ENOSPC: a full disk or /dev/full) */
    errno = 0;
    int bad = ferror(o->f), e = errno;
    if (o->is_stdout ? fflush(o->f) != 0 : fclose(o->f) != 0)
        bad = 1, e = errno;
    const char *name = o->is_stdout ? "stdout" : o->final;
    if (bad)
        fprintf(stderr, "slipfield %s: error writing %s: %s\n", cmd, name, strerror(e ? e : EIO));
    if (!o->is_stdout && !o->in_place) {
        if (ok && !bad && rename(o->tmp, o->final) != 0) {
            fprintf(stderr, "slipfield %s: cannot rename to %s: %s\n", cmd, o->final, strerror(errno));
            bad = 1;
        }
        if (!ok || bad)
            unlink(o->tmp);
        untrack_tmp(o);
    }
    return bad ? SF_EXIT_USAGE : ok ? SF_EXIT_OK : SF_EXIT_INTERNAL;
}

int sf_cli_parse(const char *cmd, int argc, char **argv, const sf_opt *opts, size_t nopts,
                 const char **scene, void (*usage)(FILE *))
{
    sf_optspec sp = { cmd, opts, nopts, usage, 1, "more than one scene given", NULL };
    size_t n;
    *scene = NULL;
    return sf_opt_parse(&sp, argc, argv, scene, &n);
}
