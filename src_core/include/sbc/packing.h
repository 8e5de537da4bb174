/* servo_bc: packings of discs (centres and radii). */
#ifndef SBC_PACKING_H
#define SBC_PACKING_H

#include "sbc/status.h"

typedef struct sbc_packing {
    int n;
    double *x; /* [2n] centres, m */
    double *r; /* [n] radii, m */
} sbc_packing;

/* Regular square lattice of Sect. 4.1: nx by ny discs of radius `radius`
 * with centres `spacing` apart, the first at the origin (m). */
sbc_status sbc_packing_lattice_square(sbc_packing *p, int nx, int ny, double spacing, double radius,
                                      sbc_error *err);

/* Reads "x y r" per line (m); '#' starts a comment; errors name the line. */
sbc_status sbc_packing_read(sbc_packing *p, const char *path, sbc_error *err);

void sbc_packing_free(sbc_packing *p);

#endif
