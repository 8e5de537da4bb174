/* Private: the embedded 2D engine's state (engine.c), shared with the file
 * that saves and loads it (engine_state.c). */
#ifndef SBC_ENGINE_PRIVATE_H
#define SBC_ENGINE_PRIVATE_H

#include "sbc/embedded/engine.h"
#include "sbc/seal.h"

#include "neighbor.h"

struct sbc_engine {
    int n;
    double *x, *v, *f;           /* [2n] m, m/s, N */
    double *theta, *omega, *tq;  /* [n] rad, rad/s, N m */
    double *r, *mass, *inv_m, *inv_I;
    unsigned char *kinematic;
    double rmax, rmin;
    sbc_frictional law;
    int history;
    int bonded;              /* the scene has cohesive bonds */
    sbc_cohesive bond_law;   /* eqs. 7-8 */
    int bond_count, bonds_initial;
    double dt, alpha, beta;
    int fire;                /* FIRE (fire_damping.h) instead of eq. 10 */
    sbc_fire_state fire_state;
    sbc_pairs pairs;
    int stale; /* the pair list must be rebuilt before the next force evaluation */
    double *stream;          /* keyword remap x: the velocity added to each particle, taken back next step (driver.h) */
    int streaming;           /* ... some of it is in v now */
    const sbc_frame *frame;
    int sealed;              /* seal.h walls on the frame's polygon */
    sbc_seal seal;
    double *seal_reaction;   /* [3Q] N */
    int *frame_slot;         /* [n] frame position of each particle, -1 interior */
    /* per-step measures */
    double ek, ep, overlap_sum, rotation_sum;
    double net_max, contact_force_sum; /* max |net force| on the interior, sum |f_c|, N */
    long contact_count, step;
    /* frame-ordered snapshot buffers */
    double *snap_x, *snap_theta, *snap_f, *snap_tq;
    sbc_snapshot snap;       /* the driver's: this step's measures (sbc_engine_callbacks) */
};

#endif
