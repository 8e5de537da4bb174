/* Frame of boundary particles: partition, anticlockwise order, periodic
 * partners, area vectors (eq. 2) and reference volume. */
#include "sbc/frame.h"

#include "sbc/saved.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct edge_item {
    int particle;
    double key; /* coordinate along the edge, ordered anticlockwise */
} edge_item;

static int compare_items(const void *a, const void *b)
{
    double ka = ((const edge_item *)a)->key, kb = ((const edge_item *)b)->key;
    return (ka > kb) - (ka < kb);
}

static sbc_status frame_alloc(sbc_frame *f, int q, sbc_error *err)
{
    memset(f, 0, sizeof *f);
    f->n = q;
    f->particle = malloc(sizeof(int) * (size_t)q);
    f->side = malloc(sizeof(int) * (size_t)q);
    f->partner = malloc(sizeof(int) * (size_t)q);
    f->X = malloc(sizeof(double) * 2 * (size_t)q);
    f->R = malloc(sizeof(double) * (size_t)q);
    f->A = malloc(sizeof(double) * 2 * (size_t)q);
    if (!f->particle || !f->side || !f->partner || !f->X || !f->R || !f->A) {
        sbc_frame_free(f);
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory for %d particles", q);
    }
    return SBC_OK;
}

void sbc_frame_free(sbc_frame *f)
{
    if (!f)
        return;
    free(f->particle);
    free(f->side);
    free(f->partner);
    free(f->X);
    free(f->R);
    free(f->A);
    memset(f, 0, sizeof *f);
}

/* Area vectors of eq. 2 for an anticlockwise closed frame:
 *   A_q = R_q/(R_q+R_{q-1}) (X_q - X_{q-1}) x e3 + R_q/(R_q+R_{q+1}) (X_{q+1} - X_q) x e3,
 * with (a1, a2, 0) x e3 = (a2, -a1, 0). V is the area of the quadrilateral of
 * the four corner centres (shoelace formula). */
void sbc_frame_update_geometry(sbc_frame *f)
{
    int q, n = f->n;
    for (q = 0; q < n; ++q) {
        int qm = (q + n - 1) % n, qp = (q + 1) % n;
        double wm = f->R[q] / (f->R[q] + f->R[qm]);
        double wp = f->R[q] / (f->R[q] + f->R[qp]);
        double dm0 = f->X[2 * q] - f->X[2 * qm], dm1 = f->X[2 * q + 1] - f->X[2 * qm + 1];
        double dp0 = f->X[2 * qp] - f->X[2 * q], dp1 = f->X[2 * qp + 1] - f->X[2 * q + 1];
        f->A[2 * q] = wm * dm1 + wp * dp1;
        f->A[2 * q + 1] = -(wm * dm0 + wp * dp0);
    }
    f->V = 0.0;
    for (q = 0; q < 4; ++q) {
        const double *a = &f->X[2 * f->corner[q]], *b = &f->X[2 * f->corner[(q + 1) % 4]];
        f->V += 0.5 * (a[0] * b[1] - b[0] * a[1]);
    }
}

/* Pairs the edge positions [first, first+count) with [other, other+count),
 * which run in the opposite direction (bottom x ascending against top x
 * descending; right y ascending against left y descending). */
static void pair_edges(sbc_frame *f, int first, int other, int count)
{
    int k;
    for (k = 0; k < count; ++k) {
        int a = first + k, b = other + count - 1 - k;
        f->partner[a] = b;
        f->partner[b] = a;
    }
}

/* Assembles the frame from the corner particles and the four edge lists. */
static sbc_status assemble(sbc_frame *f, const int corner_particle[4], edge_item *edge[4],
                           const int count[4], const double *x, const double *r, sbc_error *err)
{
    int s, k, q = 4 + count[0] + count[1] + count[2] + count[3], pos = 0;
    sbc_status st = frame_alloc(f, q, err);
    if (st != SBC_OK)
        return st;
    for (s = 0; s < 4; ++s) {
        qsort(edge[s], (size_t)count[s], sizeof(edge_item), compare_items);
        f->corner[s] = pos;
        f->particle[pos] = corner_particle[s];
        f->side[pos++] = SBC_SIDE_CORNER;
        for (k = 0; k < count[s]; ++k) {
            f->particle[pos] = edge[s][k].particle;
            f->side[pos++] = SBC_SIDE_BOTTOM + s;
        }
    }
    for (k = 0; k < q; ++k) {
        int p = f->particle[k];
        f->X[2 * k] = x[2 * p];
        f->X[2 * k + 1] = x[2 * p + 1];
        f->R[k] = r[p];
        f->partner[k] = -1;
    }
    if (count[0] == count[2])
        pair_edges(f, f->corner[0] + 1, f->corner[2] + 1, count[0]);
    if (count[1] == count[3])
        pair_edges(f, f->corner[1] + 1, f->corner[3] + 1, count[1]);
    sbc_frame_update_geometry(f);
    if (!(f->V > 0.0)) {
        sbc_frame_free(f);
        return sbc_fail(err, SBC_ERR_FRAME, "frame: the corner centres enclose no area");
    }
    return SBC_OK;
}

/* Key along the anticlockwise direction of each edge: bottom +x, right +y,
 * top -x, left -y. */
static double edge_key(int s, const double *xp)
{
    switch (s) {
    case 0: return xp[0];
    case 1: return xp[1];
    case 2: return -xp[0];
    default: return -xp[1];
    }
}

/* box == NULL: edges are the bands of width `band` inside the bounding box of
 * the centres; otherwise the discs crossing the edges of the square box. */
static sbc_status build(sbc_frame *f, int count_in, const int *list, int n, const double *x,
                        const double *r, double band, const double *box, sbc_error *err)
{
    static const char *corner_name[4] = {"bottom-left", "bottom-right", "top-right", "top-left"};
    static const char *edge_name[4] = {"bottom", "right", "top", "left"};
    double lo[2] = {DBL_MAX, DBL_MAX}, hi[2] = {-DBL_MAX, -DBL_MAX}, rmin = DBL_MAX;
    int corner_particle[4] = {-1, -1, -1, -1}, count[4] = {0, 0, 0, 0};
    edge_item *edge[4] = {NULL, NULL, NULL, NULL};
    int k, s, m = list ? count_in : n;
    sbc_status st = SBC_OK;

    memset(f, 0, sizeof *f);
    if (m < 4)
        return sbc_fail(err, SBC_ERR_FRAME, "frame: %d particles cannot form a frame (need at least 4)", m);
    for (k = 0; k < m; ++k) {
        int p = list ? list[k] : k;
        if (p < 0 || p >= n)
            return sbc_fail(err, SBC_ERR_FRAME, "frame: particle index %d out of range [0, %d)", p, n);
        for (s = 0; s < 2; ++s) {
            if (x[2 * p + s] < lo[s]) lo[s] = x[2 * p + s];
            if (x[2 * p + s] > hi[s]) hi[s] = x[2 * p + s];
        }
        if (r[p] < rmin) rmin = r[p];
    }
    if (band <= 0.0)
        band = 0.5 * rmin;
    if (box) {
        lo[0] = box[0];
        hi[0] = box[1];
        lo[1] = box[2];
        hi[1] = box[3];
        if (!(hi[0] - lo[0] > 0.0 && hi[1] - lo[1] > 0.0))
            return sbc_fail(err, SBC_ERR_FRAME, "frame: box %g %g %g %g is empty", box[0], box[1], box[2], box[3]);
    } else if (!(hi[0] - lo[0] > 2.0 * band && hi[1] - lo[1] > 2.0 * band))
        return sbc_fail(err, SBC_ERR_FRAME, "frame: the packing is too thin (%g x %g m) to have four edges",
                        hi[0] - lo[0], hi[1] - lo[1]);
    for (s = 0; s < 4; ++s) {
        edge[s] = malloc(sizeof(edge_item) * (size_t)m);
        if (!edge[s]) {
            st = sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
            goto done;
        }
    }
    for (k = 0; k < m; ++k) {
        int p = list ? list[k] : k;
        const double *xp = &x[2 * p];
        int on[4], c = -1;
        if (box) {
            on[0] = fabs(xp[1] - lo[1]) < r[p];
            on[1] = fabs(hi[0] - xp[0]) < r[p];
            on[2] = fabs(hi[1] - xp[1]) < r[p];
            on[3] = fabs(xp[0] - lo[0]) < r[p];
            if (on[0] + on[1] + on[2] + on[3] > 2 || (on[0] && on[2]) || (on[1] && on[3])) {
                st = sbc_fail(err, SBC_ERR_FRAME, "frame: particle %d (radius %g m) crosses opposite edges of the "
                              "box", p, r[p]);
                goto done;
            }
        } else {
            on[0] = xp[1] - lo[1] <= band;
            on[1] = hi[0] - xp[0] <= band;
            on[2] = hi[1] - xp[1] <= band;
            on[3] = xp[0] - lo[0] <= band;
        }
        if (list && !(on[0] || on[1] || on[2] || on[3])) {
            /* explicit frame: assign to the nearest edge */
            double d[4] = {xp[1] - lo[1], hi[0] - xp[0], hi[1] - xp[1], xp[0] - lo[0]};
            int best = 0;
            for (s = 1; s < 4; ++s)
                if (d[s] < d[best]) best = s;
            on[best] = 1;
        }
        if (on[3] && on[0]) c = 0;
        else if (on[0] && on[1]) c = 1;
        else if (on[1] && on[2]) c = 2;
        else if (on[2] && on[3]) c = 3;
        if (c >= 0) {
            if (corner_particle[c] >= 0) {
                st = sbc_fail(err, SBC_ERR_FRAME,
                              "frame: two particles (%d and %d) sit at the %s corner", corner_particle[c], p,
                              corner_name[c]);
                goto done;
            }
            corner_particle[c] = p;
            continue;
        }
        for (s = 0; s < 4; ++s) {
            if (on[s]) {
                edge[s][count[s]].particle = p;
                edge[s][count[s]++].key = edge_key(s, xp);
                break;
            }
        }
    }
    for (s = 0; s < 4; ++s) {
        if (corner_particle[s] < 0) {
            st = sbc_fail(err, SBC_ERR_FRAME, "frame: no particle at the %s corner of the packing", corner_name[s]);
            goto done;
        }
    }
    for (s = 0; s < 4; ++s) {
        if (count[s] == 0 && !list) {
            st = sbc_fail(err, SBC_ERR_FRAME, "frame: the %s edge has no particles between its corners",
                          edge_name[s]);
            goto done;
        }
    }
    st = assemble(f, corner_particle, edge, count, x, r, err);
done:
    for (s = 0; s < 4; ++s)
        free(edge[s]);
    return st;
}

sbc_status sbc_frame_detect(sbc_frame *f, int n, const double *x, const double *r, double band,
                            sbc_error *err)
{
    return build(f, n, NULL, n, x, r, band, NULL, err);
}

/* A geometrically periodic packing pairs every edge particle with a copy at
 * exactly +-L; frees f and fails when one has none. */
static sbc_status check_periodic(sbc_frame *f, const double box[4], sbc_error *err)
{
    int k;
    for (k = 0; k < f->n; ++k) {
        /* bottom -> top differ by +L in y (c = 1), left -> right by +L in x (c = 0) */
        int q = f->partner[k], c = f->side[k] == SBC_SIDE_BOTTOM ? 1 : 0;
        double L = box[2 * c + 1] - box[2 * c];
        if (f->side[k] != SBC_SIDE_BOTTOM && f->side[k] != SBC_SIDE_LEFT)
            continue;
        if (q < 0 || fabs(f->X[2 * q + c] - f->X[2 * k + c] - L) > 1e-9 * L ||
            fabs(f->X[2 * q + 1 - c] - f->X[2 * k + 1 - c]) > 1e-9 * L || f->R[q] != f->R[k]) {
            int p = f->particle[k];
            sbc_frame_free(f);
            return sbc_fail(err, SBC_ERR_FRAME,
                            "frame: particle %d on the %s edge has no periodic copy on the opposite edge (the box "
                            "must be the square of a geometrically periodic packing)",
                            p, c ? "bottom" : "left");
        }
    }
    return SBC_OK;
}

sbc_status sbc_frame_detect_box(sbc_frame *f, int n, const double *x, const double *r, const double box[4],
                                sbc_error *err)
{
    sbc_status st = build(f, n, NULL, n, x, r, 0.0, box, err);
    return st != SBC_OK ? st : check_periodic(f, box, err);
}

/* The largest rectangle whose four corners are listed particles of equal
 * radius at exactly (x, y), (x + Lx, y), (x, y + Ly), (x + Lx, y + Ly) (to
 * 1e-12 of the listed extent): the corner copies of a geometrically periodic
 * packing (Sect. 4.2). Returns 0 when there is none. O(count^2). */
static int periodic_corners(int count, const int *list, const double *x, const double *r, double box[4])
{
    double lo = HUGE_VAL, hi = -HUGE_VAL, eps, best = 0.0;
    int a, b, c, d;
    for (a = 0; a < count; ++a) {
        const double *p = &x[2 * list[a]];
        lo = fmin(lo, fmin(p[0], p[1]));
        hi = fmax(hi, fmax(p[0], p[1]));
    }
    eps = 1e-12 * (hi - lo);
    for (a = 0; a < count; ++a) {
        const double *p = &x[2 * list[a]];
        for (b = 0; b < count; ++b) { /* same y, to the right */
            const double *q = &x[2 * list[b]];
            if (fabs(q[1] - p[1]) > eps || !(q[0] > p[0] + eps) || r[list[b]] != r[list[a]])
                continue;
            for (c = 0; c < count; ++c) { /* same x, above */
                const double *u = &x[2 * list[c]];
                if (fabs(u[0] - p[0]) > eps || !(u[1] > p[1] + eps) || r[list[c]] != r[list[a]])
                    continue;
                if ((q[0] - p[0]) * (u[1] - p[1]) <= best)
                    continue;
                for (d = 0; d < count; ++d) { /* the fourth corner */
                    const double *w = &x[2 * list[d]];
                    if (fabs(w[0] - q[0]) <= eps && fabs(w[1] - u[1]) <= eps && r[list[d]] == r[list[a]]) {
                        best = (q[0] - p[0]) * (u[1] - p[1]);
                        box[0] = p[0], box[1] = q[0], box[2] = p[1], box[3] = u[1];
                        break;
                    }
                }
            }
        }
    }
    return best > 0.0;
}

sbc_status sbc_frame_detect_packing(sbc_frame *f, const sbc_packing *p, sbc_error *err)
{
    if (p->has_box)
        return sbc_frame_detect_box(f, p->n, p->x, p->r, p->box, err);
    return sbc_frame_detect(f, p->n, p->x, p->r, 0.0, err);
}

sbc_status sbc_frame_from_list(sbc_frame *f, int count, const int *list, const double *x,
                               const double *r, sbc_error *err)
{
    double box[4];
    int n = 0, k;
    for (k = 0; k < count; ++k)
        if (list[k] + 1 > n) n = list[k] + 1;
    /* the frame group of a geometrically periodic packing: the discs crossing
       the square spanned by its corner copies, every one with its copy at +-L */
    if (periodic_corners(count, list, x, r, box)) {
        sbc_error quiet;
        if (build(f, count, list, n, x, r, 0.0, box, &quiet) == SBC_OK) {
            if (f->n == count && check_periodic(f, box, &quiet) == SBC_OK)
                return SBC_OK;
            if (f->n > 0)
                sbc_frame_free(f);
        }
    }
    return build(f, count, list, n, x, r, 0.0, NULL, err);
}

/* Layout: Q, then per frame position: particle, side, partner, X (2), R, A (2);
 * then the four corners and V. */
size_t sbc_frame_state_size(const sbc_frame *f) { return 1 + 8 * (size_t)f->n + 5; }

void sbc_frame_save(const sbc_frame *f, double *out)
{
    int q, c;
    *out++ = f->n;
    for (q = 0; q < f->n; ++q) {
        *out++ = f->particle[q];
        *out++ = f->side[q];
        *out++ = f->partner[q];
        *out++ = f->X[2 * q];
        *out++ = f->X[2 * q + 1];
        *out++ = f->R[q];
        *out++ = f->A[2 * q];
        *out++ = f->A[2 * q + 1];
    }
    for (c = 0; c < 4; ++c)
        *out++ = f->corner[c];
    *out = f->V;
}

sbc_status sbc_frame_load(sbc_frame *f, const double *in, size_t n, sbc_error *err)
{
    sbc_saved rd;
    int q, c, nq;
    sbc_status st;
    sbc_saved_start(&rd, in, n, "frame restart data", err);
    nq = (int)sbc_saved_int(&rd, "frame particles Q", 4, 100000000L);
    if (rd.st != SBC_OK)
        return rd.st;
    if (n != 1 + 8 * (size_t)nq + 5)
        return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: %zu values do not describe a frame of %d particles "
                        "(expected %zu)", n, nq, 1 + 8 * (size_t)nq + 5);
    if ((st = frame_alloc(f, nq, err)) != SBC_OK)
        return st;
    for (q = 0; q < nq; ++q) {
        f->particle[q] = (int)sbc_saved_int(&rd, "particle", 0, INT_MAX - 1);
        f->side[q] = (int)sbc_saved_int(&rd, "side", SBC_SIDE_CORNER, SBC_SIDE_LEFT);
        f->partner[q] = (int)sbc_saved_int(&rd, "partner", -1, nq - 1);
        f->X[2 * q] = sbc_saved_real(&rd, "X1");
        f->X[2 * q + 1] = sbc_saved_real(&rd, "X2");
        f->R[q] = sbc_saved_positive(&rd, "R");
        f->A[2 * q] = sbc_saved_real(&rd, "A1");
        f->A[2 * q + 1] = sbc_saved_real(&rd, "A2");
    }
    for (c = 0; c < 4; ++c)
        f->corner[c] = (int)sbc_saved_int(&rd, "corner", 0, nq - 1);
    f->V = sbc_saved_positive(&rd, "V");
    if (rd.st != SBC_OK)
        return rd.st;
    /* the invariants the servo indexes by: corners have no partner, a
       partner's partner is the particle itself, the corner list names corners
       (an edge particle may lack a partner: (D) needs none) */
    for (q = 0; q < nq; ++q) {
        const int p = f->partner[q];
        if ((f->side[q] == SBC_SIDE_CORNER && p >= 0) || (p >= 0 && f->partner[p] != q))
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: frame position %d (side %d) has partner %d, "
                            "which is not its periodic partner", q, f->side[q], p);
    }
    for (c = 0; c < 4; ++c)
        if (f->side[f->corner[c]] != SBC_SIDE_CORNER)
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: corner %d is frame position %d, not a corner", c,
                            f->corner[c]);
    return SBC_OK;
}

void sbc_frame_centres(const sbc_frame *frame, const double *x, double *fx)
{
    int q;
    for (q = 0; q < frame->n; ++q) {
        fx[2 * q] = x[2 * frame->particle[q]];
        fx[2 * q + 1] = x[2 * frame->particle[q] + 1];
    }
}
