/* Keyword interior newton (docs/servo_bc.md, "Interior"): each increment
 * solved as a static equilibrium by Newton on the contact network.
 *
 * - Closed forms at `tight`: the prestressed frictional 5 x 5 lattice
 *   (d = 2 mm, R = 1.01 mm, kn 1e4, ks 2e3 N/m, mu 0.4) under (D) and (P),
 *   P_ii = -N kn (2R - d F_ii) / ((N - 1) d), P12 = P21 = 0, to 1e-6 of |P11|;
 *   the touching frictionless 5 x 5 lattice under (T),
 *   P11 = -kn eps (N - 1) / (N - 3/2), to 1e-5 (test_newton.c); the
 *   lattices in at most two Newton iterations an increment (their answer is
 *   the affine start: none).
 * - A frictionless irregular packing (55 discs, one equilibrium) under (D):
 *   newton equals dynamic at `tight` to 1e-5 of the stress scale.
 * - The frictional irregular packing under (D), (P): every row certified
 *   (the run ends), the same bits in two runs; under (T), where the solve
 *   stalls, the relaxation finishing the increment to a certified row; and
 *   the material point's
 *   condensed tangent after three shear steps against central differences
 *   of the increment's map from the committed state (the FE code's
 *   derivative) to 1e-4 of |C|, under (D), (P) and (T).
 * - A (P) increment whose first solve stalls converges when tried again
 *   with the rotations balanced one by one (no relaxation).
 * - Four frictional points sheared in a batch on 1 and 2 threads: the same
 *   bits.
 * - A (P) point integrated again at its committed F returns its committed P
 *   to 1e-12: the solve starts from the committed frame (fluctuations and
 *   rotations), not from the commands.
 * - The mixed layer (its T components moved by the servo between static
 *   solves) on the frictional packing: every row certified with P22 =
 *   P22*, the same bytes in two runs; on the lattice, test_mixed.c.
 * - Refusals by name: remap x, speed > 0, seal yes, a host driver that
 *   does not solve its interior (cohesive bonds: test_interior_bonds.c). */
#include "check.h"
#include "csv_read.h"
#include "layer.h"
#include "packing_file.h"
#include "tangent_map.h"
#include "tests.h"

#include "sbc/driver.h"
#include "sbc/embedded/script.h"
#include "sbc/material_point.h"
#include "sbc/packing.h"
#include "sbc/settings.h"
#include "base/sparse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N 5
#define SPACING 2e-3
#define KN 1e4

/* the 55-disc irregular periodic packing of the FE^2 points (docs/fe2.md) */
static int packing_path(char *path, size_t cap)
{
    static int made = 0;
    return packing_file("interior_disc55", "dimension 2\ngenerate periodic n0 40 rmin 1e-3 polydispersity 1.5 seed 3 "
                        "strain 0.01\n", path, cap, &made);
}

/* a point of the frictional packing pk (kn KN, ks 5e3 N/m, mu 0.5, 2e3 kg/m^2, dt 1e-4 s) with words */
static sbc_point_def frictional_point(const sbc_packing *pk, const char *words)
{
    sbc_point_def def = sbc_point_def_default();
    def.n = pk->n;
    def.x = pk->x;
    def.r = pk->r;
    def.box = pk->has_box ? pk->box : NULL;
    def.words = words;
    def.law.kn = KN;
    def.law.ks = 5e3;
    def.law.mu = 0.5;
    def.density = 2e3;
    def.dt = 1e-4;
    return def;
}

/* the script (its last "%s" the csv path, before it the words) into rows; the row count or -1 */
static int run_case(const char *tag, const char *script, const char *words, double rows[][CSV_COLS], int max,
                    char *csv, size_t cap)
{
    char text[2048], name[80];
    sbc_error err;
    snprintf(name, sizeof name, "interior_%s", tag);
    snprintf(csv, cap, "%s/%s.csv", test_tmpdir, name);
    snprintf(text, sizeof text, script, words, csv);
    if (sbc_script_run_string(text, name, NULL, &err) != SBC_OK) {
        printf("  interior: %s: %s\n", name, err.message);
        return -1;
    }
    return csv_read(csv, rows, max);
}

static void lattices(void)
{
    static const char prestressed[] = "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.01e-3\n"
                                      "contact frictional kn 1e4 %s\ndensity 2e3\ntimestep 1e-5\n"
                                      "servo_bc %s file %s\nrun\n";
    static const char touching[] = "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1e-3\n"
                                   "contact frictional kn 1e4 ks 0 mu 0\ndensity 2e3\ntimestep 1e-5\n"
                                   "servo_bc %s file %s\nrun\n";
    static double rows[8][CSV_COLS];
    const char *bcs[2] = {"D", "P"};
    char csv[512], script[512], words[160];
    int b, k, n;
    for (b = 0; b < 2; ++b) {
        double worst = 0.0;
        snprintf(script, sizeof script, prestressed, "ks 2e3 mu 0.4", "%s", "%s");
        snprintf(words, sizeof words, "%s F 0.999 0 0 0.998 increments 2 accuracy tight interior newton", bcs[b]);
        n = run_case(bcs[b], script, words, rows, 8, csv, sizeof csv);
        CHECK(n == 3);
        for (k = 1; k < n; ++k) {
            const double a = rows[k][COL("F11")], c = rows[k][COL("F22")];
            const double P11 = -N * KN * (2 * 1.01e-3 - SPACING * a) / ((N - 1) * SPACING);
            const double P22 = -N * KN * (2 * 1.01e-3 - SPACING * c) / ((N - 1) * SPACING);
            worst = fmax(worst, fmax(fabs(rows[k][COL("P11")] - P11), fabs(rows[k][COL("P22")] - P22)) / fabs(P11));
            worst = fmax(worst, fmax(fabs(rows[k][COL("P12")]), fabs(rows[k][COL("P21")])) / fabs(P11));
            CHECK(rows[k][COL("newton_iterations")] <= 2.0); /* the affine start is the answer: 0 */
            if (bcs[b][0] == 'D') /* the frictional lattice: every interior dof stiffened, none held */
                CHECK(rows[k][COL("newton_held")] == 0.0);
        }
        CHECK(n == 3 && worst <= 1e-6);
        printf("  interior: frictional 5 x 5 lattice (%s), newton: closed form to %.2e of |P11|, %g Newton iterations "
               "and %g DEM steps in increment 1\n", bcs[b], worst, n == 3 ? rows[1][COL("newton_iterations")] : -1.0,
               n == 3 ? rows[1][COL("relax_steps")] : -1.0);
    }
    { /* (T) on the touching frictionless lattice */
        double worst = 0.0;
        n = run_case("T", touching, "T F 0.99 0 0 1 increments 3 accuracy tight interior newton", rows, 8, csv,
                     sizeof csv);
        CHECK(n == 4);
        for (k = 1; k < n; ++k) {
            const double eps = 1.0 - rows[k][COL("F11")], want = -KN * eps * (N - 1) / (N - 1.5);
            worst = fmax(worst, fabs(rows[k][COL("P11")] - want) / fabs(want));
        }
        CHECK(n == 4 && worst <= 1e-5);
        printf("  interior: touching frictionless 5 x 5 lattice (T), newton: P11 = -kn eps (N-1)/(N-3/2) to %.2e\n",
               worst);
    }
    { /* frictionless: linear but for the turning contacts */
        double most = 0.0;
        snprintf(script, sizeof script, prestressed, "ks 0 mu 0", "%s", "%s");
        n = run_case("D_frictionless", script, "D F 0.999 0 0 0.998 increments 3 accuracy tight interior newton",
                     rows, 8, csv, sizeof csv);
        CHECK(n == 4);
        for (k = 1; k < n; ++k) {
            most = fmax(most, rows[k][COL("newton_iterations")]);
            /* no contact turns an interior disc: its rotation is held, (N - 2)^2 of them */
            CHECK(rows[k][COL("newton_held")] == (N - 2) * (N - 2));
        }
        CHECK(n == 4 && most <= 2.0);
        printf("  interior: frictionless prestressed lattice (D), newton: at most %g Newton iterations an increment, "
               "%g rotations held ((N - 2)^2 = %d)\n", most, n == 4 ? rows[1][COL("newton_held")] : -1.0, (N - 2) * (N - 2));
    }
}

static const char irregular[] = "dimension 2\nread_packing %s\ncontact frictional kn 1e4 %%s\ndensity 2e3\ntimestep "
                                "1e-4\nservo_bc %%s file %%s\nrun\n";

/* the largest difference of P over the rows of two runs, relative to the largest |P| */
static double path_gap(double a[][CSV_COLS], double b[][CSV_COLS], int n)
{
    static const char *const comp[4] = {"P11", "P12", "P21", "P22"};
    double gap = 0.0, scale = 0.0;
    int k, c;
    for (k = 0; k < n; ++k)
        for (c = 0; c < 4; ++c) {
            gap = fmax(gap, fabs(a[k][COL(comp[c])] - b[k][COL(comp[c])]));
            scale = fmax(scale, fabs(b[k][COL(comp[c])]));
        }
    return scale > 0.0 ? gap / scale : HUGE_VAL;
}

static void frictionless_irregular(void)
{
    static double rows[2][8][CSV_COLS];
    const char *interior[2] = {"dynamic", "newton"};
    char path[512], script[1024], law[64], csv[512], words[160], tag[32];
    int m, n[2] = {-1, -1};
    long steps[2] = {0, 0};
    if (!packing_path(path, sizeof path)) {
        CHECK(0);
        return;
    }
    snprintf(script, sizeof script, irregular, path);
    snprintf(law, sizeof law, "ks 0 mu 0");
    for (m = 0; m < 2; ++m) {
        char full[1024];
        int k;
        snprintf(full, sizeof full, script, law, "%s", "%s");
        snprintf(words, sizeof words, "D F 0.9985 0.003 0 1 increments 3 accuracy tight interior %s", interior[m]);
        snprintf(tag, sizeof tag, "frictionless_%s", interior[m]);
        n[m] = run_case(tag, full, words, rows[m], 8, csv, sizeof csv);
        for (k = 1; k < n[m]; ++k)
            steps[m] += (long)rows[m][k][COL("relax_steps")];
    }
    CHECK(n[0] == 4 && n[1] == 4);
    if (n[0] == 4 && n[1] == 4) {
        const double gap = path_gap(rows[1], rows[0], 4);
        CHECK(gap <= 1e-5);
        printf("  interior: frictionless 55 discs (D): newton against dynamic %.2e of the stress scale; DEM steps %ld "
               "against %ld\n", gap, steps[1], steps[0]);
    }
}

/* the script of the frictional 55 discs (ks 5e3 N/m, mu 0.5) into full, its "%s" the words and the csv; 0 without
   the packing */
static int frictional_script(char *full, size_t cap)
{
    char path[512], script[1024];
    if (!packing_path(path, sizeof path))
        return 0;
    snprintf(script, sizeof script, irregular, path);
    snprintf(full, cap, script, "ks 5e3 mu 0.5", "%s", "%s");
    return 1;
}

static void frictional_irregular(void)
{
    static double rows[8][CSV_COLS];
    const char *bcs[2] = {"D", "P"};
    char full[1024], csv[2][512], words[160], tag[32];
    int b, r;
    if (!frictional_script(full, sizeof full)) {
        CHECK(0);
        return;
    }
    for (b = 0; b < 2; ++b) {
        long steps = 0, iterations = 0;
        int n = -1, k;
        snprintf(words, sizeof words, "%s F 0.9985 0.003 0 1 increments 3 accuracy tight interior newton", bcs[b]);
        for (r = 0; r < 2; ++r) {
            snprintf(tag, sizeof tag, "frictional_%s_%d", bcs[b], r);
            n = run_case(tag, full, words, rows, 8, csv[r], sizeof csv[r]);
            CHECK(n == 4); /* a row that misses its preset stops the run */
        }
        CHECK(same_bytes(csv[0], csv[1]));
        for (k = 1; k < n; ++k) {
            steps += (long)rows[k][COL("relax_steps")];
            iterations += (long)rows[k][COL("newton_iterations")];
            CHECK(rows[k][COL("unbalanced")] <= 1e-7);
        }
        printf("  interior: frictional 55 discs (%s), newton: 3 certified increments in %ld DEM steps and %ld Newton "
               "iterations, two runs %s\n", bcs[b], steps, iterations,
               same_bytes(csv[0], csv[1]) ? "byte for byte" : "DIFFER");
    }
    { /* (T): the free frame's discs roll and every solve stalls; the relaxation finishes each increment from
         the solve's iterate and the rows are certified all the same */
        int n;
        snprintf(words, sizeof words, "T F 0.9985 0.003 0 1 increments 1 accuracy fast interior newton");
        n = run_case("frictional_T", full, words, rows, 8, csv[0], sizeof csv[0]);
        CHECK(n == 2);
        CHECK(n == 2 && rows[1][COL("newton_iterations")] > 0.0 && rows[1][COL("relax_steps")] > 20.0 &&
              rows[1][COL("unbalanced")] <= 1e-3);
        printf("  interior: frictional 55 discs (T), newton: the stalled solve finished by %g DEM steps of relaxation "
               "after %g Newton iterations, unbalanced %g\n", n == 2 ? rows[1][COL("relax_steps")] : -1.0,
               n == 2 ? rows[1][COL("newton_iterations")] : -1.0, n == 2 ? rows[1][COL("unbalanced")] : -1.0);
    }
}

/* a (P) increment of F = (0.99, 0.02; 0, 1) on the frictional 55 discs in one step: the first static solve stalls
   (discs whose contacts all slide sit on a plateau of their moment), and tried again with the rotations balanced one
   by one before each Newton step it converges: the row in the 40 DEM steps of its certification, where the
   relaxation had finished the increment (thousands of steps) */
static void stalled_then_turned(void)
{
    static double rows[4][CSV_COLS];
    char full[1024], csv[512];
    int n;
    if (!frictional_script(full, sizeof full)) {
        CHECK(0);
        return;
    }
    n = run_case("turned", full, "P F 0.99 0.02 0 1 increments 1 accuracy tight interior newton", rows, 4, csv,
                 sizeof csv);
    CHECK(n == 2);
    CHECK(n == 2 && rows[1][COL("relax_steps")] <= 40.0 && rows[1][COL("newton_iterations")] > 0.0 &&
          rows[1][COL("unbalanced")] <= 1e-7);
    printf("  interior: frictional 55 discs (P), F12 0.02 in one increment: %g Newton iterations, %g DEM steps (the "
           "rotations balanced one by one after the first solve stalled)\n",
           n == 2 ? rows[1][COL("newton_iterations")] : -1.0, n == 2 ? rows[1][COL("relax_steps")] : -1.0);
}

/* the mixed layer (bottom D D, sides P P, top D T) on the frictional 55 discs, its stress P22* = -20 N/m held from
   increment 0, sheared by F12 = 0.003 in 2 increments: every row certified with P22 = P22*, the same bytes in two
   runs (the T components moved by the servo between static solves) */
static void mixed_layer(void)
{
    static double rows[8][CSV_COLS];
    char full[1024], csv[2][512];
    long solves = 0, steps = 0;
    int r, k, n = -1;
    if (!frictional_script(full, sizeof full)) {
        CHECK(0);
        return;
    }
    for (r = 0; r < 2; ++r) {
        char tag[32];
        snprintf(tag, sizeof tag, "mixed_%d", r);
        n = run_case(tag, full, "mixed F 1 0.003 0 1 increments 2 stress P22 -20 0 accuracy tight interior newton",
                     rows, 8, csv[r], sizeof csv[r]);
        CHECK(n == 3);
    }
    CHECK(same_bytes(csv[0], csv[1]));
    for (k = 0; k < n; ++k) {
        CHECK_REL(rows[k][COL("P22")], -20.0, 1e-4);
        CHECK(fabs(rows[k][COL("hill_mandel")]) <= 1e-6 && rows[k][COL("unbalanced")] <= 1e-7 &&
              rows[k][COL("newton_iterations")] > 0.0);
        solves += (long)rows[k][COL("iterations")];
        steps += (long)rows[k][COL("relax_steps")];
    }
    printf("  interior: mixed layer on the frictional 55 discs, newton: %d certified rows (P22 %.6f N/m at F12 = "
           "0.003), %ld servo iterations and %ld DEM steps, two runs %s\n", n, n == 3 ? rows[2][COL("P22")] : 0.0,
           solves, steps, same_bytes(csv[0], csv[1]) ? "byte for byte" : "DIFFER");
}

static void consistent_tangent(void)
{
    const char *words[3] = {"D accuracy tight interior newton", "P accuracy tight interior newton", "T accuracy tight interior newton"};
    char path[512];
    sbc_packing pk;
    sbc_error err;
    int w;
    memset(&pk, 0, sizeof pk);
    if (!packing_path(path, sizeof path) || sbc_packing_read(&pk, path, &err) != SBC_OK) {
        CHECK(0);
        return;
    }
    for (w = 0; w < 3; ++w) {
        sbc_point_def def = frictional_point(&pk, words[w]);
        double C[81] = {0}, D[81] = {0}, gap;
        gap = tangent_map_gap(&def, 1, 0, C, D, &err); /* F12 = 0.001 k, F11 = 1 - 0.0005 k */
        if (gap < 0.0)
            printf("  interior: point: %s\n", err.message);
        CHECK(gap >= 0.0 && gap <= 1e-4);
        printf("  interior: material point %s, frictional 55 discs after three shear steps: condensed tangent against "
               "the increment's map by central differences %.2e of |C| (C1111 %.6g, %.6g)\n", words[w], gap, C[0],
               D[0]);
    }
    sbc_packing_free(&pk);
}

/* a (P) point sheared in three committed steps, integrated again at its committed F: its committed P to 1e-12
   (the solve starts at the committed state, the frame's periodic fluctuations and rotations included; from the
   commands' F X_q and zero rotations it iterated back to the equilibrium, 3.6e-11 away, or stalled) */
static void periodic_start_kept(void)
{
    char path[512];
    sbc_packing pk;
    sbc_point_def def;
    sbc_point *p = NULL;
    sbc_error err;
    double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, P[9], Fc[9], Pc[9], ratio, worst = 0.0;
    int k, ok = 1;
    memset(&pk, 0, sizeof pk);
    if (!packing_path(path, sizeof path) || sbc_packing_read(&pk, path, &err) != SBC_OK) {
        CHECK(0);
        return;
    }
    def = frictional_point(&pk, "P accuracy tight");
    p = sbc_point_create(&def, &err);
    for (k = 1; p && ok && k <= 3; ++k) {
        F[1] = 0.001 * k;
        F[0] = 1.0 - 0.0005 * k;
        ok = sbc_point_integrate(p, F, P, &ratio, &err) == SBC_POINT_CONVERGED && sbc_point_commit(p) == SBC_OK;
    }
    CHECK(p != NULL && ok);
    if (p && ok) {
        sbc_point_committed(p, Fc, Pc);
        CHECK(sbc_point_integrate(p, Fc, P, &ratio, &err) == SBC_POINT_CONVERGED);
        for (k = 0; k < 9; ++k)
            worst = fmax(worst, fabs(P[k] - Pc[k]) / fabs(Pc[0]));
        CHECK(worst <= 1e-12);
        printf("  interior: (P) point integrated again at its committed F after three shear steps: P %.2e of |P11| "
               "from the committed P\n", worst);
    }
    sbc_point_free(p);
    sbc_packing_free(&pk);
}

/* four frictional 55-disc points (interior newton, the default) sheared in a batch on 1 and on 2 threads:
   the same P bit for bit (each point's increment is a function of its committed state and F alone) */
static void threads(void)
{
    enum { COUNT = 4 };
    char path[512];
    sbc_packing pk;
    sbc_point *pts[2][COUNT];
    double F[9 * COUNT], P[2][9 * COUNT], ratio[COUNT];
    int status[COUNT], k, t, made = 1, converged = 0;
    sbc_error err;
    memset(&pk, 0, sizeof pk);
    memset(pts, 0, sizeof pts);
    if (!packing_path(path, sizeof path) || sbc_packing_read(&pk, path, &err) != SBC_OK) {
        CHECK(0);
        return;
    }
    for (k = 0; k < COUNT; ++k) {
        sbc_point_def def = frictional_point(&pk, "P accuracy tight");
        memset(&F[9 * k], 0, sizeof(double) * 9);
        F[9 * k] = 1.0 - 0.0005 * k;
        F[9 * k + 1] = 0.001 * (k + 1);
        F[9 * k + 4] = F[9 * k + 8] = 1.0;
        for (t = 0; t < 2; ++t)
            made &= (pts[t][k] = sbc_point_create(&def, &err)) != NULL;
    }
    CHECK(made);
    if (made) {
        converged = sbc_points_integrate(pts[0], COUNT, F, P[0], status, ratio, 1, &err) == SBC_OK;
        converged &= sbc_points_integrate(pts[1], COUNT, F, P[1], status, ratio, 2, &err) == SBC_OK;
        CHECK(converged && memcmp(P[0], P[1], sizeof P[0]) == 0);
    }
    printf("  interior: 4 frictional 55-disc points (P, newton) on 1 and 2 threads: %s\n",
           converged && memcmp(P[0], P[1], sizeof P[0]) == 0 ? "the same bits" : "DIFFER");
    for (t = 0; t < 2; ++t)
        for (k = 0; k < COUNT; ++k)
            sbc_point_free(pts[t][k]);
    sbc_packing_free(&pk);
}

static void refusals(void)
{
    sbc_settings s;
    sbc_error err;
    CHECK(sbc_settings_parse_words(&s, "mixed stress P22 -1 2 interior newton", &err) == SBC_OK && s.interior == SBC_INTERIOR_NEWTON);
    CHECK(sbc_settings_parse_words(&s, "P interior newton remap x", &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'remap'") != NULL);
    CHECK(sbc_settings_parse_words(&s, "P speed 0.01 interior newton", &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'speed'") != NULL);
    CHECK(sbc_settings_parse_words(&s, "mixed stress P22 -1 2 seal yes interior newton", &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'seal': yes puts walls") != NULL);
    CHECK(sbc_settings_parse_words(&s, "P interior sideways", &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'interior': value 'sideways' is not valid (expected dynamic or newton)"));
    CHECK(sbc_settings_parse_words(&s, "T interior newton", &err) == SBC_OK && s.interior == SBC_INTERIOR_NEWTON &&
          s.remap == 0 && s.speed == 0.0);
    /* a host that relaxes its interior itself (LAMMPS, LIGGGHTS, YADE through the driver) */
    CHECK(test_driver_refused(&s, &err) &&
          strstr(err.message, "keyword 'interior': newton solves the interior's static equilibrium") != NULL);
}

/* a core built without UMFPACK (make SPARSE=no) refuses the keyword by name and keeps the points dynamic */
static void without_sparse(void)
{
    sbc_settings s;
    sbc_error err;
    CHECK(sbc_settings_parse_words(&s, "D interior newton", &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'interior': newton needs the sparse direct solver (UMFPACK)") != NULL);
    CHECK(sbc_settings_parse_words(&s, "D", &err) == SBC_OK && s.interior == SBC_INTERIOR_DYNAMIC);
    printf("  interior: without a sparse solver: %s\n", err.message);
}

void test_interior(void)
{
    if (!sbc_sparse_available()) {
        without_sparse();
        return;
    }
    lattices();
    frictionless_irregular();
    frictional_irregular();
    stalled_then_turned();
    mixed_layer();
    consistent_tangent();
    periodic_start_kept();
    threads();
    refusals();
}
