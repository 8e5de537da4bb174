/* The frame of a geometrically periodic sphere packing (the 3D generator's,
 * Sect. 4.2 lifted): a cuboid whose eight corners hold one sphere and its
 * images; the frame is every sphere crossing a face of it, each with its
 * images at exactly +-L across the faces it crosses. The surface through the
 * frame's centres: each face triangulated in its own plane, where the
 * spheres on its four edges are moved onto the edge lines (their centres
 * wander up to a radius off them, and face spheres can lie beyond them in
 * projection, so the centres' own projections bound no polygon); the
 * Delaunay triangulation of that square (triangulate.h) is then lifted to
 * the centres. A high face takes its low face's triangles through the images,
 * so (P)'s paired faces share one triangulation, and each edge's stretches
 * between consecutive edge spheres bound one triangle of either face beside
 * it: the surface is closed, and sum_q X_q (x) A_q = V I to round-off. */
#include "frame_private.h"
#include "triangulate.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a particle keyed by its centre across axis a: the two other coordinates,
   the radius, then its coordinate along a */
typedef struct keyed {
    double key[4];
    int index;
} keyed;

static int compare_keyed(const void *pa, const void *pb)
{
    const keyed *a = pa, *b = pb;
    int k;
    for (k = 0; k < 4; ++k)
        if (a->key[k] != b->key[k])
            return (a->key[k] > b->key[k]) - (a->key[k] < b->key[k]);
    return a->index - b->index;
}

/* next [3n]: along each axis a, the particle of the same radius and the same
   two other coordinates with the next larger coordinate a (-1 if none) */
static int next_along_axes(int n, const double *x, const double *r, int *next)
{
    keyed *s = malloc(sizeof *s * (size_t)n);
    int a, k;
    if (!s)
        return -1;
    for (a = 0; a < 3; ++a) {
        for (k = 0; k < n; ++k) {
            s[k].key[0] = x[3 * k + (a + 1) % 3];
            s[k].key[1] = x[3 * k + (a + 2) % 3];
            s[k].key[2] = r[k];
            s[k].key[3] = x[3 * k + a];
            s[k].index = k;
            next[3 * k + a] = -1;
        }
        qsort(s, (size_t)n, sizeof *s, compare_keyed);
        for (k = 1; k < n; ++k)
            if (s[k].key[0] == s[k - 1].key[0] && s[k].key[1] == s[k - 1].key[1] && s[k].key[2] == s[k - 1].key[2] &&
                s[k].key[3] > s[k - 1].key[3])
                next[3 * s[k - 1].index + a] = s[k].index;
    }
    free(s);
    return 0;
}

/* The cuboid of the largest volume whose corners hold a sphere and its seven
   images and which every sphere meets: octet [8] by corner index (bits 1,
   2, 4: high x, y, z); 0 if none (a lattice's cells fail the last) */
static int periodic_octet(int n, const double *x, const double *r, const int *next, int octet[8])
{
    double best = 0.0, reach_lo[3], reach_hi[3]; /* the least x + r, the largest x - r */
    int p, c;
    for (c = 0; c < 3; ++c)
        reach_lo[c] = HUGE_VAL, reach_hi[c] = -HUGE_VAL;
    for (p = 0; p < n; ++p)
        for (c = 0; c < 3; ++c) {
            reach_lo[c] = fmin(reach_lo[c], x[3 * p + c] + r[p]);
            reach_hi[c] = fmax(reach_hi[c], x[3 * p + c] - r[p]);
        }
    for (p = 0; p < n; ++p) {
        int o[8], ok = 1;
        double L[3], volume;
        o[0] = p;
        o[1] = next[3 * p], o[2] = next[3 * p + 1], o[4] = next[3 * p + 2];
        if (o[1] < 0 || o[2] < 0 || o[4] < 0)
            continue;
        o[3] = next[3 * o[1] + 1], o[5] = next[3 * o[1] + 2], o[6] = next[3 * o[2] + 2];
        o[7] = o[3] >= 0 ? next[3 * o[3] + 2] : -1;
        for (c = 3; c < 8; ++c)
            ok &= c == 4 || o[c] >= 0;
        if (!ok || next[3 * o[2]] != o[3] || next[3 * o[4]] != o[5] || next[3 * o[4] + 1] != o[6] ||
            next[3 * o[6]] != o[7])
            continue;
        for (c = 0; c < 3; ++c)
            L[c] = x[3 * o[1 << c] + c] - x[3 * p + c];
        for (c = 1; c < 8; ++c) { /* every corner at the same lengths */
            int a;
            for (a = 0; a < 3; ++a)
                ok &= x[3 * o[c] + a] == x[3 * p + a] + (c >> a & 1 ? L[a] : 0.0) ||
                      fabs(x[3 * o[c] + a] - x[3 * p + a] - (c >> a & 1 ? L[a] : 0.0)) <= 1e-12 * L[a];
        }
        for (c = 0; c < 3; ++c) /* every sphere meets the cuboid, as the reconstruction keeps them */
            ok &= reach_lo[c] >= x[3 * p + c] && reach_hi[c] <= x[3 * p + c] + L[c];
        volume = L[0] * L[1] * L[2];
        if (ok && volume > best) {
            best = volume;
            memcpy(octet, o, sizeof o);
        }
    }
    return best > 0.0;
}

/* the faces of the cuboid lo, hi crossed by sphere (x, r): SBC_FACE_ bits */
static int crossed(const double *x, double r, const double lo[3], const double hi[3])
{
    int a, side = 0;
    for (a = 0; a < 3; ++a) {
        side |= (x[a] - r < lo[a] && x[a] + r > lo[a]) << (2 * a);
        side |= (x[a] - r < hi[a] && x[a] + r > hi[a]) << (2 * a + 1);
    }
    return side;
}

/* image [3Q]: the frame positions on the low and the high face of each axis,
   matched by their two other coordinates and radius (a copy keeps them to
   the bit); partner for face particles */
static sbc_status match_images(sbc_frame *f, const double L[3], sbc_error *err)
{
    keyed *lo = malloc(sizeof *lo * (size_t)f->n), *hi = malloc(sizeof *hi * (size_t)f->n);
    int a, q, k, nlo, nhi;
    sbc_status st = SBC_OK;
    if (!lo || !hi) {
        free(lo);
        free(hi);
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    }
    for (q = 0; q < 3 * f->n; ++q)
        f->image[q] = -1;
    for (a = 0; a < 3 && st == SBC_OK; ++a) {
        for (q = 0, nlo = nhi = 0; q < f->n; ++q) {
            keyed *e = f->side[q] >> (2 * a) & 1 ? &lo[nlo++] : f->side[q] >> (2 * a) & 2 ? &hi[nhi++] : NULL;
            if (!e)
                continue;
            e->key[0] = f->X[3 * q + (a + 1) % 3];
            e->key[1] = f->X[3 * q + (a + 2) % 3];
            e->key[2] = f->R[q];
            e->key[3] = 0.0;
            e->index = q;
        }
        qsort(lo, (size_t)nlo, sizeof *lo, compare_keyed);
        qsort(hi, (size_t)nhi, sizeof *hi, compare_keyed);
        for (k = 0; k < (nlo > nhi ? nlo : nhi); ++k) {
            const keyed *l = k < nlo ? &lo[k] : NULL, *h = k < nhi ? &hi[k] : NULL;
            if (!l || !h || memcmp(l->key, h->key, sizeof l->key) != 0 ||
                fabs(f->X[3 * h->index + a] - f->X[3 * l->index + a] - L[a]) > 1e-9 * L[a]) {
                const keyed *first = !h || (l && compare_keyed(l, h) < 0) ? l : h;
                st = sbc_fail(err, SBC_ERR_FRAME, "frame: particle %d on face %s has no periodic image on face %s at "
                              "exactly %c%g m (the packing must be geometrically periodic)", f->particle[first->index],
                              sbc_frame_face_name[2 * a + (first == h)], sbc_frame_face_name[2 * a + (first == l)],
                              first == l ? '+' : '-', L[a]);
                break;
            }
            f->image[3 * l->index + a] = h->index;
            f->image[3 * h->index + a] = l->index;
            if (sbc_frame_face_count(f->side[l->index]) == 1) {
                f->partner[l->index] = h->index;
                f->partner[h->index] = l->index;
            }
        }
    }
    free(lo);
    free(hi);
    return st;
}

/* The triangles of the low face of axis a into cells [4 .] from *ncell on,
   outward (as degenerate quadrilaterals (i, j, k, i), which give each corner
   a third of the triangle's vector area), and the high face's through the
   images. */
static sbc_status triangulate_axis(sbc_frame *f, int a, const double lo[3], const double L[3], int *cells, int *ncell,
                                   sbc_error *err)
{
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    int q, m = 0, t, ntri, *member = malloc(sizeof(int) * (size_t)f->n), *tri;
    double *uv = malloc(sizeof(double) * 2 * (size_t)f->n);
    tri = malloc(sizeof(int) * 6 * (size_t)f->n);
    if (!member || !uv || !tri) {
        free(member);
        free(uv);
        free(tri);
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    }
    for (q = 0; q < f->n; ++q) {
        const int side = f->side[q];
        if (!(side >> (2 * a) & 1))
            continue;
        /* on an edge: onto its line; inside the face: the centre's own place */
        uv[2 * m] = side >> (2 * u) & 1 ? 0.0 : side >> (2 * u) & 2 ? 1.0 : (f->X[3 * q + u] - lo[u]) / L[u];
        uv[2 * m + 1] = side >> (2 * v) & 1 ? 0.0 : side >> (2 * v) & 2 ? 1.0 : (f->X[3 * q + v] - lo[v]) / L[v];
        member[m++] = q;
    }
    ntri = sbc_triangulate_square(m, uv, tri);
    for (t = 0; t < ntri; ++t) {
        const int i = member[tri[3 * t]], j = member[tri[3 * t + 1]], k = member[tri[3 * t + 2]];
        int *lo_cell = &cells[4 * (*ncell)++], *hi_cell = &cells[4 * (*ncell)++];
        lo_cell[0] = lo_cell[3] = i, lo_cell[1] = k, lo_cell[2] = j;
        hi_cell[0] = hi_cell[3] = f->image[3 * i + a], hi_cell[1] = f->image[3 * j + a], hi_cell[2] = f->image[3 * k + a];
    }
    free(member);
    free(uv);
    free(tri);
    if (ntri < 0)
        return sbc_fail(err, SBC_ERR_FRAME, "frame: the %d centres of face %s admit no triangulation of the face (two "
                        "edge spheres at one place along an edge?)", m, sbc_frame_face_name[2 * a]);
    return SBC_OK;
}

sbc_status sbc_frame_detect_periodic_3d(sbc_frame *f, int n, const double *x, const double *r, int *cube,
                                        sbc_error *err)
{
    int *next, octet[8], p, a, m = 0, cap = 0;
    double lo[3], hi[3], L[3];
    sbc_frame_item *it;
    sbc_status st;
    memset(f, 0, sizeof *f);
    *cube = 0;
    if (n < 8 || !(next = malloc(sizeof(int) * 3 * (size_t)n)))
        return n < 8 ? SBC_ERR_FRAME : sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    if (next_along_axes(n, x, r, next) != 0 || !periodic_octet(n, x, r, next, octet)) {
        free(next);
        return SBC_ERR_FRAME;
    }
    free(next);
    *cube = 1;
    for (a = 0; a < 3; ++a) {
        lo[a] = x[3 * octet[0] + a];
        hi[a] = x[3 * octet[7] + a];
        L[a] = hi[a] - lo[a];
    }
    if (!(it = malloc(sizeof *it * (size_t)n)))
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    for (p = 0; p < n; ++p) {
        const int side = crossed(&x[3 * p], r[p], lo, hi);
        if (!side)
            continue;
        for (a = 0; a < 3; ++a)
            if ((side >> (2 * a) & 3) == 3) {
                free(it);
                return sbc_fail(err, SBC_ERR_FRAME, "frame: particle %d (radius %g m) crosses both faces %s and %s of "
                                "the periodic cuboid", p, r[p], sbc_frame_face_name[2 * a], sbc_frame_face_name[2 * a + 1]);
            }
        if (sbc_frame_face_count(side) == 3) {
            const int c = (side & SBC_FACE_XHI ? 1 : 0) | (side & SBC_FACE_YHI ? 2 : 0) | (side & SBC_FACE_ZHI ? 4 : 0);
            if (octet[c] != p) {
                free(it);
                return sbc_fail(err, SBC_ERR_FRAME, "frame: particle %d crosses the three faces at the corner (%s, %s, "
                                "%s) that particle %d holds", p, sbc_frame_face_name[c & 1],
                                sbc_frame_face_name[2 + (c >> 1 & 1)], sbc_frame_face_name[4 + (c >> 2 & 1)], octet[c]);
            }
        }
        it[m].particle = p;
        it[m].side = side;
        it[m].rank = 3 - sbc_frame_face_count(side);
        it[m++].x = &x[3 * p];
    }
    st = sbc_frame_from_items_3d(f, it, m, r, err);
    free(it);
    if (st != SBC_OK)
        return st;
    for (p = 0; p < f->n; ++p)
        cap += 2 * sbc_frame_face_count(f->side[p]); /* a face's triangles: fewer than twice its particles */
    if (!(f->image = malloc(sizeof(int) * 3 * (size_t)f->n)) || !(f->cell = malloc(sizeof(int) * 4 * (size_t)cap)))
        st = sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory for the surface of %d particles", f->n);
    if (st == SBC_OK)
        st = match_images(f, L, err);
    for (a = 0; a < 3 && st == SBC_OK; ++a)
        st = triangulate_axis(f, a, lo, L, f->cell, &f->ncell, err);
    if (st == SBC_OK) {
        sbc_frame_update_geometry(f);
        if (!(fabs(f->V - L[0] * L[1] * L[2]) <= 1e-9 * L[0] * L[1] * L[2]))
            st = sbc_fail(err, SBC_ERR_FRAME, "frame: the surface through the frame's centres encloses %g m^3, not the "
                          "periodic cuboid's %g m^3", f->V, L[0] * L[1] * L[2]);
    }
    if (st != SBC_OK)
        sbc_frame_free(f);
    return st;
}
