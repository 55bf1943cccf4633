#ifndef SF_VERSION_H
#define SF_VERSION_H
#define SF_VERSION "0.1.0"
#ifndef SF_GIT_REV
#define SF_GIT_REV "unknown"
#endif
#endif
