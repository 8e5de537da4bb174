/* servo_bc fuzz harnesses (libFuzzer entry point, replay/replay.c for the
 * replays in make check). Each harness feeds one input surface of the core
 * and aborts when the core breaks its contract: a refusal without a message,
 * or an accepted input that yields a non-finite command. ASan and UBSan
 * catch the rest. */
#ifndef SBC_FUZZ_H
#define SBC_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* the input as a NUL-terminated string (a NUL byte inside ends it early);
 * the caller frees it */
static inline char *fuzz_text(const uint8_t *data, size_t size)
{
    char *t = malloc(size + 1);
    if (!t)
        abort();
    memcpy(t, data, size);
    t[size] = '\0';
    return t;
}

/* the contract: a refusal names its cause */
static inline void fuzz_expect_message(const char *message, const char *what)
{
    if (!message || !message[0]) {
        fprintf(stderr, "fuzz: %s refused an input without a message\n", what);
        abort();
    }
    if (getenv("FUZZ_VERBOSE"))
        printf("  %s: %s\n", what, message);
}

/* drive_controller.c: 20 steps of c (Q frame particles) at rest; aborts on a
 * non-finite command or a failure without a message */
#include "sbc/controller.h"
void fuzz_drive_controller(sbc_controller *c, int q, long particles);

/* work in a private folder, so that outputs an input names stay there */
void fuzz_private_folder(void);

#endif
