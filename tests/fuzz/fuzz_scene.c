/* libFuzzer target: the scene parser on arbitrary bytes, with the
 * solver's key table and the case's (a case's scene block: every key type).
 * It must return SF_SUCCESS or SF_EPARSE with a message naming the place,
 * never crash, leak or read out of bounds (ASan + UBSan). */
#include "case.h"
#include "scene.h"
#include "sf_error.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    sf_scene s;
    sf_case_spec v;
    sf_scene_default(&s);
    sf_case_spec_default(&v);
    char err[256];
    int rc = sf_case_scene_parse(&s, &v, text, "fuzz.scene", 1, err, sizeof err);
    if (rc != SF_SUCCESS && rc != SF_EPARSE)
        abort();
    if (rc == SF_EPARSE && strncmp(err, "fuzz.scene:", 11) != 0)
        abort();   /* every message names the file */
    free(text);
    return 0;
}
