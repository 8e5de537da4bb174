/* servo_bc: is the packing still held by its frame? (confine.h) */
#include "sbc/confine.h"
#include "geometry.h"

#include <math.h>
#include <stdio.h>

int sbc_confine_inside(const sbc_frame *f, const double *fx, const double *p)
{
    return sbc_frame_geometry_of(f->dim)->inside(f, fx, p);
}

sbc_status sbc_confine_check(const sbc_frame *f, const double *fx, int increment, long id, const double *x,
                             const double *v, sbc_error *err)
{
    const int dim = f->dim;
    double lo[SBC_DIM_MAX], hi[SBC_DIM_MAX], size = 0.0, far = 0.0;
    char centre[3 * 32];
    int q, c, moving = 0, finite = 1;
    for (c = 0; c < dim; ++c)
        finite &= isfinite(x[c]) != 0;
    if (!finite)
        return sbc_fail(err, SBC_ERR_NUMERIC,
                        "servo_bc: increment %d: particle %ld has a non-finite position (the packing blew up; lower "
                        "the time step or take smaller increments); the results before increment %d stand",
                        increment, id, increment);
    if (sbc_confine_inside(f, fx, x))
        return SBC_OK;
    for (c = 0; c < dim; ++c) {
        lo[c] = HUGE_VAL, hi[c] = -HUGE_VAL;
        for (q = 0; q < f->n; ++q) {
            lo[c] = fmin(lo[c], fx[3 * q + c]);
            hi[c] = fmax(hi[c], fx[3 * q + c]);
        }
        size = fmax(size, hi[c] - lo[c]);
        far = fmax(far, fmax(lo[c] - x[c], x[c] - hi[c]));
        moving |= v[c] != 0.0;
    }
    if (far > size && moving) /* a frame's width away and moving: thrown */
        return sbc_fail(err, SBC_ERR_NUMERIC,
                        "servo_bc: increment %d: interior particle %ld was thrown %g m beyond the frame of width %g m "
                        "(the packing blew up; lower the time step: with several contacts per particle the stable "
                        "step is below the critical step of a contact pair); the results before increment %d stand",
                        increment, id, far, size, increment);
    if (dim == 3)
        snprintf(centre, sizeof centre, "(%g, %g, %g)", x[0], x[1], x[2]);
    else
        snprintf(centre, sizeof centre, "(%g, %g)", x[0], x[1]);
    return sbc_fail(err, SBC_ERR_GEOMETRY,
                    "servo_bc: increment %d: interior particle %ld escaped through a gap between frame particles (its "
                    "centre %s m is outside the %s of the frame's centres); the results before increment %d stand",
                    increment, id, centre, sbc_frame_geometry_of(dim)->surface, increment);
}
