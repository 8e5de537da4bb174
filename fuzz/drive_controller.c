/* A few controller steps on a packing held at rest at the commanded
 * positions: what every harness that makes a controller does with it. */
#include "fuzz.h"

#include <math.h>

void fuzz_drive_controller(sbc_controller *c, int q, long particles)
{
    double *zero = calloc(3 * (size_t)q + 1, sizeof(double));
    int k, i;
    if (!zero)
        abort();
    for (k = 0; k < 20; ++k) {
        sbc_commands cmd = sbc_controller_commands(c);
        sbc_snapshot snap;
        sbc_error err;
        sbc_event ev;
        for (i = 0; i < 3 * q; ++i)
            if (!isfinite(cmd.x[i])) {
                fprintf(stderr, "fuzz: a non-finite command\n");
                abort();
            }
        memset(&snap, 0, sizeof snap);
        snap.x = cmd.x;
        snap.theta = zero;
        snap.force = zero;
        snap.torque = zero;
        snap.potential_energy = 1e-9;
        snap.contact_force_sum = 1.0;
        snap.contact_count = 24;
        snap.particle_count = particles;
        ev = sbc_controller_step(c, &snap, &err);
        if (ev == SBC_EVENT_FAILED) {
            fuzz_expect_message(err.message, "sbc_controller_step");
            break;
        }
        if (ev == SBC_EVENT_FINISHED)
            break;
    }
    free(zero);
}
