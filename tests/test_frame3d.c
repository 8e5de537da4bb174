/* The frame of a sphere packing (sbc_frame_detect_3d, frame_3d.c) on simple
 * cubic lattices: its particles, corners, pairs across faces, the area
 * vectors of eq. 2 in 3D by hand (d^2, d^2/2, d^2/4 from each face), the
 * identity sum_q X_q (x) A_q = V I, an affine image of the frame (V det G),
 * the point-in-polyhedron test of confine.h, and the refusals. */
#include "check.h"
#include "tests.h"

#include "sbc/columns.h"
#include "sbc/confine.h"
#include "sbc/controller.h"
#include "sbc/damping.h"
#include "sbc/driver.h"
#include "sbc/frame.h"
#include "base/words.h"
#include "servo/geometry.h"

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

/* the largest |sum_q X_q (x) A_q - V I| over V |I| (tests.h) */
double test_frame_identity_error(const sbc_frame *f)
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
    int q, k, c, bad_pair = 0, bad_image = 0, images = 0, faces = 0, paired = 0, bad_corner = 0;
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
        for (k = 0; k < 3; ++k) { /* the image across axis k: the same place, |dX_k| = L_k, on faces of k only */
            const int p = f.image[3 * q + k], on = f.side[q] >> (2 * k) & 3;
            int j, same = p >= 0;
            for (j = 0; j < 3 && p >= 0; ++j)
                same &= j == k ? fabs(f.X[3 * p + j] - f.X[3 * q + j]) == L[j] : f.X[3 * p + j] == f.X[3 * q + j];
            bad_image |= on ? !same || f.image[3 * p + k] != q : p != -1;
            images += p >= 0;
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
    /* every particle has one image per face it lies on: 2 N_a N_b places per axis pair of faces */
    CHECK(!bad_image && images == 2 * (n1 * n2 + n2 * n3 + n1 * n3));
    CHECK(worst_a < 1e-13 && !bad_pair && paired == faces && faces == 2 * ((n1 - 2) * (n2 - 2) + (n2 - 2) * (n3 - 2) +
                                                                   (n1 - 2) * (n3 - 2)));
    CHECK(fabs(f.V - L[0] * L[1] * L[2]) <= 1e-14 * f.V && test_frame_identity_error(&f) < 1e-14);
    printf("  frame3d: %d x %d x %d lattice: Q = %d, %d cells, |A - A by hand| / d^2 = %.1e, V %.6g m^3, "
           "|sum X (x) A - V I| / V = %.1e\n", n1, n2, n3, f.n, f.ncell, worst_a, f.V, test_frame_identity_error(&f));
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
        CHECK(fabs(f.V - det * V0) <= 1e-13 * f.V && test_frame_identity_error(&f) < 1e-13);
    }
    /* centres moved off their planes (by up to 5 % of d, deterministic): the
       quadrilaterals are no longer planar, the identity still holds */
    {
        unsigned long long s = 12345;
        double before = f.V;
        for (k = 0; k < 3 * f.n; ++k) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            f.X[k] += 0.05 * d * ((double)(s >> 11) / 9007199254740992.0 - 0.5);
        }
        sbc_frame_update_geometry(&f);
        CHECK(test_frame_identity_error(&f) < 1e-13 && fabs(f.V - before) < 0.1 * before);
        printf("  frame3d: %d x %d x %d lattice, centres moved by up to 2.5 %% of d: |sum X (x) A - V I| / V = %.1e\n",
               n1, n2, n3, test_frame_identity_error(&f));
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
    sbc_confine c;
    static const double in[][3] = {{1.5, 1.5, 1.5}, {0.01, 0.01, 0.01}, {2.99, 1.0, 2.0}, {1.0, 1.0, 1.0}};
    static const double out[][3] = {{-0.01, 1.5, 1.5}, {3.01, 1.0, 1.0}, {1.0, 1.0, 3.5}, {4.0, 4.0, 4.0}};
    sbc_frame f;
    sbc_error err;
    int k, ok_in = 1, ok_out = 1;
    cubic(4, 4, 4, d, x, r);
    CHECK(sbc_frame_detect_3d(&f, 64, x, r, 0.0, &err) == SBC_OK);
    for (k = 0; k < f.n; ++k)
        memcpy(&fx[3 * k], &f.X[3 * k], sizeof(double) * 3);
    sbc_confine_prepare(&c, &f, fx);
    CHECK(c.inner == 1 && c.in_lo[0] == 0.0 && c.in_hi[2] == 3.0); /* the open box (0, 3)^3 */
    for (k = 0; k < 4; ++k) {
        ok_in &= sbc_confine_inside(&c, in[k]);
        ok_out &= !sbc_confine_inside(&c, out[k]);
    }
    CHECK(ok_in && ok_out);
    /* the prepared boxes decide as the full test does, on a sheared frame too: a grid of points through it */
    for (k = 0; k < f.n; ++k)
        fx[3 * k] += 0.4 * f.X[3 * k + 2] - 0.2 * f.X[3 * k + 1];
    sbc_confine_prepare(&c, &f, fx);
    {
        int i, j, l, same = 1, inside_count = 0;
        for (i = -2; i <= 22; ++i)
            for (j = -2; j <= 17; ++j)
                for (l = -2; l <= 17; ++l) {
                    const double p[3] = {0.21 * i - 1.0, 0.2 * j + 0.013, 0.2 * l + 0.007};
                    const int fast = sbc_confine_inside(&c, p), full = sbc_frame_geometry_of(3)->inside(&f, fx, p);
                    same &= fast == full;
                    inside_count += full;
                }
        CHECK(same && inside_count > 1000);
    }
    memcpy(fx, f.X, sizeof(double) * 3 * (size_t)f.n);
    sbc_confine_prepare(&c, &f, fx);
    CHECK(sbc_confine_check(&c, 2, 7, out[1], v, &err) == SBC_ERR_GEOMETRY &&
          strstr(err.message, "interior particle 7 escaped") && strstr(err.message, "(3.01, 1, 1) m is outside the "
                                                                                  "polyhedron"));
    /* the controller takes a 3D frame under 3D words, and (P) where every family is whole */
    {
        static const char *words2[] = {"D", "F", "1.01", "0", "0", "1"}, *wordsP[] = {"P"};
        int member[8], saved, a = 0;
        sbc_settings s;
        double mass[64];
        for (k = 0; k < 64; ++k)
            mass[k] = 1.0;
        CHECK(sbc_settings_parse(&s, 6, words2, &err) == SBC_OK);
        CHECK(sbc_controller_create(&f, &s, mass, 1e-6, 1e4, &err) == NULL &&
              strstr(err.message, "a frame of dimension 3 under words of dimension 2"));
        CHECK(sbc_settings_parse(&s, 1, wordsP, &err) == SBC_OK && sbc_settings_check_dimension(&s, 3, &err) == SBC_OK);
        CHECK(sbc_frame_family(&f, f.corner[0], member) == 8 && member[7] == f.corner[7] &&
              sbc_frame_family(&f, f.corner[7], member) == 0);
        while (a < 2 && f.image[3 * (f.n - 1) + a] < 0)
            ++a;
        saved = f.image[3 * (f.n - 1) + a];
        f.image[3 * (f.n - 1) + a] = -1; /* the last face particle loses its image */
        CHECK(sbc_frame_family(&f, f.n - 1, member) == -1);
        CHECK(sbc_controller_create(&f, &s, mass, 1e-6, 1e4, &err) == NULL &&
              strstr(err.message, "servo_bc P: frame particle 55 (packing index") &&
              strstr(err.message, "has no periodic image on an opposite face"));
        f.image[3 * (f.n - 1) + a] = saved;
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
    CHECK(n == 2 + 10 * (size_t)f.n + 9 + 1 + 4 * (size_t)f.ncell + 3 * (size_t)f.n);
    state = malloc(sizeof(double) * n);
    sbc_frame_save(&f, state);
    CHECK(sbc_frame_load(&g, state, n, &err) == SBC_OK);
    CHECK(g.dim == 3 && g.n == f.n && g.V == f.V && g.ncell == f.ncell &&
          memcmp(g.X, f.X, sizeof(double) * 3 * (size_t)f.n) == 0 &&
          memcmp(g.A, f.A, sizeof(double) * 3 * (size_t)f.n) == 0 &&
          memcmp(g.side, f.side, sizeof(int) * (size_t)f.n) == 0 &&
          memcmp(g.partner, f.partner, sizeof(int) * (size_t)f.n) == 0 &&
          memcmp(g.corner, f.corner, sizeof f.corner) == 0 && memcmp(g.cell, f.cell, sizeof(int) * 4 * (size_t)f.ncell) == 0 &&
          memcmp(g.image, f.image, sizeof(int) * 3 * (size_t)f.n) == 0);
    sbc_frame_free(&g);
    CHECK(sbc_frame_load(&g, state, n - 1, &err) == SBC_ERR_INPUT && strstr(err.message, "3D frame of 96 particles"));
    state[n - 1 - 3 * (size_t)f.n] = f.n; /* a cell corner past the frame */
    CHECK(sbc_frame_load(&g, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "cell corner"));
    sbc_frame_save(&f, state);
    state[n - 3 * (size_t)f.n] = f.image[1]; /* corner 0's image across x: corner 0's image across y */
    CHECK(sbc_frame_load(&g, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "image"));
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
          strstr(err.message, "servo_bc mixed: the packing is 3D but the words are 2D: give F with nine values"));
    CHECK(sbc_settings_check_dimension(&s, 4, &err) == SBC_ERR_INPUT && strstr(err.message, "dimension 4"));
}

/* a host of the driver for the lattice tests: spheres on a simple cubic
 * lattice with normal springs kn between nearest neighbours and, when kt >
 * 0, tangential springs kt on the part of their relative displacement from
 * the lattice normal to the line of centres (elastic: no sliding, no
 * rotation), FIRE or eq. 10 on the interior, the frame where the commands
 * put it. Central springs alone leave a simple cubic lattice without shear
 * stiffness, and with a prestress in compression its shear modes are
 * unstable; the tangential springs give it one. */
typedef struct springs {
    int n, npair, Q;
    int *pair;                  /* [2 npair] */
    double *x, *x0, *v, *f;     /* [3n] */
    unsigned char *frame;       /* [n] */
    const sbc_frame *fr;
    double R, kn, kt, m, dt, alpha;
    double ep, overlap, count, fsum;
} springs;

static void springs_forces(springs *h)
{
    int p, k;
    memset(h->f, 0, sizeof(double) * 3 * (size_t)h->n);
    h->ep = h->overlap = h->count = h->fsum = 0.0;
    for (p = 0; p < h->npair; ++p) {
        const int i = h->pair[2 * p], j = h->pair[2 * p + 1];
        double d[3], u[3], L, dn, un = 0.0, s2 = 0.0;
        for (k = 0; k < 3; ++k)
            d[k] = h->x[3 * j + k] - h->x[3 * i + k];
        L = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        dn = 2.0 * h->R - L;
        if (dn <= 0.0)
            continue;
        for (k = 0; k < 3; ++k) {
            u[k] = d[k] - (h->x0[3 * j + k] - h->x0[3 * i + k]);
            un += u[k] * d[k] / L;
        }
        for (k = 0; k < 3; ++k) {
            const double s = u[k] - un * d[k] / L; /* tangential relative displacement, m */
            h->f[3 * i + k] += -h->kn * dn * d[k] / L + h->kt * s;
            h->f[3 * j + k] -= -h->kn * dn * d[k] / L + h->kt * s;
            s2 += s * s;
        }
        h->ep += 0.5 * h->kn * dn * dn + 0.5 * h->kt * s2;
        h->overlap += dn / h->R;
        h->count += 1.0;
        h->fsum += sqrt(h->kn * dn * h->kn * dn + h->kt * h->kt * s2);
    }
}

static void springs_fire_sums(void *u, double *sums)
{
    const springs *h = u;
    const double zero[3] = {0.0, 0.0, 0.0}; /* no rotation */
    int i;
    for (i = 0; i < h->n; ++i)
        if (!h->frame[i])
            sbc_fire_add(sums, 3, &h->f[3 * i], &h->v[3 * i], zero, zero);
}

static void springs_interior(void *u, const sbc_fire_mix *mix, int again, double out[2])
{
    springs *h = u;
    double ek = 0.0, net = 0.0;
    int i, k;
    (void)again;
    for (i = 0; i < h->n; ++i) {
        double *v = &h->v[3 * i], *f = &h->f[3 * i];
        const double zero[3] = {0.0, 0.0, 0.0};
        if (h->frame[i])
            continue;
        net = fmax(net, f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        for (k = 0; k < 3; ++k) {
            if (mix)
                v[k] = sbc_fire_velocity(mix, sbc_fire_factor(mix->push, mix, h->dt / h->m), v[k], f[k]);
            else
                f[k] = sbc_damp_local(f[k], v[k], h->alpha);
            v[k] += h->dt * f[k] / h->m;
            h->x[3 * i + k] += h->dt * v[k];
        }
        if (f[0] != 0.0 || f[1] != 0.0 || f[2] != 0.0)
            ek += sbc_kinetic_energy(3, h->m, 0.0, v, zero);
    }
    out[0] = ek;
    out[1] = sqrt(net);
}

static void springs_contacts(void *u, double out[4])
{
    const springs *h = u;
    out[0] = h->ep, out[1] = h->overlap, out[2] = h->count, out[3] = h->fsum;
}

static void springs_frame(void *u, double *buf)
{
    const springs *h = u;
    int q, k;
    for (q = 0; q < h->Q; ++q)
        for (k = 0; k < 3; ++k) {
            buf[3 * q + k] = h->x[3 * h->fr->particle[q] + k];
            buf[3 * h->Q + 3 * q + k] = h->f[3 * h->fr->particle[q] + k];
        }
    buf[SBC_DRIVER_SUMS(3, h->Q) + 1] = h->n;
}

/* The boundary condition bc ("D", "P", "T") on an N^3 spring lattice (d 2
 * mm, radius R: 1.02 mm prestressed, 1 mm touching; kn 1e4 N/m, kt N/m)
 * under F (3 x 3 slots) in `increments` increments at preset accuracy,
 * through the host driver: the converged rows into rows [8]; returns their
 * count (-1 when the run failed, with the message printed) and the steps.
 * split > 0: after that many steps the controller's state and FIRE's are
 * saved, controller and driver freed, and new ones made from the saved
 * state go on (a restart). */
static int run_words(const char *text, int N, double R, double kt, const double shift[3], long split,
                     sbc_result rows[8], long *steps);

static int run_cubic(const char *bc, int N, double R, double kt, const double F[9], int increments,
                     const char *accuracy, long split, sbc_result rows[8], long *steps)
{
    static const double none[3] = {0.0, 0.0, 0.0};
    char text[512];
    snprintf(text, sizeof text, "%s F %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g increments %d accuracy %s",
             bc, F[0], F[1], F[2], F[3], F[4], F[5], F[6], F[7], F[8], increments, accuracy);
    return run_words(text, N, R, kt, none, split, rows, steps);
}

/* run_cubic with the words of text, the lattice translated by shift (m);
 * the springs host has no remap callback, so its words end in remap none */
static int run_words(const char *text, int N, double R, double kt, const double shift[3], long split,
                     sbc_result rows[8], long *steps)
{
    const double d = 2e-3, kn = 1e4;
    const int n = N * N * N;
    char line[512], *words[40];
    int nwords;
    springs h;
    sbc_frame f;
    sbc_settings s;
    sbc_error err;
    sbc_controller *c;
    sbc_driver *drv;
    sbc_driver_callbacks cb = {0};
    double *r = malloc(sizeof(double) * (size_t)n), *mass;
    sbc_event ev = SBC_EVENT_RELAXING;
    int i, j, q, nrows = 0;
    snprintf(line, sizeof line, "%s remap none", text);
    nwords = sbc_split_words(line, words, 40);
    memset(&h, 0, sizeof h);
    h.n = n, h.R = R, h.kn = kn, h.kt = kt, h.m = 1e-3, h.dt = 1e-5, h.alpha = 0.7;
    h.x = malloc(sizeof(double) * 3 * (size_t)n);
    h.x0 = malloc(sizeof(double) * 3 * (size_t)n);
    h.v = calloc(3 * (size_t)n, sizeof(double));
    h.f = calloc(3 * (size_t)n, sizeof(double));
    h.frame = calloc((size_t)n, 1);
    h.pair = malloc(sizeof(int) * 6 * (size_t)n);
    cubic(N, N, N, d, h.x, r);
    for (i = 0; i < 3 * n; ++i)
        h.x[i] += shift[i % 3];
    memcpy(h.x0, h.x, sizeof(double) * 3 * (size_t)n);
    for (i = 0; i < n; ++i) {
        r[i] = R;
        for (j = i + 1; j < n; ++j) {
            const double dx = h.x[3 * j] - h.x[3 * i], dy = h.x[3 * j + 1] - h.x[3 * i + 1], dz = h.x[3 * j + 2] - h.x[3 * i + 2];
            if (dx * dx + dy * dy + dz * dz < 1.5 * d * d) {
                h.pair[2 * h.npair] = i;
                h.pair[2 * h.npair++ + 1] = j;
            }
        }
    }
    CHECK(sbc_frame_detect_3d(&f, n, h.x, r, 0.0, &err) == SBC_OK);
    CHECK(sbc_settings_parse(&s, nwords, (const char *const *)words, &err) == SBC_OK && sbc_settings_check_dimension(&s, 3, &err) == SBC_OK);
    h.Q = f.n, h.fr = &f;
    mass = malloc(sizeof(double) * (size_t)f.n);
    for (q = 0; q < f.n; ++q) {
        h.frame[f.particle[q]] = 1;
        mass[q] = h.m;
    }
    c = sbc_controller_create(&f, &s, mass, h.dt, kn, &err);
    CHECK(c != NULL);
    cb.user_data = &h, cb.fire_sums = springs_fire_sums, cb.interior = springs_interior;
    cb.contacts = springs_contacts, cb.frame = springs_frame;
    drv = c ? sbc_driver_create(c, &s, &cb, &err) : NULL;
    for (*steps = 0; drv && ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED && *steps < 2000000; ++*steps) {
        sbc_commands cmd;
        springs_forces(&h);
        ev = sbc_driver_step(drv, 0, &err);
        cmd = sbc_controller_commands(c);
        for (q = 0; q < f.n; ++q)
            memcpy(&h.x[3 * f.particle[q]], &cmd.x[3 * q], sizeof(double) * 3);
        if ((ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) && nrows < 8)
            rows[nrows++] = *sbc_controller_result(c);
        if (*steps + 1 == split && ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED) {
            const size_t size = sbc_controller_state_size(c);
            double *state = malloc(sizeof(double) * size);
            const sbc_fire_state fire = *sbc_driver_fire(drv);
            sbc_controller_save(c, state);
            sbc_driver_free(drv);
            sbc_controller_free(c);
            c = sbc_controller_create(&f, &s, mass, h.dt, kn, &err);
            CHECK(c && sbc_controller_load(c, state, size, &err) == SBC_OK);
            drv = c ? sbc_driver_create(c, &s, &cb, &err) : NULL;
            if (drv)
                *sbc_driver_fire(drv) = fire;
            free(state);
        }
    }
    if (ev != SBC_EVENT_FINISHED) {
        printf("  %s\n", err.message);
        nrows = -1;
    }
    sbc_driver_free(drv);
    sbc_controller_free(c);
    sbc_frame_free(&f);
    free(mass);
    free(r);
    free(h.x), free(h.x0), free(h.v), free(h.f), free(h.frame), free(h.pair);
    return nrows;
}

/* (D) or (P) on the lattice with tangential springs kt = kn / 2 under F =
 * diag(0.999, 0.998, 0.997) at `tight`: the affine state stretches no
 * tangential spring, and every chain along axis i carries kn (2R - d F_ii),
 * so P_ii = -N^2 kn (2R - d F_ii) / ((N - 1)^2 d^2), off the diagonal 0;
 * under (P) the affine state is periodic (each family's forces cancel) and
 * in equilibrium, so the same */
static void lattice_prestressed(const char *bc, int N)
{
    const double d = 2e-3, R = 1.02e-3, kn = 1e4, F[9] = {0.999, 0, 0, 0, 0.998, 0, 0, 0, 0.997};
    sbc_result rows[8];
    long steps;
    const int nrows = run_cubic(bc, N, R, 0.5 * kn, F, 2, "tight", 0, rows, &steps);
    double worst = 0.0, hm = 0.0, Pmax = 0.0;
    int k, i, j;
    CHECK(nrows == 3);
    for (k = 0; k < nrows; ++k) {
        for (i = 0; i < 3; ++i)
            for (j = 0; j < 3; ++j) {
                const double Fii = rows[k].F[SBC_IJ(i, i)];
                const double expect = i == j ? -N * N * kn * (2.0 * R - d * Fii) / ((N - 1.0) * (N - 1.0) * d * d) : 0.0;
                worst = fmax(worst, fabs(rows[k].P[SBC_IJ(i, j)] - expect));
                Pmax = fmax(Pmax, fabs(expect));
            }
        hm = fmax(hm, fabs(rows[k].hill_mandel));
    }
    CHECK(worst <= 1e-6 * Pmax && hm <= 1e-6);
    printf("  frame3d: (%s) on a prestressed %d^3 lattice, F = diag(0.999, 0.998, 0.997), tight: %d rows in %ld steps, "
           "max |P - closed form| = %.1e of max |P| (%.4g N/m^2), |Hill-Mandel| %.1e\n",
           bc, N, nrows, steps, worst / Pmax, Pmax, hm);
}

/* (T) on a touching frictionless N^3 lattice under F = diag(1 - e1, 1 - e2,
 * 1) at `tight`: the frame's tractions are P A_q, so the chain along axis i
 * that ends at a node of area A_c carries P_ii A_c and shortens by (N - 1)
 * P_ii A_c / kn; eq. 15 gives F_ii = 1 + (N - 1) P_ii sum_c A_c^2 / (kn L^3)
 * with sum_c A_c^2 = d^4 ((N - 2)^2 + (N - 2) + 1/4) = d^4 (N - 3/2)^2 over
 * a face, L = (N - 1) d: P_ii = -kn e_i (N - 1)^2 / (d (N - 3/2)^2), P33 = 0
 * and off the diagonal 0. Chains of unequal force shift against their
 * neighbours, which tilts the lateral contacts: a second-order effect, of
 * relative size ~e. */
static void lattice_T(int N, double e1, double e2)
{
    const double d = 2e-3, R = 1e-3, kn = 1e4, F[9] = {1.0 - e1, 0, 0, 0, 1.0 - e2, 0, 0, 0, 1.0};
    const double e[3] = {e1, e2, 0.0};
    sbc_result rows[8];
    long steps;
    const int nrows = run_cubic("T", N, R, 0.0, F, 2, "tight", 0, rows, &steps);
    double worst = 0.0, hm = 0.0, Pmax = 0.0, Pclosed[3];
    int k, i, j;
    CHECK(nrows == 3);
    for (i = 0; i < 3; ++i)
        Pclosed[i] = -kn * e[i] * (N - 1.0) * (N - 1.0) / (d * (N - 1.5) * (N - 1.5));
    if (nrows != 3)
        return;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            const double expect = i == j ? Pclosed[i] : 0.0;
            worst = fmax(worst, fabs(rows[2].P[SBC_IJ(i, j)] - expect));
            Pmax = fmax(Pmax, fabs(expect));
        }
    for (k = 0; k < nrows; ++k)
        hm = fmax(hm, fabs(rows[k].hill_mandel));
    CHECK(worst <= 1e-5 * Pmax && hm <= 1e-6);
    printf("  frame3d: (T) on a touching frictionless %d^3 lattice, F = diag(1 - %g, 1 - %g, 1), tight: %ld steps, "
           "%d iterations, max |P - closed form| = %.1e of max |P| (%.4g N/m^2), |Hill-Mandel| %.1e\n",
           N, e1, e2, steps, rows[2].iterations, worst / Pmax, Pmax, hm);
}

/* The 3D layer (mixed: zlo D D D, zhi D D T, the side faces P P P) on a
 * touching 4^3 lattice (tangential springs kt = kn / 2, which the
 * compression does not load: they give the shear stage a stiffness) under
 * P33* = -1e4 N/m^2 in 2 increments,
 * then F13 = 0.01 in 2: stage 1 ends at F33 = 1 - p d (N - 3/2)^2 / (kn (N -
 * 1)^2) (the columns under the top's edges and corners carry a half and a
 * quarter of a column's load, as the side columns of the 2D layer carry half:
 * sum over the top's nodes of A_c^2 = d^4 (N - 3/2)^2, and the lateral
 * contacts stay at zero overlap); the shear stage keeps P33 = P33*;
 * Hill-Mandel holds at every increment; the layer translated by (2^-7,
 * XX
 * own tolerance does not hide a 1e-9 difference. */
static void layer_3d(void)
{
    static const char *const words = "mixed F 1 0 0.01 0 1 0 0 0 1 increments 2 stress P33 -1e4 2 accuracy tight "
                                     "tol_relative 1e-10";
    const double none[3] = {0.0, 0.0, 0.0}, shift[3] = {0.0078125, 0.015625, 0.03125}, N = 4.0, d = 2e-3, kn = 1e4;
    const double p = 1e4, F33 = 1.0 - p * d * (N - 1.5) * (N - 1.5) / (kn * (N - 1.0) * (N - 1.0));
    sbc_result rows[2][8];
    long steps[2];
    const int n0 = run_words(words, 4, 1e-3, 0.5 * kn, none, 0, rows[0], &steps[0]);
    const int n1 = run_words(words, 4, 1e-3, 0.5 * kn, shift, 0, rows[1], &steps[1]);
    double worst = 0.0, hm = 0.0;
    int k, c;
    CHECK(n0 == 5 && n1 == 5);
    if (n0 != 5 || n1 != 5)
        return;
    CHECK(fabs(rows[0][2].F[8] - F33) <= 1e-9 * (1.0 - F33) && fabs(rows[0][2].P[8] + p) <= 1e-9 * p);
    CHECK(fabs(rows[0][3].P[8] + p) <= 1e-4 * p && fabs(rows[0][4].P[8] + p) <= 1e-4 * p);
    CHECK(fabs(rows[0][4].F[2] - 0.01) <= 1e-12);
    for (k = 0; k < 5; ++k) {
        hm = fmax(hm, fabs(rows[0][k].hill_mandel));
        for (c = 0; c < 9; ++c) /* F and P, against 1 and the stress scale p */
            worst = fmax(worst, fmax(fabs(rows[0][k].F[c] - rows[1][k].F[c]),
                                     fabs(rows[0][k].P[c] - rows[1][k].P[c]) / p));
    }
    CHECK(hm <= 1e-6 && worst <= 1e-9);
    printf("  frame3d: 3D layer on a touching 4^3 lattice: 1 - F33 = %.9e after the stress stage (closed form %.9e), "
           "P33 %.9f N/m^2 there and %.6f at F13 = 0.01, Hill-Mandel <= %.1e, translated layer %.1e apart, %ld "
           "steps\n", 1.0 - rows[0][2].F[8], 1.0 - F33, rows[0][2].P[8], rows[0][4].P[8], hm, worst, steps[0]);
}

/* restart in 3D: (P) and (T) runs split within an increment's servo
 * iterations and continued by a new controller and driver from the saved
 * state give the rows of the whole run, bit for bit */
static void restart_split(const char *bc, double R, double kt, const double F[9], long split)
{
    sbc_result whole[8], parts[8];
    long s1, s2;
    const int n1 = run_cubic(bc, 4, R, kt, F, 2, "tight", 0, whole, &s1);
    const int n2 = run_cubic(bc, 4, R, kt, F, 2, "tight", split, parts, &s2);
    int k, same = n1 == 3 && n2 == 3 && s1 == s2;
    for (k = 0; same && k < n1; ++k)
        same = memcmp(whole[k].P, parts[k].P, sizeof whole[k].P) == 0 &&
               memcmp(whole[k].F, parts[k].F, sizeof whole[k].F) == 0 && whole[k].iterations == parts[k].iterations;
    CHECK(split < s1 && same);
    printf("  frame3d: (%s) restarted at step %ld of %ld: the %d rows bit for bit\n", bc, split, s1, n2);
}

/* objectivity: (D) or (P) on the frictionless prestressed lattice under F =
 * Q diag(0.999, 0.998, 0.997), Q a rotation (20 degrees about z after 10
 * about x), at `balanced` gives Q P(diag) to 1e-4 of max |P| */
static void objectivity(const char *bc, int N)
{
    const double R = 1.02e-3;
    const double D[9] = {0.999, 0, 0, 0, 0.998, 0, 0, 0, 0.997}, a = 20.0 * 3.14159265358979323846 / 180.0, b = 10.0 * 3.14159265358979323846 / 180.0;
    const double Rz[9] = {cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1}, Rx[9] = {1, 0, 0, 0, cos(b), -sin(b), 0, sin(b), cos(b)};
    double Qr[9], F[9], QP[9], worst = 0.0, Pmax = 0.0;
    sbc_result diag[8], turned[8];
    long s1, s2;
    int i, j, k, n1, n2;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            Qr[3 * i + j] = 0.0;
            for (k = 0; k < 3; ++k)
                Qr[3 * i + j] += Rz[3 * i + k] * Rx[3 * k + j];
        }
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j)
            F[3 * i + j] = Qr[3 * i + j] * D[3 * j + j];
    n1 = run_cubic(bc, N, R, 0.0, D, 1, "balanced", 0, diag, &s1);
    n2 = run_cubic(bc, N, R, 0.0, F, 4, "balanced", 0, turned, &s2);
    CHECK(n1 == 2 && n2 == 5);
    if (n1 != 2 || n2 != 5)
        return;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            QP[3 * i + j] = 0.0;
            for (k = 0; k < 3; ++k)
                QP[3 * i + j] += Qr[3 * i + k] * diag[1].P[3 * k + j];
            Pmax = fmax(Pmax, fabs(diag[1].P[3 * i + j]));
        }
    for (k = 0; k < 9; ++k)
        worst = fmax(worst, fabs(turned[4].P[k] - QP[k]));
    CHECK(worst <= 1e-4 * Pmax);
    printf("  frame3d: objectivity, (%s) under Q diag(0.999, 0.998, 0.997) (Q: 20 deg about z after 10 about x), "
           "balanced: max |P - Q P(diag)| = %.1e of max |P| (%ld and %ld steps)\n", bc, worst / Pmax, s1, s2);
}

/* the results file's columns in 3D (columns.h): nine components of F, P
 * and sigma, row-major, then the 2D file's trailing columns */
static void columns(void)
{
    static const char *const head3 =
        "increment,F11,F12,F13,F21,F22,F23,F31,F32,F33,P11,P12,P13,P21,P22,P23,P31,P32,P33,sigma11,sigma12,sigma13,"
        "sigma21,sigma22,sigma23,sigma31,sigma32,sigma33,overlap_mean,rotation_mean,iterations,relax_steps,r_force,"
        "r_moment,r_deformation,unbalanced,frame_residual,hill_mandel,newton_iterations,newton_held";
    char line[2048];
    double v[SBC_COLUMNS];
    sbc_result r;
    int k, n;
    memset(&r, 0, sizeof r);
    r.dim = 3;
    r.increment = 4;
    for (k = 0; k < 9; ++k)
        r.F[k] = 1.0 + k, r.P[k] = 10.0 + k, r.sigma[k] = 20.0 + k;
    r.hill_mandel = -1e-9;
    CHECK(sbc_column_count(2) == SBC_COLUMNS_2D && sbc_column_count(3) == SBC_COLUMNS);
    n = sbc_columns_header(3, line, sizeof line);
    CHECK(n == (int)strlen(head3) && strcmp(line, head3) == 0);
    r.newton_iterations = 7;
    r.newton_held = 3;
    CHECK(sbc_column_values(&r, v) == 40 && v[0] == 4.0 && v[3] == 3.0 && v[9] == 9.0 && v[12] == 12.0 &&
          v[27] == 28.0 && v[37] == -1e-9 && v[38] == 7.0 && v[39] == 3.0);
    CHECK(sbc_column_index(3, "F13") == 3 && sbc_column_index(2, "F13") == -1 && sbc_column_index(2, "F21") == 3 &&
          strcmp(sbc_column_name(3, 37), "hill_mandel") == 0 && strcmp(sbc_column_name(3, 38), "newton_iterations") == 0 &&
          strcmp(sbc_column_name(3, 39), "newton_held") == 0 && sbc_column_name(3, 40) == NULL);
}

void test_frame_3d(void)
{
    columns();
    lattice_prestressed("D", 4);
    lattice_prestressed("P", 4);
    lattice_T(4, 2e-6, 1e-6);
    layer_3d();
    {
        const double prestressed[9] = {0.999, 0, 0, 0, 0.998, 0, 0, 0, 0.997};
        const double touching[9] = {1.0 - 2e-6, 0, 0, 0, 1.0 - 1e-6, 0, 0, 0, 1.0};
        restart_split("P", 1.02e-3, 5e3, prestressed, 1700);
        restart_split("T", 1e-3, 0.0, touching, 1200);
    }
    objectivity("D", 4);
    objectivity("P", 4);
    words();
    saved();
    lattice(3, 3, 3);
    lattice(4, 5, 6);
    lattice(10, 10, 10);
    inside();
    refused();
}
