/* slipfield verification: the registry of checks.  Each family keeps its
 * checks in verification/checks/<family>.c as a NULL-terminated table;
 * registry.c lists the tables. */
#ifndef SF_REGISTRY_H
#define SF_REGISTRY_H

#include "case.h"
#include "result.h"

/* Run the check for case c, filling r.  Return SF_SUCCESS, or an error
 * code when the check could not be carried out (the case then fails). */
typedef int (*sf_check_fn)(const sf_case *c, sf_result *r);

typedef struct {
    const char *name;
    sf_check_fn fn;
    const char *summary;
} sf_check_def;

const sf_check_def *sf_check_find(const char *name);
/* Iterate: returns NULL past the end. */
const sf_check_def *sf_check_at(size_t i);

#endif
