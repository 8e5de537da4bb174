/* Private: the frame's geometry that differs in kind between dimensions, one
 * row per dimension (as GSL's step types): the closed surface through the
 * frame's centres, its area vectors (eq. 2) and the test of a point against
 * it (confine.h). frame_2d.c holds the 2D row (a polygon), frame_3d.c the
 * 3D row (a polyhedron of quadrilaterals). */
#ifndef SBC_GEOMETRY_H
#define SBC_GEOMETRY_H

#include "sbc/frame.h"

typedef struct sbc_frame_geometry {
    int dim;
    const char *surface; /* the closed surface through the frame's centres, for messages */
    /* eq. 2: the area vectors A [3Q] and the reference volume V from X */
    void (*area_vectors)(sbc_frame *f);
    /* 1 when the point p [dim] is inside the surface through the centres fx [3Q] */
    int (*inside)(const sbc_frame *f, const double *fx, const double *p);
    /* sbc_frame_family (frame.h) */
    int (*family)(const sbc_frame *f, int q, int members[8]);
    /* sbc_frame_faces (frame.h) */
    int (*faces)(const sbc_frame *f, int q);
} sbc_frame_geometry;

extern const sbc_frame_geometry sbc_frame_geometry_2d, sbc_frame_geometry_3d;

/* The row of dimension dim; NULL for a dimension with none. */
const sbc_frame_geometry *sbc_frame_geometry_of(int dim);

#endif
