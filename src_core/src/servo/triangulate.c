/* The Delaunay triangulation of points in the unit square (Bowyer-Watson):
 * the square split along a diagonal, then each point inserted by removing the
 * triangles whose circumcircle holds it and joining it to the cavity's
 * boundary. A point on a side lies on the chord of the triangle beside that
 * side, so that triangle is always in its cavity; the side's stretch through
 * the point is the one cavity edge the point is collinear with, and is left
 * open: the two stretches either side of it become hull edges. */
#include "triangulate.h"

#include <math.h>
#include <stdlib.h>

/* twice the signed area of (a, b, c): > 0 anticlockwise */
static double orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* > 0 when d lies inside the circle through the anticlockwise a, b, c */
static double incircle(const double *a, const double *b, const double *c, const double *d)
{
    const double ax = a[0] - d[0], ay = a[1] - d[1], bx = b[0] - d[0], by = b[1] - d[1];
    const double cx = c[0] - d[0], cy = c[1] - d[1];
    return (ax * ax + ay * ay) * (bx * cy - by * cx) - (bx * bx + by * by) * (ax * cy - ay * cx) +
           (cx * cx + cy * cy) * (ax * by - ay * bx);
}

static int on_side(const double *p) { return p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0; }

static int corner_of(const double *p)
{
    if ((p[0] != 0.0 && p[0] != 1.0) || (p[1] != 0.0 && p[1] != 1.0))
        return -1;
    return (p[0] == 1.0) + 2 * (p[1] == 1.0);
}

/* the cavity of point p: its edges (e[2k], e[2k+1]) whose reverse is no other
   bad triangle's edge, into edge; returns their count */
static int cavity_edges(const int *tri, const int *bad, int nbad, int *edge)
{
    int i, j, s, t, count = 0;
    for (i = 0; i < nbad; ++i)
        for (s = 0; s < 3; ++s) {
            const int a = tri[3 * bad[i] + s], b = tri[3 * bad[i] + (s + 1) % 3];
            int shared = 0;
            for (j = 0; j < nbad && !shared; ++j)
                for (t = 0; t < 3 && !shared; ++t)
                    shared = j != i && tri[3 * bad[j] + t] == b && tri[3 * bad[j] + (t + 1) % 3] == a;
            if (!shared) {
                edge[2 * count] = a;
                edge[2 * count++ + 1] = b;
            }
        }
    return count;
}

static int insert(int p, const double *uv, int *tri, int *ntri, int *bad, int *edge)
{
    const double *x = &uv[2 * p];
    int t, nbad = 0, nedge, k, made = 0;
    for (t = 0; t < *ntri; ++t) {
        const int *v = &tri[3 * t];
        if (incircle(&uv[2 * v[0]], &uv[2 * v[1]], &uv[2 * v[2]], x) > 0.0)
            bad[nbad++] = t;
    }
    if (nbad == 0)
        return -1;
    nedge = cavity_edges(tri, bad, nbad, edge);
    for (k = nbad - 1; k >= 0; --k) { /* bad ascends: remove from the top down */
        --*ntri;
        tri[3 * bad[k]] = tri[3 * *ntri];
        tri[3 * bad[k] + 1] = tri[3 * *ntri + 1];
        tri[3 * bad[k] + 2] = tri[3 * *ntri + 2];
    }
    for (k = 0; k < nedge; ++k) {
        const int a = edge[2 * k], b = edge[2 * k + 1];
        const double o = orient(&uv[2 * a], &uv[2 * b], x);
        if (o < 0.0)
            return -1; /* the cavity is not star-shaped from p: the predicates failed */
        if (o == 0.0)
            continue; /* the side's stretch p lies on */
        tri[3 * *ntri] = a;
        tri[3 * *ntri + 1] = b;
        tri[3 * (*ntri)++ + 2] = p;
        ++made;
    }
    return made >= 2 ? 0 : -1;
}

/* the triangles tile the unit square: each anticlockwise, their areas adding
   up to 1, as many as a triangulation of these points has */
static int tiles(int m, const double *uv, const int *tri, int ntri)
{
    double area = 0.0;
    int t, k, h = 0;
    for (k = 0; k < m; ++k)
        h += on_side(&uv[2 * k]);
    if (ntri != 2 * m - h - 2)
        return 0;
    for (t = 0; t < ntri; ++t) {
        const double o = orient(&uv[2 * tri[3 * t]], &uv[2 * tri[3 * t + 1]], &uv[2 * tri[3 * t + 2]]);
        if (!(o > 0.0))
            return 0;
        area += 0.5 * o;
    }
    return fabs(area - 1.0) <= 1e-12;
}

int sbc_triangulate_square(int m, const double *uv, int *tri)
{
    int corner[4] = {-1, -1, -1, -1}, k, ntri = 0, ok = 1, *bad, *edge;
    if (m < 4)
        return -1;
    for (k = 0; k < m; ++k) {
        const double *p = &uv[2 * k];
        const int c = corner_of(p);
        if (!(p[0] >= 0.0 && p[0] <= 1.0 && p[1] >= 0.0 && p[1] <= 1.0))
            return -1;
        if (c >= 0) {
            if (corner[c] >= 0)
                return -1;
            corner[c] = k;
        }
    }
    for (k = 0; k < 4; ++k)
        if (corner[k] < 0)
            return -1;
    bad = malloc(sizeof(int) * (size_t)(2 * m));
    edge = malloc(sizeof(int) * (size_t)(4 * m + 8));
    if (!bad || !edge) {
        free(bad);
        free(edge);
        return -1;
    }
    /* corners 0 (0,0), 1 (1,0), 3 (1,1), 2 (0,1): two anticlockwise triangles */
    tri[0] = corner[0], tri[1] = corner[1], tri[2] = corner[3];
    tri[3] = corner[0], tri[4] = corner[3], tri[5] = corner[2];
    ntri = 2;
    for (k = 0; k < m && ok; ++k)
        if (corner_of(&uv[2 * k]) < 0 && on_side(&uv[2 * k])) /* the sides first, then the inside */
            ok = insert(k, uv, tri, &ntri, bad, edge) == 0;
    for (k = 0; k < m && ok; ++k)
        if (!on_side(&uv[2 * k]))
            ok = insert(k, uv, tri, &ntri, bad, edge) == 0;
    free(bad);
    free(edge);
    return ok && tiles(m, uv, tri, ntri) ? ntri : -1;
}
