/* Shared helpers for the CMocka tests.
 * CMocka 1.1.5's assert_float_equal narrows to float (docs/design.md sec. 10):
 * use assert_close, which compares doubles with an absolute+relative
 * tolerance and prints both values on failure. */
#ifndef SF_TEST_UTIL_H
#define SF_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include "sf_error.h"   /* every test main calls sf_init() first */
#include "scene.h"

#define assert_close(a, b, tol) do {                                         \
        double a_ = (a), b_ = (b), t_ = (tol);                               \
        if (!(fabs(a_ - b_) <= t_ * (1.0 + fabs(b_)))) {                     \
            print_error("%s = %.17g, expected %s = %.17g (tol %.3g)\n",      \
                        #a, a_, #b, b_, t_);                                 \
            fail();                                                          \
        }                                                                    \
    } while (0)

/* Table 1 on the tiled window at l/R = 0.1 (l = 0.05 m, a strip 0.05 m
 * wide): the smallest tiled scene the window tests use */
static inline void sf_test_tiled_scene(sf_scene *s)
{
    sf_scene_default(s);
    s->l = 0.05;
    s->strip_halfwidth = 0.05;
    s->cof_generator = SF_COFGEN_TILES;
}

#endif
