/* interior newton with cohesive bonds (eqs. 7-8; docs/servo_bc.md, "Interior"):
 * - The touching, bonded 4 x 4 lattice (Table 6) stretched under (D) to
 *   F11 = 1.001: every horizontal bond at kn d e, P11 = N kn e / (N - 1) to
 *   1e-9, all 24 bonds intact; at F11 = 1.002 (over fn_u / (kn d) = 1.5e-3)
 *   the 12 horizontal bonds break, the solve reports them broken one by one,
 *   and P = 0: the same as the relaxation.
 * - The same lattice sheared (elastic: one equilibrium): newton equals
 *   dynamic at `tight` to 1e-6 of the stress.
 * - A bonded irregular packing: the incremental shear spring of eq. 7 makes
 *   the response depend on the path, so newton and dynamic part at coarse
 *   increments; halving them, both converge to the same path (to 1e-4 at 32
 *   increments).
 * - The cohesive mixed layer (P22 held by the servo between static solves):
 *   every row certified, P22 = P22*, bonds broken, two runs byte for byte.
 * - Bonded 55-disc material points after three shear steps with bonds broken
 *   on the way: the condensed tangent against central differences of the
 *   increment's map under (D), (P), (T), at most 1e-4 of |C|. */
#include "check.h"
#include "csv_read.h"
#include "packing_file.h"
#include "tangent_map.h"
#include "tests.h"

#include "sbc/embedded/script.h"
#include "sbc/material_point.h"
#include "sbc/packing.h"
#include "base/sparse.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Table 6 in SI: kn 1e8 N/m, fn_u 300 N; the lattice's spacing 2e-3 m */
#define KB 1e8
#define LATTICE "dimension 2\nlattice square 4 4 spacing 2e-3 radius 1e-3\n" \
                "contact cohesive kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2 mu 0.6\ndensity 1e4\ntimestep 5e-6\n"

/* the script text (a format whose last two "%s" are the words and the csv) run into rows, the log to tag.log;
   the row count or -1 */
static int run_bonded(const char *tag, const char *script, const char *words, double rows[][CSV_COLS], int max,
                      char *csv, size_t cap)
{
    char text[2048], name[80], logname[512];
    sbc_error err;
    FILE *log;
    int ok;
    snprintf(name, sizeof name, "interior_bonds_%s", tag);
    snprintf(csv, cap, "%s/%s.csv", test_tmpdir, name);
    snprintf(logname, sizeof logname, "%s/%s.log", test_tmpdir, name);
    snprintf(text, sizeof text, script, words, csv);
    log = fopen(logname, "w");
    ok = log && sbc_script_run_string(text, name, log, &err) == SBC_OK;
    if (log)
        fclose(log);
    if (!ok) {
        printf("  interior bonds: %s: %s\n", name, log ? err.message : "no log");
        return -1;
    }
    return csv_read(csv, rows, max);
}

static int log_has(const char *tag, const char *text)
{
    char logname[512];
    snprintf(logname, sizeof logname, "%s/interior_bonds_%s.log", test_tmpdir, tag);
    return file_contains(logname, text);
}

static void lattice_tension(void)
{
    static double rows[2][4][CSV_COLS];
    const char *modes[2] = {"dynamic", "newton"};
    const double e = 1e-3, closed = 4.0 * KB * e / 3.0; /* N kn e / (N - 1), N = 4 */
    char csv[512], words[160], tag[40];
    int m, n[2];
    for (m = 0; m < 2; ++m) {
        snprintf(words, sizeof words, "D F 1.002 0 0 1 increments 2 accuracy tight interior %s", modes[m]);
        snprintf(tag, sizeof tag, "tension_%s", modes[m]);
        n[m] = run_bonded(tag, LATTICE "servo_bc %s file %s\nrun\n", words, rows[m], 4, csv, sizeof csv);
        CHECK(n[m] == 3);
        if (n[m] != 3)
            return;
        CHECK_REL(rows[m][1][COL("P11")], closed, 1e-9);
        CHECK(fabs(rows[m][2][COL("P11")]) <= 1e-9 * closed && fabs(rows[m][2][COL("P22")]) <= 1e-9 * closed);
        CHECK(log_has(tag, "bonds intact 24") && log_has(tag, "bonds intact 12"));
    }
    CHECK(rows[1][2][COL("newton_iterations")] > 0.0 && log_has("tension_newton", "12 bonds broken"));
    printf("  interior bonds: bonded 4 x 4 lattice stretched, newton: P11 %.10g N/m (closed form %.10g), then the 12 "
           "horizontal bonds broken one by one, P11 %.2e (dynamic %.2e), %g Newton iterations\n",
           rows[1][1][COL("P11")], closed, rows[1][2][COL("P11")], rows[0][2][COL("P11")],
           rows[1][2][COL("newton_iterations")]);
}

static void lattice_shear(void)
{
    static double rows[2][4][CSV_COLS];
    const char *modes[2] = {"dynamic", "newton"};
    char csv[512], words[160], tag[40];
    int m, k;
    double worst = 0.0;
    for (m = 0; m < 2; ++m) {
        snprintf(words, sizeof words, "D F 1 1e-4 0 1 increments 2 accuracy tight interior %s", modes[m]);
        snprintf(tag, sizeof tag, "shear_%s", modes[m]);
        CHECK(run_bonded(tag, LATTICE "servo_bc %s file %s\nrun\n", words, rows[m], 4, csv, sizeof csv) == 3);
    }
    for (k = 1; k < 3; ++k)
        worst = fmax(worst, fabs(rows[1][k][COL("P12")] - rows[0][k][COL("P12")]) / fabs(rows[0][2][COL("P12")]));
    CHECK(fabs(rows[0][2][COL("P12")]) > 1e3 && worst <= 1e-6);
    printf("  interior bonds: bonded 4 x 4 lattice sheared: newton against dynamic %.2e of P12 = %.6g N/m\n", worst,
           rows[0][2][COL("P12")]);
}

static int packing_path(char *path, size_t cap)
{
    static int made = 0;
    return packing_file("interior_bonds37", "dimension 2\ngenerate periodic n0 25 rmin 0.8e-3 polydispersity 1.5 "
                        "seed 1\n", path, cap, &made);
}

static const char irregular[] = "dimension 2\nread_packing %s\ncontact cohesive kn 1e8 ks 4e7 kr 20 fn 2400 fs 480 "
                                "mr 1.6 mu 0.6\ndensity 1e4\ntimestep 5e-6\nservo_bc %%s file %%s\nrun\n";

/* the relative gap of P11 between newton and dynamic at the end of the path, in increments */
static double path_gap(const char *script, int increments)
{
    static double rows[2][40][CSV_COLS];
    const char *modes[2] = {"dynamic", "newton"};
    char csv[512], words[200], tag[40];
    int m, n[2];
    for (m = 0; m < 2; ++m) {
        snprintf(words, sizeof words, "D F 0.998 0.004 0 0.998 increments %d accuracy tight interior %s", increments,
                 modes[m]);
        snprintf(tag, sizeof tag, "path%d_%s", increments, modes[m]);
        n[m] = run_bonded(tag, script, words, rows[m], 40, csv, sizeof csv);
    }
    if (n[0] != increments + 1 || n[1] != n[0])
        return HUGE_VAL;
    return fabs(rows[1][increments][COL("P11")] - rows[0][increments][COL("P11")]) /
           fabs(rows[0][increments][COL("P11")]);
}

static void irregular_path(void)
{
    char path[512], script[1024];
    double gap[3];
    const int inc[3] = {2, 8, 32};
    int k;
    if (!packing_path(path, sizeof path)) {
        CHECK(0);
        return;
    }
    snprintf(script, sizeof script, irregular, path);
    for (k = 0; k < 3; ++k)
        gap[k] = path_gap(script, inc[k]);
    CHECK(gap[1] < 0.25 * gap[0] && gap[2] <= 1e-4);
    printf("  interior bonds: 37 bonded discs, F = (0.998, 0.004; 0, 0.998) in 2, 8, 32 increments: newton against "
           "dynamic %.2e, %.2e, %.2e of P11\n", gap[0], gap[1], gap[2]);
}

static void mixed_layer(void)
{
    static double rows[2][8][CSV_COLS];
    char path[512], script[1024], csv[2][512], tag[40];
    int r, k, n = 0;
    if (!packing_path(path, sizeof path)) {
        CHECK(0);
        return;
    }
    snprintf(script, sizeof script, irregular, path);
    for (r = 0; r < 2; ++r) {
        snprintf(tag, sizeof tag, "layer_%d", r);
        n = run_bonded(tag, script, "mixed F 1 0.004 0 1 increments 2 stress P22 -1.05e6 3 interior newton",
                       rows[r], 8, csv[r], sizeof csv[r]);
        CHECK(n == 6);
    }
    CHECK(same_bytes(csv[0], csv[1]) && log_has("layer_0", "bonds broken (the worst first)"));
    for (k = 1; k < n; ++k) {
        const double target = k <= 3 ? -1.05e6 * k / 3.0 : -1.05e6;
        CHECK(fabs(rows[0][k][COL("P22")] - target) <= 1e-4 * 1.05e6);
        CHECK(rows[0][k][COL("unbalanced")] <= 1e-4 && fabs(rows[0][k][COL("hill_mandel")]) <= 1e-4 &&
              rows[0][k][COL("newton_iterations")] > 0.0);
    }
    printf("  interior bonds: cohesive mixed layer on 37 discs, newton: %d certified rows, P22 %.6g N/m at the end, "
           "two runs %s\n", n, n == 6 ? rows[0][5][COL("P22")] : 0.0, same_bytes(csv[0], csv[1]) ? "byte for byte" :
           "DIFFER");
}

static void condensed_tangent(void)
{
    const char *words[3] = {"D accuracy tight interior newton", "P accuracy tight interior newton",
                            "T accuracy tight interior newton"};
    static int made = 0;
    char path[512];
    sbc_packing pk;
    sbc_error err;
    int w, s;
    memset(&pk, 0, sizeof pk);
    if (!packing_file("interior_disc55", "dimension 2\ngenerate periodic n0 40 rmin 1e-3 polydispersity 1.5 seed 3 "
                      "strain 0.01\n", path, sizeof path, &made) ||
        sbc_packing_read(&pk, path, &err) != SBC_OK) {
        CHECK(0);
        return;
    }
    for (w = 0; w < 3; ++w) {
        double gap[2], C[2][81], D[81];
        for (s = 0; s < 2; ++s) { /* strong bonds (none breaks), then weak ones (some break on the path) */
            sbc_point_def def = sbc_point_def_default();
            sbc_cohesive law = {1e4, 5e3, 1e-3, s ? 0.02 : 1e9, s ? 0.02 : 1e9, s ? 0.02 : 1e9, 0.5};
            def.n = pk.n;
            def.x = pk.x;
            def.r = pk.r;
            def.box = pk.has_box ? pk.box : NULL;
            def.words = words[w];
            def.law.kn = 1e4;
            def.law.ks = 5e3;
            def.law.mu = 0.5;
            def.density = 2e3;
            def.dt = 1e-4;
            def.bonds = &law;
            gap[s] = tangent_map_gap(&def, 1, 0, C[s], D, &err); /* F12 = 0.001 k, F11 = 1 - 0.0005 k */
            if (gap[s] < 0.0)
                printf("  interior bonds: point: %s\n", err.message);
            CHECK(gap[s] >= 0.0 && gap[s] <= 1e-4);
        }
        CHECK(fabs(C[1][10] - C[0][10]) > 0.01 * fabs(C[0][10])); /* the broken bonds soften C1212 */
        printf("  interior bonds: bonded 55-disc point %c after three shear steps: condensed tangent against the "
               "increment's map %.2e of |C| (bonds intact), %.2e (bonds broken on the way; C1212 %.6g against %.6g)\n",
               words[w][0], gap[0], gap[1], C[1][10], C[0][10]);
    }
    sbc_packing_free(&pk);
}

void test_interior_bonds(void)
{
    if (!sbc_sparse_available()) { /* interior newton is refused by name there (test_interior.c) */
        printf("  interior bonds: the core has no sparse solver: interior newton is refused, nothing to compare\n");
        return;
    }
    lattice_tension();
    lattice_shear();
    irregular_path();
    mixed_layer();
    condensed_tangent();
}
