/* The host handle (host.c, the YADE path). Input: the servo_bc words on the
 * first line, then one particle per line, `x y r [m]` (m, m, m, kg; m
 * defaults to 1e-3 kg). When the handle is made, a few host steps with
 * measures that hold the packing at rest. */
#include "fuzz.h"

#include "sbc/host.h"

#include <math.h>

#define MAX_PARTICLES 64

static void drive(sbc_host *h, int n)
{
    const int q = sbc_host_frame_size(h);
    double measures[SBC_HOST_MEASURES] = {0}, x[3 * MAX_PARTICLES], theta[MAX_PARTICLES] = {0},
           force[3 * MAX_PARTICLES] = {0}, torque[MAX_PARTICLES] = {0};
    int k, i;
    measures[SBC_HOST_EP] = 1e-9;
    measures[SBC_HOST_CONTACT_SUM] = 1.0;
    measures[SBC_HOST_CONTACT_COUNT] = 2 * n;
    measures[SBC_HOST_PARTICLE_COUNT] = n;
    for (k = 0; k < 20; ++k) {
        const double *cx = sbc_host_command_x(h);
        int ev;
        for (i = 0; i < 3 * q; ++i) {
            if (!isfinite(cx[i]))
                abort();
            x[i] = cx[i];
        }
        sbc_host_needs(h, measures);
        ev = sbc_host_step(h, measures, x, theta, force, torque);
        if (ev == SBC_EVENT_FAILED) {
            fuzz_expect_message(sbc_host_message(h), "sbc_host_step");
            break;
        }
        if (ev == SBC_EVENT_FINISHED)
            break;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size), *line, *next, msg[512];
    double xy[2 * MAX_PARTICLES], r[MAX_PARTICLES], m[MAX_PARTICLES];
    int n = 0;
    sbc_host *h;
    fuzz_private_folder();
    next = strchr(text, '\n');
    if (next)
        *next++ = '\0';
    for (line = next; line && *line && n < MAX_PARTICLES; line = next) {
        char *end;
        next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        xy[2 * n] = strtod(line, &end);
        xy[2 * n + 1] = strtod(end, &end);
        r[n] = strtod(end, &end);
        m[n] = strtod(end, &line);
        if (line == end)
            m[n] = 1e-3;
        ++n;
    }
    msg[0] = '\0';
    h = sbc_host_create(text, n, xy, r, m, 0, NULL, 1e-6, 1e4, msg, sizeof msg);
    if (h) {
        drive(h, n);
        sbc_host_free(h);
    } else
        fuzz_expect_message(msg, "sbc_host_create");
    free(text);
    return 0;
}
