/* servo_bc: the results file (docs/servo_bc.md, Output), one row per
 * converged increment in the columns of columns.h, written and flushed at
 * once so that nothing is lost if a run stops.
 *
 * The file is opened through output_file.h (never over a file servo_bc did
 * not write; locked while the run writes it). A row is whole or absent: a
 * write that fails (disk full, file size limit) is cut back to the last whole
 * row and reported with the file's name and the system's reason. */
#ifndef SBC_RESULTS_H
#define SBC_RESULTS_H

#include <stdio.h>

#include "sbc/controller.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_csv {
    FILE *fp;                  /* NULL: no results file */
    char path[SBC_NAME_LEN];
} sbc_csv;

/* Opens path for writing and writes the header of a dim-dimensional run
 * (columns.h). */
sbc_status sbc_csv_open(sbc_csv *csv, const char *path, int dim, sbc_error *err);

/* A run continued from a restart whose increment in progress is `next`:
 * opens path, keeps the header and the rows of increments before `next`,
 * drops the rest (rows an interrupted run wrote after its restart file), so
 * that the continued file equals an uninterrupted run's. A missing or empty
 * file is begun anew with the header; *kept (may be NULL) is the number of
 * rows kept. */
sbc_status sbc_csv_resume(sbc_csv *csv, const char *path, int dim, int next, int *kept, sbc_error *err);

/* Writes one row with 17 significant digits; refuses a non-finite value. */
sbc_status sbc_csv_write(sbc_csv *csv, const sbc_result *r, sbc_error *err);

/* The log line of a converged increment, one format for every host (no
 * newline), into out [cap]:
 *   servo_bc P: increment 3/10 F12 +0.00300 sigma11 -2.396300e+02 sigma12 +1.234500e+01 N/m
 *   steps 1234 iterations 5 unbalanced 3.2e-06 HM 1.1e-12
 * (N/m^2 in 3D). The F shown is the component farthest from the identity (the layer's
 * shear, F12 or F13, unless another is strictly farther), the stresses a companion normal
 * stress and the same component: a triaxial path shows F33, sigma11, sigma33. total: the
 * path's increments (sbc_settings_total_increments). Returns its length (as snprintf). */
int sbc_result_line(const sbc_result *r, sbc_bc bc, int total, char *out, size_t cap);

/* Closes the file (nothing when none is open). */
void sbc_csv_close(sbc_csv *csv);

#ifdef __cplusplus
}
#endif

#endif
