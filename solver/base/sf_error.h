/* slipfield: named error codes, GSL style. Every fallible solver call
 * returns one of these; sf_strerror() gives the message. One code, one
 * meaning: a plan that is usable but truncated (SF_ETRUNC) is not a plan
 * that was refused for its size (SF_ETOOBIG), and neither is an allocation
 * that failed (SF_ENOMEM). */
#ifndef SF_ERROR_H
#define SF_ERROR_H
#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

enum {
    SF_SUCCESS = 0,
    SF_EINVAL  = 1,   /* invalid argument (NaN, out of range, inconsistent) */
    SF_ENOMEM  = 2,   /* allocation failed */
    SF_ETRUNC  = 3,   /* a warning, not a failure: the embedding hit its padding
                         cap and the covariance is truncated; the object IS
                         returned and usable (error in its info) */
    SF_EIO     = 4,   /* file could not be read or written */
    SF_EPARSE  = 5,   /* syntax error in a scene or case file */
    SF_EFAIL   = 6,   /* numerical failure (no convergence, NaN produced) */
    SF_EMAXITER = 7,  /* iteration or event limit reached */
    SF_ETOOBIG = 8    /* refused: the request is over a documented size cap
                         (grid points, embedding size, window width) or a
                         size would overflow; nothing is returned */
};

const char *sf_strerror(int code);

#if defined(__GNUC__)
#define SF_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define SF_PRINTF_LIKE(f, a)
#endif

/* The one error-message idiom: write the printf-style message into
 * err[0..n) (nothing when err is NULL or n is 0) and return rc, so that
 * `return sf_seterr(err, errlen, SF_EINVAL, "bad %s", what);` reports and
 * fails in one statement. */
int sf_seterr(char *err, size_t n, int rc, const char *fmt, ...) SF_PRINTF_LIKE(4, 5);

/* Exit statuses of every slipfield program: the CLI, the verification
 * harness and its case processes (docs/design.md sec. 1.4). */
enum { SF_EXIT_OK = 0, SF_EXIT_CHECK = 1, SF_EXIT_USAGE = 2, SF_EXIT_INTERNAL = 3 };

/* Call once at the start of every program that uses the library (the CLI,
 * each unit test, the bench; an application embedding slipfield too),
 * before any other slipfield call.  It switches GSL's default error
 * handler off: that handler abort()s, while the solver checks the status
 * of every GSL call that can fail (root brackets, elliptic integrals on a
 * NaN state, odeiv2 steps) and turns it into an SF_E* code.  GSL's handler
 * is process-wide: sf_init() sets it for the whole process and is not
 * thread-safe (call it before starting threads). */
void sf_init(void);

/* The one test for "may I use what this call returned?": success or the
 * SF_ETRUNC warning.  Use `if (!sf_usable(rc)) return rc;`. */
static inline int sf_usable(int rc) { return rc == SF_SUCCESS || rc == SF_ETRUNC; }

#ifdef __cplusplus
}
#endif
#endif
