/* servo_bc: the per-step protocol of a host, once (docs/core.md, "The host
 * driver"). A host computes its contact forces, then calls sbc_driver_step,
 * which asks the host through callbacks (SUNDIALS-style, with user_data) for
 * what the controller needs on this step, in this order:
 *
 *   fire_sums  (damping fire)  FIRE's sums over the rank's interior, reduced (sum)
 *   interior                   damping (eq. 10, or FIRE's mix) on the rank's
 *                              interior; its Ek (reduced: sum) and largest
 *                              |net contact force| before damping (max)
 *   contacts   (when needed)   Ep, sum dn/Rbar, count, sum |f| (sum)
 *   net_force  (optional, after contacts) the largest |net contact force|
 *                              again, from this step's contact sums (max)
 *   frame      (when needed)   the frame's positions, reactions, moments and
 *                              rotations in frame order, sum |theta|, count (sum)
 *   confined   (on a converged increment, on failure, every SBC_CONFINE_EVERY
 *                              steps) confine.h against the frame's centres
 *   row        (converged)     the increment's row and its log line
 *   remap      (keyword remap x, while the frame travels to an increment's
 *                              first commands) the interior follows the
 *                              affine part of the frame's move; the next
 *                              step begins by taking back its velocity
 *
 * then steps the controller and returns its event; the host applies
 * sbc_controller_commands before its next step. Every rank of a parallel host
 * calls it with reduce set; all ranks take the same decisions. */
#ifndef SBC_DRIVER_H
#define SBC_DRIVER_H

#include <stddef.h>

#include "sbc/controller.h"
#include "sbc/fire_damping.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_reduce_op { SBC_REDUCE_SUM = 0, SBC_REDUCE_MAX } sbc_reduce_op;

/* The frame buffer of the frame callback, doubles at these offsets (Q: frame
 * particles, r = SBC_ROTATIONS(dim)): x [3Q] at 0, force [3Q] at 3Q, torque
 * [rQ] at SBC_DRIVER_TORQUE, theta [rQ] at SBC_DRIVER_THETA, then sum |theta|
 * and the particle count at SBC_DRIVER_SUMS (8Q + 2 doubles in 2D). */
#define SBC_DRIVER_TORQUE(dim, Q) (6 * (size_t)(Q))
#define SBC_DRIVER_THETA(dim, Q) ((6 + (size_t)SBC_ROTATIONS(dim)) * (size_t)(Q))
#define SBC_DRIVER_SUMS(dim, Q) ((6 + 2 * (size_t)SBC_ROTATIONS(dim)) * (size_t)(Q))
#define SBC_DRIVER_FRAME_SIZE(dim, Q) (SBC_DRIVER_SUMS(dim, Q) + 2)

typedef struct sbc_driver_callbacks {
    void *user_data;
    /* FIRE's sums (fire_damping.h) over this rank's interior particles into sums */
    void (*fire_sums)(void *user_data, double *sums);
    /* damping on this rank's interior (mix: FIRE's of this step, NULL: eq. 10
       or none, as the settings say); out[0] its Ek (eq. 12, the particles that
       carry a force), out[1] its largest |net contact force| before damping;
       again: the step is a revisit (a later run's setup), damp but count no
       rotation */
    void (*interior)(void *user_data, const sbc_fire_mix *mix, int again, double out[2]);
    /* this rank's contact sums: Ep (J), sum dn / Rbar, contact count, sum |contact force| (N) */
    void (*contacts)(void *user_data, double out[4]);
    /* this rank's share of the frame buffer (SBC_DRIVER_FRAME_SIZE, zeroed by the driver) */
    void (*frame)(void *user_data, double *buf);
    /* out = op over the ranks of in [n]; NULL for a single process */
    void (*reduce)(void *user_data, const double *in, double *out, int n, sbc_reduce_op op);
    /* confine.h over this rank's interior against the frame's centres fx [3Q]:
       SBC_OK, or the sbc_status of the refusal with the same message on
       every rank; NULL: not checked */
    int (*confined)(void *user_data, const double *fx, int increment, char *message, size_t cap);
    /* a converged increment: its row and log line (sbc_result_line); SBC_OK,
       or an sbc_status with the message (the run stops) */
    int (*row)(void *user_data, const sbc_result *row, const char *line, char *message, size_t cap);
    /* optional, for a host whose measure of the largest |net contact force|
       depends on the contact sums (YADE's unbalancedForce is relative to the
       mean contact force): this rank's, once the contact sums [4] of all
       ranks are known; it replaces interior's out[1]. NULL: interior's stands */
    double (*net_force)(void *user_data, const double *contacts);
    /* the user_data of row alone, for a host whose particle callbacks come
       from an engine (sbc_engine_callbacks, sbc_spheres_callbacks) while its
       rows are its own; NULL: user_data */
    void *row_data;
    /* keyword remap x (required with it), on this rank's interior
       particles, with u_i = (M - I)(x_i - origin) (sbc_remap_displacement;
       M [9] in 3 x 3 slots, origin [3] m) from the present centres:
       sign +1: each particle moves by u_i before the host's next contact
       forces and its velocity gains u_i / dt, so that the contact law's
       relative velocities see the move, as they see the frame's (a host
       whose step integrates after the driver, such as the embedded engines,
       moves x by u_i now; one that integrates x += dt v before its forces,
       such as LAMMPS, lets the velocity carry it); the host keeps what it
       added per particle. sign -1, at the start of every step but a
       revisit (M = I): the velocity added, if any, is taken back exactly and
       forgotten */
    void (*remap)(void *user_data, const double *M, const double *origin, int sign);
    /* keyword update newton (required with it under (P) and (T)): the
       frame's correction from the host's linearized contact network
       (controller.h, sbc_newton_fn), with newton_data (NULL: user_data) */
    sbc_newton_fn newton;
    void *newton_data;
    /* keyword interior newton (required with it): 1 when the host solves its
       interior's static equilibrium at each new position of the frame before
       its next contact forces (the embedded 2D runner and material point:
       host/statics.h); 0: the host relaxes the interior with its own dynamics */
    int solves_interior;
} sbc_driver_callbacks;

typedef struct sbc_driver sbc_driver;

/* A driver for the controller c (borrowed; it must outlive the driver) with
 * the settings it was created with. NULL with the message on failure. */
sbc_driver *sbc_driver_create(sbc_controller *c, const sbc_settings *s, const sbc_driver_callbacks *cb,
                              sbc_error *err);
void sbc_driver_free(sbc_driver *d);

/* One host step after its contact forces. again: the host revisits a step
 * already taken (the setup of a later run): damping only, returns
 * SBC_EVENT_RELAXING without stepping the controller. */
sbc_event sbc_driver_step(sbc_driver *d, int again, sbc_error *err);

/* The interior's share of the frame's move (sbc_controller_remap) through
 * the remap callback, when one is due. sbc_driver_step calls it after the
 * controller's step; a host that aims the controller itself
 * (sbc_controller_aim) calls it before its next step. */
void sbc_driver_remap(sbc_driver *d);

/* The frame buffer (SBC_DRIVER_FRAME_SIZE(dim, Q)) from a snapshot's frame
 * arrays and sums, for a host that measures into an sbc_snapshot. */
void sbc_driver_frame_from_snapshot(const sbc_snapshot *s, int dim, int Q, double *buf);

/* FIRE's state, for a host's restart file. */
sbc_fire_state *sbc_driver_fire(sbc_driver *d);

#ifdef __cplusplus
}
#endif

#endif
