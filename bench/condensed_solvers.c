/* The condensed tangent's solve (host/condensed.c, docs/fe2.md): the sparse
 * direct solver (UMFPACK) against the dense LU on the same network, a
 * prestressed SIDE x SIDE disc lattice (spacing 2 mm, radius 1.01 mm, kn
 * 1e4 N/m, ks 2e3 N/m: every contact sticking) under (D) and (T), measured
 * in one run: ms per tangent, their ratio, the two tangents' difference
 * relative to max |C|, and the dense matrix's memory (8 bytes per unknown
 * squared; the sparse solve's is UMFPACK's factors, a few hundred bytes per
 * unknown here). The dense solve is skipped above DENSE_MAX unknowns.
 *
 *   bench_condensed [SIDE ...]     default 10 20 40 80 160 */
#define _POSIX_C_SOURCE 200809L
#include "../src_core/src/base/sparse.h"
#include "../src_core/src/host/condensed.h"
#include "sbc/frame.h"
#include "sbc/packing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DENSE_MAX 8000 /* unknowns: 0.5 GB, about a minute */

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    static const int sides[] = {10, 20, 40, 80, 160};
    const int nside = argc > 1 ? argc - 1 : (int)(sizeof sides / sizeof sides[0]);
    int a, b;
    if (!sbc_sparse_available()) {
        printf("bench_condensed: the core was built without a sparse solver (SPARSE=no or no UMFPACK): nothing to "
               "compare\n");
        return 0;
    }
    printf("condensed tangent: %s against the dense LU, prestressed sticking lattices\n", sbc_sparse_solver_name());
    printf("%-4s %6s %3s %9s %10s %10s %8s %12s %10s\n", "side", "discs", "bc", "unknowns", "sparse ms", "dense ms",
           "ratio", "difference", "dense MB");
    for (a = 0; a < nside; ++a) {
        const int side = argc > 1 ? atoi(argv[a + 1]) : sides[a], n = side * side;
        double *x = malloc(sizeof(double) * 2 * (size_t)n), *r = malloc(sizeof(double) * (size_t)n);
        int *pi = malloc(sizeof(int) * 2 * (size_t)n), *pj = malloc(sizeof(int) * 2 * (size_t)n), i, j, np = 0;
        sbc_packing pk;
        sbc_frame f;
        sbc_network net;
        sbc_error err;
        if (side < 3 || !x || !r || !pi || !pj) {
            fprintf(stderr, "bench_condensed: side %d (expected 3 or more)\n", side);
            return 1;
        }
        for (j = 0; j < side; ++j)
            for (i = 0; i < side; ++i) {
                const int p = side * j + i;
                x[2 * p] = 2e-3 * i;
                x[2 * p + 1] = 2e-3 * j;
                r[p] = 1.01e-3;
                if (i + 1 < side)
                    pi[np] = p, pj[np++] = p + 1;
                if (j + 1 < side)
                    pi[np] = p, pj[np++] = p + side;
            }
        memset(&pk, 0, sizeof pk);
        pk.n = n;
        pk.x = x;
        pk.r = r;
        if (sbc_frame_detect_packing(&f, &pk, &err) != SBC_OK)
            return fprintf(stderr, "bench_condensed: %s\n", err.message), 1;
        memset(&net, 0, sizeof net);
        net.dim = 2;
        net.n = n;
        net.x = x;
        net.r = r;
        net.npair = np;
        net.i = pi;
        net.j = pj;
        net.law.kn = 1e4;
        net.law.ks = 2e3;
        net.law.mu = 0.4;
        for (b = 0; b < 2; ++b) {
            const sbc_bc bc = b ? SBC_BC_T : SBC_BC_D;
            const long unknowns = 3L * (b ? n : n - f.n) + (b ? 6 : 0);
            double S[81], D[81], t0, t1, t2 = 0.0, largest = 0.0, diff = 0.0;
            int mechanisms, k, dense = unknowns <= DENSE_MAX;
            net.dense = 0;
            t0 = now();
            if (sbc_condensed_tangent(&net, &f, bc, S, &mechanisms, &err) != SBC_OK)
                return fprintf(stderr, "bench_condensed: %s\n", err.message), 1;
            t1 = now();
            if (dense) {
                net.dense = 1;
                if (sbc_condensed_tangent(&net, &f, bc, D, &mechanisms, &err) != SBC_OK)
                    return fprintf(stderr, "bench_condensed: %s\n", err.message), 1;
                t2 = now();
                for (k = 0; k < 81; ++k) {
                    largest = fmax(largest, fabs(D[k]));
                    diff = fmax(diff, fabs(S[k] - D[k]));
                }
                printf("%-4d %6d %3s %9ld %10.1f %10.1f %8.1f %12.2e %10.0f\n", side, n, b ? "T" : "D", unknowns,
                       1e3 * (t1 - t0), 1e3 * (t2 - t1), (t2 - t1) / (t1 - t0), diff / largest,
                       8e-6 * (double)unknowns * (double)unknowns);
            } else {
                printf("%-4d %6d %3s %9ld %10.1f %10s %8s %12s %10.0f\n", side, n, b ? "T" : "D", unknowns,
                       1e3 * (t1 - t0), "-", "-", "-", 8e-6 * (double)unknowns * (double)unknowns);
            }
            fflush(stdout);
        }
        sbc_frame_free(&f);
        free(x);
        free(r);
        free(pi);
        free(pj);
    }
    return 0;
}
