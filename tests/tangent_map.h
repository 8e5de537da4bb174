/* Test helper: a material point's condensed tangent against the derivative of its increment's map. */
#ifndef SBC_TEST_TANGENT_MAP_H
#define SBC_TEST_TANGENT_MAP_H

#include "sbc/material_point.h"

/* The point of def sheared in four steps k = 1..4 of F_shear = 0.001 k (component `shear` of F, 3i + j) with
 * F_normal = 1 - 0.0005 k (component `normal`), the first three committed; then its condensed tangent C and the
 * central differences D (step 1e-7) of the map from the committed state F -> P at the fourth. Returns
 * |C - D| / |D| (Frobenius), or -1 with the message in err when the point, an integrate or the tangent failed. */
double tangent_map_gap(const sbc_point_def *def, int shear, int normal, double C[81], double D[81], sbc_error *err);

#endif
