/* The space-filling design of the accuracy plan's checks, shared by the
 * run on the design (design.c: plan_design) and the checks on its stored
 * tables (design_stored.c): the design's box, points and scenes, the
 * promise's rates and their exact binomial tests.  Defined in design.c;
 * internal to verification/checks. */
#ifndef SF_CHECKS_DESIGN_COMMON_H
#define SF_CHECKS_DESIGN_COMMON_H

#include <stddef.h>
#include "../case.h"
#include "../result.h"
#include "numplan.h"
#include "scene.h"

enum { NQ = 3, ND = 6, NLEV = 3 };

/* The promise, as rates over design points (a point's error: the largest
 * relative error of its decided QoIs, the quantity the plan's models are
 * calibrated on, numplan.c): each is H0 of an exact one-sided binomial
 * test that rejects when the points over the line are too many. */
#define MISS_RATE 0.05     /* achieved > qoi_tol */
#define WILD_RATE 0.01     /* achieved > `tolerance` x qoi_tol */
#define UNDER_RATE 0.05    /* achieved > the plan's predicted error */
#define UNDECIDED_RATE 0.25   /* points that cannot decide (no cycle, a cycle at the edge, reference not converged) */
#define NTEST 4            /* the case's alpha split over the four tests (Bonferroni) */
#define MDE_POWER 0.99

/* The smallest count k whose P(X >= k | n, p0) is <= alpha: the test
 * rejects H0 "rate <= p0" at k or more (n + 1: it cannot reject at this n). */
size_t design_binom_critical(size_t n, double p0, double alpha);

/* One rate's test: the row (a p-value at alpha) and a line of findings
 * with the observed fraction, its Clopper-Pearson 95% interval, the
 * critical count and the minimum detectable rate. */
void design_rate_test(sf_result *r, const char *what, size_t k, size_t n, double p0, double alpha);

/* The prediction's sharpness (reported, not gated: outside the box its
 * fit covers the prediction is the budget, orders of magnitude above the
 * error at large l/R): the median of achieved / predicted over the
 * decided points with its distribution-free 95% interval (order
 * statistics, binomial(n, 1/2)). */
void design_report_sharpness(sf_result *r, double *ratio, size_t n);

/* The design's box from the case's scene (lo, hi per dimension) and its
 * Latin hypercube (n points, design seed; the caller frees *u);
 * SF_EINVAL with the scene's requirements noted. */
int design_box(const sf_case *c, sf_result *r, double *lo, double *hi);

double *design_points(unsigned long seed, size_t n);

/* Point ui's scene: s0 at the point's l/R (*lr), CV, v_b, mean COF, T, qoi_tol */
int design_scene(const sf_scene *s0, const double *lo, const double *hi, const double *ui, sf_scene *s,
                 double *lr, char *err, size_t errlen);

/* A point's scene and settings as the design's table prints them (the
 * stored measurements are matched against this text): l/R, CV, v_b, mu,
 * T, qoi_tol, rings, rtol, separated by sep */
void design_point_text(char *buf, size_t len, const char *sep, double lr, const sf_scene *s, const sf_numplan *np);

#endif
