/* servo_bc: the embedded reference engine (2D discs).
 *
 * Explicit integration of eq. 9 (mass M = rho pi R^2, disc inertia
 * I = M R^2 / 2), local non-viscous damping of eq. 10 on interior particles,
 * frictional contacts of eq. 6, optional cohesive bonds of eqs. 7-8 between
 * the pairs touching at the start, cell-list neighbour search. Frame particles
 * are kinematic: each step they move to the controller's targets. The engine
 * drives the controller exactly as an external host does:
 *
 *   loop: sbc_engine_step -> sbc_engine_snapshot -> sbc_controller_step
 *         -> sbc_engine_move_frame(commands)
 */
#ifndef SBC_ENGINE_H
#define SBC_ENGINE_H

#include "sbc/contact.h"
#include "sbc/controller.h"
#include "sbc/driver.h"
#include "sbc/fire_damping.h"
#include "sbc/frame.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_engine_def {
    int n;               /* particles */
    const double *x;     /* [2n] initial centres, m */
    const double *r;     /* [n] radii, m */
    double density;      /* mass per area, kg/m^2 */
    sbc_frictional law;  /* contact law, eq. 6 */
    const sbc_cohesive *bonds; /* NULL: no bonds. Otherwise every pair whose gap is below
                                  1e-6 R_min at creation is bonded (eqs. 7-8), and `law` is
                                  replaced by (kn, ks, mu) of the bond law, which broken bonds
                                  and new contacts follow (eq. 6). Copied at creation. */
    double dt;           /* time step, s */
    double alpha, beta;  /* local damping of eq. 10 (0 = none) */
    int fire;            /* 1: FIRE's velocity mix (fire_damping.h) instead of eq. 10 */
    double skin;         /* neighbour-list skin, m; <= 0: a quarter of the smallest radius */
} sbc_engine_def;

/* Paper values: density 2e3 kg/m^2, Table 4 law, dt 1e-6 s, alpha = beta = 0.7. */
sbc_engine_def sbc_engine_def_default(void);

typedef struct sbc_engine sbc_engine;

sbc_engine *sbc_engine_create(const sbc_engine_def *def, sbc_error *err);
void sbc_engine_free(sbc_engine *e);

/* Makes the frame's particles kinematic (driven by commands); may be NULL
 * for a free packing. The frame must outlive the engine. */
void sbc_engine_set_frame(sbc_engine *e, const sbc_frame *frame);

/* Switches the frame's seal on (seal.h: the edges of the polygon of the
 * frame's centres are frictionless walls for the interior, kn of the contact
 * law). After sbc_engine_set_frame, which switches it off again. */
sbc_status sbc_engine_seal(sbc_engine *e, sbc_error *err);

/* One time step: contact forces, moments and energies at the current
 * positions, and the interior particles advanced by the equations of motion
 * with damping. Frame particles keep their place (see sbc_engine_move_frame). */
sbc_status sbc_engine_step(sbc_engine *e, sbc_error *err);

/* sbc_engine_step in the host driver's parts (driver.h): the contact forces
 * at x^n (and the seal's); FIRE's sums of the interior; the interior to
 * x^(n+1) with FIRE's mix of this step, or with eq. 10 (or nothing) for mix
 * NULL. */
sbc_status sbc_engine_forces(sbc_engine *e, sbc_error *err);
void sbc_engine_fire_sums(const sbc_engine *e, double *sums);
void sbc_engine_integrate(sbc_engine *e, const sbc_fire_mix *mix);

/* Fills a snapshot from the last sbc_engine_step: frame positions and
 * reactions before the frame moves, Ek after the interior moved (arrays
 * owned by the engine). */
void sbc_engine_snapshot(sbc_engine *e, sbc_snapshot *snap);

/* The engine as a host of the driver (driver.h): fire_sums, interior (which
 * integrates and takes the step's snapshot), contacts, frame and confined
 * (confine.h on every particle the frame does not move; a non-finite
 * position anywhere is named first), with the engine as user_data; row is
 * left to the caller (row_data). After sbc_engine_set_frame. */
sbc_driver_callbacks sbc_engine_callbacks(sbc_engine *e);

/* Moves the frame particles to the commanded targets within the step just
 * taken (cmd NULL: the frame stays where it is). */
void sbc_engine_move_frame(sbc_engine *e, const sbc_commands *cmd);

/* Read access for output writers. */
typedef struct sbc_engine_view {
    int n;
    const double *x, *v, *r, *theta, *omega, *mass;
    const double *f, *torque; /* contact forces (N) and moments (N m) of the last sbc_engine_step */
    const unsigned char *kinematic;
    int pair_count;
    const int *pair_i, *pair_j;
    const unsigned char *pair_bond; /* [pair_count] 1 = intact bond; NULL in a scene without bonds */
    const double *pair_fs;          /* [pair_count] tangential spring force, N; NULL without friction */
    const double *pair_m;           /* [pair_count] an intact bond's moment on pair_i (eqs. 7-8), N m; NULL without
                                       bonds */
    int bond_count, bonds_initial;  /* intact bonds now and at creation */
    sbc_frictional law;
    long step;
    double time; /* s */
} sbc_engine_view;

sbc_engine_view sbc_engine_get_view(const sbc_engine *e);

/* Masses of the frame particles in frame order, [Q] kg (for the controller). */
void sbc_engine_frame_masses(const sbc_engine *e, double *mass);

/* The host path (cohesive_host.h): a host that integrates the discs itself
 * hands its centres x [2n] (m), the velocities of the step just taken v [2n]
 * (m/s) and omega [n] (rad/s, v(t - dt/2) in a leapfrog scheme) and its time
 * step dt (s); the engine runs its pair loop (eq. 6, eqs. 7-8) at those
 * positions, rebuilding the pair list when a disc has moved half the skin.
 * The loads are then in sbc_engine_get_view (f, torque), the sums of relax.h
 * in sbc_engine_snapshot. Nothing is integrated. */
sbc_status sbc_engine_host_loads(sbc_engine *e, const double *x, const double *v, const double *omega, double dt,
                                 sbc_error *err);

/* Restart of the pair state: one record of SBC_PAIR_RECORD doubles
 * (i, j, intact bond 0/1, tangential spring fs N, bond moment m N m) per pair
 * that carries state. sbc_engine_pair_records writes them into out (NULL:
 * only counts) and returns their number; sbc_engine_set_pair_records clears
 * every pair's state and puts the records back into a list built at the
 * present centres (bonds_initial: the count at creation). */
#define SBC_PAIR_RECORD 5
int sbc_engine_pair_records(const sbc_engine *e, double *out);
sbc_status sbc_engine_set_pair_records(sbc_engine *e, const double *rec, int count, int bonds_initial,
                                       sbc_error *err);

/* interior newton (host/statics.h): every particle put at x [2n] (m) and
 * theta [n] (rad), at rest (velocities and spins zero), followed by
 * sbc_engine_set_pair_records with the contacts' springs of that state. */
void sbc_engine_place(sbc_engine *e, const double *x, const double *theta);

/* Critical time step estimate 2 sqrt(M_min / (2 kn)) (s): the period limit
 * of the stiffest particle-contact oscillator; with bonds also
 * 2 sqrt(I_min / (2 kr)) for the bending spring, whichever is smaller. */
double sbc_engine_critical_dt(const sbc_engine *e);

/* The engine's state (positions, velocities, rotations, the last forces,
 * the pair list with its contact and bond history, the step count) as
 * doubles, for a material point's commit and revert and its saved bytes:
 * sbc_engine_state_size counts them, sbc_engine_save writes them,
 * sbc_engine_load reads them into an engine created from the same packing
 * and definition (every value checked; the run then continues bit for bit). */
size_t sbc_engine_state_size(const sbc_engine *e);
void sbc_engine_save(const sbc_engine *e, double *out);
sbc_status sbc_engine_load(sbc_engine *e, const double *in, size_t n, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
