/* Private: an aggregate on an embedded engine, the 2D disc engine or the 3D
 * sphere engine through the same operations (as GSL's step types), for the
 * material point (material_point.c) and the runner's tangents
 * (runner/script_tangent.c): its increments and its tangents
 * C_ijkl = dP_ij / dF_kl (C[9 (3i + j) + 3k + l], docs/fe2.md). */
#ifndef SBC_AGGREGATE_H
#define SBC_AGGREGATE_H

#include <stddef.h>

#include "sbc/contact.h"
#include "sbc/controller.h"
#include "sbc/driver.h"
#include "sbc/fire_damping.h"
#include "sbc/frame.h"
#include "sbc/material_point.h"
#include "sbc/settings.h"
#include "sbc/status.h"

typedef struct sbc_engine_ops {
    int dim;
    void *(*create)(const sbc_point_def *d, const sbc_settings *s, sbc_error *err);
    void (*free)(void *e);
    void (*set_frame)(void *e, const sbc_frame *f);
    sbc_status (*seal)(void *e, sbc_error *err); /* keyword seal yes: walls on the frame's surface (seal.h),
                                                    after set_frame */
    sbc_driver_callbacks (*callbacks)(void *e);
    sbc_status (*forces)(void *e, sbc_error *err);
    void (*move_frame)(void *e, const sbc_commands *cmd);
    void (*frame_masses)(const void *e, double *mass);
    double (*critical_dt)(const void *e);
    size_t (*state_size)(const void *e);
    void (*save)(const void *e, double *out);
    sbc_status (*load)(void *e, const double *in, size_t n, sbc_error *err);
    /* the engine's pairs: their count, pair k's particles and the tangential spring's force on ij[0] (N), the
       centres [dim n] and radii */
    int (*pair_count)(const void *e);
    void (*pair)(const void *e, int k, int ij[2], double fs[3]);
    const double *(*centres)(const void *e);
    const double *(*radii)(const void *e);
    const double *(*rotations)(const void *e); /* [n] rad (2D) */
    /* pair k's intact cohesive bond (1, with its moment on ij[0] into *m, N m) or 0; NULL where the engine has no
       bonds (spheres) */
    int (*bond)(const void *e, int k, double *m);
    /* interior newton (statics.h): every particle put at x, theta at rest, with the contacts' pair records
       (engine.h); NULL where the engine has no static solver (spheres) */
    sbc_status (*place)(void *e, const double *x, const double *theta, const double *records, int count,
                        sbc_error *err);
} sbc_engine_ops;

extern const sbc_engine_ops sbc_engine_ops_discs;   /* sbc_engine (embedded/engine.h) */
extern const sbc_engine_ops sbc_engine_ops_spheres; /* sbc_spheres (embedded/spheres.h) */

typedef struct sbc_aggregate {
    const sbc_engine_ops *ops;
    void *engine;
    int n;                        /* particles */
    const sbc_frame *frame;       /* the frame the controller was created with */
    const sbc_settings *settings; /* D, P or T and their keywords */
    const double *mass;           /* [frame n] the frame particles' masses, kg */
    double dt;                    /* s */
    sbc_frictional law;           /* eq. 6 */
    const sbc_cohesive *bonds;    /* the engine's cohesive bonds (eqs. 7-8; law then holds their kn, ks, mu),
                                     NULL: none */
    struct sbc_statics_tally *tally; /* interior newton: the solves' counts, NULL with interior dynamic */
} sbc_aggregate;

/* interior newton: what the static solves of an increment did (the row's
   newton_iterations, the log's notes) */
typedef struct sbc_statics_tally {
    long iterations;   /* Newton iterations since the last row */
    int solves;        /* static solves since the last row */
    int unconverged;   /* ... that stopped short of the tolerance (the dynamic relaxation finished them) */
    int retried;       /* ... that stalled at first and converged when tried again (statics.h: substeps) */
    int broken;        /* cohesive bonds the solves broke since the last row */
    int mechanisms;    /* dofs held for want of stiffness at the last solve */
    double residual;   /* the last solve's relative residual */
    int fallback;      /* an unconverged solve: the increment is finished by the dynamic relaxation and the
                          servo, without further solves */
    char why[200];     /* the last unconverged solve: why */
} sbc_statics_tally;

/* One host step's frame move and forces: the frame to ctl's commands;
 * with interior newton (a->tally), where the frame moved (or always, with
 * settle), the static equilibrium from the state before the move with the
 * frame at its new place under the condition's own unknowns (statics.h),
 * the engine placed there at rest and, under (P) and (T), the frame's
 * place made ctl's commands (sbc_controller_adopt); then the contact
 * forces. After an unconverged solve (tally->fallback) the increment goes
 * on by the dynamic relaxation and the servo alone. */
sbc_status sbc_aggregate_advance(const sbc_aggregate *a, sbc_controller *ctl, int settle, sbc_error *err);

/* Host steps (move the frame, forces, sbc_driver_step) until ctl accepts an
 * increment (SBC_EVENT_INCREMENT or SBC_EVENT_FINISHED) or fails; first: the
 * forces of the first step are taken already. */
sbc_event sbc_aggregate_run_increment(const sbc_aggregate *a, sbc_controller *ctl, sbc_driver *driver, int first,
                                      sbc_error *err);

/* The engine's driver callbacks (ops->callbacks) with the Newton
 * correction of keyword update newton (sbc_aggregate_newton on a). */
sbc_driver_callbacks sbc_aggregate_callbacks(const sbc_aggregate *a);

/* update newton (sbc_newton_fn, controller.h) on an aggregate
 * (user_data): the frame's correction by the condensed network
 * (condensed.h, sbc_condensed_correction). */
int sbc_aggregate_newton(void *aggregate, const double *reaction, const double *moment, double *du, double *dtheta,
                         char *message, size_t cap);

/* The engine's contact network (host/condensed.h) into net; its pair
 * arrays in *ij (i [npair], j [npair], with bonds their flags [npair]),
 * *fs, which the caller frees (also on failure). */
struct sbc_network;
sbc_status sbc_aggregate_network(const sbc_aggregate *a, struct sbc_network *net, int **ij, double **fs,
                                 sbc_error *err);

/* The affine tangent at F (material_point.h, sbc_point_tangent_affine). */
sbc_status sbc_aggregate_affine(const sbc_aggregate *a, const double F[9], double C[81], sbc_error *err);

/* Where an increment started (a material point's committed state): the
 * centres x [dim n] (m); in 3D also the rotations theta [3n] (rad) and the
 * engine's pairs then, sorted by i then j (i < j), with their springs fs
 * [3 npair] (N, as sbc_engine_ops.pair gives them). */
typedef struct sbc_increment_start {
    const double *x, *theta;
    int npair;
    const int *i, *j;
    const double *fs;
} sbc_increment_start;

/* The condensed tangent (material_point.h, sbc_point_tangent_condensed);
 * start: NULL (the current state's linearization), or where the increment
 * started (its derivative, condensed.h); in 3D without start->theta, NULL. */
sbc_status sbc_aggregate_condensed(const sbc_aggregate *a, const sbc_increment_start *start, double C[81],
                                   int *mechanisms, sbc_error *err);

/* The perturbation tangent at an increment that `accepted` has just accepted
 * (before the host's next step: in the driver's row callback), at its F:
 * from that state, one increment to F + h e_kl and one to F - h e_kl for
 * each k, l (2 dim^2 increments, each on a copy of the controller and a
 * driver of its own whose FIRE starts from *fire); central differences of
 * eq. 23's P. The engine is back in its state afterwards, bit for bit; the
 * controller and *fire are not touched. */
sbc_status sbc_aggregate_perturbation(const sbc_aggregate *a, const sbc_controller *accepted,
                                      const sbc_fire_state *fire, double h, double C[81], sbc_error *err);

#endif
