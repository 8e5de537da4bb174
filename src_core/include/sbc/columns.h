/* servo_bc: the result columns, one table (name, unit, the dimensions that
 * have the column, how it is written, description) that drives the results
 * file's header and rows (results.h), the hosts' result row (host.h), the
 * YADE module's COLUMNS, the fixes' thermo vector (sbc_thermo_vector) and the
 * docs' column table (tests/tables.sh checks
 * docs/servo_bc.md against it). Adding a column is one line here and the code
 * that computes it; new columns are only ever appended. */
#ifndef SBC_COLUMNS_H
#define SBC_COLUMNS_H

#include <stddef.h>

#include "sbc/controller.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How a column's value is written: a count ("%d"/"%ld"), a measured value to
 * 17 significant digits ("%.17g", read back bit for bit), or an accuracy
 * measure to 6 ("%.6g"). */
typedef enum sbc_column_format { SBC_COLUMN_COUNT, SBC_COLUMN_VALUE, SBC_COLUMN_MEASURE } sbc_column_format;

typedef struct sbc_column {
    const char *name;        /* the header's word */
    const char *unit;        /* SI unit, "-" for none */
    unsigned dimensions;     /* bit 2: 2D, bit 3: 3D (SBC_COLUMN_2D ...) */
    sbc_column_format format;
    const char *description; /* one line, with the paper's equation */
    size_t offset;           /* of the value in sbc_result */
    char type;               /* its C type there: 'i' int, 'l' long, 'd' double */
} sbc_column;

#define SBC_COLUMN_2D (1u << 2)
#define SBC_COLUMN_3D (1u << 3)

/* The columns of both dimensions, in the files' order: a 2D file has those
 * marked 2D (SBC_COLUMNS_2D), a 3D file those marked 3D (F, P and sigma with
 * nine components each). */
#define SBC_COLUMNS 40
#define SBC_COLUMNS_2D 25
extern const sbc_column sbc_columns[SBC_COLUMNS];

/* Column k of a results file of dimension dim (NULL outside). */
const sbc_column *sbc_column_of(int dim, int k);

/* The values of r in the columns of its dimension (r->dim), as doubles
 * (counts exactly), into values [SBC_COLUMNS]; returns their count. */
int sbc_column_values(const sbc_result *r, double *values);

/* For hosts that load the library at run time (the YADE module): the
 * number of columns of dimension dim and the name of column k (NULL
 * outside). */
int sbc_column_count(int dim);
const char *sbc_column_name(int dim, int k);

/* The index of the column called name among those of dimension dim, or -1. */
int sbc_column_index(int dim, const char *name);

/* The header line of a results file of dimension dim into out [cap]: the
 * names joined by commas, no newline. Returns its length (as snprintf). */
int sbc_columns_header(int dim, char *out, size_t cap);

/* The thermo vector of the LAMMPS and LIGGGHTS fixes, f_ID[1] ..
 * f_ID[SBC_THERMO_COUNT]: result columns of the last converged increment by
 * name, and the progress of the increment under way. The layout is that of
 * 0.2.0 (input decks index it); new entries are only ever appended. */
typedef enum sbc_thermo_kind {
    SBC_THERMO_COLUMN = 0,   /* the result column `column` */
    SBC_THERMO_R_FORCE,      /* the force residual so far in the increment under way */
    SBC_THERMO_R_MOMENT,     /* the moment residual so far */
    SBC_THERMO_R_DEFORMATION, /* the deformation residual so far */
    SBC_THERMO_ITERATION,    /* servo iterations so far */
    SBC_THERMO_FINISHED      /* 1 once the loading path is finished */
} sbc_thermo_kind;

typedef struct sbc_thermo_entry {
    sbc_thermo_kind kind;
    const char *column; /* SBC_THERMO_COLUMN: the column's name */
} sbc_thermo_entry;

#define SBC_THERMO_COUNT 36
extern const sbc_thermo_entry sbc_thermo_vector[SBC_THERMO_COUNT];

/* The 1-based index in the thermo vector (f_ID[index]) of the result column
 * called column (F11 ... F33, P.., sigma.., unbalanced, ...), 0 when the
 * vector does not hold it. */
int sbc_thermo_index(const char *column);

/* Entry k (0-based: f_ID[k + 1]) for a controller c whose last converged row
 * is last; 0 outside the vector. */
double sbc_thermo_value(const sbc_controller *c, const sbc_result *last, int finished, int k);

#ifdef __cplusplus
}
#endif

#endif
