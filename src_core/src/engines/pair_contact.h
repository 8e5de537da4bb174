/* Private: one contact of the 2D pair loop (paper Sect. 2.2.2: eq. 6, eqs.
 * 7-8 for an intact bond, eq. 12's energy, eq. 39's overlap), shared by the
 * embedded engine's pair loop (engine.c) and the hosts' distributed contacts
 * (cohesive_host.h), so that both compute a pair alike to the bit.
 * Conventions of contact.h: n from i to j, t = e3 x n. */
#ifndef SBC_PAIR_CONTACT_H
#define SBC_PAIR_CONTACT_H

#include <math.h>

#include "sbc/contact.h"

/* Velocities below 1e-120 (m/s, rad/s) and spring forces below 1e-120 N
 * carry no physics, and their squares must stay above the subnormal range.
 * In a packing held in exact equilibrium, round-off seeds decay geometrically
 * towards that range, where x86 arithmetic is about 2x slower. Flushing them
 * keeps the library free of global floating-point state (no FTZ/DAZ flags). */
static inline double sbc_flush(double a) { return fabs(a) < 1e-120 ? 0.0 : a; }

/* Two discs in contact at the start are bonded (Sect. 2.2.2): their gap
 * |x_j - x_i| - R_i - R_j below SBC_BOND_TOUCH times the smallest radius. */
#define SBC_BOND_TOUCH 1e-6

/* The laws of a scene: eq. 6 (law, with 1/ks or 0) and eqs. 7-8 (bond). */
typedef struct sbc_pair_laws {
    sbc_frictional law;
    double inv_ks; /* 1/N m */
    sbc_cohesive bond;
} sbc_pair_laws;

/* Running sums of a pass over the pairs: eq. 12's Ep (J), sum dn / (R_i +
 * R_j) (eq. 39 is twice that), sum |contact force| (N), contacts, bonds
 * broken in the pass. */
typedef struct sbc_pair_sums {
    double ep, ov, fc;
    long nc;
    int broken;
} sbc_pair_sums;

/* The pair (i, j) at centre offset (dx, dy) = x_j - x_i (m), radii ri, rj
 * (m), velocities (m/s), spins wi, wj (rad/s) and wri = ri wi (m/s), over a
 * step dt (s). State: *fs the tangential spring (N), *m the bond moment on i
 * (N m), *bond 1 while the bond is intact (m and bond unused when BONDS is 0,
 * fs when HISTORY is 0). HISTORY and BONDS are compile-time constants in the
 * callers. Returns 0 when the pair carries no load (apart and unbonded: fs
 * cleared); else 1, with out = the force on i (fx, fy, N; -out on j) and,
 * with HISTORY, the moments on i and on j (N m). */
static inline int sbc_pair_contact(const sbc_pair_laws *L, const int history, const int bonds, double dx, double dy,
                                   double ri, double rj, double vxi, double vyi, double wi, double wri, double vxj,
                                   double vyj, double wj, double dt, double *fs_state, double *m_state,
                                   unsigned char *bond_state, sbc_pair_sums *s, double out[4])
{
    const double rs = ri + rj, d2 = dx * dx + dy * dy, kn = L->law.kn;
    double d, inv_d, nx, ny, dn, fn, fs = 0.0, dus;
    const int bonded = bonds && *bond_state;
    if (!bonded && d2 >= rs * rs) {
        if (history)
            *fs_state = 0.0; /* contact lost: history cleared */
        return 0;
    }
    d = sqrt(d2);
    inv_d = 1.0 / d;
    nx = dx * inv_d;
    ny = dy * inv_d;
    dn = rs - d;
    fn = kn * dn;
    /* t = (-ny, nx); dus = ((v_j - v_i).t - (R_i w_i + R_j w_j)) dt (bonds imply history) */
    dus = history ? ((vyj - vyi) * nx - (vxj - vxi) * ny - (wri + rj * wj)) * dt : 0.0;
    if (bonded) {
        /* eqs. 7-8, dtheta = (w_j - w_i) dt; moment +m on i, -m on j */
        sbc_bond b;
        int broke;
        b.fs = *fs_state;
        b.m = *m_state;
        b.broken = 0;
        fn = sbc_cohesive_force(&L->bond, dn, dus, (wj - wi) * dt, &b, &broke);
        fs = sbc_flush(b.fs);
        *fs_state = fs;
        *m_state = b.m;
        if (broke) {
            *bond_state = 0;
            ++s->broken;
        }
        out[2] = ri * fs + b.m;
        out[3] = rj * fs - b.m;
        s->ep += sbc_cohesive_energy(&L->bond, dn, &b) - 0.5 * fn * dn; /* normal part added below */
    } else if (history) { /* eq. 6 */
        fs = *fs_state;
        sbc_frictional_force(&L->law, dn, dus, &fs, NULL);
        fs = sbc_flush(fs);
        *fs_state = fs;
        out[2] = ri * fs;
        out[3] = rj * fs;
        s->ep += 0.5 * fs * fs * L->inv_ks; /* eq. 12, tangential part (sbc_frictional_energy) */
    }
    /* force on i: -fn n + fs t */
    out[0] = -fn * nx - fs * ny;
    out[1] = -fn * ny + fs * nx;
    s->ep += 0.5 * fn * dn; /* eq. 12, normal part */
    s->fc += sqrt(fn * fn + fs * fs);
    s->ov += dn / rs;
    ++s->nc;
    return 1;
}

#endif
