/* servo_bc: FIRE minimization (Bitzek et al. 2006). */
#include "fire.h"

#include <math.h>
#include <string.h>

double sbc_fire_minimize(sbc_fire_problem *pb, double ftol, int maxit)
{
    double dt = 0.1, alpha = 0.1, e = pb->forces(pb->ctx);
    size_t k, n = pb->n;
    int it, npos = 0;
    memset(pb->v, 0, sizeof(double) * n);
    for (it = 0; it < maxit; ++it) {
        double p = 0.0, vn = 0.0, fnrm = 0.0, fmax = 0.0;
        for (k = 0; k < n; ++k) {
            p += pb->f[k] * pb->v[k];
            vn += pb->v[k] * pb->v[k];
            fnrm += pb->f[k] * pb->f[k];
            if (fabs(pb->f[k]) > fmax) fmax = fabs(pb->f[k]);
        }
        if (fmax < ftol)
            break;
        vn = sqrt(vn);
        fnrm = sqrt(fnrm);
        for (k = 0; k < n; ++k)
            pb->v[k] = (1.0 - alpha) * pb->v[k] + alpha * vn * pb->f[k] / fnrm;
        if (p > 0.0) {
            if (++npos > 5) {
                dt = fmin(1.1 * dt, pb->dt_max);
                alpha *= 0.99;
            }
        } else {
            npos = 0;
            dt *= 0.5;
            alpha = 0.1;
            memset(pb->v, 0, sizeof(double) * n);
        }
        for (k = 0; k < n; ++k) {
            pb->v[k] += dt * pb->f[k];
            pb->x[k] += dt * pb->v[k];
            if (pb->place)
                pb->place(pb->ctx, k);
        }
        e = pb->forces(pb->ctx);
    }
    return e;
}
