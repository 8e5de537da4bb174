/* The cost of a material point's tangents (material_point.h, docs/fe2.md):
 * on prestressed frictional SIDE x SIDE lattices (spacing 2 mm, radius
 * 1.01 mm, kn 1e4 N/m, ks 2e3 N/m, mu 0.4) under (D), (P) and (T) at
 * `balanced`, one increment to F = [[0.999, 0.0005], [0, 0.9995]], then the
 * condensed, the affine and the perturbation (h = 1e-5) tangent at that
 * state. Prints ms per tangent, the perturbation's time over the condensed
 * one's as a ratio measured in the same run, and the two tangents'
 * difference relative to |C|.
 *
 *   bench_tangents [SIDE ...]     default 5 10 20 */
#define _POSIX_C_SOURCE 200809L
#include "sbc/material_point.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double difference(const double *C, const double *K)
{
    double norm = 0.0, diff = 0.0;
    int k;
    for (k = 0; k < 81; ++k) {
        norm += C[k] * C[k];
        diff += (C[k] - K[k]) * (C[k] - K[k]);
    }
    return sqrt(diff / norm);
}

int main(int argc, char **argv)
{
    static const char *words[3] = {"D accuracy balanced", "P accuracy balanced", "T accuracy balanced"};
    int sides[16] = {5, 10, 20}, nside = argc > 1 ? argc - 1 : 3, a, b, i, j;
    printf("%-4s %6s %-21s %12s %10s %14s %8s %12s\n", "side", "discs", "words", "condensed ms", "affine ms",
           "perturbation ms", "ratio", "difference");
    for (a = 0; a < nside && a < 16; ++a) {
        const int side = argc > 1 ? atoi(argv[a + 1]) : sides[a], n = side * side;
        double *x = malloc(sizeof(double) * 2 * (size_t)n), *r = malloc(sizeof(double) * (size_t)n);
        if (side < 3 || !x || !r) {
            fprintf(stderr, "bench_tangents: side %d (expected 3 or more)\n", side);
            return 1;
        }
        for (j = 0; j < side; ++j)
            for (i = 0; i < side; ++i) {
                x[2 * (side * j + i)] = 2e-3 * i;
                x[2 * (side * j + i) + 1] = 2e-3 * j;
                r[side * j + i] = 1.01e-3;
            }
        for (b = 0; b < 3; ++b) {
            sbc_point_def d = sbc_point_def_default();
            const double F[9] = {0.999, 0.0005, 0, 0, 0.9995, 0, 0, 0, 1};
            double P[9], K[81], A[81], C[81], ratio, t0, t1, t2, t3;
            int mechanisms;
            sbc_error err;
            sbc_point *p;
            d.n = n;
            d.x = x;
            d.r = r;
            d.words = words[b];
            d.law.kn = 1e4;
            d.law.ks = 2e3;
            d.law.mu = 0.4;
            d.density = 2e3;
            d.dt = 2e-6;
            if (!(p = sbc_point_create(&d, &err)) ||
                sbc_point_integrate(p, F, P, &ratio, &err) != SBC_POINT_CONVERGED) {
                fprintf(stderr, "bench_tangents: %s\n", err.message);
                return 1;
            }
            t0 = now();
            if (sbc_point_tangent_condensed(p, K, &mechanisms, &err) != SBC_OK)
                return fprintf(stderr, "bench_tangents: %s\n", err.message), 1;
            t1 = now();
            if (sbc_point_tangent_affine(p, A, &err) != SBC_OK)
                return fprintf(stderr, "bench_tangents: %s\n", err.message), 1;
            t2 = now();
            if (sbc_point_tangent_perturbation(p, 1e-5, C, &err) != SBC_OK)
                return fprintf(stderr, "bench_tangents: %s\n", err.message), 1;
            t3 = now();
            printf("%-4d %6d %-21s %12.2f %10.3f %14.1f %8.0f %12.2e\n", side, n, words[b], 1e3 * (t1 - t0),
                   1e3 * (t2 - t1), 1e3 * (t3 - t2), (t3 - t2) / (t1 - t0), difference(C, K));
            fflush(stdout);
            sbc_point_free(p);
        }
        free(x);
        free(r);
    }
    return 0;
}
