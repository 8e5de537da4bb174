/* servo_bc: is the packing still held by its frame? (confine.h) */
#include "sbc/confine.h"
#include "geometry.h"

#include <math.h>
#include <stdio.h>

void sbc_confine_prepare(sbc_confine *c, const sbc_frame *f, const double *fx)
{
    const int dim = f->dim;
    int q, k;
    c->frame = f;
    c->fx = fx;
    c->inner = -1;
    for (k = 0; k < SBC_DIM_MAX; ++k) {
        c->lo[k] = c->in_lo[k] = HUGE_VAL;
        c->hi[k] = c->in_hi[k] = -HUGE_VAL;
    }
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < dim; ++k) {
            c->lo[k] = fmin(c->lo[k], fx[3 * q + k]);
            c->hi[k] = fmax(c->hi[k], fx[3 * q + k]);
        }
    /* the centres on face (edge) lo of axis k lie below in_lo[k], those on
       hi above in_hi[k], and with them the surface's cells (the polygon's
       segments, which join centres of one edge): none meets the open box
       between, which is connected, hence all inside or all outside */
    for (k = 0; k < dim; ++k)
        c->in_lo[k] = -HUGE_VAL, c->in_hi[k] = HUGE_VAL;
    for (q = 0; q < f->n; ++q) {
        int on = f->side[q];
        if (dim == 2) /* the 2D sides (frame.h) as face bits: left, right, bottom, top */
            on = on == SBC_SIDE_LEFT ? 1 : on == SBC_SIDE_RIGHT ? 2 : on == SBC_SIDE_BOTTOM ? 4 : on == SBC_SIDE_TOP ? 8
               : q == f->corner[SBC_CORNER_BL] ? 5 : q == f->corner[SBC_CORNER_BR] ? 6
               : q == f->corner[SBC_CORNER_TR] ? 10 : 9;
        for (k = 0; k < dim; ++k) {
            if (on >> (2 * k) & 1)
                c->in_lo[k] = fmax(c->in_lo[k], fx[3 * q + k]);
            if (on >> (2 * k + 1) & 1)
                c->in_hi[k] = fmin(c->in_hi[k], fx[3 * q + k]);
        }
    }
    {
        double mid[SBC_DIM_MAX] = {0.0, 0.0, 0.0};
        int open = 1;
        for (k = 0; k < dim; ++k) {
            open &= c->in_lo[k] < c->in_hi[k];
            mid[k] = 0.5 * (c->in_lo[k] + c->in_hi[k]);
        }
        if (open)
            c->inner = sbc_frame_geometry_of(dim)->inside(f, fx, mid);
    }
}

int sbc_confine_inside(const sbc_confine *c, const double *p)
{
    const sbc_frame *f = c->frame;
    int k, out = 0, in = c->inner >= 0;
    for (k = 0; k < f->dim; ++k) {
        out |= p[k] < c->lo[k] || p[k] > c->hi[k];
        in &= p[k] > c->in_lo[k] && p[k] < c->in_hi[k];
    }
    if (out)
        return 0;
    if (in)
        return c->inner;
    return sbc_frame_geometry_of(f->dim)->inside(f, c->fx, p);
}

sbc_status sbc_confine_check(const sbc_confine *cf, int increment, long id, const double *x, const double *v,
                             sbc_error *err)
{
    const int dim = cf->frame->dim;
    const double *lo = cf->lo, *hi = cf->hi; /* the box of the centres, prepared */
    double size = 0.0, far = 0.0;
    char centre[3 * 32];
    int c, moving = 0, finite = 1;
    for (c = 0; c < dim; ++c)
        finite &= isfinite(x[c]) != 0;
    if (!finite)
        return sbc_fail(err, SBC_ERR_NUMERIC,
                        "servo_bc: increment %d: particle %ld has a non-finite position (the packing blew up; lower "
                        "the time step or take smaller increments); the results before increment %d stand",
                        increment, id, increment);
    if (sbc_confine_inside(cf, x))
        return SBC_OK;
    for (c = 0; c < dim; ++c) {
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
