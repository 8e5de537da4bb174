/* servo_bc: the driver's frame buffer from a snapshot (driver.h), a layout
 * alone: here, below the engines that fill it and the driver that reads it */
#include "sbc/driver.h"

#include <string.h>

void sbc_driver_frame_from_snapshot(const sbc_snapshot *s, int dim, int Q, double *buf)
{
    const size_t q = (size_t)Q, r = (size_t)SBC_ROTATIONS(dim);
    memcpy(buf, s->x, sizeof(double) * 3 * q);
    memcpy(buf + 3 * q, s->force, sizeof(double) * 3 * q);
    memcpy(buf + SBC_DRIVER_TORQUE(dim, Q), s->torque, sizeof(double) * r * q);
    memcpy(buf + SBC_DRIVER_THETA(dim, Q), s->theta, sizeof(double) * r * q);
    buf[SBC_DRIVER_SUMS(dim, Q)] = s->rotation_sum;
    buf[SBC_DRIVER_SUMS(dim, Q) + 1] = (double)s->particle_count;
}
