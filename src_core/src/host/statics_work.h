/* Private: interior newton's working state (statics.c), shared with the
 * rotations' solves (statics_turns.c). */
#ifndef SBC_STATICS_WORK_H
#define SBC_STATICS_WORK_H

#include "../engines/neighbor.h"
#include "condensed.h"
#include "statics.h"

/* the largest move of a disc in one Newton iteration, in smallest radii: a
   longer step is scaled down (contacts stay within reach of the pair list) */
#define STEP_CAP 0.25
/* the rotations' solves take the rotation unknowns whose moment is above this share of the worst residual */
#define TURN_SHARE 0.1

typedef struct statics_work {
    const sbc_statics_problem *p;
    sbc_pairs cand;          /* candidate pairs, within reach at the last build */
    int dim, rd, nd;         /* 2 or 3; rotations per particle (1 or 3); dofs per particle */
    double *fs;              /* [cand capacity] 2D: the springs of the iterate along t (N) */
    double *fsv;             /* [3 cand capacity] ... as vectors in the contact plane (condensed.h's sbc_network) */
    double *fs0c;            /* [3 cand capacity] 3D: each candidate's committed spring (N) */
    double *psi;             /* [cand capacity] the tangential spring's potential in the rotations, J:
                                -(|y|^2 - max(0, |y| - mu fn)^2) / (2 ks), y the trial in the contact plane (whose
                                gradient over a particle's rotation is the spring's moment on it; concave) */
    int *bondc;              /* with bonds: [cand capacity] 1 where the candidate was evaluated as an intact bond */
    double *mc;              /* with bonds: [cand capacity] ... its bending moment on i, N m */
    unsigned char *intact;   /* with bonds: [npair0] the committed bonds not broken by this solve */
    double *res;             /* [nd n] net loads of the iterate on each dof, N and N m */
    int *unk;                /* [nd n] each dof's unknown, -1 prescribed (condensed.h) */
    int L, nu;               /* the dofs' unknowns, and all unknowns with (T)'s multipliers */
    double *R;               /* [nu] the residual of each unknown */
    double *row_scale;       /* [nu] 1, or 1/R for a rotation's row (the merit in N) */
    double *dy;              /* [nu] Newton's correction */
    double *lambda;          /* [dim^2 + dim] (T): the multipliers (P, m over border) */
    double *xe;              /* [dim n] the state on entry (T: the frame's place for eq. 15 and its mean) */
    double border;           /* (T): the multipliers' scale, kn */
    double *xt, *tt;         /* [dim n], [rd n] a trial state of the line search */
    double rmax, rmin;
    double xmax;             /* the largest |coordinate| of the committed centres, m (the round-off's scale) */
    double mean_force;       /* mean |contact force| of the last evaluation, N */
    int contacts;            /* ... touching pairs */
    int built;               /* the candidates have been built once */
} statics_work;

/* candidate k's contact at (x, theta) (the increment's law, statics.h): its loads added to w->res, its spring to
   w->fsv (2D also w->fs), its potential to w->psi; returns |f| (N), or -1 when open */
double sbc_statics_contact(statics_work *w, int k, const double *x, const double *theta);

/* One sweep over the rotation unknowns (a particle's, or a family of periodic images' shared one) whose moment
 * over R is above target (N), in the order of their first particle: each solved with every other unknown held, by
 * maximizing the concave potential of its contacts' springs (w->psi: its gradient is the moment) with
 * Levenberg-damped Newton. A contact that slides has no rotational stiffness, and a particle whose contacts all
 * slide sits on a plateau of its moment that the global Newton step does not see across; the sweep crosses it.
 * net is the iterate's network (its x, theta, fs: w's). w->res and w->fsv are stale on return (evaluate again).
 * Returns the unknowns moved, -1 out of memory. */
int sbc_statics_turn_sweep(statics_work *w, const sbc_network *net, const double *x, double *theta, double target);

#endif
