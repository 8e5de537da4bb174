/* servo_bc: the servo-controlled aggregate as a material point of a finite
 * element model (FE^2, docs/fe2.md).
 *
 * A point is a packing on an embedded engine (2D discs or 3D spheres) under
 * (D), (P) or (T). An FE
 * code asks it for the first Piola stress P(F) of a deformation F (eq. 23 of
 * the frame's forces, eq. 15 holding F), starting from its last committed
 * state; it commits the state of a converged global iteration or reverts to
 * the committed one, and stores the committed state per integration point as
 * an array of doubles. The tangent C_ijkl = dP_ij / dF_kl at the current
 * state (the last converged integrate: a macro Newton's consistent tangent)
 * by perturbation solves from the committed state, affine, or condensed. Like Box2D's b2WorldDef: a definition
 * with its defaults, then create.
 *
 *   sbc_point_def d = sbc_point_def_default();
 *   d.n = n; d.x = xy; d.r = r; d.words = "P accuracy balanced";
 *   sbc_point *p = sbc_point_create(&d, &err);       relaxed at F = I, committed
 *   if (sbc_point_integrate(p, F, P, &ratio, &err) == SBC_POINT_CONVERGED)
 *       sbc_point_commit(p);                          else: cut the step by ratio
 *
 * A mixed frame is taken when its faces are D or P (every component of F
 * given; docs/fe2.md, "Mixed points"). */
#ifndef SBC_MATERIAL_POINT_H
#define SBC_MATERIAL_POINT_H

#include <stddef.h>

#include "sbc/contact.h"
#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_point_def {
    int dim;            /* 2 (discs) or 3 (spheres) */
    int n;              /* particles */
    const double *x;    /* [dim n] centres, m (the frame is detected as the runner's is, in 3D by
                           sbc_frame_detect_3d: lattice faces or a geometrically periodic packing) */
    const double *r;    /* [n] radii, m */
    const double *box;  /* 2D: NULL, or [4] xlo xhi ylo yhi of a geometrically periodic packing's
                           square (m): its frame is the discs crossing the square's edges (packing.h) */
    const char *words;  /* servo_bc words: the BC (D, P or T) and its keywords (accuracy, ...);
                           F, increments, stress and file are the point's and refused; mixed takes D and P
                           faces (a T component needs a stress) */
    sbc_frictional law; /* eq. 6 */
    double density;     /* kg/m^2 in 2D, kg/m^3 in 3D */
    double dt;          /* time step, s */
    const sbc_cohesive *bonds; /* 2D: NULL, or cohesive bonds (eqs. 7-8) between the discs touching at creation
                                  (gap below 1e-6 of the smallest radius, as the runner's 'contact cohesive');
                                  their state is the point's (and the law's kn, ks, mu replace law's, for
                                  broken bonds and new contacts). The affine tangent sums eq. 6 only and
                                  refuses a bonded point; the condensed and perturbation tangents take it */
} sbc_point_def;

/* dim 2, no packing, words "D", the contact law's default, density 2e3
 * kg/m^2, dt 1e-6 s (the embedded engine's defaults). */
sbc_point_def sbc_point_def_default(void);

typedef struct sbc_point sbc_point;

/* The error contract of the functions below: err must not be NULL; a NULL
 * point is refused (SBC_ERR_INPUT or SBC_POINT_FAILED, with the message in
 * err; without err: nothing done, 0 returned, the outputs zeroed), never
 * followed. Arrays are read and written at the sizes each function states;
 * a caller whose arrays are shorter (a binding from another language) checks
 * their lengths first, as the Python module's MaterialPoint does. */

/* Builds the engine, the frame and the controller, relaxes the packing at
 * F = I and commits that state (certified or not: sbc_point_certified).
 * NULL with the message in err. */
sbc_point *sbc_point_create(const sbc_point_def *def, sbc_error *err);
void sbc_point_free(sbc_point *p);

typedef enum sbc_point_status {
    SBC_POINT_CONVERGED = 0, /* the increment converged and its state is certified at the words' accuracy */
    SBC_POINT_FAILED,        /* the controller stopped (message in err); the point is back at its committed state */
    SBC_POINT_UNCERTIFIED    /* the increment converged, but its state cannot be certified at the words' accuracy
                                (the reason in err, as the runner would stop with it): P stands and the state may be
                                committed; step ratio 0.5 suggests a smaller step that may certify */
} sbc_point_status;

/* One increment from the committed state to F (3 x 3 slots, the dim x dim
 * block read): P (3 x 3 slots, N/m in 2D, N/m^2 in 3D) and a suggested step ratio (1
 * when converged; 0.5 when failed or uncertified: retry with a step that much smaller).
 * Never aborts. The point then holds the new state until commit or revert;
 * a second integrate starts from the committed state again. */
sbc_point_status sbc_point_integrate(sbc_point *p, const double F[9], double P[9], double *step_ratio,
                                     sbc_error *err);

/* 1 when the current state (the last converged integrate since commit or
 * revert, else the committed one; the creation's at first) is certified at
 * the words' accuracy, 0 when it was accepted uncertified. */
int sbc_point_certified(const sbc_point *p);

/* The state of the last converged integrate becomes the committed one.
 * SBC_OK, or SBC_ERR_NOMEM (the committed state as it was): the state's
 * size follows the engine's pair list (sbc_point_state_size). */
sbc_status sbc_point_commit(sbc_point *p);

/* Back to the committed state. */
void sbc_point_revert(sbc_point *p);

/* The committed F and P (3 x 3 slots). */
void sbc_point_committed(const sbc_point *p, double F[9], double P[9]);

/* The committed state as doubles (engine, controller, FIRE, F, P), for an
 * FE code to store per integration point: sbc_point_state_size counts them
 * (it changes with the contacts the committed state has),
 * sbc_point_save writes them, sbc_point_load makes them the committed and
 * current state of a point created from the same definition (in another
 * process too: it continues bit for bit). */
size_t sbc_point_state_size(const sbc_point *p);
void sbc_point_save(const sbc_point *p, double *out);
sbc_status sbc_point_load(sbc_point *p, const double *in, size_t n, sbc_error *err);

/* C_ijkl = dP_ij / dF_kl at the current F (of the last converged integrate
 * since commit or revert, else the committed F) by central differences of
 * step h on each F_kl: 2 dim^2 integrates from the committed state, the
 * derivative of the map F -> P that integrate is (the consistent tangent of
 * a macro Newton iteration); the point is back at its current state
 * afterwards, bit for bit. C [81], C[9 (3i + j) + 3k + l], the components
 * beyond dim 0. Fails with the message of the first perturbation that does
 * not converge (C then 0). */
sbc_status sbc_point_tangent_perturbation(sbc_point *p, double h, double C[81], sbc_error *err);
#define SBC_POINT_H_SMALLEST 1e-12 /* the perturbation steps h accepted */
#define SBC_POINT_H_LARGEST 0.1

/* Many points at once (the integration points of a mesh): points[k] to F
 * [9k .. 9k + 8], into P [9k ..], status [k] (sbc_point_status) and ratio
 * [k], on `threads` threads (C11 threads; <= 1: in the calling thread). A
 * point is integrated by one thread, so every result is that of
 * sbc_point_integrate on it alone, bit for bit, whatever the thread count.
 * SBC_OK when every point converged certified, else the status and message
 * of the first that failed or was not certified ("point 7: ..."); the
 * others' results stand. */
sbc_status sbc_points_integrate(sbc_point *const *points, int count, const double *F, double *P, int *status,
                                double *ratio, int threads, sbc_error *err);

/* The affine (Voigt) tangent at the current state: every particle
 * follows F, each contact c (reference branch L = F^-1 l of its current
 * branch l from a to b, unit normal n, overlap dn) stiffens by
 *   K = -kn n (x) n + (kn dn / |l|) (I - n (x) n) - ks (I - n (x) n)
 * (the normal spring, its force turning with the branch, the tangential
 * spring of a contact that sticks; a sliding one has none), and with
 * P = -(1/V) sum_c f_c (x) L_c (eq. 23 over the contacts, f_c the force on b)
 *   C_ijkl = -(1/V) sum_c K_ik L_l L_j.
 * Rotations and the relaxation of the interior are left out: stiffer than
 * the aggregate, exact where it deforms affinely (a lattice under (D)).
 * Same layout as sbc_point_tangent_perturbation. */
sbc_status sbc_point_tangent_affine(sbc_point *p, double C[81], sbc_error *err);

/* The condensed tangent at the current state: the contact network's
 * stiffness (normal springs, the tangential springs of sticking contacts,
 * the slip law of sliding ones, the terms of the forces turning with their
 * contacts) with the interior condensed out and the frame's kinematics of
 * the point's condition applied: (D) the frame follows F, (P) its periodic
 * pairs share a fluctuation and a rotation and their forces balance, (T)
 * its forces are P A_q under eq. 15 (docs/fe2.md). 2D and 3D. Solved by
 * a sparse direct solver (UMFPACK) where the core is built with it (memory
 * about linear in the particles: 10^5 discs in 6 s and 1.5 GB), densely
 * otherwise (memory as the square of the degrees of freedom, 3 per disc and
 * 6 per sphere: a few thousand discs at most). *mechanisms (may be NULL):
 * the degrees of freedom that carry no stiffness (rattlers, rotations of
 * discs whose contacts all slide), set to zero; the dense solve also counts
 * the pivots it cannot take (the gear mode of a square lattice's free
 * rotations under (T)). In 2D the tangential springs of sticking contacts
 * are differentiated along the increment from the committed state (the
 * straight path of each branch), so that C is the derivative of integrate's
 * P with respect to F, the consistent tangent a macro Newton needs for its
 * quadratic rate (docs/fe2.md, "The consistent tangent"); right after a
 * commit, and in 3D, it is the state's. Same layout as the others. */
sbc_status sbc_point_tangent_condensed(sbc_point *p, double C[81], int *mechanisms, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
