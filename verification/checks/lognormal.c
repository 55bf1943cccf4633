#include "checks.h"
const sf_check_def sf_checks_lognormal[] = { { NULL, NULL, NULL } };
