/* The 3D frame's geometry: the frame of a sphere packing in a cuboid
 * whose faces are a lattice's (sbc_frame_detect_grid_3d), the surface through its centres as the
 * quadrilaterals of the faces' grids, and the 3D row of geometry.h: the
 * area vectors of eq. 2 in 3D, the enclosed volume, the point-in-polyhedron
 * test. Host centres are [3n] here. */
#include "frame_private.h"
#include "geometry.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *const sbc_frame_face_name[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
#define face_name sbc_frame_face_name

/* the vector area of the triangle (a, b, c), (b - a) x (c - a) / 2, into S */
static void triangle_area(const double *a, const double *b, const double *c, double S[3])
{
    const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    int k;
    sbc_cross3(ab, ac, S);
    for (k = 0; k < 3; ++k)
        S[k] *= 0.5;
}

/* eq. 2 in 3D: each surface quadrilateral (a, b, c, d) is cut into two
 * triangles along either diagonal, (a, b, c) + (a, c, d) and (a, b, d) +
 * (b, c, d); each triangle gives a third of its vector area to each of its
 * corners, and the two cuts are averaged. Each cut is a closed surface of
 * flat triangles, so sum_q X_q (x) A_q = V I holds to round-off whether or
 * not the quadrilaterals are planar, with V = sum_q X_q . A_q / 3 the mean of
 * the two cuts' volumes (divergence theorem). On a planar parallelogram every
 * corner gets a quarter of its vector area (the 2D half-segment rule
 * lifted): d^2 to a face particle of a cubic lattice, d^2/2 to an edge
 * particle, d^2/4 to a corner, from each face it lies on. */
static void area_vectors(sbc_frame *f)
{
    int c, q, k;
    memset(f->A, 0, sizeof(double) * 3 * (size_t)f->n);
    for (c = 0; c < f->ncell; ++c) {
        const int *v = &f->cell[4 * c];
        const double *a = &f->X[3 * v[0]], *b = &f->X[3 * v[1]], *cc = &f->X[3 * v[2]], *d = &f->X[3 * v[3]];
        double S1[3], S2[3], T1[3], T2[3];
        triangle_area(a, b, cc, S1);
        triangle_area(a, cc, d, S2);
        triangle_area(a, b, d, T1);
        triangle_area(b, cc, d, T2);
        for (k = 0; k < 3; ++k) {
            f->A[3 * v[0] + k] += (S1[k] + S2[k] + T1[k]) / 6.0;
            f->A[3 * v[1] + k] += (S1[k] + T1[k] + T2[k]) / 6.0;
            f->A[3 * v[2] + k] += (S1[k] + S2[k] + T2[k]) / 6.0;
            f->A[3 * v[3] + k] += (S2[k] + T1[k] + T2[k]) / 6.0;
        }
    }
    f->V = 0.0;
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < 3; ++k)
            f->V += f->X[3 * q + k] * f->A[3 * q + k];
    f->V /= 3.0;
}

/* 1 when the ray p + t dir (t > 0) crosses the triangle (a, b, c)
   (Moeller-Trumbore) */
static int ray_crosses(const double *p, const double dir[3], const double *a, const double *b, const double *c)
{
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double s[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    double h[3], g[3], det, u, w, t;
    sbc_cross3(dir, e2, h);
    det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (det == 0.0)
        return 0;
    u = (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]) / det;
    if (u < 0.0 || u > 1.0)
        return 0;
    sbc_cross3(s, e1, g);
    w = (dir[0] * g[0] + dir[1] * g[1] + dir[2] * g[2]) / det;
    if (w < 0.0 || u + w > 1.0)
        return 0;
    t = (e2[0] * g[0] + e2[1] * g[1] + e2[2] * g[2]) / det;
    return t > 0.0;
}

/* a point inside the surface through the centres fx: the parity of the
 * crossings of a ray in a direction no lattice plane or edge holds with the
 * two triangles (a, b, c), (a, c, d) of each quadrilateral */
static int inside_polyhedron(const sbc_frame *f, const double *fx, const double *p)
{
    static const double dir[3] = {1.0, 0.5377358490566038, 0.3141592653589793};
    int c, in = 0;
    for (c = 0; c < f->ncell; ++c) {
        const int *v = &f->cell[4 * c];
        const double *a = &fx[3 * v[0]], *b = &fx[3 * v[1]], *cc = &fx[3 * v[2]], *d = &fx[3 * v[3]];
        in ^= ray_crosses(p, dir, a, b, cc);
        in ^= ray_crosses(p, dir, a, cc, d);
    }
    return in;
}

/* (P)'s families in 3D: a particle on the low face of each axis it lies on
 * and its images across those axes (sbc_frame.image): a face pair, an edge
 * quadruple, the eight corners; members ordered by the bits of the axes
 * crossed */
static int family_3d(const sbc_frame *f, int q, int members[8])
{
    int axis[3], na = 0, a, s, j;
    for (a = 0; a < 3; ++a)
        if (f->side[q] >> (2 * a) & 3) {
            if (f->image[3 * q + a] < 0)
                return -1;
            axis[na++] = a;
        }
    for (j = 0; j < na; ++j)
        if (f->side[q] >> (2 * axis[j]) & 2) /* on a high face: a member of another's family */
            return 0;
    for (s = 0; s < 1 << na; ++s) {
        int p = q;
        for (j = 0; j < na; ++j)
            if (s >> j & 1)
                p = f->image[3 * p + axis[j]];
        members[s] = p;
    }
    return 1 << na;
}

static int faces_3d(const sbc_frame *f, int q) { return f->side[q]; }

const sbc_frame_geometry sbc_frame_geometry_3d = {3, "polyhedron", area_vectors, inside_polyhedron, family_3d,
                                                  faces_3d};

/* ---- detection ---- */

typedef sbc_frame_item item;

static int bits(int m) { return sbc_frame_face_count(m); }

int sbc_frame_face_count(int side)
{
    return (side & 1) + (side >> 1 & 1) + (side >> 2 & 1) + (side >> 3 & 1) + (side >> 4 & 1) + (side >> 5 & 1);
}

/* frame order: corners by their index, then edge and face particles by their
   faces, then z, y, x */
static int compare_items(const void *pa, const void *pb)
{
    const item *a = pa, *b = pb;
    int k;
    if (a->rank != b->rank)
        return a->rank - b->rank;
    if (a->side != b->side)
        return a->side - b->side;
    for (k = 2; k >= 0; --k)
        if (a->x[k] != b->x[k])
            return (a->x[k] > b->x[k]) - (a->x[k] < b->x[k]);
    return a->particle - b->particle;
}

sbc_status sbc_frame_from_items_3d(sbc_frame *f, item *it, int m, const double *r, sbc_error *err)
{
    int q, k;
    sbc_status st;
    qsort(it, (size_t)m, sizeof *it, compare_items);
    if ((st = sbc_frame_alloc(f, 3, m, err)) != SBC_OK)
        return st;
    for (q = 0; q < m; ++q) {
        f->particle[q] = it[q].particle;
        f->side[q] = it[q].side;
        f->partner[q] = -1;
        f->R[q] = r[it[q].particle];
        for (k = 0; k < 3; ++k)
            f->X[3 * q + k] = it[q].x[k];
    }
    for (k = 0; k < 8; ++k)
        f->corner[k] = k; /* the corners lead the frame order, by their index */
    return SBC_OK;
}

static int compare_doubles(const void *pa, const void *pb)
{
    const double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

/* The distinct values of v [m] within tol of each other: the sorted first
   value of each cluster into starts; returns their count */
static int clusters(double *v, int m, double tol, double *starts)
{
    int k, count = 0;
    qsort(v, (size_t)m, sizeof *v, compare_doubles);
    for (k = 0; k < m; ++k)
        if (count == 0 || v[k] - starts[count - 1] > tol)
            starts[count++] = v[k];
    return count;
}

/* the cluster of value v among starts [count]: the last start <= v + tol */
static int cluster_of(const double *starts, int count, double v, double tol)
{
    int lo = 0, hi = count - 1;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (starts[mid] <= v + tol)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* one face's grid: the place (i, j) of each of its particles along its two
   in-plane axes u, v (cyclic after the face's axis); grid [nu nv] frame
   positions */
typedef struct face_grid {
    int nu, nv;
    int *grid;
    double *us, *vs; /* [nu], [nv] the places' coordinates, m */
} face_grid;

static void grid_free(face_grid *g)
{
    free(g->grid);
    free(g->us);
    free(g->vs);
    memset(g, 0, sizeof *g);
}

static sbc_status face_build(const sbc_frame *f, int face, double tol, face_grid *g, sbc_error *err)
{
    const int a = face / 2, u = (a + 1) % 3, v = (a + 2) % 3;
    int q, m = 0, k;
    double *cu, *cv;
    memset(g, 0, sizeof *g);
    for (q = 0; q < f->n; ++q)
        m += (f->side[q] >> face) & 1;
    cu = malloc(sizeof(double) * (size_t)m);
    cv = malloc(sizeof(double) * (size_t)m);
    g->us = malloc(sizeof(double) * (size_t)m);
    g->vs = malloc(sizeof(double) * (size_t)m);
    if (!cu || !cv || !g->us || !g->vs) {
        free(cu);
        free(cv);
        grid_free(g);
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    }
    for (q = 0, k = 0; q < f->n; ++q)
        if ((f->side[q] >> face) & 1) {
            cu[k] = f->X[3 * q + u];
            cv[k++] = f->X[3 * q + v];
        }
    g->nu = clusters(cu, m, tol, g->us);
    g->nv = clusters(cv, m, tol, g->vs);
    free(cu);
    free(cv);
    if ((long)g->nu * g->nv != m || g->nu < 2 || g->nv < 2 || !(g->grid = malloc(sizeof(int) * (size_t)m))) {
        const int nu = g->nu, nv = g->nv;
        grid_free(g);
        if ((long)nu * nv != m || nu < 2 || nv < 2)
            return sbc_fail(err, SBC_ERR_FRAME, "frame: the %d centres of face %s form no grid (%d x %d places along "
                            "it); sbc_frame_detect_3d needs faces laid out as a lattice's", m, face_name[face], nu, nv);
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    }
    for (k = 0; k < m; ++k)
        g->grid[k] = -1;
    for (q = 0; q < f->n; ++q)
        if ((f->side[q] >> face) & 1) {
            const int i = cluster_of(g->us, g->nu, f->X[3 * q + u], tol), j = cluster_of(g->vs, g->nv, f->X[3 * q + v], tol);
            if (g->grid[i * g->nv + j] >= 0) {
                const int other = f->particle[g->grid[i * g->nv + j]];
                grid_free(g);
                return sbc_fail(err, SBC_ERR_FRAME, "frame: particles %d and %d share a place of the grid of face %s",
                                other, f->particle[q], face_name[face]);
            }
            g->grid[i * g->nv + j] = q;
        }
    return SBC_OK;
}

/* the face's quadrilaterals into cell (from *count on), anticlockwise seen
   from outside: e_u x e_v = e_a points out of the high face */
static void face_cells(const face_grid *g, int face, int *cell, int *count)
{
    int i, j;
    for (i = 0; i + 1 < g->nu; ++i)
        for (j = 0; j + 1 < g->nv; ++j) {
            int *c = &cell[4 * (*count)++];
            const int a = g->grid[i * g->nv + j], b = g->grid[(i + 1) * g->nv + j];
            const int cc = g->grid[(i + 1) * g->nv + j + 1], d = g->grid[i * g->nv + j + 1];
            c[0] = a;
            c[1] = face & 1 ? b : d;
            c[2] = cc;
            c[3] = face & 1 ? d : b;
        }
}

/* the images across axis a: each place of the low face and the same place
   of the high face, when both grids have the same places; face particles'
   partner is their one image */
static void pair_faces(sbc_frame *f, int a, const face_grid *lo, const face_grid *hi, double tol)
{
    int k;
    if (lo->nu != hi->nu || lo->nv != hi->nv)
        return;
    for (k = 0; k < lo->nu; ++k)
        if (fabs(lo->us[k] - hi->us[k]) > tol)
            return;
    for (k = 0; k < lo->nv; ++k)
        if (fabs(lo->vs[k] - hi->vs[k]) > tol)
            return;
    for (k = 0; k < lo->nu * lo->nv; ++k) {
        const int p = lo->grid[k], q = hi->grid[k];
        f->image[3 * p + a] = q;
        f->image[3 * q + a] = p;
        if (bits(f->side[p]) == 1 && bits(f->side[q]) == 1) {
            f->partner[p] = q;
            f->partner[q] = p;
        }
    }
}

/* the particles within band of each face of the box lo, hi: their items
   (corners checked) into it; returns the count, or -1 with err */
static int frame_items(int n, const double *x, double band, const double lo[3], const double hi[3], item *it,
                       int corner_particle[8], sbc_error *err)
{
    int p, k, m = 0;
    for (k = 0; k < 8; ++k)
        corner_particle[k] = -1;
    for (p = 0; p < n; ++p) {
        const double *xp = &x[3 * p];
        int side = 0;
        for (k = 0; k < 3; ++k) {
            side |= (xp[k] - lo[k] <= band) << (2 * k);
            side |= (hi[k] - xp[k] <= band) << (2 * k + 1);
        }
        if (!side)
            continue;
        if (bits(side) == 3) {
            const int c = (side & SBC_FACE_XHI ? 1 : 0) | (side & SBC_FACE_YHI ? 2 : 0) | (side & SBC_FACE_ZHI ? 4 : 0);
            if (corner_particle[c] >= 0) {
                sbc_fail(err, SBC_ERR_FRAME, "frame: two particles (%d and %d) sit at the corner (%s, %s, %s)",
                         corner_particle[c], p, face_name[c & 1], face_name[2 + (c >> 1 & 1)],
                         face_name[4 + (c >> 2 & 1)]);
                return -1;
            }
            corner_particle[c] = p;
        }
        it[m].particle = p;
        it[m].side = side;
        it[m].rank = 3 - bits(side);
        it[m++].x = xp;
    }
    for (k = 0; k < 8; ++k)
        if (corner_particle[k] < 0) {
            sbc_fail(err, SBC_ERR_FRAME, "frame: no particle at the corner (%s, %s, %s) of the packing",
                     face_name[k & 1], face_name[2 + (k >> 1 & 1)], face_name[4 + (k >> 2 & 1)]);
            return -1;
        }
    return m;
}

sbc_status sbc_frame_detect_grid_3d(sbc_frame *f, int n, const double *x, const double *r, double band, sbc_error *err)
{
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX}, rmin = DBL_MAX;
    int corner_particle[8], p, k, m, q, face, ncell = 0;
    face_grid grid[6];
    item *it;
    sbc_status st = SBC_OK;
    memset(f, 0, sizeof *f);
    if (n < 8)
        return sbc_fail(err, SBC_ERR_FRAME, "frame: %d particles cannot form a 3D frame (need at least 8)", n);
    for (p = 0; p < n; ++p) {
        for (k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], x[3 * p + k]);
            hi[k] = fmax(hi[k], x[3 * p + k]);
        }
        rmin = fmin(rmin, r[p]);
    }
    if (band <= 0.0)
        band = 0.5 * rmin;
    if (!(hi[0] - lo[0] > 2.0 * band && hi[1] - lo[1] > 2.0 * band && hi[2] - lo[2] > 2.0 * band))
        return sbc_fail(err, SBC_ERR_FRAME, "frame: the packing is too thin (%g x %g x %g m) to have six faces",
                        hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    if (!(it = malloc(sizeof *it * (size_t)n)))
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory");
    if ((m = frame_items(n, x, band, lo, hi, it, corner_particle, err)) < 0) {
        free(it);
        return err->status;
    }
    st = sbc_frame_from_items_3d(f, it, m, r, err);
    free(it);
    if (st != SBC_OK)
        return st;
    memset(grid, 0, sizeof grid);
    for (face = 0; face < 6 && st == SBC_OK; ++face)
        if ((st = face_build(f, face, band, &grid[face], err)) == SBC_OK)
            ncell += (grid[face].nu - 1) * (grid[face].nv - 1);
    if (st == SBC_OK && (!(f->cell = malloc(sizeof(int) * 4 * (size_t)ncell)) ||
                         !(f->image = malloc(sizeof(int) * 3 * (size_t)f->n))))
        st = sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory for %d surface cells", ncell);
    if (st == SBC_OK) {
        for (face = 0; face < 6; ++face)
            face_cells(&grid[face], face, f->cell, &f->ncell);
        for (q = 0; q < 3 * f->n; ++q)
            f->image[q] = -1;
        for (k = 0; k < 3; ++k)
            pair_faces(f, k, &grid[2 * k], &grid[2 * k + 1], band);
        area_vectors(f);
        if (!(f->V > 0.0))
            st = sbc_fail(err, SBC_ERR_FRAME, "frame: the surface through the frame's centres encloses no volume");
    }
    for (face = 0; face < 6; ++face)
        grid_free(&grid[face]);
    if (st != SBC_OK)
        sbc_frame_free(f);
    return st;
}
