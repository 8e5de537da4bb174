/* VTK snapshots of a 3D servo_bc run (spheres_vtk.h). */
#include "sbc/embedded/spheres_vtk.h"
#include "sbc/embedded/output_file.h"
#include "vtk_parts.h"

#include <stdio.h>
#include <stdlib.h>

static void vectors(FILE *fp, const char *name, int n, const double *v)
{
    int k;
    fprintf(fp, "VECTORS %s double\n", name);
    for (k = 0; k < n; ++k)
        fprintf(fp, "%.12g %.12g %.12g\n", v[3 * k], v[3 * k + 1], v[3 * k + 2]);
}

static sbc_status close_file(FILE *fp, const char *name, sbc_error *err)
{
    return sbc_output_close(fp, name, "vtk", err);
}

sbc_status sbc_spheres_vtk_write(const char *prefix, int increment, const sbc_spheres_view *w,
                                 const sbc_frame *frame, sbc_error *err)
{
    char name[1024];
    unsigned char *in_frame = calloc((size_t)w->n, 1);
    FILE *fp;
    int k, q, triangles;
    if (!in_frame)
        return sbc_fail(err, SBC_ERR_NOMEM, "vtk: out of memory");
    for (q = 0; q < frame->n; ++q)
        in_frame[frame->particle[q]] = 1;
    if (!(fp = sbc_vtk_open(prefix, "spheres", increment, name, sizeof name, err))) {
        free(in_frame);
        return SBC_ERR_IO;
    }
    fprintf(fp, "# vtk DataFile Version 3.0\nservo_bc spheres, increment %d, step %ld\nASCII\nDATASET POLYDATA\n",
            increment, w->step);
    fprintf(fp, "POINTS %d double\n", w->n);
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%.12g %.12g %.12g\n", w->x[3 * k], w->x[3 * k + 1], w->x[3 * k + 2]);
    sbc_vtk_vertices(fp, w->n, w->r);
    fprintf(fp, "SCALARS frame int 1\nLOOKUP_TABLE default\n");
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "%d\n", in_frame[k]);
    free(in_frame);
    vectors(fp, "velocity", w->n, w->v);
    vectors(fp, "rotation", w->n, w->theta);
    vectors(fp, "force", w->n, w->f);
    if (close_file(fp, name, err) != SBC_OK)
        return err->status;

    if (!(fp = sbc_vtk_open(prefix, "frame", increment, name, sizeof name, err)))
        return SBC_ERR_IO;
    fprintf(fp, "# vtk DataFile Version 3.0\nservo_bc frame surface, increment %d\nASCII\nDATASET POLYDATA\n",
            increment);
    fprintf(fp, "POINTS %d double\n", frame->n);
    for (q = 0; q < frame->n; ++q) {
        const double *x = &w->x[3 * frame->particle[q]];
        fprintf(fp, "%.12g %.12g %.12g\n", x[0], x[1], x[2]);
    }
    /* a triangle, stored as the cell (i, j, k, i), is written as one */
    for (k = 0, triangles = 0; k < frame->ncell; ++k)
        triangles += frame->cell[4 * k + 3] == frame->cell[4 * k];
    fprintf(fp, "POLYGONS %d %d\n", frame->ncell, 5 * frame->ncell - triangles);
    for (k = 0; k < frame->ncell; ++k) {
        const int *c = &frame->cell[4 * k];
        if (c[3] == c[0])
            fprintf(fp, "3 %d %d %d\n", c[0], c[1], c[2]);
        else
            fprintf(fp, "4 %d %d %d %d\n", c[0], c[1], c[2], c[3]);
    }
    fprintf(fp, "POINT_DATA %d\nVECTORS reaction double\n", frame->n);
    for (q = 0; q < frame->n; ++q) {
        const double *f = &w->f[3 * frame->particle[q]];
        fprintf(fp, "%.12g %.12g %.12g\n", -f[0], -f[1], -f[2]);
    }
    return close_file(fp, name, err);
}
