/* Private: how the frame travels to new commands (a new increment, a servo
 * correction). The paper puts the frame on its new positions in one time
 * step; a frame particle that jumps by u in one step hits its neighbours at
 * u/dt, and the transient lets frictional contacts slip, which leaves a
 * self-equilibrated tangential state in the relaxed packing (measured on the
 * 6 x 6 frictional lattice: |P12| / |P11| = 1.7e-5 after one increment in
 * one step, 5.7e-6 at 0.1 radii per critical step, 1.7e-8 at 1.1e-3;
 * docs/servo_bc.md). Here the frame travels along a straight line at no more
 * than `speed` radii per critical time step t_q = sqrt(2 M_q / kn) of each
 * frame particle; speed 0 (or kn unknown) keeps the paper's single step. */
#ifndef SBC_MOTION_H
#define SBC_MOTION_H

#include "sbc/frame.h"

typedef struct sbc_motion {
    int rot;                  /* SBC_ROTATIONS(dim): the stride of the rotations */
    double *x_from, *th_from; /* [3Q], [rot Q] commands before the move, m, rad */
    double *x_goal, *th_goal; /* [3Q], [rot Q] commands after it */
    long steps;               /* time steps the move takes (>= 1) */
    long done;                /* ... of which taken */
} sbc_motion;

int sbc_motion_alloc(sbc_motion *m, int q, int rot);
void sbc_motion_free(sbc_motion *m);

/* Starts a move from the commands in force (x_from, th_from, copied by the
 * caller beforehand) to the commands in x, th, and writes into x, th the
 * commands of the move's first step. mass [Q] kg, kn N/m, dt s. carry: NULL,
 * or the map M [9] about origin [3] that the interior follows during the move
 * (keyword remap x, controller.h): the speed then bounds each frame
 * particle's move relative to the interior around it, x_goal - x_from -
 * (M - I)(x_from - origin), for that part alone strikes its neighbours. */
void sbc_motion_begin(sbc_motion *m, const sbc_frame *f, const double *mass, double kn, double dt, double speed,
                      const double *carry, const double *origin, double *x, double *th);

/* The next step of a move under way: writes its commands into x, th and
 * returns 1; returns 0 when the move is over (the goal is in force). */
int sbc_motion_advance(sbc_motion *m, int q, double *x, double *th);

#endif
