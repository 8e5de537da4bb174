/* Keyword update newton (docs/servo_bc.md, "Newton"): the servo's correction
 * from the linearized contact network with the interior condensed out.
 *
 * - A prestressed frictional 5 x 5 lattice (d = 2 mm, R = 1.01 mm, kn 1e4,
 *   ks 2e3 N/m, mu 0.4) under (P) at F = diag(1 - 0.0005 i, 1 - 0.001 i),
 *   2 increments, `tight`: P_ii = -N kn (2R - d F_ii) / ((N - 1) d) to 1e-6
 *   of |P11|, as under secant, in less than half secant's servo iterations
 *   (the Newton corrections at work, not the secant fallback).
 * - The touching frictionless 5 x 5 lattice (R = 1 mm) under (T) at
 *   F = diag(1 - 0.01 i / 3, 1), 3 increments, `tight`: every chain along x
 *   carries the force of its end node's area, P11 = -kn eps (N - 1) /
 *   (N - 3/2) (test_accuracy.c), to 1e-5 of |P11|.
 * - The 4^3 frictional sphere lattice under (P), diag(0.999, 0.998, 0.997):
 *   P_ii = -N^2 kn (2R - d F_ii) / ((N - 1)^2 d^2) to 1e-6.
 * - A material point of the frictional lattice under (P) with update newton:
 *   the closed form after an integrate, to 1e-6.
 * - Refusals: newton with mixed (the words), a host driver without the
 *   newton callback (cohesive bonds under update newton: test_point.c and
 *   test_interior_bonds.c). */
#include "check.h"
#include "csv_read.h"
#include "layer.h"
#include "tests.h"

#include "sbc/driver.h"
#include "sbc/embedded/script.h"
#include "sbc/material_point.h"
#include "sbc/settings.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define N 5
#define SPACING 2e-3
#define KN 1e4

/* the script with "%s" the update rule and then the csv path; its rows (2D) into rows, or -1 */
static int run_rule(const char *tag, const char *script, const char *rule, double rows[][CSV_COLS], int max)
{
    char csv[512], text[2048], name[64];
    sbc_error err;
    snprintf(name, sizeof name, "newton_%s_%s", tag, rule);
    snprintf(csv, sizeof csv, "%s/%s.csv", test_tmpdir, name);
    snprintf(text, sizeof text, script, rule, csv);
    if (sbc_script_run_string(text, name, NULL, &err) != SBC_OK) {
        printf("  newton: %s: %s\n", name, err.message);
        return -1;
    }
    return csv_read(csv, rows, max);
}

static double mean_iterations(double rows[][CSV_COLS], int n)
{
    double sum = 0.0;
    int k;
    for (k = 1; k < n; ++k)
        sum += rows[k][COL("iterations")];
    return n > 1 ? sum / (n - 1) : 0.0;
}

static void periodic_lattice(void)
{
    static const char script[] = "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.01e-3\n"
                                 "contact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
                                 "servo_bc P F 0.999 0 0 0.998 increments 2 accuracy tight remap none update %s file %s\nrun\n";
    static double rows[2][8][CSV_COLS];
    const char *rules[2] = {"secant", "newton"};
    double iterations[2] = {0.0, 0.0};
    int r, k;
    for (r = 0; r < 2; ++r) {
        const int n = run_rule("lattice_P", script, rules[r], rows[r], 8);
        double worst = 0.0;
        CHECK(n == 3);
        for (k = 1; k < n; ++k) {
            const double a = rows[r][k][COL("F11")], b = rows[r][k][COL("F22")];
            const double P11 = -N * KN * (2 * 1.01e-3 - SPACING * a) / ((N - 1) * SPACING);
            const double P22 = -N * KN * (2 * 1.01e-3 - SPACING * b) / ((N - 1) * SPACING);
            worst = fmax(worst, fmax(fabs(rows[r][k][COL("P11")] - P11), fabs(rows[r][k][COL("P22")] - P22)) /
                                    fabs(P11));
            worst = fmax(worst, fmax(fabs(rows[r][k][COL("P12")]), fabs(rows[r][k][COL("P21")])) / fabs(P11));
        }
        CHECK(n == 3 && worst <= 1e-6);
        iterations[r] = n > 0 ? mean_iterations(rows[r], n) : 0.0;
        printf("  newton: frictional 5 x 5 lattice (P), update %s: closed form to %.2e of |P11|, servo "
               "iterations per increment %.1f\n", rules[r], worst, iterations[r]);
    }
    /* the Newton corrections at work (not the secant fallback after 8 without progress) */
    CHECK(iterations[1] > 0.0 && iterations[1] < 0.5 * iterations[0]);
}

static void traction_lattice(void)
{
    static const char script[] = "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1e-3\n"
                                 "contact frictional kn 1e4 ks 0 mu 0\ndensity 2e3\ntimestep 1e-5\n"
                                 "servo_bc T F 0.99 0 0 1 increments 3 accuracy tight update %s file %s\nrun\n";
    static double rows[8][CSV_COLS];
    const int n = run_rule("lattice_T", script, "newton", rows, 8);
    double worst = 0.0;
    int k;
    CHECK(n == 4);
    for (k = 1; k < n; ++k) {
        const double eps = 1.0 - rows[k][COL("F11")], want = -KN * eps * (N - 1) / (N - 1.5);
        worst = fmax(worst, fabs(rows[k][COL("P11")] - want) / fabs(want));
    }
    CHECK(n == 4 && worst <= 1e-5);
    printf("  newton: touching frictionless 5 x 5 lattice (T): P11 = -kn eps (N-1)/(N-3/2) to %.2e, servo "
           "iterations per increment %.1f\n", worst, n > 0 ? mean_iterations(rows, n) : 0.0);
}

static void sphere_lattice(void)
{
    static const char script[] = "dimension 3\nlattice cubic 4 4 4 spacing 2e-3 radius 1.01e-3\n"
                                 "contact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2650\ntimestep 2e-6\n"
                                 "servo_bc P F 0.999 0 0 0 0.998 0 0 0 0.997 accuracy tight update newton file %s\n"
                                 "run\n";
    static double rows[4][SBC_COLUMNS];
    char csv[512], text[1024];
    sbc_error err;
    double worst = 0.0;
    int n = -1, i;
    snprintf(csv, sizeof csv, "%s/newton_spheres.csv", test_tmpdir);
    snprintf(text, sizeof text, script, csv);
    if (sbc_script_run_string(text, "newton_spheres", NULL, &err) == SBC_OK)
        n = csv_read_3d(csv, rows, 4);
    else
        printf("  newton: spheres: %s\n", err.message);
    CHECK(n == 2);
    for (i = 0; i < 3 && n == 2; ++i) {
        const double F = rows[1][COL3(i == 0 ? "F11" : i == 1 ? "F22" : "F33")];
        const double want = -16.0 * KN * (2 * 1.01e-3 - SPACING * F) / (9.0 * SPACING * SPACING);
        worst = fmax(worst, fabs(rows[1][COL3(i == 0 ? "P11" : i == 1 ? "P22" : "P33")] - want) / fabs(want));
    }
    CHECK(n == 2 && worst <= 1e-6);
    printf("  newton: frictional 4^3 sphere lattice (P): closed form to %.2e, %g servo iterations\n", worst,
           n == 2 ? rows[1][COL3("iterations")] : -1.0);
}

static void material_point(void)
{
    static double xy[2 * N * N], rad[N * N];
    sbc_point_def def = sbc_point_def_default();
    double F[9] = {0.9995, 0, 0, 0, 0.999, 0, 0, 0, 1}, P[9], ratio, want11, want22;
    sbc_error err;
    sbc_point *p;
    test_square_lattice(N, SPACING, 1.01e-3, xy, rad);
    def.n = N * N;
    def.x = xy;
    def.r = rad;
    def.words = "P accuracy tight update newton";
    def.law.kn = KN;
    def.law.ks = 2e3;
    def.law.mu = 0.4;
    def.density = 2e3;
    def.dt = 1e-5;
    p = sbc_point_create(&def, &err);
    CHECK(p != NULL);
    if (!p) {
        printf("  newton: point: %s\n", err.message);
        return;
    }
    CHECK(sbc_point_integrate(p, F, P, &ratio, &err) == SBC_POINT_CONVERGED);
    want11 = -N * KN * (2 * 1.01e-3 - SPACING * F[0]) / ((N - 1) * SPACING);
    want22 = -N * KN * (2 * 1.01e-3 - SPACING * F[4]) / ((N - 1) * SPACING);
    CHECK(fabs(P[0] - want11) <= 1e-6 * fabs(want11) && fabs(P[4] - want22) <= 1e-6 * fabs(want11));
    printf("  newton: material point (P): P11 %.10g (closed form %.10g)\n", P[0], want11);
    sbc_point_free(p);
}

static void refusals(void)
{
    sbc_settings s;
    sbc_error err;
    CHECK(sbc_settings_parse_words(&s, "mixed update newton", &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'update': newton takes (P) and (T)") != NULL);
    /* remap none: this host has no remap callback either */
    CHECK(sbc_settings_parse_words(&s, "T update newton remap none", &err) == SBC_OK && s.update == SBC_UPDATE_NEWTON);
    CHECK(test_driver_refused(&s, &err) &&
          strstr(err.message, "keyword 'update': newton needs the host's linearized contact network") != NULL);
}

void test_newton(void)
{
    periodic_lattice();
    traction_lattice();
    sphere_lattice();
    material_point();
    refusals();
}
