/* The presets' stated accuracies (docs/servo_bc.md, Accuracy) against
 * closed forms, and the default words at time steps from 1e-3 to 0.3 of the
 * critical step.
 *
 * Frictional lattice (mu 0.4, ks = kn/5), N x N discs of radius 1.02 mm 2 mm
 * apart (prestressed), F = diag(0.99, 0.995) in 4 increments, (D) and (P):
 * the affine state is in equilibrium and, loaded quasi-statically, the only
 * one reached (tangential springs stay unloaded), so (tests/test_lattice.c)
 *   P11 = -N kn (2R - d F11) / ((N-1) d),  P22 likewise,  P12 = P21 = 0.
 * Every row must meet the preset's accuracy a: |P11 - P11*| <= a |P11*|,
 * the same for P22, |P12|, |P21| <= a |P11*|; and the error must not grow
 * from fast to balanced to tight.
 *
 * (T) on a touching frictionless 5 x 5 lattice (spacing 2R) under
 * F = diag(0.99, 1): the rows are independent chains; uniform traction puts
 * a force f on the N-2 middle rows and f/2 on the two whose ends are
 * corners (half the area vector), and eq. 15 weighs the rows' shortenings
 * (N-1) f_i / kn by those area vectors, so
 *   eps = 1 - F11 = f (N - 3/2) / (kn (N-1) d),
 *   P11 = -f / d = -kn eps (N-1) / (N - 3/2),  P22 = P12 = 0. */
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/embedded/script.h"
#include "sbc/settings.h"

#include <stdio.h>
#include <string.h>

enum { INCREMENTS = 4 };

/* Runs one lattice case; returns the largest relative error of the rows
 * against the closed form (P11, P22, P12 / P11, P21 / P11), -1 on failure. */
static double frictional_lattice(int N, const char *bc, const char *preset, const char *damping)
{
    const double d = 2e-3, R = 1.02e-3, kn = 1e4;
    char script[2048], csv[512];
    static double rows[INCREMENTS + 2][CSV_COLS];
    sbc_error err;
    double worst = 0.0;
    int n, k;
    snprintf(csv, sizeof csv, "%s/accuracy_%d_%s_%s_%c.csv", test_tmpdir, N, bc, preset, strstr(damping, "fire") ? 'F' : 'L');
    snprintf(script, sizeof script,
             "dimension 2\nlattice square %d %d spacing %.17g radius %.17g\n"
             "contact frictional kn %.17g ks %.17g mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
             "servo_bc %s F 0.99 0 0 0.995 increments %d accuracy %s %s file %s\nrun\n",
             N, N, d, R, kn, kn / 5, bc, INCREMENTS, preset, damping, csv);
    if (sbc_script_run_string(script, "accuracy", NULL, &err) != SBC_OK) {
        printf("  %s\n", err.message);
        return -1.0;
    }
    n = csv_read(csv, rows, INCREMENTS + 2);
    if (n != INCREMENTS + 1)
        return -1.0;
    for (k = 1; k < n; ++k) {
        const double *r = rows[k];
        const double P11 = -N * kn * (2 * R - d * r[1]) / ((N - 1) * d);
        const double P22 = -N * kn * (2 * R - d * r[4]) / ((N - 1) * d);
        const double e[4] = {fabs(r[5] - P11) / fabs(P11), fabs(r[8] - P22) / fabs(P22), fabs(r[6]) / fabs(P11),
                             fabs(r[7]) / fabs(P11)};
        int c;
        for (c = 0; c < 4; ++c)
            worst = fmax(worst, e[c]);
        /* the accuracy columns: the force balance reached, and Hill-Mandel */
        CHECK(r[20] >= 0.0 && r[21] >= 0.0 && fabs(r[22]) < 1e-6);
    }
    return worst;
}

/* every preset, with the local damping of eq. 10 and with FIRE */
static void presets_on_lattices(void)
{
    static const char *presets[3] = {"fast", "balanced", "tight"};
    static const char *dampings[2] = {"damping 0.7 0.7", "damping fire"};
    static const char *bcs[2] = {"D", "P"};
    static const int sizes[3] = {5, 7, 9};
    int s, b, p, d;
    for (d = 0; d < 2; ++d)
        for (s = 0; s < 3; ++s)
            for (b = 0; b < 2; ++b) {
                double prev = 1.0;
                for (p = 0; p < 3; ++p) {
                    const double stated = sbc_settings_preset_accuracy(presets[p]);
                    const double e = frictional_lattice(sizes[s], bcs[b], presets[p], dampings[d]);
                    CHECK(e >= 0.0 && e <= stated);
                    /* never worse than the looser preset (up to round-off) */
                    CHECK(e >= 0.0 && e <= fmax(prev, 1e-10));
                    if (p == 2 && s == 2)
                        printf("  accuracy: %dx%d frictional lattice, (%s), tight, %s: %.2g of the closed form\n",
                               sizes[s], sizes[s], bcs[b], dampings[d], e);
                    if (e < 0.0 || e > stated)
                        printf("  %dx%d (%s) accuracy %s %s: error %.3g, stated %.3g\n", sizes[s], sizes[s], bcs[b],
                               presets[p], dampings[d], e, stated);
                    prev = e;
                }
            }
}

static void traction_lattice(void)
{
    static const char *presets[2] = {"balanced", "tight"};
    const int N = 5;
    const double kn = 1e4;
    int p;
    for (p = 0; p < 2; ++p) {
        char script[1024], csv[512];
        static double rows[4][CSV_COLS];
        const double tol = p == 1 ? 1e-5 : sbc_settings_preset_accuracy(presets[p]);
        sbc_error err;
        int n, k;
        snprintf(csv, sizeof csv, "%s/accuracy_T_%s.csv", test_tmpdir, presets[p]);
        snprintf(script, sizeof script,
                 "dimension 2\nlattice square %d %d spacing 2e-3 radius 1e-3\ncontact frictional kn %g ks 0 mu 0\n"
                 "density 2e3\ntimestep 1e-5\nservo_bc T F 0.99 0 0 1 increments 2 accuracy %s file %s\nrun\n",
                 N, N, kn, presets[p], csv);
        CHECK(sbc_script_run_string(script, "traction", NULL, &err) == SBC_OK);
        n = csv_read(csv, rows, 4);
        CHECK(n == 3);
        for (k = 1; k < n; ++k) {
            const double eps = 1.0 - rows[k][COL("F11")];
            const double P11 = -kn * eps * (N - 1) / (N - 1.5);
            CHECK_REL(rows[k][COL("F11")], 1.0 - 0.005 * k, 1e-12); /* eq. 15 holds exactly (restore_eq15) */
            CHECK_REL(rows[k][COL("P11")], P11, tol);
            CHECK_ABS(rows[k][COL("P22")], 0.0, tol * fabs(P11));
            CHECK_ABS(rows[k][COL("P12")], 0.0, tol * fabs(P11));
        }
    }
}

/* A user's 6 x 6 frictional lattice in simple shear (P), F12 = 0.02 in 4
 * increments, at dt = f of the critical step; returns sigma11, sigma12 of
 * the last row through *s11, *s12, 0 when the run failed. */
static int shear_lattice(double f, const char *words, double *s11, double *s12)
{
    char script[1024], csv[512];
    static double rows[6][CSV_COLS];
    const double m = 2e3 * 3.14159265358979323846 * 1.02e-3 * 1.02e-3, dtc = 2.0 * sqrt(m / (2.0 * 1e4));
    sbc_error err;
    int n;
    snprintf(csv, sizeof csv, "%s/accuracy_shear_%g.csv", test_tmpdir, f);
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 6 6 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n"
             "density 2e3\ntimestep %.17g\nservo_bc P F 1 0.02 0 1 increments 4 %s file %s\nrun\n",
             f * dtc, words, csv);
    if (sbc_script_run_string(script, "shear", NULL, &err) != SBC_OK) {
        printf("  shear at %g of the critical step (%s): %s\n", f, words, err.message);
        return 0;
    }
    n = csv_read(csv, rows, 6);
    if (n != 5)
        return 0;
    *s11 = rows[4][COL("sigma11")];
    *s12 = rows[4][COL("sigma12")];
    return 1;
}

static void shear_at_any_time_step(void)
{
    static const double fractions[4] = {1e-3, 0.08, 0.3, 0.01};
    double t11 = 0.0, t12 = 0.0, b11, b12;
    int k;
    /* the reference: tight at 0.08 of the critical step */
    CHECK(shear_lattice(0.08, "accuracy tight", &t11, &t12));
    for (k = 0; k < 4; ++k) {
        const int ok = shear_lattice(fractions[k], "", &b11, &b12); /* the default words */
        const double scale = fmax(fabs(t11), fabs(t12));
        CHECK(ok);
        /* balanced (the default) agrees with tight within its stated accuracy */
        CHECK_ABS(b11, t11, sbc_settings_preset_accuracy("balanced") * scale);
        CHECK_ABS(b12, t12, sbc_settings_preset_accuracy("balanced") * scale);
        if (k == 1)
            printf("  accuracy: 6x6 shear at 0.08 of the critical step, sigma12 balanced %.8g, tight %.8g N/m\n", b12,
                   t12);
    }
}

void test_accuracy(void)
{
    presets_on_lattices();
    traction_lattice();
    shear_at_any_time_step();
}
