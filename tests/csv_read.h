/* Test helper: reads the servo_bc CSV back. */
#ifndef SBC_TEST_CSV_READ_H
#define SBC_TEST_CSV_READ_H

#include "sbc/columns.h"

#define CSV_COLS SBC_COLUMNS_2D

/* the column called name (columns.h); tests read columns by name */
#define COL(name) sbc_column_index(2, name)

/* Reads up to max rows of CSV_COLS numbers after the header; returns the
 * row count, -1 when the file is missing or a field is not a finite number. */
int csv_read(const char *path, double rows[][CSV_COLS], int max);

/* The same for a 3D file (SBC_COLUMNS numbers a row); read a column as
 * rows[i][COL3(name)]. */
#define COL3(name) sbc_column_index(3, name)
int csv_read_3d(const char *path, double rows[][SBC_COLUMNS], int max);

/* Writes text to path; returns 0 on success. */
int write_text(const char *path, const char *text);

#endif
