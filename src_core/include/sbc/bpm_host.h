/* servo_bc: the 3D bond models (bpm.h, bpm_bond.h) for a host that
 * integrates the spheres itself and reaches C through a foreign-function
 * interface (YADE's Python via ctypes): plain types only.
 *
 * The host keeps positions, velocities and the integration; the core keeps
 * the bonds and their state. Per host step, after the host's forces are
 * reset and before its integrator: sbc_bpm_host_loads with the spheres'
 * centres and their velocities of the step (v(t - dt/2) in a leapfrog
 * scheme), then add the loads to the spheres. The bond loop runs in C. */
#ifndef SBC_BPM_HOST_H
#define SBC_BPM_HOST_H

#include <stddef.h>

#include "sbc/bpm.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bonds between every pair of the n spheres (centres x [3n], radii r [n],
 * masses m [n]: m, kg) that touch (gap <= 1e-9 of the radii's sum), with
 * model "beam" (Timoshenko beams, E_b = E Pa, nu_b = nu) or "parallel"
 * (parallel bonds, k^n = E / 2 r_p with r_p the smallest radius, k^s =
 * k^n / 4.2: thesis Table 3); bond radius alpha r_min (eq. 9).
 * strength: NULL for bonds that never fail, or [5] = tension F_t,u (N, > 0),
 * shear F_s,u (N), bending M_b,u (N m), twisting M_t,u (N m) (>= 0; 0 leaves
 * the term out) and the friction coefficient mu of a broken bond's contact
 * (bpm_bond.h, sbc_bond_strength). Returns NULL with the message in msg (cap
 * bytes) on bad input or when no pair touches. */
sbc_bpm *sbc_bpm_host_create(const char *model, double E, double nu, double alpha, const double *strength, int n,
                             const double *x, const double *r, const double *m, char *msg, size_t cap);

/* Bonds formed; bonds intact (formed less broken). */
int sbc_bpm_host_bond_count(const sbc_bpm *e);
int sbc_bpm_host_intact(const sbc_bpm *e);

/* One host step of length dt (s): the bonds' loads at centres x [3n] (m)
 * from velocities v [3n] (m/s) and angular velocities w [3n] (rad/s) into
 * load [6n] (force N, moment N m per sphere; overwritten). Returns 0, or 1
 * for a non-finite load. */
int sbc_bpm_host_loads(sbc_bpm *e, const double *x, const double *v, const double *w, double dt, double *load);

/* The bonds' strain energy (eq. 50 or the beams' 1/2 u K u, with the
 * elastic energy of broken bonds' contacts), J. */
double sbc_bpm_host_strain_energy(const sbc_bpm *e);

/* Eq. 51's share of the bonds: the energy broken bonds held when they broke
 * and the work of friction in their contacts, J (0 without failure). */
double sbc_bpm_host_dissipated(const sbc_bpm *e);

/* Restart of what is not per bond: the energy the broken bonds held (J). */
double sbc_bpm_host_fracture_energy(const sbc_bpm *e);
void sbc_bpm_host_set_fracture_energy(sbc_bpm *e, double w);

/* Restart: one bond's state as doubles (28 for a beam: its frame, stiffness
 * terms, end loads and energy; 13 for a parallel bond; with a strength 8
 * more: broken or not, and the broken bond's contact), read out of (get)
 * or written into (set) bond k, 0 <= k < sbc_bpm_host_bond_count. Bonds are
 * numbered as sbc_bpm_host_create formed them: created again from the same
 * centres, radii and masses, they come back in the same order. */
int sbc_bpm_host_state_doubles(const sbc_bpm *e);
void sbc_bpm_host_state_get(const sbc_bpm *e, int k, double *state);
void sbc_bpm_host_state_set(sbc_bpm *e, int k, const double *state);

#ifdef __cplusplus
}
#endif

#endif
