/* Private: what the VTK writers share (vtk.c, spheres_vtk.c). */
#ifndef SBC_VTK_PARTS_H
#define SBC_VTK_PARTS_H

#include "sbc/status.h"

#include <stdio.h>

/* PREFIX_WHAT_NNNNNN.vtk (its name into name [len]) opened for writing;
 * NULL with err when it cannot be */
FILE *sbc_vtk_open(const char *prefix, const char *what, int increment, char *name, size_t len, sbc_error *err);

/* after the POINTS: each of the n points a vertex, then the point data's
 * first array, the radii r [n] (m) */
void sbc_vtk_vertices(FILE *fp, int n, const double *r);

#endif
