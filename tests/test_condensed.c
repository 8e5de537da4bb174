/* The condensed tangent's solvers (host/condensed.c, docs/fe2.md): the
 * sparse direct solve (UMFPACK, where the core is built with it) against the
 * dense one on the same networks, and both against the closed form:
 * - a prestressed 6 x 6 disc lattice (spacing d = 2 mm, R = 1.01 mm, kn 1e4,
 *   ks 2e3 N/m: every contact sticks, no tangential force yet) under (D),
 *   (P) and (T), and a frictionless one under (D), whose C1111 = N kn / (N - 1);
 * - a prestressed 4^3 sphere lattice under (D) and (P), frictionless under (D):
 *   C1111 = N^2 kn / ((N - 1)^2 d);
 * the two solvers agree to 1e-10 of max |C|, the mechanisms counted alike. */
#include "check.h"
#include "layer.h"
#include "tests.h"

#include "../src_core/src/base/sparse.h"
#include "../src_core/src/host/condensed.h"
#include "sbc/frame.h"
#include "sbc/packing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SPACING 2e-3
#define RADIUS 1.01e-3
#define KN 1e4

/* every overlapping pair of the centres x [dim n] with radius RADIUS */
static int overlapping_pairs(int dim, int n, const double *x, int *pi, int *pj)
{
    int a, b, k, count = 0;
    for (a = 0; a < n; ++a)
        for (b = a + 1; b < n; ++b) {
            double d2 = 0.0;
            for (k = 0; k < dim; ++k)
                d2 += (x[dim * b + k] - x[dim * a + k]) * (x[dim * b + k] - x[dim * a + k]);
            if (d2 < 4.0 * RADIUS * RADIUS) {
                pi[count] = a;
                pj[count++] = b;
            }
        }
    return count;
}

/* the tangent by both solvers: their largest difference relative to max |C|; C of the sparse one, the
   mechanisms of both (the dense solve also counts the pivots it cannot take: the gear mode of (T)) */
static double both_solvers(sbc_network *net, const sbc_frame *f, sbc_bc bc, double C[81], int *mechanisms,
                           int *mech_dense)
{
    double D[81], largest = 0.0, diff = 0.0;
    int k;
    sbc_error err;
    net->dense = 0;
    CHECK(sbc_condensed_tangent(net, f, bc, C, mechanisms, &err) == SBC_OK);
    net->dense = 1;
    CHECK(sbc_condensed_tangent(net, f, bc, D, mech_dense, &err) == SBC_OK);
    CHECK(*mech_dense >= *mechanisms);
    for (k = 0; k < 81; ++k) {
        largest = fmax(largest, fabs(D[k]));
        diff = fmax(diff, fabs(C[k] - D[k]));
    }
    return largest > 0.0 ? diff / largest : 1.0;
}

static void lattice_2d(void)
{
    enum { N = 6 };
    static double xy[2 * N * N], r[N * N];
    static int pi[4 * N * N], pj[4 * N * N];
    static const sbc_bc bcs[3] = {SBC_BC_D, SBC_BC_P, SBC_BC_T};
    sbc_packing pk;
    sbc_frame f;
    sbc_network net;
    sbc_error err;
    double C[81];
    int b, mechanisms, mech_dense;
    test_square_lattice(N, SPACING, RADIUS, xy, r);
    memset(&pk, 0, sizeof pk);
    pk.n = N * N;
    pk.x = xy;
    pk.r = r;
    CHECK(sbc_frame_detect_packing(&f, &pk, &err) == SBC_OK);
    memset(&net, 0, sizeof net);
    net.dim = 2;
    net.n = N * N;
    net.x = xy;
    net.r = r;
    net.npair = overlapping_pairs(2, N * N, xy, pi, pj);
    net.i = pi;
    net.j = pj;
    net.law.kn = KN;
    net.law.ks = 2e3;
    net.law.mu = 0.4;
    for (b = 0; b < 3; ++b) {
        const double diff = both_solvers(&net, &f, bcs[b], C, &mechanisms, &mech_dense);
        CHECK(diff <= 1e-10 && isfinite(C[0]) && C[0] > 0.0);
        /* (T): the free rotations' gear mode (neighbours spinning opposite ways) carries no stiffness */
        CHECK(bcs[b] == SBC_BC_T ? mech_dense > mechanisms || !sbc_sparse_available() : mech_dense == mechanisms);
        printf("  condensed: 6 x 6 disc lattice, sticking, (%c): sparse against dense %.2e of max |C|, "
               "C1111 %.8g, mechanisms %d and %d (%s)\n", "DPT"[b], diff, C[0], mechanisms, mech_dense,
               sbc_sparse_solver_name());
    }
    net.law.ks = 0.0;
    net.law.mu = 0.0;
    {
        const double diff = both_solvers(&net, &f, SBC_BC_D, C, &mechanisms, &mech_dense), want = N * KN / (N - 1.0);
        CHECK(diff <= 1e-10 && fabs(C[0] - want) <= 1e-10 * want);
        printf("  condensed: frictionless 6 x 6 lattice (D): sparse against dense %.2e, C1111 %.10g (closed form "
               "%.10g)\n", diff, C[0], want);
    }
    sbc_frame_free(&f);
}

static void lattice_3d(void)
{
    enum { N = 4, NP = N * N * N };
    static double x[3 * NP], r[NP];
    static int pi[3 * NP], pj[3 * NP];
    sbc_frame f;
    sbc_network net;
    sbc_error err;
    double C[81];
    int i, j, k, mechanisms, mech_dense;
    for (k = 0; k < N; ++k)
        for (j = 0; j < N; ++j)
            for (i = 0; i < N; ++i) {
                const int p = (k * N + j) * N + i;
                x[3 * p] = i * SPACING;
                x[3 * p + 1] = j * SPACING;
                x[3 * p + 2] = k * SPACING;
                r[p] = RADIUS;
            }
    CHECK(sbc_frame_detect_3d(&f, NP, x, r, 0.0, &err) == SBC_OK);
    memset(&net, 0, sizeof net);
    net.dim = 3;
    net.n = NP;
    net.x = x;
    net.r = r;
    net.npair = overlapping_pairs(3, NP, x, pi, pj);
    net.i = pi;
    net.j = pj;
    net.law.kn = KN;
    net.law.ks = 2e3;
    net.law.mu = 0.4;
    for (i = 0; i < 2; ++i) {
        const double diff = both_solvers(&net, &f, i ? SBC_BC_P : SBC_BC_D, C, &mechanisms, &mech_dense);
        CHECK(diff <= 1e-10 && isfinite(C[0]) && C[0] > 0.0 && mech_dense == mechanisms);
        printf("  condensed: 4^3 sphere lattice, sticking, (%c): sparse against dense %.2e of max |C|, C1111 %.8g, "
               "%d mechanisms\n", i ? 'P' : 'D', diff, C[0], mechanisms);
    }
    net.law.ks = 0.0;
    net.law.mu = 0.0;
    {
        const double diff = both_solvers(&net, &f, SBC_BC_D, C, &mechanisms, &mech_dense);
        const double want = N * N * KN / ((N - 1.0) * (N - 1.0) * SPACING);
        CHECK(diff <= 1e-10 && fabs(C[0] - want) <= 1e-10 * want);
        printf("  condensed: frictionless 4^3 lattice (D): sparse against dense %.2e, C1111 %.10g (closed form %.10g)\n",
               diff, C[0], want);
    }
    sbc_frame_free(&f);
}

void test_condensed(void)
{
    lattice_2d();
    lattice_3d();
}
