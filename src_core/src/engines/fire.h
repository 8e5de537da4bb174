/* servo_bc: what the packing generators (2D periodic jamming, 3D radius
 * expansion) share: FIRE minimization (Bitzek et al. 2006) and the random
 * stream. Internal header. */
#ifndef SBC_FIRE_H
#define SBC_FIRE_H

#include <stddef.h>

typedef struct sbc_fire_problem {
    size_t n;       /* degrees of freedom */
    double *x;      /* positions, n */
    double *v;      /* work array, n */
    double *f;      /* forces (minus the energy gradient), n: filled by forces() */
    double (*forces)(void *ctx); /* fills f from x, returns the energy */
    void (*place)(void *ctx, size_t k); /* after x[k] moved: wrap or clamp it (may be NULL) */
    void *ctx;
    double dt_max;  /* largest step (FIRE's Delta t_max), in the units where the stiffness is 1 */
} sbc_fire_problem;

/* xorshift64*: uniform in [0, 1), deterministic on every platform; the
 * generators' random stream (state *s, never 0). */
static inline double sbc_uniform(unsigned long long *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

/* Minimizes from x until every |f| < ftol or maxit iterations (steps start at
 * 0.1, grow to dt_max); returns the energy. */
double sbc_fire_minimize(sbc_fire_problem *p, double ftol, int maxit);

#endif
