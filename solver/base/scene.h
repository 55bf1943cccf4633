/* slipfield: scenes.  A scene is `key = value` lines (`#` comments), SI
 * units, defaults from the paper's Table 1 stochastic baseline.  Parsing is
 * strict: unknown or duplicate keys, missing values, NaN/Inf and
 * out-of-range values are errors naming file, line and key.
 *
 * One table (scene.c) describes every solver key: type, unit, default,
 * range and a one-line help.  The format and its parser are generic (a
 * key table per struct, sf_keytab below): the verification layer declares
 * the keys of a case (check, tolerance, ...) in its own table and parses
 * a case's scene block with both tables at once, so the solver knows
 * nothing of checks and there is still one format with one parser.
 * `slipfield help scene` prints both tables.
 */
#ifndef SF_SCENE_H
#define SF_SCENE_H
#ifdef __cplusplus
extern "C" {
#endif

#include "sf_version.h"   /* SF_VERSION_STR, the stringifier SF_STR uses */

#include <stddef.h>
#include <stdio.h>

#define SF_LIST_MAX 64
#define SF_SCENE_MAX_KEYS 128
/* The most realisations (or samples) a run takes: the scene key `samples`
 * and `slipfield sweep --realisations` / --pilot share this cap. */
#define SF_MAX_SAMPLES 10000000

typedef struct {
    size_t n;
    double v[SF_LIST_MAX];
} sf_list;

enum { SF_INTEG_ADAPTIVE = 0, SF_INTEG_RK4 = 1, SF_INTEG_RK8PD = 2, SF_INTEG_RKCK = 3 };
enum { SF_DOF_1 = 0, SF_DOF_3 = 1 };   /* values of the `dof` key ("1", "3") */
enum { SF_COFGEN_AUTO = 0, SF_COFGEN_CIRCULANT = 1, SF_COFGEN_TILES = 2, SF_COFGEN_BELT_NOISE = 3 };   /* `cof_generator` */
/* auto takes the tiles above 2^SF_COF_AUTO_LOG2 strip points (numplan.h:
 * SF_COF_AUTO_POINTS, and why); the key's help says the number */
#define SF_COF_AUTO_LOG2 20
#define SF_STR(x) SF_VERSION_STR(x)   /* a macro's value as a string literal (sf_version.h's stringifier) */
enum { SF_COFMODEL_AUTO = 0, SF_COFMODEL_POINT = 1, SF_COFMODEL_CELL = 2 };   /* `cof_model` (numplan.h) */
enum { SF_QOI_PAPER = 0, SF_QOI_CYCLES = 1 };   /* `qoi_def`: which definitions give pv_x, pv_F, stick_fraction (oscillator.h) */

typedef struct {
    /* physics (Table 1) */
    double m, k, v_b, R, l, mu_mean, mu_std, mu_k_ratio, g, T, eps_lambda, dt;
    unsigned long seed;
    int cof;                 /* sf_cof_kind: uniform, variable, field */
    /* random-field grid */
    size_t nx, ny;
    double dx, dy, pad_cap, eig_tol;
    int no_padding, precorrect;
    int fftw_planner;        /* 0: FFTW_ESTIMATE, 1: FFTW_MEASURE (sf_field_spec.measure) */
    double strip_halfwidth;  /* belt strip half-width in y [m]; 0: automatic bound */
    int cof_generator;       /* SF_COFGEN_*: circulant strip, tiles on demand, or auto */
    int cof_model;           /* SF_COFMODEL_*: point values, cell averages, or the plan's choice */
    size_t samples;
    /* contact */
    int layout;              /* sf_layout */
    size_t cells;            /* 0: chosen by the plan (numplan.h) */
    double u, v, w;          /* relative velocity [m/s] and spin [rad/s] */
    size_t ntheta, npsi;     /* limit-surface direction grid */
    /* dynamics */
    int integrator;
    int dof;                 /* SF_DOF_1: the 1-D model of Eqs. 3-4; SF_DOF_3: x, y, phi (Eq. 5) */
    double rtol, t_skip;     /* rtol 0: chosen by the plan (numplan.h) */
    size_t max_steps;        /* slip steps a run may take (oscillator.h: SF_EMAXITER past it) */
    double qoi_tol;          /* relative QoI error the plan aims at */
    int qoi_def;             /* SF_QOI_PAPER (window stick fraction, PV per oscillation) or SF_QOI_CYCLES */
    double x0, y0, phi0, vx0, vy0, w0;   /* initial state (ground frame, SI): default rest at the origin */
    int velocity_jump, exact_section, history;
    int shortcuts;           /* 0: the plan computes in full (cases verifying its shortcuts) */
    /* which keys the file set (index into the key table) */
    unsigned char set[SF_SCENE_MAX_KEYS];
} sf_scene;

/* ---- the `key = value` format: one parser, a key table per layer ---- */

typedef enum { SF_KEY_DOUBLE, SF_KEY_SIZE, SF_KEY_ULONG, SF_KEY_BOOL, SF_KEY_ENUM, SF_KEY_STRING, SF_KEY_LIST } sf_key_type;

/* One key of a struct.  lo/hi bounds (DOUBLE, SIZE, LIST items: not
 * checked for LIST) are inclusive unless the *_open flag is set. */
typedef struct {
    const char *name;
    sf_key_type type;
    size_t off;                 /* offsetof the field in its struct */
    size_t size;                /* STRING: buffer size */
    double lo, hi;
    int lo_open, hi_open;
    const char *def;            /* default as text, parsed by the same code */
    const char *unit;           /* "1": dimensionless; "": a switch or a name */
    const char *const *choices; /* ENUM: names in value order, NULL-terminated */
    const char *help;
} sf_key;

/* An enum key's names, in value order: at file scope a static array
 * (C11 6.5.2.5), so sf_keys_enum_name() can return them as they are. */
#define SF_KEY_CHOICES(...) ((const char *const[]){ __VA_ARGS__, NULL })

/* A key table bound to one struct: keys[0..n) index obj; set[i] says
 * key i was in the text (n flags).  obj and set may be NULL for the
 * functions that only read the table (sf_keys_print, sf_keys_enum_name). */
typedef struct {
    const sf_key *keys;
    size_t n;
    void *obj;
    unsigned char *set;
} sf_keytab;

/* Every key of t to its default; no key marked set. */
void sf_keys_default(const sf_keytab *t);
/* Parse `text` (NUL-terminated) against the tables t[0..nt): a key is
 * looked up in each in turn; an unknown or repeated key, a missing or bad
 * value are errors "file:line: ..." (lines counted from first_line).
 * Returns SF_SUCCESS or SF_EPARSE with the message in err. */
int sf_keys_parse(const sf_keytab *t, size_t nt, const char *text, const char *file,
                  int first_line, char *err, size_t errlen);
/* Whether the text set the key (unknown names -> 0). */
int sf_keys_was_set(const sf_keytab *t, const char *key);
/* The name of an ENUM key's value; "?" for an unknown key or value. */
const char *sf_keys_enum_name(const sf_keytab *t, const char *key, int value);
/* The struct as `key = value` lines, every key of the table. */
void sf_keys_write(const sf_keytab *t, FILE *out);
/* The tables t[0..nt) as one listing under one header line (name, unit,
 * default, range or choices, meaning). */
void sf_keys_print(const sf_keytab *t, size_t nt, FILE *out);

/* ---- scenes ---- */

/* The scene's key table bound to *s (const is cast away: parse only into
 * a scene you own). */
sf_keytab sf_scene_keytab(const sf_scene *s);

/* Table 1 defaults. */
void sf_scene_default(sf_scene *s);

/* Parse `text` (NUL-terminated) into *s (which should hold defaults).
 * `file` and `first_line` are used in messages: "file:line: key 'k': ...".
 * Returns SF_SUCCESS or SF_EPARSE with the message in err. */
int sf_scene_parse(sf_scene *s, const char *text, const char *file,
                   int first_line, char *err, size_t errlen);

/* Read and parse a whole scene file (at most 1 MiB). SF_EIO, SF_EPARSE. */
int sf_scene_read_file(sf_scene *s, const char *path, char *err, size_t errlen);

/* Read a text file of at most 1 MiB whole (scene and case files): *text
 * is NUL-terminated and malloc'd (caller frees), *len its length.  SF_EIO
 * when it cannot be opened or read, SF_EPARSE when larger than 1 MiB or
 * holding a NUL byte (messages name the file and `what`, e.g. "scene"). */
int sf_read_text(const char *path, const char *what, char **text, size_t *len, char *err, size_t errlen);

/* Whether a key was set by the file (by name; unknown names -> 0). */
int sf_scene_was_set(const sf_scene *s, const char *key);

/* Write the effective scene as `key = value` lines (all keys). */
void sf_scene_write(const sf_scene *s, FILE *out);

/* Print the scene's key table (name, unit, default, range, help); the
 * case keys are verification's (sf_case_print_keys). */
void sf_scene_print_keys(FILE *out);

/* The unit of a key as the key table has it ("m/s", "1" for a
 * dimensionless number, "" for a switch or a name); l_over_R (a sweep
 * parameter) is "1"; NULL for an unknown key.  For axis labels. */
const char *sf_scene_key_unit(const char *key);

/* Names of the enum values, for messages and reports. */
const char *sf_scene_enum_name(const char *key, int value);

#ifdef __cplusplus
}
#endif
#endif
