/* servo_bc: contact laws as kernels on per-pair state (paper Sect. 2.2.2).
 *
 * 2D convention: for a contact between particles i and j, n is the unit
 * vector from the centre of i to the centre of j and t = e3 x n = (-n2, n1).
 * The overlap is dn = R_i + R_j - |x_j - x_i| (m, positive in contact). The
 * tangential displacement increment of j relative to i at the contact is
 *   dus = (dx_j - dx_i) . t - (R_i dtheta_i + R_j dtheta_j)          (m).
 * Forces: on i, -fn n + fs t; on j, +fn n - fs t. Contact moments from the
 * tangential force: m_i = R_i fs, m_j = R_j fs (N m, about e3). */
#ifndef SBC_CONTACT_H
#define SBC_CONTACT_H

#include <math.h>
#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Frictional contact law, eq. 6. */
typedef struct sbc_frictional {
    double kn; /* normal stiffness, N/m */
    double ks; /* tangential stiffness, N/m; 0 = frictionless, no history */
    double mu; /* Coulomb friction coefficient, - */
} sbc_frictional;

/* The paper's Table 4 values: kn = 1e4 N/m, ks = 2e3 N/m, mu = 0.4. */
sbc_frictional sbc_frictional_default(void);

/* 1 when the law needs a tangential spring per contact. */
static inline int sbc_frictional_has_history(const sbc_frictional *law)
{
    return law->ks > 0.0 && law->mu > 0.0;
}

/* Eq. 6 with an incremental tangential spring: fn = kn dn; the spring force
 * fs (N, in/out per-contact state) is advanced by ks dus and capped at
 * mu fn (sliding). A contact with dn <= 0 is lost: fs is reset to 0.
 * Returns fn (N); *sliding (may be NULL) is set to 1 when the cap acts. */
static inline double sbc_frictional_force(const sbc_frictional *law, double dn, double dus, double *fs,
                                          int *sliding)
{
    double fn, trial, limit;
    int slide = 0;
    if (dn <= 0.0) {
        *fs = 0.0;
        if (sliding)
            *sliding = 0;
        return 0.0;
    }
    fn = law->kn * dn;
    trial = *fs + law->ks * dus;
    limit = law->mu * fn;
    if (fabs(trial) > limit) {
        trial = trial < 0.0 ? -limit : limit;
        slide = 1;
    }
    *fs = trial;
    if (sliding)
        *sliding = slide;
    return fn;
}

/* Elastic energy stored in a contact, eq. 12: kn dn^2/2 + ks dus_e^2/2 with
 * the elastic tangential displacement dus_e = fs/ks (J). */
static inline double sbc_frictional_energy(const sbc_frictional *law, double dn, double fs)
{
    double e = dn > 0.0 ? 0.5 * law->kn * dn * dn : 0.0;
    if (law->ks > 0.0)
        e += 0.5 * fs * fs / law->ks;
    return e;
}

/* Cohesive bond law, eqs. 7-8 (Sect. 2.2.2). Two particles in contact at the
 * start are bonded; while bonded
 *   fn = kn dn (dn < 0: the bond carries tension), fs += ks dus, m += kr dtheta,
 * with dtheta = d(theta_j - theta_i) the relative rotation increment; the bond
 * moment acts +m on i and -m on j (N m). It breaks for good when
 *   (-fn)/fn_u + |fs|/fs_u + |m|/m_u >= 1                              (eq. 8)
 * Our reading: eq. 8 writes f^b_n without absolute value and calls f^{b,u}_n
 * the tensile strength, so the bond force enters with its sign, tension
 * positive: compression lowers the criterion and lets the bond carry more
 * shear and bending (Mohr-Coulomb-like). The other reading (compression
 * ignored) breaks 42 of the 54 bonds of a 37-particle layer in the first
 * increment of P22* = -1.05e6 N/m (mean normal forces ~1e3 N against
 * fs_u = 60 N), which contradicts the paper's Figs. 11-12, where the bonds
 * survive the vertical stress. After failure the contact follows the
 * frictional law of eq. 6 with kn, ks and mu,
 * and carries no moment. */
typedef struct sbc_cohesive {
    double kn;   /* bond normal stiffness k^b_n, N/m */
    double ks;   /* bond shear stiffness k^b_s, N/m */
    double kr;   /* bond bending stiffness k^b_theta, N m/rad */
    double fn_u; /* tensile strength f^{b,u}_n, N */
    double fs_u; /* shear strength f^{b,u}_s, N */
    double m_u;  /* bending strength m^{b,u}_theta, N m */
    double mu;   /* friction coefficient after failure, - */
} sbc_cohesive;

/* Table 6 in SI: kn 1e8 N/m, ks 4e7 N/m, kr 20 N m/rad, fn_u 300 N, fs_u 60 N,
 * m_u 0.2 N m, mu 0.6. */
sbc_cohesive sbc_cohesive_default(void);

/* The law's words "kn KN ks KS kr KR fn FN fs FS mr MR mu MU" (w [nw], in
 * this order), shared by the runner's `contact cohesive` and the hosts'
 * `servo_bc/bonds cohesive`; cmd names the command in the messages (which
 * keyword, which value, what was expected). */
sbc_status sbc_cohesive_parse(int nw, char *const *w, const char *cmd, sbc_cohesive *law, sbc_error *err);

/* Per-pair state of a cohesive contact. */
typedef struct sbc_bond {
    double fs;  /* tangential spring force, N */
    double m;   /* bond moment on i, N m */
    int broken; /* 1 once eq. 8 has reached 1 */
} sbc_bond;

/* Advances one contact by the increments dus (m) and dtheta (rad) at overlap
 * dn (m); returns fn (N, positive in compression). *broke (may be NULL) is
 * set to 1 on the call at which the bond fails. */
double sbc_cohesive_force(const sbc_cohesive *law, double dn, double dus, double dtheta, sbc_bond *b, int *broke);

/* Eq. 8's left-hand side for the current bond forces (0 once broken). */
double sbc_cohesive_criterion(const sbc_cohesive *law, double fn, const sbc_bond *b);

/* Elastic energy of the contact, eq. 12 with the rotational term kr dtheta^2/2 = m^2/(2 kr) (J). */
double sbc_cohesive_energy(const sbc_cohesive *law, double dn, const sbc_bond *b);

#ifdef __cplusplus
}
#endif

#endif
