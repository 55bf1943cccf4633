/* The box-averaged lognormal covariance oracle of the cell-average checks
 * (defined in cellavg_oracle.c, used by cellavg.c).  Internal to
 * verification/checks. */
#ifndef SF_CHECKS_CELLAVG_ORACLE_H
#define SF_CHECKS_CELLAVG_ORACLE_H

#include <stddef.h>
#include <gsl/gsl_integration.h>

/* The lognormal field's mean, its Gaussian's variance sG^2 (the oracle's
 * own Nataf parameters) and its correlation length. */
typedef struct { double mean, s2, l; } oracle_par;

/* Gauss-Legendre nodes u[] and weights w[] (triangle weight (h - |u|) / h^2
 * folded in) over [-h, h] in pieces of at most l/2; returns their count. */
size_t cellavg_nodes_1d(double h, double l, const gsl_integration_glfixed_table *gl, double *u, double *w);

/* Cov(mu_h(0), mu_h(dx, dy)) of boxes of half-width h, on the nodes of
 * cellavg_nodes_1d (n of them). */
double cellavg_oracle_cov(const oracle_par *o, double h, double dx, double dy, const double *u, const double *w,
                          size_t n);

#endif
