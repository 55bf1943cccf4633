/* slipfield: named error codes, GSL style. Every fallible solver call
 * returns one of these; sf_strerror() gives the message. */
#ifndef SF_ERROR_H
#define SF_ERROR_H

enum {
    SF_SUCCESS = 0,
    SF_EINVAL  = 1,   /* invalid argument (NaN, out of range, inconsistent) */
    SF_ENOMEM  = 2,   /* allocation failed or a size would overflow */
    SF_ECAP    = 3,   /* embedding padding hit its cap: truncated (see info) */
    SF_EIO     = 4,   /* file could not be read or written */
    SF_EPARSE  = 5,   /* syntax error in a scene or case file */
    SF_EFAIL   = 6,   /* numerical failure (no convergence, NaN produced) */
    SF_EMAXITER = 7   /* iteration or event limit reached */
};

const char *sf_strerror(int code);

#endif
