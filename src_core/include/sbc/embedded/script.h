/* servo_bc: the embedded runner's script language (LAMMPS-like, one command
 * per line, '#' comments):
 *
 *   dimension 2
 *   lattice square NX NY spacing D radius R        (m)
 *   read_packing FILE                               (x y r per line, m)
 *   contact frictional kn KN ks KS mu MU            (N/m, N/m, -)
 *   density RHO                                     (mass per area, kg/m^2)
 *   timestep DT                                     (s)
 *   servo_bc BC keyword value ...                   (docs/servo_bc.md)
 *   vtk EVERY PREFIX                                (snapshot every EVERY increments and the last)
 *   plot FILE.svg                                   (sigma~11, sigma~12 against F12 at the end)
 *   run
 *
 * Errors name the script, line, command or keyword, the offending value and
 * what was expected. */
#ifndef SBC_SCRIPT_H
#define SBC_SCRIPT_H

#include <stdio.h>

#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Runs the script text; `name` labels error messages; progress goes to log
 * (may be NULL). */
sbc_status sbc_script_run_string(const char *text, const char *name, FILE *log, sbc_error *err);

/* Reads and runs the script file at path. */
sbc_status sbc_script_run_file(const char *path, FILE *log, sbc_error *err);

/* Checks the script as servo-bc --check does: every command is read and
 * checked (packings built, the frame detected, the controller created, the
 * time step and the output names checked) but nothing is run or written. */
sbc_status sbc_script_check_string(const char *text, const char *name, FILE *log, sbc_error *err);
sbc_status sbc_script_check_file(const char *path, FILE *log, sbc_error *err);

/* A script's case as parsed up to its 'run' (opaque here). */
typedef struct sbc_script_case sbc_script_case;

/* What --decks does at 'run' instead of running: write the case into the
 * folder dir. */
typedef sbc_status (*sbc_script_decks_fn)(sbc_script_case *c, const char *dir, sbc_error *err);

/* Reads the script file at path and, at its 'run', hands the case to write
 * instead of running it. servo-bc's writer (src_core/runner/decks.c, outside
 * the core library) writes into the existing folder dir the same case for
 * every host: the packing (packing.txt, packing.lammps.data,
 * packing.liggghts.data, packing.yade) and embedded.sbc, lammps.in,
 * liggghts.in, yade.py, each of which, run in dir, writes dir/HOST.csv. */
sbc_status sbc_script_decks_file(const char *path, const char *dir, sbc_script_decks_fn write, FILE *log,
                                 sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
