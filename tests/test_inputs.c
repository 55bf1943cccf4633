/* Regression: every saved bad input and fuzz seed goes through the scene
 * parser and the case reader (under ASan + UBSan in the sanitized run):
 * an error code, never a crash.  Inputs found by `make fuzz` that crashed
 * are added to tests/bad-input/ and stay here for good. */
#include "test_util.h"
#include "case.h"
#include "scene.h"
#include "sf_error.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>

static size_t feed_dir(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    struct dirent *e;
    size_t n = 0;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' || !strcmp(e->d_name, "MANIFEST"))
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        FILE *f = fopen(path, "rb");
        if (!f)
            continue;
        char *buf = malloc(1 << 20);
        size_t len = fread(buf, 1, (1 << 20) - 1, f);
        fclose(f);
        buf[len] = '\0';
        sf_scene s;
        sf_scene_default(&s);
        char err[256];
        int rc = sf_scene_parse(&s, buf, path, 1, err, sizeof err);
        assert_true(rc == SF_SUCCESS || rc == SF_EPARSE);
        sf_case c;
        rc = sf_case_parse(&c, "cases/regression/input.md", buf, len, err, sizeof err);
        assert_true(rc == SF_SUCCESS || rc == SF_EPARSE);
        sf_case_free(&c);
        free(buf);
        n++;
    }
    closedir(d);
    return n;
}

static void saved_inputs(void **state)
{
    (void)state;
    size_t n = feed_dir("tests/bad-input") + feed_dir("tests/fuzz/corpus-scene") + feed_dir("tests/fuzz/corpus-case");
    assert_true(n >= 20);
}

int main(void)
{
    sf_init();
    const struct CMUnitTest tests[] = { cmocka_unit_test(saved_inputs) };
    return cmocka_run_group_tests_name("inputs", tests, NULL, NULL);
}
