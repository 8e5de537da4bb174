#define _POSIX_C_SOURCE 200809L
/* The packing reader (packing.c, `read_packing`): the input as a packing
 * file, then, when it reads, the checks and the frame detection a run does. */
#include "fuzz.h"

#include "sbc/frame.h"
#include "sbc/packing.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *fp;
    sbc_packing p;
    sbc_error err;
    sbc_status st;
    if (size == 0)
        return 0; /* fmemopen needs a buffer of one byte or more; an empty file is in tests/ */
    if (!(fp = fmemopen((void *)(uintptr_t)data, size, "r")))
        abort();
    st = sbc_packing_read_stream(&p, fp, "fuzz.txt", &err);
    fclose(fp);
    if (st != SBC_OK) {
        fuzz_expect_message(err.message, "sbc_packing_read");
        return 0;
    }
    if (sbc_packing_distinct(p.n, p.x, p.r, &err) == SBC_OK) {
        sbc_frame f;
        if (sbc_frame_detect_packing(&f, &p, &err) == SBC_OK)
            sbc_frame_free(&f);
        else
            fuzz_expect_message(err.message, "sbc_frame_detect_packing");
    } else
        fuzz_expect_message(err.message, "sbc_packing_distinct");
    sbc_packing_free(&p);
    return 0;
}
