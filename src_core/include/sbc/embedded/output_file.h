/* servo_bc: opening an output file.
 *
 * Every file servo_bc writes goes through sbc_output_open, which
 *  - creates the folders of its path that do not exist yet (as `mkdir -p`),
 *    so that `file out/run1/P.csv` works in a fresh folder;
 *  - overwrites an existing file only when it is empty or begins as files of
 *    its kind do (a results file with "increment,", a VTK file with
 *    "# vtk DataFile", ...): servo_bc never overwrites a file it did not
 *    write, so an output named after an input deck, a data file, a packing or
 *    another kind of output is refused with the input intact;
 *  - locks the file for writing (POSIX record lock) before truncating it, so
 *    that a second process writing the same file is refused, naming the
 *    process that holds it.
 * A results file is written unbuffered, one row per write, so that a failing
 * write can be undone to the last whole row (results.h). */
#ifndef SBC_OUTPUT_FILE_H
#define SBC_OUTPUT_FILE_H

#include <stdio.h>

#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_output_kind {
    SBC_OUTPUT_RESULTS = 0, /* the servo_bc CSV (results.h) */
    SBC_OUTPUT_SERIES,      /* a 3D test's time series (CSV beginning "step,") */
    SBC_OUTPUT_VTK,         /* legacy VTK */
    SBC_OUTPUT_SVG,         /* plots, rose diagrams, contact networks */
    SBC_OUTPUT_PACKING,     /* packings in every host's format (first line names "servo_bc packing") */
    SBC_OUTPUT_DECK         /* the hosts' inputs of servo-bc --decks */
} sbc_output_kind;

/* Opens path for writing an output of KIND as above; NULL with err set
 * ("WHAT: cannot write 'path': the reason") otherwise. */
FILE *sbc_output_open(const char *path, sbc_output_kind kind, const char *what, sbc_error *err);

/* As sbc_output_open, but the file is kept as it is, opened for reading and
 * writing at its start (a results file continued from a restart). */
FILE *sbc_output_update(const char *path, sbc_output_kind kind, const char *what, sbc_error *err);

/* Everything sbc_output_open checks, without writing anything: the folders
 * and the file are created and removed again when they did not exist. Used
 * by `servo-bc --check`. */
sbc_status sbc_output_probe(const char *path, sbc_output_kind kind, const char *what, sbc_error *err);

/* Reports why an existing file may not be overwritten as KIND (it is not
 * one of servo_bc's files of that kind); SBC_OK for a missing or empty file. */
sbc_status sbc_output_owned(const char *path, sbc_output_kind kind, const char *what, sbc_error *err);

/* Appends text [n] to fp (opened by sbc_output_open) whole or not at all: a
 * failed write (disk full, file size limit) is cut back to where it began,
 * so that the file ends with its last whole row. The message: "WHAT 'path':
 * cannot write ROW (the system's reason); the file ends with the rows before
 * it", e.g. WHAT "results file", ROW "the row of increment 53". */
sbc_status sbc_output_append(FILE *fp, const char *text, size_t n, const char *path, const char *what,
                             const char *row, sbc_error *err);

/* Closes a whole-file output (a VTK snapshot, an SVG, a packing): when any
 * write to it failed, the partial file is removed and the message names the
 * system's reason, so that an output is whole or absent. */
sbc_status sbc_output_close(FILE *fp, const char *path, const char *what, sbc_error *err);

/* Creates the folder path and its missing parents; 0 on success. */
int sbc_output_folder(const char *path);

#ifdef __cplusplus
}
#endif

#endif
