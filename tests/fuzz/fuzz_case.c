/* libFuzzer target: the literate case reader on arbitrary bytes. */
#include "case.h"
#include "sf_error.h"

#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sf_case c;
    char err[512];
    int rc = sf_case_parse(&c, "cases/fuzz/input.md", (const char *)data, size, err, sizeof err);
    if (rc != SF_SUCCESS && rc != SF_EPARSE && rc != SF_EIO)
        abort();
    sf_case_free(&c);
    return 0;
}
