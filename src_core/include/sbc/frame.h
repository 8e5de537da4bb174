/* servo_bc: the frame of boundary particles (paper Sect. 2.1).
 *
 * The frame is stored in "frame order": anticlockwise, starting at the
 * bottom-left corner, i.e. BL, bottom edge (x ascending), BR, right edge
 * (y ascending), TR, top edge (x descending), TL, left edge (y descending).
 * All per-frame arrays of the library are indexed by this frame position. */
#ifndef SBC_FRAME_H
#define SBC_FRAME_H

#include <stddef.h>

#include "sbc/packing.h"
#include "sbc/status.h"
#include "sbc/tensor.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_side {
    SBC_SIDE_CORNER = 0,
    SBC_SIDE_BOTTOM,
    SBC_SIDE_RIGHT,
    SBC_SIDE_TOP,
    SBC_SIDE_LEFT
} sbc_side;

enum { SBC_CORNER_BL = 0, SBC_CORNER_BR, SBC_CORNER_TR, SBC_CORNER_TL };

/* 3D: the faces of the box a frame particle lies on, the bits of its side
 * (one bit: a face particle, two: an edge, three: a corner). */
enum { SBC_FACE_XLO = 1, SBC_FACE_XHI = 2, SBC_FACE_YLO = 4, SBC_FACE_YHI = 8, SBC_FACE_ZLO = 16, SBC_FACE_ZHI = 32 };

/* Vectors are stored in SBC_DIM_MAX slots (tensor.h): X_q is X[3q .. 3q+2],
 * its third slot 0 in 2D. The detection functions below are those of the 2D
 * frame (frame_2d.c, host centres x [2n]) but sbc_frame_detect_3d
 * (frame_3d.c, x [3n]). */
typedef struct sbc_frame {
    int dim;        /* 2 or 3 */
    int n;          /* Q, number of frame particles */
    int *particle;  /* [Q] index of the particle in the host's packing */
    int *side;      /* [Q] sbc_side of each frame position (3D: its SBC_FACE_ bits) */
    int *partner;   /* [Q] frame position of the periodic partner (+/-), -1 for corners (3D: for
                       face particles, the one on the opposite face; -1 on edges and corners) */
    int corner[8];  /* frame positions of the corners BL, BR, TR, TL (3D: corner c at the low
                       or high x, y, z as bits 1, 2, 4 of c say) */
    double *X;      /* [3Q] reference centre positions X_q, m */
    double *R;      /* [Q] radii R_q, m */
    double *A;      /* [3Q] area vectors A_q of eq. 2, m (a length in 2D) */
    double V;       /* reference volume from the corner centres, m^2 (3D: enclosed by the
                       surface through the centres, m^3) */
    int ncell;      /* 3D: the surface through the centres, ncell quadrilaterals of frame
                       positions (a triangle (i, j, k) as (i, j, k, i)) */
    int *cell;      /* positions [4 ncell], anticlockwise seen from outside; 0 and NULL in 2D */
    int *image;     /* 3D: [3Q] the frame position of q's periodic image across axis a (the same
                       place on the opposite face of a) at 3q + a, -1 where q lies on no face of a
                       or the opposite faces' places differ; NULL in 2D */
} sbc_frame;

/* Detects the frame from the particles' centres: particles whose centre lies
 * within `band` (m) of the bounding box of all centres form the edges; the
 * particle on two adjacent edges is that corner. band <= 0 selects half the
 * smallest radius. Fails with SBC_ERR_FRAME when the four corners are not
 * unique or an edge is empty. x is [2n], r is [n]. */
sbc_status sbc_frame_detect(sbc_frame *frame, int n, const double *x,
                            const double *r, double band, sbc_error *err);

/* Detects the frame of a geometrically periodic packing (Sect. 4.2): the
 * discs crossing the edges of the rectangle box = {xlo, xhi, ylo, yhi} (m)
 * form the frame; the disc crossing two adjacent edges is that corner. Fails
 * with SBC_ERR_FRAME when a corner is missing or shared, a disc crosses
 * opposite edges, or an edge particle has no copy at exactly +-L. */
sbc_status sbc_frame_detect_box(sbc_frame *frame, int n, const double *x, const double *r, const double box[4],
                                sbc_error *err);

/* The frame of a packing: sbc_frame_detect_box when the packing declares
 * its periodic square, sbc_frame_detect (default band) otherwise. */
sbc_status sbc_frame_detect_packing(sbc_frame *frame, const sbc_packing *p, sbc_error *err);

/* Builds the frame from an explicit list of particle indices (a host's frame
 * group): corners and edges are found as in sbc_frame_detect, with the
 * bounding box of the listed centres, and a listed particle outside every
 * band is assigned to its nearest edge. */
sbc_status sbc_frame_from_list(sbc_frame *frame, int count, const int *list,
                               const double *x, const double *r, sbc_error *err);

/* The frame of a sphere packing in a cuboid (3D; x [3n], r [n]), in one of
 * two kinds, tried in this order:
 * - Lattice faces (frame_3d.c): particles whose centre lies within band (m;
 *   <= 0: half the smallest radius) of a face of the bounding box of the
 *   centres, one at each of the eight corners, each face's centres a grid:
 *   its quadrilaterals are the surface, each giving a quarter of its area
 *   vector to each of its four corners (eq. 2 in 3D).
 * - A geometrically periodic packing (frame_3d_periodic.c, as the 3D
 *   generator reconstructs it): eight spheres of one radius at the corners
 *   of a cuboid that every sphere meets, each the others' image at +-L; the
 *   frame is every sphere crossing a face of that cuboid, each with its
 *   images at exactly +-L across the faces it crosses. Each face is
 *   triangulated (Delaunay, with its edge spheres moved onto the edge
 *   lines), a high face through the images of its low face's triangles
 *   (stored as cells (i, j, k, i): a third of a triangle's vector area to
 *   each corner); V is L^3.
 * Either way sum_q X_q (x) A_q = V I, every particle on a face has its
 * periodic image on the opposite face (image; partner for face particles),
 * and the frame order is the corners, the edge particles, the face
 * particles. Fails with SBC_ERR_FRAME naming the corner, face or particle
 * at fault. */
sbc_status sbc_frame_detect_3d(sbc_frame *frame, int n, const double *x, const double *r, double band,
                               sbc_error *err);

/* (P)'s periodic families (eqs. 19, 32-34): the frame positions that are
 * periodic images of one another and move together. For a family's first
 * member q writes the family into members and returns its size (2D: a
 * bottom or right particle and its partner, 2; the corners under BL, 4. 3D:
 * a particle on the low face of each axis it lies on and its images, a face
 * pair 2, an edge quadruple 4, the corners under corner[0], 8); 0 for the
 * other members; -1 when q has no periodic image (partner) on an opposite
 * face (edge). The corners' family follows F (eq. 17). */
int sbc_frame_family(const sbc_frame *f, int q, int members[8]);

/* The faces of the box frame position q lies on, as SBC_FACE_* bits (2D:
 * bottom ylo, right xhi, top yhi, left xlo; a corner on two). */
int sbc_frame_faces(const sbc_frame *f, int q);

/* Recomputes A_q (eq. 2) and V from frame->X and frame->R. */
void sbc_frame_update_geometry(sbc_frame *frame);

/* The frame's centres in frame order, fx [3Q] (m), gathered from the
 * centres x [dim n] of the host's packing. */
void sbc_frame_centres(const sbc_frame *frame, const double *x, double *fx);

/* Restart support: the frame as a flat array of doubles (its reference
 * positions cannot be detected again from a deformed packing).
 * sbc_frame_state_size gives the count, sbc_frame_save writes it,
 * sbc_frame_load rebuilds a frame (fails on a malformed array). */
size_t sbc_frame_state_size(const sbc_frame *frame);
void sbc_frame_save(const sbc_frame *frame, double *out);
sbc_status sbc_frame_load(sbc_frame *frame, const double *in, size_t n, sbc_error *err);

/* A deep copy of src into dst (which is overwritten, not freed). */
sbc_status sbc_frame_copy(sbc_frame *dst, const sbc_frame *src, sbc_error *err);

/* Frees the arrays of frame and zeroes it. */
void sbc_frame_free(sbc_frame *frame);

#ifdef __cplusplus
}
#endif

#endif
