/* servo_bc on an irregular sphere packing, through the runner on the
 * embedded sphere engine: a generated periodic packing (30 spheres jammed and
 * compressed by 0.2 %, 71 after the reconstruction, a frame of 62) under a
 * small triaxial step F = diag(0.999, 0.999, 0.998) in 2 increments at
 * `balanced`: Hill-Mandel within the preset's 1e-4 on every row of (D) and
 * (P); (D) at least as stiff as (P) in the step. The packing translated by
 * (2^-7, 2^-6, 2^-5) m gives (P)'s rows at `tight` within 1e-3 of the stress
 * scale, not to round-off: the shifted centres round otherwise as they move,
 * and a frictional packing settles where its path takes it (docs/frame3d.md,
 * "Irregular packings": 2.4e-4 apart; `balanced` and `tight` 1.9e-3 apart). */
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

/* bc on the packing file `packing`, results into name.csv; its rows */
static int run(const char *bc, const char *accuracy, const char *packing, const char *name, double rows[][WANT])
{
    char script[2048], path[600];
    sbc_error err;
    snprintf(path, sizeof path, "%s/%s.csv", test_tmpdir, name);
    remove(path);
    snprintf(script, sizeof script,
             "dimension 3\nread_packing %s\ncontact frictional kn 1e4 ks 5e3 mu 0.5\ndensity 2650\ntimestep 9e-6\n"
             "servo_bc %s F 0.999 0 0 0 0.999 0 0 0 0.998 increments 2 accuracy %s file %s\nrun\n",
             packing, bc, accuracy, path);
    if (sbc_script_run_string(script, name, NULL, &err) != SBC_OK) {
        printf("  irregular3d %s: %s\n", bc, err.message);
        return -1;
    }
    return read_rows(path, rows);
}

void test_irregular_3d(void)
{
    static const double shift[3] = {0.0078125, 0.015625, 0.03125};
    char packing[600], moved[600], script[1024];
    double D[ROWS][WANT], P[ROWS][WANT], T[ROWS][WANT], Q[ROWS][WANT], hm = 0.0, apart = 0.0, presets = 0.0, scale = 0.0, *x = NULL, *r = NULL;
    int nD, nP, nT, nQ, k, c, n = 0;
    sbc_error err;
    snprintf(packing, sizeof packing, "%s/irregular3d.txt", test_tmpdir);
    snprintf(moved, sizeof moved, "%s/irregular3d_moved.txt", test_tmpdir);
    snprintf(script, sizeof script, "dimension 3\ngenerate periodic n0 30 rmin 1e-3 polydispersity 1.5 seed 1 "
             "strain 0.002\nwrite_packing text %s\n", packing);
    CHECK(sbc_script_run_string(script, "irregular3d", NULL, &err) == SBC_OK);
    CHECK(sbc_spheres_read(packing, &n, &x, &r, &err) == SBC_OK && n == 71);
    for (k = 0; k < 3 * n; ++k)
        x[k] += shift[k % 3];
    CHECK(n > 0 && sbc_spheres_write_text(n, x, r, moved, &err) == SBC_OK);
    free(x);
    free(r);
    nD = run("D", "balanced", packing, "irregular3d_D", D);
    nP = run("P", "balanced", packing, "irregular3d_P", P);
    nT = run("P", "tight", packing, "irregular3d_P_tight", T);
    nQ = run("P", "tight", moved, "irregular3d_P_moved", Q);
    CHECK(nD == ROWS && nP == ROWS && nT == ROWS && nQ == ROWS);
    if (nD != ROWS || nP != ROWS || nT != ROWS || nQ != ROWS)
        return;
    for (k = 0; k < ROWS; ++k) {
        hm = fmax(hm, fmax(fabs(D[k][18]), fabs(P[k][18])));
        for (c = 9; c < 18; ++c)
            scale = fmax(scale, fabs(P[k][c]));
    }
    for (k = 0; k < ROWS; ++k)
        for (c = 0; c < 18; ++c)
            apart = fmax(apart, fabs(T[k][c] - Q[k][c]) / (c < 9 ? 1.0 : scale));
    CHECK(hm <= 1e-4);
    /* the step's stiffness: the rise of -P33 from increment 0 to 2 */
    CHECK(-(D[2][17] - D[0][17]) >= -(P[2][17] - P[0][17]) && -(P[2][17] - P[0][17]) > 0.0);
    CHECK(apart <= 1e-3);
    for (k = 0; k < ROWS; ++k)
        for (c = 9; c < 18; ++c)
            presets = fmax(presets, fabs(T[k][c] - P[k][c]) / scale);
    printf("  irregular3d: 71 spheres, (D) and (P) |hill_mandel| <= %.1e; -dP33 over the step (D) %.6g, (P) %.6g "
           "N/m^2; (P) translated %.1e apart, balanced and tight %.1e apart\n", hm, -(D[2][17] - D[0][17]),
           -(P[2][17] - P[0][17]), apart, presets);
}
