/* servo_bc: the generators' periodic box of particles with unit-stiffness
 * overlaps (energy sum(overlap^2)/2): cell and neighbour lists, the overlap
 * forces and virial, FIRE relaxation in a fixed box or with the box free
 * under a pressure. Internal header (generate.c). */
#ifndef SBC_JAM_BOX_H
#define SBC_JAM_BOX_H

#include <stddef.h>

/* floor(t) for |t| < 2^62 without a libm call (the inner loop's): the same value */
static inline double sbc_jam_floor(double t)
{
    const double k = (double)(long long)t;
    return k > t ? k - 1.0 : k;
}

static inline double sbc_jam_image(double d, double L) { return d - L * sbc_jam_floor(d / L + 0.5); }

static inline double sbc_jam_wrap(double a, double L) { return a - L * sbc_jam_floor(a / L); }

typedef struct sbc_jam_box {
    int dim, n;
    double L, rmax, *x, *r, *v, *f; /* x, v, f [dim n] */
    int *head, *next, cells; /* periodic cell list, cells^dim heads */
    /* the pairs that may touch (within r_i + r_j + skin when listed), in the
       order in which the cell list visits them, as (i, j, image shift)
       triples; listed: the cells a side it was made with (-1: every pair
       visited), 0: no list */
    int *pair, npair, cap, listed, *cell;
    double skin, *x0; /* x0 [dim n]: the centres when listed */
    /* the pressure protocol: the box is a degree of freedom x[dim n] = c ln(L /
       L_start) under the pressure P (unit stiffness: length^(2 - dim)); the
       list is kept through affine changes of the box (made at L_listed) */
    int pressure, box_free;
    double P, c, L_start, L_listed, virial; /* virial: sum of overlap * distance over the pairs */
} sbc_jam_box;

/* the neighbour list's skin, in largest radii: a list is made again when a
   particle has moved by half of it */
#define SBC_JAM_SKIN 0.3

/* the pairs (i, j > i) in the cell list's order, visit(b, i, j, ctx) each (see jam_box.c) */
void sbc_jam_visit_pairs(sbc_jam_box *b, int nc, int *cell, void (*visit)(sbc_jam_box *, int, int, void *),
                         void *ctx);
/* forces into f (and the box's into x[dim n] when it is free), returns the energy (+ P V) */
double sbc_jam_forces(sbc_jam_box *b);
/* FIRE in the fixed box to every |f| < ftol or maxit iterations; returns the energy */
double sbc_jam_relax(sbc_jam_box *b, double ftol, int maxit);
/* FIRE over the centres and the box under the pressure P; returns E + P V */
double sbc_jam_relax_under(sbc_jam_box *b, double P, double ftol, int maxit);
/* the box to side L, the centres carried affinely */
void sbc_jam_scale(sbc_jam_box *b, double L);
/* every centre into [0, L) */
void sbc_jam_wrap_all(sbc_jam_box *b);
/* the centres reordered by cell (scratch [dim n]) */
void sbc_jam_sort_by_cell(sbc_jam_box *b, double *scratch);

#endif
