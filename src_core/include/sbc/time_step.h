/* servo_bc: the time step a host may run the servo at, checked before the
 * run in every host (the runner, the LAMMPS and LIGGGHTS fix, the handle of
 * host.h).
 *
 * Upper bound: SBC_TIME_STEP_FRACTION of the critical step of the lightest
 * particle on one contact, dt_c = 2 sqrt(M_min / (2 kn)): a particle with
 * several contacts is stable only below a fraction of it (1/sqrt(2) with the
 * four contacts of a square lattice), and relaxations at every preset stop
 * converging between 0.65 and 0.7 of dt_c on the square lattice
 * (docs/stability.md, "Time step").
 * Lower bound: max_relax_steps steps must span at least one dt_c; below
 * that no relaxation can end (a contact oscillation lasts longer than the
 * relaxation may), and Ek of a step so short underflows to zero, which would
 * pass for rest. */
#ifndef SBC_TIME_STEP_H
#define SBC_TIME_STEP_H

#include "sbc/settings.h"
#include "sbc/status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SBC_TIME_STEP_FRACTION 0.6

/* Below this fraction of the critical step a run is slow for nothing: a
 * relaxation spans a number of critical steps, so its DEM steps grow as dt
 * falls, for the same balance (docs/stability.md, "Time step"). The
 * examples' 1/114 costs about 10 times the steps of 0.1 and passes; the
 * paper's 1/1143 is noted. */
#define SBC_TIME_STEP_SLOW 0.002

/* dt (s) against a critical step dtc (s) given by formula (for the
 * message: "2 sqrt(M / (2 kn)) of particle 3 ..."): above dtc, above
 * SBC_TIME_STEP_FRACTION of it, or too short for max_relax_steps. */
sbc_status sbc_time_step_bound(double dt, double dtc, const char *formula, long max_relax_steps, sbc_error *err);

/* dt (s), kn (N/m; 0 = unknown: the upper bound is not checked), the
 * smallest mass (kg) and the index of its particle (for the message, -1 if
 * none), max_relax_steps. Returns SBC_OK or SBC_ERR_INPUT with the message. */
sbc_status sbc_time_step_check(double dt, double kn, double mass_min, long index, long max_relax_steps,
                               sbc_error *err);

/* A note (not an error) when dt (s) is below SBC_TIME_STEP_SLOW of the
 * critical step dtc (s) under the words s: returns 1 with the note in out,
 * else 0. None under `update fixed`, whose gains are per time step (eq. 37:
 * a larger step changes them). */
int sbc_time_step_note(const sbc_settings *s, double dt, double dtc, char *out, size_t cap);

/* The same with dtc = 2 sqrt(mass_min / (2 kn)); 0 when kn or mass_min is
 * not > 0. */
int sbc_time_step_note_mass(const sbc_settings *s, double dt, double kn, double mass_min, char *out, size_t cap);

#ifdef __cplusplus
}
#endif

#endif
