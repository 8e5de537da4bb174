/* servo_bc: FIRE (Bitzek et al. 2006, "Structural relaxation made simple",
 * PRL 97, 170201) as the quasi-static alternative to the local damping of
 * eq. 10 (keyword `damping fire`, docs/servo_bc.md).
 *
 * The host keeps its own time step (FIRE's step adaptation is left out: the
 * frame's travel and the controller count in host steps) and applies, each
 * step, after the forces and before the velocity update,
 *
 *   P = sum F.v + M.w over the interior (W)
 *   P > 0:  v <- (1 - a) v + a |v|/|F| F,  w <- (1 - a) w + a |w|/|M| M
 *           and, after N_min = 5 such steps in a row, a <- 0.99 a
 *   P <= 0: the interior stops, a <- a_start = 0.1
 *
 * "Stops" in the leapfrog sense: the velocities the step starts from are
 * half a step behind the forces (v^(n-1/2), F^n), and a packing at rest at
 * step n has v^(n-1/2) = -(dt/2) F^n/M, so that the step's kick leaves
 * v^(n+1/2) = (dt/2) F^n/M. Zeroing v^(n-1/2) instead makes the next step a
 * gradient step of dt^2/M, which is stable only below 1/sqrt(2) of the
 * integrator's own limit: on a square lattice (four contacts per disc) FIRE
 * then cycled for ever at 0.5 of the critical step 2 sqrt(M/(2 kn)).
 *
 * with |v|, |F| (|w|, |M|) the norms over all interior particles; no other
 * damping acts. Hosts that split the interior over ranks sum the five sums
 * below over ranks first; the mix is then the same on every rank. */
#ifndef SBC_FIRE_DAMPING_H
#define SBC_FIRE_DAMPING_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_fire_state {
    double alpha; /* FIRE's mixing factor a */
    long positive; /* steps in a row with P > 0 */
} sbc_fire_state;

/* The sums a host measures over its interior particles (F, M: the contact
 * forces and moments; v, w: the velocities the step starts from). */
enum {
    SBC_FIRE_POWER = 0, /* sum F.v + M w, W */
    SBC_FIRE_VV,        /* sum |v|^2, m^2/s^2 */
    SBC_FIRE_FF,        /* sum |F|^2, N^2 */
    SBC_FIRE_WW,        /* sum w^2, 1/s^2 */
    SBC_FIRE_MM,        /* sum M^2, (N m)^2 */
    SBC_FIRE_SUMS
};

/* The mix of one step, per interior particle of mass M and inertia I:
 *   v <- keep v + (push - stop dt/(2 M)) F,  w <- keep w + (spin - stop dt/(2 I)) M. */
typedef struct sbc_fire_mix {
    double keep, push, spin; /* -, m/(s N), 1/(s N m) */
    double stop;             /* 1 on the step that stops the interior, else 0 */
} sbc_fire_mix;

void sbc_fire_start(sbc_fire_state *s);

/* Advances the state by one step and returns that step's mix. */
sbc_fire_mix sbc_fire_step(sbc_fire_state *s, const double sums[SBC_FIRE_SUMS]);

#ifdef __cplusplus
}
#endif

#endif
