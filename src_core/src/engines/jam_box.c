/* servo_bc: the generators' periodic box of unit-stiffness overlaps (jam_box.h). */
#include "jam_box.h"
#include "fire.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the overlap force of the pair (i, j) at separation dx (d2 = |dx|^2) into f,
   its overlap * distance into the virial; returns the energy overlap^2 / 2 */
static double overlap_force(sbc_jam_box *b, int i, int j, const double *dx, double d2)
{
    const int dim = b->dim;
    const double rs = b->r[i] + b->r[j];
    double d, ov;
    int k;
    if (d2 >= rs * rs)
        return 0.0;
    d = sqrt(d2);
    ov = rs - d;
    b->virial += ov * d;
    if (d > 0.0)
        for (k = 0; k < dim; ++k) {
            b->f[dim * i + k] -= ov * dx[k] / d;
            b->f[dim * j + k] += ov * dx[k] / d;
        }
    return 0.5 * ov * ov;
}

/* the pair at its nearest image */
static double pair_force(sbc_jam_box *b, int i, int j)
{
    const int dim = b->dim;
    double dx[3], d2 = 0.0;
    int k;
    for (k = 0; k < dim; ++k) {
        dx[k] = sbc_jam_image(b->x[dim * j + k] - b->x[dim * i + k], b->L);
        d2 = k ? d2 + dx[k] * dx[k] : dx[k] * dx[k];
    }
    return overlap_force(b, i, j, dx, d2);
}

/* The listed pairs' forces, energy (returned) and virial, each pair at the
 * image fixed when it was listed (the pressure protocol's centres are not
 * wrapped between lists): shift (s_0 + 1) + 3 (s_1 + 1) + 9 (s_2 + 1), x_j -
 * x_i + s L. */
static double listed_forces_shifted(sbc_jam_box *b)
{
    const int dim = b->dim;
    const double L = b->L, *x = b->x, *r = b->r;
    double *f = b->f, e = 0.0, virial = 0.0, fi[3] = {0.0, 0.0, 0.0};
    int q, k, i = b->npair ? b->pair[0] : 0;
    /* the list runs by i ascending: f_i gathered here, written once per i */
    for (q = 0; q < b->npair; ++q) {
        const int j = b->pair[3 * q + 1];
        double dx[3], d2 = 0.0, d, ov, s, rs;
        int shift = b->pair[3 * q + 2];
        if (b->pair[3 * q] != i) {
            for (k = 0; k < dim; ++k) {
                f[dim * i + k] += fi[k];
                fi[k] = 0.0;
            }
            i = b->pair[3 * q];
        }
        rs = r[i] + r[j];
        for (k = 0; k < dim; ++k, shift /= 3) {
            dx[k] = x[dim * j + k] - x[dim * i + k] + (shift % 3 - 1) * L;
            d2 += dx[k] * dx[k];
        }
        if (d2 >= rs * rs || !(d2 > 0.0))
            continue;
        d = sqrt(d2);
        ov = rs - d;
        virial += ov * d;
        e += 0.5 * ov * ov;
        s = ov / d;
        for (k = 0; k < dim; ++k) {
            fi[k] -= s * dx[k];
            f[dim * j + k] += s * dx[k];
        }
    }
    for (k = 0; k < dim; ++k)
        f[dim * i + k] += fi[k];
    b->virial = virial;
    return e;
}

/* the cell of particle i along each axis, in a box of nc cells per side */
static void cell_of(const sbc_jam_box *b, int i, int nc, int c[3])
{
    int k;
    c[2] = 0;
    for (k = 0; k < b->dim; ++k) {
        c[k] = (int)(b->x[b->dim * i + k] / b->L * nc);
        if (c[k] >= nc) c[k] = nc - 1;
    }
}

/* The pairs (i, j > i) in the order the overlap sum visits them: every pair
 * when nc < 3 (or above the cells allocated), else i ascending and, for each,
 * the 3^dim cells around its own in a periodic cell list of nc cells a side
 * (each >= 2 rmax wide), each cell's particles newest first. visit(b, i, j)
 * for each; cell[i] (when not NULL) gets particle i's cell. */
void sbc_jam_visit_pairs(sbc_jam_box *b, int nc, int *cell, void (*visit)(sbc_jam_box *, int, int, void *),
                         void *ctx)
{
    const int dim = b->dim;
    int i, j, k, ncell = 1, oz, oy, ox;
    if (nc < 3 || nc > b->cells) {
        for (i = 0; i < b->n; ++i)
            for (j = i + 1; j < b->n; ++j)
                visit(b, i, j, ctx);
        return;
    }
    for (k = 0; k < dim; ++k)
        ncell *= nc;
    for (i = 0; i < ncell; ++i)
        b->head[i] = -1;
    for (i = 0; i < b->n; ++i) {
        int c[3];
        cell_of(b, i, nc, c);
        k = (c[2] * nc + c[1]) * nc + c[0];
        b->next[i] = b->head[k];
        b->head[k] = i;
        if (cell)
            cell[i] = k;
    }
    for (i = 0; i < b->n; ++i) {
        int c[3];
        cell_of(b, i, nc, c);
        for (oz = dim == 3 ? -1 : 0; oz <= (dim == 3 ? 1 : 0); ++oz)
            for (oy = -1; oy <= 1; ++oy)
                for (ox = -1; ox <= 1; ++ox) {
                    const int z = dim == 3 ? (c[2] + oz + nc) % nc : 0;
                    for (j = b->head[(z * nc + (c[1] + oy + nc) % nc) * nc + (c[0] + ox + nc) % nc]; j >= 0;
                         j = b->next[j])
                        if (j > i)
                            visit(b, i, j, ctx);
                }
    }
}

static void sum_pair(sbc_jam_box *b, int i, int j, void *e) { *(double *)e += pair_force(b, i, j); }

/* the pair (i, j) goes to the list when its gap is below the skin; a full list
   (out of memory) is marked by listed = 0 */
/* the pair (i, j) to the list (grown as needed; out of memory: listed = 0) */
static void add_pair(sbc_jam_box *b, int i, int j, int shift)
{
    if (!b->listed)
        return;
    if (b->npair == b->cap) {
        int cap = b->cap ? 2 * b->cap : 8 * b->n, *more = realloc(b->pair, sizeof(int) * 3 * (size_t)cap);
        if (!more) {
            b->listed = 0;
            return;
        }
        b->pair = more;
        b->cap = cap;
    }
    b->pair[3 * b->npair] = i;
    b->pair[3 * b->npair + 1] = j;
    b->pair[3 * b->npair + 2] = shift;
    ++b->npair;
}

static void list_pair(sbc_jam_box *b, int i, int j, void *unused)
{
    double d2 = 0.0, reach = b->r[i] + b->r[j] + b->skin;
    int k;
    (void)unused;
    for (k = 0; k < b->dim; ++k) {
        const double d = sbc_jam_image(b->x[b->dim * j + k] - b->x[b->dim * i + k], b->L);
        d2 += d * d;
    }
    if (d2 < reach * reach)
        add_pair(b, i, j, 0);
}

/* the pressure protocol's: the centres in [0, L), the nearest image's shift
   kept with the pair (listed_forces_shifted) */
static void list_pair_shifted(sbc_jam_box *b, int i, int j, void *unused)
{
    const double L = b->L, reach = b->r[i] + b->r[j] + b->skin;
    double d2 = 0.0;
    int k, shift = 0, unit = 1;
    (void)unused;
    for (k = 0; k < b->dim; ++k, unit *= 3) {
        double d = b->x[b->dim * j + k] - b->x[b->dim * i + k];
        int s = 1;
        if (d > 0.5 * L) {
            d -= L;
            s = 0;
        } else if (d < -0.5 * L) {
            d += L;
            s = 2;
        }
        d2 += d * d;
        shift += unit * s;
    }
    if (d2 < reach * reach)
        add_pair(b, i, j, shift);
}

/* Whether the list still holds every pair that can touch, in the order of
   visit_pairs: the same cell size, no particle in another cell, none moved by
   more than half the skin since it was made. */
static int list_holds(const sbc_jam_box *b, int nc)
{
    const int dim = b->dim, direct = nc < 3 || nc > b->cells;
    int i, k;
    if (!b->listed || b->listed != (direct ? -1 : nc))
        return 0;
    for (i = 0; i < b->n; ++i) {
        double d2 = 0.0;
        for (k = 0; k < dim; ++k) {
            const double d = sbc_jam_image(b->x[dim * i + k] - b->x0[dim * i + k], b->L);
            d2 += d * d;
        }
        if (4.0 * d2 >= b->skin * b->skin)
            return 0;
        if (!direct) {
            int c[3];
            cell_of(b, i, nc, c);
            if ((c[2] * nc + c[1]) * nc + c[0] != b->cell[i])
                return 0;
        }
    }
    return 1;
}

/* Whether the list still holds every pair that can touch after the box went
 * from L_listed to L (pressure protocol): a pair left out was >= r_i + r_j +
 * skin apart; the box's change moves it by at most (1 - L / L_listed)(2 r_max +
 * skin) closer, each particle's own move (from its affinely carried place;
 * the centres are not wrapped between lists) by u, so it still cannot touch
 * while 2 u_max <= skin lambda - (1 - lambda) 2 r_max, lambda = min(1, L /
 * L_listed). */
static int list_follows(const sbc_jam_box *b, int nc)
{
    const int dim = b->dim, direct = nc < 3 || nc > b->cells;
    const double scale = b->L / b->L_listed, lambda = scale < 1.0 ? scale : 1.0,
                 room = b->skin * lambda - (1.0 - lambda) * 2.0 * b->rmax;
    int i, k;
    if (!b->listed || b->listed != (direct ? -1 : nc) || !(room > 0.0))
        return 0;
    for (i = 0; i < b->n; ++i) {
        double d2 = 0.0;
        for (k = 0; k < dim; ++k) {
            const double d = b->x[dim * i + k] - scale * b->x0[dim * i + k];
            d2 += d * d;
        }
        if (4.0 * d2 >= room * room)
            return 0;
    }
    return 1;
}

/* every centre into [0, L) (the pressure protocol's are not wrapped between lists) */
void sbc_jam_wrap_all(sbc_jam_box *b)
{
    size_t k;
    for (k = 0; k < (size_t)b->dim * (size_t)b->n; ++k)
        b->x[k] = sbc_jam_wrap(b->x[k], b->L);
}

/* the pressure protocol's box from its coordinate y = x[dim n]: L = L_start
   exp(y / c), every centre carried with it (its scaled place unchanged) */
static void follow_box(sbc_jam_box *b)
{
    const size_t dn = (size_t)b->dim * (size_t)b->n;
    const double L = b->L_start * exp(b->x[dn] / b->c), ratio = L / b->L;
    size_t k;
    if (L == b->L)
        return;
    for (k = 0; k < dn; ++k)
        b->x[k] *= ratio;
    b->L = L;
}

/* Overlap forces (unit stiffness) and energy sum(overlap^2)/2 in the periodic
 * box, the pairs summed in visit_pairs' order: from the list of the pairs that
 * may touch while it holds (the pairs left out add exactly nothing, so the
 * sums are the same to the bit), else over every visited pair. The pressure
 * protocol's cells are 2 r_max + skin wide (every listed pair in neighbouring
 * cells); with the box free, x[dim n] gets its force, -d(E + P V)/dy at fixed
 * scaled centres (y = c ln(L / L_start): (sum overlap * distance - dim P V) / c),
 * and the energy P V. */
double sbc_jam_forces(sbc_jam_box *b)
{
    const size_t dn = (size_t)b->dim * (size_t)b->n;
    double e = 0.0, V;
    int k, nc, direct;
    if (b->box_free)
        follow_box(b);
    nc = (int)(b->L / (2.0 * b->rmax + (b->pressure ? b->skin : 0.0)));
    direct = nc < 3 || nc > b->cells;
    V = b->dim == 3 ? b->L * b->L * b->L : b->L * b->L;
    memset(b->f, 0, sizeof(double) * dn);
    b->virial = 0.0;
    if (!(b->pressure ? list_follows(b, nc) : list_holds(b, nc))) {
        if (b->pressure)
            sbc_jam_wrap_all(b);
        b->npair = 0;
        b->listed = direct ? -1 : nc;
        sbc_jam_visit_pairs(b, nc, b->cell, b->pressure ? list_pair_shifted : list_pair, NULL);
        memcpy(b->x0, b->x, sizeof(double) * dn);
        b->L_listed = b->L;
    }
    if (!b->listed)
        sbc_jam_visit_pairs(b, nc, NULL, sum_pair, &e);
    else if (b->pressure)
        e = listed_forces_shifted(b);
    else
        for (k = 0; k < b->npair; ++k)
            e += pair_force(b, b->pair[3 * k], b->pair[3 * k + 1]);
    if (b->box_free) {
        b->f[dn] = (b->virial - b->dim * b->P * V) / b->c;
        e += b->P * V;
    }
    return e;
}

static double forces_cb(void *ctx) { return sbc_jam_forces(ctx); }

static void wrap_cb(void *ctx, size_t k)
{
    sbc_jam_box *b = ctx;
    b->x[k] = sbc_jam_wrap(b->x[k], b->L);
}

/* FIRE minimization of the overlap energy in the fixed box, at most maxit
   iterations; returns it. */
double sbc_jam_relax(sbc_jam_box *b, double ftol, int maxit)
{
    sbc_fire_problem p;
    p.n = (size_t)b->dim * (size_t)b->n;
    p.x = b->x;
    p.v = b->v;
    p.f = b->f;
    p.forces = forces_cb;
    p.place = b->pressure ? NULL : wrap_cb; /* the pressure protocol's: when listed (forces) */
    p.ctx = b;
    p.dt_max = 1.0;
    b->listed = 0; /* the box may have been put back (L and x) since */
    return sbc_fire_minimize(&p, ftol, maxit);
}

/* FIRE minimization of the enthalpy E + P V over the centres and the box, at
   most maxit iterations; returns E + P V. */
double sbc_jam_relax_under(sbc_jam_box *b, double P, double ftol, int maxit)
{
    sbc_fire_problem p;
    const size_t dn = (size_t)b->dim * (size_t)b->n;
    double h;
    p.n = dn + 1;
    p.x = b->x;
    p.v = b->v;
    p.f = b->f;
    p.forces = forces_cb;
    p.place = NULL; /* centres wrapped when listed (forces) */
    p.ctx = b;
    p.dt_max = 1.0;
    b->P = P;
    b->box_free = 1;
    b->x[dn] = b->c * log(b->L / b->L_start);
    h = sbc_fire_minimize(&p, ftol, maxit);
    b->box_free = 0;
    return h;
}

void sbc_jam_scale(sbc_jam_box *b, double L)
{
    int k;
    for (k = 0; k < b->dim * b->n; ++k)
        b->x[k] *= L / b->L;
    b->L = L;
    b->listed = 0;
}

/* The centres reordered by their cell (the radii keep their order: the
   centres are independent of them), so that neighbours sit near each other in
   memory; scratch [dim n]. */
void sbc_jam_sort_by_cell(sbc_jam_box *b, double *scratch)
{
    const int dim = b->dim, nc = (int)(b->L / (2.0 * b->rmax + b->skin));
    int i, k, ncell = 1, at = 0;
    if (nc < 3 || nc > b->cells)
        return;
    for (k = 0; k < dim; ++k)
        ncell *= nc;
    for (k = 0; k < ncell; ++k)
        b->head[k] = 0;
    for (i = 0; i < b->n; ++i) {
        int c[3];
        cell_of(b, i, nc, c);
        b->cell[i] = (c[2] * nc + c[1]) * nc + c[0];
        ++b->head[b->cell[i]];
    }
    for (k = 0; k < ncell; ++k) {
        const int count = b->head[k];
        b->head[k] = at;
        at += count;
    }
    for (i = 0; i < b->n; ++i) {
        const int to = b->head[b->cell[i]]++;
        for (k = 0; k < dim; ++k)
            scratch[dim * to + k] = b->x[dim * i + k];
    }
    memcpy(b->x, scratch, sizeof(double) * (size_t)dim * (size_t)b->n);
}

