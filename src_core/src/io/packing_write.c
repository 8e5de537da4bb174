/* Packing writers: one packing, read by every host (text, LAMMPS and LIGGGHTS data, YADE). */
#include "sbc/packing.h"
#include "sbc/embedded/output_file.h"

#include <math.h>
#include <stdio.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static sbc_status finish(FILE *fp, const char *path, sbc_error *err)
{
    return sbc_output_close(fp, path, "write_packing", err);
}

static sbc_status open_for_writing(FILE **fp, int n, const char *path, sbc_error *err)
{
    if (n < 1)
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing: no particles to write to '%s'", path);
    if (!(*fp = sbc_output_open(path, SBC_OUTPUT_PACKING, "write_packing", err)))
        return err->status;
    return SBC_OK;
}

sbc_status sbc_packing_write_text(const sbc_packing *p, const char *path, sbc_error *err)
{
    FILE *fp;
    int k;
    sbc_status st = open_for_writing(&fp, p->n, path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# servo_bc packing: %d discs, x y r (m)\n", p->n);
    if (p->has_box)
        fprintf(fp, "box %.17g %.17g %.17g %.17g\n", p->box[0], p->box[1], p->box[2], p->box[3]);
    for (k = 0; k < p->n; ++k)
        fprintf(fp, "%.17g %.17g %.17g\n", p->x[2 * k], p->x[2 * k + 1], p->r[k]);
    return finish(fp, path, err);
}

/* The data file of atom_style sphere (id type diameter density x y z) of n
 * particles with centres x [dim n]. 2D: for a host whose 2D sphere mass is
 * 4/3 pi R^3 density (LAMMPS: sphere_mass 1) or pi R^2 density (LIGGGHTS: 0);
 * the density column makes both M = rho_A pi R^2. 3D: both hosts give M =
 * 4/3 pi R^3 density, the density column is rho (kg/m^3). */
static sbc_status write_data(int dim, int n, const double *x, const double *r, const int *is_frame, double density,
                             int sphere_mass, const char *path, sbc_error *err)
{
    const char *host = sphere_mass ? "lammps" : "liggghts";
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, rmax = 0.0;
    FILE *fp;
    int k, c;
    sbc_status st;
    if (!(density > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing %s: density %g is not positive", host, density);
    if ((st = open_for_writing(&fp, n, path, err)) != SBC_OK)
        return st;
    for (k = 0; k < n; ++k) {
        for (c = 0; c < dim; ++c) {
            if (x[dim * k + c] - r[k] < lo[c]) lo[c] = x[dim * k + c] - r[k];
            if (x[dim * k + c] + r[k] > hi[c]) hi[c] = x[dim * k + c] + r[k];
        }
        if (r[k] > rmax) rmax = r[k];
    }
    if (dim == 2) {
        fprintf(fp, "%s data file: servo_bc packing of %d discs (SI; type 2 = frame, 1 = interior; density column %s "
                    "gives M = rho_A pi R^2 with rho_A = %.17g kg/m^2)\n\n", sphere_mass ? "LAMMPS" : "LIGGGHTS", n,
                sphere_mass ? "3 rho_A / (4 R)" : "rho_A", density);
        lo[2] = hi[2] = 0.0; /* z from -rmax to rmax */
    } else {
        fprintf(fp, "%s data file: servo_bc packing of %d spheres (SI; type 2 = frame, 1 = interior; M = 4/3 pi R^3 "
                    "rho with rho = %.17g kg/m^3)\n\n", sphere_mass ? "LAMMPS" : "LIGGGHTS", n, density);
    }
    fprintf(fp, "%d atoms\n2 atom types\n\n", n);
    /* one diameter of margin around the particles: the box holds them as they move */
    fprintf(fp, "%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\n", lo[0] - 2 * rmax,
            hi[0] + 2 * rmax, lo[1] - 2 * rmax, hi[1] + 2 * rmax, dim == 2 ? -rmax : lo[2] - 2 * rmax,
            dim == 2 ? rmax : hi[2] + 2 * rmax);
    fprintf(fp, "Atoms # sphere\n\n");
    for (k = 0; k < n; ++k) {
        const double rho = dim == 3 || !sphere_mass ? density : 0.75 * density / r[k];
        if (dim == 2)
            fprintf(fp, "%d %d %.17g %.17g %.17g %.17g 0\n", k + 1, is_frame && is_frame[k] ? 2 : 1, 2.0 * r[k], rho,
                    x[2 * k], x[2 * k + 1]);
        else
            fprintf(fp, "%d %d %.17g %.17g %.17g %.17g %.17g\n", k + 1, is_frame && is_frame[k] ? 2 : 1, 2.0 * r[k],
                    rho, x[3 * k], x[3 * k + 1], x[3 * k + 2]);
    }
    return finish(fp, path, err);
}

/* LAMMPS 29Sep2021 (Debian) gives spheres M = 4/3 pi R^3 density even with
 * dimension 2 */
sbc_status sbc_packing_write_lammps(const sbc_packing *p, const int *is_frame, double density, const char *path,
                                    sbc_error *err)
{
    return write_data(2, p->n, p->x, p->r, is_frame, density, 1, path, err);
}

/* LIGGGHTS 3.8 gives 2D spheres M = pi R^2 density (measured: 6.537e-3 kg for
 * R = 1.02 mm, density 2e3) */
sbc_status sbc_packing_write_liggghts(const sbc_packing *p, const int *is_frame, double density, const char *path,
                                      sbc_error *err)
{
    return write_data(2, p->n, p->x, p->r, is_frame, density, 0, path, err);
}

sbc_status sbc_packing_write_yade(const sbc_packing *p, const int *is_frame, const char *path, sbc_error *err)
{
    FILE *fp;
    int k;
    sbc_status st = open_for_writing(&fp, p->n, path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# servo_bc packing: %d discs, x y z r (m) frame (1 = frame particle), for yade.ymport.text\n",
            p->n);
    for (k = 0; k < p->n; ++k)
        fprintf(fp, "%.17g %.17g 0 %.17g %d\n", p->x[2 * k], p->x[2 * k + 1], p->r[k], is_frame && is_frame[k]);
    return finish(fp, path, err);
}

sbc_status sbc_spheres_write_data(int n, const double *x, const double *r, const int *is_frame, double density,
                                  const char *host, const char *path, sbc_error *err)
{
    return write_data(3, n, x, r, is_frame, density, host[1] == 'a', path, err);
}

sbc_status sbc_spheres_write_yade(int n, const double *x, const double *r, const int *is_frame, const char *path,
                                  sbc_error *err)
{
    FILE *fp;
    int k;
    sbc_status st = open_for_writing(&fp, n, path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# servo_bc packing: %d spheres, x y z r (m) frame (1 = frame particle), for yade.ymport.text\n", n);
    for (k = 0; k < n; ++k)
        fprintf(fp, "%.17g %.17g %.17g %.17g %d\n", x[3 * k], x[3 * k + 1], x[3 * k + 2], r[k], is_frame && is_frame[k]);
    return finish(fp, path, err);
}

sbc_status sbc_spheres_write_text(int n, const double *x, const double *r, const char *path, sbc_error *err)
{
    FILE *fp;
    int k;
    sbc_status st = open_for_writing(&fp, n, path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# servo_bc packing: %d spheres, x y z r (m)\n", n);
    for (k = 0; k < n; ++k)
        fprintf(fp, "%.17g %.17g %.17g %.17g\n", x[3 * k], x[3 * k + 1], x[3 * k + 2], r[k]);
    return finish(fp, path, err);
}
