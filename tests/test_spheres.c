#define _DEFAULT_SOURCE /* strsep */
/* The embedded 3D engine (sbc/embedded/spheres.h): one contact against its
 * closed form, momentum and energy through a collision, and the 4^3 lattices
 * of docs/frame3d.md under (D), (P), (T) and the 3D layer's stress stage
 * through the host driver, against their closed forms. */
#include "check.h"
#include "tests.h"

#include "base/words.h"
#include "sbc/driver.h"
#include "sbc/columns.h"
#include "sbc/embedded/script.h"
#include "sbc/embedded/spheres.h"
#include "sbc/frame.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* two spheres of radius R overlapping by dn along a tilted axis: forces
 * -/+ kn dn n, no moment, Ep = kn dn^2 / 2, one contact, eq. 39's dn / Rbar */
static void one_contact(void)
{
    const double R = 1e-3, dn = 2e-6, kn = 1e4, n[3] = {0.6, 0.0, 0.8};
    double x[6], r[2] = {R, R}, worst = 0.0;
    sbc_spheres_def def = sbc_spheres_def_default();
    sbc_spheres *e;
    sbc_spheres_view w;
    sbc_error err;
    int k;
    for (k = 0; k < 3; ++k) {
        x[k] = 0.01 * (k + 1);
        x[3 + k] = x[k] + (2.0 * R - dn) * n[k];
    }
    def.n = 2, def.x = x, def.r = r, def.law.kn = kn, def.law.ks = 0.5 * kn, def.law.mu = 0.5;
    CHECK((e = sbc_spheres_create(&def, &err)) != NULL);
    if (!e)
        return;
    CHECK(sbc_spheres_forces(e, &err) == SBC_OK);
    w = sbc_spheres_get_view(e);
    for (k = 0; k < 3; ++k) {
        worst = fmax(worst, fabs(w.f[k] + kn * dn * n[k]) / (kn * dn));
        worst = fmax(worst, fabs(w.f[3 + k] - kn * dn * n[k]) / (kn * dn));
        worst = fmax(worst, fabs(w.torque[k]) / (kn * dn * R));
    }
    CHECK(worst <= 1e-9 && w.contact_count == 1 && fabs(w.potential_energy - 0.5 * kn * dn * dn) <= 1e-9 * kn * dn * dn);
    printf("  spheres: one contact: forces and moments within %.1e of -/+ kn dn n, Ep = kn dn^2 / 2\n", worst);
    sbc_spheres_free(e);
}

/* An oblique collision of two frictional spheres without damping: linear
 * momentum to round-off, angular momentum about the origin (sum m x v + I w)
 * to round-off of the step's cross terms; without friction the kinetic
 * energy comes back (restitution 1 for the undamped spring) */
static void collision(double ks, double *energy_error, double *momentum_error, double *angular_error)
{
    const double R = 1e-3, kn = 1e4, rho = 2.5e3;
    double x[6] = {0.0, 0.0, 0.0, 3e-3, 0.8e-3, 0.3e-3}, r[2] = {R, R};
    double p0[3] = {0.0, 0.0, 0.0}, L0[3] = {0.0, 0.0, 0.0}, ek0 = 0.0, ek = 0.0, p[3] = {0, 0, 0}, L[3] = {0, 0, 0};
    sbc_spheres_def def = sbc_spheres_def_default();
    sbc_driver_callbacks cb;
    sbc_spheres *e;
    sbc_spheres_view w;
    sbc_error err;
    double out[2], I;
    int step, i, k;
    def.n = 2, def.x = x, def.r = r, def.density = rho, def.law.kn = kn, def.law.ks = ks, def.law.mu = 0.3;
    def.alpha = def.beta = 0.0;
    def.dt = 1e-3 * sqrt(rho * 4.0 / 3.0 * M_PI * R * R * R / kn);
    e = sbc_spheres_create(&def, &err);
    CHECK(e != NULL);
    if (!e)
        return;
    cb = sbc_spheres_callbacks(e);
    w = sbc_spheres_get_view(e);
    ((double *)w.v)[3] = -0.5; /* sphere 1 towards sphere 0, off its axis (the engine's own array) */
    I = 0.4 * w.mass[0] * R * R;
    for (i = 0; i < 2; ++i) {
        const double *xi = &w.x[3 * i], *vi = &w.v[3 * i];
        for (k = 0; k < 3; ++k)
            p0[k] += w.mass[i] * vi[k];
        L0[0] += w.mass[i] * (xi[1] * vi[2] - xi[2] * vi[1]);
        L0[1] += w.mass[i] * (xi[2] * vi[0] - xi[0] * vi[2]);
        L0[2] += w.mass[i] * (xi[0] * vi[1] - xi[1] * vi[0]);
        ek0 += 0.5 * w.mass[i] * (vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
    }
    for (step = 0; step < 200000 && sbc_spheres_forces(e, &err) == SBC_OK; ++step)
        cb.interior(cb.user_data, NULL, 0, out);
    CHECK(step == 200000);
    CHECK(sbc_spheres_forces(e, &err) == SBC_OK);
    w = sbc_spheres_get_view(e);
    CHECK(w.contact_count == 0 && w.v[0] < 0.0); /* apart again, sphere 0 pushed along -x */
    for (i = 0; i < 2; ++i) {
        const double *xi = &w.x[3 * i], *vi = &w.v[3 * i], *wi = &w.omega[3 * i];
        for (k = 0; k < 3; ++k) {
            p[k] += w.mass[i] * vi[k];
            L[k] += I * wi[k];
        }
        L[0] += w.mass[i] * (xi[1] * vi[2] - xi[2] * vi[1]);
        L[1] += w.mass[i] * (xi[2] * vi[0] - xi[0] * vi[2]);
        L[2] += w.mass[i] * (xi[0] * vi[1] - xi[1] * vi[0]);
        ek += 0.5 * w.mass[i] * (vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]) +
              0.5 * I * (wi[0] * wi[0] + wi[1] * wi[1] + wi[2] * wi[2]);
    }
    *energy_error = fabs(ek - ek0) / ek0;
    *momentum_error = 0.0;
    *angular_error = 0.0;
    for (k = 0; k < 3; ++k) {
        *momentum_error = fmax(*momentum_error, fabs(p[k] - p0[k]) / fabs(p0[0] + p0[1] + p0[2]));
        *angular_error = fmax(*angular_error, fabs(L[k] - L0[k]));
    }
    *angular_error /= sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
    sbc_spheres_free(e);
}

static void collisions(void)
{
    double de, dp, dl, fe, fp, fl;
    collision(0.0, &de, &dp, &dl);
    collision(5e3, &fe, &fp, &fl);
    CHECK(de <= 1e-6 && dp <= 1e-12 && dl <= 1e-9);
    CHECK(fe < 1.0 && fp <= 1e-12 && fl <= 1e-9 && fe > de); /* friction dissipates or stores some of Ek */
    printf("  spheres: oblique collision, frictionless: |dEk|/Ek %.1e, momentum %.1e, angular momentum %.1e; "
           "frictional (ks 5e3, mu 0.3): |dEk|/Ek %.1e, momentum %.1e, angular momentum %.1e\n",
           de, dp, dl, fe, fp, fl);
}

/* The lattices of docs/frame3d.md (4^3, d 2 mm, kn 1e4 N/m, mass 1 g) under
 * words through the driver with this engine; rows into rows [8], their count
 * returned (-1 on failure, with the message), the steps in *steps */
static long builds; /* the pair-list builds of the last run */

static int run_skin(const char *text, double R, double ks, double mu, double skin, sbc_result rows[8], long *steps);

static int run(const char *text, double R, double ks, double mu, sbc_result rows[8], long *steps)
{
    return run_skin(text, R, ks, mu, 0.0, rows, steps);
}

/* run with the neighbour list's skin (m; <= 0: the default) */
static int run_skin(const char *text, double R, double ks, double mu, double skin, sbc_result rows[8], long *steps)
{
    const int N = 4, n = N * N * N;
    const double d = 2e-3;
    char line[512], *words[40];
    double x[3 * 64], r[64], mass[64];
    int i, j, k, nrows = 0, nw;
    sbc_spheres_def def = sbc_spheres_def_default();
    sbc_spheres *e;
    sbc_frame f;
    sbc_settings s;
    sbc_error err;
    sbc_controller *c = NULL;
    sbc_driver *drv = NULL;
    sbc_driver_callbacks cb;
    sbc_event ev = SBC_EVENT_RELAXING;
    for (k = 0, i = 0; k < N; ++k)
        for (j = 0; j < N; ++j)
            for (int l = 0; l < N; ++l, ++i) {
                x[3 * i] = l * d, x[3 * i + 1] = j * d, x[3 * i + 2] = k * d;
                r[i] = R;
            }
    def.n = n, def.x = x, def.r = r, def.law.kn = 1e4, def.law.ks = ks, def.law.mu = mu, def.dt = 1e-5;
    def.density = 1e-3 / (4.0 / 3.0 * M_PI * R * R * R);
    def.skin = skin;
    snprintf(line, sizeof line, "%s", text);
    nw = sbc_split_words(line, words, 40);
    CHECK(sbc_frame_detect_3d(&f, n, x, r, 0.0, &err) == SBC_OK);
    CHECK(sbc_settings_parse(&s, nw, (const char *const *)words, &err) == SBC_OK &&
          sbc_settings_check_dimension(&s, 3, &err) == SBC_OK);
    def.fire = s.damping == SBC_DAMPING_FIRE;
    def.alpha = s.alpha, def.beta = s.beta;
    e = sbc_spheres_create(&def, &err);
    CHECK(e != NULL);
    sbc_spheres_set_frame(e, &f);
    sbc_spheres_frame_masses(e, mass);
    c = sbc_controller_create(&f, &s, mass, def.dt, def.law.kn, &err);
    CHECK(c != NULL);
    cb = sbc_spheres_callbacks(e);
    drv = c ? sbc_driver_create(c, &s, &cb, &err) : NULL;
    for (*steps = 0; drv && ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED && *steps < 3000000; ++*steps) {
        sbc_commands cmd;
        if (sbc_spheres_forces(e, &err) != SBC_OK)
            break;
        ev = sbc_driver_step(drv, 0, &err);
        cmd = sbc_controller_commands(c);
        sbc_spheres_move_frame(e, &cmd);
        if ((ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) && nrows < 8)
            rows[nrows++] = *sbc_controller_result(c);
    }
    if (ev != SBC_EVENT_FINISHED) {
        printf("  %s\n", err.message);
        nrows = -1;
    }
    builds = e ? sbc_spheres_get_view(e).builds : 0;
    sbc_driver_free(drv);
    sbc_controller_free(c);
    sbc_spheres_free(e);
    sbc_frame_free(&f);
    return nrows;
}

/* (D) and (P) on the prestressed lattice with friction: P_ii = -N^2 kn (2R -
 * d F_ii) / ((N - 1)^2 d^2) within 1e-6 of max |P|; (T) on the touching
 * frictionless lattice: P_ii = -kn (1 - F_ii) (N - 1)^2 / (d (N - 3/2)^2)
 * within 1e-5; the layer's stress stage: F33 = 1 - 1/720, P33 = -1e4 within
 * 1e-6; |Hill-Mandel| <= 1e-6 */
static void lattices(void)
{
    static const struct {
        const char *words;
        double R, ks, mu;
        int form; /* 0 prestressed, 1 touching (T), 2 layer */
        int rows;
    } cases[] = {
        {"D F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 accuracy tight", 1.02e-3, 5e3, 0.5, 0, 3},
        {"P F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 accuracy tight", 1.02e-3, 5e3, 0.5, 0, 3},
        {"T F 0.999998 0 0 0 0.999999 0 0 0 1 increments 2 accuracy tight", 1e-3, 0.0, 0.0, 1, 3},
        {"mixed stress P33 -1e4 2 F 1 0 0 0 1 0 0 0 1 increments 1 accuracy tight", 1e-3, 5e3, 0.5, 2, 4},
    };
    const double N = 4.0, d = 2e-3, kn = 1e4;
    size_t m;
    for (m = 0; m < sizeof cases / sizeof cases[0]; ++m) {
        sbc_result rows[8];
        long steps;
        const int nrows = run(cases[m].words, cases[m].R, cases[m].ks, cases[m].mu, rows, &steps);
        double worst = 0.0, pmax = 0.0, hm = 0.0;
        int k, i, j;
        CHECK(nrows == cases[m].rows);
        if (nrows != cases[m].rows)
            continue;
        for (k = 0; k < nrows; ++k) {
            hm = fmax(hm, fabs(rows[k].hill_mandel));
            if (cases[m].form == 2)
                continue;
            for (i = 0; i < 3; ++i)
                for (j = 0; j < 3; ++j) {
                    const double F = rows[k].F[SBC_IJ(i, i)];
                    double expect = 0.0;
                    if (i == j)
                        expect = cases[m].form == 1 ? -kn * (1.0 - F) * (N - 1) * (N - 1) / (d * (N - 1.5) * (N - 1.5))
                                                    : -N * N * kn * (2.0 * cases[m].R - d * F) / ((N - 1) * (N - 1) * d * d);
                    worst = fmax(worst, fabs(rows[k].P[SBC_IJ(i, j)] - expect));
                    pmax = fmax(pmax, fabs(expect));
                }
        }
        if (cases[m].form == 2) {
            worst = fmax(fabs((1.0 - rows[2].F[8]) * 720.0 - 1.0), fabs(rows[2].P[8] + 1e4) / 1e4);
            pmax = 1.0;
        }
        CHECK(worst <= (cases[m].form == 1 ? 1e-5 : 1e-6) * pmax && hm <= 1e-6);
        printf("  spheres: %.*s...: %d rows in %ld steps, %.1e of the closed form, |Hill-Mandel| <= %.1e\n", 24,
               cases[m].words, nrows, steps, worst / pmax, hm);
    }
}

/* The runner after 'dimension 3': a (P) run on the prestressed 4^3 lattice
 * writes the 3D results file, whose rows meet the closed form to 1e-6 of max
 * |P|; bad 3D words are refused by name */
static void runner(void)
{
    static const char *const head = "dimension 3\nlattice cubic 4 4 4 spacing 2e-3 radius 1.02e-3\n"
                                    "contact frictional kn 1e4 ks 5e3 mu 0.5\ndensity 224962.886\ntimestep 1e-5\n";
    static const struct {
        const char *lines, *expect;
    } bad[] = {
        {"dimension 3\nlattice square 4 4 spacing 2e-3 radius 1e-3\n", "style 'square' is not known after 'dimension 3'"},
        {"dimension 3\ncontact cohesive kn 1\n", "law 'cohesive' is 2D in this version"},
        {"dimension 3\nservo_bc D F 0.99 0 0 1\n", "4 values give a 2D F, but the packing is 3D"},
        {"dimension 3\nlattice cubic 4 4 2 spacing 2e-3 radius 1e-3\n", "NZ '2' is not valid"},
    };
    char script[2048], path[512], line[4096];
    double worst = 0.0, pmax = 0.0;
    int rows = 0, cols[4] = {-1, -1, -1, -1};
    sbc_error err;
    FILE *fp;
    size_t k;
    snprintf(path, sizeof path, "%s/cubic3d.csv", test_tmpdir);
    snprintf(script, sizeof script, "%sservo_bc P F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 accuracy tight file %s\n"
             "vtk 2 %s/cubic3d\nrun\n", head, path, test_tmpdir);
    CHECK(sbc_script_run_string(script, "cubic3d", NULL, &err) == SBC_OK);
    { /* the snapshots of increments 0 and 2 (the last): 64 spheres; the frame's 56 centres and 54 quadrilaterals */
        static const char *const want[2][2] = {{"spheres", "POINTS 64 double"}, {"frame", "POLYGONS 54 270"}};
        int m, inc;
        for (inc = 0; inc <= 2; inc += 2)
            for (m = 0; m < 2; ++m) {
                char vtk[600], text[8192] = "";
                size_t got = 0;
                snprintf(vtk, sizeof vtk, "%s/cubic3d_%s_%06d.vtk", test_tmpdir, want[m][0], inc);
                if ((fp = fopen(vtk, "r")) != NULL) {
                    got = fread(text, 1, sizeof text - 1, fp);
                    text[got] = '\0';
                    fclose(fp);
                }
                CHECK(strncmp(text, "# vtk DataFile Version 3.0", 26) == 0 && strstr(text, want[m][1]) != NULL);
            }
        snprintf(line, sizeof line, "%s/cubic3d_spheres_000001.vtk", test_tmpdir);
        CHECK((fp = fopen(line, "r")) == NULL); /* vtk 2: not increment 1 */
        if (fp)
            fclose(fp);
    }
    if ((fp = fopen(path, "r")) != NULL) {
        while (fgets(line, sizeof line, fp)) {
            char *f[64], *p = line;
            int n = 0, i;
            while (n < 64 && (f[n] = strsep(&p, ",\n")) != NULL)
                ++n;
            if (rows++ == 0) {
                CHECK(n >= SBC_COLUMNS && strcmp(f[0], "increment") == 0 && strcmp(f[3], "F13") == 0);
                continue;
            }
            for (i = 0; i < 3; ++i) { /* P_ii against -N^2 kn (2R - d F_ii) / ((N - 1)^2 d^2) */
                const double F = atof(f[sbc_column_index(3, i == 0 ? "F11" : i == 1 ? "F22" : "F33")]);
                const double P = atof(f[sbc_column_index(3, i == 0 ? "P11" : i == 1 ? "P22" : "P33")]);
                const double e = -16.0 * 1e4 * (2.04e-3 - 2e-3 * F) / (9.0 * 4e-6);
                worst = fmax(worst, fabs(P - e));
                pmax = fmax(pmax, fabs(e));
            }
            worst = fmax(worst, fabs(atof(f[sbc_column_index(3, "P13")])));
        }
        fclose(fp);
    }
    (void)cols;
    CHECK(rows == 4 && worst <= 1e-6 * pmax);
    printf("  spheres: the runner's 3D (P) run: %d rows, max |P - closed form| = %.1e of max |P|\n", rows - 1,
           pmax > 0.0 ? worst / pmax : -1.0);
    { /* the packing written as text and read back: the same rows, bit for bit */
        char packing[600], again[600], a[4096] = "", b[4096] = "";
        size_t na = 0, nb = 0;
        snprintf(packing, sizeof packing, "%s/cubic3d_packing.txt", test_tmpdir);
        snprintf(again, sizeof again, "%s/cubic3d_again.csv", test_tmpdir);
        snprintf(script, sizeof script, "%swrite_packing text %s\n", head, packing);
        CHECK(sbc_script_run_string(script, "write3d", NULL, &err) == SBC_OK);
        snprintf(script, sizeof script, "dimension 3\nread_packing %s\ncontact frictional kn 1e4 ks 5e3 mu 0.5\n"
                 "density 224962.886\ntimestep 1e-5\nservo_bc P F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 "
                 "accuracy tight file %s\nrun\n", packing, again);
        CHECK(sbc_script_run_string(script, "read3d", NULL, &err) == SBC_OK);
        if ((fp = fopen(path, "r")) != NULL) {
            na = fread(a, 1, sizeof a - 1, fp);
            fclose(fp);
        }
        if ((fp = fopen(again, "r")) != NULL) {
            nb = fread(b, 1, sizeof b - 1, fp);
            fclose(fp);
        }
        CHECK(na > 0 && na == nb && memcmp(a, b, na) == 0);
        snprintf(script, sizeof script, "dimension 3\nread_packing %s\nrun\n", path); /* the CSV is no packing */
        CHECK(sbc_script_run_string(script, "bad3d", NULL, &err) != SBC_OK &&
              strstr(err.message, "values (expected 4: x y z r)"));
    }
    for (k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        snprintf(script, sizeof script, "%srun\n", bad[k].lines);
        CHECK(sbc_script_run_string(script, "bad3d", NULL, &err) != SBC_OK && strstr(err.message, bad[k].expect));
    }
}

/* The pair list rebuilt at every step (a skin of 1e-15 m) carries every
 * contact's tangential spring over: the frictional (P) run gives the rows of
 * the run with the default skin bit for bit */
static void rebuilds(void)
{
    /* remap none: a relaxation from the frame, many steps for the skin to matter */
    static const char *const words = "P F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 accuracy tight remap none";
    sbc_result a[8], b[8];
    long sa, sb, ba, bb;
    const int na = run_skin(words, 1.02e-3, 5e3, 0.5, 0.0, a, &sa);
    int nb, k, same;
    ba = builds;
    nb = run_skin(words, 1.02e-3, 5e3, 0.5, 1e-15, b, &sb);
    bb = builds;
    same = na == 3 && nb == 3 && sa == sb;
    for (k = 0; same && k < na; ++k)
        same = memcmp(a[k].P, b[k].P, sizeof a[k].P) == 0 && memcmp(a[k].F, b[k].F, sizeof a[k].F) == 0;
    CHECK(same && bb > sb / 2 && ba < 10);
    printf("  spheres: the pair list built %ld times in %ld steps (default skin: %ld): the frictional (P) rows bit for "
           "bit\n", bb, sb, ba);
}

void test_spheres(void)
{
    one_contact();
    collisions();
    lattices();
    rebuilds();
    runner();
}
