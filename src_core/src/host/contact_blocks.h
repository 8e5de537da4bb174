/* Private: one contact's block of the contact network's stiffness (contact_blocks.c). */
#ifndef SBC_CONTACT_BLOCKS_H
#define SBC_CONTACT_BLOCKS_H

#include "condensed.h"

#define SBC_BLOCK_MOST 12 /* the largest contact block: 2 spheres x 6 dofs */

/* d(loads)/d(dofs) of contact k of net over its particles' dofs (u_i, theta_i, u_j, theta_j), loads in the same
 * order (forces, moments); B is cleared first. Returns 0 for an open contact (B zero). */
int sbc_contact_block(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST]);

#endif
