/* servo_bc: the host-agnostic controller (paper Sect. 3, Table 1).
 *
 * A host calls sbc_controller_step once per time step with a frame snapshot
 * (positions, rotations and contact reactions of the frame particles, the
 * interior's energies) and applies the frame commands it then reads from
 * sbc_controller_commands before its next step: frame particles are moved
 * to the target positions and rotations within that one step (velocity =
 * (target - current)/dt), interior particles are integrated by the host.
 *
 * Every rank of a parallel host runs the controller on identical, reduced
 * snapshots and therefore takes identical decisions. */
#ifndef SBC_CONTROLLER_H
#define SBC_CONTROLLER_H

#include "sbc/frame.h"
#include "sbc/relax.h"
#include "sbc/settings.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_event {
    SBC_EVENT_RELAXING = 0, /* keep stepping with the same commands */
    SBC_EVENT_CORRECTED,    /* new commands within the increment (servo correction) */
    SBC_EVENT_INCREMENT,    /* increment accepted: a result is ready; new commands */
    SBC_EVENT_FINISHED,     /* last increment accepted: a result is ready; stop */
    SBC_EVENT_FAILED        /* diverged or invalid state: stop, see the error */
} sbc_event;

/* What a host measures each step. Per-frame arrays are in frame order. */
typedef struct sbc_snapshot {
    const double *x;         /* [3Q] frame centre positions, m (3 slots whatever the dimension, tensor.h) */
    const double *theta;     /* [rQ] frame rotations, rad (r = SBC_ROTATIONS(dim): the angle about e3
                                in 2D, the rotation vector, the time integral of the angular
                                velocity, in 3D) */
    const double *force;     /* [3Q] resultant contact force on each frame particle, N */
    const double *torque;    /* [rQ] resultant contact moment on each frame particle, N m */
    double kinetic_energy;   /* Ek of the interior particles that carry a force, eq. 12, J */
    double unbalanced_max;   /* largest |net force| (contact forces only, before damping) on an
                                interior particle, N */
    double potential_energy; /* Ep of all contacts, eq. 12, J (the contact sums: measured together) */
    double contact_force_sum; /* sum over contacts of |contact force| (normal and tangential), N */
    double overlap_sum;      /* sum over contacts of dn_c / Rbar_c (eq. 39), - */
    long contact_count;      /* N_c, contacts with dn > 0 */
    double rotation_sum;     /* sum over particles of |theta_i| (eq. 41), rad */
    long particle_count;     /* P + Q */
} sbc_snapshot;

/* What the host applies to the frame before its next step. */
typedef struct sbc_commands {
    const double *x;                    /* [3Q] target positions, m */
    const double *theta;                /* [rQ] target rotations, rad (as sbc_snapshot's) */
    const unsigned char *free_rotation; /* [Q] 1: the host integrates this rotation freely */
} sbc_commands;

/* One converged increment: the CSV row (results.h), with the accuracy measures. */
typedef struct sbc_result {
    int dim;              /* the frame's dimension: which columns the row has (columns.h) */
    int increment;
    double F[9];          /* eq. 15, -; tensors in 3 x 3 slots (tensor.h) */
    double P[9];          /* eq. 23, N/m */
    double sigma[9];      /* eq. 31, N/m */
    double overlap_mean;  /* eq. 39, - */
    double rotation_mean; /* eq. 41, rad */
    int iterations;       /* servo iterations (0 for D) */
    long relax_steps;     /* host steps spent on this increment */
    double r_force, r_moment, r_deformation; /* final residual norms (0 for D) */
    double hill_mandel;   /* eq. 30 relative to sbc_homogenize_work_scale */
    double unbalanced;    /* max |net force| / mean |contact force| of the interior when accepted (relax.h) */
    double frame_residual; /* frame force residual relative to the frame's forces (servo.h), 0 for D */
    long newton_iterations; /* interior newton: Newton iterations of the increment's static solves (the host
                               fills it; the controller leaves 0) */
    long newton_held;       /* interior newton: degrees of freedom held for want of stiffness (rattlers, free
                               rotations) at the increment's last solve (the host fills it; 0 otherwise) */
} sbc_result;

typedef struct sbc_controller sbc_controller;

/* Creates a controller for a frame (which must outlive it). mass is [Q]
 * frame-particle masses in kg and dt the host's time step in s (both enter
 * the servo gains of eq. 37); kn (N/m) the normal stiffness of the host's
 * contact law, which sets the frame's travel speed (motion.h), the first
 * secant correction and the round-off floor of the force criterion; 0 when
 * unknown (the frame then jumps, as in the paper). Returns NULL and sets err
 * on failure. */
sbc_controller *sbc_controller_create(const sbc_frame *frame, const sbc_settings *settings,
                                      const double *mass, double dt, double kn, sbc_error *err);
void sbc_controller_free(sbc_controller *c);

/* Frame commands in force now (valid until the next step call). */
sbc_commands sbc_controller_commands(const sbc_controller *c);

/* Advances the state machine by one host step. On SBC_EVENT_FAILED, err
 * holds a message naming the BC, the increment, the step or iteration and
 * the offending value. */
sbc_event sbc_controller_step(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err);

/* What sbc_controller_step will read of this step's snapshot, for hosts
 * that measure lazily (a contact pass and an MPI reduction saved on most
 * steps). Call with the interior's measures (kinetic_energy, unbalanced_max)
 * and potential_energy = SBC_RELAX_EP_UNMEASURED (relax.h);
 * if the answer has SBC_NEED_CONTACTS, measure the contact sums
 * (potential_energy, contact_force_sum, contact_count, overlap_sum) and call
 * again with them. SBC_NEED_FRAME: the relaxation ends on this step, so pass
 * the frame arrays and rotation_sum, particle_count. What is not needed may
 * be left NULL (frame arrays) or unmeasured; the decisions are those of a
 * fully measured snapshot. While the frame travels to new commands
 * (motion.h) nothing is needed. */
enum { SBC_NEED_CONTACTS = 1u, SBC_NEED_FRAME = 2u };
unsigned sbc_controller_needs(const sbc_controller *c, const sbc_snapshot *snap);

/* The result of the last accepted increment. */
const sbc_result *sbc_controller_result(const sbc_controller *c);

/* Progress within the current increment: servo iterations so far and the
 * last residual norms (zero before the first check and for D). */
void sbc_controller_progress(const sbc_controller *c, int *iteration, double *r_force, double *r_moment,
                             double *r_deformation);

/* Restart support: the controller's whole state as a flat array of doubles.
 * sbc_controller_load accepts a state saved for the same frame size and the
 * same loading path (BC, F, increments); it fails with SBC_ERR_INPUT naming
 * the setting that contradicts the saved one. Gains, tolerances and the
 * relaxation settings may differ: the new ones apply from the restart on. */
size_t sbc_controller_state_size(const sbc_controller *c);
void sbc_controller_save(const sbc_controller *c, double *out);
sbc_status sbc_controller_load(sbc_controller *c, const double *in, size_t n, sbc_error *err);

/* Seconds of wall time between two progress lines of a long increment, in
 * every host. */
#define SBC_PROGRESS_EVERY 10.0

/* The progress line of the increment under way (no newline): "increment 3:
 * servo iteration 120, residuals force 1.234e-02 moment 0.000e+00
 * deformation 2.1e-15, step 45000, elapsed 30 s"; step: the host's steps so
 * far, elapsed: seconds since the run started. Every host prints it with its
 * own prefix. */
void sbc_controller_progress_line(const sbc_controller *c, long step, double elapsed, char *out, size_t cap);

/* Macroscopic F imposed at increment i: I + (i / i_tot) (F_final - I). */
void sbc_controller_target_F(const sbc_controller *c, int increment, double F[9]);

/* The reference frame the controller works with: a copy of the host's frame,
 * whose X, A and V a mixed BC renews after its stress stage (Sect. 5.1). */
const sbc_frame *sbc_controller_frame(const sbc_controller *c);

/* A material point's next increment (material_point.h): once the path is
 * finished (the last increment accepted), the increment that starts now
 * aims at F (3 x 3 slots; the first dim x dim block is read) from the state
 * reached, as the path's last increment again: (D), (P) and (T), not mixed.
 * Fails, changing nothing, while an increment is under way or when det F
 * <= 0. */
sbc_status sbc_controller_aim(sbc_controller *c, const double F[9], sbc_error *err);

/* A branch from an accepted increment (the event SBC_EVENT_INCREMENT or
 * SBC_EVENT_FINISHED, before the host's next step): the increment that
 * starts there aims at F instead of the path's next F, as sbc_controller_aim
 * does after the path's end; for a perturbation tangent on a copy of the
 * controller (sbc_controller_save, sbc_controller_load). Fails, changing
 * nothing, for mixed, when det F <= 0 or once the increment has taken a step. */
sbc_status sbc_controller_branch(sbc_controller *c, const double F[9], sbc_error *err);

/* Keyword remap x: 1 when the interior is to follow the frame's move on
 * the coming step, with M (3 x 3 slots, the dim x dim block set) and origin
 * [3] (m): every interior particle moves by u = (M - I)(x - origin)
 * (sbc_remap_displacement, tensor.h). While the frame travels to an increment's first
 * commands (motion.h) in s steps, the step from t = (j - 1)/s to j/s carries
 * M = F(j/s) F((j - 1)/s)^-1 with F(t) = F_prev + t (F_now - F_prev), the
 * affine part of the frame's move (Table 1, 1.1: x_q = F X_q about the
 * origin; mixed: about the support's centre, Sect. 5.1); servo corrections
 * carry none. 0 otherwise (M, origin untouched). Valid until the next step
 * call, or after sbc_controller_aim before the first step. */
int sbc_controller_remap(const sbc_controller *c, double M[9], double origin[3]);

/* Mixed: the mode (SBC_MODE_D, _P or _T) of each frame particle's
 * components, mode [3 Q], from the face modes of s (docs/servo_bc.md,
 * "Mixed"): a particle on several faces takes those of its face normal to
 * the last axis, then the middle, then the first; P makes it a member of
 * its family of periodic images, except on a corner or where one of its
 * other faces is not periodic, where it is D. */
void sbc_mixed_modes(const sbc_frame *f, const sbc_settings *s, unsigned char *mode);

/* A material point's choice (material_point.h): an increment whose
 * converged state cannot be certified at the words' accuracy (the checks of
 * docs/servo_bc.md, "Certified rows") is accepted all the same instead of
 * SBC_EVENT_FAILED; sbc_controller_uncertified then returns 1 with the
 * reason (the failure's message) in why [cap], until the next acceptance.
 * Not part of the saved state. */
void sbc_controller_accept_uncertified(sbc_controller *c, int yes);
int sbc_controller_uncertified(const sbc_controller *c, char *why, size_t cap);

/* update newton: the host's correction of the frame, du [3Q] (m) and
 * dtheta [rQ] (rad), that balances the frame's reactions a [3Q] (N, eq. 5)
 * and moments m [rQ] (N m) on its linearized contact network with the
 * interior condensed out, as the condition asks ((P): each periodic
 * family's sums to zero; (T): every particle's force to P A_q with eq. 15
 * kept, its moment to zero). SBC_OK, or an sbc_status with the message. */
typedef int (*sbc_newton_fn)(void *user_data, const double *a, const double *m, double *du, double *dtheta,
                             char *message, size_t cap);

/* Gives the controller the host's Newton correction (update newton; a
 * controller with update newton and none stops at its first correction,
 * naming the keyword). */
void sbc_controller_set_newton(sbc_controller *c, sbc_newton_fn fn, void *user_data);

/* interior newton: a static solve has put the frame at x [3Q] (m) and
 * theta [rQ] (rad; read where the rotation is not free), which become the
 * commands in force, the frame's travel ended (the host's frame stands
 * there already). */
void sbc_controller_adopt(sbc_controller *c, const double *x, const double *theta);

/* Increment now being relaxed, 0 .. i_tot. */
int sbc_controller_increment(const sbc_controller *c);

#ifdef __cplusplus
}
#endif

#endif
