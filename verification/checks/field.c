#include "checks.h"
const sf_check_def sf_checks_field[] = { { NULL, NULL, NULL } };
