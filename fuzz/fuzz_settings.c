/* The servo_bc grammar (settings.c): words from the input, then, when they
 * parse, a controller over a 4x4 lattice frame that takes a few steps. */
#include "fuzz.h"

#include "sbc/controller.h"
#include "sbc/frame.h"
#include "sbc/packing.h"
#include "sbc/settings.h"
#include "base/words.h"


static void drive(const sbc_settings *s)
{
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    sbc_controller *c;
    double mass[16];
    int q;
    if (sbc_packing_lattice_square(&p, 4, 4, 2e-3, 1.02e-3, &err) != SBC_OK ||
        sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) != SBC_OK)
        abort();
    for (q = 0; q < f.n; ++q)
        mass[q] = 6.5e-3;
    c = sbc_controller_create(&f, s, mass, 1e-6, 1e4, &err);
    if (c)
        fuzz_drive_controller(c, f.n, p.n);
    else
        fuzz_expect_message(err.message, "sbc_controller_create");
    sbc_controller_free(c);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size), *w[128];
    int nw = sbc_split_words(text, w, 128);
    sbc_settings s = sbc_settings_default();
    sbc_error err;
    fuzz_private_folder();
    if (nw <= 128) {
        if (sbc_settings_parse(&s, nw, (const char *const *)w, &err) == SBC_OK)
            drive(&s);
        else
            fuzz_expect_message(err.message, "sbc_settings_parse");
    }
    free(text);
    return 0;
}
