/* slipfield: the version of the library a program runs with (sf_version.h). */
#include "sf_version.h"

const char *sf_version(void)
{
    return SF_VERSION_STRING;
}
