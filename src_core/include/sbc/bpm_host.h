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

/* ---- Bonds kept with their spheres --------------------------------------
 * A host on many ranks (LAMMPS, LIGGGHTS) keeps each bond's state in
 * per-atom slots that migrate with its atoms, both spheres holding a copy,
 * and computes a bond from its two spheres, one of which may be a ghost.
 * A state is sbc_bpm_host_state_doubles(law) doubles, the layout of
 * sbc_bpm_host_state_get; A is the sphere with the smaller atom ID, so both
 * owners advance their copies alike and agree when a bond breaks. */

/* The law without spheres: as sbc_bpm_host_create, with r_min (m) the
 * smallest radius of the bonded spheres over every rank (a parallel bond's
 * k^n = E / 2 r_min). NULL with the message in msg on bad input. */
sbc_bpm *sbc_bpm_host_law(const char *model, double E, double nu, double alpha, const double *strength, double rmin,
                          char *msg, size_t cap);

/* Every touching pair i < j of the n spheres (centres x [3n], radii r [n]):
 * returns the count and the pairs in *pairs (2 ints each, free with
 * sbc_bpm_host_pairs_free), or -1 with the message in msg. */
long sbc_bpm_host_pairs(const sbc_bpm *law, int n, const double *x, const double *r, int **pairs, char *msg,
                        size_t cap);
void sbc_bpm_host_pairs_free(int *pairs);

/* A new bond between A (centre xa, radius ra) and B into state. */
void sbc_bpm_host_bond_start(const sbc_bpm *law, const double xa[3], double ra, const double xb[3], double rb,
                             double *state);

/* One host step of one bond (sbc_bpm_host_loads' law for one bond): adds
 * its force and moment on A to load_a [6] and on B to load_b [6] (N, N m).
 * Returns 1 when the bond broke at this step, with the strain energy it
 * held in *fracture (J), else 0. */
int sbc_bpm_host_bond_step(const sbc_bpm *law, double *state, const double xa[3], double ra, const double va[3],
                           const double wa[3], const double xb[3], double rb, const double vb[3], const double wb[3],
                           double dt, double load_a[6], double load_b[6], double *fracture);

/* A bond whose partner is out of the host's reach (beyond its ghost
 * cutoff, so farther than any contact): a broken bond's contact is apart
 * (no load, its spring reset as sbc_broken_bond_increment does); returns 0,
 * or 1 when the bond is intact (an intact bond cannot be out of reach). */
int sbc_bpm_host_bond_apart(const sbc_bpm *law, double *state);

/* The bond's axial stiffness (N/m, for eq. 48: 0.22 sqrt(m_min / k_max)),
 * whether it is broken, and its energies (sbc_bpm_bond_energies, J; xb NULL
 * for a partner out of reach, as sbc_bpm_host_bond_apart). */
double sbc_bpm_host_bond_stiffness(const sbc_bpm *law, const double *state);
int sbc_bpm_host_bond_broken(const sbc_bpm *law, const double *state);
void sbc_bpm_host_bond_energies(const sbc_bpm *law, const double *state, const double xa[3], double ra,
                                const double xb[3], double rb, double *strain, double *friction);

#ifdef __cplusplus
}
#endif

#endif
