#include "sbc/contact.h"

#include <stddef.h>

sbc_frictional sbc_frictional_default(void)
{
    sbc_frictional law;
    law.kn = 1.0e4; /* N/m, Table 4 */
    law.ks = 2.0e3; /* N/m, Table 4 */
    law.mu = 0.4;   /* Table 4 */
    return law;
}

sbc_cohesive sbc_cohesive_default(void)
{
    sbc_cohesive law;
    law.kn = 1.0e8;  /* N/m, Table 6: 1e5 N/mm */
    law.ks = 4.0e7;  /* N/m, Table 6: 4e4 N/mm */
    law.kr = 20.0;   /* N m/rad, Table 6: 2e4 N mm */
    law.fn_u = 300.0; /* N */
    law.fs_u = 60.0;  /* N */
    law.m_u = 0.2;    /* N m, Table 6: 200 N mm */
    law.mu = 0.6;
    return law;
}

double sbc_cohesive_criterion(const sbc_cohesive *law, double fn, const sbc_bond *b)
{
    if (b->broken)
        return 0.0;
    return -fn / law->fn_u + fabs(b->fs) / law->fs_u + fabs(b->m) / law->m_u; /* eq. 8, tension positive */
}

/* the frictional law of eq. 6 that a broken bond follows */
static sbc_frictional after_failure(const sbc_cohesive *law)
{
    sbc_frictional fr;
    fr.kn = law->kn;
    fr.ks = law->ks;
    fr.mu = law->mu;
    return fr;
}

double sbc_cohesive_force(const sbc_cohesive *law, double dn, double dus, double dtheta, sbc_bond *b, int *broke)
{
    double fn;
    if (broke)
        *broke = 0;
    sbc_frictional fr = after_failure(law);
    if (b->broken) { /* eq. 6 for good */
        b->m = 0.0;
        return sbc_frictional_force(&fr, dn, dus, &b->fs, NULL);
    }
    fn = law->kn * dn;      /* eq. 7, tension when dn < 0 */
    b->fs += law->ks * dus; /* eq. 7 */
    b->m += law->kr * dtheta;
    if (sbc_cohesive_criterion(law, fn, b) >= 1.0) {
        b->broken = 1;
        if (broke)
            *broke = 1;
        b->m = 0.0;
        /* the failed contact continues frictionally from its current spring */
        return sbc_frictional_force(&fr, dn, 0.0, &b->fs, NULL);
    }
    return fn;
}

double sbc_cohesive_energy(const sbc_cohesive *law, double dn, const sbc_bond *b)
{
    double e = 0.0;
    if (!b->broken || dn > 0.0)
        e += 0.5 * law->kn * dn * dn;
    if (law->ks > 0.0)
        e += 0.5 * b->fs * b->fs / law->ks;
    if (!b->broken && law->kr > 0.0)
        e += 0.5 * b->m * b->m / law->kr;
    return e;
}
