/* servo_bc on an irregular sphere packing, through the runner on the
 * embedded sphere engine: a generated periodic packing (30 spheres jammed,
 * touching and free of force, 70 after the reconstruction, a frame of 62;
 * tests/packings/irregular30_touching.txt, read from the top of the
 * repository as make runs the tests),
 * frictional contacts (kn 1e4 N/m, ks 5e3 N/m, mu 0.5).
 * - A small triaxial step F = diag(0.999, 0.999, 0.998) in 2 increments:
 *   (D) and (P) at `balanced`, (T) at `fast`; Hill-Mandel within the preset's
 *   accuracy on every row, and (D) >= (P) >= (T) in the step's stiffness
 *   (the rise of -P33).
 * - The 3D layer (mixed: zlo D D D, zhi D D T, the sides P P P) at
 *   `balanced`: a stress stage to P33* = -1000 N/m^2, then F13 = 0.001;
 *   Hill-Mandel within 1e-4 on every row, P33 held at P33* to 1e-3, P13
 *   rising. The layer translated by (2^-7, 2^-6, 2^-5) m keeps P33 and
 *   Hill-Mandel alike, but its free components part by 3.7e-2 of |P33*|
 *   (P22 at F13 = 0.001: -797 and -760 N/m^2): the shifted centres round
 *   otherwise, and this small packing, compressed from free of force, settles
 *   where its path takes it (2 % apart with mu = 100, so not by sliding;
 *   docs/frame3d.md, "Irregular packings"). The test holds them to 0.1 of
 *   |P33*|, which a wrong frame or sign would break; on the lattice the layer
 *   translates to 3.4e-10 (test_frame3d.c). */
#define _DEFAULT_SOURCE /* strsep */
#include "check.h"
#include "tests.h"

#include "sbc/columns.h"
#include "sbc/embedded/script.h"
#include "sbc/packing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ROWS 3
#define WANT 19 /* F (9), P (9), hill_mandel */
#define HM 18
#define P33 17
#define F13 2
#define P13 11

/* the rows of a 3D results file: F11..F33, P11..P33, hill_mandel; returns
   the row count (-1: no file) */
static int read_rows(const char *path, double rows[][WANT])
{
    static const char *const names[WANT] = {"F11", "F12", "F13", "F21", "F22", "F23", "F31", "F32", "F33",
                                            "P11", "P12", "P13", "P21", "P22", "P23", "P31", "P32", "P33",
                                            "hill_mandel"};
    char line[8192];
    int n = 0, k;
    FILE *fp = fopen(path, "r");
    if (!fp)
        return -1;
    if (!fgets(line, sizeof line, fp)) {
        fclose(fp);
        return -1;
    }
    while (n < ROWS && fgets(line, sizeof line, fp)) {
        char *f[128], *p = line;
        int m = 0;
        while (m < 128 && (f[m] = strsep(&p, ",\n")) != NULL)
            ++m;
        for (k = 0; k < WANT; ++k) {
            const int c = sbc_column_index(3, names[k]);
            rows[n][k] = c >= 0 && c < m ? atof(f[c]) : NAN;
        }
        ++n;
    }
    fclose(fp);
    return n;
}

/* the servo_bc words on the packing file `packing`, results into name.csv;
   its rows */
static int run(const char *words, const char *packing, const char *name, double rows[][WANT])
{
    char script[2048], path[600];
    sbc_error err;
    snprintf(path, sizeof path, "%s/%s.csv", test_tmpdir, name);
    remove(path);
    snprintf(script, sizeof script,
             "dimension 3\nread_packing %s\ncontact frictional kn 1e4 ks 5e3 mu 0.5\ndensity 2650\ntimestep 9e-6\n"
             "servo_bc %s file %s\nrun\n", packing, words, path);
    if (sbc_script_run_string(script, name, NULL, &err) != SBC_OK) {
        printf("  irregular3d %s: %s\n", name, err.message);
        return -1;
    }
    return read_rows(path, rows);
}

static double worst_hill_mandel(double rows[][WANT])
{
    double w = 0.0;
    int k;
    for (k = 0; k < ROWS; ++k)
        w = fmax(w, fabs(rows[k][HM]));
    return w;
}

/* the rise of -P33 from increment 0 to 2 (N/m^2) */
static double rise(double rows[][WANT]) { return -(rows[2][P33] - rows[0][P33]); }

static void triaxial(const char *packing)
{
    static const char *const step = "F 0.999 0 0 0 0.999 0 0 0 0.998 increments 2 accuracy";
    char words[256];
    double D[ROWS][WANT], P[ROWS][WANT], T[ROWS][WANT];
    int nD, nP, nT;
    snprintf(words, sizeof words, "D %s balanced", step);
    nD = run(words, packing, "irregular3d_D", D);
    snprintf(words, sizeof words, "P %s balanced", step);
    nP = run(words, packing, "irregular3d_P", P);
    snprintf(words, sizeof words, "T %s fast", step);
    nT = run(words, packing, "irregular3d_T", T);
    CHECK(nD == ROWS && nP == ROWS && nT == ROWS);
    if (nD != ROWS || nP != ROWS || nT != ROWS)
        return;
    CHECK(worst_hill_mandel(D) <= 1e-4 && worst_hill_mandel(P) <= 1e-4 && worst_hill_mandel(T) <= 1e-2);
    CHECK(rise(D) >= rise(P) && rise(P) >= rise(T) && rise(P) > 0.0);
    printf("  irregular3d: 70 spheres, triaxial step: -dP33 (D) %.6g, (P) %.6g, (T) %.3g N/m^2; |hill_mandel| "
           "(D) %.1e, (P) %.1e (balanced), (T) %.1e (fast)\n", rise(D), rise(P), rise(T), worst_hill_mandel(D),
           worst_hill_mandel(P), worst_hill_mandel(T));
}

static void layer(const char *packing, const char *moved)
{
    static const char *const words = "mixed F 1 0 0.001 0 1 0 0 0 1 increments 1 stress P33 -1e3 1 accuracy balanced";
    double L[ROWS][WANT], M[ROWS][WANT], apart = 0.0, held = 0.0;
    const int nL = run(words, packing, "irregular3d_layer", L), nM = run(words, moved, "irregular3d_layer_moved", M);
    int k, c;
    CHECK(nL == ROWS && nM == ROWS);
    if (nL != ROWS || nM != ROWS)
        return;
    for (k = 0; k < ROWS; ++k)
        for (c = 0; c < 18; ++c)
            apart = fmax(apart, fabs(L[k][c] - M[k][c]) / (c < 9 ? 1.0 : 1e3));
    for (k = 1; k < ROWS; ++k)
        held = fmax(held, fabs(L[k][P33] + 1e3) / 1e3);
    CHECK(worst_hill_mandel(L) <= 1e-4 && worst_hill_mandel(M) <= 1e-4);
    CHECK(held <= 1e-3 && fabs(L[2][F13] - 0.001) <= 1e-12 && L[2][P13] > L[1][P13]);
    CHECK(apart <= 0.1);
    printf("  irregular3d: the 3D layer, P33 within %.1e of -1000 N/m^2, P13 %.6g N/m^2 at F13 = 0.001, "
           "|hill_mandel| %.1e; translated %.1e apart\n", held, L[2][P13], worst_hill_mandel(L), apart);
}

/* The 3D layer on the packing compressed by 0.2 % (tests/packings/irregular30_strain.txt, 71 spheres;
   inputs/compare/irregular_layer_prestressed_3d.sbc) with P33* = -1.5e4 N/m^2 held from increment 0
   (`stress P33 -1.5e4 0`), then F13 = 0.001 in 2: P33 held to 1e-3 of P33* at every row, Hill-Mandel within
   balanced's 1e-4, P13 rising. With a stress stage from 0 (N >= 1) increment 0 unloads the prestressed packing
   and stops at max_iterations (docs/frame3d.md). */
static void layer_prestressed(void)
{
    static const char *const words = "mixed F 1 0 0.001 0 1 0 0 0 1 increments 2 stress P33 -1.5e4 0 "
                                     "accuracy balanced";
    double L[ROWS][WANT], held = 0.0;
    const int n = run(words, "tests/packings/irregular30_strain.txt", "irregular3d_layer_prestressed", L);
    int k;
    CHECK(n == ROWS);
    if (n != ROWS)
        return;
    for (k = 0; k < ROWS; ++k)
        held = fmax(held, fabs(L[k][P33] + 1.5e4) / 1.5e4);
    CHECK(worst_hill_mandel(L) <= 1e-4);
    CHECK(held <= 1e-3 && fabs(L[2][F13] - 0.001) <= 1e-12 && L[2][P13] > L[1][P13] && L[1][P13] > L[0][P13]);
    printf("  irregular3d: the 3D layer on the prestressed packing, P33* held from increment 0: P33 within %.1e of "
           "-1.5e4 N/m^2, P13 %.6g, %.6g, %.6g N/m^2, |hill_mandel| %.1e\n", held, L[0][P13], L[1][P13], L[2][P13],
           worst_hill_mandel(L));
}

void test_irregular_3d(void)
{
    /* the packing of inputs/compare/irregular_layer_3d.sbc (its generate line in its header) */
    static const char packing[] = "tests/packings/irregular30_touching.txt";
    static const double shift[3] = {0.0078125, 0.015625, 0.03125};
    char moved[600];
    double *x = NULL, *r = NULL;
    int k, n = 0;
    sbc_error err;
    snprintf(moved, sizeof moved, "%s/irregular3d_moved.txt", test_tmpdir);
    CHECK(sbc_spheres_read(packing, &n, &x, &r, &err) == SBC_OK && n == 70);
    for (k = 0; k < 3 * n; ++k)
        x[k] += shift[k % 3];
    CHECK(n > 0 && sbc_spheres_write_text(n, x, r, moved, &err) == SBC_OK);
    free(x);
    free(r);
    triaxial(packing);
    layer(packing, moved);
    layer_prestressed();
}
