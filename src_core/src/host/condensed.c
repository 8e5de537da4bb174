/* The condensed tangent of an aggregate (docs/fe2.md, "The condensed
 * tangent"): the contact network's stiffness, linearized about the current
 * equilibrium, with everything but the frame's prescribed kinematics solved
 * for. Degrees of freedom per particle: the translation and the rotation
 * (u_x, u_y, theta in 2D; u, theta as 3-vectors in 3D). */
#include "condensed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/dense.h"
#include "../base/sparse.h"
#include "sbc/homogenize.h"
#include "sbc/tensor.h"


#define MAXB 12 /* the largest contact block: 2 spheres x 6 dofs */

/* 2D: d(loads)/d(dofs) of one contact, loads (f_i, tau_i, f_j, tau_j) over
 * dofs (u_i, theta_i, u_j, theta_j). With l = x_j - x_i, d = |l|, n = l/d,
 * t = (-n_y, n_x), overlap dn = R_i + R_j - d, fn = kn dn, the engine's
 * tangential force fs = (the spring's force on i) . t, and the force on j
 * f_j = fn n - fs t (eq. 6; the engine's moments tau = R fs on both):
 *   d f_j = -kn n (n.dl) + (fn/d) t (t.dl) + (fs/d) n (t.dl) - dfs t,  f_i = -f_j
 *   dfs = ks (t.dl - R_i dtheta_i - R_j dtheta_j)        sticking
 *   dfs = -sgn(fs) mu kn (n.dl)                           sliding (|fs| at mu fn)
 * with dl = du_j - du_i; the first two terms turn the normal force with the
 * branch, the third the tangential one. */
static int block_2d(const sbc_network *net, int k, double B[MAXB][MAXB])
{
    const int a = net->i[k], b = net->j[k];
    const double *xa = &net->x[2 * a], *xb = &net->x[2 * b];
    const double lx = xb[0] - xa[0], ly = xb[1] - xa[1], d = sqrt(lx * lx + ly * ly);
    const double Ra = net->r[a], Rb = net->r[b], dn = Ra + Rb - d;
    const sbc_frictional *law = &net->law;
    double n[2], t[2], fn, fs, M[2][2], w[2][2] = {{0, 0}, {0, 0}}, g[2] = {0, 0}, gr[2] = {0, 0};
    int p, q, stick, slide;
    if (!(dn > 0.0) || !(d > 0.0))
        return 0; /* open */
    n[0] = lx / d;
    n[1] = ly / d;
    t[0] = -n[1];
    t[1] = n[0];
    fn = law->kn * dn;
    fs = net->fs ? net->fs[3 * k] * t[0] + net->fs[3 * k + 1] * t[1] : 0.0;
    slide = law->ks > 0.0 && fabs(fs) >= law->mu * fn * (1.0 - 1e-12);
    stick = law->ks > 0.0 && !slide;
    for (p = 0; p < 2; ++p)
        for (q = 0; q < 2; ++q)
            M[p][q] = -law->kn * n[p] * n[q] + fn / d * t[p] * t[q] + fs / d * n[p] * t[q];
    if (stick) { /* dfs = g . dl + gr . (dtheta_i, dtheta_j) */
        for (p = 0; p < 2; ++p) {
            g[p] = law->ks * t[p];
            for (q = 0; q < 2; ++q)
                M[p][q] -= law->ks * t[p] * t[q];
            w[p][0] = law->ks * Ra * t[p];
            w[p][1] = law->ks * Rb * t[p];
        }
        gr[0] = -law->ks * Ra;
        gr[1] = -law->ks * Rb;
    } else if (slide) {
        const double s = fs < 0.0 ? -1.0 : 1.0;
        for (p = 0; p < 2; ++p) {
            g[p] = -s * law->mu * law->kn * n[p];
            for (q = 0; q < 2; ++q)
                M[p][q] += s * law->mu * law->kn * t[p] * n[q];
        }
    }
    for (p = 0; p < 2; ++p) {
        for (q = 0; q < 2; ++q) {
            B[3 + p][3 + q] = M[p][q];  /* f_j over u_j */
            B[3 + p][q] = -M[p][q];     /* f_j over u_i */
            B[p][3 + q] = -M[p][q];     /* f_i = -f_j */
            B[p][q] = M[p][q];
        }
        B[3 + p][2] = w[p][0];
        B[3 + p][5] = w[p][1];
        B[p][2] = -w[p][0];
        B[p][5] = -w[p][1];
        /* tau_i = R_i fs, tau_j = R_j fs */
        B[2][3 + p] = Ra * g[p];
        B[2][p] = -Ra * g[p];
        B[5][3 + p] = Rb * g[p];
        B[5][p] = -Rb * g[p];
    }
    B[2][2] = Ra * gr[0];
    B[2][5] = Ra * gr[1];
    B[5][2] = Rb * gr[0];
    B[5][5] = Rb * gr[1];
    return 1;
}

/* [v]x w = v x w */
static void cross_matrix(const double v[3], double X[3][3])
{
    X[0][0] = X[1][1] = X[2][2] = 0.0;
    X[0][1] = -v[2];
    X[0][2] = v[1];
    X[1][0] = v[2];
    X[1][2] = -v[0];
    X[2][0] = -v[1];
    X[2][1] = v[0];
}

/* 3D: the same over (u_i, theta_i, u_j, theta_j), each 3 (spheres.c and
 * bpm_bond.c's sbc_broken_bond_increment). With l, L, n, overlap dn as in
 * 2D, P = I - n n, the contact point halfway across the overlap
 * (r_i = s n, r_j = (s - L) n, s = R_i - dn/2) and the force on i
 * f = -kn dn n + fs (fs the spring, in the contact plane):
 *   d f = [kn n n - (kn dn / L) P] dl + dfs
 *   dfs = ks P dl + ks s [n]x dtheta_i - ks (s - L) [n]x dtheta_j - n (fs . dl) / L   sticking
 * (the spring loads with the contact point's tangential slip and is kept in
 * the turning plane), and sliding (|fs| at mu fn, direction e):
 *   dfs = -mu kn (n . dl) e + (I - e e) (the sticking dfs);
 * the loads are f on i, -f on j, the moments r_i x f and f x r_j, whose
 * arms change with dl too. */
static int block_3d(const sbc_network *net, int k, double B[MAXB][MAXB])
{
    const int a = net->i[k], b = net->j[k];
    const double *xa = &net->x[3 * a], *xb = &net->x[3 * b];
    const sbc_frictional *law = &net->law;
    double l[3], n[3], L = 0.0, dn, s, fn, fs[3] = {0, 0, 0}, f[3], e[3] = {0, 0, 0}, mag;
    double P[3][3], N[3][3], Fx[3][3], M[3][3], Wa[3][3], Wb[3][3], Ra[3][3], Rb[3][3], Ga[3][3], Gb[3][3];
    double D[3][3]; /* rows of df over (u_i, theta_i, u_j, theta_j) as 3 x 12 */
    double row[3][MAXB];
    int p, q, m, stick, slide;
    for (p = 0; p < 3; ++p) {
        l[p] = xb[p] - xa[p];
        L += l[p] * l[p];
    }
    L = sqrt(L);
    dn = net->r[a] + net->r[b] - L;
    if (!(dn > 0.0) || !(L > 0.0))
        return 0; /* open */
    for (p = 0; p < 3; ++p)
        n[p] = l[p] / L;
    s = net->r[a] - 0.5 * dn;
    fn = law->kn * dn;
    if (net->fs)
        for (p = 0; p < 3; ++p)
            fs[p] = net->fs[3 * k + p];
    mag = sqrt(sbc_dot3(fs, fs));
    slide = law->ks > 0.0 && mag >= law->mu * fn * (1.0 - 1e-12);
    stick = law->ks > 0.0 && !slide;
    for (p = 0; p < 3; ++p) {
        f[p] = -fn * n[p] + fs[p];
        if (slide && mag > 0.0)
            e[p] = fs[p] / mag;
    }
    cross_matrix(n, N);
    cross_matrix(f, Fx);
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            const double I = p == q ? 1.0 : 0.0;
            double tan_dl, tan_a, tan_b; /* the sticking dfs */
            P[p][q] = I - n[p] * n[q];
            tan_dl = (law->ks > 0.0 ? law->ks * P[p][q] : 0.0) - n[p] * fs[q] / L;
            tan_a = law->ks * s * N[p][q];
            tan_b = -law->ks * (s - L) * N[p][q];
            M[p][q] = law->kn * n[p] * n[q] - law->kn * dn / L * P[p][q] + (stick ? tan_dl : 0.0);
            Wa[p][q] = stick ? tan_a : 0.0;
            Wb[p][q] = stick ? tan_b : 0.0;
            D[p][q] = tan_dl; /* kept for the sliding projection */
            Ra[p][q] = tan_a;
            Rb[p][q] = tan_b;
        }
    if (slide) /* (I - e e) (sticking dfs) - mu kn e n^T */
        for (p = 0; p < 3; ++p)
            for (q = 0; q < 3; ++q) {
                double pd = 0.0, pa = 0.0, pb = 0.0;
                for (m = 0; m < 3; ++m) {
                    const double Pe = (p == m ? 1.0 : 0.0) - e[p] * e[m];
                    pd += Pe * D[m][q];
                    pa += Pe * Ra[m][q];
                    pb += Pe * Rb[m][q];
                }
                M[p][q] += pd - law->mu * law->kn * e[p] * n[q];
                Wa[p][q] = pa;
                Wb[p][q] = pb;
            }
    /* the moments' arms: d r_i = (n n^T / 2 + (s / L) P) dl, d r_j = (-n n^T / 2 + ((s - L) / L) P) dl */
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            double ga = 0.0, gb = 0.0;
            for (m = 0; m < 3; ++m) {
                ga += -Fx[p][m] * (0.5 * n[m] * n[q] + s / L * P[m][q]); /* d r_i x f = -[f]x d r_i */
                gb += Fx[p][m] * (-0.5 * n[m] * n[q] + (s - L) / L * P[m][q]); /* f x d r_j */
            }
            Ga[p][q] = ga;
            Gb[p][q] = gb;
        }
    for (p = 0; p < 3; ++p) /* df over (u_i, theta_i, u_j, theta_j) */
        for (q = 0; q < 3; ++q) {
            row[p][q] = -M[p][q];
            row[p][3 + q] = Wa[p][q];
            row[p][6 + q] = M[p][q];
            row[p][9 + q] = Wb[p][q];
        }
    for (p = 0; p < 3; ++p)
        for (q = 0; q < MAXB; ++q) {
            double ta = 0.0, tb = 0.0;
            for (m = 0; m < 3; ++m) {
                ta += s * N[p][m] * row[m][q];          /* r_i x df */
                tb += -(s - L) * N[p][m] * row[m][q];   /* df x r_j = -r_j x df */
            }
            if (q < 3) {
                ta -= Ga[p][q];
                tb -= Gb[p][q];
            } else if (q >= 6 && q < 9) {
                ta += Ga[p][q - 6];
                tb += Gb[p][q - 6];
            }
            B[p][q] = row[p][q];       /* f on i */
            B[3 + p][q] = ta;          /* moment on i */
            B[6 + p][q] = -row[p][q];  /* -f on j */
            B[9 + p][q] = tb;          /* moment on j */
        }
    return 1;
}

static int contact_block(const sbc_network *net, int k, double B[MAXB][MAXB])
{
    memset(B, 0, sizeof(double) * MAXB * MAXB);
    return net->dim == 3 ? block_3d(net, k, B) : block_2d(net, k, B);
}

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
            for (c = 0; c < nd; ++c)
                unk[nd * p + c] = count++;
    for (q = 0; q < f->n && bc != SBC_BC_T; ++q) {
        const int p0 = f->particle[q];
        const int size = bc == SBC_BC_P ? sbc_frame_family(f, q, members) : -1;
        for (kl = 0; kl < dim * dim; ++kl) /* F X_q on the translations */
            for (c = 0; c < dim; ++c)
                z0[(long)kl * ndof + nd * p0 + c] = c == kl / dim ? f->X[3 * q + kl % dim] : 0.0;
        if (size == 0)
            continue; /* a later member of a family */
        if (size < 0) {
            for (c = 0; c < nd; ++c)
                unk[nd * p0 + c] = -1;
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
 * column): colptr [n + 1], rows and vals [nt] are filled; their used length
 * is colptr[n]. */
static void compress_columns(int n, long nt, const int *ti, const int *tj, const double *tv, int *colptr, int *rows,
                             double *vals, int *next)
{
    long t;
    int c, at;
    memset(colptr, 0, sizeof(int) * (size_t)(n + 1));
    for (t = 0; t < nt; ++t)
        colptr[tj[t] + 1]++;
    for (c = 0; c < n; ++c)
        colptr[c + 1] += colptr[c];
    memcpy(next, colptr, sizeof(int) * (size_t)n);
    for (t = 0; t < nt; ++t) {
        const int to = next[tj[t]]++;
        rows[to] = ti[t];
        vals[to] = tv[t];
    }
    for (c = at = 0; c < n; ++c) { /* insertion sort of the column by row, then its duplicates summed */
        const int begin = colptr[c], end = colptr[c + 1];
        int k, m;
        for (k = begin + 1; k < end; ++k) {
            const int r = rows[k];
            const double v = vals[k];
            for (m = k; m > begin && rows[m - 1] > r; --m) {
                rows[m] = rows[m - 1];
                vals[m] = vals[m - 1];
            }
            rows[m] = r;
            vals[m] = v;
        }
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
}

/* The sparse solve of A Y = B (sparse.h), kept when each column of Y
 * satisfies its equations to 1e-9 of the largest |B| + |A| |Y| (a system with a
 * mechanism whose load is nil, such as the gear mode of a square lattice's
 * free rotations under (T), is solved so; the mechanism's share of Y is then
 * the solver's, and nothing loads it); 0 with B untouched otherwise. */
static int sparse_solve(int n, const int *colptr, const int *rows, const double *vals, int nrhs, double *B)
{
    double *Y = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1) * (size_t)nrhs);
    double *r = calloc((size_t)(n > 0 ? n : 1) * (size_t)nrhs, sizeof(double));
    double *size = calloc((size_t)(n > 0 ? n : 1) * (size_t)nrhs, sizeof(double));
    int ok = 0, c, k, m;
    if (Y && r && size && sbc_sparse_available()) {
        memcpy(Y, B, sizeof(double) * (size_t)n * (size_t)nrhs);
        if (sbc_sparse_solve(n, colptr, rows, vals, nrhs, Y) == 0) {
            ok = 1;
            for (c = 0; c < n; ++c) /* r = A Y - B, size = |A| |Y| + |B| */
                for (k = colptr[c]; k < colptr[c + 1]; ++k)
                    for (m = 0; m < nrhs; ++m) {
                        r[(long)rows[k] * nrhs + m] += vals[k] * Y[(long)c * nrhs + m];
                        size[(long)rows[k] * nrhs + m] += fabs(vals[k] * Y[(long)c * nrhs + m]);
                    }
            for (m = 0; m < nrhs && ok; ++m) { /* column by column, in the largest entries' norm */
                double miss = 0.0, scale = 0.0;
                for (k = 0; k < n; ++k) {
                    const long at = (long)k * nrhs + m;
                    ok = ok && isfinite(Y[at]);
                    miss = fmax(miss, fabs(r[at] - B[at]));
                    scale = fmax(scale, size[at] + fabs(B[at]));
                }
                ok = ok && miss <= 1e-9 * scale;
            }
            if (ok)
                memcpy(B, Y, sizeof(double) * (size_t)n * (size_t)nrhs);
        }
    }
    free(Y);
    free(r);
    free(size);
    return ok;
}

/* K Y = rhs over the nu unknowns, K as nt triplets, rhs [nu nc] row-major
 * overwritten by Y. Unknowns that nothing depends on (a rattler, the
 * rotation of a particle whose contacts all slide or have no tangential
 * spring) are dropped with their own equation and counted in *mechanisms;
 * the rest is solved by the sparse solver (sparse.h) where the core has one
 * and its solution holds, densely otherwise (dense.h, whose pivots <= tol
 * are counted as mechanisms too). */
static sbc_status solve_unknowns(int nu, long nt, const int *ti, const int *tj, const double *tv, int nc, double *rhs,
                                 double tol, int dense, int *mechanisms, sbc_error *err)
{
    int *colptr = malloc(sizeof(int) * (size_t)(nu + 1)), *rows = malloc(sizeof(int) * (size_t)(nt > 0 ? nt : 1));
    int *keep = malloc(sizeof(int) * (size_t)(nu > 0 ? nu : 1)), *next = malloc(sizeof(int) * (size_t)(nu + 1));
    double *vals = malloc(sizeof(double) * (size_t)(nt > 0 ? nt : 1)), *K = NULL;
    int u, v, k, nk, at, solved;
    sbc_status st = SBC_OK;
    if (!colptr || !rows || !keep || !next || !vals) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: out of memory for %ld stiffness entries", nt);
        goto done;
    }
    compress_columns(nu, nt, ti, tj, tv, colptr, rows, vals, next);
    for (u = nk = 0; u < nu; ++u) {
        int used = 0;
        for (k = colptr[u]; k < colptr[u + 1] && !used; ++k)
            used = vals[k] != 0.0;
        keep[u] = used ? nk++ : -1;
        if (!used)
            ++*mechanisms;
    }
    /* the kept unknowns compacted in place (keep[u] <= u, ascending: nothing unread is overwritten), solved, and
       spread back from the last (descending: the same) */
    for (u = at = 0; u < nu; ++u) {
        const int begin = colptr[u], end = colptr[u + 1];
        if (keep[u] < 0)
            continue;
        next[keep[u]] = at;
        for (k = begin; k < end; ++k)
            if (keep[rows[k]] >= 0 && vals[k] != 0.0) {
                rows[at] = keep[rows[k]];
                vals[at++] = vals[k];
            }
        memmove(&rhs[(long)keep[u] * nc], &rhs[(long)u * nc], sizeof(double) * (size_t)nc);
    }
    next[nk] = at;
    solved = !dense && sparse_solve(nk, next, rows, vals, nc, rhs);
    if (!solved) {
        if (!(K = calloc((size_t)nk * (size_t)nk, sizeof *K))) {
            st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: the dense solve of %d unknowns needs %.3g GB (%s)",
                          nk, 8e-9 * nk * (double)nk,
                          sbc_sparse_available() ? "the sparse solver found the system singular"
                                                 : "the core was built without a sparse solver: docs/fe2.md");
            goto done;
        }
        for (v = 0; v < nk; ++v)
            for (k = next[v]; k < next[v + 1]; ++k)
                K[(long)rows[k] * nk + v] = vals[k];
        *mechanisms += sbc_dense_solve(nk, K, nc, rhs, tol);
    }
    for (u = nu - 1; u >= 0; --u) {
        if (keep[u] >= 0)
            memmove(&rhs[(long)u * nc], &rhs[(long)keep[u] * nc], sizeof(double) * (size_t)nc);
        else
            memset(&rhs[(long)u * nc], 0, sizeof(double) * (size_t)nc);
    }
done:
    free(colptr);
    free(rows);
    free(keep);
    free(next);
    free(vals);
    free(K);
    return st;
}

sbc_status sbc_condensed_tangent(const sbc_network *net, const sbc_frame *f, sbc_bc bc, double C[81],
                                 int *mechanisms, sbc_error *err)
{
    const int dim = net->dim, nd = dofs_of(dim), nb = 2 * nd, ndof = nd * net->n, nc = dim * dim;
    const int extra = bc == SBC_BC_T ? nc + dim : 0;
    double (*blocks)[MAXB][MAXB] = NULL, *z0 = NULL, *tv = NULL, *rhs = NULL, *dz = NULL, *load = NULL, *a = NULL;
    int *unk = NULL, *frame_of = NULL, *open = NULL, *ti = NULL, *tj = NULL;
    int nu, k, s, u, v, kl, q, p;
    long nt = 0, cap;
    double scale = 0.0, G[9];
    sbc_status st = SBC_OK;
    memset(C, 0, sizeof(double) * 81);
    *mechanisms = 0;
    if (dim != f->dim || (dim != 2 && dim != 3))
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the condensed tangent of a %dD network on a %dD frame",
                        dim, f->dim);
    if (bc != SBC_BC_D && bc != SBC_BC_P && bc != SBC_BC_T)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the condensed tangent takes (D), (P) or (T)");
    blocks = malloc(sizeof *blocks * (size_t)(net->npair > 0 ? net->npair : 1));
    open = calloc((size_t)(net->npair > 0 ? net->npair : 1), sizeof *open);
    z0 = calloc((size_t)ndof * (size_t)nc, sizeof *z0);
    unk = malloc(sizeof *unk * (size_t)ndof);
    frame_of = malloc(sizeof *frame_of * (size_t)net->n);
    dz = malloc(sizeof *dz * (size_t)ndof);
    load = malloc(sizeof *load * (size_t)ndof);
    a = calloc(3 * (size_t)f->n, sizeof *a);
    if (!blocks || !open || !z0 || !unk || !frame_of || !dz || !load || !a) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory (condensed tangent of %d particles)", net->n);
        goto done;
    }
    for (p = 0; p < net->n; ++p)
        frame_of[p] = -1;
    for (q = 0; q < f->n; ++q)
        frame_of[f->particle[q]] = q;
    for (k = 0; k < net->npair; ++k)
        open[k] = !contact_block(net, k, blocks[k]);
    nu = number_unknowns(net, f, bc, frame_of, unk, z0) + extra;
    /* the unknowns' matrix as triplets: each contact's block, the multipliers of (T) */
    cap = (long)net->npair * nb * nb + (bc == SBC_BC_T ? (long)f->n * dim * (2 * dim + 2) : 0);
    ti = malloc(sizeof *ti * (size_t)(cap > 0 ? cap : 1));
    tj = malloc(sizeof *tj * (size_t)(cap > 0 ? cap : 1));
    tv = malloc(sizeof *tv * (size_t)(cap > 0 ? cap : 1));
    rhs = calloc((size_t)nu * (size_t)nc, sizeof *rhs);
    if (!ti || !tj || !tv || !rhs) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory (the condensed tangent's %d unknowns)", nu);
        goto done;
    }
    /* sum over each unknown's dofs of their loads: K y = -K z0 */
#define PUSH(r, c, value) (ti[nt] = (r), tj[nt] = (c), tv[nt++] = (value))
    for (k = 0; k < net->npair; ++k) {
        if (open[k])
            continue;
        for (s = 0; s < nb; ++s) {
            const int ra = slot_dof(net, k, s);
            if ((u = unk[ra]) < 0)
                continue;
            for (v = 0; v < nb; ++v) {
                const int cb = slot_dof(net, k, v);
                const double kab = blocks[k][s][v];
                if (kab == 0.0)
                    continue;
                scale = fmax(scale, fabs(kab));
                if (unk[cb] >= 0)
                    PUSH(u, unk[cb], kab);
                for (kl = 0; kl < nc; ++kl)
                    rhs[(long)u * nc + kl] -= kab * z0[(long)kl * ndof + cb];
            }
        }
    }
    if (bc == SBC_BC_T) { /* a_q = P A_q + m on the frame; sum_q x_q (x) A_q = F G (eq. 15); sum_q u_q = 0 */
        const int L = nu - extra;
        memset(G, 0, sizeof G);
        for (q = 0; q < f->n; ++q)
            for (k = 0; k < dim; ++k)
                for (s = 0; s < dim; ++s)
                    G[SBC_IJ(k, s)] += f->X[3 * q + k] * f->A[3 * q + s];
        for (q = 0; q < f->n; ++q) {
            const int p0 = f->particle[q];
            for (k = 0; k < dim; ++k) {
                const int row = unk[nd * p0 + k];
                for (s = 0; s < dim; ++s) { /* multipliers scaled to the stiffness */
                    PUSH(row, L + dim * k + s, f->A[3 * q + s] * scale);
                    PUSH(L + dim * k + s, row, f->A[3 * q + s] * scale / f->V);
                }
                PUSH(row, L + nc + k, scale);
                PUSH(L + nc + k, row, scale);
            }
        }
        for (kl = 0; kl < nc; ++kl) /* dF = e_k (x) e_l: (dF G)_cj = delta_ck G_lj */
            for (s = 0; s < dim; ++s)
                rhs[(long)(L + dim * (kl / dim) + s) * nc + kl] = G[SBC_IJ(kl % dim, s)] * scale / f->V;
    }
#undef PUSH
    if ((st = solve_unknowns(nu, nt, ti, tj, tv, nc, rhs, 1e-12 * scale, net->dense, mechanisms, err)) != SBC_OK)
        goto done;
    /* dP of each dF = e_k (x) e_l: the frame's forces a_q = -(loads on q), eq. 23 */
    for (kl = 0; kl < nc; ++kl) {
        double dP[9];
        for (s = 0; s < ndof; ++s)
            dz[s] = z0[(long)kl * ndof + s] + (unk[s] >= 0 ? rhs[(long)unk[s] * nc + kl] : 0.0);
        memset(load, 0, sizeof(double) * (size_t)ndof);
        for (k = 0; k < net->npair; ++k)
            if (!open[k])
                for (s = 0; s < nb; ++s)
                    for (v = 0; v < nb; ++v)
                        load[slot_dof(net, k, s)] += blocks[k][s][v] * dz[slot_dof(net, k, v)];
        for (q = 0; q < f->n; ++q)
            for (s = 0; s < dim; ++s)
                a[3 * q + s] = -load[nd * f->particle[q] + s];
        sbc_homogenize_P(f, a, dP);
        for (s = 0; s < nc; ++s)
            C[9 * SBC_IJ(s / dim, s % dim) + SBC_IJ(kl / dim, kl % dim)] = dP[SBC_IJ(s / dim, s % dim)];
    }
done:
    free(blocks);
    free(open);
    free(z0);
    free(unk);
    free(frame_of);
    free(dz);
    free(load);
    free(a);
    free(ti);
    free(tj);
    free(tv);
    free(rhs);
    return st;
}
