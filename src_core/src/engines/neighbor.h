/* Private: cell-binned Verlet pair list with per-pair tangential history and,
 * for cohesive scenes, per-pair bond state.
 * Pairs (i < j) are stored by i (CSR) and sorted by j within i, so that the
 * history of surviving pairs is carried over at a rebuild by a merge: O(N). */
#ifndef SBC_NEIGHBOR_H
#define SBC_NEIGHBOR_H

#include <stddef.h>

#include "sbc/status.h"

typedef struct sbc_pairs {
    int dim;        /* 2 or 3 */
    int n;          /* particles */
    int count;      /* pairs */
    int capacity;
    int *start;     /* [n+1] pairs of particle i are start[i] .. start[i+1]-1 */
    int *i, *j;     /* [capacity] */
    double *fs;     /* [capacity] tangential spring force, N; NULL without history */
    double *m;      /* [capacity] bond moment on i, N m; NULL without bonds */
    unsigned char *bond; /* [capacity] 1 while the pair's bond is intact; NULL without bonds */
    /* cell grid scratch */
    int *cell_of, *cell_start, *cell_cursor, *cell_order, cell_capacity;
    double *x_build; /* [dim n] positions at the last build, m */
    double skin;     /* m */
} sbc_pairs;

/* history: keep fs per pair; bonds: keep m and bond per pair (implies history). */
sbc_status sbc_pairs_init(sbc_pairs *p, int dim, int n, double skin, int history, int bonds, sbc_error *err);
void sbc_pairs_free(sbc_pairs *p);

/* Rebuilds the list for positions x [dim n] and radii r [n], keeping the
 * tangential history and bond state of pairs present before and after. An
 * intact bond is never dropped as long as its stretch stays below the skin. */
sbc_status sbc_pairs_build(sbc_pairs *p, const double *x, const double *r, double rmax, sbc_error *err);

/* Bonds every listed pair whose gap |x_j - x_i| - R_i - R_j is below gap (m);
 * returns the number of bonds. */
int sbc_pairs_bond_touching(sbc_pairs *p, const double *x, const double *r, double gap);

/* The list's state (pairs, their history and bonds, the positions of the
 * last build) as doubles: sbc_pairs_state_size counts them, sbc_pairs_save
 * writes them at out and returns the end, sbc_pairs_load reads them back
 * from s into a list initialised for the same n, history and bonds (every
 * value checked; the cell grid is scratch). */
size_t sbc_pairs_state_size(const sbc_pairs *p);
double *sbc_pairs_save(const sbc_pairs *p, double *out);
struct sbc_saved;
sbc_status sbc_pairs_load(sbc_pairs *p, struct sbc_saved *s);

#endif
