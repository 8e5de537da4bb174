/* Private: one contact's block of the contact network's stiffness (contact_blocks.c). */
#ifndef SBC_CONTACT_BLOCKS_H
#define SBC_CONTACT_BLOCKS_H

#include "condensed.h"

#define SBC_BLOCK_MOST 12 /* the largest contact block: 2 spheres x 6 dofs */

/* 3D: a contact's tangential spring over an increment by backward Euler
 * (the sphere engine's law, spheres.c, in one step): with the branch
 * l = x_j - x_i, L = |l|, n = l / L, the overlap dn = R_i + R_j - L, the
 * contact point's arms r_i = s n, r_j = (s - L) n (s = R_i - dn / 2) and the
 * slip of i's contact point against j's over the increment
 *   du = -(l - l0) + dtheta_i x r_i - dtheta_j x r_j                       (m)
 * the trial v = fs0 - ks du (fs0 the committed spring, N), kept in the
 * contact plane, P v (P = I - n n), and capped at mu fn (eq. 6):
 * fs = c P v, c = min(1, mu kn dn / |P v|). */
typedef struct sbc_spring_3d {
    double n[3], L, dn, s; /* the contact's normal, branch length, overlap (m) and arm of i */
    double v[3];           /* the trial before the projection, N */
    double fs[3];          /* the spring at the end, the force on i in the contact plane, N */
    double c;              /* the return map's factor (1 sticking) */
    int open;              /* 1: no overlap (fs 0) */
} sbc_spring_3d;

/* The spring of a contact between i at xi and j at xj (m), radii Ri, Rj, whose committed branch was l0 (NULL: the
 * current one) and whose particles turned by dthi, dthj (NULL: 0, rad) since fs0 (N; NULL: none). */
void sbc_spring_3d_at(const double xi[3], const double xj[3], double Ri, double Rj, const double l0[3],
                      const double dthi[3], const double dthj[3], const double fs0[3], const sbc_frictional *law,
                      sbc_spring_3d *out);

/* The index of pair (a, b), a < b, among npair pairs (i [npair], j [npair]) sorted by i then j; -1 when it is
 * not among them (a committed contact state looked up from the current pair list). */
int sbc_pair_index(int npair, const int *i, const int *j, int a, int b);

/* d(loads)/d(dofs) of contact k of net over its particles' dofs (u_i, theta_i, u_j, theta_j), loads in the same
 * order (forces, moments); B is cleared first. Returns 0 for an open contact (B zero). */
int sbc_contact_block(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST]);

#endif
