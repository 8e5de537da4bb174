/* The host handle (host.c, the YADE path). Input: the servo_bc words on the
 * first line, then one particle per line, `x y r [m]` (m, m, m, kg; m
 * defaults to 1e-3 kg). When the handle is made, a few host steps with
 * measures that hold the packing at rest. */
#include "fuzz.h"

#include "sbc/host.h"

#include <math.h>

#define MAX_PARTICLES 64

/* a host whose packing is at rest: the frame where the commands put it */
typedef struct resting {
    sbc_host *h;
    int n, q;
} resting;

static void rest_interior(void *u, const double *mix, double *out)
{
    (void)u, (void)mix;
    out[0] = out[1] = 0.0;
}

static void rest_fire_sums(void *u, double *sums)
{
    (void)u;
    memset(sums, 0, sizeof(double) * SBC_FIRE_SUMS);
}

static void rest_contacts(void *u, double *out)
{
    const resting *r = u;
    out[0] = 1e-9, out[1] = 0.0, out[2] = 2.0 * r->n, out[3] = 1.0;
}

static void rest_frame(void *u, double *buf)
{
    const resting *r = u;
    const double *cx = sbc_host_command_x(r->h);
    int i;
    for (i = 0; i < 3 * r->q; ++i) {
        if (!isfinite(cx[i]))
            abort();
        buf[i] = cx[i];
    }
    buf[8 * r->q + 1] = r->n;
}

static void drive(sbc_host *h, int n)
{
    resting r;
    sbc_host_callbacks cb = {0};
    int k;
    r.h = h, r.n = n, r.q = sbc_host_frame_size(h);
    cb.user_data = &r;
    cb.fire_sums = rest_fire_sums;
    cb.interior = rest_interior;
    cb.contacts = rest_contacts;
    cb.frame = rest_frame;
    if (sbc_host_drive(h, &cb) != 0)
        abort();
    for (k = 0; k < 20; ++k) {
        const int ev = sbc_host_step(h);
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
    h = sbc_host_create(text, 2, n, xy, r, m, 0, NULL, 1e-6, 1e4, msg, sizeof msg);
    if (h) {
        drive(h, n);
        sbc_host_free(h);
    } else
        fuzz_expect_message(msg, "sbc_host_create");
    free(text);
    return 0;
}
