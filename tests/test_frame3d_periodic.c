/* The frame of a geometrically periodic sphere packing (frame_3d_periodic.c)
 * and the triangulation of its faces (triangulate.c): the Delaunay
 * triangulation of a square against its own count, area and empty-circle
 * property; on generated packings (tests/packings, read from the top of the
 * repository as make runs the tests) the frame's spheres (every sphere crossing
 * a face), their images at exactly +-L, a closed and outward surface (each
 * edge of it in two triangles, once each way), (P)'s paired faces sharing
 * their triangles through the images, the identity sum_q X_q (x) A_q = V I
 * and V = L^3; the frame through its restart data; the same frame from
 * shuffled and shifted centres; the refusals. */
#include "check.h"
#include "tests.h"

#include "sbc/embedded/generate.h" /* sbc_sphere_packing */
#include "sbc/packing.h"
#include "sbc/frame.h"
#include "servo/triangulate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long lcg = 12345;
static double uniform(void)
{
    lcg = lcg * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg >> 11) / 9007199254740992.0;
}

/* m points of the unit square: its corners, s on each side, the rest inside;
   the triangulation's count, area, orientation and empty circles */
static void square(int m, int s)
{
    double *uv = malloc(sizeof(double) * 2 * (size_t)m);
    int *tri = malloc(sizeof(int) * 6 * (size_t)m), k, t, n, empty = 1, h = 4 + 4 * s;
    double area = 0.0;
    for (k = 0; k < 4; ++k)
        uv[2 * k] = k & 1, uv[2 * k + 1] = k >> 1;
    for (k = 4; k < 4 + 4 * s; ++k) { /* side (k - 4) % 4 */
        const int side = (k - 4) % 4;
        const double along = 0.05 + 0.9 * uniform();
        uv[2 * k] = side == 0 ? along : side == 1 ? 1.0 : side == 2 ? along : 0.0;
        uv[2 * k + 1] = side == 0 ? 0.0 : side == 1 ? along : side == 2 ? 1.0 : along;
    }
    for (; k < m; ++k)
        uv[2 * k] = 0.01 + 0.98 * uniform(), uv[2 * k + 1] = 0.01 + 0.98 * uniform();
    n = sbc_triangulate_square(m, uv, tri);
    CHECK(n == 2 * m - h - 2);
    for (t = 0; t < n; ++t) {
        const double *a = &uv[2 * tri[3 * t]], *b = &uv[2 * tri[3 * t + 1]], *c = &uv[2 * tri[3 * t + 2]];
        area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        for (k = 0; k < m; ++k) { /* no point strictly inside a circumcircle (beyond round-off) */
            const double *d = &uv[2 * k];
            const double ax = a[0] - d[0], ay = a[1] - d[1], bx = b[0] - d[0], by = b[1] - d[1], cx = c[0] - d[0],
                         cy = c[1] - d[1];
            const double in = (ax * ax + ay * ay) * (bx * cy - by * cx) - (bx * bx + by * by) * (ax * cy - ay * cx) +
                              (cx * cx + cy * cy) * (ax * by - ay * bx);
            empty &= in <= 1e-12;
        }
    }
    CHECK_ABS(area, 1.0, 1e-13);
    CHECK(empty);
    /* refused: a corner missing, a point outside, a point twice */
    uv[0] = 0.5;
    CHECK(sbc_triangulate_square(m, uv, tri) == -1);
    uv[0] = -0.1, uv[1] = 0.5;
    CHECK(sbc_triangulate_square(m, uv, tri) == -1);
    uv[0] = uv[1] = 0.0;
    uv[2 * (m - 1)] = uv[2 * (m - 2)], uv[2 * (m - 1) + 1] = uv[2 * (m - 2) + 1];
    CHECK(sbc_triangulate_square(m, uv, tri) == -1);
    free(uv);
    free(tri);
}

/* every directed edge of the triangles once and its reverse once */
static int closed(const sbc_frame *f)
{
    int c, d, k, l, ok = 1;
    for (c = 0; c < f->ncell && ok; ++c)
        for (k = 0; k < 3 && ok; ++k) {
            const int a = f->cell[4 * c + k], b = f->cell[4 * c + (k + 1) % 3];
            int same = 0, reverse = 0;
            for (d = 0; d < f->ncell; ++d)
                for (l = 0; l < 3; ++l) {
                    same += f->cell[4 * d + l] == a && f->cell[4 * d + (l + 1) % 3] == b;
                    reverse += f->cell[4 * d + l] == b && f->cell[4 * d + (l + 1) % 3] == a;
                }
            ok = same == 1 && reverse == 1;
        }
    return ok;
}

/* the faces crossed by sphere p of the cube [0, L]^3 as SBC_FACE_ bits */
static int crossing(const double *x, double r, double L)
{
    int a, side = 0;
    for (a = 0; a < 3; ++a) {
        side |= (x[a] - r < 0.0 && x[a] + r > 0.0) << (2 * a);
        side |= (x[a] - r < L && x[a] + r > L) << (2 * a + 1);
    }
    return side;
}

/* a generated packing from tests/packings (its generate line in its
   header): the spheres, and L from the corner sphere at the origin and its
   image at (L, 0, 0), the sphere of the same radius with y = z = 0 */
static int read_packing(const char *path, sbc_sphere_packing *p)
{
    sbc_error err;
    int k, o = -1;
    memset(p, 0, sizeof *p);
    if (sbc_spheres_read(path, &p->n, &p->x, &p->r, &err) != SBC_OK)
        return 0;
    for (k = 0; k < p->n; ++k)
        if (p->x[3 * k] == 0.0 && p->x[3 * k + 1] == 0.0 && p->x[3 * k + 2] == 0.0)
            o = k;
    for (k = 0; k < p->n && o >= 0; ++k)
        if (p->r[k] == p->r[o] && p->x[3 * k + 1] == 0.0 && p->x[3 * k + 2] == 0.0 && p->x[3 * k] > p->L)
            p->L = p->x[3 * k];
    return p->L > 0.0;
}

static void periodic(const char *path, int expect)
{
    sbc_sphere_packing p;
    sbc_frame f, g;
    sbc_error err;
    int q, k, a, c, expected = 0, sides_ok = 1, images_ok = 1, paired_ok = 1, outward = 0, *order;
    double *xs, *rs, shift[3] = {0.1234567e-3, -2.3456789e-3, 0.7654321e-3};
    CHECK(read_packing(path, &p) && p.n == expect);
    if (p.n != expect)
        return;
    CHECK(sbc_frame_detect_3d(&f, p.n, p.x, p.r, 0.0, &err) == SBC_OK);
    if (f.n == 0)
        return;
    for (k = 0; k < p.n; ++k)
        expected += crossing(&p.x[3 * k], p.r[k], p.L) != 0;
    for (q = 0; q < f.n; ++q)
        sides_ok &= f.side[q] == crossing(&p.x[3 * f.particle[q]], p.r[f.particle[q]], p.L);
    CHECK(f.n == expected && sides_ok);
    for (k = 0; k < 8; ++k) /* corner k at (L if bit a of k) */
        for (a = 0; a < 3; ++a)
            sides_ok &= f.X[3 * f.corner[k] + a] == (k >> a & 1 ? p.L : 0.0);
    CHECK(sides_ok);
    for (q = 0; q < f.n; ++q) /* the image across each crossed axis: the same place +-L */
        for (a = 0; a < 3; ++a) {
            const int im = f.image[3 * q + a], on = f.side[q] >> (2 * a) & 3;
            if (!on) {
                images_ok &= im == -1;
                continue;
            }
            images_ok &= im >= 0 && f.image[3 * im + a] == q && f.R[im] == f.R[q] &&
                         f.X[3 * im + a] == f.X[3 * q + a] + (on == 1 ? p.L : -p.L) &&
                         f.X[3 * im + (a + 1) % 3] == f.X[3 * q + (a + 1) % 3] &&
                         f.X[3 * im + (a + 2) % 3] == f.X[3 * q + (a + 2) % 3];
        }
    CHECK(images_ok);
    /* (P): each high-face triangle is its low-face twin's images, reversed */
    for (c = 0; c < f.ncell; c += 2) {
        const int *lo = &f.cell[4 * c], *hi = &f.cell[4 * c + 4];
        int axis = -1;
        for (a = 0; a < 3; ++a)
            if (f.side[lo[0]] >> (2 * a) & 1 && f.side[lo[1]] >> (2 * a) & 1 && f.side[lo[2]] >> (2 * a) & 1)
                axis = a;
        paired_ok &= axis >= 0 && lo[3] == lo[0] && hi[3] == hi[0] && hi[0] == f.image[3 * lo[0] + axis] &&
                     hi[1] == f.image[3 * lo[2] + axis] && hi[2] == f.image[3 * lo[1] + axis];
    }
    CHECK(paired_ok);
    CHECK(closed(&f));
    CHECK(test_frame_identity_error(&f) < 1e-14);
    CHECK_REL(f.V, p.L * p.L * p.L, 1e-14);
    for (q = 0; q < f.n; ++q) { /* every area vector points out of the cube's centre */
        double dot = 0.0;
        for (a = 0; a < 3; ++a)
            dot += f.A[3 * q + a] * (f.X[3 * q + a] - 0.5 * p.L);
        outward += dot > 0.0;
    }
    CHECK(outward == f.n);
    { /* restart data: the triangles and images come back as they were */
        const size_t size = sbc_frame_state_size(&f);
        double *state = malloc(sizeof(double) * size);
        CHECK(state != NULL);
        if (state) {
            sbc_frame_save(&f, state);
            CHECK(sbc_frame_load(&g, state, size, &err) == SBC_OK);
            CHECK(g.n == f.n && g.ncell == f.ncell && g.V == f.V &&
                  memcmp(g.cell, f.cell, sizeof(int) * 4 * (size_t)f.ncell) == 0 &&
                  memcmp(g.image, f.image, sizeof(int) * 3 * (size_t)f.n) == 0 &&
                  memcmp(g.A, f.A, sizeof(double) * 3 * (size_t)f.n) == 0);
            sbc_frame_free(&g);
            free(state);
        }
    }
    /* a host's centres: shuffled and shifted, the same frame */
    order = malloc(sizeof(int) * (size_t)p.n);
    xs = malloc(sizeof(double) * 3 * (size_t)p.n);
    rs = malloc(sizeof(double) * (size_t)p.n);
    for (k = 0; k < p.n; ++k)
        order[k] = (k * 7919) % p.n; /* p.n is no multiple of 7919 */
    for (k = 0; k < p.n; ++k) {
        for (a = 0; a < 3; ++a)
            xs[3 * k + a] = p.x[3 * order[k] + a] + shift[a];
        rs[k] = p.r[order[k]];
    }
    CHECK(sbc_frame_detect_3d(&g, p.n, xs, rs, 0.0, &err) == SBC_OK);
    if (g.n == f.n) {
        int same = g.ncell == f.ncell;
        for (q = 0; q < f.n; ++q)
            same &= order[g.particle[q]] == f.particle[q] && g.side[q] == f.side[q];
        CHECK(same && test_frame_identity_error(&g) < 1e-13 && fabs(g.V / f.V - 1.0) < 1e-12);
    } else {
        CHECK(g.n == f.n);
    }
    sbc_frame_free(&g);
    /* an image taken away: refused with the particle and the faces */
    for (k = 0, q = -1; k < p.n && q < 0; ++k)
        if (crossing(&p.x[3 * k], p.r[k], p.L) == SBC_FACE_ZLO)
            q = k;
    for (k = 0; k < 3; ++k)
        xs[3 * q + k] = p.x[3 * q + k] + shift[k];
    for (k = 0; k < p.n; ++k) { /* unshuffled, shifted */
        for (a = 0; a < 3; ++a)
            xs[3 * k + a] = p.x[3 * k + a] + shift[a];
        rs[k] = p.r[k];
    }
    rs[q] *= 1.0 + 1e-9;
    {   /* named: q on zlo, or its image on zhi, whichever the matching meets first */
        char want_lo[96], want_hi[96];
        int image = -1;
        for (k = 0; k < p.n; ++k)
            if (p.r[k] == p.r[q] && p.x[3 * k] == p.x[3 * q] && p.x[3 * k + 1] == p.x[3 * q + 1] &&
                p.x[3 * k + 2] == p.x[3 * q + 2] + p.L)
                image = k;
        snprintf(want_lo, sizeof want_lo, "particle %d on face zlo has no periodic image on face zhi", q);
        snprintf(want_hi, sizeof want_hi, "particle %d on face zhi has no periodic image on face zlo", image);
        CHECK(image >= 0 && sbc_frame_detect_3d(&g, p.n, xs, rs, 0.0, &err) == SBC_ERR_FRAME &&
              (strstr(err.message, want_lo) || strstr(err.message, want_hi)));
    }
    free(order);
    free(xs);
    free(rs);
    sbc_frame_free(&f);
    sbc_sphere_packing_free(&p);
}

/* neither a lattice nor periodic: both named in the refusal */
static void neither(void)
{
    double x[3 * 27], r[27];
    sbc_frame f;
    sbc_error err;
    int k;
    for (k = 0; k < 27; ++k) {
        x[3 * k] = 6e-3 * uniform();
        x[3 * k + 1] = 6e-3 * uniform();
        x[3 * k + 2] = 6e-3 * uniform();
        r[k] = 1e-3;
    }
    CHECK(sbc_frame_detect_3d(&f, 27, x, r, 0.0, &err) == SBC_ERR_FRAME && strstr(err.message, "nor is it a "
                                                                                  "geometrically periodic packing"));
}

void test_frame_3d_periodic(void)
{
    square(40, 3);
    square(300, 10);
    periodic("tests/packings/irregular24_strain.txt", 60);
    periodic("tests/packings/irregular24_pd2.txt", 63);
    neither();
}
