#include "bench.h"
int bench_sweep(FILE *f, const char *dir)
{
    (void)dir;
    fprintf(f, "## sweep\n\nTODO\n");
    return 0;
}
