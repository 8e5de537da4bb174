/* servo_bc: the thesis' test set-ups on a bonded specimen (Sects. 4.3-4.4),
 * run on the embedded 3D engine (bpm.h). The engine must hold the bonded
 * specimen, its time step set.
 *
 * Uniaxial test (Fig. 24). End spheres: centres within zone r_p of the
 * specimen's x faces. The left end moves along x at the loading velocity,
 * the right end is held in x; both are free in y and z, every other sphere
 * is free. Every sphere starts on the linear velocity ramp between the two
 * ends, so that no load peak enters at the start (the thesis' "initial
 * linearly ramped loading velocity").
 *   E   = (F_x / dL) (L0 / A)                      eq. 64, the slope fitted over
 *                                                  the second half of the run
 *   nu  = -(dw / w0) / (dL / L0)  (and h for z)    eq. 65 as -eps_y / eps_x
 * with L0 the distance between the centres of the two end zones (the length
 * the bonds between them span; for the cubic lattice this gives the thesis'
 * 3.14 GPa at every r_p), A = w0 h0 the specimen's cross-section, and w, h
 * the distances between the mean centres of the spheres within zone r_p of
 * the y and z faces (Fig. 26); a specimen one sphere across (those zones'
 * centres closer than r_p) has no such distance, and its strain is then
 * measured over the outer width, the centres' span plus 2 r_p. At the end, the RVE stress of the whole
 * specimen (eq. 54) and the boundary-load stress F_x / A (Sect. 5.3.1).
 *
 * Three-point flexural test (Fig. 28). Supports: the spheres within zone r_p
 * of the bottom face (z) and of an end face (x); the left ones are pinned
 * (every degree of freedom held but the rotation about y), the right ones
 * may also slide in x. Load: F, ramped linearly over `ramp` steps and then
 * held, shared equally by the spheres within zone r_p of the top face whose
 * centres lie within zone r_p of midspan. Deflection delta: the mean
 * downward displacement of the loaded spheres and of the spheres in the
 * same x range on the bottom face, averaged over the last tenth of the run
 * (as the thesis does at 2.5 mm, where a vibration of 0.8 % remains). With L_e the distance between the
 * supports, b the x extent of the loaded centres, I = w h^3 / 12 and A = w h
 * of the specimen's cross-section, f_s = 10/9 and nu from the uniaxial test:
 *   E_f = F / 2 delta [L_e^3 / 24 I + L_e f_s (1 + nu) / A]          eq. 67
 *   E_f = F / 2 delta [(8 L_e^3 - 4 b^2 L_e + b^3) / 192 I
 *                      + f_s (L_e - b)(1 + nu) / A]                  eq. 69 */
#ifndef SBC_BPM_LOADING_H
#define SBC_BPM_LOADING_H

#include "sbc/bpm.h"

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_bpm_uniaxial {
    double rp;       /* particle radius r_p, m (sets the zones) */
    double zone;     /* end and bounding zones, in r_p (thesis: 1.5) */
    double velocity; /* loading velocity v_l, m/s: > 0 tension, < 0 compression (thesis: 1e-5) */
    long steps;      /* steps to run */
    FILE *series;    /* when not NULL: step, dL, F_x, eps_y, eps_z, W_kin, W_int, W_dis, W_ext per sample */
    long every;      /* sample interval, steps (0: 100 samples) */
} sbc_bpm_uniaxial;

typedef struct sbc_bpm_uniaxial_result {
    double E;            /* eq. 64, Pa */
    double nu_xy, nu_xz; /* eq. 65 */
    double L0, A, w0, h0; /* m, m^2, m, m */
    double force, dL;    /* F_x (N, > 0 in tension) and dL (m) at the end */
    size_t loaded, held; /* spheres in the two end zones */
    double balance;      /* the largest eq. 53 ratio over the samples of the second half */
    double sigma_rve[9]; /* eq. 54 over every sphere, V = the spheres' extent (bpm_stress.h), Pa */
    double sigma_load;   /* F_x / A, the boundary-load stress (Tables 5-6: sigma^C_xx), Pa */
} sbc_bpm_uniaxial_result;

sbc_status sbc_bpm_uniaxial_run(sbc_bpm *e, const sbc_bpm_uniaxial *test, sbc_bpm_uniaxial_result *res,
                                sbc_error *err);

typedef struct sbc_bpm_bending {
    double rp;    /* particle radius r_p, m */
    double zone;  /* supports and loaded band, in r_p (thesis: 1.5) */
    double force; /* total load F, N (thesis: 1e3) */
    double nu;    /* Poisson's ratio for G in eqs. 67 and 69 */
    long ramp;    /* load ramp, steps (thesis: 5000 to 40000) */
    long steps;   /* steps in all (ramp included) */
    FILE *series; /* when not NULL: step, F, delta, W_kin, W_int, W_dis, W_ext per sample */
    long every;   /* sample interval, steps (0: 100 samples) */
} sbc_bpm_bending;

typedef struct sbc_bpm_bending_result {
    double delta;            /* mean over the last tenth of the run (the vibration averaged out), m */
    double swing;            /* max - min of delta over that tenth, m */
    double Ef_point, Ef_band; /* eqs. 67 and 69, Pa */
    double Le, b, I, A;      /* m, m, m^4, m^2 */
    size_t loaded, supports;
    double balance;          /* the largest eq. 53 ratio over the samples after the ramp */
} sbc_bpm_bending_result;

sbc_status sbc_bpm_bending_run(sbc_bpm *e, const sbc_bpm_bending *test, sbc_bpm_bending_result *res,
                               sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
