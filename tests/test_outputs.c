/* Outputs: CSV header and rows, VTK and SVG files of a short run. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/columns.h"
#include "sbc/results.h"
#include "sbc/embedded/plot.h"
#include "sbc/embedded/script.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* The fixes' thermo vector (columns.h): the 0.2.0 layout that decks index,
 * f_ID[1] increment, [2-5] F, [6-9] P, [10-13] sigma, [18] finished,
 * [19-21] unbalanced, frame_residual, hill_mandel, read from a row. */
static void thermo_vector(void)
{
    sbc_result r;
    int k, named = 0;
    memset(&r, 0, sizeof r);
    r.dim = 2;
    r.increment = 7;
    for (k = 0; k < 9; ++k) {
        r.F[k] = 1.0 + k;
        r.P[k] = 10.0 + k;
        r.sigma[k] = 20.0 + k;
    }
    r.unbalanced = 1e-5, r.frame_residual = 2e-5, r.hill_mandel = -3e-9;
    for (k = 0; k < SBC_THERMO_COUNT; ++k)
        named += sbc_thermo_vector[k].kind == SBC_THERMO_COLUMN && sbc_column_index(2, sbc_thermo_vector[k].column) >= 0;
    CHECK(named == 16);
    CHECK(sbc_thermo_value(NULL, &r, 0, 0) == 7.0);
    /* F11 F12 F21 F22 are slots 0 1 3 4 of the 3 x 3 storage */
    CHECK(sbc_thermo_value(NULL, &r, 0, 1) == 1.0 && sbc_thermo_value(NULL, &r, 0, 2) == 2.0 &&
          sbc_thermo_value(NULL, &r, 0, 3) == 4.0 && sbc_thermo_value(NULL, &r, 0, 4) == 5.0);
    CHECK(sbc_thermo_value(NULL, &r, 0, 8) == 14.0 && sbc_thermo_value(NULL, &r, 0, 12) == 24.0);
    CHECK(sbc_thermo_value(NULL, &r, 1, 17) == 1.0 && sbc_thermo_value(NULL, &r, 0, 17) == 0.0);
    CHECK(sbc_thermo_value(NULL, &r, 0, 18) == 1e-5 && sbc_thermo_value(NULL, &r, 0, 19) == 2e-5 &&
          sbc_thermo_value(NULL, &r, 0, 20) == -3e-9);
    CHECK(sbc_thermo_value(NULL, &r, 0, SBC_THERMO_COUNT) == 0.0 && sbc_thermo_value(NULL, &r, 0, -1) == 0.0);
    CHECK(sbc_thermo_value(NULL, &r, 0, 25) == 0.0); /* F33 of a 2D row: not in its columns */
    /* 3D: the nine components of F, P, sigma, each at its documented index (docs/lammps/fix_servo_bc.rst) */
    r.dim = 3;
    {
        static const char *const name[9] = {"11", "12", "13", "21", "22", "23", "31", "32", "33"};
        int all = 0;
        for (k = 0; k < 9; ++k) {
            char c[16];
            snprintf(c, sizeof c, "F%s", name[k]);
            all += sbc_thermo_value(NULL, &r, 0, sbc_thermo_index(c) - 1) == r.F[k];
            snprintf(c, sizeof c, "P%s", name[k]);
            all += sbc_thermo_value(NULL, &r, 0, sbc_thermo_index(c) - 1) == r.P[k];
            snprintf(c, sizeof c, "sigma%s", name[k]);
            all += sbc_thermo_value(NULL, &r, 0, sbc_thermo_index(c) - 1) == r.sigma[k];
        }
        CHECK(all == 27);
        CHECK(sbc_thermo_index("F13") == 22 && sbc_thermo_index("F33") == 26 && sbc_thermo_index("P33") == 31 &&
              sbc_thermo_index("sigma33") == 36 && sbc_thermo_index("sigma12") == 11 && sbc_thermo_index("x") == 0);
    }
    r.dim = 2;
    /* the one log line of every host (results.h): the component of F farthest from I */
    {
        static const double shear[9] = {0.999, 0.02, 0.03, -0.01, 0.999, 0, 0, 0, 1};
        static const double triaxial[9] = {1.001, 0, 0, 0, 1.001, 0, 0, 0, 0.99};
        char line[320];
        memcpy(r.F, shear, sizeof shear);
        r.relax_steps = 1234, r.iterations = 5;
        sbc_result_line(&r, SBC_BC_P, 10, line, sizeof line);
        CHECK(strcmp(line, "servo_bc P: increment 7/10 F12 +0.02000 sigma11 +2.000000e+01 sigma12 +2.100000e+01 N/m "
                           "steps 1234 iterations 5 unbalanced 1e-05 HM -3.0e-09") == 0);
        r.dim = 3; /* stresses per area in 3D; the layer's F13, sigma33, sigma13 */
        sbc_result_line(&r, SBC_BC_D, 10, line, sizeof line);
        CHECK(strstr(line, "increment 7/10 F13 +0.03000 sigma33 +2.800000e+01 sigma13 +2.200000e+01 N/m^2 steps 1234") !=
              NULL);
        memcpy(r.F, triaxial, sizeof triaxial); /* a triaxial path: F33, the lateral sigma11, sigma33 */
        sbc_result_line(&r, SBC_BC_D, 10, line, sizeof line);
        CHECK(strstr(line, "increment 7/10 F33 +0.99000 sigma11 +2.000000e+01 sigma33 +2.800000e+01 N/m^2") != NULL);
        r.dim = 2, r.F[8] = 1.0; /* 2D, F11 = F22: the first, F11, with sigma22 */
        sbc_result_line(&r, SBC_BC_D, 10, line, sizeof line);
        CHECK(strstr(line, "increment 7/10 F11 +1.00100 sigma22 +2.400000e+01 sigma11 +2.000000e+01 N/m ") != NULL);
    }
}

void test_outputs(void)
{
    thermo_vector();
    char script[2048], csv[512], path[600], prefix[512], svg[512];
    static double rows[16][CSV_COLS];
    sbc_error err;
    int n;
    /* outputs in folders that do not exist yet: created (as mkdir -p) */
    snprintf(csv, sizeof csv, "%s/new/folder/outputs.csv", test_tmpdir);
    snprintf(prefix, sizeof prefix, "%s/vtk/outputs", test_tmpdir);
    snprintf(svg, sizeof svg, "%s/outputs.svg", test_tmpdir);
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 4 4 spacing 2e-3 radius 1.02e-3\n"
             "contact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
             "servo_bc D F 0.99 -0.02 -0.02 0.99 increments 4 file %s\n"
             "vtk 2 %s\nplot %s\nrun\n",
             csv, prefix, svg);
    remove(csv);
    remove(svg);
    /* --check reads every command and writes nothing */
    CHECK(sbc_script_check_string(script, "outputs", NULL, &err) == SBC_OK);
    CHECK(!file_contains(csv, "F12") && !file_contains(svg, "svg"));
    CHECK(sbc_script_run_string(script, "outputs", NULL, &err) == SBC_OK);
    n = csv_read(csv, rows, 16);
    CHECK(n == 5); /* increments 0..4, all fields finite */
    CHECK(n == 5 && rows[4][COL("increment")] == 4.0 && rows[4][COL("relax_steps")] > 0.0);
    snprintf(path, sizeof path, "%s_particles_000002.vtk", prefix);
    CHECK(file_contains(path, "POINTS 16 double"));
    CHECK(file_contains(path, "SCALARS radius double 1"));
    snprintf(path, sizeof path, "%s_contacts_000004.vtk", prefix);
    CHECK(file_contains(path, "LINES 24 72")); /* 2 * 4 * 3 lattice contacts */
    CHECK(file_contains(path, "SCALARS normal_force double 1"));
    snprintf(path, sizeof path, "%s_particles_000001.vtk", prefix);
    CHECK(!file_contains(path, "POINTS")); /* not a chosen increment */
    CHECK(file_contains(svg, "<polyline"));
    CHECK(file_contains(svg, "<circle")); /* 5 points: a dot on each (SBC_PLOT_MARKERS) */
    CHECK(!file_contains(svg, "nan"));
    /* F12 < 0: drawn as the paper does, -sigma~ (dimensionless, t = 1 m) against -F12, left to right */
    CHECK(file_contains(svg, ">-F12 (-)</text>") && file_contains(svg, ">-sigma~ (-)</text>"));
    /* the legend avoids the curves: a curve through the top left corner moves it to the top right */
    {
        static const double x[4] = {0.0, 0.05, 0.1, 1.0}, y[4] = {1.0, 0.98, 0.96, 0.0};
        sbc_series curve = {"curve", 4, x, y};
        snprintf(path, sizeof path, "%s/legend.svg", test_tmpdir);
        CHECK(sbc_plot_svg(path, "legend", "x", "y", 1, &curve, &err) == SBC_OK);
        CHECK(!file_contains(path, "<rect x=\"98\" y=\"46\" width=\"300\"") &&
              file_contains(path, "width=\"300\""));
    }
    /* servo-bc-plot overlays columns of result files (built beside the runner) */
    {
        char cmd[4096], tool[600], out[600];
        snprintf(tool, sizeof tool, "%s-plot", test_runner);
        snprintf(out, sizeof out, "%s/overlay.svg", test_tmpdir);
        snprintf(cmd, sizeof cmd, "%s %s T X Y F12 -1 sigma11 -1.02e-7 %s one %s two", tool, out, csv, csv);
        CHECK(system(cmd) == 0);
        CHECK(file_contains(out, "stroke-dasharray") && file_contains(out, ">two</text>"));
        snprintf(cmd, sizeof cmd, "%s %s T X Y F12 -1 nosuchcolumn 1 %s one 2>/dev/null", tool, out, csv);
        CHECK(system(cmd) != 0);
        snprintf(cmd, sizeof cmd, "%s --help | grep -q 'usage: servo-bc-plot' && %s --help | grep -q -- '--check'",
                 tool, test_runner);
        CHECK(system(cmd) == 0);
    }
}
