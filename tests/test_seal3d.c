/* The frame's seal in 3D (seal.h): walls on the triangles of the frame's
 * surface. The wall force and its split against closed forms on the faces
 * of a cube, forces as the gradient of the wall energy (the frame's corners
 * included), the host handle (YADE's way in), and a column of spheres
 * squeezed between two walls through the runner, to its closed form. */
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/embedded/script.h"
#include "sbc/frame.h"
#include "sbc/host.h"
#include "sbc/packing.h"
#include "sbc/seal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the eight corners of a cube of side L (radius L / 10), in the order
   x fastest, then y, then z */
static void corners(double L, double x[24], double r[8])
{
    int c;
    for (c = 0; c < 8; ++c) {
        x[3 * c] = (c & 1) ? L : 0.0;
        x[3 * c + 1] = (c & 2) ? L : 0.0;
        x[3 * c + 2] = (c & 4) ? L : 0.0;
        r[c] = 0.1 * L;
    }
}

static int never_frame(const void *ctx, int k) { (void)ctx; (void)k; return -1; }

/* wall energy and forces of one sphere of radius r at p against the
   frame's centres fx [3Q]; reaction [3Q] */
static double wall(const sbc_frame *f, const double *fx, const double p[3], double r, double kn, double force[3],
                   double *reaction)
{
    sbc_seal s;
    sbc_seal_particles pt;
    sbc_error err;
    double e = -1.0;
    memset(force, 0, sizeof(double) * 3);
    memset(reaction, 0, sizeof(double) * 3 * (size_t)f->n);
    pt.n = 1;
    pt.x = p;
    pt.f = force;
    pt.stride = 3;
    pt.r = &r;
    pt.frame = never_frame;
    pt.ctx = NULL;
    if (sbc_seal_init(&s, f, 0.25 * r, &err) == SBC_OK)
        sbc_seal_forces(&s, f, fx, &pt, kn, 1, reaction, &e, &err);
    sbc_seal_free(&s);
    return e;
}

/* Near each face of the unit cube, at (0.3, 0.2) of the face and s = 0.3 w r
 * inside: kn (w r - s) along the inward normal, energy kn (w r - s)^2 / 2; the
 * corners' reactions add up to minus the force, each pushes outward, and
 * their weights put the wall point at the sphere's projection (no moment).
 * Beyond the wall, or beyond an edge of the cube, nothing; a centre that has
 * crossed the face is pushed back in. */
static void closed_form(void)
{
    const double L = 1.0, r = 0.05, kn = 1e4, w = SBC_SEAL_WALL * r, s = 0.3 * w, fn = kn * (w - s);
    double x[24], rad[8], p[3], f[3], R[24], e;
    sbc_frame fr;
    sbc_error err;
    int axis, high;
    corners(L, x, rad);
    memset(&fr, 0, sizeof fr);
    CHECK(sbc_frame_detect_3d(&fr, 8, x, rad, 0.0, &err) == SBC_OK && fr.n == 8);
    if (fr.n != 8)
        return;
    for (axis = 0; axis < 3; ++axis)
        for (high = 0; high < 2; ++high) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const double in = high ? -1.0 : 1.0; /* the inward normal along axis */
            double sum[3] = {0, 0, 0}, at[3] = {0, 0, 0}, out = 1.0;
            int q, k;
            p[u] = 0.3 * L;
            p[v] = 0.2 * L;
            p[axis] = high ? L - s : s;
            e = wall(&fr, fr.X, p, r, kn, f, R);
            CHECK_REL(f[axis], in * fn, 1e-12);
            CHECK_ABS(f[u], 0.0, 1e-12 * fn);
            CHECK_ABS(f[v], 0.0, 1e-12 * fn);
            CHECK_REL(e, 0.5 * fn * (w - s), 1e-12);
            for (q = 0; q < 8; ++q) {
                for (k = 0; k < 3; ++k) {
                    sum[k] += R[3 * q + k];
                    at[k] += fr.X[3 * q + k] * R[3 * q + axis];
                }
                out = fmin(out, -in * R[3 * q + axis]);
            }
            for (k = 0; k < 3; ++k)
                CHECK_ABS(sum[k] + f[k], 0.0, 1e-12 * fn);
            CHECK(out >= 0.0); /* every corner pushed outward or not at all */
            CHECK_ABS(at[u] / -(in * fn), p[u], 1e-12 * L);
            CHECK_ABS(at[v] / -(in * fn), p[v], 1e-12 * L);
            p[axis] = high ? L - 1.01 * w : 1.01 * w;
            CHECK(wall(&fr, fr.X, p, r, kn, f, R) == 0.0 && f[axis] == 0.0);
            p[axis] = high ? L + 0.01 * L : -0.01 * L; /* beyond an edge of the cube: off every face */
            p[u] = -0.01 * L;
            CHECK(wall(&fr, fr.X, p, r, kn, f, R) == 0.0 && f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0);
            p[u] = 0.3 * L;
            p[axis] = high ? L + 0.2 * r : -0.2 * r;
            wall(&fr, fr.X, p, r, kn, f, R);
            CHECK_REL(f[axis], in * kn * (w + 0.2 * r), 1e-12);
        }
    sbc_frame_free(&fr);
}

/* the forces are minus the gradient of the wall energy in every coordinate,
 * the corners' included: the split does the work of the wall force */
static void energy_gradient(void)
{
    static const double shake[24] = {0.01, -0.02, 0.015, 1.03, 0.04, -0.01, -0.02, 0.97, 0.02, 0.98, 1.02, -0.03,
                                     0.02, -0.01, 1.01, 0.99, 0.03, 0.98, 0.01, 1.02, 1.03, 1.01, 0.97, 0.99};
    const double r = 0.05, kn = 1e4, h = 1e-7, p0[3] = {0.63, 0.31, 0.01};
    double x[24], rad[8], f[3], R[24], fp[3], Rp[24], e0;
    sbc_frame fr;
    sbc_error err;
    int c;
    corners(1.0, x, rad);
    memset(&fr, 0, sizeof fr);
    CHECK(sbc_frame_detect_3d(&fr, 8, x, rad, 0.0, &err) == SBC_OK && fr.n == 8);
    if (fr.n != 8)
        return;
    {
        double fx0[24];
        int q, k;
        for (q = 0; q < 8; ++q) /* the corners moved off the cube, kept in frame order */
            for (k = 0; k < 3; ++k)
                fx0[3 * q + k] = shake[3 * fr.particle[q] + k];
        e0 = wall(&fr, fx0, p0, r, kn, f, R);
        CHECK(e0 > 0.0 && f[2] > 0.0);
        for (c = 0; c < 27; ++c) {
            double fx[24], p[3], ep, em;
            memcpy(fx, fx0, sizeof fx);
            memcpy(p, p0, sizeof p);
            if (c < 3) p[c] += h; else fx[c - 3] += h;
            ep = wall(&fr, fx, p, r, kn, fp, Rp);
            memcpy(fx, fx0, sizeof fx);
            memcpy(p, p0, sizeof p);
            if (c < 3) p[c] -= h; else fx[c - 3] -= h;
            em = wall(&fr, fx, p, r, kn, fp, Rp);
            CHECK_ABS(c < 3 ? f[c] : R[c - 3], -(ep - em) / (2.0 * h), 1e-6 * kn * r);
        }
    }
    sbc_frame_free(&fr);
}

/* The host handle in 3D: the column packing (inputs/compare/seal_column_3d.txt:
 * the cube's corners, side 7.1 mm, and four spheres of 1 mm along z), its
 * bottom sphere lowered to 0.3 r over the bottom face: kn (r/2 - 0.3 r)
 * upwards on it, the same downwards shared by the four bottom corners, none
 * before it is lowered, none without the keyword. */
static void host_handle(void)
{
    const double r = 1e-3, kn = 1e4, L = 7.1e-3, m = 2650 * 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
    double x[36], rad[12], mass[12], f[36], e, down;
    int k, sealed, list[1] = {0};
    char msg[256];
    corners(L, x, rad);
    for (k = 0; k < 12; ++k) {
        if (k >= 8) {
            x[3 * k] = L / 3.0;
            x[3 * k + 1] = L / 4.0;
            x[3 * k + 2] = 0.55e-3 + 2e-3 * (k - 8);
        }
        rad[k] = r;
        mass[k] = m;
    }
    for (sealed = 0; sealed < 2; ++sealed) {
        sbc_host *h = sbc_host_create(sealed ? "D F 1 0 0 0 1 0 0 0 0.99 seal yes" : "D F 1 0 0 0 1 0 0 0 0.99", 3, 12,
                                      x, rad, mass, 0, list, 1e-5, kn, msg, sizeof msg);
        CHECK(h != NULL);
        if (!h) {
            printf("  seal3d: %s\n", msg);
            continue;
        }
        CHECK(sbc_host_sealed(h) == sealed);
        CHECK(sbc_host_seal(h, x, f, &e) == 0 && f[3 * 8 + 2] == 0.0 && e == 0.0);
        x[3 * 8 + 2] = 0.3 * r;
        CHECK(sbc_host_seal(h, x, f, &e) == sealed);
        CHECK_REL(f[3 * 8 + 2], sealed ? kn * 0.2 * r : 0.0, 1e-12);
        CHECK_ABS(f[3 * 8], 0.0, 1e-12 * kn * r);
        down = 0.0;
        for (k = 0; k < 4; ++k)
            down += f[3 * k + 2];
        CHECK_REL(down, sealed ? -kn * 0.2 * r : 0.0, 1e-12);
        CHECK_REL(e, sealed ? 0.5 * kn * 0.04 * r * r : 0.0, 1e-12);
        x[3 * 8 + 2] = 0.55e-3;
        sbc_host_free(h);
    }
}

/* The column through the runner (inputs/compare/seal_column_3d.sbc, in every
 * host through tests/cross_host.sh): four spheres of r = 1 mm along z, 0.05
 * mm short of both walls (which stand at r/2 from the faces), in a cube of
 * L = 7.1 mm. Under (D) F33 = 1 - eps the walls close the gaps g and the
 * five springs in series (two walls, three contacts, kn each) carry P = kn
 * (eps L - 2 g) / 5: sigma33 = -P / L^2 (P33 F33 / J = P33), -257.885 and
 * -4483.24 N/m^2 at eps = 0.015 and 0.03; without the seal the column
 * touches nothing. */
static void column(void)
{
    static double rows[4][SBC_COLUMNS];
    const double kn = 1e4, L = 7.1e-3, g = 0.05e-3;
    char csv[512], script[2048];
    sbc_error err;
    int sealed, i;
    for (sealed = 0; sealed < 2; ++sealed) {
        snprintf(csv, sizeof csv, "%s/seal_column_%d.csv", test_tmpdir, sealed);
        snprintf(script, sizeof script,
                 "dimension 3\nread_packing inputs/compare/seal_column_3d.txt\n"
                 "contact frictional kn 1e4 ks 5e3 mu 0.5\ndensity 2650\ntimestep 1e-5\n"
                 "servo_bc D F 1 0 0 0 1 0 0 0 0.97 increments 2 accuracy tight seal %s file %s\nrun\n",
                 sealed ? "yes" : "no", csv);
        CHECK(sbc_script_run_string(script, "seal_column", NULL, &err) == SBC_OK);
        if (csv_read_3d(csv, rows, 4) != 3) {
            CHECK(0);
            continue;
        }
        for (i = 1; i < 3; ++i) {
            const double eps = 0.015 * i, want = sealed ? -kn * (eps * L - 2.0 * g) / 5.0 / (L * L) : 0.0;
            CHECK_ABS(rows[i][COL3("sigma33")], want, 1e-7 * 4483.0);
            CHECK_ABS(rows[i][COL3("sigma11")], 0.0, 1e-9 * 4483.0);
            CHECK_ABS(rows[i][COL3("sigma13")], 0.0, 1e-9 * 4483.0);
            CHECK_ABS(rows[i][COL3("sigma23")], 0.0, 1e-9 * 4483.0);
            CHECK(fabs(rows[i][COL3("hill_mandel")]) <= 1e-6);
        }
    }
}

/* +1 when the triangle v [3] (frame positions, as stored) faces out of the
   box along the axis of the face its corners lie on, -1 into it, 0 when
   they share no face */
static int facing(const sbc_frame *f, const int v[3])
{
    double u[3], w[3], m[3];
    int k, axis;
    for (k = 0; k < 3; ++k) {
        u[k] = f->X[3 * v[1] + k] - f->X[3 * v[0] + k];
        w[k] = f->X[3 * v[2] + k] - f->X[3 * v[0] + k];
    }
    sbc_cross3(u, w, m);
    for (axis = 0; axis < 3; ++axis)
        for (k = 0; k < 2; ++k)
            if (f->side[v[0]] & f->side[v[1]] & f->side[v[2]] & (1 << (2 * axis + k)))
                return (k ? m[axis] : -m[axis]) > 0.0 ? 1 : -1;
    return 0;
}

/* Generated irregular packings (tests/packings): the seal leaves them as
 * they are (no wall touches a sphere at the reference centres, frame
 * spheres included), and its walls are the surface's triangles but those
 * facing into the box (2 of 100 triangles in the first packing, none in
 * the others; docs/frame3d.md). */
static void reference_still(void)
{
    static const char *const paths[3] = {"tests/packings/irregular24_strain.txt", "tests/packings/irregular24_pd2.txt",
                                         "tests/packings/irregular30_touching.txt"};
    int i;
    for (i = 0; i < 3; ++i) {
        sbc_frame fr;
        sbc_seal sl;
        sbc_seal_particles pt;
        sbc_error err;
        double *x = NULL, *r = NULL, *f = NULL, *R = NULL, centre[3] = {0, 0, 0}, e = -1.0, rmin = 1.0;
        int n = 0, k, c, t, inward = 0, triangles = 0, *slot = NULL, out_ok = 1;
        memset(&fr, 0, sizeof fr);
        CHECK(sbc_spheres_read(paths[i], &n, &x, &r, &err) == SBC_OK);
        CHECK(n > 0 && sbc_frame_detect_3d(&fr, n, x, r, 0.0, &err) == SBC_OK);
        f = calloc(3 * (size_t)(n > 0 ? n : 1), sizeof(double));
        R = calloc(3 * (size_t)(fr.n > 0 ? fr.n : 1), sizeof(double));
        slot = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
        if (fr.n == 0 || !f || !R || !slot) {
            free(x); free(r); free(f); free(R); free(slot);
            sbc_frame_free(&fr);
            continue;
        }
        for (k = 0; k < n; ++k) {
            slot[k] = -1;
            rmin = fmin(rmin, r[k]);
        }
        for (k = 0; k < fr.n; ++k) {
            slot[fr.particle[k]] = k;
            for (c = 0; c < 3; ++c)
                centre[c] += fr.X[3 * k + c] / fr.n;
        }
        /* the triangles facing into the box: the normal's component along
           the axis of the face all three corners lie on points inward */
        for (c = 0; c < fr.ncell; ++c)
            for (t = 0; t < (fr.cell[4 * c + 3] == fr.cell[4 * c] ? 1 : 2); ++t) {
                const int v[3] = {fr.cell[4 * c], fr.cell[4 * c + 1 + t], fr.cell[4 * c + 2 + t]};
                inward += facing(&fr, v) < 0;
                ++triangles;
            }
        CHECK(sbc_seal_init(&sl, &fr, 0.25 * rmin, &err) == SBC_OK);
        CHECK(sl.nwall == triangles - inward);
        for (t = 0; t < sl.nwall; ++t)
            out_ok &= facing(&fr, &sl.corner[3 * t]) > 0;
        CHECK(out_ok);
        pt = sbc_seal_packed(n, x, f, 3, r, slot);
        CHECK(sbc_seal_forces(&sl, &fr, fr.X, &pt, 1e4, 1, R, &e, &err) == SBC_OK);
        CHECK(sl.contacts == 0 && e == 0.0);
        printf("  seal3d: %s: %d walls of %d triangles, none touching a sphere at the reference centres\n", paths[i],
               sl.nwall, triangles);
        sbc_seal_free(&sl);
        sbc_frame_free(&fr);
        free(x); free(r); free(f); free(R); free(slot);
    }
}

void test_seal_3d(void)
{
    reference_still();
    closed_form();
    energy_gradient();
    host_handle();
    column();
}
