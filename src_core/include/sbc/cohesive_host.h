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

#include "sbc/contact.h"

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

/* The distributed path (fix servo_bc/bonds cohesive on MPI ranks): the host
 * keeps each pair's state with its atoms and calls these per pair, end A the
 * disc of smaller ID (the gathered path's order, so both give the same
 * pairs). A pair's state is SBC_COHESIVE_PAIR_STATE doubles: 1 while its bond
 * is intact (else 0), the tangential spring fs (N), the bond moment m on end
 * A (N m); all 0 for a pair the host need not keep. */
#define SBC_COHESIVE_PAIR_STATE 3

/* The candidate pairs among n discs (centres xy [2n] m, radii r [n] m):
 * those closer than ra + rb + reach (m), by the core's grid, as index pairs
 * (a < b) in *pairs (2 ints each; free with sbc_cohesive_host_pairs_free).
 * Returns the count, or -1 with the message in msg (cap bytes). */
long sbc_cohesive_host_pairs(int n, const double *xy, const double *r, double reach, int **pairs, char *msg,
                             size_t cap);
void sbc_cohesive_host_pairs_free(int *pairs);

/* A pair at the first run: writes its state, bonded when the discs touch
 * (gap |xb - xa| - ra - rb below 1e-6 rmin, rmin the smallest radius of the
 * discs, m; the gathered path's rule); returns 1 when bonded. */
int sbc_cohesive_pair_start(const double xa[2], double ra, const double xb[2], double rb, double rmin, double *state);

/* One host step dt (s) of count pairs under law (eqs. 6-8), the rank's
 * loop in one call: pair k joins the discs ends [2k] (end A) and ends
 * [2k + 1]; disc i's centre (m) is at x [stride i], its velocity (m/s) at
 * v [stride i], its spin about e3 (rad/s) at w [wstride i] (v and w NULL:
 * at rest, as at a run's set-up), its radius (m) r [i]. Advances each
 * pair's state [3 count] and writes its loads [6 count]: on end A (fx, fy
 * N, moment N m), then on end B; a pair that carries no load (apart and
 * unbonded) gets its state and loads all 0. sums [4] (may be NULL) gains the
 * pairs' share of sbc_cohesive_host_sums. Returns the pairs' intact bonds
 * after the step. */
long sbc_cohesive_pairs_step(const sbc_cohesive *law, long count, const int *ends, const double *x, const double *v,
                             int stride, const double *w, int wstride, const double *r, double dt, double *state,
                             double *loads, double sums[4]);

#ifdef __cplusplus
}
#endif

#endif
