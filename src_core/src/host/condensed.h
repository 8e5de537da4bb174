/* Private: the condensed tangent of an aggregate (material_point.c, docs/fe2.md). */
#ifndef SBC_CONDENSED_H
#define SBC_CONDENSED_H

#include "sbc/contact.h"
#include "sbc/frame.h"
#include "sbc/settings.h"
#include "sbc/status.h"

/* A contact whose tangential spring is within this fraction of the Coulomb
 * limit mu fn counts as sliding in the linearizations (the condensed and
 * affine tangents, interior newton's Jacobian): a contact that slid to the
 * end of its increment is left a hair below the limit by the steps that
 * certify the row (1e-11 to 1e-9 of it, measured in docs/servo_bc.md, "Interior"),
 * and 1e-12 called it sticking there at random. */
#define SBC_SLIDING_BAND 1e-6

/* The contact network of an aggregate in its current state, in the
 * conventions of the embedded engines (engine.c in 2D, spheres.c in 3D). */
typedef struct sbc_network {
    int dim;            /* 2 (discs) or 3 (spheres) */
    int n;              /* particles */
    const double *x;    /* [dim n] centres, m */
    const double *r;    /* [n] radii, m */
    int npair;          /* pairs of the engine's list (open ones are skipped) */
    const int *i, *j;   /* [npair] */
    const double *fs;   /* [3 npair] the tangential spring's force on i, N, in the contact plane (the force on
                           i is -fn n + fs, n from i to j); NULL without friction */
    sbc_frictional law; /* eq. 6 (with bonds: their kn, ks, mu, which broken bonds and new contacts follow) */
    const int *bond;    /* 2D: [npair] 1 where the pair is an intact cohesive bond (eqs. 7-8: its normal spring
                           also in tension, its shear spring uncapped, its bending spring kr); NULL: none */
    double kr;          /* the bonds' bending stiffness, N m/rad */
    const double *x0;   /* [dim n] the centres where the increment started (a material point's committed
                           state), or NULL; see sbc_condensed_tangent */
    const double *theta0, *theta; /* 3D with x0: [3n] the rotations where the increment started and now, rad */
    const double *fs0;  /* 3D with x0: [3 npair] each pair's committed spring (sbc_spring_3d_at), N; NULL: none */
    int dense;          /* 1: solved densely even where the core has a sparse solver (tests compare the two) */
    const unsigned char *mode; /* mixed: the frame particles' component modes [3Q] (sbc_mixed_modes), D or P
                                  (T is not linearized here); NULL otherwise */
    int frame_rotation_zero;   /* (T) with `rotation zero`: the frame's rotations held at zero */
    double border;             /* (T): the scale of the multipliers' rows and columns, N/m; 0: the largest
                                  contact stiffness entry (interior newton fixes it over its iterations) */
    const unsigned char *free_rotation; /* interior newton, mixed: [Q] 1 where a frame particle that follows its
                                           commands has its rotations free (the host's free rotations, a T
                                           component's): unknowns of the solve; NULL: held */
    double shift;              /* interior newton's pseudo-time term (statics.h), N/m: taken from the diagonal of
                                  each translation's unknown, times R^2 from each rotation's; 0 otherwise */
} sbc_network;

/* C_ijkl = dP_ij / dF_kl (C[9 (3i + j) + 3k + l]) of the aggregate at
 * equilibrium under bc (D, P, T, or mixed of D and P with net->mode) on frame f: the stiffness of the contact
 * network (normal springs, tangential springs of sticking contacts, the slip
 * law of sliding ones, the terms of the forces turning with their contacts)
 * with the interior's and the free frame's degrees of freedom condensed out
 * and the frame's kinematics of bc applied. *mechanisms: the degrees of
 * freedom found to carry no stiffness (set to zero). With net->x0, a
 * sticking contact's tangential spring is differentiated as the increment
 * from x0 loaded it, along the straight path from x0's branch to the
 * current one, instead of at the current state alone: the derivative of
 * one increment's P with respect to its end, which a macro Newton needs
 * for its quadratic rate (docs/fe2.md, "The consistent tangent"). */
sbc_status sbc_condensed_tangent(const sbc_network *net, const sbc_frame *f, sbc_bc bc, double C[81],
                                 int *mechanisms, sbc_error *err);

/* update newton (docs/servo_bc.md, "Newton"): the frame's correction du [3Q]
 * (m) and dtheta [rQ] (rad, r = 1 in 2D, 3 in 3D) that brings the frame's
 * reactions reaction [3Q] (N, a_q of eq. 5) and moments moment [rQ] (N m)
 * to what bc asks of them on the linearized network with the interior
 * condensed out: (P) each family's sums of forces and moments to zero (its
 * shared fluctuation and rotation solved for; the corners keep following F),
 * (T) every frame particle's force to P A_q + m with eq. 15 and the frame's
 * mean translation kept (the multipliers P, m solved for), and its moment to
 * zero; (D) nothing (all zero). */
sbc_status sbc_condensed_correction(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const double *reaction,
                                    const double *moment, double *du, double *dtheta, int *mechanisms, sbc_error *err);

/* 2D: the slip a sticking contact's tangential spring takes over an
 * increment whose branch goes from x0b - x0a to l = (lx, ly) (m), the
 * integral of t . dl along the straight path (condensed.c), and its
 * gradient over l, grad [2]. */
double sbc_path_slip(const double x0a[2], const double x0b[2], double lx, double ly, double grad[2]);

/* interior newton (statics.h): the unknowns of the network's dofs under bc
 * on frame f, unk [dofs n] (-1 where the frame's condition prescribes the
 * dof; a (P) family's members share theirs), as the condensed tangent
 * numbers them; returns their count L; under (T) the multipliers of
 * a_q = P A_q + m (dim^2, then dim) follow as unknowns L .. L + dim^2 + dim - 1.
 * -1 on failure (err). */
int sbc_condensed_unknowns(const sbc_network *net, const sbc_frame *f, sbc_bc bc, int *unk, sbc_error *err);

/* interior newton: the Newton correction dy [nu] of the unknowns
 * (sbc_condensed_unknowns, nu = L plus the multipliers), K dy = -residual,
 * residual [nu] the net loads summed over each unknown's dofs (N, N m) and
 * under (T) the rows of the multipliers, K their derivative (the contact
 * blocks of the condensed tangent, bordered by net->border under (T)).
 * *mechanisms: the unknowns found to carry no stiffness, held (dy 0): those
 * the pivots find, and with net->shift those no contact stiffens (which the
 * pseudo-time term alone holds). */
/* interior newton: the unknowns no contact stiffens (net->shift > 0), counted from the assembled system without
 * a solve; -1 on failure (err). */
int sbc_condensed_unstiffened(const sbc_network *net, const sbc_frame *f, sbc_bc bc, sbc_error *err);

sbc_status sbc_condensed_newton_step(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const double *residual,
                                     double *dy, int *mechanisms, sbc_error *err);

#endif
