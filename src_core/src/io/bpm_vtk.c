/* servo_bc: VTK snapshot of the 3D bonded particle engine, for ParaView. */
#include "sbc/embedded/bpm_vtk.h"
#include "sbc/embedded/output_file.h"

#include "sbc/embedded/bpm_stress.h"

#include <stdio.h>
#include <stdlib.h>

sbc_status sbc_bpm_vtk_write(const char *prefix, const sbc_bpm *e, sbc_error *err)
{
    char path[1024];
    double *sigma;
    FILE *fp;
    size_t i;
    int q;
    if ((size_t)snprintf(path, sizeof path, "%s_spheres.vtk", prefix) >= sizeof path)
        return sbc_fail(err, SBC_ERR_INPUT, "vtk: prefix '%s' is too long (expected at most %zu characters)", prefix,
                        sizeof path - 14);
    sigma = malloc((9 * e->n + 1) * sizeof *sigma);
    if (!sigma)
        return sbc_fail(err, SBC_ERR_NOMEM, "vtk: out of memory");
    sbc_bpm_particle_stress(e, sigma, err);
    fp = sbc_output_open(path, SBC_OUTPUT_VTK, "vtk", err);
    if (!fp) {
        free(sigma);
        return err->status;
    }
    fprintf(fp, "# vtk DataFile Version 3.0\nservo_bc 3D bonded spheres\nASCII\nDATASET POLYDATA\nPOINTS %zu double\n",
            e->n);
    for (i = 0; i < e->n; ++i)
        fprintf(fp, "%.10g %.10g %.10g\n", e->x[3 * i], e->x[3 * i + 1], e->x[3 * i + 2]);
    fprintf(fp, "VERTICES %zu %zu\n", e->n, 2 * e->n);
    for (i = 0; i < e->n; ++i)
        fprintf(fp, "1 %zu\n", i);
    fprintf(fp, "POINT_DATA %zu\nSCALARS radius double 1\nLOOKUP_TABLE default\n", e->n);
    for (i = 0; i < e->n; ++i)
        fprintf(fp, "%.10g\n", e->r[i]);
    fprintf(fp, "SCALARS bonds int 1\nLOOKUP_TABLE default\n");
    for (i = 0; i < e->n; ++i)
        fprintf(fp, "%u\n", e->coordination[i]);
    fprintf(fp, "VECTORS velocity double\n");
    for (i = 0; i < e->n; ++i)
        fprintf(fp, "%.10g %.10g %.10g\n", e->v[3 * i], e->v[3 * i + 1], e->v[3 * i + 2]);
    fprintf(fp, "TENSORS stress double\n"); /* eq. 62, Pa */
    for (i = 0; i < e->n; ++i)
        for (q = 0; q < 3; ++q)
            fprintf(fp, "%.10g %.10g %.10g\n", sigma[9 * i + 3 * (size_t)q], sigma[9 * i + 3 * (size_t)q + 1],
                    sigma[9 * i + 3 * (size_t)q + 2]);
    free(sigma);
    return sbc_output_close(fp, path, "vtk", err);
}
