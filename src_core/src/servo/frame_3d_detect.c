/* sbc_frame_detect_3d: the frame of a sphere packing, as a lattice's faces
 * (frame_3d.c) or, failing that, as a geometrically periodic packing
 * (frame_3d_periodic.c); the two kinds in one call so that neither file
 * calls the other. */
#include "frame_private.h"

sbc_status sbc_frame_detect_3d(sbc_frame *f, int n, const double *x, const double *r, double band, sbc_error *err)
{
    sbc_error grid_err;
    int cube;
    sbc_status st = sbc_frame_detect_grid_3d(f, n, x, r, band, &grid_err);
    if (st != SBC_ERR_FRAME) {
        if (st != SBC_OK)
            *err = grid_err;
        return st;
    }
    st = sbc_frame_detect_periodic_3d(f, n, x, r, &cube, err);
    if (cube)
        return st;
    return sbc_fail(err, SBC_ERR_FRAME, "%s; nor is it a geometrically periodic packing (no eight spheres of one "
                    "radius at the corners of a cuboid, each the others' image at exactly +-L)", grid_err.message);
}
