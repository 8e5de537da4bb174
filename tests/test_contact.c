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
