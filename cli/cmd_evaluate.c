/* slipfield evaluate SCENE --design FILE --out FILE [--threads T] [--no-unum]
 * The model at each row of an external design (SALib, OpenTURNS, Chaospy
 * ...): a TSV table whose header names scene keys.  Row j is the scene
 * with the row's values, on realisation j's field (the stream a sweep
 * gives its realisation j), or the row's own realisation index or seed;
 * out: the design's columns, per QoI its value, its ratio to the
 * deterministic model at the row's parameters and its u_num, and the
 * row's status.  The rows run through sf_mc_run: the same bytes for any
 * thread count. */
#include "cli.h"
#include "model.h"
#include "montecarlo.h"
#include "numplan.h"
#include "oscillator.h"
#include "sf_error.h"
#include "sweep.h"
#include "unum.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void usage(FILE *f)
{
    fputs("usage: slipfield evaluate SCENE --design FILE --out FILE [--threads T]\n"
          "                                [--no-unum]\n"
          "The model at each row of a design (a table of parameter sets, e.g. made by\n"
          "SALib, OpenTURNS or Chaospy): one realisation per row.\n"
          "  --design FILE  TSV ('-': stdin): a header line naming the columns, then one\n"
          "                 row per parameter set, cells separated by tabs; blank lines\n"
          "                 and lines starting with '#' are skipped (numpy: savetxt(...,\n"
          "                 delimiter='\\t', header=..., comments='')).  A column is\n"
          "                 any numeric scene key (l, v_b, mu_mean, mu_std, T, t_skip, k,\n"
          "                 m, R, ...: 'slipfield help scene'; each cell checked as the\n"
          "                 scene file's value is, with the same bounds and messages),\n"
          "                 the row's values replacing the scene's; or\n"
          "                   l_over_R     sets l = value x R (after the row's R)\n"
          "                   realisation  the field of realisation I (0 to 9999999):\n"
          "                                stream sf_mc_seed(scene seed, I), the field of\n"
          "                                `slipfield sweep`'s realisation I and of\n"
          "                                `slipfield run --realisation I`\n"
          "                   seed         the row's own seed: the field `slipfield run`\n"
          "                                draws for the scene with that seed\n"
          "                 Without realisation or seed, row j (0, 1, ... in file order)\n"
          "                 is realisation j.  mu_mean sets the mean COF alone (sweep\n"
          "                 --param mu_mean holds the CV: give mu_std too for that).\n"
          "  --out FILE     TSV ('-': stdout), one row per design row: the design's\n"
          "                 cells as given, then per QoI its value, its ratio to the\n"
          "                 deterministic model (uniform COF at the row's mu_mean, same\n"
          "                 T, t_skip and stepper: as sweep's ratios) and its numerical\n"
          "                 error u_num (as run --summary's: a coarser companion solve\n"
          "                 of the same realisation: up to ~2/3 more CPU, --no-unum):\n"
          "                   pv_x[m] pv_x_ratio[-] u_pv_x[m]\n"
          "                   pv_F[N] pv_F_ratio[-] u_pv_F[N]\n"
          "                   stick_fraction[-] stick_fraction_ratio[-]\n"
          "                   u_stick_fraction[-]\n"
          "                 and status: ok, or why the row failed (its run, or its\n"
          "                 deterministic reference: then its ratios are nan; what the\n"
          "                 row computed is kept, the rest nan).  A QoI the run cannot\n"
          "                 form (no complete cycle after t_skip) is nan with status ok\n"
          "                 (said on stderr)\n"
          "  --threads T    OpenMP threads (default: all); the output does not depend\n"
          "                 on it (the rows run as a sweep's realisations)\n"
          "  --no-unum      no companion solves (the u_ columns nan)\n"
          "Exit status: 0 every row ok, 1 a row failed (the others are filled),\n"
          "2 bad input (a cell, the design's layout: file:line:column) before any run.\n",
          f);
}

enum { COL_KEY, COL_LR, COL_SEED, COL_REAL };
#define REAL_MAX 9999999
#define MAX_ROWS 1000000

/* The output of a row: per QoI value, ratio, u_num; then its status code. */
enum { NQ = SF_SWEEP_NQ, O_VAL = SF_MODEL_PVX, O_RATIO = SF_MODEL_RATIO, O_U = SF_MODEL_U, O_RC = SF_MODEL_NOUT,
       NOUT = SF_MODEL_NOUT + 1 };
#define MSG 240

typedef struct {
    char *name;
    int kind;
    size_t key;     /* COL_KEY, COL_SEED: index in the scene's key table */
} column;

typedef struct {
    sf_scene s;              /* the scene with the row's values */
    int line;                /* in the design */
    int own_seed;            /* 1: the MT19937 at s.seed; 0: realisation `real`'s stream */
    size_t real;
    char **cell;             /* the cells as given (pointers into text) */
    char *text;
} design_row;

typedef struct {
    const design_row *rows;
    unsigned long seed;      /* the scene's: realisation i's stream is sf_mc_stream(seed, i) */
    int unum;
    char *msg;               /* MSG per row: its error, or a warning when its status is ok */
} eval_ctx;

/* A thread's workspace: the model's (its cache of the last scene's COF
 * plan and reference, model.h) and the rows it reads. */
typedef struct {
    const eval_ctx *c;
    sf_model_ws *m;
} eval_ws;

static void *ws_alloc(void *ctx)
{
    eval_ws *w = calloc(1, sizeof *w);
    if (w && !(w->m = sf_model_ws_alloc())) {
        free(w);
        return NULL;
    }
    if (w)
        w->c = ctx;
    return w;
}

static void ws_free(void *p)
{
    eval_ws *w = p;
    sf_model_ws_free(w->m);
    free(w);
}

/* Row i on its stream (the model's solve): a failed row fails alone, its
 * status says why. */
static int eval_row(void *p, size_t i, gsl_rng *rng, double *out)
{
    eval_ws *w = p;
    const design_row *row = &w->c->rows[i];
    char *msg = w->c->msg + i * MSG;
    if (row->own_seed)
        gsl_rng_set(rng, row->s.seed);   /* as `slipfield run` seeds the scene's field */
    else
        sf_mc_stream(rng, w->c->seed, row->real);   /* as a sweep seeds its realisation */
    out[O_RC] = sf_model_ws_solve(w->m, &row->s, rng, w->c->unum, out, msg, MSG);
    return SF_SUCCESS;
}

/* ---- reading the design ---- */

typedef struct {
    const char *path;
    column *col;
    size_t ncol;
    design_row *rows;
    size_t nrows;
} design;

static void design_free(design *d)
{
    for (size_t c = 0; c < d->ncol; c++)
        free(d->col[c].name);
    free(d->col);
    for (size_t j = 0; j < d->nrows; j++) {
        free(d->rows[j].cell);
        free(d->rows[j].text);
    }
    free(d->rows);
}

/* Split line (its newline gone) at tabs into cells trimmed of blanks:
 * cell[k] and its 1-based column pos[k]; returns the number of cells or 0
 * on an allocation failure. */
static size_t split(char *line, char ***cell, int **pos)
{
    size_t n = 1;
    for (char *p = line; *p; p++)
        n += *p == '\t';
    *cell = malloc(n * sizeof **cell);
    *pos = malloc(n * sizeof **pos);
    if (!*cell || !*pos) {
        free(*cell);
        free(*pos);
        return 0;
    }
    char *p = line;
    for (size_t k = 0; k < n; k++) {
        char *end = strchr(p, '\t');
        if (end)
            *end = '\0';
        while (*p == ' ')
            p++;
        size_t len = strlen(p);
        while (len && (p[len - 1] == ' '))
            p[--len] = '\0';
        (*cell)[k] = p;
        (*pos)[k] = (int)(p - line) + 1;
        p = end ? end + 1 : p + len;
    }
    return n;
}

/* A header cell: its column kind, or an error (SF_EXIT_USAGE, printed). */
static int header_column(const design *d, const sf_scene *s0, int line, int pos, const char *name, column *c)
{
    c->key = 0;
    if (!strcmp(name, "l_over_R")) {
        c->kind = COL_LR;
        return SF_EXIT_OK;
    }
    if (!strcmp(name, "realisation")) {
        c->kind = COL_REAL;
        return SF_EXIT_OK;
    }
    sf_keytab t = sf_scene_keytab(s0);
    for (size_t k = 0; k < t.n; k++)
        if (!strcmp(t.keys[k].name, name)) {
            const sf_key *key = &t.keys[k];
            const char *users = sf_cli_key_ignored("evaluate", name);
            if (key->type != SF_KEY_DOUBLE && key->type != SF_KEY_SIZE && key->type != SF_KEY_ULONG) {
                fprintf(stderr, "slipfield evaluate: %s:%d:%d: column '%s': not a numeric scene key (set it in the "
                                "scene)\n", d->path, line, pos, name);
                return SF_EXIT_USAGE;
            }
            if (users) {
                fprintf(stderr, "slipfield evaluate: %s:%d:%d: column '%s': a scene key evaluate does not read (read "
                                "by: %s)\n", d->path, line, pos, name, users);
                return SF_EXIT_USAGE;
            }
            c->kind = strcmp(name, "seed") ? COL_KEY : COL_SEED;
            c->key = k;
            return SF_EXIT_OK;
        }
    fprintf(stderr, "slipfield evaluate: %s:%d:%d: unknown column '%.40s' (a numeric scene key, l_over_R, realisation "
                    "or seed; see 'slipfield help scene')\n", d->path, line, pos, name);
    return SF_EXIT_USAGE;
}

static int read_header(design *d, const sf_scene *s0, char *line, int lineno)
{
    char **cell;
    int *pos;
    size_t n = split(line, &cell, &pos);
    if (!n)
        return SF_EXIT_INTERNAL;
    d->col = calloc(n, sizeof *d->col);
    int rc = d->col ? SF_EXIT_OK : SF_EXIT_INTERNAL;
    int has[4] = { 0 }, l_col = 0;
    for (size_t k = 0; k < n && !rc; k++) {
        if (!*cell[k]) {
            fprintf(stderr, "slipfield evaluate: %s:%d:%d: empty column name\n", d->path, lineno, pos[k]);
            rc = SF_EXIT_USAGE;
            break;
        }
        for (size_t e = 0; e < k && !rc; e++)
            if (!strcmp(d->col[e].name, cell[k])) {
                fprintf(stderr, "slipfield evaluate: %s:%d:%d: column '%s' given twice\n", d->path, lineno, pos[k],
                        cell[k]);
                rc = SF_EXIT_USAGE;
            }
        if (rc || (rc = header_column(d, s0, lineno, pos[k], cell[k], &d->col[k])))
            break;
        if (!(d->col[k].name = strdup(cell[k]))) {
            rc = SF_EXIT_INTERNAL;
            break;
        }
        d->ncol = k + 1;
        has[d->col[k].kind] = 1;
        l_col |= d->col[k].kind == COL_KEY && !strcmp(cell[k], "l");
    }
    if (!rc && l_col && has[COL_LR]) {
        fprintf(stderr, "slipfield evaluate: %s:%d: columns 'l' and 'l_over_R' both set l: give one\n", d->path,
                lineno);
        rc = SF_EXIT_USAGE;
    }
    if (!rc && has[COL_SEED] && has[COL_REAL]) {
        fprintf(stderr, "slipfield evaluate: %s:%d: columns 'seed' and 'realisation' both choose the row's field: "
                        "give one\n", d->path, lineno);
        rc = SF_EXIT_USAGE;
    }
    free(cell);
    free(pos);
    return rc;
}

/* The scene parser's message "file:line: ..." as "file:line:col: ...". */
static void at_column(const char *err, const char *path, int line, int pos)
{
    char pre[1100];
    int n = snprintf(pre, sizeof pre, "%s:%d:", path, line);
    if (n > 0 && (size_t)n < sizeof pre && !strncmp(err, pre, (size_t)n))
        fprintf(stderr, "slipfield evaluate: %s:%d:%d:%s\n", path, line, pos, err + n);
    else
        fprintf(stderr, "slipfield evaluate: %s:%d:%d: %s\n", path, line, pos, err);
}

/* A whole number in [0, REAL_MAX] filling all of v. */
static int whole(const char *v, size_t *out)
{
    if (!isdigit((unsigned char)*v))
        return 0;
    char *end;
    errno = 0;
    unsigned long long x = strtoull(v, &end, 10);
    if (*end || errno || x > REAL_MAX)
        return 0;
    *out = (size_t)x;
    return 1;
}

/* Row j (the cells of the line) over scene s0 into r. */
static int read_row(design *d, const sf_scene *s0, design_row *r, size_t j, char **cell, const int *pos)
{
    memcpy(&r->s, s0, sizeof *s0);
    r->own_seed = 0;
    r->real = j;
    int lr = -1;
    for (size_t k = 0; k < d->ncol; k++) {
        const column *c = &d->col[k];
        if (!*cell[k]) {
            fprintf(stderr, "slipfield evaluate: %s:%d:%d: column '%s': empty cell\n", d->path, r->line, pos[k],
                    c->name);
            return SF_EXIT_USAGE;
        }
        if (strchr(cell[k], '#')) {   /* the scene parser would take it for a comment */
            fprintf(stderr, "slipfield evaluate: %s:%d:%d: column '%s': expected a number, got '%.40s'\n", d->path,
                    r->line, pos[k], c->name, cell[k]);
            return SF_EXIT_USAGE;
        }
        if (c->kind == COL_LR) {
            lr = (int)k;
        } else if (c->kind == COL_REAL) {
            if (!whole(cell[k], &r->real)) {
                fprintf(stderr, "slipfield evaluate: %s:%d:%d: column 'realisation': expected a whole number from 0 "
                                "to %d, got '%.40s'\n", d->path, r->line, pos[k], REAL_MAX, cell[k]);
                return SF_EXIT_USAGE;
            }
        } else {   /* a scene key: the scene file's parser, its bounds and messages */
            sf_keytab t = sf_scene_keytab(&r->s);
            t.set[c->key] = 0;   /* the row's value replaces the scene's */
            size_t len = strlen(c->name) + strlen(cell[k]) + 5;
            char *text = malloc(len), err[512];
            if (!text)
                return SF_EXIT_INTERNAL;
            snprintf(text, len, "%s = %s", c->name, cell[k]);
            int rc = sf_scene_parse(&r->s, text, d->path, r->line, err, sizeof err);
            free(text);
            if (rc) {
                at_column(err, d->path, r->line, pos[k]);
                return SF_EXIT_USAGE;
            }
            r->own_seed |= c->kind == COL_SEED;
        }
    }
    if (lr >= 0) {   /* after the row's R */
        char *end;
        double x = strtod(cell[lr], &end);
        if (*end || !isfinite(x)) {
            fprintf(stderr, "slipfield evaluate: %s:%d:%d: column 'l_over_R': expected a finite number, got '%.40s'\n",
                    d->path, r->line, pos[lr], cell[lr]);
            return SF_EXIT_USAGE;
        }
        if (!(x > 0) || !isfinite(x * r->s.R)) {
            fprintf(stderr, "slipfield evaluate: %s:%d:%d: column 'l_over_R': must be > 0 with l = l_over_R x R "
                            "finite (got %g)\n", d->path, r->line, pos[lr], x);
            return SF_EXIT_USAGE;
        }
        r->s.l = x * r->s.R;
    }
    return SF_EXIT_OK;
}

/* The design file: header, then rows over scene s0.  SF_EXIT_OK or an
 * exit status after printing why. */
static int read_design(design *d, const sf_scene *s0)
{
    FILE *f = strcmp(d->path, "-") ? fopen(d->path, "r") : stdin;
    if (!f) {
        fprintf(stderr, "slipfield evaluate: %s: cannot open: %s\n", d->path, strerror(errno));
        return SF_EXIT_USAGE;
    }
    char *line = NULL;
    size_t cap = 0, rcap = 0;
    ssize_t len;
    int lineno = 0, rc = SF_EXIT_OK, header = 0;
    errno = 0;
    while (!rc && (len = getline(&line, &cap, f)) >= 0) {
        lineno++;
        if (strlen(line) != (size_t)len) {
            fprintf(stderr, "slipfield evaluate: %s:%d: a NUL byte in the design\n", d->path, lineno);
            rc = SF_EXIT_USAGE;
            break;
        }
        while (len && (line[len - 1] == '\n' || line[len - 1] == '\r'))
            line[--len] = '\0';
        if (lineno == 1 && !strncmp(line, "\xef\xbb\xbf", 3))   /* a UTF-8 byte-order mark (spreadsheets) */
            memmove(line, line + 3, (size_t)(len -= 3) + 1);
        const char *p = line;
        while (isspace((unsigned char)*p))
            p++;
        if (!*p || *p == '#')
            continue;
        if (!header) {
            header = 1;
            rc = read_header(d, s0, line, lineno);
            continue;
        }
        if (d->nrows == MAX_ROWS) {
            fprintf(stderr, "slipfield evaluate: %s:%d: more than %d rows\n", d->path, lineno, MAX_ROWS);
            rc = SF_EXIT_USAGE;
            break;
        }
        if (d->nrows == rcap) {
            size_t nc = rcap ? 2 * rcap : 64;
            design_row *nr = realloc(d->rows, nc * sizeof *nr);
            if (!nr) {
                rc = SF_EXIT_INTERNAL;
                break;
            }
            d->rows = nr;
            rcap = nc;
        }
        design_row *r = &d->rows[d->nrows];
        memset(r, 0, sizeof *r);
        r->line = lineno;
        int *pos = NULL;
        size_t n = (r->text = strdup(line)) ? split(r->text, &r->cell, &pos) : 0;
        d->nrows++;   /* (freed with the design from here) */
        if (!n)
            rc = SF_EXIT_INTERNAL;
        else if (n != d->ncol) {
            fprintf(stderr, "slipfield evaluate: %s:%d: %zu cell%s, the header has %zu column%s\n", d->path, lineno, n,
                    n == 1 ? "" : "s", d->ncol, d->ncol == 1 ? "" : "s");
            rc = SF_EXIT_USAGE;
        } else
            rc = read_row(d, s0, r, d->nrows - 1, r->cell, pos);
        free(pos);
    }
    int bad = !rc && ferror(f);
    free(line);
    if (f != stdin)
        fclose(f);
    if (bad) {
        fprintf(stderr, "slipfield evaluate: %s: cannot read: %s\n", d->path, strerror(errno ? errno : EIO));
        return SF_EXIT_USAGE;
    }
    if (!rc && !header) {
        fprintf(stderr, "slipfield evaluate: %s: no header line (the column names)\n", d->path);
        return SF_EXIT_USAGE;
    }
    if (!rc && !d->nrows) {
        fprintf(stderr, "slipfield evaluate: %s: no rows under the header\n", d->path);
        return SF_EXIT_USAGE;
    }
    if (rc == SF_EXIT_INTERNAL)
        fprintf(stderr, "slipfield evaluate: %s: out of memory\n", d->path);
    return rc;
}

/* A message as one TSV cell: tabs and line breaks as blanks. */
static void put_cell(FILE *f, const char *m)
{
    for (; *m; m++)
        fputc(*m == '\t' || *m == '\n' || *m == '\r' ? ' ' : *m, f);
}

static int same_file(const char *a, const char *b)
{
    struct stat x, y;
    return strcmp(a, "-") && strcmp(b, "-") && stat(a, &x) == 0 && stat(b, &y) == 0 && x.st_dev == y.st_dev &&
           x.st_ino == y.st_ino;
}

int sf_cmd_evaluate(int argc, char **argv)
{
    const char *path, *design_path = NULL, *out_path = NULL;
    size_t threads = 0;
    int no_unum = 0;
    const sf_opt opts[] = {
        { "--design", SF_OPT_STRING, &design_path, 0, 0, NULL },
        { "--out", SF_OPT_STRING, &out_path, 0, 0, NULL },
        { "--threads", SF_OPT_SIZE, &threads, 1, 1024, NULL },
        { "--no-unum", SF_OPT_FLAG, &no_unum, 0, 0, NULL },
    };
    int rc = sf_cli_parse("evaluate", argc, argv, opts, sizeof opts / sizeof opts[0], &path, usage);
    if (rc)
        return rc == SF_CLI_HELP ? SF_EXIT_OK : rc;
    if (!design_path || !out_path) {
        fprintf(stderr, "slipfield evaluate: --design and --out are required\n");
        return SF_EXIT_USAGE;
    }
    if (same_file(out_path, design_path)) {
        fprintf(stderr, "slipfield evaluate: --out %s is the design %s: refusing to overwrite it\n", out_path,
                design_path);
        return SF_EXIT_USAGE;
    }
    sf_scene s0;
    if (sf_cli_load_scene("evaluate", path, &s0))
        return SF_EXIT_USAGE;
    design d = { design_path, NULL, 0, NULL, 0 };
    if ((rc = read_design(&d, &s0))) {
        design_free(&d);
        return rc;
    }
    for (size_t k = 0; k < d.ncol; k++) {   /* a scene key the design replaces */
        char opt[160];
        snprintf(opt, sizeof opt, "the design's column '%s'", d.col[k].name);
        if (d.col[k].kind == COL_KEY || d.col[k].kind == COL_SEED)
            sf_cli_key_overridden("evaluate", path, &s0, d.col[k].name, opt);
        else if (d.col[k].kind == COL_LR)
            sf_cli_key_overridden("evaluate", path, &s0, "l", opt);
    }
    int writer = sf_mc_rank(NULL) == 0;   /* under MPI every rank computes, rank 0 writes */
    sf_out out = { 0 };
    if (writer && (rc = sf_cli_open("evaluate", out_path, path, &out))) {
        design_free(&d);
        return rc;
    }
    double *val = calloc(d.nrows * NOUT, sizeof *val);
    char *msg = calloc(d.nrows, MSG);
    char err[300] = "";
    if (!val || !msg)
        rc = SF_ENOMEM;
    else {
        eval_ctx ctx = { d.rows, s0.seed, !no_unum, msg };
        sf_mc_spec spec = { d.nrows, NOUT, s0.seed, (int)threads, NULL, 0, 0, "slipfield evaluate" };
        sf_mc_ops ops = { ws_alloc, ws_free, eval_row };
        rc = sf_mc_run(&spec, &ops, &ctx, val, NULL, err, sizeof err);
    }
    if (rc) {
        fprintf(stderr, "slipfield evaluate: %s\n", *err ? err : sf_strerror(rc));
        if (writer)
            sf_cli_close("evaluate", &out, 0);
        free(val);
        free(msg);
        design_free(&d);
        return SF_EXIT_INTERNAL;   /* a row's failure is its own: this is a workspace's allocation */
    }
    static const char *const qn[NQ] = { "pv_x", "pv_F", "stick_fraction" }, *const qu[NQ] = { "m", "N", "-" };
    size_t failed = 0, no_qoi = 0;
    for (size_t j = 0; j < d.nrows; j++) {
        const double *v = val + j * NOUT;
        const char *m = msg + j * MSG;
        if (v[O_RC] != 0) {
            failed++;
            if (writer)
                fprintf(stderr, "slipfield evaluate: %s:%d: row %zu failed: %s\n", d.path, d.rows[j].line, j,
                        *m ? m : sf_strerror((int)v[O_RC]));
        } else {
            if (*m && writer)
                fprintf(stderr, "slipfield evaluate: %s:%d: row %zu: %s\n", d.path, d.rows[j].line, j, m);
            no_qoi += !(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]));
        }
    }
    if (no_qoi && writer)
        fprintf(stderr, "slipfield evaluate: warning: %zu of %zu rows formed no quantity of interest (no complete "
                        "cycle after t_skip: nan, status ok): raise T\n", no_qoi, d.nrows);
    int st = SF_EXIT_OK;
    if (writer) {
        for (size_t k = 0; k < d.ncol; k++)
            fprintf(out.f, "%s\t", d.col[k].name);
        for (int q = 0; q < NQ; q++)
            fprintf(out.f, "%s[%s]\t%s_ratio[-]\tu_%s[%s]\t", qn[q], qu[q], qn[q], qn[q], qu[q]);
        fputs("status\n", out.f);
        for (size_t j = 0; j < d.nrows; j++) {
            const double *v = val + j * NOUT;
            for (size_t k = 0; k < d.ncol; k++)
                fprintf(out.f, "%s\t", d.rows[j].cell[k]);
            for (int q = 0; q < NQ; q++)
                fprintf(out.f, "%.17g\t%.17g\t%.17g\t", v[O_VAL + q], v[O_RATIO + q], v[O_U + q]);
            if (v[O_RC] == 0)
                fputs("ok", out.f);
            else
                put_cell(out.f, msg[j * MSG] ? msg + j * MSG : sf_strerror((int)v[O_RC]));
            fputc('\n', out.f);
        }
        st = sf_cli_close("evaluate", &out, 1);
    }
    free(val);
    free(msg);
    design_free(&d);
    return st ? st : failed ? SF_EXIT_CHECK : SF_EXIT_OK;
}
