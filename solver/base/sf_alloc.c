/* Test-only fault injection (sf_alloc.h): a counter of allocations and
 * the index of the one to fail.  Atomic: the Monte Carlo driver and the
 * sweep allocate from OpenMP threads. */
#include "sf_alloc.h"

#ifdef SF_FAULT_INJECTION
#include <stdatomic.h>

static atomic_long fault_count, fault_target = -1;
static atomic_int fault_fired;

void sf_fault_arm(long k)
{
    atomic_store(&fault_target, -1);
    atomic_store(&fault_count, 0);
    atomic_store(&fault_fired, 0);
    atomic_store(&fault_target, k);
}

long sf_fault_count(void) { return atomic_load(&fault_count); }
int sf_fault_fired(void) { return atomic_load(&fault_fired); }

int sf_fault_fail(void)
{
    long n = atomic_fetch_add(&fault_count, 1);
    if (n != atomic_load(&fault_target))
        return 0;
    atomic_store(&fault_fired, 1);
    return 1;
}
#else
typedef int sf_alloc_unused;   /* ISO C: a translation unit declares something */
#endif
