/* servo_bc: the paper's 2D contact laws with cohesive bonds (contact.h,
 * eqs. 6-8) for a host that integrates the discs itself (LAMMPS and LIGGGHTS
 * through fix servo_bc/bonds cohesive, YADE through servo_bc.Cohesive), in
 * plain types for a foreign-function interface.
 *
 * The core runs every contact between the host's discs, bonded and
 * frictional, with the embedded engine's pair loop, its pair list and its
 * per-pair state (tangential spring, bond moment, intact flag): two
 * particles touching at creation are bonded; a bond that meets eq. 8 breaks
 * for good and the pair goes on by eq. 6 with the bond's kn, ks and mu. The
 * host's own contact law must leave these discs alone.
 *
 * Per host step, after the host's forces are reset and before anything
 * reads them: sbc_cohesive_host_loads with the discs' centres and the
 * velocities of the step (v(t - dt/2) in a leapfrog scheme, the half-step
 * velocity of velocity Verlet), then add the loads. */
#ifndef SBC_COHESIVE_HOST_H
#define SBC_COHESIVE_HOST_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_cohesive_host sbc_cohesive_host;

/* words: "kn KN ks KS kr KR fn FN fs FS mr MR mu MU" (N/m, N/m, N m/rad, N,
 * N, N m, -; the runner's `contact cohesive` words). n discs with centres
 * xy [2n] (m) and radii r [n] (m). Returns NULL with the message in msg (cap
 * bytes) on bad words or discs, or when no two discs touch. */
sbc_cohesive_host *sbc_cohesive_host_create(const char *words, int n, const double *xy, const double *r, char *msg,
                                            size_t cap);
void sbc_cohesive_host_free(sbc_cohesive_host *h);

/* The law's normal stiffness kn (N/m): the contact stiffness the servo's
 * gains scale with (sbc_controller_create). */
double sbc_cohesive_host_kn(const sbc_cohesive_host *h);

/* Intact bonds now, and at creation. */
int sbc_cohesive_host_bond_count(const sbc_cohesive_host *h);
int sbc_cohesive_host_bonds_initial(const sbc_cohesive_host *h);

/* One host step of length dt (s): the contacts' loads at centres xy [2n] (m)
 * from velocities v [2n] (m/s) and angular velocities w [n] (rad/s) into
 * load [3n] (fx, fy N, moment about e3 N m per disc; overwritten). Returns 0;
 * 1 with the message in sbc_cohesive_host_message when a centre or load is
 * not finite. */
int sbc_cohesive_host_loads(sbc_cohesive_host *h, const double *xy, const double *v, const double *w, double dt,
                            double *load);
const char *sbc_cohesive_host_message(const sbc_cohesive_host *h);

/* The sums of the last loads (relax.h): sums [4] = Ep (eq. 12 with the bond
 * terms, J), sum dn / Rbar (eq. 39), the contact count, sum |contact force|
 * (N). */
void sbc_cohesive_host_sums(const sbc_cohesive_host *h, double *sums);

/* Restart: the state of every pair that carries one, as doubles. size: how
 * many; get writes them into state [size]; set puts them back into a host
 * created again from the present centres (which bonds anew; set replaces
 * that). Returns 0, or 1 with the message in sbc_cohesive_host_message. */
size_t sbc_cohesive_host_state_size(const sbc_cohesive_host *h);
void sbc_cohesive_host_state_get(const sbc_cohesive_host *h, double *state);
int sbc_cohesive_host_state_set(sbc_cohesive_host *h, const double *state, size_t size);

#ifdef __cplusplus
}
#endif

#endif
