/* interior newton: each rotation unknown balanced with the rest held (statics_work.h) */
#include "statics_work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/dense.h"
#include "contact_blocks.h"

#define TURN_ITERATIONS 60

typedef struct turn_work {
    int *start, *adj;       /* [n + 1], [2 cand]: each particle's candidates */
    int *stamp;             /* [cand] the last unknown that took the candidate */
    int *first, *next;      /* [nu], [n]: each rotation unknown's particles, a chain from its first */
    int *members, nm;       /* [n]: the particles of the current rotation unknown */
    double *base;           /* [3 n]: their rotations when its solve began, rad */
    unsigned char *member;  /* [n] */
    int *list, nl;          /* [cand]: the current unknown's candidates */
} turn_work;

/* the rotation unknown's potential (J), moment M [rd] (N m) and, with H, dM/dtheta [rd x rd] at theta */
static double turn_at(statics_work *w, const sbc_network *net, turn_work *t, const double *x, const double *theta,
                      double *M, double *H)
{
    const int nd = w->nd, dim = w->dim, rd = w->rd;
    double psi = 0.0;
    int m, c, e, f, r, s;
    for (m = 0; m < t->nm; ++m)
        memset(&w->res[nd * t->members[m] + dim], 0, sizeof(double) * (size_t)rd);
    for (c = 0; c < t->nl; ++c) {
        (void)sbc_statics_contact(w, t->list[c], x, theta);
        psi += w->psi[t->list[c]];
    }
    for (r = 0; r < rd; ++r) {
        M[r] = 0.0;
        for (m = 0; m < t->nm; ++m)
            M[r] += w->res[nd * t->members[m] + dim + r];
    }
    if (H) {
        memset(H, 0, sizeof(double) * (size_t)(rd * rd));
        for (c = 0; c < t->nl; ++c) {
            double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST];
            const int k = t->list[c], ends[2] = {w->cand.i[k], w->cand.j[k]};
            if (!sbc_contact_block(net, k, B))
                continue;
            for (e = 0; e < 2; ++e)
                for (f = 0; f < 2; ++f)
                    if (t->member[ends[e]] && t->member[ends[f]])
                        for (r = 0; r < rd; ++r)
                            for (s = 0; s < rd; ++s)
                                H[rd * r + s] += B[e * nd + dim + r][f * nd + dim + s];
        }
    }
    return psi;
}

/* the members' rotations turned by keep + d [rd] from where their solve began */
static void turn_set(const statics_work *w, const turn_work *t, double *theta, const double *keep, const double *d)
{
    int m, r;
    for (m = 0; m < t->nm; ++m)
        for (r = 0; r < w->rd; ++r)
            theta[w->rd * t->members[m] + r] = t->base[w->rd * m + r] + keep[r] + d[r];
}

/* Maximizes the rotation unknown's concave potential (its moment the gradient) by Levenberg-damped Newton, the
   rest held: a contact that slides has no rotational stiffness, and a particle whose contacts all slide is left
   on a plateau that the global Newton's linearization does not see across. Returns 1 when it moved. */
static int turn_solve(statics_work *w, const sbc_network *net, turn_work *t, const double *x, double *theta,
                      double target)
{
    const int rd = w->rd;
    const double R = w->p->r[t->members[0]], stiff = w->p->law.ks * R * R * (t->nl > 0 ? t->nl : 1);
    double M[3], H[9], keep[3] = {0, 0, 0}, psi, lambda = 1e-6;
    int it, r, s, m, moved = 0;
    for (m = 0; m < t->nm; ++m)
        for (r = 0; r < rd; ++r)
            t->base[rd * m + r] = theta[rd * t->members[m] + r];
    psi = turn_at(w, net, t, x, theta, M, H);
    for (it = 0; it < TURN_ITERATIONS; ++it) {
        double A[9], d[3], size = 0.0, gain = 0.0, psi_t, Mt[3], Ht[9], worst = 0.0;
        for (r = 0; r < rd; ++r)
            worst = fmax(worst, fabs(M[r]) / R);
        if (worst <= target)
            break;
        for (r = 0; r < rd; ++r) {
            for (s = 0; s < rd; ++s)
                A[rd * r + s] = H[rd * r + s] - (r == s ? lambda * stiff : 0.0);
            d[r] = -M[r];
        }
        sbc_dense_solve(rd, A, 1, d, 0.0);
        for (r = 0; r < rd; ++r) {
            size += d[r] * d[r];
            gain += M[r] * d[r];
        }
        size = sqrt(size) * R;
        if (size > STEP_CAP * w->rmin)
            for (r = 0; r < rd; ++r)
                d[r] *= STEP_CAP * w->rmin / size;
        turn_set(w, t, theta, keep, d);
        psi_t = turn_at(w, net, t, x, theta, Mt, Ht);
        if (psi_t >= psi + 1e-4 * gain * fmin(1.0, STEP_CAP * w->rmin / size) && gain > 0.0) {
            for (r = 0; r < rd; ++r)
                keep[r] += d[r];
            psi = psi_t;
            memcpy(M, Mt, sizeof M);
            memcpy(H, Ht, sizeof H);
            lambda = fmax(lambda * 0.25, 1e-12);
            moved = 1;
        } else {
            const double zero[3] = {0, 0, 0};
            turn_set(w, t, theta, keep, zero);
            lambda *= 8.0;
            if (lambda > 1e8)
                break;
        }
    }
    {
        const double zero[3] = {0, 0, 0};
        turn_set(w, t, theta, keep, zero);
    }
    return moved;
}

int sbc_statics_turn_sweep(statics_work *w, const sbc_network *net, const double *x, double *theta, double target)
{
    const int n = w->p->n, nd = w->nd, dim = w->dim, cand = w->cand.count;
    turn_work t;
    const size_t nu = (size_t)(w->nu > 0 ? w->nu : 1);
    int i, k, moved = 0, *fill = calloc((size_t)n + 1, sizeof(int));
    memset(&t, 0, sizeof t);
    t.first = malloc(sizeof(int) * nu);
    t.next = malloc(sizeof(int) * (size_t)n);
    t.base = malloc(sizeof(double) * 3 * (size_t)n);
    t.start = calloc((size_t)n + 1, sizeof(int));
    t.adj = malloc(sizeof(int) * 2 * (size_t)(cand + 1));
    t.stamp = malloc(sizeof(int) * (size_t)(cand + 1));
    t.members = malloc(sizeof(int) * (size_t)n);
    t.member = calloc((size_t)n, 1);
    t.list = malloc(sizeof(int) * (size_t)(cand + 1));
    if (!fill || !t.first || !t.next || !t.base || !t.start || !t.adj || !t.stamp || !t.members || !t.member ||
        !t.list) {
        moved = -1;
        goto done;
    }
    for (k = 0; k < cand; ++k) {
        ++t.start[w->cand.i[k] + 1];
        ++t.start[w->cand.j[k] + 1];
        t.stamp[k] = -1;
    }
    for (i = 0; i < n; ++i)
        t.start[i + 1] += t.start[i];
    for (k = 0; k < cand; ++k) {
        t.adj[t.start[w->cand.i[k]] + fill[w->cand.i[k]]++] = k;
        t.adj[t.start[w->cand.j[k]] + fill[w->cand.j[k]]++] = k;
    }
    for (k = 0; k < (int)nu; ++k)
        t.first[k] = -1;
    for (i = n - 1; i >= 0; --i) { /* each unknown's particles (i, and its periodic images), in index order */
        const int u = w->unk[nd * i + dim];
        if (u >= 0) {
            t.next[i] = t.first[u];
            t.first[u] = i;
        }
    }
    for (i = 0; i < n; ++i) {
        const int u = w->unk[nd * i + dim];
        int j, m, c;
        if (u < 0 || t.first[u] != i)
            continue;
        t.nm = t.nl = 0;
        for (j = i; j >= 0; j = t.next[j]) {
            t.members[t.nm++] = j;
            t.member[j] = 1;
        }
        for (m = 0; m < t.nm; ++m)
            for (c = t.start[t.members[m]]; c < t.start[t.members[m] + 1]; ++c)
                if (t.stamp[t.adj[c]] != u) {
                    t.stamp[t.adj[c]] = u;
                    t.list[t.nl++] = t.adj[c];
                }
        moved += turn_solve(w, net, &t, x, theta, target);
        for (m = 0; m < t.nm; ++m)
            t.member[t.members[m]] = 0;
    }
done:
    free(fill);
    free(t.first);
    free(t.next);
    free(t.base);
    free(t.start);
    free(t.adj);
    free(t.stamp);
    free(t.members);
    free(t.member);
    free(t.list);
    return moved;
}
