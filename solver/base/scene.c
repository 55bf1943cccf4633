/* slipfield: scenes (scene.h): the table of every solver key, the strict
 * parser of `key = value` text into an sf_scene, and the writers of a
 * scene and of the key help. */
#include "scene.h"
#include "sf_alloc.h"
#include "sf_error.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define OFF(f) offsetof(sf_scene, f)
#define INF HUGE_VAL

static const sf_key keys[] = {
    /* physics: Table 1 stochastic baseline */
    { "m", SF_KEY_DOUBLE, OFF(m), 0, 0, INF, 1, 0, "10", "kg", NULL, "disc mass" },
    { "k", SF_KEY_DOUBLE, OFF(k), 0, 0, INF, 1, 0, "30", "N/m", NULL, "spring stiffness in x and y" },
    { "v_b", SF_KEY_DOUBLE, OFF(v_b), 0, 0, INF, 1, 0, "0.2", "m/s", NULL, "belt speed" },
    { "R", SF_KEY_DOUBLE, OFF(R), 0, 0, INF, 1, 0, "0.5", "m", NULL, "disc radius" },
    { "l", SF_KEY_DOUBLE, OFF(l), 0, 0, INF, 1, 0, "0.1", "m", NULL, "correlation length of Eq. 2" },
    { "mu_mean", SF_KEY_DOUBLE, OFF(mu_mean), 0, 0, INF, 1, 0, "0.5", "1", NULL, "mean static COF" },
    { "mu_std", SF_KEY_DOUBLE, OFF(mu_std), 0, 0, INF, 0, 0, "0.1", "1", NULL, "std of the static COF" },
    { "mu_k_ratio", SF_KEY_DOUBLE, OFF(mu_k_ratio), 0, 0, 1, 1, 0, "0.9", "1", NULL, "mu_k / mu_s (Eq. 1)" },
    { "g", SF_KEY_DOUBLE, OFF(g), 0, 0, INF, 1, 0, "9.81", "m/s^2", NULL, "gravity" },
    { "T", SF_KEY_DOUBLE, OFF(T), 0, 0, INF, 1, 0, "100", "s", NULL, "simulated time" },
    { "eps_lambda", SF_KEY_DOUBLE, OFF(eps_lambda), 0, 0, 1, 1, 0, "1e-3", "1", NULL, "slip-to-stick threshold on lambda (Eq. 12-14)" },
    { "dt", SF_KEY_DOUBLE, OFF(dt), 0, 0, INF, 1, 0, "1e-3", "s", NULL, "fixed step (rk4) or initial step" },
    { "seed", SF_KEY_ULONG, OFF(seed), 0, 0, 0, 0, 0, "20230101", "1", NULL, "random seed" },
    { "cof", SF_KEY_ENUM, OFF(cof), 0, 0, 0, 0, 0, "field", "", SF_KEY_CHOICES("uniform", "variable", "field"), "COF model" },
    /* random-field grid */
    { "nx", SF_KEY_SIZE, OFF(nx), 0, 1, 1e6, 0, 0, "64", "1", NULL, "grid points along x" },
    { "ny", SF_KEY_SIZE, OFF(ny), 0, 1, 1e6, 0, 0, "64", "1", NULL, "grid points along y" },
    { "dx", SF_KEY_DOUBLE, OFF(dx), 0, 0, INF, 1, 0, "0.025", "m", NULL, "grid spacing along x" },
    { "dy", SF_KEY_DOUBLE, OFF(dy), 0, 0, INF, 1, 0, "0.025", "m", NULL, "grid spacing along y" },
    { "pad_cap", SF_KEY_DOUBLE, OFF(pad_cap), 0, 1, 1e6, 0, 0, "16", "1", NULL, "max embedding period / minimal period" },
    { "eig_tol", SF_KEY_DOUBLE, OFF(eig_tol), 0, 0, 1, 0, 0, "1e-12", "1", NULL, "accept lambda_min >= -eig_tol lambda_max" },
    { "no_padding", SF_KEY_BOOL, OFF(no_padding), 0, 0, 0, 0, 0, "false", "", NULL, "minimal embedding only" },
    { "fftw_planner", SF_KEY_ENUM, OFF(fftw_planner), 0, 0, 0, 0, 0, "estimate", "", SF_KEY_CHOICES("estimate", "measure"), "sampling FFT plan: estimate (same bits in every process) or measure (timed, faster on large grids; see SLIPFIELD_FFTW_WISDOM)" },
    { "precorrect", SF_KEY_BOOL, OFF(precorrect), 0, 0, 0, 0, 0, "false", "", NULL, "pre-correct the Gaussian correlation so the lognormal field has Eq. 2" },
    { "strip_halfwidth", SF_KEY_DOUBLE, OFF(strip_halfwidth), 0, 0, INF, 0, 0, "0.5", "m", NULL, "lateral excursion |y| the COF strip covers beyond R (0: the spring-excursion bound); a run that leaves it fails" },
    { "cof_generator", SF_KEY_ENUM, OFF(cof_generator), 0, 0, 0, 0, 0, "auto", "", SF_KEY_CHOICES("auto", "circulant", "tiles", "belt_noise"), "belt COF field generator: circulant strip over [0, T], tiles generated on demand in a window that follows the disc, belt_noise (the tiles' window on one white noise fixed in belt coordinates, the same for every l, v_b and COF marginal: a field that moves continuously with the parameters; noise.h), or auto (circulant unless its strip exceeds 2^" SF_STR(SF_COF_AUTO_LOG2) " points; slipfield run --explain says which)" },
    { "cof_model", SF_KEY_ENUM, OFF(cof_model), 0, 0, 0, 0, 0, "auto", "", SF_KEY_CHOICES("auto", "point", "cell_average"), "COF the quadrature sees: point values of the field at the cells, or the cell-averaged field (Cartesian cells much larger than l; cellavg.h), or auto (the plan chooses from l/R: numplan.h; slipfield run --explain says which)" },
    { "samples", SF_KEY_SIZE, OFF(samples), 0, 1, SF_MAX_SAMPLES, 0, 0, "1000", "1", NULL, "number of samples or realisations" },
    /* contact */
    { "layout", SF_KEY_ENUM, OFF(layout), 0, 0, 0, 0, 0, "polar", "", SF_KEY_CHOICES("polar", "cartesian"), "disc quadrature layout" },
    { "cells", SF_KEY_SIZE, OFF(cells), 0, 0, 1e5, 0, 0, "0", "1", NULL, "quadrature resolution (rings or cells per diameter); 0: the plan chooses from qoi_tol and l/R (numplan.h)" },
    { "u", SF_KEY_DOUBLE, OFF(u), 0, -INF, INF, 0, 0, "-0.2", "m/s", NULL, "relative velocity of the centre, x" },
    { "v", SF_KEY_DOUBLE, OFF(v), 0, -INF, INF, 0, 0, "0", "m/s", NULL, "relative velocity of the centre, y" },
    { "w", SF_KEY_DOUBLE, OFF(w), 0, -INF, INF, 0, 0, "0", "rad/s", NULL, "spin" },
    { "ntheta", SF_KEY_SIZE, OFF(ntheta), 0, 1, 1e5, 0, 0, "37", "1", NULL, "limit-surface theta samples" },
    { "npsi", SF_KEY_SIZE, OFF(npsi), 0, 1, 1e5, 0, 0, "72", "1", NULL, "limit-surface psi samples" },
    /* dynamics */
    { "integrator", SF_KEY_ENUM, OFF(integrator), 0, 0, 0, 0, 0, "adaptive", "", SF_KEY_CHOICES("adaptive", "rk4", "rk8pd", "rkck"), "time stepper: adaptive = rk8pd for a closed-form wrench, rkck for a quadrature one; rk4 at fixed dt" },
    { "dof", SF_KEY_ENUM, OFF(dof), 0, 0, 0, 0, 0, "3", "", SF_KEY_CHOICES("1", "3"), "degrees of freedom: 1 (Eqs. 3-4, uniform COF) or 3 (x, y, phi; Eq. 5)" },
    { "rtol", SF_KEY_DOUBLE, OFF(rtol), 0, 0, 1, 0, 1, "0", "1", NULL, "adaptive stepper relative tolerance; 0: the plan chooses from qoi_tol (numplan.h)" },
    { "max_steps", SF_KEY_SIZE, OFF(max_steps), 0, 1, 1e15, 0, 0, "200000000", "1", NULL, "slip steps a run may take; past it the run stops with its state so far and a named error (e.g. a cell of a heavy-tailed COF field that holds the disc's centre of rotation: a sliding mode the stepper crosses in steps of ~1e-8 s)" },
    { "qoi_tol", SF_KEY_DOUBLE, OFF(qoi_tol), 0, 0, 1, 1, 1, "1e-3", "1", NULL, "relative error wanted in a realisation's PV_x, PV_F and stick fraction: the plan sets cells, rtol and the stepper from it (numplan.h)" },
    { "t_skip", SF_KEY_DOUBLE, OFF(t_skip), 0, 0, INF, 0, 0, "10", "s", NULL, "transient discarded before QoIs: they are taken over the window [t_skip, T]" },
    { "qoi_def", SF_KEY_ENUM, OFF(qoi_def), 0, 0, 0, 0, 0, "paper", "", SF_KEY_CHOICES("paper", "cycles"), "QoI definitions: paper (Sec. 3.1: stick fraction = stick time in [t_skip, T] / (T - t_skip); PV_x, PV_F per oscillation, from one maximum of x to the next, stick or not) or cycles (stick time / time of the complete stick-onset-to-onset cycles; PV per complete cycle)" },
    { "x0", SF_KEY_DOUBLE, OFF(x0), 0, -INF, INF, 0, 0, "0", "m", NULL, "initial x of the disc centre (ground frame)" },
    { "y0", SF_KEY_DOUBLE, OFF(y0), 0, -INF, INF, 0, 0, "0", "m", NULL, "initial y of the disc centre" },
    { "phi0", SF_KEY_DOUBLE, OFF(phi0), 0, -INF, INF, 0, 0, "0", "rad", NULL, "initial rotation angle" },
    { "vx0", SF_KEY_DOUBLE, OFF(vx0), 0, -INF, INF, 0, 0, "0", "m/s", NULL, "initial x velocity (ground frame; v_b with vy0 = w0 = 0 inside the stick set starts in stick)" },
    { "vy0", SF_KEY_DOUBLE, OFF(vy0), 0, -INF, INF, 0, 0, "0", "m/s", NULL, "initial y velocity (3-DOF only)" },
    { "w0", SF_KEY_DOUBLE, OFF(w0), 0, -INF, INF, 0, 0, "0", "rad/s", NULL, "initial spin (3-DOF only)" },
    { "velocity_jump", SF_KEY_BOOL, OFF(velocity_jump), 0, 0, 0, 0, 0, "true", "", NULL, "apply Eqs. 12 and 14" },
    { "exact_section", SF_KEY_BOOL, OFF(exact_section), 0, 0, 0, 0, 0, "false", "", NULL, "stick test on the exact T = 0 section" },
    { "history", SF_KEY_BOOL, OFF(history), 0, 0, 0, 0, 0, "true", "", NULL, "keep the time history" },
    { "shortcuts", SF_KEY_BOOL, OFF(shortcuts), 0, 0, 0, 0, 0, "true", "", NULL, "false: compute in full where the plan would take a shortcut" },
};

#define NKEYS (sizeof keys / sizeof keys[0])
_Static_assert(sizeof keys / sizeof keys[0] <= SF_SCENE_MAX_KEYS, "key table too large");

/* An enum key's names as "a|b|c" (help text, error messages). */
static const char *choices_text(const sf_key *k, char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; k->choices[i] && used < n; i++)
        used += (size_t)snprintf(buf + used, n - used, "%s%s", i ? "|" : "", k->choices[i]);
    return buf;
}

static const sf_key *find_key(const sf_keytab *t, const char *name, size_t len)
{
    for (size_t i = 0; i < t->n; i++)
        if (strlen(t->keys[i].name) == len && strncmp(t->keys[i].name, name, len) == 0)
            return &t->keys[i];
    return NULL;
}

static int in_range(const sf_key *k, double x)
{
    if (k->lo_open ? !(x > k->lo) : !(x >= k->lo)) return 0;
    if (k->hi_open ? !(x < k->hi) : !(x <= k->hi)) return 0;
    return 1;
}

static void range_text(const sf_key *k, char *buf, size_t n)
{
    char lo[32] = "", hi[32] = "";
    if (isfinite(k->lo)) snprintf(lo, sizeof lo, "%s %g", k->lo_open ? ">" : ">=", k->lo);
    if (isfinite(k->hi)) snprintf(hi, sizeof hi, "%s %g", k->hi_open ? "<" : "<=", k->hi);
    snprintf(buf, n, "%s%s%s", lo, (*lo && *hi) ? " and " : "", hi);
}

/* Parse one number occupying all of [s, s+len); finite only. */
static int parse_double(const char *s, size_t len, double *out)
{
    char buf[64];
    if (len == 0 || len >= sizeof buf)
        return 0;
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *end;
    errno = 0;
    double x = strtod(buf, &end);
    if (*end != '\0' || end == buf || !isfinite(x) || errno == ERANGE)
        return 0;
    *out = x;
    return 1;
}

/* A list "a, b, c" of finite numbers (at most SF_LIST_MAX). */
static int assign_list(sf_list *l, const sf_key *k, const char *v, size_t len,
                       const char *file, int line, char *err, size_t errlen)
{
    l->n = 0;
    size_t i = 0;
    while (i < len) {
        size_t j = i;
        while (j < len && v[j] != ',') j++;
        size_t a = i, b = j;
        while (a < b && isspace((unsigned char)v[a])) a++;
        while (b > a && isspace((unsigned char)v[b - 1])) b--;
        double x;
        if (!parse_double(v + a, b - a, &x))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': item %zu is not a finite number",
                          file, line, k->name, l->n + 1);
        if (l->n == SF_LIST_MAX)
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': more than %d values",
                          file, line, k->name, SF_LIST_MAX);
        l->v[l->n++] = x;
        i = j + 1;
        if (j < len && j + 1 == len)
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': trailing comma", file, line, k->name);
    }
    return SF_SUCCESS;
}

/* A whole number for an unsigned long key. */
static int assign_ulong(unsigned long *out, const sf_key *k, const char *v, size_t len,
                        const char *file, int line, char *err, size_t errlen)
{
    /* seeds: parsed exactly as an integer, never through a double */
    char buf[32];
    if (len >= sizeof buf)
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': value too long", file, line, k->name);
    memcpy(buf, v, len);
    buf[len] = '\0';
    errno = 0;
    char *end;
    unsigned long u = strtoul(buf, &end, 10);
    if (*end || end == buf || errno == ERANGE || !isdigit((unsigned char)buf[0]))
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': expected a non-negative whole number, got '%s'",
                      file, line, k->name, buf);
    *out = u;
    return SF_SUCCESS;
}

/* Assign the value text [v, v+len) to key k of the struct at obj. */
static int assign(void *obj, const sf_key *k, const char *v, size_t len,
                  const char *file, int line, char *err, size_t errlen)
{
    char *base = (char *)obj + k->off;
    char rng[80];
    range_text(k, rng, sizeof rng);
    switch (k->type) {
    case SF_KEY_DOUBLE: {
        double x;
        if (!parse_double(v, len, &x))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': expected a finite number, got '%.*s'",
                          file, line, k->name, (int)(len > 40 ? 40 : len), v);
        if (!in_range(k, x))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': must be %s (got %g)",
                          file, line, k->name, rng, x);
        *(double *)base = x;
        return SF_SUCCESS;
    }
    case SF_KEY_SIZE: {
        double x;
        int ok = parse_double(v, len, &x) && x == floor(x);
        if (!ok || x < 0)
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': expected a non-negative whole number, got '%.*s'",
                          file, line, k->name, (int)(len > 40 ? 40 : len), v);
        if (!in_range(k, x))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': must be %s (got %g)",
                          file, line, k->name, rng, x);
        *(size_t *)base = (size_t)x;
        return SF_SUCCESS;
    }
    case SF_KEY_ULONG:
        return assign_ulong((unsigned long *)base, k, v, len, file, line, err, errlen);
    case SF_KEY_BOOL: {
        static const char *t[] = { "true", "yes", "on", "1" }, *f[] = { "false", "no", "off", "0" };
        for (int i = 0; i < 4; i++) {
            if (strlen(t[i]) == len && strncmp(v, t[i], len) == 0) { *(int *)base = 1; return SF_SUCCESS; }
            if (strlen(f[i]) == len && strncmp(v, f[i], len) == 0) { *(int *)base = 0; return SF_SUCCESS; }
        }
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': expected true or false, got '%.*s'",
                      file, line, k->name, (int)(len > 40 ? 40 : len), v);
    }
    case SF_KEY_ENUM: {
        for (int idx = 0; k->choices[idx]; idx++)
            if (strlen(k->choices[idx]) == len && strncmp(k->choices[idx], v, len) == 0) {
                *(int *)base = idx;
                return SF_SUCCESS;
            }
        char names[80];
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': expected one of %s, got '%.*s'",
                      file, line, k->name, choices_text(k, names, sizeof names), (int)(len > 40 ? 40 : len), v);
    }
    case SF_KEY_STRING: {
        if (len >= k->size)
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': value longer than %zu characters",
                          file, line, k->name, k->size - 1);
        for (size_t i = 0; i < len; i++) {
            unsigned char ch = (unsigned char)v[i];
            if (!(isalnum(ch) || ch == '_' || ch == '-' || ch == ',' || ch == '.' || ch == '*' || ch == '+'))
                return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': only letters, digits and _-,.*+ are allowed",
                              file, line, k->name);
        }
        memcpy(base, v, len);
        base[len] = '\0';
        return SF_SUCCESS;
    }
    case SF_KEY_LIST:
        return assign_list((sf_list *)base, k, v, len, file, line, err, errlen);
    }
    return SF_EPARSE;
}

void sf_keys_default(const sf_keytab *t)
{
    char err[256];
    for (size_t i = 0; i < t->n; i++) {
        int rc = assign(t->obj, &t->keys[i], t->keys[i].def, strlen(t->keys[i].def), "<defaults>", 0, err, sizeof err);
        (void)rc; /* the tables' defaults are covered by a unit test */
    }
    memset(t->set, 0, t->n);
}

sf_keytab sf_scene_keytab(const sf_scene *s)
{
    return (sf_keytab){ keys, NKEYS, (void *)s, (unsigned char *)s->set };
}

void sf_scene_default(sf_scene *s)
{
    memset(s, 0, sizeof *s);
    sf_keytab t = sf_scene_keytab(s);
    sf_keys_default(&t);
}

/* One `key = value` line q[0..ql) (comment and blanks stripped) against
 * the tables t[0..nt). */
static int parse_line(const sf_keytab *t, size_t nt, const char *q, size_t ql, const char *file, int line,
                      char *err, size_t errlen)
{
    for (size_t i = 0; i < ql; i++)
        if (q[i] == '\0' || (!isprint((unsigned char)q[i]) && q[i] != '\t'))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: non-printable character in scene line", file, line);
    const char *eq = memchr(q, '=', ql);
    if (!eq)
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: expected 'key = value', got '%.*s'",
                      file, line, (int)(ql > 40 ? 40 : ql), q);
    size_t kl = (size_t)(eq - q);
    while (kl > 0 && isspace((unsigned char)q[kl - 1])) kl--;
    if (kl == 0)
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: missing key before '='", file, line);
    const sf_key *k = NULL;
    const sf_keytab *tab = t;
    for (; tab < t + nt && !(k = find_key(tab, q, kl)); tab++)
        ;
    if (!k)
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: unknown key '%.*s' (see 'slipfield help scene')",
                      file, line, (int)(kl > 40 ? 40 : kl), q);
    size_t idx = (size_t)(k - tab->keys);
    if (tab->set[idx])
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': set twice", file, line, k->name);
    const char *v = eq + 1;
    size_t vl = (size_t)(q + ql - v);
    while (vl > 0 && isspace((unsigned char)*v)) { v++; vl--; }
    if (vl == 0)
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key '%s': missing value", file, line, k->name);
    int rc = assign(tab->obj, k, v, vl, file, line, err, errlen);
    if (!rc)
        tab->set[idx] = 1;
    return rc;
}

int sf_keys_parse(const sf_keytab *t, size_t nt, const char *text, const char *file,
                  int first_line, char *err, size_t errlen)
{
    int line = first_line;
    const char *p = text;
    while (*p) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        /* strip comment and surrounding blanks */
        const char *hash = memchr(p, '#', len);
        size_t n = hash ? (size_t)(hash - p) : len;
        size_t a = 0, b = n;
        while (a < b && isspace((unsigned char)p[a])) a++;
        while (b > a && isspace((unsigned char)p[b - 1])) b--;
        if (a < b) {
            int rc = parse_line(t, nt, p + a, b - a, file, line, err, errlen);
            if (rc)
                return rc;
        }
        if (!eol)
            break;
        p = eol + 1;
        line++;
    }
    return SF_SUCCESS;
}

int sf_scene_parse(sf_scene *s, const char *text, const char *file,
                   int first_line, char *err, size_t errlen)
{
    sf_keytab t = sf_scene_keytab(s);
    return sf_keys_parse(&t, 1, text, file, first_line, err, errlen);
}

int sf_read_text(const char *path, const char *what, char **text, size_t *len, char *err, size_t errlen)
{
    *text = NULL;
    *len = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return sf_seterr(err, errlen, SF_EIO, "%s: cannot open: %s", path, strerror(errno));
    size_t cap = 1u << 20, n;
    char *buf = sf_malloc(cap + 1);
    if (!buf) {
        fclose(f);
        return SF_ENOMEM;
    }
    n = fread(buf, 1, cap + 1, f);
    int rd = ferror(f) ? errno : 0;
    fclose(f);
    if (rd) {   /* e.g. a directory: fopen succeeds, reading fails */
        free(buf);
        return sf_seterr(err, errlen, SF_EIO, "%s: cannot read: %s", path, strerror(rd));
    }
    if (n > cap) {
        free(buf);
        return sf_seterr(err, errlen, SF_EPARSE, "%s: %s file larger than 1 MiB", path, what);
    }
    buf[n] = '\0';
    if (strlen(buf) != n) {
        free(buf);
        return sf_seterr(err, errlen, SF_EPARSE, "%s: %s file contains a NUL byte", path, what);
    }
    *text = buf;
    *len = n;
    return SF_SUCCESS;
}

int sf_scene_read_file(sf_scene *s, const char *path, char *err, size_t errlen)
{
    char *buf;
    size_t n;
    int rc = sf_read_text(path, "scene", &buf, &n, err, errlen);
    if (rc)
        return rc;
    rc = sf_scene_parse(s, buf, path, 1, err, errlen);
    free(buf);
    return rc;
}

int sf_keys_was_set(const sf_keytab *t, const char *key)
{
    const sf_key *k = find_key(t, key, strlen(key));
    return k ? t->set[k - t->keys] : 0;
}

int sf_scene_was_set(const sf_scene *s, const char *key)
{
    sf_keytab t = sf_scene_keytab(s);
    return sf_keys_was_set(&t, key);
}

const char *sf_keys_enum_name(const sf_keytab *t, const char *key, int value)
{
    const sf_key *k = find_key(t, key, strlen(key));
    if (!k || k->type != SF_KEY_ENUM || value < 0)
        return "?";
    for (int i = 0; k->choices[i]; i++)
        if (i == value)
            return k->choices[i];
    return "?";
}

const char *sf_scene_enum_name(const char *key, int value)
{
    sf_keytab t = { keys, NKEYS, NULL, NULL };
    return sf_keys_enum_name(&t, key, value);
}

static void write_value(const void *obj, const sf_key *k, FILE *out)
{
    const char *base = (const char *)obj + k->off;
    switch (k->type) {
    case SF_KEY_DOUBLE: fprintf(out, "%.17g", *(const double *)base); break;
    case SF_KEY_SIZE: fprintf(out, "%zu", *(const size_t *)base); break;
    case SF_KEY_ULONG: fprintf(out, "%lu", *(const unsigned long *)base); break;
    case SF_KEY_BOOL: fputs(*(const int *)base ? "true" : "false", out); break;
    case SF_KEY_ENUM: {
        int v = *(const int *)base, i = 0;
        while (k->choices[i] && i < v) i++;
        fputs(v >= 0 && k->choices[i] ? k->choices[i] : "?", out);
        break;
    }
    case SF_KEY_STRING: fputs(base, out); break;
    case SF_KEY_LIST: {
        const sf_list *l = (const sf_list *)base;
        for (size_t i = 0; i < l->n; i++)
            fprintf(out, "%s%.17g", i ? ", " : "", l->v[i]);
        break;
    }
    }
}

void sf_keys_write(const sf_keytab *t, FILE *out)
{
    for (size_t i = 0; i < t->n; i++) {
        fprintf(out, "%s = ", t->keys[i].name);
        write_value(t->obj, &t->keys[i], out);
        fputc('\n', out);
    }
}

void sf_scene_write(const sf_scene *s, FILE *out)
{
    sf_keytab t = sf_scene_keytab(s);
    sf_keys_write(&t, out);
}

const char *sf_scene_key_unit(const char *key)
{
    if (!key)
        return NULL;
    if (!strcmp(key, "l_over_R"))
        return "1";
    for (size_t i = 0; i < NKEYS; i++)
        if (!strcmp(keys[i].name, key))
            return keys[i].unit;
    return NULL;
}

void sf_keys_print(const sf_keytab *t, size_t nt, FILE *out)
{
    fprintf(out, "%-14s %-7s %-10s %-24s %s\n", "key", "unit", "default", "range/choices", "meaning");
    for (const sf_keytab *tab = t; tab < t + nt; tab++)
        for (size_t i = 0; i < tab->n; i++) {
            const sf_key *k = &tab->keys[i];
            char rng[80];
            if (k->type == SF_KEY_ENUM)
                choices_text(k, rng, sizeof rng);
            else if (k->type == SF_KEY_DOUBLE || k->type == SF_KEY_SIZE)
                range_text(k, rng, sizeof rng);
            else
                rng[0] = '\0';
            fprintf(out, "%-14s %-7s %-10s %-24s %s\n", k->name, k->unit, k->def, rng, k->help);
        }
}

void sf_scene_print_keys(FILE *out)
{
    sf_keytab t = { keys, NKEYS, NULL, NULL };
    sf_keys_print(&t, 1, out);
}
