/* Literate cases (case.h): a case's Markdown read into its scene and
 * check spec, and the power runs' alternatives applied to a scene. */
#include "case.h"
#include "registry.h"
#include "sf_error.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *dup_range(const char *a, const char *b)
{
    size_t n = (size_t)(b - a);
    char *s = malloc(n + 1);
    if (!s) {
        fputs("slipfield: out of memory\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    memcpy(s, a, n);
    s[n] = '\0';
    return s;
}

static int valid_name(const char *s, size_t n)
{
    if (n == 0)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char c = s[i];
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-'))
            return 0;
    }
    return 1;
}

/* id from the path: the last two components, without ".md". */
static int make_id(sf_case *c, const char *path, char *err, size_t errlen)
{
    size_t len = strlen(path);
    if (len < 4 || strcmp(path + len - 3, ".md") != 0)
        return sf_seterr(err, errlen, SF_EPARSE, "%s: a case file must end in .md", path);
    const char *end = path + len - 3;
    const char *slash = end;
    while (slash > path && slash[-1] != '/') slash--;
    if (slash == path)
        return sf_seterr(err, errlen, SF_EPARSE, "%s: a case must live in a family folder (cases/<family>/<name>.md)", path);
    const char *fam_end = slash - 1, *fam = fam_end;
    while (fam > path && fam[-1] != '/') fam--;
    size_t fl = (size_t)(fam_end - fam), nl = (size_t)(end - slash);
    if (!valid_name(fam, fl) || !valid_name(slash, nl) || fl + nl + 2 > sizeof c->id || fl + 1 > sizeof c->family)
        return sf_seterr(err, errlen, SF_EPARSE,
                    "%s: family and case names must be lower-case letters, digits, '_' or '-'", path);
    snprintf(c->family, sizeof c->family, "%.*s", (int)fl, fam);
    snprintf(c->id, sizeof c->id, "%.*s/%.*s", (int)fl, fam, (int)nl, slash);
    return SF_SUCCESS;
}

/* The scene block: the scene's keys and the case's, then what a case
 * must state (a known check, a tolerance or alpha, a valid power_alt). */
static int parse_scene(sf_case *c, const char *path, char *err, size_t errlen)
{
    sf_scene_default(&c->scene);
    sf_case_spec_default(&c->spec);
    int rc = sf_case_scene_parse(&c->scene, &c->spec, c->scene_text, path, c->scene_line, err, errlen);
    if (rc)
        return rc;
    sf_keytab vt = sf_case_spec_keytab(&c->spec);
    if (!sf_keys_was_set(&vt, "check"))
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: the scene block has no 'check = NAME'", path, c->scene_line);
    if (!sf_check_find(c->spec.check))
        return sf_seterr(err, errlen, SF_EPARSE, "%s: key 'check': unknown check '%s' (see 'slipfield verify --checks')",
                    path, c->spec.check);
    if (c->spec.power_alt[0]) {
        sf_alt a;
        char e2[128];
        if (sf_alt_parse(c->spec.power_alt, &a, e2, sizeof e2))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: key 'power_alt': %s", path, c->scene_line, e2);
        if (!sf_keys_was_set(&vt, "alpha"))
            return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: 'power_alt' names the alternative of a statistical "
                        "check: the scene must set 'alpha'", path, c->scene_line);
    }
    if (!sf_keys_was_set(&vt, "tolerance") && !sf_keys_was_set(&vt, "alpha"))
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: the scene states neither 'tolerance' nor 'alpha'", path, c->scene_line);
    return SF_SUCCESS;
}

/* The parse proper, on a NUL-terminated copy buf of n bytes (freed here). */
static int parse_buf(sf_case *c, const char *path, char *buf, size_t n, char *err, size_t errlen);

int sf_case_parse(sf_case *c, const char *path, const char *text, size_t n, char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    if (strlen(path) >= sizeof c->path)
        return sf_seterr(err, errlen, SF_EPARSE, "%s: path too long", path);
    snprintf(c->path, sizeof c->path, "%s", path);
    int rc = make_id(c, path, err, errlen);
    if (rc)
        return rc;
    if (n > (1u << 20))
        return sf_seterr(err, errlen, SF_EPARSE, "%s: case file larger than 1 MiB", path);
    if (memchr(text, '\0', n))
        return sf_seterr(err, errlen, SF_EPARSE, "%s: case file contains a NUL byte", path);
    char *buf = malloc(n + 1);
    if (!buf)
        return SF_ENOMEM;
    memcpy(buf, text, n);
    buf[n] = '\0';
    return parse_buf(c, path, buf, n, err, errlen);
}

int sf_case_read(sf_case *c, const char *path, char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    char *buf;
    size_t n;
    int rc = sf_read_text(path, "case", &buf, &n, err, errlen);
    if (rc)
        return rc;
    rc = sf_case_parse(c, path, buf, n, err, errlen);
    free(buf);
    return rc;
}

static int parse_buf(sf_case *c, const char *path, char *buf, size_t n, char *err, size_t errlen)
{
    /* Walk lines: title, the single ```scene fence. */
    const char *p = buf, *open = NULL, *body = NULL, *close_ = NULL, *after = NULL;
    const char *title = NULL, *title_end = NULL, *after_title = buf;
    int line = 1, open_line = 0;
    while (*p) {
        const char *eol = strchr(p, '\n');
        const char *next = eol ? eol + 1 : p + strlen(p);
        size_t len = (size_t)((eol ? eol : next) - p);
        if (!open && !title && len > 2 && p[0] == '#' && p[1] == ' ') {
            title = p + 2;
            title_end = p + len;
            after_title = next;
        } else if (len >= 3 && strncmp(p, "```", 3) == 0) {
            const char *info = p + 3;
            size_t il = len - 3;
            while (il && (info[il - 1] == ' ' || info[il - 1] == '\r')) il--;
            int is_scene = il == 5 && strncmp(info, "scene", 5) == 0;
            if (!open && is_scene) {
                open = p;
                body = next;
                open_line = line;
            } else if (open && !close_) {
                if (il != 0) {
                    free(buf);
                    return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: a fence inside the scene block", path, line);
                }
                close_ = p;
                after = next;
            } else if (is_scene) {
                free(buf);
                return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: a second ```scene block (one per case)", path, line);
            }
        }
        p = next;
        line++;
    }
    if (!title) {
        free(buf);
        return sf_seterr(err, errlen, SF_EPARSE, "%s:1: a case starts with a '# Title' line", path);
    }
    if (!open) {
        free(buf);
        return sf_seterr(err, errlen, SF_EPARSE, "%s: no ```scene block", path);
    }
    if (!close_) {
        free(buf);
        return sf_seterr(err, errlen, SF_EPARSE, "%s:%d: unterminated ```scene block", path, open_line);
    }
    size_t tl = (size_t)(title_end - title);
    while (tl && (title[tl - 1] == '\r' || title[tl - 1] == ' ')) tl--;
    snprintf(c->title, sizeof c->title, "%.*s", (int)tl, title);
    c->prose_before = dup_range(after_title < open ? after_title : open, open);
    c->prose_after = dup_range(after, buf + n);
    c->scene_text = dup_range(body, close_);
    c->scene_line = open_line + 1;
    free(buf);

    return parse_scene(c, path, err, errlen);
}

void sf_case_free(sf_case *c)
{
    free(c->prose_before);
    free(c->prose_after);
    free(c->scene_text);
    c->prose_before = c->prose_after = c->scene_text = NULL;
}

gsl_rng *sf_case_rng(const sf_case *c)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    if (!r) {
        fputs("slipfield: out of memory\n", stderr);
        exit(SF_EXIT_INTERNAL);
    }
    gsl_rng_set(r, c->scene.seed);
    return r;
}

/* ---- the case's keys: same format and parser as the scene's ---- */

#define OFF(f) offsetof(sf_case_spec, f)
#define STR(f) offsetof(sf_case_spec, f), sizeof(((sf_case_spec *)0)->f)
#define INF HUGE_VAL

static const sf_key spec_keys[] = {
    { "check", SF_KEY_STRING, STR(check), 0, 0, 0, 0, "", "", NULL, "check to run (cases)" },
    { "tolerance", SF_KEY_DOUBLE, OFF(tolerance), 0, 0, INF, 0, 0, "0", "", NULL, "tolerance of the check (its units are the check's)" },
    { "alpha", SF_KEY_DOUBLE, OFF(alpha), 0, 0, 1, 1, 1, "1e-3", "1", NULL, "significance level of a statistical check" },
    { "tier", SF_KEY_ENUM, OFF(tier), 0, 0, 0, 0, 0, "quick", "", SF_KEY_CHOICES("quick", "full", "paper"), "verification tier (paper: the paper's settings, run only with --tier paper)" },
    { "vv", SF_KEY_ENUM, OFF(vv), 0, 0, 0, 0, 0, "code", "", SF_KEY_CHOICES("code", "solution", "validation"), "code verification, solution verification or validation" },
    { "tags", SF_KEY_STRING, STR(tags), 0, 0, 0, 0, "", "", NULL, "comma-separated tags" },
    { "pin_seed", SF_KEY_BOOL, OFF(pin_seed), 0, 0, 0, 0, 0, "false", "", NULL, "a deterministic check of one pinned realisation: verify --seed leaves this case's seed alone" },
    { "seed_proof", SF_KEY_STRING, STR(seed_proof), 0, 0, 0, 0, "", "", NULL, "a tolerance on seed-dependent data that holds at every seed: a token for why (exact-property, round-off, same-bits); the prose says it" },
    { "replicate", SF_KEY_BOOL, OFF(replicate), 0, 0, 0, 0, 0, "false", "", NULL, "with alpha: a failure of the case's deterministic rows (a tolerance on seed-dependent data, met but for a measured rate alpha) is confirmed on a fresh stream before the case fails" },
    { "power_alt", SF_KEY_STRING, STR(power_alt), 0, 0, 0, 0, "", "", NULL, "alternative a statistical case's power is measured against: KEY*FACTOR or KEY+DELTA (generator only)" },
    { "sweep", SF_KEY_LIST, OFF(sweep), 0, -INF, INF, 0, 0, "", "", NULL, "list of values a check sweeps over" },
    { "sweep_param", SF_KEY_STRING, STR(sweep_param), 0, 0, 0, 0, "", "", NULL, "parameter a sweep varies: a numeric key, l_over_R or mu_mean (fixed CV)" },
    { "held_stops", SF_KEY_SIZE, OFF(held_stops), 0, 0, 1e6, 0, 0, "0", "1", NULL, "stress_run: runs that the step budget (max_steps) must stop at a quadrature cell holding the centre of rotation (a regression case's expectation; unset: no expectation)" },
    { "looks", SF_KEY_SIZE, OFF(looks), 0, 1, 4, 0, 0, "1", "1", NULL, "claims: group-sequential looks at N, 2N, ... realisations per point (N = samples) until every claim the tier demands a verdict on is decided; each look tests at alpha / looks (Bonferroni over the looks)" },
    { "model_budget", SF_KEY_SIZE, OFF(model_budget), 0, 0, 1e6, 0, 0, "0", "1", NULL, "claims: after the verdict at N = samples, a verdict about the model from looks at 2N, 4N, ... realisations per point (the first N reused) up to this budget, stopping when the claim is confirmed, contradicted or within its margin (Lan-DeMets alpha spending over the looks); 0: none" },
    { "model_budgets", SF_KEY_LIST, OFF(model_budgets), 0, 0, 1e6, 0, 0, "", "", NULL, "claims: per sweep point (one value each, each samples x a power of 2), the model verdicts' budget there; a claim's budget is the smallest at its points, model_budget the largest; unset: model_budget everywhere" },
    { "sweep2", SF_KEY_LIST, OFF(sweep2), 0, -INF, INF, 0, 0, "", "", NULL, "second list of values" },
};
#define NSPEC (sizeof spec_keys / sizeof spec_keys[0])
_Static_assert(NSPEC <= SF_CASE_SPEC_MAX_KEYS, "case key table too large");

sf_keytab sf_case_spec_keytab(const sf_case_spec *v)
{
    return (sf_keytab){ spec_keys, NSPEC, (void *)v, (unsigned char *)v->set };
}

double sf_case_spec_declared_alpha(const sf_case_spec *v)
{
    sf_keytab t = sf_case_spec_keytab(v);
    return sf_keys_was_set(&t, "alpha") ? v->alpha : 0;
}

void sf_case_spec_default(sf_case_spec *v)
{
    memset(v, 0, sizeof *v);
    sf_keytab t = sf_case_spec_keytab(v);
    sf_keys_default(&t);
}

int sf_case_scene_parse(sf_scene *s, sf_case_spec *v, const char *text, const char *file,
                        int first_line, char *err, size_t errlen)
{
    sf_keytab t[2] = { sf_scene_keytab(s), sf_case_spec_keytab(v) };
    return sf_keys_parse(t, 2, text, file, first_line, err, errlen);
}

const char *sf_case_enum_name(const char *key, int value)
{
    sf_keytab t = { spec_keys, NSPEC, NULL, NULL };
    return sf_keys_enum_name(&t, key, value);
}

void sf_case_print_keys(FILE *out)
{
    fprintf(out, "Scene keys (scene files of every command, and a case's scene block):\n\n");
    sf_scene_print_keys(out);
    fprintf(out, "\nCase-only keys (a case file's scene block only: run, sweep, field, surface\n"
                 "and wrench reject them as unknown keys):\n\n");
    sf_keytab t = { spec_keys, NSPEC, NULL, NULL };
    sf_keys_print(&t, 1, out);
}

/* ---- power alternatives ---- */

static const struct { const char *name; size_t off; } alt_keys[] = {
    { "mu_std", offsetof(sf_scene, mu_std) },
    { "mu_mean", offsetof(sf_scene, mu_mean) },
    { "l", offsetof(sf_scene, l) },
    { "mu_k_ratio", offsetof(sf_scene, mu_k_ratio) },
    { "v_b", offsetof(sf_scene, v_b) },
};
#define NALT (sizeof alt_keys / sizeof alt_keys[0])

int sf_alt_parse(const char *spec, sf_alt *a, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    size_t kl = strcspn(spec, "*+");
    if (!spec[kl] || kl == 0 || kl >= sizeof a->key)
        return sf_seterr(err, errlen, SF_EPARSE, "'%s': expected KEY*FACTOR or KEY+DELTA", spec);
    memcpy(a->key, spec, kl);
    a->key[kl] = '\0';
    a->additive = spec[kl] == '+';
    char *end;
    a->x = strtod(spec + kl + 1, &end);
    if (*end || end == spec + kl + 1 || !isfinite(a->x))
        return sf_seterr(err, errlen, SF_EPARSE, "'%s': the factor or delta is not a number", spec);
    int known = !strcmp(a->key, "field_std") || !strcmp(a->key, "re_im_corr");
    for (size_t i = 0; i < NALT; i++)
        known |= !strcmp(a->key, alt_keys[i].name);
    if (!known)
        return sf_seterr(err, errlen, SF_EPARSE, "'%s': unknown key '%s' (mu_std, mu_mean, l, mu_k_ratio, v_b, "
                    "field_std, re_im_corr)", spec, a->key);
    /* the alternative must leave a valid generator */
    double v0 = !strcmp(a->key, "re_im_corr") ? 0 : 1;
    double v = a->additive ? v0 + a->x : v0 * a->x;
    if (!(v > 0) && strcmp(a->key, "re_im_corr"))
        return sf_seterr(err, errlen, SF_EPARSE, "'%s': the factor must be > 0", spec);
    if (!strcmp(a->key, "re_im_corr") && !(fabs(v) < 1))
        return sf_seterr(err, errlen, SF_EPARSE, "'%s': a correlation must lie in (-1, 1)", spec);
    return SF_SUCCESS;
}

void sf_alt_apply(const sf_alt *a, sf_scene *s)
{
    if (!a)
        return;
    for (size_t i = 0; i < NALT; i++)
        if (!strcmp(a->key, alt_keys[i].name)) {
            double *p = (double *)((char *)s + alt_keys[i].off);
            *p = a->additive ? *p + a->x : *p * a->x;
        }
}

double sf_alt_field_std(const sf_alt *a)
{
    if (!a || strcmp(a->key, "field_std"))
        return 1.0;
    return a->additive ? 1.0 + a->x : a->x;
}

double sf_alt_re_im_corr(const sf_alt *a)
{
    if (!a || strcmp(a->key, "re_im_corr"))
        return 0.0;
    return a->additive ? a->x : 0.0;
}
