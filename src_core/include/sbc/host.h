/* servo_bc: the core behind one opaque handle, for hosts that reach C through
 * a foreign-function interface (YADE's Python via ctypes) and should not
 * mirror the core's structs. Plain types only: words as one string, arrays
 * of doubles, events as ints, messages as C strings owned by the handle.
 *
 * One handle = parsed settings + frame + controller + the CSV of `file`.
 * Per host step: sbc_host_needs (relax.h, controller.h: what to measure),
 * sbc_host_step, then the commands (sbc_host_command_*). */
#ifndef SBC_HOST_H
#define SBC_HOST_H

#include <stddef.h>

#include "sbc/columns.h"
#include "sbc/controller.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_host sbc_host;

/* words: the servo_bc words, BC first ("P F 1 0.1 0 1 increments 10 ...").
 * n particles with centres xy [2n] (m), radii r [n] (m), masses m [n] (kg).
 * The frame: when the words name one (`frame NAME`), the host resolves NAME
 * to the indices list [nlist] (any order; the core orders them); otherwise
 * list must be empty and the frame is detected from the centres. dt: the
 * host's time step (s), kn the normal stiffness of its contact law (N/m; 0 if
 * unknown, see sbc_controller_create). Returns NULL on failure with the message in msg (cap
 * bytes, which may be 0). */
sbc_host *sbc_host_create(const char *words, int n, const double *xy, const double *r, const double *m, int nlist,
                          const int *list, double dt, double kn, char *msg, size_t cap);
void sbc_host_free(sbc_host *h);

/* A warning about the words (sbc_settings_ignored_message) and the time
 * step (sbc_time_step_note), one per line: 1 with the message in msg [cap],
 * 0 when there is none. */
int sbc_host_warning(const sbc_host *h, char *msg, size_t cap);

/* The damping the words ask for (sbc_damping of settings.h: 0 none, 1 eq.
 * 10, 2 FIRE), which a host applies itself; alpha, beta: the factors of eq.
 * 10 (0 for none; with FIRE they damp the free frame rotations of (T)). */
int sbc_host_damping(const sbc_host *h, double *alpha, double *beta);

/* damping fire (fire_damping.h): this step's mix from the interior's sums
 * [SBC_FIRE_SUMS]; mix [4] = keep, push, spin, stop (sbc_fire_mix). Call it
 * once per step. */
void sbc_host_fire_mix(sbc_host *h, const double *sums, double *mix);

/* keyword seal (seal.h): sbc_host_sealed is 1 when the words ask for it.
 * sbc_host_seal: the walls' forces on the creation's particles at centres xy
 * [2n] (m), the frame's at the commanded centres, into force [2n] (N,
 * overwritten; the walls' reactions on frame particles included): add them
 * to the host's forces before anything is measured in the step. *energy: the
 * walls' energy (J), part of Ep. Returns the walls touching a particle (0
 * without the keyword), or -1 with the message in sbc_host_message. */
int sbc_host_sealed(const sbc_host *h);
int sbc_host_seal(sbc_host *h, const double *xy, double *force, double *energy);

/* Q and the frame's particles [Q], as indices into the creation arrays, in
 * frame order (the order of every per-frame array below). */
int sbc_host_frame_size(const sbc_host *h);
const int *sbc_host_frame_particles(const sbc_host *h);

/* The measures of one host step (sbc_snapshot's scalars), as an array of
 * SBC_HOST_MEASURES doubles indexed so; unmeasured contact sums: Ep =
 * SBC_RELAX_EP_UNMEASURED (controller.h, sbc_controller_needs). */
enum {
    SBC_HOST_EK = 0,          /* J */
    SBC_HOST_NET_MAX,         /* largest |net contact force| on an interior particle, N */
    SBC_HOST_EP,              /* J */
    SBC_HOST_CONTACT_SUM,     /* sum |contact force|, N */
    SBC_HOST_CONTACT_COUNT,
    SBC_HOST_OVERLAP_SUM,     /* eq. 39 */
    SBC_HOST_ROTATION_SUM,    /* eq. 41, rad */
    SBC_HOST_PARTICLE_COUNT,
    SBC_HOST_MEASURES
};

/* sbc_controller_needs. */
unsigned sbc_host_needs(const sbc_host *h, const double *measures);

/* One host step (sbc_controller_step) with the measures above and the
 * frame arrays of sbc_snapshot in frame order: x, force [3Q] (3 slots
 * whatever the dimension), theta, torque [Q]; they may be NULL where
 * sbc_host_needs allowed it.
 * Returns the sbc_event. The row of SBC_EVENT_INCREMENT and
 * SBC_EVENT_FINISHED goes to the CSV once sbc_host_confined passes it (or at
 * the next sbc_host_step, or sbc_host_free, for a host that does not check).
 * On SBC_EVENT_FAILED the message is in sbc_host_message. */
int sbc_host_step(sbc_host *h, const double *measures, const double *x, const double *theta, const double *force,
                  const double *torque);
const char *sbc_host_message(const sbc_host *h);

/* The log line of the last converged increment (results.h, sbc_result_line),
 * owned by the handle. */
const char *sbc_host_result_line(sbc_host *h);

/* Progress within the increment under way (sbc_controller_progress), for the
 * progress lines of long increments: out [4] = servo iteration, residual
 * norms of force, moment and deformation. */
void sbc_host_progress(const sbc_host *h, double *out);

/* confine.h for n interior particles (ids [n] for the message, centres xy
 * [2n] in m, velocities vxy [2n] in m/s) against the frame's present centres
 * frame_x [3Q] (frame order). Call it after SBC_EVENT_INCREMENT and
 * SBC_EVENT_FINISHED (it then writes the pending row), after
 * SBC_EVENT_FAILED (an escape explains a stalled servo) and every
 * SBC_CONFINE_EVERY steps. Returns 0, or 1 with the message in
 * sbc_host_message and the pending row dropped. */
int sbc_host_confined(sbc_host *h, const double *frame_x, int n, const long *ids, const double *xy,
                      const double *vxy);

/* The commands in force: target positions [3Q] (m), rotations [Q] (rad),
 * free-rotation flags [Q]; valid until the next sbc_host_step. */
const double *sbc_host_command_x(const sbc_host *h);
const double *sbc_host_command_theta(const sbc_host *h);
const unsigned char *sbc_host_command_free(const sbc_host *h);

/* The last accepted increment as SBC_HOST_ROW doubles, in the columns of
 * columns.h (sbc_column_name gives their names). */
#define SBC_HOST_ROW SBC_COLUMNS
void sbc_host_result(const sbc_host *h, double *row);

#ifdef __cplusplus
}
#endif

#endif
