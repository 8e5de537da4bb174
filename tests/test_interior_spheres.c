/* Keyword interior newton on sphere packings (docs/servo_bc.md, "Interior"):
 *
 * - The increment's contact block (contact_blocks.c) against central
 *   differences of the loads of sbc_spring_3d_at, at 2 000 random states
 *   (sticking and sliding, rotations up to 0.5 rad since the committed
 *   state): to 1e-6 of the block's largest entry.
 * - Closed forms at `tight`: the prestressed frictional 4^3 lattice
 *   (d = 2 mm, R = 1.02 mm, kn 1e4, ks 5e3 N/m, mu 0.5) under (D) and (P),
 *   P_ii = -N^2 kn (2R - d F_ii) / ((N - 1)^2 d^2), to 1e-6 of max |P|, in at
 *   most two Newton iterations an increment; the touching frictionless
 *   lattice under (T), P_ii = -kn (1 - F_ii) (N - 1)^2 / (d (N - 3/2)^2), to
 *   1e-5; every solve converged (its overlaps of 4e-9 m are at the
 *   round-off floor of statics.c's attainable). The 3D layer (mixed) on the
 *   touching lattice: its stress stage's closed form to 1e-9.
 * - An irregular packing (71 spheres) without friction, one equilibrium:
 *   newton equals dynamic under (D) to 1e-6 of the stress scale.
 * - The same packing with friction under (D) and (P) at `tight`: every solve
 *   converged (no relaxation beyond the certifying steps), the rows
 *   certified, the same bits in two runs. */
#include "check.h"
#include "csv_read.h"
#include "packing_file.h"
#include "tangent_map.h"
#include "tests.h"

#include "host/contact_blocks.h"
#include "sbc/embedded/script.h"
#include "sbc/material_point.h"
#include "sbc/packing.h"
#include "sbc/tensor.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the loads (f_i, m_i, f_j, m_j) of a contact at (x, theta) whose increment started at (x0, theta0, fs0) */
static void contact_loads(const double x[6], const double th[6], const double x0[6], const double th0[6],
                          const double fs0[3], const sbc_frictional *law, const double r[2], double out[12])
{
    sbc_spring_3d sp;
    double l0[3], da[3], db[3], f[3], ra[3], rb[3];
    int q;
    for (q = 0; q < 3; ++q) {
        l0[q] = x0[3 + q] - x0[q];
        da[q] = th[q] - th0[q];
        db[q] = th[3 + q] - th0[3 + q];
    }
    sbc_spring_3d_at(x, x + 3, r[0], r[1], l0, da, db, fs0, law, &sp);
    for (q = 0; q < 3; ++q) {
        f[q] = -law->kn * sp.dn * sp.n[q] + sp.fs[q];
        ra[q] = sp.s * sp.n[q];
        rb[q] = (sp.s - sp.L) * sp.n[q];
        out[6 + q] = -f[q];
    }
    memcpy(out, f, sizeof f);
    sbc_cross3(ra, f, out + 3);
    sbc_cross3(f, rb, out + 9);
}

static double uniform(unsigned *state) /* in [-0.5, 0.5] */
{
    *state = *state * 1103515245u + 12345u;
    return (double)((*state >> 8) & 0xffffu) / 65535.0 - 0.5;
}

static void block_derivative(void)
{
    unsigned state = 7;
    double worst = 0.0;
    int trial, sliding = 0, tested = 0;
    for (trial = 0; trial < 2000; ++trial) {
        double x0[6], th0[6], x[6], th[6], fs0[3], r[2] = {1.0e-3, 1.1e-3}, Lp[12], Lm[12], most = 0.0, off = 0.0;
        double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST];
        const double turn = trial % 3 == 0 ? 1.0 : 1e-3;
        int ij[2] = {0, 1}, k, q;
        sbc_network net;
        sbc_spring_3d sp;
        memset(&net, 0, sizeof net);
        net.law.kn = 1e4;
        net.law.ks = 5e3;
        net.law.mu = trial % 2 ? 0.5 : 0.05;
        for (q = 0; q < 3; ++q) {
            x0[q] = 1e-5 * uniform(&state);
            x0[3 + q] = (q == 0 ? 2.05e-3 : 0.0) + 1e-4 * uniform(&state);
            th0[q] = uniform(&state);
            th0[3 + q] = uniform(&state);
            fs0[q] = 0.1 * uniform(&state);
        }
        for (q = 0; q < 6; ++q) {
            x[q] = x0[q] + 2e-6 * uniform(&state);
            th[q] = th0[q] + turn * uniform(&state);
        }
        net.dim = 3;
        net.n = 2;
        net.x = x;
        net.r = r;
        net.npair = 1;
        net.i = ij;
        net.j = ij + 1;
        net.x0 = x0;
        net.theta0 = th0;
        net.theta = th;
        net.fs0 = fs0;
        if (!sbc_contact_block(&net, 0, B))
            continue;
        ++tested;
        {
            double l0[3], da[3], db[3];
            for (q = 0; q < 3; ++q) {
                l0[q] = x0[3 + q] - x0[q];
                da[q] = th[q] - th0[q];
                db[q] = th[3 + q] - th0[3 + q];
            }
            sbc_spring_3d_at(x, x + 3, r[0], r[1], l0, da, db, fs0, &net.law, &sp);
            sliding += sp.c < 1.0;
        }
        for (k = 0; k < 12; ++k) { /* column k: dof k of (u_i, theta_i, u_j, theta_j); moments and rotations
                                      in N and m through R = 1e-3 m */
            const int translation = k % 6 < 3, slot = 3 * (k / 6) + k % 3;
            const double h = translation ? 1e-11 : 1e-8;
            double xp[6], tp[6];
            memcpy(xp, x, sizeof xp);
            memcpy(tp, th, sizeof tp);
            *(translation ? &xp[slot] : &tp[slot]) += h;
            contact_loads(xp, tp, x0, th0, fs0, &net.law, r, Lp);
            *(translation ? &xp[slot] : &tp[slot]) -= 2.0 * h;
            contact_loads(xp, tp, x0, th0, fs0, &net.law, r, Lm);
            for (q = 0; q < 12; ++q) {
                const double scale = (q % 6 < 3 ? 1.0 : 1e3) * (translation ? 1.0 : 1e3);
                off = fmax(off, fabs((Lp[q] - Lm[q]) / (2.0 * h) - B[q][k]) / scale);
                most = fmax(most, fabs(B[q][k]) / scale);
            }
        }
        worst = fmax(worst, off / most);
    }
    CHECK(tested > 1000 && sliding > 100 && worst <= 1e-6);
    printf("  interior spheres: the increment's contact block against central differences at %d states (%d sliding): "
           "%.2e of its largest entry\n", tested, sliding, worst);
}

/* the script with its "%s" (the csv path) filled, run; the row count or -1 */
static int run_3d(const char *tag, const char *script, double rows[][SBC_COLUMNS], int max, char *csv, size_t cap)
{
    char text[4096], name[80];
    sbc_error err;
    snprintf(name, sizeof name, "interior_spheres_%s", tag);
    snprintf(csv, cap, "%s/%s.csv", test_tmpdir, name);
    snprintf(text, sizeof text, script, csv);
    if (sbc_script_run_string(text, name, NULL, &err) != SBC_OK) {
        printf("  interior spheres: %s: %s\n", name, err.message);
        return -1;
    }
    return csv_read_3d(csv, rows, max);
}

static void lattices(void)
{
    static const struct {
        const char *bc;
        double R, ks, mu;
    } cases[] = {{"D F 0.999 0 0 0 0.998 0 0 0 0.997", 1.02e-3, 5e3, 0.5},
                 {"P F 0.999 0 0 0 0.998 0 0 0 0.997", 1.02e-3, 5e3, 0.5},
                 {"T F 0.999998 0 0 0 0.999999 0 0 0 1", 1e-3, 0.0, 0.0}};
    const double N = 4.0, d = 2e-3, kn = 1e4;
    static double rows[4][SBC_COLUMNS];
    size_t m;
    for (m = 0; m < sizeof cases / sizeof cases[0]; ++m) {
        const int touching = cases[m].bc[0] == 'T';
        char script[1024], csv[512], tag[8];
        double worst = 0.0, pmax = 0.0, most = 0.0, steps = 0.0;
        int n, k, i, j;
        snprintf(script, sizeof script, "dimension 3\nlattice cubic 4 4 4 spacing 2e-3 radius %g\n"
                 "contact frictional kn 1e4 ks %g mu %g\ndensity 224962.886\ntimestep 1e-5\n"
                 "servo_bc %s increments 2 accuracy tight interior newton file %%s\nrun\n", cases[m].R, cases[m].ks,
                 cases[m].mu, cases[m].bc);
        snprintf(tag, sizeof tag, "%c", cases[m].bc[0]);
        n = run_3d(tag, script, rows, 4, csv, sizeof csv);
        CHECK(n == 3);
        for (k = 1; k < n; ++k) {
            for (i = 0; i < 3; ++i)
                for (j = 0; j < 3; ++j) {
                    const double F = rows[k][COL3(i == 0 ? "F11" : i == 1 ? "F22" : "F33")];
                    char name[32];
                    double want = 0.0;
                    if (i == j)
                        want = touching ? -kn * (1.0 - F) * (N - 1) * (N - 1) / (d * (N - 1.5) * (N - 1.5))
                                        : -N * N * kn * (2.0 * cases[m].R - d * F) / ((N - 1) * (N - 1) * d * d);
                    snprintf(name, sizeof name, "P%d%d", i + 1, j + 1);
                    worst = fmax(worst, fabs(rows[k][COL3(name)] - want));
                    pmax = fmax(pmax, fabs(want));
                }
            most = fmax(most, rows[k][COL3("newton_iterations")]);
            steps = fmax(steps, rows[k][COL3("relax_steps")]);
        }
        CHECK(n == 3 && worst <= (touching ? 1e-5 : 1e-6) * pmax);
        CHECK(n == 3 && steps <= 40.0); /* every solve converged: the certifying steps alone */
        if (!touching) /* the affine start is the answer */
            CHECK(n == 3 && most <= 2.0);
        printf("  interior spheres: 4^3 lattice (%c), newton: closed form to %.2e of max |P|, at most %g Newton "
               "iterations and %g DEM steps an increment\n", cases[m].bc[0], pmax > 0.0 ? worst / pmax : -1.0, most,
               steps);
    }
}

/* The 3D layer (zlo D D D, zhi D D T, the side faces P P P) on the touching frictionless 4^3 lattice under a
 * stress stage to P33* = -1e4 N/m^2 in 2 increments: F33 = 1 - p d (N - 3/2)^2 / (kn (N - 1)^2) (test_frame3d.c's
 * closed form) and P33 = P33* at its end, P33* / 2 half way, every static solve converged (the T components moved by
 * the servo between them) */
static void layer(void)
{
    const double N = 4.0, d = 2e-3, kn = 1e4, p = 1e4, F33 = 1.0 - p * d * (N - 1.5) * (N - 1.5) / (kn * (N - 1.0) * (N - 1.0));
    static double rows[5][SBC_COLUMNS];
    char csv[512];
    double solves = 0.0;
    int n, k;
    n = run_3d("layer", "dimension 3\nlattice cubic 4 4 4 spacing 2e-3 radius 1e-3\ncontact frictional kn 1e4 ks 0 mu 0\n"
               "density 224962.886\ntimestep 1e-5\nservo_bc mixed F 1 0 0 0 1 0 0 0 1 increments 1 stress P33 -1e4 2 "
               "accuracy tight tol_relative 1e-10 interior newton file %s\nrun\n", rows, 5, csv, sizeof csv);
    CHECK(n == 4);
    if (n != 4)
        return;
    CHECK(fabs(rows[2][COL3("F33")] - F33) <= 1e-9 * (1.0 - F33));
    CHECK(fabs(rows[2][COL3("P33")] + p) <= 1e-9 * p && fabs(rows[1][COL3("P33")] + 0.5 * p) <= 1e-9 * p);
    for (k = 1; k <= 2; ++k) {
        CHECK(rows[k][COL3("newton_iterations")] > 0.0 &&
              rows[k][COL3("relax_steps")] <= 20.0 * (rows[k][COL3("iterations")] + 1.0));
        CHECK(fabs(rows[k][COL3("hill_mandel")]) <= 1e-6);
        solves += rows[k][COL3("iterations")];
    }
    printf("  interior spheres: 3D layer on the touching 4^3 lattice, newton: 1 - F33 = %.9e after the stress stage "
           "(closed form %.9e), P33 %.6f N/m^2, %g servo iterations, each a converged static solve\n",
           1.0 - rows[2][COL3("F33")], 1.0 - F33, rows[2][COL3("P33")], solves);
}

/* the 71-sphere irregular packing: 30 jammed in a periodic cube, compressed by 0.2 %, reconstructed */
static int packing(char *path, size_t cap)
{
    static int made = 0;
    return packing_file("interior_spheres71", "dimension 3\ngenerate periodic n0 30 rmin 1e-3 polydispersity 1.5 "
                        "seed 1 strain 0.002\n", path, cap, &made);
}

static void irregular(void)
{
    static const char head[] = "dimension 3\nread_packing %s\ncontact frictional kn 1e4 %s\ndensity 2650\n"
                               "timestep 9e-6\nservo_bc %s F 1 0 0.003 0 1 0 0 0 1 increments 2 accuracy tight "
                               "interior %s file %%s\nrun\n";
    static double a[4][SBC_COLUMNS], b[4][SBC_COLUMNS];
    char path[512], script[2048], csv[2][512];
    const char *bcs[2] = {"D", "P"};
    int n, m, k, r;
    if (!packing(path, sizeof path)) {
        CHECK(0);
        return;
    }
    { /* frictionless: one equilibrium, reached both ways */
        double gap = 0.0, scale = 0.0;
        int na;
        snprintf(script, sizeof script, head, path, "ks 0 mu 0", "D", "newton");
        na = run_3d("frictionless_newton", script, a, 4, csv[0], sizeof csv[0]);
        snprintf(script, sizeof script, head, path, "ks 0 mu 0", "D", "dynamic");
        n = run_3d("frictionless_dynamic", script, b, 4, csv[1], sizeof csv[1]);
        CHECK(na == 3 && n == 3);
        for (k = 0; k < n && na == n; ++k)
            for (m = COL3("P11"); m <= COL3("P33"); ++m) {
                gap = fmax(gap, fabs(a[k][m] - b[k][m]));
                scale = fmax(scale, fabs(b[k][m]));
            }
        CHECK(n == 3 && na == 3 && gap <= 1e-6 * scale);
        printf("  interior spheres: frictionless 71 spheres (D): newton and dynamic %.2e of the stress scale apart\n",
               scale > 0.0 ? gap / scale : -1.0);
    }
    for (m = 0; m < 2; ++m) {
        long iterations = 0;
        double steps = 0.0;
        snprintf(script, sizeof script, head, path, "ks 5e3 mu 0.5", bcs[m], "newton");
        for (r = 0; r < 2; ++r) {
            char tag[32];
            snprintf(tag, sizeof tag, "frictional_%s_%d", bcs[m], r);
            n = run_3d(tag, script, a, 4, csv[r], sizeof csv[r]);
            CHECK(n == 3);
        }
        CHECK(same_bytes(csv[0], csv[1]));
        for (k = 1; k < n; ++k) {
            iterations += (long)a[k][COL3("newton_iterations")];
            steps = fmax(steps, a[k][COL3("relax_steps")]);
            CHECK(a[k][COL3("unbalanced")] <= 1e-7 && fabs(a[k][COL3("hill_mandel")]) <= 1e-6);
        }
        CHECK(n == 3 && steps <= 40.0); /* (D): 20 certifying steps, (P): 40 (one servo iteration) */
        printf("  interior spheres: frictional 71 spheres (%s), newton: 2 certified increments in %ld Newton "
               "iterations, at most %g DEM steps an increment, two runs %s\n", bcs[m], iterations, steps,
               same_bytes(csv[0], csv[1]) ? "byte for byte" : "DIFFER");
    }
}

/* the 3D material point of the 71 spheres with friction after three committed shear steps: its condensed
   tangent against central differences of the increment's map from the committed state, to 1e-4 of |C| */
static void consistent_tangent(void)
{
    const char *words[2] = {"D accuracy tight interior newton", "P accuracy tight interior newton"};
    char path[512];
    double *x = NULL, *r = NULL;
    sbc_error err;
    int w, n = 0;
    if (!packing(path, sizeof path) || sbc_spheres_read(path, &n, &x, &r, &err) != SBC_OK) {
        CHECK(0);
        return;
    }
    for (w = 0; w < 2; ++w) {
        sbc_point_def def = sbc_point_def_default();
        double C[81] = {0}, D[81] = {0}, gap;
        def.dim = 3;
        def.n = n;
        def.x = x;
        def.r = r;
        def.words = words[w];
        def.law.kn = 1e4;
        def.law.ks = 5e3;
        def.law.mu = 0.5;
        def.density = 2650;
        def.dt = 9e-6;
        gap = tangent_map_gap(&def, 2, 8, C, D, &err); /* F13 = 0.001 k, F33 = 1 - 0.0005 k */
        if (gap < 0.0)
            printf("  interior spheres: point: %s\n", err.message);
        CHECK(gap >= 0.0 && gap <= 1e-4);
        printf("  interior spheres: material point %s, frictional 71 spheres after three shear steps: condensed "
               "tangent against the increment's map by central differences %.2e of |C| (C1313 %.6g, %.6g)\n",
               words[w], gap, C[9 * 2 + 2], D[9 * 2 + 2]);
    }
    free(x);
    free(r);
}

void test_interior_spheres(void)
{
    block_derivative();
    lattices();
    layer();
    irregular();
    consistent_tangent();
}
