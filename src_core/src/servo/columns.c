/* servo_bc: the result columns (columns.h). */
#include "sbc/columns.h"

#include <stdio.h>
#include <string.h>

#define D2 SBC_COLUMN_2D
#define D3 SBC_COLUMN_3D
#define BOTH (SBC_COLUMN_2D | SBC_COLUMN_3D)
#define AT(member, k) (offsetof(sbc_result, member) + (k) * sizeof(double))
#define COUNT(name, member, type, unit, what) {name, unit, BOTH, SBC_COLUMN_COUNT, what, offsetof(sbc_result, member), type}
#define VALUE(name, dims, off, unit, what) {name, unit, dims, SBC_COLUMN_VALUE, what, off, 'd'}
#define MEASURE(name, member, unit, what) {name, unit, BOTH, SBC_COLUMN_MEASURE, what, offsetof(sbc_result, member), 'd'}
#define STRESS_UNIT "N/m (2D), N/m^2 (3D)"

const sbc_column sbc_columns[SBC_COLUMNS] = {
    COUNT("increment", increment, 'i', "-", "the converged increment, 0 for the initial state"),
    VALUE("F11", BOTH, AT(F, SBC_IJ(0, 0)), "-", "macroscopic deformation gradient F, eq. 15, from the frame's positions"),
    VALUE("F12", BOTH, AT(F, SBC_IJ(0, 1)), "-", "F, eq. 15"),
    VALUE("F13", D3, AT(F, SBC_IJ(0, 2)), "-", "F, eq. 15"),
    VALUE("F21", BOTH, AT(F, SBC_IJ(1, 0)), "-", "F, eq. 15"),
    VALUE("F22", BOTH, AT(F, SBC_IJ(1, 1)), "-", "F, eq. 15"),
    VALUE("F23", D3, AT(F, SBC_IJ(1, 2)), "-", "F, eq. 15"),
    VALUE("F31", D3, AT(F, SBC_IJ(2, 0)), "-", "F, eq. 15"),
    VALUE("F32", D3, AT(F, SBC_IJ(2, 1)), "-", "F, eq. 15"),
    VALUE("F33", D3, AT(F, SBC_IJ(2, 2)), "-", "F, eq. 15"),
    VALUE("P11", BOTH, AT(P, SBC_IJ(0, 0)), STRESS_UNIT, "first Piola-Kirchhoff stress P, eq. 23, from the frame's forces"),
    VALUE("P12", BOTH, AT(P, SBC_IJ(0, 1)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P13", D3, AT(P, SBC_IJ(0, 2)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P21", BOTH, AT(P, SBC_IJ(1, 0)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P22", BOTH, AT(P, SBC_IJ(1, 1)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P23", D3, AT(P, SBC_IJ(1, 2)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P31", D3, AT(P, SBC_IJ(2, 0)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P32", D3, AT(P, SBC_IJ(2, 1)), STRESS_UNIT, "P, eq. 23"),
    VALUE("P33", D3, AT(P, SBC_IJ(2, 2)), STRESS_UNIT, "P, eq. 23"),
    VALUE("sigma11", BOTH, AT(sigma, SBC_IJ(0, 0)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma12", BOTH, AT(sigma, SBC_IJ(0, 1)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma13", D3, AT(sigma, SBC_IJ(0, 2)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma21", BOTH, AT(sigma, SBC_IJ(1, 0)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma22", BOTH, AT(sigma, SBC_IJ(1, 1)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma23", D3, AT(sigma, SBC_IJ(1, 2)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma31", D3, AT(sigma, SBC_IJ(2, 0)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma32", D3, AT(sigma, SBC_IJ(2, 1)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("sigma33", D3, AT(sigma, SBC_IJ(2, 2)), STRESS_UNIT, "Cauchy stress, eq. 31"),
    VALUE("overlap_mean", BOTH, AT(overlap_mean, 0), "-", "mean overlap over the mean radius of the contacts, eq. 39"),
    VALUE("rotation_mean", BOTH, AT(rotation_mean, 0), "rad", "mean absolute rotation of the particles, eq. 41"),
    COUNT("iterations", iterations, 'i', "-", "servo iterations of the increment, 0 for D"),
    COUNT("relax_steps", relax_steps, 'l', "-", "host (DEM) steps of the increment"),
    VALUE("r_force", BOTH, AT(r_force, 0), "-", "final force residual norm of the servo, eq. 37 (relative with tol_relative)"),
    VALUE("r_moment", BOTH, AT(r_moment, 0), "-", "final moment residual norm, (P) and mixed"),
    VALUE("r_deformation", BOTH, AT(r_deformation, 0), "-", "final deformation residual norm, (T) and mixed"),
    MEASURE("unbalanced", unbalanced, "-", "largest net force on an interior particle over the mean contact force"),
    MEASURE("frame_residual", frame_residual, "-", "the frame's force residual relative to its forces, 0 for D"),
    MEASURE("hill_mandel", hill_mandel, "-", "residual of eq. 30 relative to the work scale"),
    COUNT("newton_iterations", newton_iterations, 'l', "-",
          "interior newton: Newton iterations of the increment's static solves, 0 with interior dynamic"),
    COUNT("newton_held", newton_held, 'l', "-",
          "interior newton: degrees of freedom held for want of stiffness (rattlers, free rotations) at the "
          "increment's last static solve, 0 with interior dynamic"),
};

static unsigned in_dim(int dim) { return dim == 2 || dim == 3 ? 1u << dim : 0u; }

const sbc_column *sbc_column_of(int dim, int k)
{
    int j, seen = 0;
    for (j = 0; j < SBC_COLUMNS; ++j)
        if (sbc_columns[j].dimensions & in_dim(dim) && seen++ == k)
            return &sbc_columns[j];
    return NULL;
}

int sbc_column_values(const sbc_result *r, double *values)
{
    const char *base = (const char *)r;
    const unsigned bit = in_dim(r->dim);
    int j, k = 0;
    for (j = 0; j < SBC_COLUMNS; ++j) {
        const sbc_column *c = &sbc_columns[j];
        if (!(c->dimensions & bit))
            continue;
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
        ++k;
    }
    return k;
}

int sbc_column_count(int dim)
{
    int j, n = 0;
    for (j = 0; j < SBC_COLUMNS; ++j)
        n += (sbc_columns[j].dimensions & in_dim(dim)) != 0;
    return n;
}

const char *sbc_column_name(int dim, int k)
{
    const sbc_column *c = sbc_column_of(dim, k);
    return c ? c->name : NULL;
}

int sbc_column_index(int dim, const char *name)
{
    int j, k = 0;
    for (j = 0; name && j < SBC_COLUMNS; ++j)
        if (sbc_columns[j].dimensions & in_dim(dim)) {
            if (strcmp(sbc_columns[j].name, name) == 0)
                return k;
            ++k;
        }
    return -1;
}

int sbc_columns_header(int dim, char *out, size_t cap)
{
    size_t used = 0;
    int k;
    const sbc_column *c;
    for (k = 0; (c = sbc_column_of(dim, k)) != NULL; ++k) {
        const char *sep = k ? "," : "";
        if (used < cap)
            snprintf(out + used, cap - used, "%s%s", sep, c->name);
        used += strlen(sep) + strlen(c->name);
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
    /* 0.3.0: the components a 3D path adds (0 in 2D) */
    COLUMN("F13"), COLUMN("F23"), COLUMN("F31"), COLUMN("F32"), COLUMN("F33"),
    COLUMN("P13"), COLUMN("P23"), COLUMN("P31"), COLUMN("P32"), COLUMN("P33"),
    COLUMN("sigma13"), COLUMN("sigma23"), COLUMN("sigma31"), COLUMN("sigma32"), COLUMN("sigma33"),
};

int sbc_thermo_index(const char *column)
{
    int k;
    for (k = 0; k < SBC_THERMO_COUNT; ++k)
        if (sbc_thermo_vector[k].kind == SBC_THERMO_COLUMN && strcmp(sbc_thermo_vector[k].column, column) == 0)
            return k + 1;
    return 0;
}

double sbc_thermo_value(const sbc_controller *c, const sbc_result *last, int finished, int k)
{
    const sbc_thermo_entry *t;
    double values[SBC_COLUMNS], r[3];
    int iteration;
    if (k < 0 || k >= SBC_THERMO_COUNT)
        return 0.0;
    t = &sbc_thermo_vector[k];
    if (t->kind == SBC_THERMO_COLUMN) {
        const int at = sbc_column_index(last->dim, t->column);
        sbc_column_values(last, values);
        return at >= 0 ? values[at] : 0.0;
    }
    if (t->kind == SBC_THERMO_FINISHED)
        return finished;
    sbc_controller_progress(c, &iteration, &r[0], &r[1], &r[2]);
    return t->kind == SBC_THERMO_ITERATION ? iteration : r[t->kind - SBC_THERMO_R_FORCE];
}
