#include "sbc/embedded/vtk.h"
#include "sbc/embedded/output_file.h"
#include "vtk_parts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

FILE *sbc_vtk_open(const char *prefix, const char *what, int increment, char *name, size_t len, sbc_error *err)
{
    snprintf(name, len, "%s_%s_%06d.vtk", prefix, what, increment);
    return sbc_output_open(name, SBC_OUTPUT_VTK, "vtk", err);
}

void sbc_vtk_vertices(FILE *fp, int n, const double *r)
{
    int k;
    fprintf(fp, "VERTICES %d %d\n", n, 2 * n);
    for (k = 0; k < n; ++k)
        fprintf(fp, "1 %d\n", k);
    fprintf(fp, "POINT_DATA %d\nSCALARS radius double 1\nLOOKUP_TABLE default\n", n);
    for (k = 0; k < n; ++k)
        fprintf(fp, "%.12g\n", r[k]);
}

static double overlap(const sbc_engine_view *w, int k)
{
    int i = w->pair_i[k], j = w->pair_j[k];
    double dx = w->x[2 * j] - w->x[2 * i], dy = w->x[2 * j + 1] - w->x[2 * i + 1];
    return w->r[i] + w->r[j] - sqrt(dx * dx + dy * dy);
}

static int bonded(const sbc_engine_view *w, int k) { return w->pair_bond && w->pair_bond[k]; }

/* a pair carries force when it overlaps or holds an intact bond (which may be in tension) */
static int carries(const sbc_engine_view *w, int k) { return overlap(w, k) > 0.0 || bonded(w, k); }

sbc_status sbc_vtk_write(const char *prefix, int increment, const sbc_engine_view *w, sbc_error *err)
{
    char name[1024];
    FILE *fp;
    int k, nc = 0;

    fp = sbc_vtk_open(prefix, "particles", increment, name, sizeof name, err);
    if (!fp)
        return SBC_ERR_IO;
    fprintf(fp, "# vtk DataFile Version 3.0\nservo_bc particles, increment %d, t = %.9g s\nASCII\nDATASET POLYDATA\n",
            increment, w->time);
    fprintf(fp, "POINTS %d double\n", w->n);
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%.12g %.12g 0\n", w->x[2 * k], w->x[2 * k + 1]);
    sbc_vtk_vertices(fp, w->n, w->r);
    fprintf(fp, "SCALARS rotation double 1\nLOOKUP_TABLE default\n");
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%.12g\n", w->theta[k]);
    fprintf(fp, "SCALARS frame int 1\nLOOKUP_TABLE default\n");
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%d\n", (int)w->kinematic[k]);
    fprintf(fp, "VECTORS velocity double\n");
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%.12g %.12g 0\n", w->v[2 * k], w->v[2 * k + 1]);
    if (sbc_output_close(fp, name, "vtk", err) != SBC_OK)
        return err->status;

    for (k = 0; k < w->pair_count; ++k)
        nc += carries(w, k);
    fp = sbc_vtk_open(prefix, "contacts", increment, name, sizeof name, err);
    if (!fp)
        return SBC_ERR_IO;
    fprintf(fp, "# vtk DataFile Version 3.0\nservo_bc contact network, increment %d\nASCII\nDATASET POLYDATA\n",
            increment);
    fprintf(fp, "POINTS %d double\n", w->n);
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%.12g %.12g 0\n", w->x[2 * k], w->x[2 * k + 1]);
    fprintf(fp, "LINES %d %d\n", nc, 3 * nc);
    for (k = 0; k < w->pair_count; ++k)
        if (carries(w, k))
            fprintf(fp, "2 %d %d\n", w->pair_i[k], w->pair_j[k]);
    fprintf(fp, "CELL_DATA %d\nSCALARS normal_force double 1\nLOOKUP_TABLE default\n", nc);
    for (k = 0; k < w->pair_count; ++k)
        if (carries(w, k))
            fprintf(fp, "%.12g\n", w->law.kn * overlap(w, k)); /* eqs. 6-7: fn = kn dn */
    fprintf(fp, "SCALARS overlap double 1\nLOOKUP_TABLE default\n");
    for (k = 0; k < w->pair_count; ++k)
        if (carries(w, k))
            fprintf(fp, "%.12g\n", overlap(w, k));
    fprintf(fp, "SCALARS bond int 1\nLOOKUP_TABLE default\n");
    for (k = 0; k < w->pair_count; ++k)
        if (carries(w, k))
            fprintf(fp, "%d\n", bonded(w, k));
    return sbc_output_close(fp, name, "vtk", err);
}
