/* Private: keyword interior newton (docs/servo_bc.md, "Interior"): the
 * static equilibrium of a disc (2D) or sphere (3D) aggregate whose frame stands at given
 * positions, reached from its committed state by Newton on the contact
 * network. The contact law of eq. 6 is integrated over the increment by
 * backward Euler: the normal force from the end state, the tangential
 * spring from its committed value by the slip of the increment (elastic
 * trial, then the Coulomb cap, the return map of a sliding contact), the
 * slip being t . dl along the straight path of the branch (sbc_path_slip)
 * less R_i dtheta_i + R_j dtheta_j (in 3D the spring of sbc_spring_3d_at,
 * contact_blocks.h). Contacts open and close between
 * iterations; the Jacobian is the condensed tangent's contact blocks
 * (condensed.h), so each Newton step is exact where no contact changes
 * status. The frame's condition is part of the system, with the condensed
 * tangent's unknowns. Cohesive bonds (2D, eqs. 7-8) are integrated alike:
 * the normal spring in tension too, the shear spring from its committed
 * value uncapped, the bending spring m = m0 + kr (dtheta_j - dtheta_i);
 * where a converged iterate puts bonds at or over eq. 8's criterion, the
 * worst one breaks (eq. 6 from then on) and the iteration goes on, one bond
 * at a time (a bond's failure unloads or loads its neighbours, which the
 * next solve sees). The frame: (D) the frame prescribed; (P) each family of periodic
 * images shares one fluctuation and one rotation, whose net loads vanish,
 * the corners following F; (T) every frame particle free under
 * a_q = P A_q + m, with eq. 15 and the frame's mean translation kept from
 * the frame's place on entry (the multipliers P, m solved for; the frame
 * starts as its committed shape mapped to the commands' eq. 15). Globalized
 * by a backtracking line search on the residual's norm, a pseudo-time term
 * and a cap on each iteration's largest move; a stalled solve is tried
 * again with every rotation balanced one by one before each Newton step
 * (sbc_statics_turn_sweep), then in parts; degrees of freedom without
 * stiffness (rattlers, the rotations of frictionless discs) are held. */
#ifndef SBC_STATICS_H
#define SBC_STATICS_H

#include "sbc/contact.h"
#include "sbc/frame.h"
#include "sbc/settings.h"
#include "sbc/status.h"

/* The tolerance of the hosts' solves (sbc_statics_problem's tol): far
   below every preset's force balance, so that the rows are certified in the
   relaxation's window of steps; and the iterations before the dynamic
   relaxation finishes the increment from the last iterate. */
#define SBC_STATICS_TOL 1e-10
#define SBC_STATICS_ITERATIONS 60

typedef struct sbc_statics_problem {
    int dim;                    /* 2 (discs) or 3 (spheres) */
    int n;                      /* particles */
    const double *r;            /* [n] radii, m */
    sbc_frictional law;         /* eq. 6 */
    const sbc_frame *frame;     /* the aggregate's frame */
    sbc_bc bc;                  /* D, P, T (rotation_zero: T's frame rotations held) or mixed */
    const unsigned char *mode;  /* mixed: [3 Q] the frame's component modes, D or P (a T component is held at its
                                   command: the servo moves it between solves); NULL otherwise */
    const unsigned char *free_rotation; /* [Q] frame particles whose rotations are unknowns although they follow
                                           their commands (mixed: the host's free rotations); NULL: none */
    int rotation_zero;
    const double *x0, *theta0;  /* [dim n], [n] (2D) or [3n] (3D) the committed centres (m) and rotations (rad) */
    int npair0;                 /* the committed pairs, sorted by i then j, i < j */
    const int *i0, *j0;
    const double *fs0;          /* 2D [npair0] their tangential springs (N, the force on i along t), 3D [3 npair0]
                                   (the force on i, a vector); NULL: no tangential history (frictionless) */
    const sbc_cohesive *bonds;  /* 2D: the cohesive bonds' law (eqs. 7-8; law holds its kn, ks, mu), NULL: none */
    const int *bond0;           /* with bonds: [npair0] 1 where the committed pair is an intact bond */
    const double *m0;           /* with bonds: [npair0] its bending moment on i, N m */
    double tol;                 /* converged: every free dof's net force, and net moment over R, at most tol
                                   times the mean contact force */
    int max_iterations;
} sbc_statics_problem;

typedef struct sbc_statics_result {
    int iterations;   /* Newton iterations taken */
    int converged;    /* 1: the residual reached tol */
    int mechanisms;   /* dofs held for want of stiffness, at the last iteration */
    double residual;  /* the last relative residual (as tol) */
    int contacts;     /* touching pairs and intact bonds at the end */
    int broken;       /* bonds broken by the solve (eq. 8 reached at a converged iterate: the worst one broken,
                         and the iteration on from there, until every intact bond is below the criterion) */
    int substeps;     /* 0: one solve; else the parts the frame's move was cut into, each solved from the last
                         (a solve that stalled is tried again whole, then in 2, 4, 8 parts, each with the
                         rotations balanced one by one at every iteration: sbc_statics_turn_sweep) */
    double *records;  /* [SBC_PAIR_RECORD contacts] of the end state: 2D (i, j, bond, fs, m) (engine.h), 3D
                         (i, j, fs_x, fs_y, fs_z) (sbc_spheres_place) */
    char why[200];    /* not converged: why */
} sbc_statics_result;

/* Solves for the unknowns of x [dim n] and theta [n or 3n], which hold on entry the
 * committed state with the frame at its commands for the increment (which
 * satisfy eq. 15 under (T)) and on return the solution or the last iterate.
 * The iteration starts with the interior carried by the affine map that
 * fits the frame's move best; a stalled solve is tried again with the move
 * cut into 2, 4, 8 parts, each solved from the last (res->substeps), and
 * where every cut stalls too, the first attempt's iterate is returned. SBC_OK whether or not
 * the iteration converged (res says); an sbc_status on failure (memory, a
 * non-finite state). res->records is the caller's to free
 * (sbc_statics_result_free). */
sbc_status sbc_statics_solve(const sbc_statics_problem *p, double *x, double *theta, sbc_statics_result *res,
                             sbc_error *err);
void sbc_statics_result_free(sbc_statics_result *res);

#endif
