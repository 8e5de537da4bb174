/* interior newton: the static equilibrium of a disc or sphere aggregate (statics.h). */
#include "statics.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact_blocks.h"
#include "statics_work.h"
#include "sbc/tensor.h"
#include "sbc/embedded/engine.h"

/* backtracking halvings of the line search before the iteration is called stalled */
#define LINE_HALVINGS 30
/* the pseudo-time term's first weight (times kn) and the weight below which it is dropped (pure Newton) */
#define SHIFT_FIRST 1.0
#define SHIFT_LAST 1e-8
#define SHIFT_MOST 1e6
/* the most parts a frame's move is cut into when its solve stalls */
#define SUBSTEPS_MOST 8
/* the weight after a cut step: at least this */
#define SHIFT_CUT 1e-3
/* an iteration whose squared residual is not half the one this many iterations back has stalled: the
   dynamic relaxation finishes the increment (statics.h) */
#define STALL_WINDOW 20
/* how far a step under the pseudo-time term may raise the merit and still be taken */
#define FLOW_RISE 4.0
/* the round-off floor of the relative residual, in ulps of the largest coordinate times kn (attainable) */
#define ROUNDOFF_ULPS 64.0


/* net loads on every dof at (x, theta), the springs of the end state by
   backward Euler (statics.h); returns the merit: the sum over free dofs of
   the squared net forces and net moments over R (N^2) */
static double evaluate(statics_work *w, const double *x, const double *theta)
{
    const sbc_statics_problem *p = w->p;
    double sum_f = 0.0, merit = 0.0;
    int k, q;
    memset(w->res, 0, sizeof(double) * (size_t)w->nd * (size_t)p->n);
    w->contacts = 0;
    for (k = 0; k < w->cand.count; ++k) {
        const double f = sbc_statics_contact(w, k, x, theta);
        if (f >= 0.0) {
            sum_f += f;
            ++w->contacts;
        }
    }
    w->mean_force = w->contacts ? sum_f / w->contacts : 0.0;
    memset(w->R, 0, sizeof(double) * (size_t)(w->nu > 0 ? w->nu : 1));
    for (q = 0; q < w->nd * p->n; ++q)
        if (w->unk[q] >= 0)
            w->R[w->unk[q]] += w->res[q];
    if (p->bc == SBC_BC_T) { /* a_q = P A_q + m on the frame; eq. 15 and the mean translation (condensed.c) */
        const sbc_frame *f = p->frame;
        const int L = w->L, dim = w->dim, nc = dim * dim;
        for (q = 0; q < f->n; ++q) {
            const int i = f->particle[q];
            int c, s2;
            for (c = 0; c < dim; ++c) {
                const double u = x[dim * i + c] - w->xe[dim * i + c];
                double tr = w->lambda[nc + c];
                for (s2 = 0; s2 < dim; ++s2) {
                    tr += f->A[3 * q + s2] * w->lambda[dim * c + s2];
                    w->R[L + dim * c + s2] += f->A[3 * q + s2] * w->border / f->V * u;
                }
                w->R[w->unk[w->nd * i + c]] += w->border * tr;
                w->R[L + nc + c] += w->border * u;
            }
        }
    }
    for (k = 0; k < w->nu; ++k)
        merit += w->R[k] * w->row_scale[k] * w->R[k] * w->row_scale[k];
    return merit;
}

/* the residual a solve can reach: the problem's tol, or, where the contact
   forces are so small that round-off in the centres (the ulp of xmax, times
   kn, summed over a particle's contacts) is larger, ROUNDOFF_ULPS ulps of it
   over the mean contact force (docs/servo_bc.md, "Interior") */
static double attainable(const statics_work *w)
{
    const double floor = ROUNDOFF_ULPS * DBL_EPSILON * w->p->law.kn * w->xmax;
    return w->mean_force > 0.0 ? fmax(w->p->tol, floor / w->mean_force) : w->p->tol;
}

/* the largest residual of an unknown (net force, net moment over R, (T)'s
   constraints in N) over the mean contact force */
static double relative_residual(const statics_work *w)
{
    double worst = 0.0;
    int u;
    for (u = 0; u < w->nu; ++u)
        worst = fmax(worst, fabs(w->R[u] * w->row_scale[u]));
    if (w->mean_force > 0.0)
        return worst / w->mean_force;
    return worst > 0.0 ? HUGE_VAL : 0.0;
}

/* with bonds, at an evaluated iterate x: the intact bond furthest at or over eq. 8's criterion (the engine's
   test, sbc_cohesive_criterion) broken; 1 when one broke */
static int break_worst(statics_work *w, const double *x)
{
    double worst = 1.0;
    int k, at = -1;
    for (k = 0; w->bondc && k < w->cand.count; ++k)
        if (w->bondc[k]) {
            const int a = w->cand.i[k], b = w->cand.j[k];
            const double lx = x[2 * b] - x[2 * a], ly = x[2 * b + 1] - x[2 * a + 1];
            const double fn = w->p->law.kn * (w->p->r[a] + w->p->r[b] - sqrt(lx * lx + ly * ly));
            sbc_bond bond;
            double c;
            bond.fs = w->fs[k];
            bond.m = w->mc[k];
            bond.broken = 0;
            c = sbc_cohesive_criterion(w->p->bonds, fn, &bond);
            if (c >= worst) {
                worst = c;
                at = k;
            }
        }
    if (at < 0)
        return 0;
    w->intact[sbc_pair_index(w->p->npair0, w->p->i0, w->p->j0, w->cand.i[at], w->cand.j[at])] = 0;
    return 1;
}

/* the candidate pairs rebuilt when a disc has moved half the reach since the last build */
static sbc_status keep_candidates(statics_work *w, const double *x, sbc_error *err)
{
    const double lim = 0.25 * w->cand.skin * w->cand.skin;
    const int dim = w->dim;
    int i, c, stale = !w->built;
    for (i = 0; i < w->p->n && !stale; ++i) {
        double d2 = 0.0;
        for (c = 0; c < dim; ++c)
            d2 += (x[dim * i + c] - w->cand.x_build[dim * i + c]) * (x[dim * i + c] - w->cand.x_build[dim * i + c]);
        stale = d2 > lim;
    }
    if (!stale)
        return SBC_OK;
    if (sbc_pairs_build(&w->cand, x, w->p->r, w->rmax, err) != SBC_OK)
        return err->status;
    w->built = 1;
    if (w->cand.capacity > 0) {
        double *fs = realloc(w->fs, sizeof(double) * (size_t)w->cand.capacity);
        double *fsv = fs ? realloc(w->fsv, sizeof(double) * 3 * (size_t)w->cand.capacity) : NULL;
        double *fs0c = fsv ? realloc(w->fs0c, sizeof(double) * 3 * (size_t)w->cand.capacity) : NULL;
        double *psi = fs0c ? realloc(w->psi, sizeof(double) * (size_t)w->cand.capacity) : NULL;
        if (psi)
            w->psi = psi;
        if (psi && w->intact) {
            int *bondc = realloc(w->bondc, sizeof(int) * (size_t)w->cand.capacity);
            double *mc = bondc ? realloc(w->mc, sizeof(double) * (size_t)w->cand.capacity) : NULL;
            if (bondc)
                w->bondc = bondc;
            if (mc)
                w->mc = mc;
            if (!mc)
                psi = NULL;
        }
        if (fs)
            w->fs = fs;
        if (fsv)
            w->fsv = fsv;
        if (fs0c)
            w->fs0c = fs0c;
        if (!fs || !fsv || !fs0c || !psi)
            return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d pairs", w->cand.capacity);
    }
    return SBC_OK;
}

static void work_free(statics_work *w)
{
    sbc_pairs_free(&w->cand);
    free(w->fs);
    free(w->fsv);
    free(w->fs0c);
    free(w->psi);
    free(w->bondc);
    free(w->mc);
    free(w->intact);
    free(w->res);
    free(w->unk);
    free(w->R);
    free(w->row_scale);
    free(w->dy);
    free(w->lambda);
    free(w->xe);
    free(w->xt);
    free(w->tt);
}

static sbc_status work_init(statics_work *w, const sbc_statics_problem *p, sbc_error *err)
{
    const size_t n = (size_t)p->n;
    int i, k;
    memset(w, 0, sizeof *w);
    w->p = p;
    w->dim = p->dim == 3 ? 3 : 2;
    w->rd = w->dim == 3 ? 3 : 1;
    w->nd = w->dim + w->rd;
    w->rmin = DBL_MAX;
    for (i = 0; i < p->n; ++i) {
        w->rmax = fmax(w->rmax, p->r[i]);
        w->rmin = fmin(w->rmin, p->r[i]);
    }
    for (k = 0; k < w->dim * p->n; ++k)
        w->xmax = fmax(w->xmax, fabs(p->x0[k]));
    w->res = malloc(sizeof(double) * (size_t)w->nd * n);
    w->unk = malloc(sizeof(int) * (size_t)w->nd * n);
    w->xt = malloc(sizeof(double) * (size_t)w->dim * n);
    w->tt = malloc(sizeof(double) * (size_t)w->rd * n);
    w->lambda = calloc(12, sizeof(double));
    w->xe = malloc(sizeof(double) * (size_t)w->dim * n);
    if (!w->res || !w->unk || !w->xt || !w->tt || !w->lambda || !w->xe)
        return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d discs", p->n);
    {
        sbc_network net;
        memset(&net, 0, sizeof net);
        net.dim = w->dim;
        net.n = p->n;
        net.frame_rotation_zero = p->bc == SBC_BC_T && p->rotation_zero;
        net.mode = p->mode;
        net.free_rotation = p->free_rotation;
        if ((w->L = sbc_condensed_unknowns(&net, p->frame, p->bc, w->unk, err)) < 0)
            return err->status;
    }
    w->nu = w->L + (p->bc == SBC_BC_T ? w->dim * w->dim + w->dim : 0);
    w->border = p->law.kn;
    w->R = malloc(sizeof(double) * (size_t)(w->nu > 0 ? w->nu : 1));
    w->row_scale = malloc(sizeof(double) * (size_t)(w->nu > 0 ? w->nu : 1));
    w->dy = malloc(sizeof(double) * (size_t)(w->nu > 0 ? w->nu : 1));
    if (!w->R || !w->row_scale || !w->dy)
        return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d unknowns", w->nu);
    for (k = 0; k < w->nu; ++k)
        w->row_scale[k] = 1.0;
    for (k = w->nd * p->n - 1; k >= 0; --k) /* a rotation's row in N: over the (first member's) radius */
        if (k % w->nd >= w->dim && w->unk[k] >= 0)
            w->row_scale[w->unk[k]] = 1.0 / p->r[k / w->nd];
    for (k = 0; k < p->npair0; ++k) {
        if (p->i0[k] < 0 || p->i0[k] >= p->j0[k] || p->j0[k] >= p->n || (k > 0 && (p->i0[k] < p->i0[k - 1] ||
            (p->i0[k] == p->i0[k - 1] && p->j0[k] <= p->j0[k - 1]))))
            return sbc_fail(err, SBC_ERR_INPUT, "interior newton: committed pair %d (%d, %d) is out of order", k,
                            p->i0[k], p->j0[k]);
    }
    if (p->bonds && w->dim == 2) { /* the committed bonds, each intact until this solve breaks it */
        if (!(w->intact = malloc((size_t)(p->npair0 > 0 ? p->npair0 : 1))))
            return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d pairs", p->npair0);
        for (k = 0; k < p->npair0; ++k)
            w->intact[k] = p->bond0 && p->bond0[k];
    }
    /* reach: the pairs within a smallest radius of touching; with bonds, within 1.5 times the longest an intact
       bond stretches (fn_u / kn, eq. 8's first term alone), as the engine's list keeps them */
    return sbc_pairs_init(&w->cand, w->dim, p->n, w->intact ? fmax(w->rmin, 1.5 * p->bonds->fn_u / p->law.kn) : w->rmin,
                          0, 0, err);
}

/* the end state's touching pairs as pair records (engine.h) */
static sbc_status take_records(statics_work *w, const double *x, const double *theta, sbc_statics_result *res,
                               sbc_error *err)
{
    int k, c = 0;
    evaluate(w, x, theta);
    res->contacts = w->contacts;
    if (!(res->records = malloc(sizeof(double) * SBC_PAIR_RECORD * (size_t)(w->contacts > 0 ? w->contacts : 1))))
        return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d contacts", w->contacts);
    for (k = 0; k < w->cand.count; ++k) {
        const int a = w->cand.i[k], b = w->cand.j[k], dim = w->dim;
        const double rs = w->p->r[a] + w->p->r[b];
        double *o, d2 = 0.0;
        int q;
        for (q = 0; q < dim; ++q)
            d2 += (x[dim * b + q] - x[dim * a + q]) * (x[dim * b + q] - x[dim * a + q]);
        if (dim == 3 ? !(rs - sqrt(d2) > 0.0) : d2 >= rs * rs && !(w->bondc && w->bondc[k])) /* open, as evaluate saw it */
            continue;
        o = &res->records[SBC_PAIR_RECORD * c++];
        o[0] = a;
        o[1] = b;
        if (dim == 3) /* the spring as a vector (sbc_spheres_place) */
            memcpy(&o[2], &w->fsv[3 * k], sizeof(double) * 3);
        else {
            o[2] = w->bondc ? w->bondc[k] : 0;
            o[3] = w->fs[k];
            o[4] = w->bondc ? w->mc[k] : 0.0;
        }
    }
    return SBC_OK;
}

/* the iterate moved by alpha dy from (x, theta, lambda) into (xt, tt) and, with keep, lambda */
static void move(statics_work *w, const double *x, const double *theta, double alpha, double *xt, double *tt)
{
    const int n = w->p->n, dim = w->dim, rd = w->rd, nd = w->nd;
    int q;
    for (q = 0; q < nd * n; ++q) {
        const double d = w->unk[q] >= 0 ? alpha * w->dy[w->unk[q]] : 0.0;
        const int i = q / nd, c = q % nd;
        if (c >= dim)
            tt[rd * i + c - dim] = theta[rd * i + c - dim] + d;
        else
            xt[dim * i + c] = x[dim * i + c] + d;
    }
}

/* The Newton iteration's start: the interior carried along by the affine
 * map that fits the frame's move best (least squares about the frame's
 * centroid: M = (sum dn do^T)(sum do do^T)^-1, do, dn the frame's centres
 * about their centroid before and after), as `remap x` carries it during a
 * dynamic move: a lattice's increment is then solved by one Newton step, an
 * irregular packing's starts near its answer. x0 [dim n] before, x [dim n]
 * after the frame's move (its interior still at x0), overwritten. */
static void affine_start(const sbc_frame *f, int dim, int n, const double *x0, double *x)
{
    double co[3] = {0, 0, 0}, cn[3] = {0, 0, 0}, A[9] = {0}, B[9] = {0}, M[9];
    int q, i, k, l;
    unsigned char *in_frame = calloc((size_t)n, 1);
    if (!in_frame || f->n < dim + 1)
        goto done;
    for (q = 0; q < f->n; ++q) {
        const int p = f->particle[q];
        in_frame[p] = 1;
        for (k = 0; k < dim; ++k) {
            co[k] += x0[dim * p + k] / f->n;
            cn[k] += x[dim * p + k] / f->n;
        }
    }
    for (q = 0; q < f->n; ++q) {
        const int p = f->particle[q];
        for (k = 0; k < dim; ++k)
            for (l = 0; l < dim; ++l) {
                A[SBC_IJ(k, l)] += (x[dim * p + k] - cn[k]) * (x0[dim * p + l] - co[l]);
                B[SBC_IJ(k, l)] += (x0[dim * p + k] - co[k]) * (x0[dim * p + l] - co[l]);
            }
    }
    if (!sbc_tensor_right_divide(dim, A, B, M)) /* M = A B^-1 */
        goto done;
    for (i = 0; i < n; ++i)
        if (!in_frame[i])
            for (k = 0; k < dim; ++k) {
                double y = cn[k];
                for (l = 0; l < dim; ++l)
                    y += M[SBC_IJ(k, l)] * (x0[dim * i + l] - co[l]);
                x[dim * i + k] = y;
            }
done:
    free(in_frame);
}

/* the frame particles (but the corners, with skip_corners) at c + M (x0_q - c0): their committed places carried
   by the map M about the centroids c0 (committed) and c (now), m */
static void carry_frame(const sbc_frame *f, int dim, const double *x0, const double c0[3], const double c[3],
                        const double M[9], int skip_corners, double *x)
{
    int q, k, l, at;
    for (q = 0; q < f->n; ++q) {
        const int i = f->particle[q];
        for (at = 0; skip_corners && at < (dim == 3 ? 8 : 4) && f->corner[at] != q; ++at)
            ;
        if (skip_corners && at < (dim == 3 ? 8 : 4))
            continue; /* a corner: at its command */
        for (k = 0; k < dim; ++k) {
            double y = c[k];
            for (l = 0; l < dim; ++l)
                y += M[SBC_IJ(k, l)] * (x0[dim * i + l] - c0[l]);
            x[dim * i + k] = y;
        }
    }
}

/* (T): the frame starts as its committed shape carried by the map that gives it the commands' eq. 15 and mean
 * place: x_q = c + M (x0_q - c0), M = E(x) E(x0)^-1, E(y) = sum_q (y_q - c_y) (x) A_q, c the centroid of the
 * commanded frame, c0 of the committed one (the constraints of eq. 15 and of the mean translation then hold at
 * the start, whatever sum_q A_q); the interior follows by affine_start. The commands put each frame particle
 * where F X_q says: a jolt of the fluctuations the committed (T) state had found. */
static void frame_start(const sbc_frame *f, int dim, int n, const double *x0, double *x)
{
    double c0[3] = {0, 0, 0}, c[3] = {0, 0, 0}, E0[9] = {0}, E[9] = {0}, M[9];
    int q, k, l;
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < dim; ++k) {
            c0[k] += x0[dim * f->particle[q] + k] / f->n;
            c[k] += x[dim * f->particle[q] + k] / f->n;
        }
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < dim; ++k)
            for (l = 0; l < dim; ++l) {
                E0[SBC_IJ(k, l)] += (x0[dim * f->particle[q] + k] - c0[k]) * f->A[3 * q + l];
                E[SBC_IJ(k, l)] += (x[dim * f->particle[q] + k] - c[k]) * f->A[3 * q + l];
            }
    if (!sbc_tensor_right_divide(dim, E, E0, M))
        return;
    carry_frame(f, dim, x0, c0, c, M, 0, x);
    affine_start(f, dim, n, x0, x);
}

/* (P): the frame's periodic families start at their committed places carried by the map the corners take, and
 * every frame particle at its committed rotation (unknowns too, shared by a family, and by the corners),
 * x_q = c + M (x0_q - c0), M = E E0^-1, E = sum_c (x_c - c) (x) (x0_c - c0), E0 = sum_c (x0_c - c0) (x) (x0_c - c0)
 * over the corners (prescribed at F X, about their centroids c, c0), and not at the commands' F X_q, which drop
 * the fluctuations and turn the rotations to zero that the committed state had found (a balanced point then
 * started far out of balance at its own committed F: docs/servo_bc.md, "Interior"); the interior follows by
 * affine_start. A family's members keep their periodic offsets:
 * M (x0_a - x0_b) = M Fc (X_a - X_b) = F (X_a - X_b). */
static void periodic_start(const sbc_frame *f, int dim, int n, const double *x0, const double *theta0, double *x,
                           double *theta)
{
    const int rd = dim == 3 ? 3 : 1;
    const int corners = dim == 3 ? 8 : 4;
    double c0[3] = {0, 0, 0}, c[3] = {0, 0, 0}, E0[9] = {0}, E[9] = {0}, M[9];
    int q, k, l, at;
    for (at = 0; at < corners; ++at)
        for (k = 0; k < dim; ++k) {
            c0[k] += x0[dim * f->particle[f->corner[at]] + k] / corners;
            c[k] += x[dim * f->particle[f->corner[at]] + k] / corners;
        }
    for (at = 0; at < corners; ++at) {
        const int i = f->particle[f->corner[at]];
        for (k = 0; k < dim; ++k)
            for (l = 0; l < dim; ++l) {
                E0[SBC_IJ(k, l)] += (x0[dim * i + k] - c0[k]) * (x0[dim * i + l] - c0[l]);
                E[SBC_IJ(k, l)] += (x[dim * i + k] - c[k]) * (x0[dim * i + l] - c0[l]);
            }
    }
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < rd; ++k)
            theta[rd * f->particle[q] + k] = theta0[rd * f->particle[q] + k];
    if (!sbc_tensor_right_divide(dim, E, E0, M))
        return;
    carry_frame(f, dim, x0, c0, c, M, 1, x); /* the corners stay at F X */
    affine_start(f, dim, n, x0, x);
}

/* the contact network of the iterate x for a Newton step under the pseudo-time term shift (of kn) */
static void network_at(sbc_network *net, const statics_work *w, const sbc_statics_problem *p, double *x,
                       const double *theta, double shift)
{
    net->shift = shift * p->law.kn;
    net->x = x;
    net->theta = w->dim == 3 ? theta : NULL;
    net->npair = w->cand.count;
    net->i = w->cand.i;
    net->j = w->cand.j;
    net->fs = p->fs0 ? w->fsv : NULL;
    net->fs0 = p->fs0 ? w->fs0c : NULL;
    net->bond = w->bondc;
    net->kr = p->bonds ? p->bonds->kr : 0.0;
}

/* one solve from p's committed state (sbc_statics_solve, without the substeps) */
static sbc_status solve_once(const sbc_statics_problem *p, int turning, double *x, double *theta,
                             sbc_statics_result *res, sbc_error *err)
{
    statics_work w;
    sbc_network net;
    double merit, shift = SHIFT_FIRST, ring[STALL_WINDOW];
    int it, q, since = 0; /* the iterations since the start or the last bond broken */
    for (q = 0; q < STALL_WINDOW; ++q)
        ring[q] = HUGE_VAL; /* an iteration without a step writes no merit: no stall measured against it */
    sbc_status st;
    memset(res, 0, sizeof *res);
    if ((st = work_init(&w, p, err)) != SBC_OK || (st = keep_candidates(&w, x, err)) != SBC_OK) {
        work_free(&w);
        return st;
    }
    memcpy(w.xe, x, sizeof(double) * (size_t)w.dim * (size_t)p->n);
    if (p->bc == SBC_BC_T)
        frame_start(p->frame, w.dim, p->n, p->x0, x);
    else if (p->bc == SBC_BC_P)
        periodic_start(p->frame, w.dim, p->n, p->x0, p->theta0, x, theta);
    memset(&net, 0, sizeof net);
    net.dim = w.dim;
    net.n = p->n;
    net.r = p->r;
    net.law = p->law;
    net.x0 = p->x0;
    net.theta0 = w.dim == 3 ? p->theta0 : NULL;
    net.border = w.border;
    net.frame_rotation_zero = p->bc == SBC_BC_T && p->rotation_zero;
    net.mode = p->mode;
    net.free_rotation = p->free_rotation;
    merit = evaluate(&w, x, theta);
    res->residual = relative_residual(&w);
    for (it = 0;; ++it, ++since) {
        double alpha = 1.0, step = 0.0, best_alpha = 0.0, lambda_keep[12], merit_before;
        int h, k;
        if (res->residual <= attainable(&w)) { /* converged: with bonds over eq. 8, the worst broken, and on */
            if (!w.intact || !break_worst(&w, x))
                break;
            res->broken++;
            merit = evaluate(&w, x, theta);
            res->residual = relative_residual(&w);
            shift = fmax(shift, SHIFT_CUT);
            since = 0;
            for (q = 0; q < STALL_WINDOW; ++q)
                ring[q] = HUGE_VAL;
            if (res->residual <= attainable(&w))
                continue;
        }
        if (since >= p->max_iterations)
            break;
        merit_before = merit;
        if (turning && it > 0 && p->fs0) { /* each rotation balanced with the rest held (statics_work.h) */
            network_at(&net, &w, p, x, theta, shift);
            if (sbc_statics_turn_sweep(&w, &net, x, theta, TURN_SHARE * res->residual * w.mean_force) < 0) {
                st = sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for the rotations' solves");
                break;
            }
            merit = evaluate(&w, x, theta);
            res->residual = relative_residual(&w);
            if (res->residual <= attainable(&w))
                break;
        }
        network_at(&net, &w, p, x, theta, shift);
        if ((st = sbc_condensed_newton_step(&net, p->frame, p->bc, w.R, w.dy, &res->mechanisms, err)) != SBC_OK)
            break;
        for (q = 0; q < w.nd * p->n; q += w.nd) { /* the largest move of a particle's centre or surface */
            double d2 = 0.0, t2 = 0.0;
            for (k = 0; k < w.nd; ++k)
                if (w.unk[q + k] >= 0)
                    *(k < w.dim ? &d2 : &t2) += w.dy[w.unk[q + k]] * w.dy[w.unk[q + k]];
            step = fmax(step, fmax(sqrt(d2), sqrt(t2) * p->r[q / w.nd]));
        }
        if (step > STEP_CAP * w.rmin)
            alpha = STEP_CAP * w.rmin / step;
        memcpy(lambda_keep, w.lambda, sizeof lambda_keep);
        /* the step at full length (or the cap); where it does not lower the merit: under a pseudo-time term
           of at least SHIFT_FIRST, taken all the same if the merit rises at most FLOW_RISE-fold (implicit
           damped motion through an unstable stretch, as a relaxation passes it); else backtracking */
        for (h = 0; h <= LINE_HALVINGS; ++h, alpha *= 0.5) {
            double trial;
            move(&w, x, theta, alpha, w.xt, w.tt);
            for (k = w.L; k < w.nu; ++k)
                w.lambda[k - w.L] = lambda_keep[k - w.L] + alpha * w.dy[k];
            if ((st = keep_candidates(&w, w.xt, err)) != SBC_OK)
                break;
            trial = evaluate(&w, w.xt, w.tt);
            if (trial <= (1.0 - 1e-4 * alpha) * merit || (h == 0 && shift >= SHIFT_FIRST && trial <= FLOW_RISE * merit)) {
                best_alpha = alpha;
                break;
            }
        }
        if (st != SBC_OK)
            break;
        res->iterations = it + 1;
        if (!(best_alpha > 0.0)) { /* no step: a heavier pseudo-time term, and the iteration again */
            memcpy(w.lambda, lambda_keep, sizeof lambda_keep);
            merit = evaluate(&w, x, theta);
            shift = fmax(4.0 * shift, SHIFT_FIRST);
            if (shift > SHIFT_MOST) {
                snprintf(res->why, sizeof res->why, "the line search found no descent at Newton iteration %d "
                         "(relative residual %.3e)", it + 1, res->residual);
                break;
            }
            continue;
        }
        move(&w, x, theta, best_alpha, x, theta);
        for (k = w.L; k < w.nu; ++k)
            w.lambda[k - w.L] = lambda_keep[k - w.L] + best_alpha * w.dy[k];
        if ((st = keep_candidates(&w, x, err)) != SBC_OK)
            break;
        merit = evaluate(&w, x, theta);
        res->residual = relative_residual(&w);
        ring[since % STALL_WINDOW] = merit;
        if (since >= STALL_WINDOW && merit > 0.5 * ring[(since + 1) % STALL_WINDOW]) {
            res->iterations = it + 1;
            snprintf(res->why, sizeof res->why, "Newton stalled: the squared residual did not halve over "
                     "%d iterations (relative residual %.3e after %d)", STALL_WINDOW, res->residual, it + 1);
            break;
        }
        /* switched evolution relaxation: the pseudo-time grows as the residual falls after a full step that
           lowered it, and shrinks after a cut step */
        if (best_alpha < 1.0 && step * best_alpha < STEP_CAP * w.rmin * (1.0 - 1e-12))
            shift = fmax(4.0 * shift, SHIFT_CUT);
        else if (merit < merit_before)
            shift *= fmin(0.5, sqrt(merit / merit_before));
        if (shift < SHIFT_LAST)
            shift = 0.0;
        else if (shift > SHIFT_MOST)
            shift = SHIFT_MOST;
        if (!isfinite(merit)) {
            st = sbc_fail(err, SBC_ERR_NUMERIC, "interior newton: the residual is not finite at iteration %d", it + 1);
            break;
        }
    }
    if (st == SBC_OK && it == 0 && res->residual <= attainable(&w)) { /* the start was the answer: the held dofs counted */
        network_at(&net, &w, p, x, theta, shift);
        if ((res->mechanisms = sbc_condensed_unstiffened(&net, p->frame, p->bc, err)) < 0)
            st = err->status;
    }
    if (st == SBC_OK) {
        res->converged = res->residual <= attainable(&w);
        if (!res->converged && !res->why[0])
            snprintf(res->why, sizeof res->why, "%d Newton iterations left the relative residual at %.3e (tolerance "
                     "%.1e)", res->iterations, res->residual, attainable(&w));
        st = take_records(&w, x, theta, res, err);
    }
    work_free(&w);
    return st;
}

/* the committed state of a substep's problem: its centres, rotations and pairs, owned */
typedef struct substep_state {
    double *x0, *theta0, *fs0, *m0;
    int *i0, *j0, *bond0;
} substep_state;

static void substep_free(substep_state *c)
{
    free(c->x0);
    free(c->theta0);
    free(c->fs0);
    free(c->i0);
    free(c->j0);
    free(c->m0);
    free(c->bond0);
    memset(c, 0, sizeof *c);
}

/* q's committed state becomes the solution x, theta with the pairs of res (records sorted by i, then j) */
static sbc_status substep_commit(sbc_statics_problem *q, substep_state *c, const double *x, const double *theta,
                                 const sbc_statics_result *res, sbc_error *err)
{
    const size_t n = (size_t)q->n, m = (size_t)(res->contacts > 0 ? res->contacts : 1);
    const size_t dim = q->dim == 3 ? 3 : 2, rd = dim == 3 ? 3 : 1;
    int k, s;
    substep_free(c);
    c->x0 = malloc(sizeof(double) * dim * n);
    c->theta0 = malloc(sizeof(double) * rd * n);
    c->fs0 = malloc(sizeof(double) * rd * m);
    c->i0 = malloc(sizeof(int) * m);
    c->j0 = malloc(sizeof(int) * m);
    c->m0 = malloc(sizeof(double) * m);
    c->bond0 = malloc(sizeof(int) * m);
    if (!c->x0 || !c->theta0 || !c->fs0 || !c->i0 || !c->j0 || !c->m0 || !c->bond0)
        return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for a substep of %d discs", q->n);
    memcpy(c->x0, x, sizeof(double) * dim * n);
    memcpy(c->theta0, theta, sizeof(double) * rd * n);
    for (k = 0; k < res->contacts; ++k) { /* the records' springs: 2D along t (slot 3), 3D a vector (2 .. 4) */
        c->i0[k] = (int)res->records[SBC_PAIR_RECORD * k];
        c->j0[k] = (int)res->records[SBC_PAIR_RECORD * k + 1];
        c->bond0[k] = rd == 1 && res->records[SBC_PAIR_RECORD * k + 2] != 0.0; /* 2D: (i, j, bond, fs, m) */
        c->m0[k] = rd == 1 ? res->records[SBC_PAIR_RECORD * k + 4] : 0.0;
        for (s = 0; s < (int)rd; ++s)
            c->fs0[rd * k + s] = res->records[SBC_PAIR_RECORD * k + (rd == 3 ? 2 + s : 3)];
    }
    q->x0 = c->x0;
    q->theta0 = c->theta0;
    q->npair0 = res->contacts;
    q->i0 = c->i0;
    q->j0 = c->j0;
    q->fs0 = q->fs0 ? c->fs0 : NULL;
    q->bond0 = c->bond0;
    q->m0 = c->m0;
    return SBC_OK;
}

/* the frame at the fraction t of its move from p's committed place to (xt, tht), the interior at the
   committed state q (x0, theta0) carried by the frame's affine fit */
static void substep_start(const sbc_statics_problem *p, const sbc_statics_problem *q, const double *xt,
                          const double *tht, double t, double *x, double *theta)
{
    const sbc_frame *f = p->frame;
    const int dim = p->dim == 3 ? 3 : 2, rd = dim == 3 ? 3 : 1;
    int k, c;
    memcpy(x, q->x0, sizeof(double) * (size_t)dim * (size_t)p->n);
    memcpy(theta, q->theta0, sizeof(double) * (size_t)rd * (size_t)p->n);
    for (k = 0; k < f->n; ++k) {
        const int i = f->particle[k];
        for (c = 0; c < dim; ++c)
            x[dim * i + c] = p->x0[dim * i + c] + t * (xt[dim * i + c] - p->x0[dim * i + c]);
        for (c = 0; c < rd; ++c)
            theta[rd * i + c] = p->theta0[rd * i + c] + t * (tht[rd * i + c] - p->theta0[rd * i + c]);
    }
    affine_start(f, dim, p->n, q->x0, x);
}

sbc_status sbc_statics_solve(const sbc_statics_problem *p, double *x, double *theta, sbc_statics_result *res,
                             sbc_error *err)
{
    const size_t dim = p->dim == 3 ? 3 : 2, rd = dim == 3 ? 3 : 1, n = (size_t)p->n, nx = dim * n, nt = rd * n;
    double *xt = malloc(sizeof(double) * nx), *tht = malloc(sizeof(double) * nt);
    double *xf = malloc(sizeof(double) * nx), *thf = malloc(sizeof(double) * nt), *x1 = NULL;
    sbc_statics_result first, part;
    substep_state c;
    sbc_status st;
    long iterations;
    int parts, k, ok = 0;
    memset(res, 0, sizeof *res);
    memset(&first, 0, sizeof first);
    memset(&part, 0, sizeof part);
    memset(&c, 0, sizeof c);
    if (!xt || !tht || !xf || !thf) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d discs", p->n);
        goto done;
    }
    memcpy(xt, x, sizeof(double) * nx); /* the frame's target (its commands) */
    memcpy(tht, theta, sizeof(double) * nt);
    substep_start(p, p, xt, tht, 1.0, x, theta);
    if ((st = solve_once(p, 0, x, theta, &first, err)) != SBC_OK || first.converged) {
        *res = first;
        memset(&first, 0, sizeof first);
        goto done;
    }
    iterations = first.iterations;
    if (!(x1 = malloc(sizeof(double) * (nx + nt)))) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d discs", p->n);
        goto done;
    }
    memcpy(x1, x, sizeof(double) * nx); /* the first attempt's iterate, for the relaxation if no cut helps */
    memcpy(x1 + nx, theta, sizeof(double) * nt);
    /* again with the rotations balanced one by one at each iteration (with friction), then the frame's move in
       2, 4, 8 equal parts, each solved from the last, until every part converges; else the first attempt stands
       (the relaxation finishes it) */
    for (parts = p->fs0 ? 1 : 2; parts <= SUBSTEPS_MOST && !ok && st == SBC_OK; parts *= 2) {
        sbc_statics_problem q = *p;
        int broken = 0;
        for (k = 1, ok = 1; k <= parts && ok && st == SBC_OK; ++k) {
            substep_start(p, &q, xt, tht, (double)k / parts, xf, thf);
            sbc_statics_result_free(&part);
            if ((st = solve_once(&q, p->fs0 != NULL, xf, thf, &part, err)) != SBC_OK)
                break;
            iterations += part.iterations;
            broken += part.broken;
            ok = part.converged;
            if (ok && k < parts)
                st = substep_commit(&q, &c, xf, thf, &part, err);
        }
        substep_free(&c);
        if (ok && st == SBC_OK) {
            memcpy(x, xf, sizeof(double) * nx);
            memcpy(theta, thf, sizeof(double) * nt);
            *res = part;
            memset(&part, 0, sizeof part);
            res->iterations = (int)iterations;
            res->broken = broken;
            res->substeps = parts;
        }
    }
    if (!ok && st == SBC_OK) { /* every cut stalled too: the first attempt, for the relaxation */
        *res = first;
        memset(&first, 0, sizeof first);
        res->iterations = (int)iterations;
        memcpy(x, x1, sizeof(double) * nx);
        memcpy(theta, x1 + nx, sizeof(double) * nt);
    }
done:
    sbc_statics_result_free(&first);
    sbc_statics_result_free(&part);
    substep_free(&c);
    free(xt);
    free(tht);
    free(xf);
    free(thf);
    free(x1);
    return st;
}

void sbc_statics_result_free(sbc_statics_result *res)
{
    free(res->records);
    res->records = NULL;
}
