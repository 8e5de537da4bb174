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
 * Candidates (particle, edge) are collected within r + reach of the segment
 * and collected again once a particle or a frame centre has moved more than
 * reach / 2 since (a Verlet list), or when the host asks (its particle indices
 * changed). */
#ifndef SBC_SEAL_H
#define SBC_SEAL_H

#include "sbc/frame.h"
#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* w: where the wall meets a disc, in radii of the disc from the line of centres */
#define SBC_SEAL_WALL 0.5

/* The host's particles: n centres x (m) and forces f (N) with `stride`
 * doubles between particles (2 for packed 2D arrays, 3 for LAMMPS's x[i][3]),
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

typedef struct sbc_seal {
    double inward;   /* +1: frame order is counter-clockwise (inward normal = left of a -> b); -1 */
    double reach;    /* m */
    int count, cap;  /* candidates */
    int *particle;   /* [cap] host index */
    int *edge;       /* [cap] frame position q of the edge q -> q + 1 */
    int tracked;     /* particles tracked since the last collection (-1: collect at the next step) */
    double *x_built; /* [2 n] centres at the last collection */
    double *fx_built;/* [2 Q] frame centres at the last collection */
    int contacts;    /* walls touching a disc at the last step */
} sbc_seal;

/* reach: the Verlet margin (m, > 0; a quarter of the smallest radius suits).
 * The orientation is taken from the frame's reference centres. */
sbc_status sbc_seal_init(sbc_seal *s, const sbc_frame *f, double reach, sbc_error *err);
void sbc_seal_free(sbc_seal *s);

/* One step: the wall forces of the candidates, added to p->f, and their
 * reactions on the frame, added to reaction [3Q] (N, frame order; may be
 * NULL). fx [3Q]: the frame's centres now (m). kn: the normal stiffness of
 * the interior's contacts (N/m). collect: the host's particle indices have
 * changed since the last step (LAMMPS after a neighbour build). Returns the
 * walls' energy (J) in *energy. Fails only without memory. */
sbc_status sbc_seal_forces(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                           double kn, int collect, double *reaction, double *energy, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
