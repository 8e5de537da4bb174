/* servo_bc: VTK snapshots of a 3D servo_bc run (spheres.h) for ParaView, two
 * legacy ASCII POLYDATA files per snapshot:
 *   PREFIX_spheres_NNNNNN.vtk  the sphere centres as vertices, point data
 *                              radius (m), frame (1 for frame spheres),
 *                              velocity (m/s), rotation (the rotation vector,
 *                              rad) and force (the contact force, N); render
 *                              with Glyph (sphere) scaled by "radius";
 *   PREFIX_frame_NNNNNN.vtk    the surface through the frame's centres (its
 *                              quadrilaterals, frame.h) at their present
 *                              places, point data reaction (the boundary
 *                              force a_q = -contact force, eq. 5, N).
 * NNNNNN is the increment. The 2D engine's writer is vtk.h. */
#ifndef SBC_SPHERES_VTK_H
#define SBC_SPHERES_VTK_H

#include "sbc/embedded/spheres.h"

#ifdef __cplusplus
extern "C" {
#endif

sbc_status sbc_spheres_vtk_write(const char *prefix, int increment, const sbc_spheres_view *w,
                                 const sbc_frame *frame, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
