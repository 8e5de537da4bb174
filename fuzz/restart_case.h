/* The (P) case behind the restart harness and its seed (restart_seed.c): a
 * 5x5 lattice of the embedded engine, loaded as the words say (remap none:
 * the harness moves the frame alone, and the seed's state stays that of
 * tests/reference/restart/seed_P.bin). */
#ifndef SBC_FUZZ_RESTART_CASE_H
#define SBC_FUZZ_RESTART_CASE_H

#include "sbc/embedded/engine.h"
#include "sbc/frame.h"
#include "sbc/packing.h"
#include "sbc/settings.h"
#include "base/words.h"

#include <stdio.h>
#include <stdlib.h>

#define RESTART_CASE_WORDS                                                                                            \
    "P F 0.99 -0.02 -0.02 0.99 increments 3 relax 1e-6 20 tol_force 1e-12 tol_moment 1e-12 gain_force 1e3 "        \
    "gain_moment 1e3 remap none"
#define RESTART_CASE_DT 1e-5

static inline sbc_settings restart_case_settings(void)
{
    char words[] = RESTART_CASE_WORDS, *w[32];
    const int nw = sbc_split_words(words, w, 32);
    sbc_settings s = sbc_settings_default();
    sbc_error err;
    if (sbc_settings_parse(&s, nw, (const char *const *)w, &err) != SBC_OK)
        abort();
    return s;
}

/* the engine (frame set) of the case; the caller frees p, f and the engine */
static inline sbc_engine *restart_case_engine(sbc_packing *p, sbc_frame *f)
{
    sbc_engine_def def = sbc_engine_def_default();
    sbc_error err;
    sbc_engine *e;
    if (sbc_packing_lattice_square(p, 5, 5, 2e-3, 1.02e-3, &err) != SBC_OK ||
        sbc_frame_detect(f, p->n, p->x, p->r, 0.0, &err) != SBC_OK)
        abort();
    def.n = p->n;
    def.x = p->x;
    def.r = p->r;
    def.dt = RESTART_CASE_DT;
    if (!(e = sbc_engine_create(&def, &err)))
        abort();
    sbc_engine_set_frame(e, f);
    return e;
}

#endif
