/* The 2D frame's geometry: detection of the frame of a disc packing (its
 * four corners, edges in anticlockwise order, periodic partners), and the
 * 2D row of geometry.h: the area vectors of eq. 2, the reference area, the
 * point-in-polygon test. Host centres are [2n] here. */
#include "frame_private.h"
#include "geometry.h"

#include <float.h>
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

/* Area vectors of eq. 2 for an anticlockwise closed frame:
 *   A_q = R_q/(R_q+R_{q-1}) (X_q - X_{q-1}) x e3 + R_q/(R_q+R_{q+1}) (X_{q+1} - X_q) x e3,
 * with (a1, a2, 0) x e3 = (a2, -a1, 0). V is the area of the quadrilateral of
 * the four corner centres (shoelace formula). */
static void area_vectors(sbc_frame *f)
{
    int q, n = f->n;
    for (q = 0; q < n; ++q) {
        int qm = (q + n - 1) % n, qp = (q + 1) % n;
        double wm = f->R[q] / (f->R[q] + f->R[qm]);
        double wp = f->R[q] / (f->R[q] + f->R[qp]);
        const double *X = &f->X[3 * q], *Xm = &f->X[3 * qm], *Xp = &f->X[3 * qp];
        double dm0 = X[0] - Xm[0], dm1 = X[1] - Xm[1];
        double dp0 = Xp[0] - X[0], dp1 = Xp[1] - X[1];
        f->A[3 * q] = wm * dm1 + wp * dp1;
        f->A[3 * q + 1] = -(wm * dm0 + wp * dp0);
    }
    f->V = 0.0;
    for (q = 0; q < 4; ++q) {
        const double *a = &f->X[3 * f->corner[q]], *b = &f->X[3 * f->corner[(q + 1) % 4]];
        f->V += 0.5 * (a[0] * b[1] - b[0] * a[1]);
    }
}

/* a point inside the polygon of the centres fx: crossings of a ray along +x */
static int inside_polygon(const sbc_frame *f, const double *fx, const double *p)
{
    int q, in = 0;
    for (q = 0; q < f->n; ++q) {
        const double *a = &fx[3 * q], *b = &fx[3 * ((q + 1) % f->n)];
        if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            in = !in;
    }
    return in;
}

/* (P)'s families in 2D: a bottom or right particle and its partner on the
 * opposite edge; the four corners BL, BR, TR, TL under BL */
static int family_2d(const sbc_frame *f, int q, int members[8])
{
    int c;
    if (f->side[q] == SBC_SIDE_CORNER) {
        if (q != f->corner[SBC_CORNER_BL])
            return 0;
        for (c = 0; c < 4; ++c)
            members[c] = f->corner[c];
        return 4;
    }
    if (f->partner[q] < 0)
        return -1;
    if (f->side[q] != SBC_SIDE_BOTTOM && f->side[q] != SBC_SIDE_RIGHT)
        return 0;
    members[0] = q;
    members[1] = f->partner[q];
    return 2;
}

/* the edges of a 2D frame position as face bits: bottom ylo, right xhi, top
   yhi, left xlo; a corner on its two */
static int faces_2d(const sbc_frame *f, int q)
{
    static const int of_side[5] = {0, SBC_FACE_YLO, SBC_FACE_XHI, SBC_FACE_YHI, SBC_FACE_XLO};
    static const int of_corner[4] = {SBC_FACE_XLO | SBC_FACE_YLO, SBC_FACE_XHI | SBC_FACE_YLO,
                                     SBC_FACE_XHI | SBC_FACE_YHI, SBC_FACE_XLO | SBC_FACE_YHI};
    int c;
    if (f->side[q] != SBC_SIDE_CORNER)
        return of_side[f->side[q]];
    for (c = 0; c < 4; ++c)
        if (f->corner[c] == q)
            return of_corner[c];
    return 0;
}

const sbc_frame_geometry sbc_frame_geometry_2d = {2, "polygon", area_vectors, inside_polygon, family_2d, faces_2d};

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
    sbc_status st = sbc_frame_alloc(f, 2, q, err);
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
        f->X[3 * k] = x[2 * p];
        f->X[3 * k + 1] = x[2 * p + 1];
        f->R[k] = r[p];
        f->partner[k] = -1;
    }
    if (count[0] == count[2])
        pair_edges(f, f->corner[0] + 1, f->corner[2] + 1, count[0]);
    if (count[1] == count[3])
        pair_edges(f, f->corner[1] + 1, f->corner[3] + 1, count[1]);
    area_vectors(f);
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
        if (q < 0 || fabs(f->X[3 * q + c] - f->X[3 * k + c] - L) > 1e-9 * L ||
            fabs(f->X[3 * q + 1 - c] - f->X[3 * k + 1 - c]) > 1e-9 * L || f->R[q] != f->R[k]) {
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

