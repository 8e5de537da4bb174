/* Private: what the frame's files share (frame.c, frame_2d.c, frame_3d.c,
 * frame_3d_periodic.c, frame_3d_detect.c). */
#ifndef SBC_FRAME_PRIVATE_H
#define SBC_FRAME_PRIVATE_H

#include "sbc/frame.h"

/* Zeroes f and allocates its arrays for q positions of dimension dim (the
 * vectors' third slots 0); frees them and fails with SBC_ERR_NOMEM. */
sbc_status sbc_frame_alloc(sbc_frame *f, int dim, int q, sbc_error *err);

/* 3D: the faces' names, xlo ... zhi, by SBC_FACE_ bit */
extern const char *const sbc_frame_face_name[6];

/* 3D: the number of faces in side (its SBC_FACE_ bits) */
int sbc_frame_face_count(int side);

/* 3D: a frame particle found by a detection: its packing index, its
 * SBC_FACE_ bits, its rank (0 corner, 1 edge, 2 face) and its centre */
typedef struct sbc_frame_item {
    int particle, side, rank;
    const double *x;
} sbc_frame_item;

/* 3D: the frame of the m items (sorted here into frame order: the eight
 * corners by their index, then edge and face particles by their faces, then
 * z, y, x), radii r by packing index; partner -1, no cells, no images. */
sbc_status sbc_frame_from_items_3d(sbc_frame *f, sbc_frame_item *it, int m, const double *r, sbc_error *err);

/* 3D: the frame of a packing whose faces are a lattice's (frame_3d.c) */
sbc_status sbc_frame_detect_grid_3d(sbc_frame *f, int n, const double *x, const double *r, double band,
                                    sbc_error *err);

/* 3D: the frame of a geometrically periodic sphere packing
 * (frame_3d_periodic.c). *cube is 0 when no eight spheres of one radius
 * sit at the corners of a cuboid as each other's images (err untouched),
 * else 1 and the status of the detection in that cuboid. */
sbc_status sbc_frame_detect_periodic_3d(sbc_frame *f, int n, const double *x, const double *r, int *cube,
                                        sbc_error *err);

#endif
