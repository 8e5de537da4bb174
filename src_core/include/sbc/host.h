/* servo_bc: the core behind one opaque handle, for hosts that reach C through
 * a foreign-function interface (YADE's Python via ctypes) and should not
 * mirror the core's structs. Plain types only: words as one string, arrays
 * of doubles, events as ints, messages as C strings owned by the handle.
 *
 * One handle = parsed settings + frame + controller + the CSV of `file` +
 * the host driver (driver.h). Once: sbc_host_drive with the host's
 * callbacks. Per host step: sbc_host_step, then the commands
 * (sbc_host_command_*). */
#ifndef SBC_HOST_H
#define SBC_HOST_H

#include <stddef.h>

#include "sbc/columns.h"
#include "sbc/controller.h"
#include "sbc/driver.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_host sbc_host;

/* words: the servo_bc words, BC first ("P F 1 0.1 0 1 increments 10 ...").
 * dim: the packing's dimension (2: discs, 3: spheres; settings.h,
 * sbc_settings_check_dimension). n particles with centres x [dim n] (m),
 * radii r [n] (m), masses m [n] (kg). The frame: when the words name one
 * (`frame NAME`, 2D), the host resolves NAME to the indices list [nlist]
 * (any order; the core orders them); otherwise list must be empty and the
 * frame is detected from the centres (3D: sbc_frame_detect_3d). dt: the
 * host's time step (s), kn the normal stiffness of its contact law (N/m; 0
 * if unknown, see sbc_controller_create). Returns NULL on failure with the
 * message in msg (cap bytes, which may be 0). */
sbc_host *sbc_host_create(const char *words, int dim, int n, const double *x, const double *r, const double *m,
                          int nlist, const int *list, double dt, double kn, char *msg, size_t cap);
void sbc_host_free(sbc_host *h);

/* A warning about the words (sbc_settings_ignored_message) and the time
 * step (sbc_time_step_note), one per line: 1 with the message in msg [cap],
 * 0 when there is none. */
int sbc_host_warning(const sbc_host *h, char *msg, size_t cap);

/* The damping the words ask for (sbc_damping of settings.h: 0 none, 1 eq.
 * 10, 2 FIRE), which a host applies itself; alpha, beta: the factors of eq.
 * 10 (0 for none; with FIRE they damp the free frame rotations of (T)). */
int sbc_host_damping(const sbc_host *h, double *alpha, double *beta);

/* keyword seal (seal.h): sbc_host_sealed is 1 when the words ask for it.
 * sbc_host_seal: the walls' forces on the creation's particles at centres x
 * [dim n] (m), the frame's at the commanded centres, into force [dim n] (N,
 * overwritten; the walls' reactions on frame particles included): add them
 * to the host's forces before anything is measured in the step. *energy: the
 * walls' energy (J), part of Ep. Returns the walls touching a particle (0
 * without the keyword), or -1 with the message in sbc_host_message. */
int sbc_host_sealed(const sbc_host *h);
int sbc_host_seal(sbc_host *h, const double *x, double *force, double *energy);

/* Q and the frame's particles [Q], as indices into the creation arrays, in
 * frame order (the order of every per-frame array below). */
int sbc_host_frame_size(const sbc_host *h);
const int *sbc_host_frame_particles(const sbc_host *h);

/* The host's side of one step: driver.h's callbacks in plain types. The
 * per-step protocol (what to measure and when, FIRE's state, the controller,
 * the confinement cadence, the row) is the driver's, the same as every other
 * host's; the callbacks only read and write the host's particles. */
typedef struct sbc_host_callbacks {
    void *user_data;
    /* damping fire (fire_damping.h): the interior's sums [SBC_FIRE_SUMS] */
    void (*fire_sums)(void *user_data, double *sums);
    /* the interior: FIRE's mix of this step when mix is not NULL ([4] keep,
       push, spin, stop: sbc_fire_mix), then out [2]: its Ek (eq. 12, J; the
       particles that carry a force) and its largest |net contact force| (N) */
    void (*interior)(void *user_data, const double *mix, double *out);
    /* out [4]: Ep (eq. 12, J), sum dn / Rbar (eq. 39), contact count, sum
       |contact force| (N) */
    void (*contacts)(void *user_data, double *out);
    /* optional (driver.h): the largest |net contact force| again, from this
       step's contact sums [4] */
    double (*net_force)(void *user_data, const double *contacts);
    /* the frame, in frame order, into buf [SBC_DRIVER_FRAME_SIZE(Q)] (zeroed):
       x [3Q] (m), force [3Q] (N), torque [Q] (N m), theta [Q] (rad), sum
       |theta| over every particle (eq. 41), particle count */
    void (*frame)(void *user_data, double *buf);
    /* optional (without it confinement is not checked): the interior
       particles, those of the creation arrays not in the frame, in creation
       order: ids [N - Q] (for the message), centres and velocities [3 (N - Q)]
       (m, m/s) */
    void (*interior_state)(void *user_data, long *ids, double *x, double *v);
    /* optional: a converged increment, once the CSV of `file` has it: its row
       [SBC_HOST_ROW] and its log line (sbc_result_line) */
    void (*row)(void *user_data, const double *row, const char *line);
    /* keyword remap x (required with it): the interior follows the frame's
       affine move, sign +1, and gives back the velocity, sign -1, as
       driver.h's remap says; M [9] (3 x 3, row-major; the packing's
       dimension's block), origin [3] (m) */
    void (*remap)(void *user_data, const double *M, const double *origin, int sign);
} sbc_host_callbacks;

/* The callbacks of the host's steps (copied). 0, or 1 with the message in
 * sbc_host_message (a required callback missing). */
int sbc_host_drive(sbc_host *h, const sbc_host_callbacks *cb);

/* One host step, after the host's contact forces (and sbc_host_seal's):
 * sbc_driver_step through the callbacks. Returns the sbc_event; apply the
 * commands (sbc_host_command_*) before the next step. On SBC_EVENT_FAILED the
 * message is in sbc_host_message. */
int sbc_host_step(sbc_host *h);
const char *sbc_host_message(const sbc_host *h);

/* The progress line of a long increment (sbc_controller_progress_line): step
 * the host's steps so far, elapsed the seconds since its run started. */
void sbc_host_progress_line(const sbc_host *h, long step, double elapsed, char *out, size_t cap);

/* The commands in force: target positions [3Q] (m), rotations [Q] (rad),
 * free-rotation flags [Q]; valid until the next sbc_host_step. */
const double *sbc_host_command_x(const sbc_host *h);
const double *sbc_host_command_theta(const sbc_host *h);
const unsigned char *sbc_host_command_free(const sbc_host *h);

/* The last accepted increment in the columns of its dimension (columns.h:
 * sbc_column_count(dim) of the SBC_HOST_ROW doubles; sbc_column_name gives
 * their names). */
#define SBC_HOST_ROW SBC_COLUMNS
void sbc_host_result(const sbc_host *h, double *row);

#ifdef __cplusplus
}
#endif

#endif
