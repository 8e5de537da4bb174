/* Test helpers: a square lattice's centres, the seal chain, and the 37-disc
 * mixed layer of Sect. 5.3 used by several tests (generated periodic packing
 * n0 = 25, R_min = 0.8 mm, polydispersity 1.5, seed 1; Table 6 frictional
 * physics, dt = 5e-6 s). */
#ifndef SBC_TEST_LAYER_H
#define SBC_TEST_LAYER_H

#include "sbc/driver.h"
#include "sbc/embedded/engine.h"
#include "sbc/frame.h"
#include "sbc/packing.h"

#define LAYER_DT 5e-6
#define LAYER_KN 1e8

/* Fills p and its detected frame f and returns the engine on them (frame
 * set), damped by FIRE (fire = 1) or eq. 10 with 0.7 (fire = 0); NULL on
 * failure. The caller frees all three. */
sbc_engine *test_layer(sbc_packing *p, sbc_frame *f, int fire);

/* An N x N square lattice of discs of radius R, d apart, from the origin:
 * centres xy [2 N^2] (row by row), radii r [N^2]. */
void test_square_lattice(int N, double d, double R, double *xy, double *r);

/* The seal chain (tests/test_seal.c): a 5 x 5 lattice (spacing 2 mm, radius
 * 1 mm) without the middle disc of its bottom edge, and a chain in its
 * middle column standing on the wall of that gap: three discs at y = 0.52,
 * 2.52, 4.52 mm and one of radius 0.75 mm at 6.27 mm. Centres xy [2 x 28],
 * radii r [28]; returns the count, 28. */
int test_seal_chain(double *xy, double *r);

/* A host that relaxes its interior itself and has no linearized network (LAMMPS, LIGGGHTS, YADE through
 * the driver): a controller under s on the frame of a 5 x 5 lattice (d = 2 mm, R = 1.01 mm) and a driver
 * whose callbacks measure nothing. 1 when sbc_driver_create refuses s, with the message in err. */
int test_driver_refused(const sbc_settings *s, sbc_error *err);

#endif
