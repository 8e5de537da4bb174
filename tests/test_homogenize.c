/* Homogenization: eqs. 15, 23, 30, 31, 42. */
#include "check.h"
#include "tests.h"

#include "sbc/frame.h"
#include "sbc/homogenize.h"
#include "sbc/packing.h"

#include <stdlib.h>

static void affine(const sbc_frame *f, const double F[4], double *x)
{
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[2 * q];
        x[2 * q] = F[0] * X[0] + F[1] * X[1];
        x[2 * q + 1] = F[2] * X[0] + F[3] * X[1];
    }
}

void test_homogenize(void)
{
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    double F[4], P[4], S[4], *x, *a;
    static const double I[4] = {1, 0, 0, 1};
    static const double Fa[4] = {1.1, 0.3, -0.2, 0.9};
    static const double P0[4] = {-3.0, 1.5, 0.7, -2.0};
    int q, k;

    CHECK(sbc_packing_lattice_square(&p, 7, 4, 1.5e-3, 0.8e-3, &err) == SBC_OK);
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_OK);
    x = malloc(sizeof(double) * 2 * (size_t)f.n);
    a = malloc(sizeof(double) * 2 * (size_t)f.n);

    /* eq. 15: F = I in the reference state */
    sbc_homogenize_F(&f, f.X, F);
    for (k = 0; k < 4; ++k)
        CHECK_ABS(F[k], I[k], 1e-14);
    /* eq. 15 reproduces an imposed affine map */
    affine(&f, Fa, x);
    sbc_homogenize_F(&f, x, F);
    for (k = 0; k < 4; ++k)
        CHECK_ABS(F[k], Fa[k], 1e-14);

    /* eq. 23 with uniform forces a_q = P0 A_q (eq. 21) returns P0 */
    for (q = 0; q < f.n; ++q) {
        a[2 * q] = P0[0] * f.A[2 * q] + P0[1] * f.A[2 * q + 1];
        a[2 * q + 1] = P0[2] * f.A[2 * q] + P0[3] * f.A[2 * q + 1];
    }
    sbc_homogenize_P(&f, a, P);
    for (k = 0; k < 4; ++k)
        CHECK_ABS(P[k], P0[k], 1e-12);
    /* eq. 23 by hand: a single force on one particle */
    for (k = 0; k < 2 * f.n; ++k)
        a[k] = 0.0;
    q = f.corner[2];
    a[2 * q] = 2.0;
    a[2 * q + 1] = -1.0;
    sbc_homogenize_P(&f, a, P);
    CHECK_REL(P[0], 2.0 * f.X[2 * q] / f.V, 1e-15);
    CHECK_REL(P[1], 2.0 * f.X[2 * q + 1] / f.V, 1e-15);
    CHECK_REL(P[2], -1.0 * f.X[2 * q] / f.V, 1e-15);
    CHECK_REL(P[3], -1.0 * f.X[2 * q + 1] / f.V, 1e-15);

    /* eq. 31 by hand: P = [1 2; 3 4], F = [2 0; 0 1]: sigma = P F^T / 2 = [1 1; 3 2] */
    {
        const double Pm[4] = {1, 2, 3, 4}, Fm[4] = {2, 0, 0, 1}, Fbad[4] = {1, 2, 2, 1};
        CHECK(sbc_homogenize_cauchy(Pm, Fm, S, &err) == SBC_OK);
        CHECK_ABS(S[0], 1.0, 1e-15);
        CHECK_ABS(S[1], 1.0, 1e-15);
        CHECK_ABS(S[2], 3.0, 1e-15);
        CHECK_ABS(S[3], 2.0, 1e-15);
        CHECK(sbc_homogenize_cauchy(Pm, Fbad, S, &err) == SBC_ERR_GEOMETRY);
        /* symmetric P F^T gives symmetric sigma */
        {
            const double Ps[4] = {-2.0, 0.3, 0.3 * 1.2, -1.0}, Fs[4] = {1.0, 0.0, 0.0, 1.2};
            CHECK(sbc_homogenize_cauchy(Ps, Fs, S, &err) == SBC_OK);
            CHECK_ABS(S[1], S[2], 1e-15);
        }
    }

    /* eq. 30: zero for an admissible (D) state (w = 0) with arbitrary forces */
    srand(11);
    for (k = 0; k < 2 * f.n; ++k)
        a[k] = rand() / (double)RAND_MAX - 0.5;
    affine(&f, Fa, x);
    sbc_homogenize_P(&f, a, P);
    CHECK_ABS(sbc_homogenize_hill_mandel(&f, a, x, Fa, P), 0.0, 1e-12);
    /* ... and for a (T) state (a = P0 A) with arbitrary fluctuations */
    for (q = 0; q < f.n; ++q) {
        a[2 * q] = P0[0] * f.A[2 * q] + P0[1] * f.A[2 * q + 1];
        a[2 * q + 1] = P0[2] * f.A[2 * q] + P0[3] * f.A[2 * q + 1];
        x[2 * q] += 1e-5 * (rand() / (double)RAND_MAX - 0.5);
        x[2 * q + 1] += 1e-5 * (rand() / (double)RAND_MAX - 0.5);
    }
    sbc_homogenize_F(&f, x, F);
    CHECK_ABS(sbc_homogenize_hill_mandel(&f, a, x, F, P0), 0.0, 1e-15);
    /* ... but not for arbitrary forces with fluctuations (the check can fail) */
    a[0] += 1.0;
    sbc_homogenize_P(&f, a, P);
    CHECK(fabs(sbc_homogenize_hill_mandel(&f, a, x, F, P)) > 1e-6);

    /* eq. 42: constant sigma_ij = s over F12 in [0, L] gives sqrt(4 s^2 L) */
    {
        double par[5] = {0.0, 0.1, 0.2, 0.3, 0.5}, sig[20];
        for (k = 0; k < 20; ++k)
            sig[k] = -2.0;
        CHECK_REL(sbc_homogenize_path_norm(5, par, sig), sqrt(4.0 * 4.0 * 0.5), 1e-15);
        /* linear sigma_11 = F12 on [0, 1], others 0: trapezoid of s^2 on 2 points = 1/2 */
        {
            double par2[2] = {0.0, 1.0}, sig2[8] = {0, 0, 0, 0, 1, 0, 0, 0};
            CHECK_REL(sbc_homogenize_path_norm(2, par2, sig2), sqrt(0.5), 1e-15);
        }
    }
    free(x);
    free(a);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}
