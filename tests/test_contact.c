/* Frictional contact law, eq. 6. */
#include "check.h"
#include "tests.h"

#include "sbc/contact.h"

void test_contact(void)
{
    sbc_frictional law = sbc_frictional_default();
    double fs = 0.0, fn;
    int sliding = -1;

    CHECK(law.kn == 1e4 && law.ks == 2e3 && law.mu == 0.4);
    /* sticking: fn = kn dn, fs = ks dus below mu fn */
    fn = sbc_frictional_force(&law, 4e-5, 1e-5, &fs, &sliding);
    CHECK_REL(fn, 0.4, 1e-15);
    CHECK_REL(fs, 0.02, 1e-15);
    CHECK(sliding == 0);
    /* incremental: a second increment adds */
    fn = sbc_frictional_force(&law, 4e-5, 2e-5, &fs, &sliding);
    CHECK_REL(fs, 0.06, 1e-14);
    CHECK(sliding == 0);
    /* sliding: capped at mu fn = 0.16 N, sign kept */
    fn = sbc_frictional_force(&law, 4e-5, 1e-4, &fs, &sliding);
    CHECK_REL(fs, 0.16, 1e-15);
    CHECK(sliding == 1);
    fs = 0.0;
    sbc_frictional_force(&law, 4e-5, -1e-3, &fs, &sliding);
    CHECK_REL(fs, -0.16, 1e-15);
    CHECK(sliding == 1);
    /* unloading of the tangential spring: back from the cap, elastic again */
    fn = sbc_frictional_force(&law, 4e-5, 3e-5, &fs, &sliding);
    CHECK_REL(fs, -0.16 + 0.06, 1e-14);
    CHECK(sliding == 0);
    /* normal unloading shrinks the cap: fs follows mu fn down */
    fs = 0.15;
    fn = sbc_frictional_force(&law, 1e-5, 0.0, &fs, &sliding);
    CHECK_REL(fn, 0.1, 1e-15);
    CHECK_REL(fs, 0.04, 1e-14);
    CHECK(sliding == 1);
    /* loss of contact: no force, history cleared */
    fn = sbc_frictional_force(&law, -1e-9, 1e-5, &fs, &sliding);
    CHECK(fn == 0.0 && fs == 0.0 && sliding == 0);
    /* eq. 12 energy: kn dn^2/2 + fs^2/(2 ks) */
    CHECK_REL(sbc_frictional_energy(&law, 4e-5, 0.02), 0.5 * 1e4 * 16e-10 + 0.5 * 0.02 * 0.02 / 2e3, 1e-15);
    CHECK(sbc_frictional_energy(&law, -1e-5, 0.0) == 0.0);
    /* frictionless law keeps no history */
    law.mu = 0.0;
    CHECK(!sbc_frictional_has_history(&law));
    law.mu = 0.4;
    law.ks = 0.0;
    CHECK(!sbc_frictional_has_history(&law));
}

/* Cohesive law, eqs. 7-8: linear below failure, failure exactly when eq. 8
 * reaches 1, frictional and moment-free for good afterwards. */
void test_cohesive(void)
{
    sbc_cohesive law = sbc_cohesive_default();
    sbc_bond b = {0.0, 0.0, 0};
    double fn;
    int broke = -1;
    CHECK(law.kn == 1e8 && law.ks == 4e7 && law.kr == 20.0 && law.fn_u == 300.0 && law.fs_u == 60.0 &&
          law.m_u == 0.2 && law.mu == 0.6);
    /* below failure: tension, shear and bending, each linear */
    fn = sbc_cohesive_force(&law, -1e-6, 2e-7, 1e-3, &b, &broke);
    CHECK_REL(fn, -100.0, 1e-14);
    CHECK_REL(b.fs, 8.0, 1e-14);
    CHECK_REL(b.m, 0.02, 1e-14);
    CHECK(!b.broken && broke == 0);
    CHECK_REL(sbc_cohesive_criterion(&law, fn, &b), 100.0 / 300 + 8.0 / 60 + 0.02 / 0.2, 1e-14);
    /* eq. 12 with the rotational term */
    CHECK_REL(sbc_cohesive_energy(&law, -1e-6, &b), 0.5 * 1e8 * 1e-12 + 0.5 * 64 / 4e7 + 0.5 * 4e-4 / 20.0, 1e-14);
    /* compression enters eq. 8 with its sign (tension positive): it lowers the criterion... */
    b.fs = b.m = 0.0;
    fn = sbc_cohesive_force(&law, 1e-4, 0.0, 0.0, &b, &broke);
    CHECK(!b.broken && fn == 1e4);
    CHECK_REL(sbc_cohesive_criterion(&law, fn, &b), -1e4 / 300.0, 1e-14);
    /* ...so that a bond compressed by 300 N holds a shear force of 2 fs_u = 120 N until just before 120 N */
    {
        sbc_bond c = {0.0, 0.0, 0};
        sbc_cohesive_force(&law, 3e-6, 119.9 / 4e7, 0.0, &c, &broke);
        CHECK(!c.broken && broke == 0);
        sbc_cohesive_force(&law, 3e-6, 0.2 / 4e7, 0.0, &c, &broke);
        CHECK(c.broken && broke == 1); /* -1 + 120.1/60 >= 1 */
    }
    /* pure tension: intact just below f_u, broken exactly at it */
    b.fs = b.m = 0.0;
    sbc_cohesive_force(&law, -2.99e-6, 0.0, 0.0, &b, &broke);
    CHECK(!b.broken && broke == 0);
    fn = sbc_cohesive_force(&law, -3e-6, 0.0, 0.0, &b, &broke);
    CHECK(b.broken && broke == 1);
    /* after failure: no tension, no moment, frictional in compression, for good */
    CHECK(fn == 0.0 && b.m == 0.0 && b.fs == 0.0);
    fn = sbc_cohesive_force(&law, 1e-6, 1e-4, 1.0, &b, &broke);
    CHECK_REL(fn, 100.0, 1e-14);
    CHECK_REL(b.fs, 0.6 * 100.0, 1e-14); /* capped at mu fn */
    CHECK(b.m == 0.0 && broke == 0);
    CHECK(sbc_cohesive_criterion(&law, fn, &b) == 0.0);
    /* combined loading reaching 1 exactly: tension 150 N (1/2) + shear 15 N (1/4) + moment 0.05 N m (1/4) */
    {
        sbc_bond c = {0.0, 0.0, 0};
        sbc_cohesive_force(&law, 0.0, 15.0 / 4e7, 0.05 / 20.0 * 0.999, &c, &broke);
        CHECK(!c.broken);
        sbc_cohesive_force(&law, -1.5e-6, 0.0, 0.0, &c, &broke);
        CHECK(!c.broken); /* 0.5 + 0.25 + 0.24975 < 1 */
        sbc_cohesive_force(&law, -1.5e-6, 0.0, 0.05 / 20.0 * 0.001, &c, &broke);
        CHECK(c.broken && broke == 1);
    }
}
