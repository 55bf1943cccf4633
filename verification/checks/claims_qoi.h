/* The QoIs of one run under every definition the paper's claims compare
 * (claims_qoi.c), for the claims engine (claims_engine.c).  Internal to
 * verification/checks. */
#ifndef SF_CHECKS_CLAIMS_QOI_H
#define SF_CHECKS_CLAIMS_QOI_H

#include "common.h"
#include "claims.h"

/* Raw QoIs of one run (t_skip = 0 in the run) under every definition:
 * out[NOUT] (claims.h), from the run's result res and history h up to
 * T; the windows start at tskip (D_OURS, D_CYCLES), 0 (D_TSKIP0) and
 * tlate (D_TSKIP_LATE). */
void claims_raw_qoi(const sf_osc_result *res, const check_hist *h, double T, double tskip, double tlate,
                    double *out);

#endif
