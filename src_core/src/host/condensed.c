/* The condensed tangent of an aggregate (docs/fe2.md, "The condensed
 * tangent"): the contact network's stiffness, linearized about the current
 * equilibrium, with everything but the frame's prescribed kinematics solved
 * for. Degrees of freedom per particle: the translation and the rotation
 * (u_x, u_y, theta in 2D; u, theta as 3-vectors in 3D). */
#include "condensed.h"
#include "contact_blocks.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/dense.h"
#include "../base/sparse.h"
#include "sbc/homogenize.h"
#include "sbc/tensor.h"


#define MAXB SBC_BLOCK_MOST


/* degrees of freedom per particle: translations and rotations */
static int dofs_of(int dim) { return dim == 3 ? 6 : 3; }

/* the global dof of slot s (0 .. 2 DOF - 1) of contact k */
static int slot_dof(const sbc_network *net, int k, int s)
{
    const int nd = dofs_of(net->dim);
    return nd * (s < nd ? net->i[k] : net->j[k]) + s % nd;
}

/* Which dofs are the system's unknowns. unk[dof]: its unknown (shared by a
 * (P) family), -1 where the frame prescribes it; z0 [dim^2][ndof]: the
 * prescribed part of each dof for dF = e_k (x) e_l (F X_q on the frame's
 * translations under (D) and (P)). Returns the number of unknowns. */
static int number_unknowns(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const int *frame_of, int *unk,
                           double *z0)
{
    const int dim = net->dim, nd = dofs_of(dim), ndof = nd * net->n;
    int p, c, q, m, members[8], count = 0, kl;
    for (p = 0; p < net->n; ++p)
        if (frame_of[p] < 0 || bc == SBC_BC_T)
            for (c = 0; c < nd; ++c) /* (T) with `rotation zero`: the frame's rotations prescribed, at 0 */
                unk[nd * p + c] = frame_of[p] >= 0 && c >= dim && net->frame_rotation_zero ? -1 : count++;
    for (q = 0; q < f->n && bc != SBC_BC_T; ++q) {
        const int p0 = f->particle[q];
        const int periodic = bc == SBC_BC_P || (bc == SBC_BC_MIXED && net->mode[3 * q] == SBC_MODE_P);
        const int size = periodic ? sbc_frame_family(f, q, members) : -1;
        for (kl = 0; kl < dim * dim; ++kl) /* F X_q on the translations */
            for (c = 0; c < dim; ++c)
                z0[(long)kl * ndof + nd * p0 + c] = c == kl / dim ? f->X[3 * q + kl % dim] : 0.0;
        if (size == 0)
            continue; /* a later member of a family */
        if (size < 0) { /* follows its commands; a free rotation is solved for (interior newton, mixed) */
            for (c = 0; c < nd; ++c)
                unk[nd * p0 + c] = c >= dim && net->free_rotation && net->free_rotation[q] ? count++ : -1;
            continue;
        }
        for (m = 0; m < size; ++m) {
            const int pm = f->particle[members[m]];
            if (q == f->corner[0]) { /* the corners follow F (eq. 17) and share one rotation, their moments balancing */
                for (c = 0; c < nd; ++c)
                    unk[nd * pm + c] = c < dim ? -1 : count + c - dim;
            } else { /* a family of periodic images: one fluctuation and one rotation (eqs. 19, 32-34) */
                for (c = 0; c < nd; ++c)
                    unk[nd * pm + c] = count + c;
            }
        }
        count += q == f->corner[0] ? nd - dim : nd;
    }
    return count;
}

/* Compressed columns of the nt triplets (ti, tj, tv) of an n x n matrix,
 * duplicates summed in the order given (a stable sort by row within each
 * column, by counting: the triplets bucketed by row, then dealt to their
 * columns row by row): colptr [n + 1], rows and vals [nt] are filled; their
 * used length is colptr[n]. next [n + 1] is workspace. 0 when out of memory. */
static int compress_columns(int n, long nt, const int *ti, const int *tj, const double *tv, int *colptr, int *rows,
                            double *vals, int *next)
{
    long t, *by_row = malloc(sizeof(long) * (size_t)(nt > 0 ? nt : 1));
    int c, r, at;
    if (!by_row)
        return 0;
    memset(next, 0, sizeof(int) * (size_t)(n + 1)); /* the triplets of each row, in the order given */
    for (t = 0; t < nt; ++t)
        next[ti[t] + 1]++;
    for (r = 0; r < n; ++r)
        next[r + 1] += next[r];
    for (t = 0; t < nt; ++t)
        by_row[next[ti[t]]++] = t;
    memset(colptr, 0, sizeof(int) * (size_t)(n + 1));
    for (t = 0; t < nt; ++t)
        colptr[tj[t] + 1]++;
    for (c = 0; c < n; ++c)
        colptr[c + 1] += colptr[c];
    memcpy(next, colptr, sizeof(int) * (size_t)n);
    for (t = 0; t < nt; ++t) { /* row by row: each column's entries sorted by row, ties in the order given */
        const long from = by_row[t];
        const int to = next[tj[from]]++;
        rows[to] = ti[from];
        vals[to] = tv[from];
    }
    free(by_row);
    for (c = at = 0; c < n; ++c) { /* duplicates summed */
        const int begin = colptr[c], end = colptr[c + 1];
        int k;
        colptr[c] = at;
        for (k = begin; k < end; ++k) {
            if (at > colptr[c] && rows[at - 1] == rows[k])
                vals[at - 1] += vals[k];
            else {
                rows[at] = rows[k];
                vals[at++] = vals[k];
            }
        }
    }
    colptr[n] = at;
    return 1;
}

/* the rounds of mechanisms found by the sparse solve before the dense LU takes over */
#define SPARSE_ROUNDS 8

/* The columns keep_col >= 0 and the rows keep_row >= 0 of the compressed
 * columns (colptr, rows, vals) of an n x n matrix, renumbered, into (cp, ri,
 * vx) of the nk x nk matrix they leave; returns its entry count (cp[nk]). */
static int reduced_columns(int n, const int *colptr, const int *rows, const double *vals, const int *keep_col,
                            const int *keep_row, int *cp, int *ri, double *vx)
{
    int u, k, at = 0;
    for (u = 0; u < n; ++u) {
        if (keep_col[u] < 0)
            continue;
        cp[keep_col[u]] = at;
        for (k = colptr[u]; k < colptr[u + 1]; ++k)
            if (keep_row[rows[k]] >= 0 && vals[k] != 0.0) {
                ri[at] = keep_row[rows[k]];
                vx[at++] = vals[k];
            }
    }
    return at;
}

/* renumbers the kept entries of keep [n] (>= 0) 0, 1, ...; their count */
static int renumber(int n, int *keep)
{
    int u, count = 0;
    for (u = 0; u < n; ++u)
        if (keep[u] >= 0)
            keep[u] = count++;
    return count;
}

/* K Y = rhs over the nu unknowns, K as nt triplets, rhs [nu nc] row-major
 * overwritten by Y. Unknowns that nothing depends on (a rattler, the
 * rotation of a particle whose contacts all slide or have no tangential
 * spring) are dropped with their own equation and counted in *mechanisms.
 * The rest is solved by the sparse solver (sparse.h) where the core has one:
 * a pivot at or below 1e-12 of the largest (of the rows scaled by their
 * sums) is a mechanism (the gear mode of a square lattice's free rotations:
 * neighbours spinning opposite ways), dropped with its pivot's equation, and
 * the rest factored again, as the dense LU (dense.h) does with a pivot at or
 * below tol, which solves it without a sparse solver. */
static sbc_status solve_unknowns(int nu, long nt, const int *ti, const int *tj, const double *tv, int nc, double *rhs,
                                 double tol, int dense, int *mechanisms, sbc_error *err)
{
    const size_t n1 = (size_t)(nu > 0 ? nu : 1), e1 = (size_t)(nt > 0 ? nt : 1);
    int *colptr = malloc(sizeof(int) * (n1 + 1)), *rows = malloc(sizeof(int) * e1), *next = malloc(sizeof(int) * (n1 + 1));
    int *keep_col = malloc(sizeof(int) * n1), *keep_row = malloc(sizeof(int) * n1), *cp = malloc(sizeof(int) * (n1 + 1));
    int *ri = malloc(sizeof(int) * e1), *drop_c = malloc(sizeof(int) * n1), *drop_r = malloc(sizeof(int) * n1);
    double *vals = malloc(sizeof(double) * e1), *vx = malloc(sizeof(double) * e1), *Y = NULL, *K = NULL;
    int u, v, k, nk = 0, round, ndrop, solved = 0;
    sbc_status st = SBC_OK;
    if (!colptr || !rows || !next || !keep_col || !keep_row || !cp || !ri || !drop_c || !drop_r || !vals || !vx ||
        !(Y = malloc(sizeof(double) * n1 * (size_t)nc))) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: out of memory for %ld stiffness entries", nt);
        goto done;
    }
    if (!compress_columns(nu, nt, ti, tj, tv, colptr, rows, vals, next)) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: out of memory for %ld stiffness entries", nt);
        goto done;
    }
    /* an unknown that nothing depends on and that depends on nothing (a rattler) is dropped with its equation;
       a column without entries whose equation has some (the rotation of a disc whose contacts all slide: its
       moment balance still binds the translations) is left to the pivots, which drop it with the equation
       that depends on the others */
    {
        double largest = 0.0; /* an equation whose entries are round-off (the moment of a sphere's normal forces,
                                 whose arms stay parallel to them) has none */
        for (k = 0; k < colptr[nu]; ++k)
            largest = fmax(largest, fabs(vals[k]));
        for (u = 0; u < nu; ++u)
            keep_row[u] = -1;
        for (u = 0; u < nu; ++u)
            for (k = colptr[u]; k < colptr[u + 1]; ++k)
                if (fabs(vals[k]) > 1e-12 * largest)
                    keep_row[rows[k]] = 0;
    }
    for (u = 0; u < nu; ++u) {
        int used = keep_row[u] == 0;
        for (k = colptr[u]; k < colptr[u + 1] && !used; ++k)
            used = vals[k] != 0.0;
        keep_col[u] = keep_row[u] = used ? 0 : -1;
        if (!used)
            ++*mechanisms;
    }
    for (round = 0; !solved; ++round) {
        int *cols_of = next; /* a reduced column's unknown, then a reduced row's equation */
        nk = renumber(nu, keep_col);
        renumber(nu, keep_row);
        cp[nk] = reduced_columns(nu, colptr, rows, vals, keep_col, keep_row, cp, ri, vx);
        for (u = 0; u < nu; ++u)
            if (keep_row[u] >= 0)
                memcpy(&Y[(long)keep_row[u] * nc], &rhs[(long)u * nc], sizeof(double) * (size_t)nc);
        if (dense || round >= SPARSE_ROUNDS)
            break;
        k = sbc_sparse_solve(nk, cp, ri, vx, nc, Y, 1e-12, drop_c, drop_r, &ndrop);
        if (k < 0)
            break;
        if (k == 0) {
            solved = 1;
            break;
        }
        /* mechanisms: their columns and pivot rows out, and again */
        for (u = 0; u < nu; ++u)
            if (keep_col[u] >= 0)
                cols_of[keep_col[u]] = u;
        for (v = 0; v < ndrop; ++v)
            drop_c[v] = cols_of[drop_c[v]];
        for (u = 0; u < nu; ++u)
            if (keep_row[u] >= 0)
                cols_of[keep_row[u]] = u;
        for (v = 0; v < ndrop; ++v)
            drop_r[v] = cols_of[drop_r[v]];
        for (v = 0; v < ndrop; ++v) {
            keep_col[drop_c[v]] = -1;
            keep_row[drop_r[v]] = -1;
        }
        *mechanisms += ndrop;
    }
    if (!solved) {
        if (!(K = calloc((size_t)nk * (size_t)nk, sizeof *K))) {
            st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: the dense solve of %d unknowns needs %.3g GB (%s)",
                          nk, 8e-9 * nk * (double)nk,
                          sbc_sparse_available() ? "the sparse solver found too many mechanisms"
                                                 : "the core was built without a sparse solver: docs/fe2.md");
            goto done;
        }
        for (v = 0; v < nk; ++v)
            for (k = cp[v]; k < cp[v + 1]; ++k)
                K[(long)ri[k] * nk + v] = vx[k];
        *mechanisms += sbc_dense_solve(nk, K, nc, Y, tol);
    }
    for (u = 0; u < nu; ++u) {
        if (keep_col[u] >= 0)
            memcpy(&rhs[(long)u * nc], &Y[(long)keep_col[u] * nc], sizeof(double) * (size_t)nc);
        else
            memset(&rhs[(long)u * nc], 0, sizeof(double) * (size_t)nc);
    }
done:
    free(colptr);
    free(rows);
    free(next);
    free(keep_col);
    free(keep_row);
    free(cp);
    free(ri);
    free(drop_c);
    free(drop_r);
    free(vals);
    free(vx);
    free(Y);
    free(K);
    return st;
}

/* The linearized system of a network under a frame's condition: the
 * contact blocks, the unknowns (number_unknowns) and the matrix over them as
 * triplets, bordered under (T) by the multipliers of a_q = P A_q + m and
 * eq. 15 (rows and columns L .. nu - 1). */
typedef struct linear_system {
    int dim, nd, nb, ndof, nc, nu, L;
    double (*blocks)[MAXB][MAXB];
    int *open;      /* [npair] 1: the pair does not touch */
    double *z0;     /* [nc ndof] the prescribed part of each dof for dF = e_k (x) e_l */
    int *unk;       /* [ndof] the dof's unknown, -1 when prescribed */
    int *ti, *tj;   /* [nt] */
    double *tv;     /* [nt] */
    long nt;
    double scale;   /* the largest contact stiffness entry */
    int unstiff;    /* with the pseudo-time term: the unknowns no contact stiffens, which it alone holds */
} linear_system;

static void system_free(linear_system *y)
{
    free(y->blocks);
    free(y->open);
    free(y->z0);
    free(y->unk);
    free(y->ti);
    free(y->tj);
    free(y->tv);
    memset(y, 0, sizeof *y);
}

static sbc_status system_build(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const char *what,
                               linear_system *y, sbc_error *err)
{
    const int dim = net->dim, nd = dofs_of(dim), nb = 2 * nd, ndof = nd * net->n, nc = dim * dim;
    const int extra = bc == SBC_BC_T ? nc + dim : 0;
    int *frame_of = NULL, k, s, u, v, q, p;
    long cap, contact_nt;
    sbc_status st = SBC_OK;
    memset(y, 0, sizeof *y);
    if (dim != f->dim || (dim != 2 && dim != 3))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: a %dD network on a %dD frame", what, dim, f->dim);
    if (bc != SBC_BC_D && bc != SBC_BC_P && bc != SBC_BC_T && bc != SBC_BC_MIXED)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: (D), (P), (T) or mixed only", what);
    if (bc == SBC_BC_MIXED && !net->mode)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: mixed without the frame's modes", what);
    for (q = 0; bc == SBC_BC_MIXED && q < f->n * 3; ++q)
        if (q % 3 < dim && net->mode[q] == SBC_MODE_T)
            return sbc_fail(err, SBC_ERR_INPUT, "%s: mixed with a T component (frame particle %d) is not linearized "
                            "here; D and P components are", what, q / 3);
    y->dim = dim, y->nd = nd, y->nb = nb, y->ndof = ndof, y->nc = nc;
    y->blocks = malloc(sizeof *y->blocks * (size_t)(net->npair > 0 ? net->npair : 1));
    y->open = calloc((size_t)(net->npair > 0 ? net->npair : 1), sizeof *y->open);
    y->z0 = calloc((size_t)ndof * (size_t)nc, sizeof *y->z0);
    y->unk = malloc(sizeof *y->unk * (size_t)ndof);
    frame_of = malloc(sizeof *frame_of * (size_t)net->n);
    if (!y->blocks || !y->open || !y->z0 || !y->unk || !frame_of) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "%s: out of memory (%d particles)", what, net->n);
        goto done;
    }
    for (p = 0; p < net->n; ++p)
        frame_of[p] = -1;
    for (q = 0; q < f->n; ++q)
        frame_of[f->particle[q]] = q;
    for (k = 0; k < net->npair; ++k)
        y->open[k] = !sbc_contact_block(net, k, y->blocks[k]);
    y->nu = number_unknowns(net, f, bc, frame_of, y->unk, y->z0) + extra;
    y->L = y->nu - extra;
    if (net->border > 0.0)
        y->scale = net->border; /* the multipliers' scale, fixed by the caller */
    cap = (long)net->npair * nb * nb + (bc == SBC_BC_T ? (long)f->n * dim * (2 * dim + 2) : 0) +
          (net->shift > 0.0 ? ndof : 0);
    y->ti = malloc(sizeof *y->ti * (size_t)(cap > 0 ? cap : 1));
    y->tj = malloc(sizeof *y->tj * (size_t)(cap > 0 ? cap : 1));
    y->tv = malloc(sizeof *y->tv * (size_t)(cap > 0 ? cap : 1));
    if (!y->ti || !y->tj || !y->tv) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "%s: out of memory (%d unknowns)", what, y->nu);
        goto done;
    }
    /* sum over each unknown's dofs of their loads */
#define PUSH(r, c, value) (y->ti[y->nt] = (r), y->tj[y->nt] = (c), y->tv[y->nt++] = (value))
    for (k = 0; k < net->npair; ++k) {
        if (y->open[k])
            continue;
        for (s = 0; s < nb; ++s) {
            if ((u = y->unk[slot_dof(net, k, s)]) < 0)
                continue;
            for (v = 0; v < nb; ++v) {
                const double kab = y->blocks[k][s][v];
                if (!(net->border > 0.0))
                    y->scale = fmax(y->scale, fabs(kab));
                if (kab != 0.0 && y->unk[slot_dof(net, k, v)] >= 0)
                    PUSH(u, y->unk[slot_dof(net, k, v)], kab);
            }
        }
    }
    contact_nt = y->nt; /* the contacts' entries end here */
    if (bc == SBC_BC_T) /* a_q = P A_q + m on the frame; sum_q x_q (x) A_q = F G (eq. 15); sum_q u_q = 0 */
        for (q = 0; q < f->n; ++q) {
            const int p0 = f->particle[q];
            for (k = 0; k < dim; ++k) {
                const int row = y->unk[nd * p0 + k];
                for (s = 0; s < dim; ++s) { /* multipliers scaled to the stiffness */
                    PUSH(row, y->L + dim * k + s, f->A[3 * q + s] * y->scale);
                    PUSH(y->L + dim * k + s, row, f->A[3 * q + s] * y->scale / f->V);
                }
                PUSH(row, y->L + nc + k, y->scale);
                PUSH(y->L + nc + k, row, y->scale);
            }
        }
    if (net->shift > 0.0) { /* interior newton's pseudo-time term: -shift on a translation, -shift R^2 on a
                               rotation (the loads' derivative is negative where the network is stable), once per
                               unknown (at its first dof) */
        unsigned char *done = calloc((size_t)(y->nu > 0 ? y->nu : 1), 1);
        long t;
        if (!done) {
            st = sbc_fail(err, SBC_ERR_NOMEM, "%s: out of memory (%d unknowns)", what, y->nu);
            goto done;
        }
        for (t = 0; t < contact_nt; ++t) /* 2: a contact stiffens the unknown (its row has an entry) */
            if (y->ti[t] < y->L)
                done[y->ti[t]] = 2;
        for (u = 0; u < y->L; ++u)
            y->unstiff += done[u] != 2;
        memset(done, 0, (size_t)(y->nu > 0 ? y->nu : 1));
        for (p = 0; p < ndof; ++p)
            if ((u = y->unk[p]) >= 0 && !done[u]) {
                done[u] = 1;
                PUSH(u, u, p % nd < dim ? -net->shift : -net->shift * net->r[p / nd] * net->r[p / nd]);
            }
        free(done);
    }
#undef PUSH
done:
    free(frame_of);
    if (st != SBC_OK)
        system_free(y);
    return st;
}

sbc_status sbc_condensed_tangent(const sbc_network *net, const sbc_frame *f, sbc_bc bc, double C[81],
                                 int *mechanisms, sbc_error *err)
{
    linear_system y;
    double *rhs = NULL, *dz = NULL, *load = NULL, *a = NULL, G[9];
    int k, s, u, v, kl, q;
    sbc_status st;
    memset(C, 0, sizeof(double) * 81);
    *mechanisms = 0;
    if ((st = system_build(net, f, bc, "condensed tangent", &y, err)) != SBC_OK)
        return st;
    rhs = calloc((size_t)y.nu * (size_t)y.nc, sizeof *rhs);
    dz = malloc(sizeof *dz * (size_t)y.ndof);
    load = malloc(sizeof *load * (size_t)y.ndof);
    a = calloc(3 * (size_t)f->n, sizeof *a);
    if (!rhs || !dz || !load || !a) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: out of memory (%d unknowns)", y.nu);
        goto done;
    }
    for (k = 0; k < net->npair; ++k) /* K y = -K z0 */
        if (!y.open[k])
            for (s = 0; s < y.nb; ++s)
                if ((u = y.unk[slot_dof(net, k, s)]) >= 0)
                    for (v = 0; v < y.nb; ++v)
                        for (kl = 0; kl < y.nc; ++kl)
                            rhs[(long)u * y.nc + kl] -= y.blocks[k][s][v] * y.z0[(long)kl * y.ndof + slot_dof(net, k, v)];
    if (bc == SBC_BC_T) { /* eq. 15 for dF = e_k (x) e_l: (dF G)_cj = delta_ck G_lj */
        const int dim = y.dim;
        memset(G, 0, sizeof G);
        for (q = 0; q < f->n; ++q)
            for (k = 0; k < dim; ++k)
                for (s = 0; s < dim; ++s)
                    G[SBC_IJ(k, s)] += f->X[3 * q + k] * f->A[3 * q + s];
        for (kl = 0; kl < y.nc; ++kl)
            for (s = 0; s < dim; ++s)
                rhs[(long)(y.L + dim * (kl / dim) + s) * y.nc + kl] = G[SBC_IJ(kl % dim, s)] * y.scale / f->V;
    }
    if ((st = solve_unknowns(y.nu, y.nt, y.ti, y.tj, y.tv, y.nc, rhs, 1e-12 * y.scale, net->dense, mechanisms,
                             err)) != SBC_OK)
        goto done;
    /* dP of each dF = e_k (x) e_l: the frame's forces a_q = -(loads on q), eq. 23 */
    for (kl = 0; kl < y.nc; ++kl) {
        const int dim = y.dim;
        double dP[9];
        for (s = 0; s < y.ndof; ++s)
            dz[s] = y.z0[(long)kl * y.ndof + s] + (y.unk[s] >= 0 ? rhs[(long)y.unk[s] * y.nc + kl] : 0.0);
        memset(load, 0, sizeof(double) * (size_t)y.ndof);
        for (k = 0; k < net->npair; ++k)
            if (!y.open[k])
                for (s = 0; s < y.nb; ++s)
                    for (v = 0; v < y.nb; ++v)
                        load[slot_dof(net, k, s)] += y.blocks[k][s][v] * dz[slot_dof(net, k, v)];
        for (q = 0; q < f->n; ++q)
            for (s = 0; s < dim; ++s)
                a[3 * q + s] = -load[y.nd * f->particle[q] + s];
        sbc_homogenize_P(f, a, dP);
        for (s = 0; s < y.nc; ++s)
            C[9 * SBC_IJ(s / dim, s % dim) + SBC_IJ(kl / dim, kl % dim)] = dP[SBC_IJ(s / dim, s % dim)];
    }
done:
    system_free(&y);
    free(rhs);
    free(dz);
    free(load);
    free(a);
    return st;
}

sbc_status sbc_condensed_correction(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const double *reaction,
                                    const double *moment, double *du, double *dtheta, int *mechanisms, sbc_error *err)
{
    linear_system y;
    double *rhs = NULL;
    int q, c, rot;
    sbc_status st;
    *mechanisms = 0;
    if ((st = system_build(net, f, bc, "update newton", &y, err)) != SBC_OK)
        return st;
    rot = y.nd - y.dim;
    memset(du, 0, sizeof(double) * 3 * (size_t)f->n);
    memset(dtheta, 0, sizeof(double) * (size_t)rot * (size_t)f->n);
    if (!(rhs = calloc((size_t)y.nu, sizeof *rhs))) {
        system_free(&y);
        return sbc_fail(err, SBC_ERR_NOMEM, "update newton: out of memory (%d unknowns)", y.nu);
    }
    /* the loads' change that balances each frame particle: the contact loads on q are -a_q (eq. 5), so
       K dz = a on its translations and m on its rotations, summed over a (P) family's shared unknowns */
    for (q = 0; q < f->n; ++q)
        for (c = 0; c < y.nd; ++c) {
            const int u = y.unk[y.nd * f->particle[q] + c];
            if (u >= 0)
                rhs[u] += c < y.dim ? reaction[3 * q + c] : moment[rot * q + c - y.dim];
        }
    if ((st = solve_unknowns(y.nu, y.nt, y.ti, y.tj, y.tv, 1, rhs, 1e-12 * y.scale, net->dense, mechanisms, err)) ==
        SBC_OK)
        for (q = 0; q < f->n; ++q)
            for (c = 0; c < y.nd; ++c) {
                const int u = y.unk[y.nd * f->particle[q] + c];
                if (u < 0)
                    continue;
                if (c < y.dim)
                    du[3 * q + c] = rhs[u];
                else
                    dtheta[rot * q + c - y.dim] = rhs[u];
            }
    system_free(&y);
    free(rhs);
    return st;
}

int sbc_condensed_unknowns(const sbc_network *net, const sbc_frame *f, sbc_bc bc, int *unk, sbc_error *err)
{
    const int nd = dofs_of(net->dim), ndof = nd * net->n, nc = net->dim * net->dim;
    int *frame_of = malloc(sizeof *frame_of * (size_t)(net->n > 0 ? net->n : 1)), q, count = -1;
    double *z0 = calloc((size_t)ndof * (size_t)nc, sizeof *z0);
    if (!frame_of || !z0)
        sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory (%d particles)", net->n);
    else {
        for (q = 0; q < net->n; ++q)
            frame_of[q] = -1;
        for (q = 0; q < f->n; ++q)
            frame_of[f->particle[q]] = q;
        count = number_unknowns(net, f, bc, frame_of, unk, z0);
    }
    free(frame_of);
    free(z0);
    return count;
}

int sbc_condensed_unstiffened(const sbc_network *net, const sbc_frame *f, sbc_bc bc, sbc_error *err)
{
    linear_system y;
    int count;
    if (system_build(net, f, bc, "interior newton", &y, err) != SBC_OK)
        return -1;
    count = y.unstiff;
    system_free(&y);
    return count;
}

sbc_status sbc_condensed_newton_step(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const double *residual,
                                     double *dy, int *mechanisms, sbc_error *err)
{
    linear_system y;
    int u;
    sbc_status st;
    *mechanisms = 0;
    if ((st = system_build(net, f, bc, "interior newton", &y, err)) != SBC_OK)
        return st;
    for (u = 0; u < y.nu; ++u)
        dy[u] = -residual[u];
    st = solve_unknowns(y.nu, y.nt, y.ti, y.tj, y.tv, 1, dy, 1e-12 * y.scale, net->dense, mechanisms, err);
    *mechanisms += y.unstiff; /* held by the pseudo-time term, as the pivots hold those they find */
    system_free(&y);
    return st;
}
