/* Private: cell-binned Verlet pair list with per-pair tangential history.
 * Pairs (i < j) are stored by i (CSR) and sorted by j within i, so that the
 * history of surviving pairs is carried over at a rebuild by a merge: O(N). */
#ifndef SBC_NEIGHBOR_H
#define SBC_NEIGHBOR_H

#include "sbc/status.h"

typedef struct sbc_pairs {
    int n;          /* particles */
    int count;      /* pairs */
    int capacity;
    int *start;     /* [n+1] pairs of particle i are start[i] .. start[i+1]-1 */
    int *i, *j;     /* [capacity] */
    double *fs;     /* [capacity] tangential spring force, N; NULL without history */
    /* cell grid scratch */
    int *cell_of, *cell_start, *cell_cursor, *cell_order, cell_capacity;
    double *x_build; /* [2n] positions at the last build, m */
    double skin;     /* m */
} sbc_pairs;

sbc_status sbc_pairs_init(sbc_pairs *p, int n, double skin, int history, sbc_error *err);
void sbc_pairs_free(sbc_pairs *p);

/* Rebuilds the list for positions x [2n] and radii r [n], keeping the
 * tangential history of pairs present before and after. */
sbc_status sbc_pairs_build(sbc_pairs *p, const double *x, const double *r, double rmax, sbc_error *err);

#endif
