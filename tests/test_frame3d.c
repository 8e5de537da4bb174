/* The frame of a sphere packing (sbc_frame_detect_3d, frame_3d.c) on simple
 * cubic lattices: its particles, corners, pairs across faces, the area
 * vectors of eq. 2 in 3D by hand (d^2, d^2/2, d^2/4 from each face), the
 * identity sum_q X_q (x) A_q = V I, an affine image of the frame (V det G),
 * the point-in-polyhedron test of confine.h, and the refusals. */
#include "check.h"
#include "tests.h"

#include "sbc/confine.h"
#include "sbc/controller.h"
#include "sbc/frame.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* an nx x ny x nz simple cubic lattice of spacing d (m), radius d/2 */
static int cubic(int nx, int ny, int nz, double d, double *x, double *r)
{
    int i, j, k, n = 0;
    for (k = 0; k < nz; ++k)
        for (j = 0; j < ny; ++j)
            for (i = 0; i < nx; ++i) {
                x[3 * n] = i * d, x[3 * n + 1] = j * d, x[3 * n + 2] = k * d;
                r[n++] = 0.5 * d;
            }
    return n;
}

/* the largest |sum_q X_q (x) A_q - V I| over V |I| */
static double identity_error(const sbc_frame *f)
{
    double worst = 0.0;
    int i, j, q;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double s = 0.0;
            for (q = 0; q < f->n; ++q)
                s += f->X[3 * q + i] * f->A[3 * q + j];
            worst = fmax(worst, fabs(s - (i == j ? f->V : 0.0)) / f->V);
        }
    return worst;
}

static int count_bits(int m)
{
    int b = 0;
    for (; m; m >>= 1)
        b += m & 1;
    return b;
}

/* the lattice N1 x N2 x N3: Q, the corners, A by hand, pairs, eq. 2 */
static void lattice(int n1, int n2, int n3)
{
    const double d = 2e-3;
    const int n = n1 * n2 * n3;
    double *x = malloc(sizeof(double) * 3 * (size_t)n), *r = malloc(sizeof(double) * (size_t)n);
    const double L[3] = {(n1 - 1) * d, (n2 - 1) * d, (n3 - 1) * d};
    sbc_frame f;
    sbc_error err;
    double worst_a = 0.0;
    int q, k, c, bad_pair = 0, faces = 0, paired = 0, bad_corner = 0;
    cubic(n1, n2, n3, d, x, r);
    CHECK(sbc_frame_detect_3d(&f, n, x, r, 0.0, &err) == SBC_OK);
    if (f.n == 0) {
        printf("  %s\n", err.message);
        free(x);
        free(r);
        return;
    }
    CHECK(f.dim == 3 && f.n == n - (n1 - 2) * (n2 - 2) * (n3 - 2));
    CHECK(f.ncell == 2 * ((n1 - 1) * (n2 - 1) + (n2 - 1) * (n3 - 1) + (n1 - 1) * (n3 - 1)));
    for (c = 0; c < 8; ++c) { /* corner c at the high x, y, z as its bits say */
        const double *X = &f.X[3 * f.corner[c]];
        for (k = 0; k < 3; ++k)
            bad_corner |= X[k] != ((c >> k) & 1 ? L[k] : 0.0);
    }
    CHECK(!bad_corner);
    for (q = 0; q < f.n; ++q) {
        /* from each face it lies on, d^2 over 1, 2, 4 (face, edge, corner), outwards */
        const double share = d * d / (count_bits(f.side[q]) == 1 ? 1.0 : count_bits(f.side[q]) == 2 ? 2.0 : 4.0);
        for (k = 0; k < 3; ++k) {
            const double expect = f.side[q] >> (2 * k) & 1 ? -share : f.side[q] >> (2 * k + 1) & 1 ? share : 0.0;
            worst_a = fmax(worst_a, fabs(f.A[3 * q + k] - expect) / (d * d));
        }
        if (count_bits(f.side[q]) == 1) {
            const int p = f.partner[q];
            ++faces;
            if (p >= 0) {
                int same = 0;
                ++paired;
                for (k = 0; k < 3; ++k) /* the same place, across the face's axis */
                    same += f.side[q] >> (2 * k) & 3 ? fabs(f.X[3 * p + k] - f.X[3 * q + k]) == L[k]
                                                     : f.X[3 * p + k] == f.X[3 * q + k];
                bad_pair |= same != 3 || f.partner[p] != q;
            }
        } else
            bad_pair |= f.partner[q] != -1;
    }
    CHECK(worst_a < 1e-13 && !bad_pair && paired == faces && faces == 2 * ((n1 - 2) * (n2 - 2) + (n2 - 2) * (n3 - 2) +
                                                                   (n1 - 2) * (n3 - 2)));
    CHECK(fabs(f.V - L[0] * L[1] * L[2]) <= 1e-14 * f.V && identity_error(&f) < 1e-14);
    printf("  frame3d: %d x %d x %d lattice: Q = %d, %d cells, |A - A by hand| / d^2 = %.1e, V %.6g m^3, "
           "|sum X (x) A - V I| / V = %.1e\n", n1, n2, n3, f.n, f.ncell, worst_a, f.V, identity_error(&f));
    /* an affine image X -> G X keeps the faces planar: the identity with V det G */
    {
        const double G[9] = {1.1, 0.2, -0.05, 0.03, 0.9, 0.1, 0.0, -0.07, 1.2};
        const double V0 = f.V, det = sbc_tensor_det(3, G);
        for (q = 0; q < f.n; ++q) {
            double y[3];
            sbc_tensor_apply(3, G, &f.X[3 * q], y);
            memcpy(&f.X[3 * q], y, sizeof y);
        }
        sbc_frame_update_geometry(&f);
        CHECK(fabs(f.V - det * V0) <= 1e-13 * f.V && identity_error(&f) < 1e-13);
    }
    sbc_frame_free(&f);
    free(x);
    free(r);
}

/* confine.h in 3D: inside and outside the cube of a 4^3 lattice's centres */
static void inside(void)
{
    const double d = 1.0;
    double x[3 * 64], r[64], fx[3 * 64], v[3] = {0.0, 0.0, 0.0};
    static const double in[][3] = {{1.5, 1.5, 1.5}, {0.01, 0.01, 0.01}, {2.99, 1.0, 2.0}, {1.0, 1.0, 1.0}};
    static const double out[][3] = {{-0.01, 1.5, 1.5}, {3.01, 1.0, 1.0}, {1.0, 1.0, 3.5}, {4.0, 4.0, 4.0}};
    sbc_frame f;
    sbc_error err;
    int k, ok_in = 1, ok_out = 1;
    cubic(4, 4, 4, d, x, r);
    CHECK(sbc_frame_detect_3d(&f, 64, x, r, 0.0, &err) == SBC_OK);
    for (k = 0; k < f.n; ++k)
        memcpy(&fx[3 * k], &f.X[3 * k], sizeof(double) * 3);
    for (k = 0; k < 4; ++k) {
        ok_in &= sbc_confine_inside(&f, fx, in[k]);
        ok_out &= !sbc_confine_inside(&f, fx, out[k]);
    }
    CHECK(ok_in && ok_out);
    CHECK(sbc_confine_check(&f, fx, 2, 7, out[1], v, &err) == SBC_ERR_GEOMETRY &&
          strstr(err.message, "interior particle 7 escaped") && strstr(err.message, "(3.01, 1, 1) m is outside the "
                                                                                  "polyhedron"));
    /* the 3D frame is refused by the controller until it drives 3D conditions */
    {
        static const char *words[] = {"D", "F", "1", "0", "0", "1"};
        sbc_settings s;
        double mass[64];
        for (k = 0; k < 64; ++k)
            mass[k] = 1.0;
        CHECK(sbc_settings_parse(&s, 6, words, &err) == SBC_OK);
        CHECK(sbc_controller_create(&f, &s, mass, 1e-6, 1e4, &err) == NULL &&
              strstr(err.message, "a frame of dimension 3") && strstr(err.message, "2D frames only"));
    }
    sbc_frame_free(&f);
}

/* what cannot be a frame: a missing corner, a face whose centres form no grid, a flat packing */
static void refused(void)
{
    double x[3 * 64], r[64];
    sbc_frame f;
    sbc_error err;
    int n = cubic(4, 4, 4, 1.0, x, r);
    x[3 * 63] += 0.7; /* the corner (3, 3, 3) moves out to x = 3.7: face xhi holds it alone */
    CHECK(sbc_frame_detect_3d(&f, n, x, r, 0.0, &err) == SBC_ERR_FRAME &&
          strstr(err.message, "no particle at the corner (xhi, ylo, zlo)"));
    cubic(4, 4, 4, 1.0, x, r);
    x[3 * 5] += 0.45; /* particle 5 on face zlo at (1.45, 1): 5 places along x, 16 centres */
    CHECK(sbc_frame_detect_3d(&f, n, x, r, 0.0, &err) == SBC_ERR_FRAME && strstr(err.message, "face zlo") &&
          strstr(err.message, "form no grid"));
    n = cubic(4, 4, 1, 1.0, x, r);
    CHECK(sbc_frame_detect_3d(&f, n, x, r, 0.0, &err) == SBC_ERR_FRAME && strstr(err.message, "too thin"));
    CHECK(sbc_frame_detect_3d(&f, 5, x, r, 0.0, &err) == SBC_ERR_FRAME && strstr(err.message, "need at least 8"));
}

/* the 3D frame's restart data: a round trip, and refusals by name */
static void saved(void)
{
    double x[3 * 120], r[120], *state;
    sbc_frame f, g;
    sbc_error err;
    size_t n;
    const int np = cubic(4, 5, 6, 1e-3, x, r);
    CHECK(sbc_frame_detect_3d(&f, np, x, r, 0.0, &err) == SBC_OK);
    n = sbc_frame_state_size(&f);
    CHECK(n == 2 + 10 * (size_t)f.n + 9 + 1 + 4 * (size_t)f.ncell);
    state = malloc(sizeof(double) * n);
    sbc_frame_save(&f, state);
    CHECK(sbc_frame_load(&g, state, n, &err) == SBC_OK);
    CHECK(g.dim == 3 && g.n == f.n && g.V == f.V && g.ncell == f.ncell &&
          memcmp(g.X, f.X, sizeof(double) * 3 * (size_t)f.n) == 0 &&
          memcmp(g.A, f.A, sizeof(double) * 3 * (size_t)f.n) == 0 &&
          memcmp(g.side, f.side, sizeof(int) * (size_t)f.n) == 0 &&
          memcmp(g.partner, f.partner, sizeof(int) * (size_t)f.n) == 0 &&
          memcmp(g.corner, f.corner, sizeof f.corner) == 0 && memcmp(g.cell, f.cell, sizeof(int) * 4 * (size_t)f.ncell) == 0);
    sbc_frame_free(&g);
    CHECK(sbc_frame_load(&g, state, n - 1, &err) == SBC_ERR_INPUT && strstr(err.message, "3D frame of 96 particles"));
    state[n - 1] = f.n; /* a cell corner past the frame */
    CHECK(sbc_frame_load(&g, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "cell corner"));
    sbc_frame_save(&f, state);
    state[2 + 1] = 0; /* the first corner's side: no face */
    CHECK(sbc_frame_load(&g, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "side"));
    free(state);
    sbc_frame_free(&f);
}

/* the words in 3D: nine values of F, held to the packing's dimension */
static void words(void)
{
    static const char *w3[] = {"D", "F", "1", "0.1", "0", "0", "1", "0", "0", "0", "0.99", "increments", "2"};
    static const char *w2[] = {"D", "F", "0.99", "0", "0", "1"}, *none[] = {"P", "increments", "3"};
    static const char *bad3[] = {"D", "F", "1", "0", "0", "0", "1", "0", "0", "0", "-1"};
    static const char *path3[] = {"D", "F", "-0.5", "0", "0", "0", "-0.5", "0", "0", "0", "1"};
    static const char *mixed[] = {"mixed", "stress", "P22", "-100", "2"};
    sbc_settings s;
    sbc_error err;
    CHECK(sbc_settings_parse(&s, 13, w3, &err) == SBC_OK && s.dim == 3 && s.F[SBC_IJ(0, 1)] == 0.1 &&
          s.F[SBC_IJ(2, 2)] == 0.99 && s.F[SBC_IJ(1, 1)] == 1.0 && s.increments == 2);
    CHECK(sbc_settings_check_dimension(&s, 3, &err) == SBC_OK && s.dim == 3);
    CHECK(sbc_settings_check_dimension(&s, 2, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "9 values give a 3D F, but the packing is 2D (expected 4 values"));
    CHECK(sbc_settings_parse(&s, 6, w2, &err) == SBC_OK && s.dim == 2);
    CHECK(sbc_settings_check_dimension(&s, 3, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "4 values give a 2D F, but the packing is 3D (expected 9 values, F11 F12 F13"));
    /* no deformation in the words: the packing's dimension, F = I */
    CHECK(sbc_settings_parse(&s, 3, none, &err) == SBC_OK && sbc_settings_check_dimension(&s, 3, &err) == SBC_OK &&
          s.dim == 3 && s.F[SBC_IJ(2, 2)] == 1.0 && sbc_tensor_det(3, s.F) == 1.0);
    CHECK(sbc_settings_parse(&s, 11, bad3, &err) == SBC_ERR_INPUT && strstr(err.message, "det F = -1 is not positive"));
    /* det F of diag(-0.5, -0.5, 1) is 0.25 > 0, but the path from I passes det F = 0 at t = 2/3 */
    CHECK(sbc_settings_parse(&s, 11, path3, &err) == SBC_ERR_INPUT && strstr(err.message, "linear path"));
    CHECK(sbc_settings_parse(&s, 5, mixed, &err) == SBC_OK && sbc_settings_check_dimension(&s, 3, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "mixed conditions"));
    CHECK(sbc_settings_check_dimension(&s, 4, &err) == SBC_ERR_INPUT && strstr(err.message, "dimension 4"));
}

void test_frame_3d(void)
{
    words();
    saved();
    lattice(3, 3, 3);
    lattice(4, 5, 6);
    lattice(10, 10, 10);
    inside();
    refused();
}
