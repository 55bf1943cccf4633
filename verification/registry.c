/* The table of check families: every check a case can name, in the order
 * `slipfield verify --checks` lists them (registry.h: lookup by name). */
#include "registry.h"
#include "checks/checks.h"

#include <string.h>

static const sf_check_def *const families[] = {
    sf_checks_field,
    sf_checks_lognormal,
    sf_checks_contact,
    sf_checks_surface,
    sf_checks_stress,
    sf_checks_deterministic,
    sf_checks_dynamics,
    sf_checks_belt,
    sf_checks_limits,
    sf_checks_validation,
    sf_checks_mean_cof,
    sf_checks_plan,
    sf_checks_design,
    sf_checks_design_stored,
    sf_checks_cellavg,
    sf_checks_mms,
    sf_checks_cofstrip,
    sf_checks_selftest,
    sf_checks_ref3dof,
    sf_checks_sweepstats,
    sf_checks_estimators,
    sf_checks_mcstop,
    sf_checks_covest,
    sf_checks_sensitivity,
    sf_checks_beltnoise,
    sf_checks_beltbox,
    sf_checks_claims_synth,
};

const sf_check_def *sf_check_at(size_t i)
{
    for (size_t f = 0; f < sizeof families / sizeof families[0]; f++) {
        for (const sf_check_def *d = families[f]; d->name; d++) {
            if (i == 0)
                return d;
            i--;
        }
    }
    return NULL;
}

const sf_check_def *sf_check_find(const char *name)
{
    const sf_check_def *d;
    for (size_t i = 0; (d = sf_check_at(i)); i++)
        if (strcmp(d->name, name) == 0)
            return d;
    return NULL;
}
