/* A material point as an FE code drives it (docs/fe2.md): a prestressed
 * 5 x 5 lattice under (P), two load steps of an FE integration point, the
 * second cut in half when the point asks for it, the tangent, the state
 * stored as doubles and restored into a new point. Built and run by make
 * check (it prints "material point example: ..." and exits 0).
 *
 *   cc -std=c11 -Isrc_core/include inputs/fe2/material_point.c build/libservo_bc.a -lumfpack -lm
 * (-lumfpack where the core was built with UMFPACK, the default when libsuitesparse-dev is installed), or
 * after make install, with the shared library:
 *   cc -std=c11 inputs/fe2/material_point.c $(pkg-config --cflags --libs servo_bc) */
#include "sbc/material_point.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(void)
{
    double x[50], r[25], F[9] = {0}, P[9], C[81], ratio, step = 0.001;
    sbc_point_def d = sbc_point_def_default();
    sbc_point *p, *q;
    sbc_error err;
    double *state;
    size_t size;
    int i, j, load;
    for (j = 0; j < 5; ++j) /* the packing: centres x [2n] (m), radii r [n] (m) */
        for (i = 0; i < 5; ++i) {
            x[2 * (5 * j + i)] = 2e-3 * i;
            x[2 * (5 * j + i) + 1] = 2e-3 * j;
            r[5 * j + i] = 1.01e-3;
        }
    d.n = 25;
    d.x = x;
    d.r = r;
    d.words = "P accuracy balanced"; /* the BC and its keywords; F and the path are the FE code's */
    d.law.kn = 1e4;                  /* eq. 6: N/m */
    d.law.ks = 5e3;
    d.law.mu = 0.5;
    d.density = 2e3; /* kg/m^2 */
    d.dt = 2e-6;     /* s */
    if (!(p = sbc_point_create(&d, &err))) { /* relaxed at F = I and committed */
        fprintf(stderr, "material point example: %s\n", err.message);
        return 1;
    }
    for (load = 1; load <= 2; ++load) { /* the FE code's load steps: uniaxial compression F11 */
        const double goal = 1.0 - load * step;
        double dF;
        sbc_point_committed(p, F, P);
        dF = goal - F[0];
        while (F[0] != goal) {
            double G[9];
            memcpy(G, F, sizeof G);
            G[0] = fabs(dF) < fabs(goal - F[0]) ? F[0] + dF : goal;
            if (sbc_point_integrate(p, G, P, &ratio, &err) == SBC_POINT_CONVERGED) {
                sbc_point_commit(p); /* the global iteration converged: the new start */
                memcpy(F, G, sizeof F);
            } else if (fabs(dF *= ratio) < 1e-9) { /* the point is back at its committed state */
                fprintf(stderr, "material point example: %s\n", err.message);
                return 1;
            } else {
                printf("material point example: step cut by %g (%s)\n", ratio, err.message);
            }
        }
        printf("material point example: load %d: F11 = %.4f, P11 = %.6g N/m, P22 = %.6g N/m\n", load, F[0], P[0], P[4]);
    }
    if (sbc_point_tangent_affine(p, C, &err) != SBC_OK) /* or sbc_point_tangent_perturbation(p, 1e-4, C, &err) */
        return 1;
    printf("material point example: affine C1111 = %.6g N/m, C1212 = %.6g N/m\n", C[0], C[10]);
    size = sbc_point_state_size(p); /* what the FE code stores per integration point */
    state = malloc(sizeof(double) * size);
    q = sbc_point_create(&d, &err);
    if (!state || !q) {
        fprintf(stderr, "material point example: out of memory or %s\n", err.message);
        return 1;
    }
    sbc_point_save(p, state);
    if (sbc_point_load(q, state, size, &err) != SBC_OK) { /* the state restored into a new point */
        fprintf(stderr, "material point example: %s\n", err.message);
        return 1;
    }
    F[0] = 1.0 - 3 * step;
    {
        double Pq[9];
        const int same = sbc_point_integrate(p, F, P, &ratio, &err) == SBC_POINT_CONVERGED &&
                         sbc_point_integrate(q, F, Pq, &ratio, &err) == SBC_POINT_CONVERGED && !memcmp(P, Pq, sizeof P);
        printf("material point example: the restored point continues %s (%zu doubles stored)\n",
               same ? "bit for bit" : "DIFFERENTLY", size);
        free(state);
        sbc_point_free(q);
        sbc_point_free(p);
        return same ? 0 : 1;
    }
}
