/* servo_bc: the embedded 3D engine, frictional spheres with rotation.
 *
 * Explicit integration of eq. 9 in 3D (mass M = rho 4/3 pi R^3, sphere
 * inertia I = 2/5 M R^2): v += dt f / M, x += dt v, w += dt m / I, theta +=
 * dt w on the interior, with the local damping of eq. 10 per component or
 * FIRE's mix (fire_damping.h); the contact law of eq. 6 in 3D, the thesis'
 * contact springs (bpm_bond.h, sbc_broken_bond_increment): a normal spring kn
 * on the overlap, a tangential spring ks on the relative displacement of the
 * contact point, kept in the contact plane as the normal turns and capped at
 * mu kn dn (Coulomb); a cell list with a skin. Frame particles are kinematic:
 * each step they move to the controller's commands (positions and rotation
 * vectors). The engine is a host of the driver (driver.h) as LAMMPS is:
 *
 *   loop: sbc_spheres_forces -> sbc_driver_step -> sbc_spheres_move_frame
 */
#ifndef SBC_SPHERES_H
#define SBC_SPHERES_H

#include "sbc/contact.h"
#include "sbc/driver.h"
#include "sbc/frame.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_spheres_def {
    int n;               /* spheres */
    const double *x;     /* [3n] initial centres, m */
    const double *r;     /* [n] radii, m */
    double density;      /* kg/m^3 */
    sbc_frictional law;  /* kn, ks (0: frictionless), mu */
    double dt;           /* time step, s */
    double alpha, beta;  /* local damping of eq. 10 (0 = none) */
    int fire;            /* 1: FIRE's mix instead of eq. 10 on the interior (the frame's free
                            rotations keep eq. 10 with beta) */
    double skin;         /* neighbour-list skin, m; <= 0: a quarter of the smallest radius */
} sbc_spheres_def;

/* density 2.5e3 kg/m^3, the default law of contact.h, dt 1e-6 s, alpha =
 * beta = 0.7, eq. 10 */
sbc_spheres_def sbc_spheres_def_default(void);

typedef struct sbc_spheres sbc_spheres;

sbc_spheres *sbc_spheres_create(const sbc_spheres_def *def, sbc_error *err);
void sbc_spheres_free(sbc_spheres *e);

/* Makes the frame's particles kinematic (a 3D frame of these spheres; it
 * must outlive the engine). */
void sbc_spheres_set_frame(sbc_spheres *e, const sbc_frame *frame);

/* Keyword seal (seal.h): the triangles of the frame's surface become walls
 * for every sphere, their reactions added to the frame spheres' forces and
 * their energy to the contacts'. After sbc_spheres_set_frame. */
sbc_status sbc_spheres_seal(sbc_spheres *e, sbc_error *err);

/* The contact forces and moments at the present centres (the pair list
 * rebuilt when a sphere moved half the skin since its last build), and the
 * contact sums of relax.h. */
sbc_status sbc_spheres_forces(sbc_spheres *e, sbc_error *err);

/* The engine as a host of the driver: fire_sums, interior (which integrates
 * the interior), contacts, frame and confined, with the engine as user_data;
 * row is left to the caller (row_data). */
sbc_driver_callbacks sbc_spheres_callbacks(sbc_spheres *e);

/* Frame particles to the commanded targets within the step just taken
 * (velocity = (target - x) / dt; a free rotation (T) integrated with eq. 10's
 * beta). */
void sbc_spheres_move_frame(sbc_spheres *e, const sbc_commands *cmd);

/* Masses of the frame particles in frame order, [Q] kg. */
void sbc_spheres_frame_masses(const sbc_spheres *e, double *mass);

/* 2 sqrt(M_min / (2 kn)), s. */
double sbc_spheres_critical_dt(const sbc_spheres *e);

typedef struct sbc_spheres_view {
    int n;
    const double *x, *v, *r, *theta, *omega, *mass; /* [3n] centres, velocities, rotations, angular
                                                       velocities; [n] radii, masses */
    const double *f, *torque;                       /* [3n] contact loads of the last forces, N, N m */
    int pair_count, contact_count;
    double potential_energy; /* eq. 12 over the contacts, J */
    long step;
    long builds;             /* pair-list builds so far */
} sbc_spheres_view;

sbc_spheres_view sbc_spheres_get_view(const sbc_spheres *e);

/* Pair k of the list (0 .. pair_count - 1): its spheres ij [2] and its
 * tangential spring force on ij[0], fs [3] (N, in the contact plane), 0 for
 * an open pair. */
void sbc_spheres_pair(const sbc_spheres *e, int k, int ij[2], double fs[3]);

/* Every sphere put at x [3n] (m) with rotations theta [3n] (rad), at rest,
 * the pair list rebuilt there, and each contact's tangential spring from
 * records: count records of (i, j, fs_x, fs_y, fs_z), i < j (N, the spring's
 * force on i); the pairs not listed have none (the static solves of
 * interior newton, statics.h). */
sbc_status sbc_spheres_place(sbc_spheres *e, const double *x, const double *theta, const double *records, int count,
                             sbc_error *err);

/* The engine's state as doubles, as sbc_engine_save's (positions,
 * velocities, rotations, the last loads, the pair list with each contact's
 * spring, the step count): sbc_spheres_load reads it into an engine created
 * from the same packing and definition, every value checked. */
size_t sbc_spheres_state_size(const sbc_spheres *e);
void sbc_spheres_save(const sbc_spheres *e, double *out);
sbc_status sbc_spheres_load(sbc_spheres *e, const double *in, size_t n, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
