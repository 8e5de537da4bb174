/* Test helper: a material point's condensed tangent against the derivative of its increment's map. */
#include "tangent_map.h"

#include <math.h>
#include <string.h>

/* C_ijkl of the map (committed state, F) -> P by central differences (step h) */
static int map_derivative(sbc_point *p, int dim, const double F[9], double h, double D[81], sbc_error *err)
{
    int k, l, ij, s;
    memset(D, 0, sizeof(double) * 81);
    for (k = 0; k < dim; ++k)
        for (l = 0; l < dim; ++l) {
            double P[2][9], G[9], ratio;
            for (s = 0; s < 2; ++s) {
                memcpy(G, F, sizeof G);
                G[3 * k + l] += s == 0 ? h : -h;
                sbc_point_revert(p);
                if (sbc_point_integrate(p, G, P[s], &ratio, err) != SBC_POINT_CONVERGED)
                    return 0;
            }
            for (ij = 0; ij < 9; ++ij)
                D[9 * ij + 3 * k + l] = (P[0][ij] - P[1][ij]) / (2.0 * h);
        }
    return 1;
}

double tangent_map_gap(const sbc_point_def *def, int shear, int normal, double C[81], double D[81], sbc_error *err)
{
    double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, P[9], ratio, num = 0.0, den = 0.0, gap = -1.0;
    int k, mechanisms, ok = 1;
    sbc_point *p = sbc_point_create(def, err);
    if (!p)
        return -1.0;
    for (k = 1; k <= 4 && ok; ++k) { /* three committed shear steps, the fourth integrated */
        F[normal] = 1.0 - 0.0005 * k;
        F[shear] = 0.001 * k;
        ok = sbc_point_integrate(p, F, P, &ratio, err) == SBC_POINT_CONVERGED;
        if (ok && k < 4)
            sbc_point_commit(p);
    }
    if (ok && sbc_point_tangent_condensed(p, C, &mechanisms, err) == SBC_OK &&
        map_derivative(p, def->dim, F, 1e-7, D, err)) {
        for (k = 0; k < 81; ++k) {
            num += (C[k] - D[k]) * (C[k] - D[k]);
            den += D[k] * D[k];
        }
        gap = den > 0.0 ? sqrt(num / den) : -1.0;
    }
    sbc_point_free(p);
    return gap;
}
