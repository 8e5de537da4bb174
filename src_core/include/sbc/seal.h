/* servo_bc: the frame's seal (keyword `seal`, docs/servo_bc.md "Seal").
 *
 * The frame of an irregular packing is a ring of discs that do not all
 * touch: under large shear an interior disc can pass between two of them
 * (confine.h). With the seal on, each edge of the polygon of the frame's
 * centres, in frame order, is a frictionless wall for the interior discs: a
 * disc of radius r whose centre lies at signed distance s < w r (w =
 * SBC_SEAL_WALL) on the inner side of the segment between frame centres a and
 * b, at parameter t = (p - a).(b - a) / |b - a|^2 strictly inside (0, 1), is
 * pushed inwards by
 *
 *   f = kn (w r - s) n                                 (n: the edge's inward unit normal)
 *
 * and frame particles a and b take -(1 - t) f and -t f. The wall point
 * a + t (b - a) moves as (1 - t) v_a + t v_b, so the split does the same work
 * as f at that point (the boundary work of eq. 30 is still that of the frame
 * particles' forces), and it acts on the line of centres: no moment on either.
 * Energy kn (w r - s)^2 / 2.
 *
 * The wall stands half a radius inside the disc's reach so that it leaves
 * every packing as it is until a disc is on its way out: a disc of radius r
 * touching two frame discs of radius r meets it only when their gap exceeds
 * 1.87 r (it passes through at 2 r); at w = 1 it would meet discs resting in
 * gaps of 1.46 r, which the generated packings have (docs/servo_bc.md,
 * "Seal": w = 1 moved sigma11 of the 232-disc packing by 4 % before any
 * loading).
 *
 * Frame particles meet the walls too, all but the two edges they end: under
 * (T) the frame's discs are free, and at the corners that shear makes acute
 * the uniform tractions squeeze them out along the edges (a disc of the left
 * edge slid around the corner disc below the bottom edge, the 232-disc packing
 * at F12 = 0.2): the walls keep the polygon from folding.
 *
 * In 3D the walls are the triangles of the closed surface through the
 * frame's centres (sbc_frame.cell: a triangle (a, b, c, a) as it is, a
 * quadrilateral (a, b, c, d) as (a, b, c) and (a, c, d)): a sphere of radius r
 * whose centre lies at signed distance s < w r on the inner side of a
 * triangle's plane, projecting strictly inside it (barycentric coordinates
 * l_a, l_b, l_c all > 0), is pushed along the inward unit normal n by the
 * same f, and the triangle's corners take -l_a f, -l_b f and -l_c f: the
 * wall point l_a x_a + l_b x_b + l_c x_c moves with the corners' velocities
 * so weighted, and the split is that force at that point again (the same
 * work, no moment). No interior sphere of the generated packings measured
 * comes within r/2 of a wall (docs/frame3d.md, "Seal"). A frame sphere
 * meets the triangles of the faces it does not lie on (an edge sphere's
 * centre is off the edge line and outside the next triangles of its own
 * faces). A triangle that faces into the box (the face its corners share
 * points the other way: an edge sphere moved onto its edge line for the
 * triangulation can fold the triangle beside it) is no wall: it would push
 * the spheres inside out.
 *
 * Candidates (particle, wall) are collected within r + reach of the segment
 * or triangle and collected again once a particle or a frame centre has
 * moved more than reach / 2 since (a Verlet list), or when the host asks
 * (its particle indices changed). */
#ifndef SBC_SEAL_H
#define SBC_SEAL_H

#include "sbc/frame.h"
#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* w: where the wall meets a disc, in radii of the disc from the line of
 * centres (3D: a sphere, from the triangle's plane) */
#define SBC_SEAL_WALL 0.5

/* The host's particles: n centres x (m) and forces f (N) with `stride`
 * doubles between particles (2 for packed 2D arrays, 3 for LAMMPS's x[i][3]
 * and for packed 3D arrays; in 3D at least 3),
 * radii r [n] (m). frame(ctx, k): the frame position q of particle k, -1
 * for an interior particle, -2 for one the servo does not hold (ignored). */
typedef struct sbc_seal_particles {
    int n;
    const double *x;
    double *f;
    int stride;
    const double *r;
    int (*frame)(const void *ctx, int k);
    const void *ctx;
} sbc_seal_particles;

/* The particles of packed arrays: x and f [dim n] (stride dim), radii r
 * [n], and slot [n] the frame position of each particle (-1 interior), all
 * borrowed. */
sbc_seal_particles sbc_seal_packed(int n, const double *x, double *f, int dim, const double *r, const int *slot);

/* slot for sbc_seal_packed: the frame position of each of n particles, -1
 * for the interior (malloc'd, the caller frees it; NULL without memory). */
int *sbc_seal_slots(const sbc_frame *f, int n);

typedef struct sbc_seal {
    int dim;         /* the frame's: 2 walls are segments, 3 triangles */
    double inward;   /* 2D: +1 when frame order is counter-clockwise (inward normal = left of a -> b),
                        else -1; 3D: +1 when (b - a) x (c - a) of the walls points inward, else -1 */
    double reach;    /* m */
    int nwall;       /* 2D: Q, the edge q -> q + 1 is wall q; 3D: the triangles */
    int *corner;     /* 3D: [3 nwall] frame positions of each triangle's corners; NULL in 2D */
    int count, cap;  /* candidates */
    int *particle;   /* [cap] host index */
    int *edge;       /* [cap] the wall */
    int tracked;     /* particles tracked since the last collection (-1: collect at the next step) */
    double *x_built; /* [dim n] centres at the last collection */
    double *fx_built;/* [3 Q] frame centres at the last collection */
    int contacts;    /* walls touching a particle at the last step */
} sbc_seal;

/* reach: the Verlet margin (m, > 0; a quarter of the smallest radius suits).
 * The orientation is taken from the frame's reference centres (2D: the
 * polygon's area; 3D: the volume the triangles enclose). */
sbc_status sbc_seal_init(sbc_seal *s, const sbc_frame *f, double reach, sbc_error *err);
void sbc_seal_free(sbc_seal *s);

/* One step: the wall forces of the candidates, added to p->f (the first dim
 * components of each particle's), and their
 * reactions on the frame, added to reaction [3Q] (N, frame order; may be
 * NULL). fx [3Q]: the frame's centres now (m). kn: the normal stiffness of
 * the interior's contacts (N/m). collect: the host's particle indices have
 * changed since the last step (LAMMPS after a neighbour build). Returns the
 * walls' energy (J) in *energy. Fails only without memory. */
sbc_status sbc_seal_forces(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                           double kn, int collect, double *reaction, double *energy, sbc_error *err);

/* sbc_seal_forces on packed arrays (sbc_seal_packed) whose indices are the
 * frame's (f->particle), with the reactions added to the frame particles'
 * forces in p->f too (reaction [3Q]: zeroed and filled as there). */
sbc_status sbc_seal_forces_packed(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                                  double kn, double *reaction, double *energy, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
