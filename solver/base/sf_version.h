/* slipfield: the library's version.  The macros are the version of the
 * headers a program was compiled against; sf_version() is the version of
 * the library it runs with (they differ when the shared library was
 * replaced).  Releases are tagged v<MAJOR>.<MINOR>.<PATCH> in git;
 * libslipfield.so.<MAJOR> is the soname. */
#ifndef SF_VERSION_H_PUBLIC
#define SF_VERSION_H_PUBLIC
#ifdef __cplusplus
extern "C" {
#endif

#define SF_VERSION_MAJOR 0
#define SF_VERSION_MINOR 2
#define SF_VERSION_PATCH 0
#define SF_VERSION_STR_(x) #x
#define SF_VERSION_STR(x) SF_VERSION_STR_(x)
/* "0.2.0" */
#define SF_VERSION_STRING \
    SF_VERSION_STR(SF_VERSION_MAJOR) "." SF_VERSION_STR(SF_VERSION_MINOR) "." SF_VERSION_STR(SF_VERSION_PATCH)

/* SF_VERSION_STRING as the library was built. */
const char *sf_version(void);

#ifdef __cplusplus
}
#endif
#endif
