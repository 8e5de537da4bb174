/* servo_bc: VTK snapshots of the embedded engine, for ParaView.
 *
 * Two legacy ASCII POLYDATA files per snapshot:
 *   PREFIX_particles_NNNNNN.vtk  points with radius (m), rotation (rad),
 *                                velocity (m/s) and frame flag; render with
 *                                Glyph (sphere/disc) scaled by "radius";
 *   PREFIX_contacts_NNNNNN.vtk   one line per contact or intact bond between
 *                                the centres, cell data normal_force (N,
 *                                negative in a bond under tension), overlap
 *                                (m) and bond (1 = intact cohesive bond). */
#ifndef SBC_VTK_H
#define SBC_VTK_H

#include "sbc/embedded/engine.h"

#ifdef __cplusplus
extern "C" {
#endif

sbc_status sbc_vtk_write(const char *prefix, int increment, const sbc_engine_view *view, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
