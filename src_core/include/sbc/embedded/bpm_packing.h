/* servo_bc: monodisperse sphere packings for the 3D bonded particle model
 * (thesis Sect. 4.1), filling a box [0, L0] x [0, L1] x [0, L2] (m).
 *
 *   cubic   simple cubic lattice, spacing 2 r_p: floor(L / 2 r_p) spheres per
 *           axis (0.25 x 0.1 x 0.1 m at 5 mm: 25 x 10 x 10 = 2500, C_n 5.52,
 *           porosity 0.48: Table 2 exactly).
 *   hcp     hexagonal close packing: rows along x at 2 r_p with every other
 *           row shifted by r_p, rows sqrt(3) r_p apart in y, layers
 *           2 sqrt(2/3) r_p apart in z, every other layer (B) over the
 *           hollows of the one below (ABAB...). Rows and layers: as many as
 *           fit in the box; spheres per row: as many as in the cubic lattice,
 *           so the shifted rows stick out of the box by r_p in x. At 5 mm in
 *           0.25 x 0.1 x 0.1 m: 25 x 11 x 12 = 3300 spheres in 0.255 x
 *           0.0995 x 0.0998 m, as Table 2.
 *
 * Spheres are appended to an engine (bpm.h); nothing is bonded here. */
#ifndef SBC_BPM_PACKING_H
#define SBC_BPM_PACKING_H

#include "sbc/bpm.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_bpm_lattice { SBC_PACK_CUBIC = 0, SBC_PACK_HCP = 1 } sbc_bpm_lattice;

/* Adds the lattice to e. extent (may be NULL) receives the bounding box of
 * the spheres (min and max of x - r and x + r per axis: extent[0..2] low,
 * extent[3..5] high). SBC_ERR_INPUT when not one sphere fits. */
sbc_status sbc_bpm_pack_lattice(sbc_bpm *e, sbc_bpm_lattice lattice, const double box[3], double rp, double rho,
                                double extent[6], sbc_error *err);

/* Random close packing by radius expansion (our own algorithm; the thesis
 * used GiD's mesher). n = round((1 - porosity) V / (4/3 pi r_p^3)) centres
 * are placed uniformly at random (seeded, deterministic) in the box; the
 * radius grows from r_p/2 to r_p in 60 equal steps of packing fraction, and
 * after each the overlaps between spheres and with the walls are minimized
 * (FIRE on sum(overlap^2)/2, net forces to 1e-4 r_p on the way, 1e-7 r_p
 * at the end). SBC_ERR_GEOMETRY when overlaps of 1e-4 r_p remain (the
 * spheres jammed: the porosity asked for is too low for the box; the bound
 * is sqrt(2 E), since a jammed packing balances its forces). Bond with a
 * touch tolerance that reaches across the gaps the relaxation leaves
 * (bpm.h); the bond laws are incremental, so what overlap remains carries
 * no force. */
sbc_status sbc_bpm_pack_random(sbc_bpm *e, const double box[3], double rp, double rho, double porosity,
                               unsigned long seed, double extent[6], sbc_error *err);

/* Bounding box of the spheres of e (as above). */
void sbc_bpm_extent(const sbc_bpm *e, double extent[6]);

/* Porosity of the spheres in the box extent: 1 - sum(4/3 pi r^3) / volume. */
double sbc_bpm_porosity(const sbc_bpm *e, const double extent[6]);

#ifdef __cplusplus
}
#endif

#endif
