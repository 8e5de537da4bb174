/* servo_bc: irregular polydisperse periodic packings (paper Sect. 4.2).
 *
 * Method: radius expansion with overlap minimization in a periodic square (a
 * jamming protocol). n discs with radii uniform in [R_min, pd R_min] are
 * placed at random in a periodic box; the box shrinks in small steps and,
 * after each, the overlaps are relaxed by FIRE minimization of
 * sum (overlap^2)/2; the box stops shrinking when the overlaps can no longer be
 * removed (jamming), and the last unjammed box is kept. We chose it over a
 * Lubachevsky-Stillinger event-driven code because it is short, deterministic
 * for a seed, needs no event calendar, and jams polydisperse discs at packing
 * fractions near the paper's 0.83-0.85. A second protocol (SBC_GENERATE_PRESSURE,
 * below) jams large packings in one compression instead.
 *
 * Then the geometrically periodic reconstruction of Sect. 4.2: the square is
 * shifted so that one particle's centre sits at a corner (that particle, copied
 * to the three other corners, gives the frame its four corners: disc 0, or the
 * largest disc when R_max > (1 + sqrt 2) r_0, so that no other disc crosses
 * the two edges beside it), and every
 * particle crossing an edge of the square is copied to the opposite edge, so
 * that each frame particle has its partner at exactly +-L. */
#ifndef SBC_GENERATE_H
#define SBC_GENERATE_H

#include "sbc/packing.h"

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_generate_def {
    int n;               /* particles before the reconstruction, n0 */
    double r_min;        /* smallest radius, m */
    double polydispersity; /* R_max / R_min, >= 1 (the runner accepts up to 10) */
    unsigned long seed;  /* random seed; the same seed gives the same packing */
    double strain;       /* > 0: the jammed box is compressed by this linear strain
                            and relaxed again, so that the packing carries load; 0: touching, free of force */
    int protocol;        /* SBC_GENERATE_SHRINK (the default) or SBC_GENERATE_PRESSURE, below */
    FILE *log;           /* progress lines every SBC_GENERATE_PROGRESS seconds of a long generation (may be NULL) */
} sbc_generate_def;

#define SBC_GENERATE_PROGRESS 10.0
#define SBC_GENERATE_MAX 2000000 /* particles before the reconstruction */

/* The jamming protocols. SHRINK: the box shrinks by steps, the overlaps relaxed
 * from scratch after each (FIRE to 1e-12 R_min), the step halved at each jam,
 * down to 1e-5 of the box. PRESSURE: the enthalpy sum(overlap^2)/2 + P V
 * minimized by FIRE over the centres and the box together, at overlaps of
 * about 1e-2, 1e-3, ... 1e-6 R_min, each stage from the last (P = omega
 * R_min^(2 - dim)), then the box stretched affinely until its largest overlap
 * closes. The two give different packings of the same statistics. */
enum { SBC_GENERATE_SHRINK = 0, SBC_GENERATE_PRESSURE = 1 };

/* The paper's: n0 = 200, R_min = 0.67 mm, polydispersity 2, seed 1. */
sbc_generate_def sbc_generate_def_default(void);

typedef struct sbc_generate_info {
    int n0, n;          /* particles before and after the reconstruction */
    double L;           /* side of the square, m */
    double fraction;    /* area of the discs inside the square / L^2 */
    double coordination;/* mean contacts per original disc (the n0 of the periodic square, images
                           included; touching within 1e-6 R_min) */
    double residual;    /* the largest net force on a particle over the mean contact force (unit stiffness: the
                           overlaps), 0 when none overlaps; how far from balance the relaxation left it */
} sbc_generate_info;

/* Generates the periodic packing; p is filled with the reconstructed discs
 * (centres in m), info with its figures. */
sbc_status sbc_generate_periodic(const sbc_generate_def *def, sbc_packing *p, sbc_generate_info *info,
                                 sbc_error *err);

/* The same in 3D: spheres (radii uniform in [R_min, pd R_min]) jammed in a
 * periodic cube from a packing fraction of 0.3, one sphere's centre moved to
 * the corner (copied to the eight corners: sphere 0, or the largest when
 * R_max > (1 + sqrt 3) r_0), every sphere crossing a face copied across it
 * (across two faces: three copies, as the edges of the cube ask). info's
 * L is the cube's side, fraction the volume fraction. */
typedef struct sbc_sphere_packing {
    int n;
    double *x; /* [3n] centres, m */
    double *r; /* [n] radii, m */
    double L;  /* the periodic cube [0, L]^3, m */
} sbc_sphere_packing;

sbc_status sbc_generate_periodic_3d(const sbc_generate_def *def, sbc_sphere_packing *p, sbc_generate_info *info,
                                    sbc_error *err);
void sbc_sphere_packing_free(sbc_sphere_packing *p);

#ifdef __cplusplus
}
#endif

#endif
