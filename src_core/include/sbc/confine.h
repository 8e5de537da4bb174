/* servo_bc: is the packing still held by its frame? One check, shared by the
 * embedded runner and every host, so that all of them stop alike.
 *
 * An interior particle whose centre has left the polygon of the frame's
 * centres has slipped through a gap between frame particles: nothing confines
 * it any more, and no later increment can be trusted (the mixed layer of
 * Sect. 5.3 near increment 80, docs/cross-host.md). No generated packing or
 * lattice starts with such a particle. The runner and the hosts check every
 * 10^4 steps, at every converged increment (before its row is kept) and when
 * the servo fails: an escaped particle explains a stalled servo better than
 * its residuals do. */
#ifndef SBC_CONFINE_H
#define SBC_CONFINE_H

#include "sbc/frame.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Steps between two checks during a relaxation. */
#define SBC_CONFINE_EVERY 10000

/* The frame's centres fx [3Q] (m, frame order) prepared for the tests of
 * one check over many particles (borrowed: f and fx must outlive it): the
 * box of the centres (outside it, outside) and the open box bounded by the
 * innermost centre of each side, which no segment or cell of the surface
 * meets, inside or outside as its centre is. Most particles are decided in
 * O(1), the others by the full test. */
typedef struct sbc_confine {
    const sbc_frame *frame;
    const double *fx;
    double lo[SBC_DIM_MAX], hi[SBC_DIM_MAX];       /* the box of the centres, m */
    double in_lo[SBC_DIM_MAX], in_hi[SBC_DIM_MAX]; /* the open box no side meets, m */
    int inner;                                      /* -1 no such box, else 1 inside, 0 outside */
} sbc_confine;

/* O(Q): one pass and one full test. */
void sbc_confine_prepare(sbc_confine *c, const sbc_frame *f, const double *fx);

/* 1 when p [dim] (m) lies inside the closed surface through the frame's
 * centres (in 2D their polygon, by the even-odd rule; in 3D the polyhedron of
 * the surface's cells, by a ray's crossings), else 0. O(1) in the prepared
 * boxes, O(Q) near the surface. */
int sbc_confine_inside(const sbc_confine *c, const double *p);

/* One interior particle, numbered id by the host (for the message), at x
 * [dim] (m) with velocity v [dim] (m/s), against the frame's centres as
 * prepared in c. increment: the increment under way, whose results are not
 * kept when the check fails. Returns SBC_OK, or fails with
 *   SBC_ERR_NUMERIC   a non-finite position, or a moving particle more than
 *                     the frame's width beyond it (the packing blew up);
 *   SBC_ERR_GEOMETRY  a particle that slipped out through a gap. */
sbc_status sbc_confine_check(const sbc_confine *c, int increment, long id, const double *x, const double *v,
                             sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
