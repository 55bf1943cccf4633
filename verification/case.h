/* slipfield verification: literate cases.
 *
 * A case is a Markdown file under cases/<family>/<name>.md: a '# ' title,
 * prose (claim, why it should hold, what would break it) and exactly one
 * fenced ```scene block holding the scene plus `check = NAME`,
 * `tolerance = ...` (and `alpha = ...` for statistical checks), optional
 * `tier`, `vv` and `tags`.  The case id is "<family>/<name>".
 */
#ifndef SF_CASE_H
#define SF_CASE_H

#include "scene.h"
#include <stdio.h>
#include <gsl/gsl_rng.h>

enum { SF_TIER_QUICK = 0, SF_TIER_FULL = 1, SF_TIER_PAPER = 2 };
enum { SF_VV_CODE = 0, SF_VV_SOLUTION = 1, SF_VV_VALIDATION = 2 };

#define SF_CASE_SPEC_MAX_KEYS 24

/* What a case checks and how: the keys of a case's scene block that the
 * solver does not read.  They share the scene's file format and parser
 * (scene.h: sf_keytab); their table is in case.c. */
typedef struct {
    char check[64];          /* the check a case runs (registry.h) */
    double tolerance, alpha;
    int tier, vv;            /* SF_TIER_*, SF_VV_* */
    char tags[128];
    /* the moderate alternative a statistical case's power is measured
     * against (`slipfield verify --alternative scene`): KEY*FACTOR or
     * KEY+DELTA, applied to the data generator's scene only */
    char power_alt[48];
    int pin_seed;            /* 1: a deterministic check of one pinned realisation
                                (`verify --seed` leaves this case's seed alone) */
    /* a tolerance on seed-dependent data that holds at every seed: a token
     * for why (exact-property, round-off, same-bits), the prose says it;
     * the case then spends none of the tier's false-alarm budget (budget.h) */
    char seed_proof[200];
    /* a case with alpha whose deterministic rows gate seed-dependent data
     * (an estimate from a few realisations against a fixed tolerance, at a
     * measured rate alpha): a failure of them is confirmed on a fresh
     * stream, as a suspect statistical row is (budget.h) */
    int replicate;
    sf_list sweep, sweep2;
    char sweep_param[32];    /* the scene key (or l_over_R) a sweep varies */
    /* stress_run: runs its step budget (max_steps) must stop at a cell that
     * holds the centre of rotation (a regression case's expectation) */
    size_t held_stops;
    /* claims: the group-sequential design's looks (1: one fixed N); look k
     * runs k x samples realisations per point and the last is taken when
     * every claim the tier demands a verdict on is decided */
    size_t looks;
    /* claims: the model verdicts' budget, realisations a point (0: no
     * model verdicts; claims_engine.c, docs/design.md sec. 7.7) */
    size_t model_budget;
    /* claims: per sweep point (one value each), the model verdicts' budget
     * there, each samples x a power of 2 (so that the looks of claims that
     * share a point are nested); a claim's budget is the smallest at its
     * points; model_budget is then the largest (empty: model_budget at
     * every point) */
    sf_list model_budgets;
    /* which keys the block set (index into the table) */
    unsigned char set[SF_CASE_SPEC_MAX_KEYS];
} sf_case_spec;

/* The case keys' table bound to *v (const cast away as sf_scene_keytab). */
sf_keytab sf_case_spec_keytab(const sf_case_spec *v);
/* The alpha the case declares: 0 when it sets none (the key's default is
 * not a declaration; the false-alarm budget counts declared alphas). */
double sf_case_spec_declared_alpha(const sf_case_spec *v);
/* Defaults: no check, tolerance 0, alpha 1e-3, tier quick, vv code. */
void sf_case_spec_default(sf_case_spec *v);
/* Parse a case's scene block: the scene's keys into *s, the case's into
 * *v (both should hold defaults); one parser, file:line messages. */
int sf_case_scene_parse(sf_scene *s, sf_case_spec *v, const char *text, const char *file,
                        int first_line, char *err, size_t errlen);
/* The name of a case key's enum value ("tier", "vv"); "?" if unknown. */
const char *sf_case_enum_name(const char *key, int value);
/* `slipfield help scene`: the scene's keys, then the case's. */
void sf_case_print_keys(FILE *out);

typedef struct {
    char id[128];          /* family/name: [a-z0-9_-] only */
    char family[64];
    char path[512];
    char title[256];
    char *prose_before;    /* Markdown before the scene block (no title) */
    char *prose_after;     /* Markdown after it */
    char *scene_text;      /* the block's text, as written */
    int scene_line;        /* line number of the block's first line */
    sf_scene scene;        /* what the solver reads */
    sf_case_spec spec;     /* what the check reads besides: check, tolerance, ... */
    /* Power runs (docs/reports.md, `make power`): the alternative the DATA GENERATOR draws
     * under ("" for the null: the normal run).  Set by `slipfield verify
     * --alternative`; the checks' generator helpers (checks/common.h:
     * check_gen_scene, check_field_sample...) apply it, oracles never. */
    char alternative[48];
} sf_case;

/* An alternative: KEY*FACTOR or KEY+DELTA.  KEY is a scene key of the
 * generator (mu_std, mu_mean, l, mu_k_ratio, v_b) or a generator-only
 * quantity with no scene key: field_std (std of the standard Gaussian
 * field, nominally 1) and re_im_corr (correlation between the real and
 * imaginary fields of one FFT at the same point, nominally 0). */
typedef struct {
    char key[24];
    int additive;      /* 0: value *= x; 1: value += x */
    double x;
} sf_alt;
/* Parse spec; SF_SUCCESS or SF_EPARSE with the reason in err. */
int sf_alt_parse(const char *spec, sf_alt *a, char *err, size_t errlen);
/* Apply the scene-key part to s (field_std and re_im_corr: no change). */
void sf_alt_apply(const sf_alt *a, sf_scene *s);
/* The generator-only quantities under a (1 and 0 when a is NULL or
 * names a scene key). */
double sf_alt_field_std(const sf_alt *a);
double sf_alt_re_im_corr(const sf_alt *a);

/* Read and validate a case (scene parsed strictly, check name known).
 * Returns SF_SUCCESS, SF_EIO or SF_EPARSE with "file:line: ..." in err. */
int sf_case_read(sf_case *c, const char *path, char *err, size_t errlen);
void sf_case_free(sf_case *c);

/* The same from text[n] (need not be NUL-terminated); path names the case
 * (its id) and appears in messages. */
int sf_case_parse(sf_case *c, const char *path, const char *text, size_t n, char *err, size_t errlen);

/* A fresh MT19937 seeded from the scene (caller frees). */
gsl_rng *sf_case_rng(const sf_case *c);

#endif
