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
#include <gsl/gsl_rng.h>

typedef struct {
    char id[128];          /* family/name: [a-z0-9_-] only */
    char family[64];
    char path[512];
    char title[256];
    char *prose_before;    /* Markdown before the scene block (no title) */
    char *prose_after;     /* Markdown after it */
    char *scene_text;      /* the block's text, as written */
    int scene_line;        /* line number of the block's first line */
    sf_scene scene;
} sf_case;

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
