/* servo_bc: particle and RVE stress of the 3D bonded particle model (thesis
 * Sect. 3.6, eqs. 54-62).
 *
 * Particle stress, eq. 62 (Love-Weber): sigma_p = (1/V_p) sum_c (x_c - x_p)
 * (x) F_c, with F_c the force acting ON the particle at contact c (the
 * thesis writes the force the particle applies, hence its minus sign; both
 * give negative stress in compression). Bond forces act at the bond's
 * contact point (bpm_bond.h: halfway across the gap on the centre line);
 * bond moments are left out, as eq. 59 assumes. An external or reaction load
 * component k on a sphere acts on its surface on the outer side along axis k
 * (x_p + r sgn(x_pk - c_k) e_k, c the centre of the spheres' extent; the
 * thesis' rule for the end spheres of the uniaxial test). Dashpot forces are
 * left out (quasi-static states).
 *
 * RVE stress, eq. 54: sigma = (1/V) sum_p V_p sigma_p over the spheres
 * flagged in mask (all when mask is NULL), V the RVE volume. */
#ifndef SBC_BPM_STRESS_H
#define SBC_BPM_STRESS_H

#include "sbc/bpm.h"

#ifdef __cplusplus
extern "C" {
#endif

/* sigma: 9 per sphere, row-major, Pa. */
sbc_status sbc_bpm_particle_stress(const sbc_bpm *e, double *sigma, sbc_error *err);

/* sigma[9], Pa. */
sbc_status sbc_bpm_rve_stress(const sbc_bpm *e, const unsigned char *mask, double volume, double sigma[9],
                              sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
