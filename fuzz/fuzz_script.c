/* The runner's script language (script*.c) as `servo-bc --check` reads it:
 * every command checked, packings built, the frame and the controller made,
 * nothing run or written. Packings are capped at 64 particles in this build
 * (SBC_PACKING_MAX), and inputs that jam a packing (`generate`, `packing
 * random`) are skipped: jamming takes 20-500 ms under the sanitizers even for
 * 4-50 discs, which would hold the campaign below 10^3 executions per second.
 * test_generate.c, test_bpm.c and test_input.c cover those commands. */
#include "fuzz.h"

#include "sbc/embedded/script.h"

static int jams(const char *text)
{
    return strstr(text, "generate") != NULL || strstr(text, "random") != NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size);
    sbc_error err;
    fuzz_private_folder();
    if (jams(text)) {
        free(text);
        return 0;
    }
    if (sbc_script_check_string(text, "fuzz.sbc", NULL, &err) != SBC_OK)
        fuzz_expect_message(err.message, "sbc_script_check_string");
    free(text);
    return 0;
}
