/* slipfield: the paired estimators at a target standard error (sweep.h:
 * sf_sweep_run_estimator_se), above both of them (mlmc.h, antithetic.h). */
#include "antithetic.h"
#include "mlmc.h"
#include "sf_error.h"
#include "sweep.h"

#include <math.h>
#include <string.h>

enum { NQ = SF_SWEEP_NQ };

int sf_sweep_run_estimator_se(const sf_scene *s, int est, const double target_se[SF_SWEEP_NQ], size_t n_pilot,
                              size_t n_max, int threads, const char *label, sf_sweep_point *out, char *err,
                              size_t errlen)
{
    memset(out, 0, sizeof *out);
    int any = 0;
    for (int q = 0; target_se && q < NQ; q++) {
        if (isnan(target_se[q]))
            continue;
        if (!(target_se[q] > 0) || !isfinite(target_se[q]))
            return sf_seterr(err, errlen, SF_EINVAL, "estimator sweep: a target standard error must be finite and > 0 "
                                                     "(got %g)", target_se[q]);
        any = 1;
    }
    if (!any)
        return sf_seterr(err, errlen, SF_EINVAL, "estimator sweep: no ratio has a target standard error");
    switch (est) {
    case SF_EST_MLMC:
    case SF_EST_MLMC_BOXES:
    case SF_EST_MLMC_SUB: return sf_mlmc_run_se(s, est, target_se, n_pilot, n_max, threads, label, out, err, errlen);
    case SF_EST_ANTITHETIC: return sf_anti_run(s, n_max, n_pilot, target_se, threads, label, out, err, errlen);
    default:
        return sf_seterr(err, errlen, SF_EINVAL, "estimator sweep: a target standard error takes mlmc, mlmc-boxes, "
                                                 "mlmc-sub or antithetic (got %s)", sf_sweep_estimator_name(est));
    }
}
