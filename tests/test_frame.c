/* Frame geometry (Sect. 2.1, eq. 2). */
#include "check.h"
#include "tests.h"

#include "sbc/confine.h"
#include "servo/geometry.h"
#include "sbc/frame.h"
#include "sbc/packing.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double signed_area(const sbc_frame *f)
{
    double a = 0.0;
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *p = &f->X[3 * q], *r = &f->X[3 * ((q + 1) % f->n)];
        a += 0.5 * (p[0] * r[1] - r[0] * p[1]);
    }
    return a;
}

static void lattice_frame(void)
{
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    int q, counts[5] = {0, 0, 0, 0, 0};
    double cx = 4e-3, cy = 4e-3, sum[2] = {0.0, 0.0};
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_OK);
    CHECK(f.n == 16);                          /* outer ring of a 5 x 5 lattice */
    CHECK_REL(f.V, 64e-6, 1e-12);              /* paper: V = 64 mm^2 for 25 particles */
    CHECK(signed_area(&f) > 0.0);              /* anticlockwise */
    CHECK(f.particle[f.corner[SBC_CORNER_BL]] == 0);
    CHECK(f.particle[f.corner[SBC_CORNER_BR]] == 4);
    CHECK(f.particle[f.corner[SBC_CORNER_TR]] == 24);
    CHECK(f.particle[f.corner[SBC_CORNER_TL]] == 20);
    for (q = 0; q < f.n; ++q) {
        const double *A = &f.A[3 * q], *X = &f.X[3 * q];
        int qm = (q + f.n - 1) % f.n, qp = (q + 1) % f.n;
        counts[f.side[q]]++;
        sum[0] += A[0];
        sum[1] += A[1];
        /* outward: A points away from the centre of the square */
        CHECK(A[0] * (X[0] - cx) + A[1] * (X[1] - cy) > 0.0);
        /* equal radii: A_q = (X_{q+1} - X_{q-1}) x e3 / 2 */
        CHECK_ABS(A[0], 0.5 * (f.X[3 * qp + 1] - f.X[3 * qm + 1]), 1e-18);
        CHECK_ABS(A[1], -0.5 * (f.X[3 * qp] - f.X[3 * qm]), 1e-18);
        /* periodic partners at exactly +/- L */
        if (f.side[q] == SBC_SIDE_BOTTOM) {
            int t = f.partner[q];
            CHECK(f.side[t] == SBC_SIDE_TOP && f.partner[t] == q);
            CHECK_ABS(f.X[3 * t] - X[0], 0.0, 1e-18);
            CHECK_ABS(f.X[3 * t + 1] - X[1], 8e-3, 1e-15);
        }
        if (f.side[q] == SBC_SIDE_RIGHT) {
            int t = f.partner[q];
            CHECK(f.side[t] == SBC_SIDE_LEFT && f.partner[t] == q);
            CHECK_ABS(f.X[3 * t + 1] - X[1], 0.0, 1e-18);
        }
        if (f.side[q] == SBC_SIDE_CORNER)
            CHECK(f.partner[q] == -1);
    }
    CHECK(counts[SBC_SIDE_CORNER] == 4 && counts[SBC_SIDE_BOTTOM] == 3 && counts[SBC_SIDE_RIGHT] == 3 &&
          counts[SBC_SIDE_TOP] == 3 && counts[SBC_SIDE_LEFT] == 3);
    CHECK_ABS(sum[0], 0.0, 1e-18);
    CHECK_ABS(sum[1], 0.0, 1e-18);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}

/* Polydisperse radii: the weights of eq. 2 still sum to one per chord, so
 * the area vectors of a closed frame sum to zero; each still points outward. */
static void polydisperse_frame(void)
{
    enum { N = 6 };
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    double sum[2] = {0.0, 0.0};
    int q, k;
    CHECK(sbc_packing_lattice_square(&p, N, N, 1.0, 0.55, &err) == SBC_OK);
    srand(7);
    for (k = 0; k < p.n; ++k)
        p.r[k] = 0.35 + 0.3 * rand() / (double)RAND_MAX;
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.2, &err) == SBC_OK);
    CHECK(f.n == 4 * (N - 1));
    for (q = 0; q < f.n; ++q) {
        const double *A = &f.A[3 * q], *X = &f.X[3 * q];
        sum[0] += A[0];
        sum[1] += A[1];
        CHECK(A[0] * (X[0] - 2.5) + A[1] * (X[1] - 2.5) > 0.0);
    }
    CHECK_ABS(sum[0], 0.0, 1e-14);
    CHECK_ABS(sum[1], 0.0, 1e-14);
    /* on the straight bottom edge, |A_q| = weighted share of both chords */
    q = f.corner[SBC_CORNER_BL] + 1;
    CHECK_REL(-f.A[3 * q + 1],
              f.R[q] / (f.R[q] + f.R[q - 1]) * 1.0 + f.R[q] / (f.R[q] + f.R[q + 1]) * 1.0, 1e-14);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}

static void frame_errors(void)
{
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    /* a second particle on the bottom-left corner */
    CHECK(sbc_packing_lattice_square(&p, 4, 4, 2e-3, 1.02e-3, &err) == SBC_OK);
    p.x[2 * 1] = 0.1e-3; /* particle 1 moved next to the corner: both on bottom and left bands */
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_ERR_FRAME);
    CHECK(strstr(err.message, "bottom-left corner") != NULL);
    sbc_packing_free(&p);
    /* a corner missing */
    CHECK(sbc_packing_lattice_square(&p, 4, 4, 2e-3, 1.02e-3, &err) == SBC_OK);
    p.x[2 * 15] -= 1.5e-3;
    p.x[2 * 15 + 1] -= 1.5e-3;
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_ERR_FRAME);
    CHECK(strstr(err.message, "corner") != NULL);
    sbc_packing_free(&p);
    /* too few particles */
    CHECK(sbc_packing_lattice_square(&p, 1, 3, 2e-3, 1.02e-3, &err) == SBC_OK);
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_ERR_FRAME);
    sbc_packing_free(&p);
}

/* confine.h on the 5 x 5 lattice (frame centres on the square [0, 8 mm]^2):
 * inside, escaped through a gap, thrown, non-finite; the frame's own centres
 * fx, not its reference X, define the polygon. */
static void confinement(void)
{
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    double fx[3 * 16], still[2] = {0.0, 0.0}, moving[2] = {0.0, -3.0}, nan_x[2];
    sbc_confine c, ref;
    int q;
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_OK && f.n == 16);
    memcpy(fx, f.X, sizeof fx);
    sbc_confine_prepare(&c, &f, fx);
    sbc_confine_prepare(&ref, &f, f.X);
    {
        const double centre[2] = {4e-3, 4e-3}, gap[2] = {3e-3, -0.4e-3}, far[2] = {4e-3, -0.02};
        CHECK(sbc_confine_check(&c, 3, 12, centre, still, &err) == SBC_OK);
        CHECK(sbc_confine_check(&c, 3, 12, gap, still, &err) == SBC_ERR_GEOMETRY &&
              strstr(err.message, "servo_bc: increment 3: interior particle 12 escaped through a gap between frame "
                                  "particles (its centre (0.003, -0.0004) m") &&
              strstr(err.message, "the results before increment 3 stand"));
        CHECK(sbc_confine_check(&c, 3, 12, far, moving, &err) == SBC_ERR_NUMERIC &&
              strstr(err.message, "interior particle 12 was thrown 0.02 m beyond the frame of width 0.008 m"));
        CHECK(sbc_confine_check(&c, 3, 12, far, still, &err) == SBC_ERR_GEOMETRY); /* at rest: escaped */
        for (q = 0; q < f.n; ++q) /* the frame sheared by 1 mm at the top: (0.4 mm, 7.6 mm) is now left of its left edge */
            fx[3 * q] += 1e-3 * f.X[3 * q + 1] / 8e-3;
        sbc_confine_prepare(&c, &f, fx); /* moved centres: prepared again */
        { /* the prepared boxes decide as the full polygon test does, on a grid through the sheared frame */
            int i, j, same = 1, inside = 0;
            for (i = -5; i <= 55; ++i)
                for (j = -5; j <= 45; ++j) {
                    const double pt[2] = {0.2e-3 * i + 0.013e-3, 0.2e-3 * j + 0.007e-3};
                    const int full = sbc_frame_geometry_of(2)->inside(&f, fx, pt);
                    same &= sbc_confine_inside(&c, pt) == full;
                    inside += full;
                }
            CHECK(same && c.inner == 1 && inside > 1000);
        }
        {
            const double corner[2] = {0.4e-3, 7.6e-3};
            CHECK(sbc_confine_check(&ref, 0, 1, corner, still, &err) == SBC_OK);
            CHECK(sbc_confine_check(&c, 0, 1, corner, still, &err) == SBC_ERR_GEOMETRY);
        }
        nan_x[0] = 4e-3;
        nan_x[1] = nan("");
        CHECK(sbc_confine_check(&c, 2, 5, nan_x, still, &err) == SBC_ERR_NUMERIC &&
              strstr(err.message, "increment 2: particle 5 has a non-finite position"));
    }
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}

void test_frame(void)
{
    lattice_frame();
    polydisperse_frame();
    frame_errors();
    confinement();
}
