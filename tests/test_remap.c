/* Keyword remap x (docs/servo_bc.md, "Remap"): the interior follows the
 * affine part of each increment's change of F while the frame travels there.
 *
 * - Prestressed frictional lattices under F = diag(a, b) (2D, N x N) and
 *   diag(a, b, c) (3D, N^3): the affine state is the equilibrium
 *   (test_accuracy.c), so with remap every increment is one relaxation
 *   window for (D) and one servo iteration (two windows) for (P), and the
 *   rows meet the closed forms
 *     2D  P_ii = -N kn (2R - d F_ii) / ((N - 1) d)
 *     3D  P_ii = -N^2 kn (2R - d F_ii) / ((N - 1)^2 d^2)
 *   to 1e-9 of |P11|, off-diagonals below 1e-9 of |P11|.
 * ((T) on a lattice and a frictionless irregular packing with and without
 * remap are in tests/remap.sh, too long for the sanitizer and valgrind runs.)
 * - A material point (material_point.h) of the frictional 5 x 5 lattice
 *   under (P) with remap x: two integrates (the second after a commit) meet
 *   the closed form to 1e-9, as the runner's rows do.
 * - The words: `remap y` refused by name and value; a host driver without
 *   the remap callback refuses `remap x`. */
#include "check.h"
#include "csv_read.h"
#include "layer.h"
#include "tests.h"

#include "sbc/driver.h"
#include "sbc/embedded/script.h"
#include "sbc/material_point.h"
#include "sbc/settings.h"
#include "sbc/tensor.h"

#include <stdio.h>
#include <string.h>

enum { INCREMENTS = 3, WINDOW = 20 };

/* runs script with "REMAP" replaced by the remap words, into csv; rows read (3D: wide rows) */
static int run_case(const char *tag, const char *script, int dim, double rows[][SBC_COLUMNS], int max)
{
    char csv[512], text[2048];
    sbc_error err;
    snprintf(csv, sizeof csv, "%s/remap_%s.csv", test_tmpdir, tag);
    snprintf(text, sizeof text, script, csv);
    if (sbc_script_run_string(text, tag, NULL, &err) != SBC_OK) {
        printf("  %s: %s\n", tag, err.message);
        return -1;
    }
    if (dim == 3)
        return csv_read_3d(csv, rows, max);
    {
        static double flat[16][CSV_COLS];
        int n = csv_read(csv, flat, max < 16 ? max : 16), k, c;
        for (k = 0; k < n; ++k)
            for (c = 0; c < CSV_COLS; ++c)
                rows[k][c] = flat[k][c];
        return n;
    }
}

/* the lattice closed forms with remap: rows, iterations, steps */
static void lattices(void)
{
    const double d = 2e-3, R = 1.02e-3, kn = 1e4;
    static double rows[INCREMENTS + 2][SBC_COLUMNS];
    static const char *bcs[2] = {"D", "P"};
    int dim, b;
    for (dim = 2; dim <= 3; ++dim)
        for (b = 0; b < 2; ++b) {
            const int N = dim == 2 ? 9 : 4;
            char script[1024], tag[32];
            double worst = 0.0;
            int n, k, steps_ok = 1, iterations_ok = 1;
            snprintf(tag, sizeof tag, "lattice%d_%s", dim, bcs[b]);
            snprintf(script, sizeof script,
                     "dimension %d\nlattice %s spacing %.17g radius %.17g\n"
                     "contact frictional kn %.17g ks %.17g mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
                     "servo_bc %s F %s increments %d accuracy tight remap x file %%s\nrun\n",
                     dim, dim == 2 ? "square 9 9" : "cubic 4 4 4", d, R, kn, kn / 5, bcs[b],
                     dim == 2 ? "0.99 0 0 0.995" : "0.99 0 0 0 0.995 0 0 0 0.993", INCREMENTS);
            n = run_case(tag, script, dim, rows, INCREMENTS + 2);
            CHECK(n == INCREMENTS + 1);
            if (n != INCREMENTS + 1)
                continue;
            for (k = 1; k < n; ++k) {
                const double *r = rows[k];
                const double scale = dim == 2 ? N * kn / ((N - 1) * d) : N * N * kn / ((N - 1.0) * (N - 1.0) * d * d);
                const double P11 = -scale * (2 * R - d * r[sbc_column_index(dim, "F11")]);
                int i, j;
                for (i = 0; i < dim; ++i)
                    for (j = 0; j < dim; ++j) {
                        char F[8], P[8];
                        const int f = sbc_column_index(dim, sbc_tensor_component_name("F", i, j, F));
                        const int p = sbc_column_index(dim, sbc_tensor_component_name("P", i, j, P));
                        const double want = i == j ? -scale * (2 * R - d * r[f]) : 0.0;
                        worst = fmax(worst, fabs(r[p] - want) / fabs(P11));
                    }
                steps_ok &= (long)r[sbc_column_index(dim, "relax_steps")] == (b == 0 ? WINDOW : 2 * WINDOW);
                iterations_ok &= (int)r[sbc_column_index(dim, "iterations")] == b;
            }
            printf("  remap x, %s (%s), %d increments: closed form to %.2e of |P11|, %s DEM steps per increment\n",
                   dim == 2 ? "9 x 9 lattice" : "4^3 lattice", bcs[b], INCREMENTS, worst,
                   steps_ok ? (b == 0 ? "20 (one window)" : "40 (one servo iteration)") : "NOT the window's");
            CHECK(worst < 1e-9);
            CHECK(steps_ok);
            CHECK(iterations_ok);
        }
}

static void refusals(void)
{
    sbc_settings s;
    sbc_error err;
    CHECK(sbc_settings_parse_words(&s, "P remap y", &err) == SBC_ERR_INPUT);
    CHECK(strstr(err.message, "keyword 'remap': value 'y' is not valid (expected x or none)") != NULL);
    CHECK(sbc_settings_parse_words(&s, "P remap x", &err) == SBC_OK && s.remap == 1);
    /* the presets' own: x under fast, balanced and tight, none under paper */
    CHECK(sbc_settings_parse_words(&s, "P", &err) == SBC_OK && s.remap == 1);
    CHECK(sbc_settings_parse_words(&s, "P accuracy fast", &err) == SBC_OK && s.remap == 1);
    CHECK(sbc_settings_parse_words(&s, "P accuracy tight", &err) == SBC_OK && s.remap == 1);
    CHECK(sbc_settings_parse_words(&s, "P accuracy paper", &err) == SBC_OK && s.remap == 0);
    CHECK(sbc_settings_parse_words(&s, "P remap none", &err) == SBC_OK && s.remap == 0);
}

/* the material point aims its controller itself (sbc_driver_remap after sbc_controller_aim) */
static void material_point(void)
{
    enum { N = 5 };
    const double d = 2e-3, R = 1.02e-3, kn = 1e4;
    static double xy[2 * N * N], rad[N * N];
    sbc_point_def def = sbc_point_def_default();
    sbc_point *p;
    sbc_error err;
    double worst = 0.0;
    int k, ok = 1;
    test_square_lattice(N, d, R, xy, rad);
    def.n = N * N;
    def.x = xy;
    def.r = rad;
    def.words = "P accuracy tight remap x";
    def.law.kn = kn;
    def.law.ks = kn / 5;
    def.law.mu = 0.4;
    def.density = 2e3;
    def.dt = 1e-5;
    p = sbc_point_create(&def, &err);
    CHECK(p != NULL);
    if (!p) {
        printf("  %s\n", err.message);
        return;
    }
    for (k = 1; k <= 2; ++k) {
        const double a = 1.0 - 0.001 * k, b = 1.0 - 0.0005 * k;
        double F[9] = {0}, P[9], ratio;
        F[0] = a;
        F[4] = b;
        ok &= sbc_point_integrate(p, F, P, &ratio, &err) == SBC_POINT_CONVERGED;
        sbc_point_commit(p);
        worst = fmax(worst, fabs(P[0] + N * kn * (2 * R - d * a) / ((N - 1) * d)) / fabs(P[0]));
        worst = fmax(worst, fabs(P[4] + N * kn * (2 * R - d * b) / ((N - 1) * d)) / fabs(P[0]));
        worst = fmax(worst, fmax(fabs(P[1]), fabs(P[3])) / fabs(P[0]));
    }
    printf("  material point, frictional 5 x 5 lattice, (P) remap x: two integrates on the closed form to %.2e\n", worst);
    CHECK(ok && worst < 1e-9);
    sbc_point_free(p);
}

void test_remap(void)
{
    refusals();
    material_point();
    lattices();
}
