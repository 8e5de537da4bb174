/* The runner's script language (script*.c) as `servo-bc --check` reads it:
 * every command checked, packings built, the frame and the controller made,
 * nothing run or written. */
#include "fuzz.h"

#include "sbc/script.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size);
    sbc_error err;
    fuzz_private_folder();
    if (sbc_script_check_string(text, "fuzz.sbc", NULL, &err) != SBC_OK)
        fuzz_expect_message(err.message, "sbc_script_check_string");
    free(text);
    return 0;
}
