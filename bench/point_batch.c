/* Material points in a batch (material_point.h, docs/fe2.md): COUNT points,
 * each a prestressed frictional SIDE x SIDE lattice (spacing 2 mm, radius
 * 1.01 mm, kn 1e4 N/m, ks 5e3 N/m, mu 0.5) under (P) at `balanced`, one
 * increment to F = [[0.999, 0.001], [0, 1]] on 1 thread and on THREADS,
 * each batch from freshly created points. Prints the state an FE code
 * stores per point (bytes), the process memory per point (resident, from
 * /proc/self/statm), ms per integrate on 1 thread and on THREADS, and the
 * speed-up as a ratio measured in the same run.
 *
 *   bench_points [COUNT [SIDE [THREADS]]]     defaults 16 10 2 */
#define _POSIX_C_SOURCE 200809L
#include "sbc/material_point.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double resident_bytes(void)
{
    long pages = 0, resident = 0;
    FILE *fp = fopen("/proc/self/statm", "r");
    if (fp) {
        if (fscanf(fp, "%ld %ld", &pages, &resident) != 2)
            resident = 0;
        fclose(fp);
    }
    return (double)resident * 4096.0;
}

/* creates count points and integrates them on `threads`: ms per integrate */
static double run(int count, const sbc_point_def *d, int threads, double *memory, size_t *state)
{
    sbc_point **pts = calloc((size_t)count, sizeof *pts);
    double *F = malloc(sizeof(double) * 9 * (size_t)count), *P = malloc(sizeof(double) * 9 * (size_t)count);
    double *ratio = malloc(sizeof(double) * (size_t)count), t0, t1, before = resident_bytes();
    int *status = malloc(sizeof(int) * (size_t)count), k;
    sbc_error err;
    for (k = 0; k < count; ++k) {
        double G[9] = {0.999, 0.001, 0, 0, 1.0, 0, 0, 0, 0};
        memcpy(&F[9 * k], G, sizeof G);
        if (!(pts[k] = sbc_point_create(d, &err))) {
            fprintf(stderr, "bench_points: %s\n", err.message);
            exit(1);
        }
    }
    *memory = (resident_bytes() - before) / count;
    *state = sbc_point_state_size(pts[0]) * sizeof(double);
    t0 = now();
    if (sbc_points_integrate(pts, count, F, P, status, ratio, threads, &err) != SBC_OK) {
        fprintf(stderr, "bench_points: %s\n", err.message);
        exit(1);
    }
    t1 = now();
    for (k = 0; k < count; ++k)
        sbc_point_free(pts[k]);
    free(pts), free(F), free(P), free(ratio), free(status);
    return 1e3 * (t1 - t0) / count;
}

int main(int argc, char **argv)
{
    const int count = argc > 1 ? atoi(argv[1]) : 16, side = argc > 2 ? atoi(argv[2]) : 10;
    const int threads = argc > 3 ? atoi(argv[3]) : 2;
    sbc_point_def d = sbc_point_def_default();
    double *x = malloc(sizeof(double) * 2 * (size_t)(side * side)), *r = malloc(sizeof(double) * (size_t)(side * side));
    double memory, m2, serial, parallel;
    size_t state;
    int i, j;
    for (j = 0; j < side; ++j)
        for (i = 0; i < side; ++i) {
            x[2 * (side * j + i)] = 2e-3 * i;
            x[2 * (side * j + i) + 1] = 2e-3 * j;
            r[side * j + i] = 1.01e-3;
        }
    d.n = side * side;
    d.x = x;
    d.r = r;
    d.words = "P accuracy balanced";
    d.law.kn = 1e4;
    d.law.ks = 5e3;
    d.law.mu = 0.5;
    d.density = 2e3;
    d.dt = 2e-6;
    serial = run(count, &d, 1, &memory, &state);
    parallel = run(count, &d, threads, &m2, &state);
    printf("points %d of %d discs: state %zu bytes per point, resident memory %.0f bytes per point; "
           "integrate %.2f ms per point on 1 thread, %.2f ms on %d threads, speed-up %.2f\n",
           count, side * side, state, memory, serial, parallel, threads, serial / parallel);
    free(x), free(r);
    return 0;
}
