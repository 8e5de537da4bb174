/* The condensed tangent of a 2D disc aggregate (docs/fe2.md, "The condensed
 * tangent"): the contact network's stiffness, linearized about the current
 * equilibrium, with everything but the frame's prescribed kinematics solved
 * for. Degrees of freedom: u_x, u_y and theta per disc (3p, 3p + 1, 3p + 2). */
#include "condensed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/dense.h"
#include "sbc/homogenize.h"

#define DOF 3 /* per disc in 2D */

/* d(loads)/d(dofs) of one contact, loads (f_i, tau_i, f_j, tau_j) over dofs
 * (u_i, theta_i, u_j, theta_j). With l = x_j - x_i, d = |l|, n = l/d,
 * t = (-n_y, n_x), overlap dn = R_i + R_j - d, fn = kn dn, and the force on
 * j f_j = fn n - fs t (eq. 6; the engine's moments tau = R fs on both):
 *   d f_j = -kn n (n.dl) + (fn/d) t (t.dl) + (fs/d) n (t.dl) - dfs t,  f_i = -f_j
 *   dfs = ks (t.dl - R_i dtheta_i - R_j dtheta_j)        sticking
 *   dfs = -sgn(fs) mu kn (n.dl)                           sliding (|fs| at mu fn)
 * with dl = du_j - du_i; the first two terms turn the normal force with the
 * branch, the third the tangential one. */
static int contact_block(const sbc_network *net, int k, double B[6][6])
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
    fs = net->fs ? net->fs[k] : 0.0;
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
    memset(B, 0, sizeof(double) * 36);
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

/* the global dof of slot s (0..5) of contact k */
static int slot_dof(const sbc_network *net, int k, int s) { return DOF * (s < 3 ? net->i[k] : net->j[k]) + s % 3; }

/* Which dofs are the system's unknowns. unk[dof]: its unknown (shared by a
 * (P) family), -1 where the frame prescribes it; z0 [dim^2][ndof]: the
 * prescribed part of each dof for dF = e_k (x) e_l (F X_q on the frame's
 * translations under (D) and (P)). Returns the number of unknowns. */
static int number_unknowns(const sbc_network *net, const sbc_frame *f, sbc_bc bc, const int *frame_of, int *unk,
                           double *z0)
{
    const int ndof = DOF * net->n;
    int p, c, q, m, members[8], count = 0, kl;
    for (p = 0; p < net->n; ++p)
        if (frame_of[p] < 0 || bc == SBC_BC_T)
            for (c = 0; c < DOF; ++c)
                unk[DOF * p + c] = count++;
    for (q = 0; q < f->n && bc != SBC_BC_T; ++q) {
        const int p0 = f->particle[q];
        const int size = bc == SBC_BC_P ? sbc_frame_family(f, q, members) : -1;
        for (kl = 0; kl < 4; ++kl) /* F X_q on the translations */
            for (c = 0; c < 2; ++c)
                z0[(long)kl * ndof + DOF * p0 + c] = c == kl / 2 ? f->X[3 * q + kl % 2] : 0.0;
        if (size == 0 || size == 4)
            continue; /* a later member, or the corners (which follow F, eq. 17) */
        if (size < 0) {
            for (c = 0; c < DOF; ++c)
                unk[DOF * p0 + c] = -1;
            continue;
        }
        for (m = 0; m < size; ++m) /* a (P) pair: one fluctuation and one rotation (eqs. 19, 32-34) */
            for (c = 0; c < DOF; ++c)
                unk[DOF * f->particle[members[m]] + c] = count + c;
        count += DOF;
    }
    if (bc == SBC_BC_P) { /* the corners follow F and share one rotation, their moments balancing */
        for (c = 0; c < 4; ++c) {
            const int p0 = f->particle[f->corner[c]];
            unk[DOF * p0] = unk[DOF * p0 + 1] = -1;
            unk[DOF * p0 + 2] = count;
        }
        ++count;
    }
    return count;
}

sbc_status sbc_condensed_tangent(const sbc_network *net, const sbc_frame *f, sbc_bc bc, double C[81],
                                 int *mechanisms, sbc_error *err)
{
    const int ndof = DOF * net->n, extra = bc == SBC_BC_T ? 4 + 2 : 0;
    double (*blocks)[6][6] = NULL, *z0 = NULL, *K = NULL, *rhs = NULL, *dz = NULL, *load = NULL, *a = NULL;
    int *unk = NULL, *frame_of = NULL, *keep = NULL, *open = NULL;
    int nu, nk, k, s, u, v, kl, q, p;
    double scale = 0.0, G[9];
    sbc_status st = SBC_OK;
    memset(C, 0, sizeof(double) * 81);
    *mechanisms = 0;
    if (f->dim != 2)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the condensed tangent is built for 2D aggregates only");
    if (bc != SBC_BC_D && bc != SBC_BC_P && bc != SBC_BC_T)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the condensed tangent takes (D), (P) or (T)");
    blocks = malloc(sizeof *blocks * (size_t)(net->npair > 0 ? net->npair : 1));
    open = calloc((size_t)(net->npair > 0 ? net->npair : 1), sizeof *open);
    z0 = calloc((size_t)ndof * 4, sizeof *z0);
    unk = malloc(sizeof *unk * (size_t)ndof);
    frame_of = malloc(sizeof *frame_of * (size_t)net->n);
    dz = malloc(sizeof *dz * (size_t)ndof);
    load = malloc(sizeof *load * (size_t)ndof);
    a = calloc(3 * (size_t)f->n, sizeof *a);
    if (!blocks || !open || !z0 || !unk || !frame_of || !dz || !load || !a) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory (condensed tangent of %d discs)", net->n);
        goto done;
    }
    for (p = 0; p < net->n; ++p)
        frame_of[p] = -1;
    for (q = 0; q < f->n; ++q)
        frame_of[f->particle[q]] = q;
    for (k = 0; k < net->npair; ++k)
        open[k] = !contact_block(net, k, blocks[k]);
    nu = number_unknowns(net, f, bc, frame_of, unk, z0) + extra;
    /* the unknowns' matrix, before the dead ones are dropped */
    K = calloc((size_t)nu * (size_t)nu, sizeof *K);
    rhs = calloc((size_t)nu * 4, sizeof *rhs);
    keep = malloc(sizeof *keep * (size_t)nu);
    if (!K || !rhs || !keep) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "material point: the condensed tangent's %d unknowns need %.3g GB (a "
                      "dense solve)", nu, 8e-9 * nu * (double)nu);
        goto done;
    }
    /* sum over each unknown's dofs of their loads: K y = -K z0 */
    for (k = 0; k < net->npair; ++k) {
        if (open[k])
            continue;
        for (s = 0; s < 6; ++s) {
            const int ra = slot_dof(net, k, s);
            if ((u = unk[ra]) < 0)
                continue;
            for (v = 0; v < 6; ++v) {
                const int cb = slot_dof(net, k, v);
                const double kab = blocks[k][s][v];
                if (kab == 0.0)
                    continue;
                scale = fmax(scale, fabs(kab));
                if (unk[cb] >= 0)
                    K[(long)u * nu + unk[cb]] += kab;
                for (kl = 0; kl < 4; ++kl)
                    rhs[(long)u * 4 + kl] -= kab * z0[(long)kl * ndof + cb];
            }
        }
    }
    if (bc == SBC_BC_T) { /* a_q = P A_q + m on the frame; sum_q x_q (x) A_q = F G (eq. 15); sum_q u_q = 0 */
        const int L = nu - extra;
        memset(G, 0, sizeof G);
        for (q = 0; q < f->n; ++q)
            for (k = 0; k < 2; ++k)
                for (s = 0; s < 2; ++s)
                    G[SBC_IJ(k, s)] += f->X[3 * q + k] * f->A[3 * q + s];
        for (q = 0; q < f->n; ++q) {
            const int p0 = f->particle[q];
            for (k = 0; k < 2; ++k) {
                const int row = unk[DOF * p0 + k];
                for (s = 0; s < 2; ++s) {
                    K[(long)row * nu + L + 2 * k + s] += f->A[3 * q + s] * scale; /* scaled multipliers */
                    K[(long)(L + 2 * k + s) * nu + row] += f->A[3 * q + s] * scale / f->V;
                }
                K[(long)row * nu + L + 4 + k] += scale;
                K[(long)(L + 4 + k) * nu + row] += scale;
            }
        }
        for (kl = 0; kl < 4; ++kl) /* dF = e_k (x) e_l: (dF G)_cj = delta_ck G_lj */
            for (s = 0; s < 2; ++s)
                rhs[(long)(L + 2 * (kl / 2) + s) * 4 + kl] = G[SBC_IJ(kl % 2, s)] * scale / f->V;
    }
    /* unknowns that nothing depends on (a rattler, the rotation of a disc whose contacts all slide or have no
       tangential spring) are dropped with their own equation */
    for (u = nk = 0; u < nu; ++u) {
        int used = 0;
        for (v = 0; v < nu && !used; ++v)
            used = K[(long)v * nu + u] != 0.0;
        keep[u] = used ? nk++ : -1;
        if (!used)
            ++*mechanisms;
    }
    {
        double *Kk = malloc(sizeof *Kk * (size_t)nk * (size_t)(nk > 0 ? nk : 1));
        double *Rk = malloc(sizeof *Rk * (size_t)(nk > 0 ? nk : 1) * 4);
        if (!Kk || !Rk) {
            free(Kk);
            free(Rk);
            st = sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory (condensed tangent)");
            goto done;
        }
        for (u = 0; u < nu; ++u) {
            if (keep[u] < 0)
                continue;
            for (v = 0; v < nu; ++v)
                if (keep[v] >= 0)
                    Kk[(long)keep[u] * nk + keep[v]] = K[(long)u * nu + v];
            memcpy(&Rk[(long)keep[u] * 4], &rhs[(long)u * 4], sizeof(double) * 4);
        }
        *mechanisms += sbc_dense_solve(nk, Kk, 4, Rk, 1e-12 * scale);
        for (u = 0; u < nu; ++u)
            memcpy(&rhs[(long)u * 4], keep[u] >= 0 ? &Rk[(long)keep[u] * 4] : (const double[4]){0, 0, 0, 0},
                   sizeof(double) * 4);
        free(Kk);
        free(Rk);
    }
    /* dP of each dF = e_k (x) e_l: the frame's forces a_q = -(loads on q), eq. 23 */
    for (kl = 0; kl < 4; ++kl) {
        double dP[9];
        for (s = 0; s < ndof; ++s)
            dz[s] = z0[(long)kl * ndof + s] + (unk[s] >= 0 ? rhs[(long)unk[s] * 4 + kl] : 0.0);
        memset(load, 0, sizeof(double) * (size_t)ndof);
        for (k = 0; k < net->npair; ++k)
            if (!open[k])
                for (s = 0; s < 6; ++s)
                    for (v = 0; v < 6; ++v)
                        load[slot_dof(net, k, s)] += blocks[k][s][v] * dz[slot_dof(net, k, v)];
        for (q = 0; q < f->n; ++q)
            for (s = 0; s < 2; ++s)
                a[3 * q + s] = -load[DOF * f->particle[q] + s];
        sbc_homogenize_P(f, a, dP);
        for (s = 0; s < 4; ++s)
            C[9 * SBC_IJ(s / 2, s % 2) + SBC_IJ(kl / 2, kl % 2)] = dP[SBC_IJ(s / 2, s % 2)];
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
    free(K);
    free(rhs);
    free(keep);
    return st;
}
