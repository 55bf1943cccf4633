#include "bench.h"
int bench_memory(FILE *f, const char *dir)
{
    (void)dir;
    fprintf(f, "## memory\n\nTODO\n");
    return 0;
}
