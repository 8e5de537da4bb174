/* servo_bc: the per-particle kernels of the relaxation, inline, the same
 * arithmetic in every host that applies them: eq. 10 (local damping), FIRE's
 * sums and mix (fire_damping.h), a particle's kinetic energy (eq. 12). Vectors have dim components; a
 * particle's rotation has SBC_ROTATIONS(dim) (the z component in 2D). */
#ifndef SBC_DAMPING_H
#define SBC_DAMPING_H

#include <math.h>

#include "sbc/fire_damping.h"
#include "sbc/tensor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* eq. 10: one component f of a force (N) or moment (N m) damped against the
 * velocity component v it drives: f - alpha |f| sign(v); unchanged at v = 0 */
static inline double sbc_damp_local(double f, double v, double alpha)
{
    return f - alpha * fabs(f) * ((v > 0.0) - (v < 0.0));
}

/* FIRE's sums (SBC_FIRE_SUMS) plus one interior particle's: force f and
 * velocity v [dim], moment t and angular velocity w [SBC_ROTATIONS(dim)] */
static inline void sbc_fire_add(double *sums, int dim, const double *f, const double *v, const double *t,
                                const double *w)
{
    double p = 0.0, vv = 0.0, ff = 0.0, ww = 0.0, mm = 0.0;
    int k;
    for (k = 0; k < dim; ++k) {
        p += f[k] * v[k];
        vv += v[k] * v[k];
        ff += f[k] * f[k];
    }
    for (k = 0; k < SBC_ROTATIONS(dim); ++k) {
        p += t[k] * w[k];
        ww += w[k] * w[k];
        mm += t[k] * t[k];
    }
    sums[SBC_FIRE_POWER] += p;
    sums[SBC_FIRE_VV] += vv;
    sums[SBC_FIRE_FF] += ff;
    sums[SBC_FIRE_WW] += ww;
    sums[SBC_FIRE_MM] += mm;
}

/* FIRE's factor on the force of a particle whose kick is dt / M (s/kg, or
 * s/(kg m^2) for a rotation; the host's own quotient): push (or spin, for a
 * rotation) less the stop's half kick, stop dt / 2M (fire_damping.h) */
static inline double sbc_fire_factor(double push, const sbc_fire_mix *mix, double kick)
{
    return push - mix->stop * 0.5 * kick;
}

/* FIRE's mix on one velocity component v (m/s, rad/s) under the force
 * component f, with factor (sbc_fire_factor): keep v + factor f */
static inline double sbc_fire_velocity(const sbc_fire_mix *mix, double factor, double v, double f)
{
    return mix->keep * v + factor * f;
}

/* eq. 12: the kinetic energy (J) of a particle of mass m (kg) and moment of
 * inertia I (kg m^2) with velocity v [dim] and angular velocity w
 * [SBC_ROTATIONS(dim)] */
static inline double sbc_kinetic_energy(int dim, double m, double I, const double *v, const double *w)
{
    double vv = 0.0, ww = 0.0;
    int k;
    for (k = 0; k < dim; ++k)
        vv += v[k] * v[k];
    for (k = 0; k < SBC_ROTATIONS(dim); ++k)
        ww += w[k] * w[k];
    return 0.5 * m * vv + 0.5 * I * ww;
}

#ifdef __cplusplus
}
#endif

#endif
