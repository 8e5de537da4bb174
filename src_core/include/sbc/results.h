/* servo_bc: the results file (docs/servo_bc.md, Output), one row per
 * converged increment, flushed at once so that nothing is lost if a run
 * stops. After the contract's 20 columns come the accuracy measures of the
 * row: unbalanced (relax.h), frame_residual (servo.h) and hill_mandel
 * (eq. 30, relative); new columns are only ever appended. */
#ifndef SBC_RESULTS_H
#define SBC_RESULTS_H

#include <stdio.h>

#include "sbc/controller.h"

/* The CSV header line (no newline). */
extern const char sbc_csv_header[];

/* Opens path for writing and writes the header. */
sbc_status sbc_csv_open(FILE **fp, const char *path, sbc_error *err);

/* Opens path for appending (a run continued from a restart) and writes the
 * header only when the file is empty or new. */
sbc_status sbc_csv_append(FILE **fp, const char *path, sbc_error *err);

/* Writes one row with 17 significant digits and flushes. */
sbc_status sbc_csv_write(FILE *fp, const sbc_result *r, sbc_error *err);

#endif
