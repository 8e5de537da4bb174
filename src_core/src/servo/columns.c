/* servo_bc: the result columns (columns.h). */
#include "sbc/columns.h"

#include <stdio.h>
#include <string.h>

#define D2 SBC_COLUMN_2D
#define AT(member, k) (offsetof(sbc_result, member) + (k) * sizeof(double))
#define COUNT(name, member, type, unit, what) {name, unit, D2, SBC_COLUMN_COUNT, what, offsetof(sbc_result, member), type}
#define VALUE(name, off, unit, what) {name, unit, D2, SBC_COLUMN_VALUE, what, off, 'd'}
#define MEASURE(name, member, unit, what) {name, unit, D2, SBC_COLUMN_MEASURE, what, offsetof(sbc_result, member), 'd'}

const sbc_column sbc_columns[SBC_COLUMNS] = {
    COUNT("increment", increment, 'i', "-", "the converged increment, 0 for the initial state"),
    VALUE("F11", AT(F, SBC_IJ(0, 0)), "-", "macroscopic deformation gradient F, eq. 15, from the frame's positions"),
    VALUE("F12", AT(F, SBC_IJ(0, 1)), "-", "F, eq. 15"),
    VALUE("F21", AT(F, SBC_IJ(1, 0)), "-", "F, eq. 15"),
    VALUE("F22", AT(F, SBC_IJ(1, 1)), "-", "F, eq. 15"),
    VALUE("P11", AT(P, SBC_IJ(0, 0)), "N/m", "first Piola-Kirchhoff stress P, eq. 23, from the frame's forces"),
    VALUE("P12", AT(P, SBC_IJ(0, 1)), "N/m", "P, eq. 23"),
    VALUE("P21", AT(P, SBC_IJ(1, 0)), "N/m", "P, eq. 23"),
    VALUE("P22", AT(P, SBC_IJ(1, 1)), "N/m", "P, eq. 23"),
    VALUE("sigma11", AT(sigma, SBC_IJ(0, 0)), "N/m", "Cauchy stress, eq. 31"),
    VALUE("sigma12", AT(sigma, SBC_IJ(0, 1)), "N/m", "Cauchy stress, eq. 31"),
    VALUE("sigma21", AT(sigma, SBC_IJ(1, 0)), "N/m", "Cauchy stress, eq. 31"),
    VALUE("sigma22", AT(sigma, SBC_IJ(1, 1)), "N/m", "Cauchy stress, eq. 31"),
    VALUE("overlap_mean", AT(overlap_mean, 0), "-", "mean overlap over the mean radius of the contacts, eq. 39"),
    VALUE("rotation_mean", AT(rotation_mean, 0), "rad", "mean absolute rotation of the particles, eq. 41"),
    COUNT("iterations", iterations, 'i', "-", "servo iterations of the increment, 0 for D"),
    COUNT("relax_steps", relax_steps, 'l', "-", "host (DEM) steps of the increment"),
    VALUE("r_force", AT(r_force, 0), "-", "final force residual norm of the servo, eq. 37 (relative with tol_relative)"),
    VALUE("r_moment", AT(r_moment, 0), "-", "final moment residual norm, (P) and mixed"),
    VALUE("r_deformation", AT(r_deformation, 0), "-", "final deformation residual norm, (T) and mixed"),
    MEASURE("unbalanced", unbalanced, "-", "largest net force on an interior particle over the mean contact force"),
    MEASURE("frame_residual", frame_residual, "-", "the frame's force residual relative to its forces, 0 for D"),
    MEASURE("hill_mandel", hill_mandel, "-", "residual of eq. 30 relative to the work scale"),
};

void sbc_column_values(const sbc_result *r, double values[SBC_COLUMNS])
{
    const char *base = (const char *)r;
    int k;
    for (k = 0; k < SBC_COLUMNS; ++k) {
        const sbc_column *c = &sbc_columns[k];
        if (c->type == 'i') {
            int v;
            memcpy(&v, base + c->offset, sizeof v);
            values[k] = v;
        } else if (c->type == 'l') {
            long v;
            memcpy(&v, base + c->offset, sizeof v);
            values[k] = (double)v;
        } else {
            memcpy(&values[k], base + c->offset, sizeof values[k]);
        }
    }
}

int sbc_column_count(void) { return SBC_COLUMNS; }

const char *sbc_column_name(int k) { return k >= 0 && k < SBC_COLUMNS ? sbc_columns[k].name : NULL; }

int sbc_column_index(const char *name)
{
    int k;
    for (k = 0; name && k < SBC_COLUMNS; ++k)
        if (strcmp(sbc_columns[k].name, name) == 0)
            return k;
    return -1;
}

int sbc_columns_header(char *out, size_t cap)
{
    size_t used = 0;
    int k;
    for (k = 0; k < SBC_COLUMNS; ++k) {
        const char *sep = k ? "," : "";
        if (used < cap)
            snprintf(out + used, cap - used, "%s%s", sep, sbc_columns[k].name);
        used += strlen(sep) + strlen(sbc_columns[k].name);
    }
    return (int)used;
}

#define COLUMN(name) {SBC_THERMO_COLUMN, name}
const sbc_thermo_entry sbc_thermo_vector[SBC_THERMO_COUNT] = {
    COLUMN("increment"), COLUMN("F11"), COLUMN("F12"), COLUMN("F21"), COLUMN("F22"),
    COLUMN("P11"), COLUMN("P12"), COLUMN("P21"), COLUMN("P22"),
    COLUMN("sigma11"), COLUMN("sigma12"), COLUMN("sigma21"), COLUMN("sigma22"),
    {SBC_THERMO_R_FORCE, NULL}, {SBC_THERMO_R_MOMENT, NULL}, {SBC_THERMO_R_DEFORMATION, NULL},
    {SBC_THERMO_ITERATION, NULL}, {SBC_THERMO_FINISHED, NULL},
    COLUMN("unbalanced"), COLUMN("frame_residual"), COLUMN("hill_mandel"),
};

double sbc_thermo_value(const sbc_controller *c, const sbc_result *last, int finished, int k)
{
    const sbc_thermo_entry *t;
    double values[SBC_COLUMNS], r[3];
    int iteration;
    if (k < 0 || k >= SBC_THERMO_COUNT)
        return 0.0;
    t = &sbc_thermo_vector[k];
    if (t->kind == SBC_THERMO_COLUMN) {
        sbc_column_values(last, values);
        return values[sbc_column_index(t->column)];
    }
    if (t->kind == SBC_THERMO_FINISHED)
        return finished;
    sbc_controller_progress(c, &iteration, &r[0], &r[1], &r[2]);
    return t->kind == SBC_THERMO_ITERATION ? iteration : r[t->kind - SBC_THERMO_R_FORCE];
}
