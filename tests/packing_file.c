/* Test helper: a generated packing written once per run of the tests. */
#include "packing_file.h"
#include "check.h"

#include "sbc/embedded/script.h"

#include <stdio.h>

int packing_file(const char *name, const char *generate, char *path, size_t cap, int *made)
{
    char text[2048];
    sbc_error err;
    snprintf(path, cap, "%s/%s.txt", test_tmpdir, name);
    if (*made)
        return 1;
    snprintf(text, sizeof text, "%swrite_packing text %s\n", generate, path);
    if (sbc_script_run_string(text, name, NULL, &err) != SBC_OK) {
        printf("  %s: generate: %s\n", name, err.message);
        return 0;
    }
    *made = 1;
    return 1;
}
