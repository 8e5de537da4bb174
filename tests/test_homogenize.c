/* Homogenization: eqs. 15, 23, 30, 31, 42. */
#include "check.h"
#include "tests.h"

#include "sbc/frame.h"
#include "sbc/homogenize.h"
#include "sbc/packing.h"
#include "sbc/tensor.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void affine(const sbc_frame *f, const double F[9], double *x)
{
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[3 * q];
        x[3 * q] = F[0] * X[0] + F[1] * X[1];
        x[3 * q + 1] = F[3] * X[0] + F[4] * X[1];
        x[3 * q + 2] = 0.0;
    }
}

/* the 2 x 2 block of t, row-major, as the four values a test lists */
static double c2(const double t[9], int k) { return t[SBC_IJ(k / 2, k % 2)]; }


/* tensor.h: dimension as a value. 3D by hand; 2D the 2 x 2 formulas. */
static void tensors(void)
{
    const double M[9] = {2, 1, 0, 0, 3, 1, 1, 0, 1}, S[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    double inv[9], out[9], back[9], v[3], I[9], name_check = 0.0;
    char name[8];
    int i, j, k;
    /* det M = 2 (3 - 0) - 1 (0 - 1) + 0 = 7 */
    CHECK_ABS(sbc_tensor_det(3, M), 7.0, 1e-15);
    CHECK_ABS(sbc_tensor_det(2, M), 6.0, 0.0);
    CHECK(sbc_tensor_inverse(3, M, inv));
    for (i = 0; i < 3; ++i) /* M M^-1 = I */
        for (j = 0; j < 3; ++j) {
            double s = 0.0;
            for (k = 0; k < 3; ++k)
                s += M[SBC_IJ(i, k)] * inv[SBC_IJ(k, j)];
            CHECK_ABS(s, i == j ? 1.0 : 0.0, 1e-15);
        }
    /* S M^-1 M = S */
    CHECK(sbc_tensor_right_divide(3, S, M, out));
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double s = 0.0;
            for (k = 0; k < 3; ++k)
                s += out[SBC_IJ(i, k)] * M[SBC_IJ(k, j)];
            back[SBC_IJ(i, j)] = s;
        }
    for (k = 0; k < 9; ++k)
        CHECK_ABS(back[k], S[k], 1e-14);
    /* 2D: the 2 x 2 block only, the rest 0 */
    {
        const double S2[9] = TENSOR2(1, 2, 3, 4), M2[9] = TENSOR2(2, 1, 1, 1);
        CHECK(sbc_tensor_right_divide(2, S2, M2, out));
        CHECK_ABS(out[0], -1.0, 1e-15); /* [1 2; 3 4] [1 -1; -1 2] = [-1 3; -1 5] */
        CHECK_ABS(out[1], 3.0, 1e-15);
        CHECK_ABS(out[3], -1.0, 1e-15);
        CHECK_ABS(out[4], 5.0, 1e-15);
        CHECK(out[2] == 0.0 && out[5] == 0.0 && out[8] == 0.0);
    }
    /* singular: refused, out untouched */
    {
        const double Z[9] = {1, 2, 3, 2, 4, 6, 0, 0, 1};
        out[0] = 42.0;
        CHECK(!sbc_tensor_inverse(3, Z, out) && !sbc_tensor_right_divide(3, S, Z, out) && out[0] == 42.0);
    }
    sbc_tensor_apply(3, M, (const double[3]){1.0, -1.0, 2.0}, v);
    CHECK(v[0] == 1.0 && v[1] == -1.0 && v[2] == 3.0);
    sbc_tensor_apply(2, M, (const double[3]){1.0, -1.0, 2.0}, v);
    CHECK(v[0] == 1.0 && v[1] == -3.0 && v[2] == 0.0);
    sbc_tensor_identity(3, I);
    CHECK_ABS(sbc_tensor_norm(3, I), sqrt(3.0), 1e-15);
    CHECK(sbc_tensor_norm_from_identity(3, I) == 0.0);
    sbc_tensor_identity(2, I);
    CHECK(I[8] == 0.0 && I[4] == 1.0);
    name_check = strcmp(sbc_tensor_component_name("sigma", 2, 0, name), "sigma31") == 0 &&
                 strcmp(sbc_tensor_component_name("F", 0, 1, name), "F12") == 0;
    CHECK(name_check == 1.0);
}

/* eqs. 15, 23, 30 on a 3D frame by hand: the eight corners X = (+-1, +-1,
 * +-1) of a cube with A_q = V X_q / 8, V = 8, so that sum_q X_q (x) A_q = V I:
 * an affine map gives back its F, a uniform traction a_q = P0 A_q its P0,
 * and the Hill-Mandel residual of that state is 0. (A 3D frame's own A_q,
 * from its surface, is the geometry of the 3D frame.) */
static void cube(void)
{
    int particle[8], side[8], partner[8], q, k;
    double X[24], A[24], R[8], x[24], a[24], F[9], P[9];
    const double F0[9] = {1.1, 0.05, -0.02, 0.0, 0.95, 0.03, 0.01, -0.04, 1.02};
    const double P0[9] = {-3.0, 1.0, 0.5, 1.0, -2.0, 0.2, 0.5, 0.2, -4.0};
    sbc_frame f;
    memset(&f, 0, sizeof f);
    for (q = 0; q < 8; ++q) {
        X[3 * q] = q & 1 ? 1.0 : -1.0;
        X[3 * q + 1] = q & 2 ? 1.0 : -1.0;
        X[3 * q + 2] = q & 4 ? 1.0 : -1.0;
        for (k = 0; k < 3; ++k)
            A[3 * q + k] = X[3 * q + k];
        particle[q] = q, side[q] = SBC_SIDE_CORNER, partner[q] = -1, R[q] = 0.1;
    }
    f.dim = 3, f.n = 8, f.particle = particle, f.side = side, f.partner = partner, f.X = X, f.A = A, f.R = R;
    f.V = 8.0;
    for (q = 0; q < 8; ++q) {
        sbc_tensor_apply(3, F0, &X[3 * q], &x[3 * q]);
        sbc_tensor_apply(3, P0, &A[3 * q], &a[3 * q]);
    }
    sbc_homogenize_F(&f, x, F);
    sbc_homogenize_P(&f, a, P);
    for (k = 0; k < 9; ++k) {
        CHECK_ABS(F[k], F0[k], 1e-15);
        CHECK_ABS(P[k], P0[k], 1e-14);
    }
    CHECK_ABS(sbc_homogenize_hill_mandel(&f, a, x, F, P), 0.0, 1e-14);
    CHECK_REL(sbc_homogenize_work_scale(3, P, F), sbc_tensor_norm(3, P0) * (1.0 + sbc_tensor_norm_from_identity(3, F0)),
              1e-14);
}

void test_homogenize(void)
{
    sbc_packing p;
    sbc_frame f;
    sbc_error err;
    double F[9], P[9], S[9], *x, *a;
    static const double I[4] = {1, 0, 0, 1};
    static const double Fa[9] = TENSOR2(1.1, 0.3, -0.2, 0.9);
    static const double P0[9] = TENSOR2(-3.0, 1.5, 0.7, -2.0);
    int q, k;

    CHECK(sbc_packing_lattice_square(&p, 7, 4, 1.5e-3, 0.8e-3, &err) == SBC_OK);
    CHECK(sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err) == SBC_OK);
    x = calloc(3 * (size_t)f.n, sizeof(double));
    a = calloc(3 * (size_t)f.n, sizeof(double));
    CHECK(f.dim == 2);

    /* eq. 15: F = I in the reference state */
    sbc_homogenize_F(&f, f.X, F);
    for (k = 0; k < 4; ++k)
        CHECK_ABS(c2(F, k), I[k], 1e-14);
    for (k = 2; k < 9; k += k == 2 ? 3 : 1) /* the slots outside the 2 x 2 block stay 0 */
        CHECK(F[k] == 0.0);
    /* eq. 15 reproduces an imposed affine map */
    affine(&f, Fa, x);
    sbc_homogenize_F(&f, x, F);
    for (k = 0; k < 4; ++k)
        CHECK_ABS(c2(F, k), c2(Fa, k), 1e-14);

    /* eq. 23 with uniform forces a_q = P0 A_q (eq. 21) returns P0 */
    for (q = 0; q < f.n; ++q) {
        a[3 * q] = P0[0] * f.A[3 * q] + P0[1] * f.A[3 * q + 1];
        a[3 * q + 1] = P0[3] * f.A[3 * q] + P0[4] * f.A[3 * q + 1];
    }
    sbc_homogenize_P(&f, a, P);
    for (k = 0; k < 4; ++k)
        CHECK_ABS(c2(P, k), c2(P0, k), 1e-12);
    /* eq. 23 by hand: a single force on one particle */
    for (k = 0; k < 3 * f.n; ++k)
        a[k] = 0.0;
    q = f.corner[2];
    a[3 * q] = 2.0;
    a[3 * q + 1] = -1.0;
    sbc_homogenize_P(&f, a, P);
    CHECK_REL(P[0], 2.0 * f.X[3 * q] / f.V, 1e-15);
    CHECK_REL(P[1], 2.0 * f.X[3 * q + 1] / f.V, 1e-15);
    CHECK_REL(P[3], -1.0 * f.X[3 * q] / f.V, 1e-15);
    CHECK_REL(P[4], -1.0 * f.X[3 * q + 1] / f.V, 1e-15);

    /* eq. 31 by hand: P = [1 2; 3 4], F = [2 0; 0 1]: sigma = P F^T / 2 = [1 1; 3 2] */
    {
        const double Pm[9] = TENSOR2(1, 2, 3, 4), Fm[9] = TENSOR2(2, 0, 0, 1), Fbad[9] = TENSOR2(1, 2, 2, 1);
        CHECK(sbc_homogenize_cauchy(2, Pm, Fm, S, &err) == SBC_OK);
        CHECK_ABS(S[0], 1.0, 1e-15);
        CHECK_ABS(S[1], 1.0, 1e-15);
        CHECK_ABS(S[3], 3.0, 1e-15);
        CHECK_ABS(S[4], 2.0, 1e-15);
        CHECK(sbc_homogenize_cauchy(2, Pm, Fbad, S, &err) == SBC_ERR_GEOMETRY);
        /* symmetric P F^T gives symmetric sigma */
        {
            const double Ps[9] = TENSOR2(-2.0, 0.3, 0.3 * 1.2, -1.0), Fs[9] = TENSOR2(1.0, 0.0, 0.0, 1.2);
            CHECK(sbc_homogenize_cauchy(2, Ps, Fs, S, &err) == SBC_OK);
            CHECK_ABS(S[1], S[3], 1e-15);
        }
        /* 3D, by hand: P = [1 2 0; 0 3 1; 2 0 1], F = diag(2, 1, 1) + e1 (x) e3:
           det F = 2, sigma_ij = P_ik F_jk / 2 */
        {
            const double P3[9] = {1, 2, 0, 0, 3, 1, 2, 0, 1}, F3[9] = {2, 0, 1, 0, 1, 0, 0, 0, 1};
            const double want[9] = {1.0, 1.0, 0.0, 0.5, 1.5, 0.5, 2.5, 0.0, 0.5};
            CHECK(sbc_homogenize_cauchy(3, P3, F3, S, &err) == SBC_OK);
            for (k = 0; k < 9; ++k)
                CHECK_ABS(S[k], want[k], 1e-15);
            CHECK_ABS(sbc_tensor_det(3, F3), 2.0, 0.0);
        }
    }

    /* eq. 30: zero for an admissible (D) state (w = 0) with arbitrary forces */
    srand(11);
    for (k = 0; k < 3 * f.n; ++k)
        a[k] = k % 3 == 2 ? 0.0 : rand() / (double)RAND_MAX - 0.5;
    affine(&f, Fa, x);
    sbc_homogenize_P(&f, a, P);
    CHECK_ABS(sbc_homogenize_hill_mandel(&f, a, x, Fa, P), 0.0, 1e-12);
    /* ... and for a (T) state (a = P0 A) with arbitrary fluctuations */
    for (q = 0; q < f.n; ++q) {
        a[3 * q] = P0[0] * f.A[3 * q] + P0[1] * f.A[3 * q + 1];
        a[3 * q + 1] = P0[3] * f.A[3 * q] + P0[4] * f.A[3 * q + 1];
        x[3 * q] += 1e-5 * (rand() / (double)RAND_MAX - 0.5);
        x[3 * q + 1] += 1e-5 * (rand() / (double)RAND_MAX - 0.5);
    }
    sbc_homogenize_F(&f, x, F);
    CHECK_ABS(sbc_homogenize_hill_mandel(&f, a, x, F, P0), 0.0, 1e-15);
    /* ... but not for arbitrary forces with fluctuations (the check can fail) */
    a[0] += 1.0;
    sbc_homogenize_P(&f, a, P);
    CHECK(fabs(sbc_homogenize_hill_mandel(&f, a, x, F, P)) > 1e-6);

    /* eq. 42: constant sigma_ij = s over F12 in [0, L] gives sqrt(4 s^2 L) */
    {
        double par[5] = {0.0, 0.1, 0.2, 0.3, 0.5}, sig[45];
        for (k = 0; k < 45; ++k)
            sig[k] = -2.0;
        CHECK_REL(sbc_homogenize_path_norm(2, 5, par, sig), sqrt(4.0 * 4.0 * 0.5), 1e-15);
        CHECK_REL(sbc_homogenize_path_norm(3, 5, par, sig), sqrt(9.0 * 4.0 * 0.5), 1e-15);
        /* linear sigma_11 = F12 on [0, 1], others 0: trapezoid of s^2 on 2 points = 1/2 */
        {
            double par2[2] = {0.0, 1.0}, sig2[18] = {0};
            sig2[9] = 1.0;
            CHECK_REL(sbc_homogenize_path_norm(2, 2, par2, sig2), sqrt(0.5), 1e-15);
        }
    }
    free(x);
    free(a);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
    tensors();
    cube();
}
