/* slipfield: the solver's allocations, with test-only fault injection
 * (SQLite style).  Every allocation in solver/ goes through sf_malloc,
 * sf_calloc, sf_realloc, or SF_FALLIBLE(call) for a library call that
 * allocates and returns NULL on failure (GSL and FFTW allocators, FFTW
 * plans).  In a normal build they are plain malloc, calloc, realloc and
 * the call itself: no cost.  Compiled with -DSF_FAULT_INJECTION (the test
 * builds of tests/test_faults.c, the sanitised tests and `make coverage`
 * only; never the library that is installed or runs the cases) each one
 * first asks sf_fault_fail(), which makes the k-th allocation after
 * sf_fault_arm(k) fail (once: later ones succeed, as after a transient
 * shortage), so that a test can walk every allocation-failure path of a
 * call and check that it returns SF_ENOMEM, leaks nothing and hands out
 * no half-built object. */
#ifndef SF_ALLOC_H
#define SF_ALLOC_H

#include <stdlib.h>

#ifdef SF_FAULT_INJECTION
/* Fail the k-th allocation (k = 0: the next one) from now on; k < 0
 * disarms.  Resets the count. */
void sf_fault_arm(long k);
/* Allocations seen since the last sf_fault_arm (failed one included). */
long sf_fault_count(void);
/* 1 when the armed allocation was failed since the last sf_fault_arm. */
int sf_fault_fired(void);
/* Counts one allocation; 1 when it is the one to fail. */
int sf_fault_fail(void);
#define sf_malloc(n) (sf_fault_fail() ? NULL : malloc(n))
#define sf_calloc(n, s) (sf_fault_fail() ? NULL : calloc(n, s))
#define sf_realloc(p, n) (sf_fault_fail() ? NULL : realloc(p, n))
#define SF_FALLIBLE(call) (sf_fault_fail() ? NULL : (call))
#else
#define sf_malloc(n) malloc(n)
#define sf_calloc(n, s) calloc(n, s)
#define sf_realloc(p, n) realloc(p, n)
#define SF_FALLIBLE(call) (call)
#endif

#endif
