/* One table of checks per family (verification/checks/<family>.c). */
#ifndef SF_CHECKS_H
#define SF_CHECKS_H

#include "../registry.h"

extern const sf_check_def sf_checks_field[];
extern const sf_check_def sf_checks_lognormal[];
extern const sf_check_def sf_checks_contact[];
extern const sf_check_def sf_checks_surface[];
extern const sf_check_def sf_checks_stress[];
extern const sf_check_def sf_checks_deterministic[];
extern const sf_check_def sf_checks_dynamics[];
extern const sf_check_def sf_checks_belt[];
extern const sf_check_def sf_checks_limits[];
extern const sf_check_def sf_checks_validation[];
extern const sf_check_def sf_checks_mean_cof[];
extern const sf_check_def sf_checks_plan[];
extern const sf_check_def sf_checks_design[];
extern const sf_check_def sf_checks_design_stored[];
extern const sf_check_def sf_checks_cellavg[];
extern const sf_check_def sf_checks_mms[];
extern const sf_check_def sf_checks_selftest[];
extern const sf_check_def sf_checks_ref3dof[];
extern const sf_check_def sf_checks_sweepstats[];
extern const sf_check_def sf_checks_estimators[];
extern const sf_check_def sf_checks_mcstop[];
extern const sf_check_def sf_checks_covest[];
extern const sf_check_def sf_checks_cofstrip[];
extern const sf_check_def sf_checks_sensitivity[];
extern const sf_check_def sf_checks_beltnoise[];
extern const sf_check_def sf_checks_beltbox[];
extern const sf_check_def sf_checks_claims_synth[];

#endif
