/* A verdict's name in reports and results (outcome.h). */
#include "outcome.h"

const char *sf_verdict_name(int v)
{
    return v == SF_VERDICT_PASS ? "PASS" : v == SF_VERDICT_FAIL ? "FAIL" : "ERROR";
}
