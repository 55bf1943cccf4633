/* slipfield: the error codes' messages (sf_strerror), sf_seterr, which
 * writes a failed call's message into the caller's buffer, and sf_init,
 * which turns GSL's abort-on-error handler off (sf_error.h). */
#include "sf_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <gsl/gsl_errno.h>

int sf_seterr(char *err, size_t n, int rc, const char *fmt, ...)
{
    if (err && n) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, n, fmt, ap);
        va_end(ap);
    }
    return rc;
}

void sf_init(void)
{
    gsl_set_error_handler_off();
}

const char *sf_strerror(int code)
{
    switch (code) {
    case SF_SUCCESS: return "success";
    case SF_EINVAL:  return "invalid argument";
    case SF_ENOMEM:  return "out of memory";
    case SF_ETRUNC:  return "embedding padding cap reached (covariance truncated)";
    case SF_EIO:     return "input/output error";
    case SF_EPARSE:  return "parse error";
    case SF_EFAIL:   return "numerical failure";
    case SF_EMAXITER: return "iteration limit reached";
    case SF_ETOOBIG: return "over the size cap";
    default:         return "unknown error";
    }
}
