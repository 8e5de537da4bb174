/* servo_bc: VTK snapshot of the 3D bonded particle engine (bpm.h), for
 * ParaView: one legacy ASCII POLYDATA file PREFIX_spheres.vtk with the
 * sphere centres as vertices and point data radius (m), bonds (intact bonds
 * per sphere), velocity (m/s) and stress (the particle stress of eq. 62, Pa).
 * Render with Glyph (sphere) scaled by "radius". The 2D engine's writer is
 * vtk.h. */
#ifndef SBC_BPM_VTK_H
#define SBC_BPM_VTK_H

#include "sbc/bpm.h"

#ifdef __cplusplus
extern "C" {
#endif

sbc_status sbc_bpm_vtk_write(const char *prefix, const sbc_bpm *e, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
