/* The restart loaders (sbc_frame_load, sbc_controller_load) as the LAMMPS and
 * LIGGGHTS fixes call them. Input: raw doubles, L, then the L values of the
 * frame block, then the controller state. When both load, a controller of
 * the (P) case of restart_case.h takes a few steps from the loaded state. */
#include "fuzz.h"

#include "restart_case.h"

#include "sbc/controller.h"


/* the case's masses and the controller settings, made once */
static sbc_settings settings;
static double masses[64];
static int nmasses;

static void setup(void)
{
    sbc_packing p;
    sbc_frame f;
    sbc_engine *e;
    if (nmasses)
        return;
    e = restart_case_engine(&p, &f);
    if (f.n > 64)
        abort();
    sbc_engine_frame_masses(e, masses);
    nmasses = f.n;
    settings = restart_case_settings();
    sbc_engine_free(e);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}

static void drive(const sbc_frame *f, const double *state, size_t n)
{
    int q;
    sbc_error err;
    sbc_controller *c;
    double *mass = malloc(sizeof(double) * ((size_t)f->n + 1));
    if (!mass)
        abort();
    for (q = 0; q < f->n; ++q)
        mass[q] = masses[q % nmasses];
    if (!(c = sbc_controller_create(f, &settings, mass, RESTART_CASE_DT, sbc_engine_def_default().law.kn, &err)))
        fuzz_expect_message(err.message, "sbc_controller_create");
    else if (sbc_controller_load(c, state, n, &err) != SBC_OK)
        fuzz_expect_message(err.message, "sbc_controller_load");
    else
        fuzz_drive_controller(c, f->n, f->n);
    sbc_controller_free(c);
    free(mass);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const size_t n = size / sizeof(double);
    double *v = malloc(sizeof(double) * (n ? n : 1)), len;
    sbc_frame f;
    sbc_error err;
    if (!v)
        abort();
    setup();
    memcpy(v, data, n * sizeof(double));
    memset(&f, 0, sizeof f);
    if (n >= 1 && (len = v[0]) >= 0.0 && len <= (double)(n - 1)) {
        if (sbc_frame_load(&f, v + 1, (size_t)len, &err) == SBC_OK)
            drive(&f, v + 1 + (size_t)len, n - 1 - (size_t)len);
        else
            fuzz_expect_message(err.message, "sbc_frame_load");
        sbc_frame_free(&f);
    }
    free(v);
    return 0;
}
