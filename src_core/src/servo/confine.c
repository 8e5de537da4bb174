/* servo_bc: is the packing still held by its frame? (confine.h) */
#include "sbc/confine.h"

#include <math.h>

int sbc_confine_inside(const sbc_frame *f, const double *fx, const double p[2])
{
    int q, in = 0;
    for (q = 0; q < f->n; ++q) {
        const double *a = &fx[3 * q], *b = &fx[3 * ((q + 1) % f->n)];
        if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            in = !in;
    }
    return in;
}

sbc_status sbc_confine_check(const sbc_frame *f, const double *fx, int increment, long id, const double x[2],
                             const double v[2], sbc_error *err)
{
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL}, size, far = 0.0;
    int q, c;
    if (!isfinite(x[0]) || !isfinite(x[1]))
        return sbc_fail(err, SBC_ERR_NUMERIC,
                        "servo_bc: increment %d: particle %ld has a non-finite position (the packing blew up; lower "
                        "the time step or take smaller increments); the results before increment %d stand",
                        increment, id, increment);
    if (sbc_confine_inside(f, fx, x))
        return SBC_OK;
    for (q = 0; q < f->n; ++q)
        for (c = 0; c < 2; ++c) {
            lo[c] = fmin(lo[c], fx[3 * q + c]);
            hi[c] = fmax(hi[c], fx[3 * q + c]);
        }
    size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    for (c = 0; c < 2; ++c)
        far = fmax(far, fmax(lo[c] - x[c], x[c] - hi[c]));
    if (far > size && hypot(v[0], v[1]) > 0.0) /* a frame's width away and moving: thrown */
        return sbc_fail(err, SBC_ERR_NUMERIC,
                        "servo_bc: increment %d: interior particle %ld was thrown %g m beyond the frame of width %g m "
                        "(the packing blew up; lower the time step: with several contacts per particle the stable "
                        "step is below the critical step of a contact pair); the results before increment %d stand",
                        increment, id, far, size, increment);
    return sbc_fail(err, SBC_ERR_GEOMETRY,
                    "servo_bc: increment %d: interior particle %ld escaped through a gap between frame particles (its "
                    "centre (%g, %g) m is outside the polygon of the frame's centres); the results before increment "
                    "%d stand",
                    increment, id, x[0], x[1], increment);
}
