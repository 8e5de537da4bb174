/* Packing generator (Sect. 4.2): deterministic per seed, no overlaps beyond the
 * relaxation tolerance, periodic copies at exactly +-L, one corner particle on
 * all four corners. */
#include "check.h"
#include "tests.h"

#include "sbc/frame.h"
#include "sbc/embedded/generate.h"
#include "sbc/embedded/plot.h"
#include "sbc/embedded/script.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Lines of a file that start with `prefix`; -1 when it cannot be read. */
static int count_lines(const char *path, const char *prefix)
{
    FILE *fp = fopen(path, "r");
    char buf[512];
    int n = 0;
    if (!fp)
        return -1;
    while (fgets(buf, sizeof buf, fp))
        n += strncmp(buf, prefix, strlen(prefix)) == 0;
    fclose(fp);
    return n;
}

/* The frame of the reconstructed packing: discs crossing the square's edges,
 * partners at exactly +-L, the corner particle at the four corners; the
 * writers reproduce the packing bit for bit; the runner drives it. */
static void test_generated_frame(const sbc_packing *a, double L)
{
    sbc_frame f;
    sbc_packing back;
    sbc_error err;
    char path[512], script[2048];
    int k, host, crossing = 0, exact = 1, sides[5] = {0, 0, 0, 0, 0}, twos, n, *is_frame;
    double *angle;
    CHECK(a->has_box && a->box[0] == 0.0 && a->box[1] == L && a->box[3] == L);
    CHECK(sbc_frame_detect_packing(&f, a, &err) == SBC_OK);
    for (k = 0; k < a->n; ++k) {
        double x = a->x[2 * k], y = a->x[2 * k + 1], r = a->r[k];
        crossing += fabs(x) < r || fabs(x - L) < r || fabs(y) < r || fabs(y - L) < r;
    }
    CHECK(f.n == crossing);
    for (k = 0; k < f.n; ++k) {
        int q = f.partner[k];
        ++sides[f.side[k]];
        if (f.side[k] == SBC_SIDE_BOTTOM)
            exact &= f.X[3 * q] == f.X[3 * k] && f.X[3 * q + 1] == f.X[3 * k + 1] + L;
        if (f.side[k] == SBC_SIDE_LEFT)
            exact &= f.X[3 * q + 1] == f.X[3 * k + 1] && f.X[3 * q] == f.X[3 * k] + L;
    }
    CHECK(exact);
    CHECK(sides[SBC_SIDE_CORNER] == 4 && sides[SBC_SIDE_BOTTOM] == sides[SBC_SIDE_TOP] &&
          sides[SBC_SIDE_LEFT] == sides[SBC_SIDE_RIGHT] && sides[SBC_SIDE_BOTTOM] > 0);
    CHECK_REL(f.V, L * L, 1e-12);
    /* text round trip: bit for bit, box included */
    snprintf(path, sizeof path, "%s/generated.txt", test_tmpdir);
    CHECK(sbc_packing_write_text(a, path, &err) == SBC_OK);
    CHECK(sbc_packing_read(&back, path, &err) == SBC_OK);
    CHECK(back.n == a->n && back.has_box && memcmp(back.box, a->box, sizeof a->box) == 0 &&
          memcmp(back.x, a->x, sizeof(double) * 2 * (size_t)a->n) == 0 &&
          memcmp(back.r, a->r, sizeof(double) * (size_t)a->n) == 0);
    sbc_packing_free(&back);
    /* LAMMPS and LIGGGHTS data files: one atom line per disc, the frame as
     * type 2, the density column giving each host M = rho_A pi R^2 (eq. 9) */
    is_frame = calloc((size_t)a->n, sizeof *is_frame);
    for (k = 0; k < f.n; ++k)
        is_frame[f.particle[k]] = 1;
    for (host = 0; host < 2; ++host) {
        FILE *fp;
        char buf[512];
        int atoms = 0, in_atoms = 0, id, type;
        double d, rho, x, y, z, mass_err = 0.0;
        snprintf(path, sizeof path, "%s/generated_%d.data", test_tmpdir, host);
        CHECK(host == 0 ? sbc_packing_write_lammps(a, is_frame, 2e3, path, &err) == SBC_OK
                        : sbc_packing_write_liggghts(a, is_frame, 2e3, path, &err) == SBC_OK);
        fp = fopen(path, "r");
        twos = 0;
        while (fp && fgets(buf, sizeof buf, fp)) {
            if (strncmp(buf, "Atoms", 5) == 0) { in_atoms = 1; continue; }
            if (in_atoms && sscanf(buf, "%d %d %lf %lf %lf %lf %lf", &id, &type, &d, &rho, &x, &y, &z) == 7) {
                /* LAMMPS' 2D mass is the sphere's 4/3 pi R^3 rho, LIGGGHTS' pi R^2 rho */
                double R = 0.5 * d, pi = 3.14159265358979323846;
                double m = host == 0 ? 4.0 / 3.0 * pi * R * R * R * rho : pi * R * R * rho;
                double want = 2e3 * pi * R * R;
                if (fabs(m - want) / want > mass_err) mass_err = fabs(m - want) / want;
                ++atoms;
                twos += type == 2;
                exact &= x == a->x[2 * (id - 1)] && y == a->x[2 * (id - 1) + 1] && R == a->r[id - 1];
            }
        }
        if (fp) fclose(fp);
        CHECK(atoms == a->n && twos == f.n && exact);
        CHECK(mass_err < 1e-15);
    }
    free(is_frame);
    snprintf(path, sizeof path, "%s/generated.yade", test_tmpdir);
    {
        int *is_frame = calloc((size_t)a->n, sizeof *is_frame), q;
        for (q = 0; q < f.n; ++q)
            is_frame[f.particle[q]] = 1;
        CHECK(sbc_packing_write_yade(a, is_frame, path, &err) == SBC_OK);
        CHECK(count_lines(path, "#") == 1 && count_lines(path, "") == a->n + 1);
        /* the fifth column flags exactly the frame */
        {
            FILE *fp = fopen(path, "r");
            char buf[256];
            int k = 0, flagged = 0, right = 1, flag;
            double x, y, z, r;
            while (fp && fgets(buf, sizeof buf, fp)) {
                if (buf[0] == '#') continue;
                if (sscanf(buf, "%lf %lf %lf %lf %d", &x, &y, &z, &r, &flag) != 5) { right = 0; break; }
                right &= x == a->x[2 * k] && y == a->x[2 * k + 1] && z == 0.0 && r == a->r[k] && flag == is_frame[k];
                flagged += flag;
                ++k;
            }
            if (fp) fclose(fp);
            CHECK(right && k == a->n && flagged == f.n);
        }
        free(is_frame);
    }
    /* rose diagram: one wedge per bin */
    CHECK(sbc_packing_contact_angles(a, 1e-6 * 0.67e-3, &angle, &n, &err) == SBC_OK);
    CHECK(n > a->n); /* coordination above 2 */
    snprintf(path, sizeof path, "%s/rose.svg", test_tmpdir);
    CHECK(sbc_plot_rose(path, "rose", n, angle, 36, &err) == SBC_OK);
    CHECK(count_lines(path, "<path") == 36);
    free(angle);
    CHECK(sbc_plot_rose(path, "rose", 0, NULL, 7, &err) == SBC_ERR_INPUT && strstr(err.message, "7 bins"));
    /* a box that is not the packing's square is refused with a message */
    {
        double box[4] = {0.0, 0.9 * L, 0.0, L};
        sbc_frame g;
        CHECK(sbc_frame_detect_box(&g, a->n, a->x, a->r, box, &err) == SBC_ERR_FRAME &&
              strstr(err.message, "frame:"));
    }
    /* a host's frame group (the type-2 atoms of the LAMMPS data file), in any
       order: the periodic square is found from its corner copies, and the
       frame is the one of sbc_frame_detect_box */
    {
        sbc_frame g;
        int *list = malloc(sizeof(int) * (size_t)f.n), q, same = 1;
        for (q = 0; q < f.n; ++q)
            list[q] = f.particle[(q * 7) % f.n]; /* a permutation: f.n is not a multiple of 7 here */
        CHECK(f.n % 7 != 0);
        CHECK(sbc_frame_from_list(&g, f.n, list, a->x, a->r, &err) == SBC_OK);
        CHECK(g.n == f.n && g.V == f.V);
        for (q = 0; q < f.n && g.n == f.n; ++q)
            same = same && g.particle[q] == f.particle[q] && g.partner[q] == f.partner[q] && g.A[3 * q] == f.A[3 * q];
        CHECK(same);
        sbc_frame_free(&g);
        free(list);
    }
    sbc_frame_free(&f);
    /* the runner: generate, write, read back and run two (P) increments */
    snprintf(path, sizeof path, "%s/runner_generated.txt", test_tmpdir);
    snprintf(script, sizeof script,
             "dimension 2\ngenerate periodic n0 25 rmin 0.67e-3 polydispersity 2 seed 1\n"
             "write_packing text %s\nread_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n"
             "density 2e3\ntimestep 1e-5\n"
             "servo_bc P F 1 0.01 0 1 increments 2 gain_force 1e3 gain_moment 1e3 gain_deformation 1e-2 "
             "tol_force 1e-6 tol_moment 1e-6 tol_deformation 1e-3\nrun\n",
             path, path);
    CHECK(sbc_script_run_string(script, "generated", NULL, &err) == SBC_OK);
    if (err.status != SBC_OK) printf("  %s\n", err.message);
    /* a disc outside the frame is not confined: the run stops at once, naming it (the packing's first line
       announces one disc fewer: it goes, since read_packing holds a file to the count it announces) */
    {
        FILE *in = fopen(path, "r"), *fp;
        char line[256], edited[600];
        snprintf(edited, sizeof edited, "%s.edited", path);
        if (in && (fp = fopen(edited, "w"))) {
            if (fgets(line, sizeof line, in))
                while (fgets(line, sizeof line, in))
                    fputs(line, fp);
            fprintf(fp, "1.0 1.0 0.67e-3\n");
            fclose(fp);
        }
        if (in)
            fclose(in);
        snprintf(script, sizeof script,
                 "dimension 2\nread_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\n"
                 "timestep 1e-5\nservo_bc D F 1 0.01 0 1 increments 2\nnetwork 1 %s/escaped\nrun\n",
                 edited, test_tmpdir);
        CHECK(sbc_script_run_string(script, "escaped", NULL, &err) == SBC_ERR_GEOMETRY &&
              strstr(err.message, "increment 0: interior particle 36 escaped through a gap between frame particles"));
        /* the picture of the state it stopped in: the frame's polygon, the one disc outside it in orange */
        snprintf(path, sizeof path, "%s/escaped_000000.svg", test_tmpdir);
        CHECK(file_contains(path, "where the run stopped, in increment 0"));
        CHECK(file_contains(path, "discs outside it: 1<"));
        CHECK(file_contains(path, "<polygon fill=\"none\""));
        CHECK(file_contains(path, "fill=\"#ff9900\" stroke"));
    }
    CHECK(sbc_script_run_string("generate periodic n0 25 rmin 0.67e-3 polydispersity 11 seed 1\n", "bad", NULL,
                                &err) == SBC_ERR_INPUT &&
          strstr(err.message, "bad:1: generate: polydispersity '11' is not valid (expected a real from 1 to 10"));
    CHECK(sbc_script_run_string("write_packing vtk x\n", "bad", NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "no packing"));
    /* the runner's writers by name: YADE needs no density, the data files do */
    {
        const char *format[3] = {"yade", "lammps", "liggghts"};
        int k;
        for (k = 0; k < 3; ++k) {
            snprintf(path, sizeof path, "%s/runner_packing.%s", test_tmpdir, format[k]);
            snprintf(script, sizeof script, "lattice square 3 3 spacing 2e-3 radius 1.02e-3\nwrite_packing %s %s\n",
                     format[k], path);
            CHECK(k == 0 ? sbc_script_run_string(script, "w", NULL, &err) == SBC_OK
                         : sbc_script_run_string(script, "w", NULL, &err) == SBC_ERR_INPUT &&
                               strstr(err.message, "no density"));
            snprintf(script, sizeof script,
                     "lattice square 3 3 spacing 2e-3 radius 1.02e-3\ndensity 2e3\nwrite_packing %s %s\n", format[k],
                     path);
            CHECK(sbc_script_run_string(script, "w", NULL, &err) == SBC_OK && count_lines(path, "") >= 9);
        }
        CHECK(count_lines(path, "LIGGGHTS data file") == 1);
    }
}


/* The reconstructed packing a of d: no overlaps beyond the relaxation
 * tolerance, radii in [R_min, pd R_min], every disc crossing an edge copied at
 * exactly +-L, one corner particle on the four corners (the only discs that
 * cross two edges); returns the corner particle's radius. */
static double check_reconstruction(const sbc_packing *a, const sbc_generate_def *d, double L)
{
    int i, j, overlaps = 0, unpaired = 0, corners = 0, two_edges = 0;
    double tol = 1e-9 * d->r_min, r_corner = 0.0, r_max = 0.0;
    for (i = 0; i < a->n; ++i) {
        double x = a->x[2 * i], y = a->x[2 * i + 1], r = a->r[i];
        CHECK(r >= d->r_min && r <= d->polydispersity * d->r_min);
        for (j = i + 1; j < a->n; ++j) {
            double dx = a->x[2 * j] - x, dy = a->x[2 * j + 1] - y;
            if (sqrt(dx * dx + dy * dy) < a->r[j] + r - tol) ++overlaps;
        }
        /* a disc crossing an edge has its copy at exactly +-L on the other side */
        if (x - r < 0.0 || x + r > L) {
            double want = x - r < 0.0 ? x + L : x - L;
            int found = 0;
            for (j = 0; j < a->n; ++j)
                found |= a->x[2 * j] == want && a->x[2 * j + 1] == y && a->r[j] == r;
            unpaired += !found;
        }
        if (y - r < 0.0 || y + r > L) {
            double want = y - r < 0.0 ? y + L : y - L;
            int found = 0;
            for (j = 0; j < a->n; ++j)
                found |= a->x[2 * j + 1] == want && a->x[2 * j] == x && a->r[j] == r;
            unpaired += !found;
        }
        if ((x == 0.0 || x == L) && (y == 0.0 || y == L)) {
            ++corners;
            r_corner = r;
        } else {
            two_edges += (fabs(x) < r || fabs(x - L) < r) && (fabs(y) < r || fabs(y - L) < r);
        }
    }
    CHECK(overlaps == 0);
    CHECK(unpaired == 0);
    CHECK(corners == 4);
    CHECK(two_edges == 0);
    for (i = 0; i < a->n; ++i)
        r_max = fmax(r_max, a->r[i]);
    CHECK(r_max <= (1.0 + sqrt(2.0)) * r_corner); /* no disc can cross the two edges beside the corner disc */
    return r_corner;
}

/* strain E: the jammed box compressed by E and relaxed: L scales by 1 - E,
 * the volume fraction by 1/(1 - E)^2, and the discs overlap (a load-bearing
 * packing: the paper's volume fractions 0.833-0.850 at E = 0.01) */
static void strained(void)
{
    sbc_generate_def d = sbc_generate_def_default();
    sbc_packing a, b;
    sbc_generate_info ia, ib;
    sbc_error err;
    double deepest = 0.0;
    int i, j;
    d.n = 60;
    CHECK(sbc_generate_periodic(&d, &a, &ia, &err) == SBC_OK);
    d.strain = 0.01;
    CHECK(sbc_generate_periodic(&d, &b, &ib, &err) == SBC_OK);
    /* the unstrained box is stretched by 1e-8 to open its contacts (generate.c) */
    CHECK_REL(ib.L, 0.99 * ia.L / (1.0 + 1e-8), 1e-12);
    CHECK_REL(ib.fraction, ia.fraction * (1.0 + 1e-8) * (1.0 + 1e-8) / (0.99 * 0.99), 1e-12);
    for (i = 0; i < b.n; ++i)
        for (j = i + 1; j < b.n; ++j) {
            const double dx = b.x[2 * j] - b.x[2 * i], dy = b.x[2 * j + 1] - b.x[2 * i + 1];
            deepest = fmax(deepest, (b.r[i] + b.r[j] - sqrt(dx * dx + dy * dy)) / d.r_min);
        }
    CHECK(deepest > 1e-3); /* overlaps of at least 1e-3 R_min somewhere: it carries load */
    printf("  generate: strain 0.01: volume fraction %.4f -> %.4f, deepest overlap %.2g R_min\n", ia.fraction,
           ib.fraction, deepest);
    sbc_packing_free(&a);
    sbc_packing_free(&b);
}

/* 3D: n0 spheres jammed in a periodic cube (sbc_generate_periodic_3d): the
 * same seed gives the same packing bit for bit; a sphere at each of the
 * eight corners; every sphere that crosses a face of [0, L]^3 has its copy
 * at exactly +-L across it (the other coordinates equal); the jammed volume
 * fraction of a random packing (0.5 to 0.7: 24 spheres in a periodic cube
 * jam looser than a large packing's 0.64); strain 0.01 scales L by 0.99 and
 * loads the contacts */
static void spheres(void)
{
    sbc_generate_def d = sbc_generate_def_default();
    sbc_sphere_packing a, b, c;
    sbc_generate_info ia, ib, ic;
    sbc_error err;
    int i, j, k, corners = 0, crossings = 0, missing = 0;
    double deepest = 0.0;
    d.n = 24;
    d.polydispersity = 1.5;
    CHECK(sbc_generate_periodic_3d(&d, &a, &ia, &err) == SBC_OK);
    CHECK(sbc_generate_periodic_3d(&d, &b, &ib, &err) == SBC_OK);
    CHECK(a.n == b.n && a.n > 24 && memcmp(a.x, b.x, sizeof(double) * 3 * (size_t)a.n) == 0 &&
          memcmp(a.r, b.r, sizeof(double) * (size_t)a.n) == 0);
    for (i = 0; i < a.n; ++i) {
        const double *x = &a.x[3 * i];
        int at = 1;
        for (k = 0; k < 3; ++k)
            at &= x[k] == 0.0 || x[k] == a.L;
        corners += at;
        for (k = 0; k < 3; ++k) { /* crossing face k: its copy across it */
            const double shift = x[k] - a.r[i] < 0.0 ? a.L : x[k] + a.r[i] > a.L ? -a.L : 0.0;
            int found = 0;
            if (shift == 0.0)
                continue;
            ++crossings;
            for (j = 0; j < a.n && !found; ++j)
                found = a.r[j] == a.r[i] && a.x[3 * j + k] == x[k] + shift &&
                        a.x[3 * j + (k + 1) % 3] == x[(k + 1) % 3] && a.x[3 * j + (k + 2) % 3] == x[(k + 2) % 3];
            missing += !found;
        }
    }
    CHECK(corners == 8 && crossings > 0 && missing == 0);
    CHECK(ia.fraction > 0.5 && ia.fraction < 0.7 && fabs(ia.L - a.L) == 0.0);
    d.strain = 0.01;
    CHECK(sbc_generate_periodic_3d(&d, &c, &ic, &err) == SBC_OK);
    CHECK_REL(ic.L, 0.99 * ia.L / (1.0 + 1e-8), 1e-12);
    for (i = 0; i < c.n; ++i)
        for (j = i + 1; j < c.n; ++j) {
            double d2 = 0.0;
            for (k = 0; k < 3; ++k)
                d2 += (c.x[3 * j + k] - c.x[3 * i + k]) * (c.x[3 * j + k] - c.x[3 * i + k]);
            deepest = fmax(deepest, (c.r[i] + c.r[j] - sqrt(d2)) / d.r_min);
        }
    CHECK(deepest > 1e-3);
    printf("  generate: 3D, %d spheres: %d after the reconstruction, 8 corners, %d face crossings each with its copy "
           "at +-L, volume fraction %.4f, coordination %.2f; strain 0.01: fraction %.4f, deepest overlap %.2g R_min\n",
           ia.n0, a.n, crossings, ia.fraction, ia.coordination, ic.fraction, deepest);
    sbc_sphere_packing_free(&a);
    sbc_sphere_packing_free(&b);
    sbc_sphere_packing_free(&c);
}

/* 3D, polydispersity 2: a sphere of radius r crossing the three faces at the
 * corner beside a corner sphere of radius R_c does not overlap it once r >=
 * R_c / (sqrt 3 - 1) = 1.37 R_c, so the corner is the largest sphere where
 * another would cross there (n0 60, seed 2: particle 0, r = 1.06 mm, was the
 * corner and a sphere of 1.97 mm crossed its three faces, which no frame
 * takes). Only the corner sphere's eight copies may cross every face. */
static void corner_not_crossed(void)
{
    sbc_generate_def d = sbc_generate_def_default();
    sbc_sphere_packing a;
    sbc_error err;
    int i, k, crossing = 0, corners = 0;
    double rmax = 0.0, corner_r = 0.0;
    d.n = 60;
    d.r_min = 1e-3;
    d.polydispersity = 2.0;
    d.seed = 2;
    d.strain = 0.01;
    CHECK(sbc_generate_periodic_3d(&d, &a, NULL, &err) == SBC_OK);
    for (i = 0; i < a.n; ++i) {
        int all = 1, at = 1;
        for (k = 0; k < 3; ++k) {
            all &= a.x[3 * i + k] - a.r[i] < 0.0 || a.x[3 * i + k] + a.r[i] > a.L;
            at &= a.x[3 * i + k] == 0.0 || a.x[3 * i + k] == a.L;
        }
        crossing += all && !at;
        corners += at;
        if (at) corner_r = a.r[i];
        rmax = fmax(rmax, a.r[i]);
    }
    CHECK(crossing == 0 && corners == 8 && corner_r == rmax);
    printf("  generate: 3D, n0 60, polydispersity 2, seed 2: %d spheres, the corner sphere the largest (%.4g mm), "
           "%d others crossing the three faces at the corner\n", a.n, 1e3 * corner_r, crossing);
    sbc_sphere_packing_free(&a);
}

/* protocol pressure: the same seed gives the same packing; touching (strain
 * 0): no pair overlaps, and the pair that set the box touches within 1e-8 of
 * its radii; strain 0.01 loads the contacts, a
 * frictionless jammed packing's coordination (>= 2 dim less its rattlers),
 * relaxed to 1e-6 of the mean contact force; spheres alike; the runner's
 * keyword and its errors */
static void pressure_protocol(void)
{
    sbc_generate_def d = sbc_generate_def_default();
    sbc_packing a, b, c;
    sbc_sphere_packing t;
    sbc_generate_info ia, ib, ic, it;
    sbc_error err;
    double closest = 1.0, deepest = 0.0;
    int i, j;
    d.n = 300;
    d.r_min = 1e-3;
    d.protocol = SBC_GENERATE_PRESSURE;
    CHECK(sbc_generate_periodic(&d, &a, &ia, &err) == SBC_OK);
    CHECK(sbc_generate_periodic(&d, &b, &ib, &err) == SBC_OK);
    CHECK(a.n == b.n && memcmp(a.x, b.x, sizeof(double) * 2 * (size_t)a.n) == 0 &&
          memcmp(a.r, b.r, sizeof(double) * (size_t)a.n) == 0);
    check_reconstruction(&a, &d, ia.L);
    for (i = 0; i < a.n; ++i)
        for (j = i + 1; j < a.n; ++j) {
            const double dx = a.x[2 * j] - a.x[2 * i], dy = a.x[2 * j + 1] - a.x[2 * i + 1];
            closest = fmin(closest, sqrt(dx * dx + dy * dy) / (a.r[i] + a.r[j]) - 1.0);
        }
    CHECK(closest >= 0.0 && closest < 1e-8 && ia.residual == 0.0);
    CHECK(ia.fraction > 0.80 && ia.fraction < 0.87);
    d.strain = 0.01;
    CHECK(sbc_generate_periodic(&d, &c, &ic, &err) == SBC_OK);
    /* the strained box is 0.99 of the jamming point extrapolated from the stages' pressures, the touching box
       (every overlap opened) lies above that point by what the stages left unrelaxed */
    CHECK(ic.L < 0.99 * ia.L && ic.L > 0.99 * 0.999 * ia.L);
    for (i = 0; i < c.n; ++i)
        for (j = i + 1; j < c.n; ++j) {
            const double dx = c.x[2 * j] - c.x[2 * i], dy = c.x[2 * j + 1] - c.x[2 * i + 1];
            deepest = fmax(deepest, (c.r[i] + c.r[j] - sqrt(dx * dx + dy * dy)) / d.r_min);
        }
    CHECK(deepest > 1e-3 && ic.fraction > 0.83 && ic.fraction < 0.87 && ic.coordination > 3.6 &&
          ic.residual < 1e-6);
    printf("  generate: protocol pressure, n0 300: touching at fraction %.4f (closest gap %.1e of the radii); strain "
           "0.01: box %.6f of the touching one, fraction %.4f, coordination %.3f, largest net force %.1e of the "
           "mean\n", ia.fraction, closest, ic.L / ia.L, ic.fraction, ic.coordination, ic.residual);
    sbc_packing_free(&a);
    sbc_packing_free(&b);
    sbc_packing_free(&c);
    d.n = 100;
    d.protocol = SBC_GENERATE_PRESSURE;
    CHECK(sbc_generate_periodic_3d(&d, &t, &it, &err) == SBC_OK);
    CHECK(it.fraction > 0.58 && it.fraction < 0.72 && it.coordination > 5.0 && it.residual < 1e-6 && t.n > 100);
    printf("  generate: protocol pressure, 100 spheres, strain 0.01: fraction %.4f, coordination %.3f, largest net "
           "force %.1e of the mean\n", it.fraction, it.coordination, it.residual);
    sbc_sphere_packing_free(&t);
    CHECK(sbc_script_run_string("generate periodic n0 25 rmin 1e-3 polydispersity 2 seed 1 protocol fast\n", "bad",
                                NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "bad:1: generate: protocol 'fast' is not known (expected shrink or pressure)"));
    CHECK(sbc_script_run_string("generate periodic n0 25 rmin 1e-3 polydispersity 2 seed 1 strain 0.01 pressure 1\n",
                                "bad", NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "bad:1: generate: keyword 'pressure' is not known (expected strain or protocol"));
    CHECK(sbc_script_run_string("generate periodic n0 25 rmin 1e-3 polydispersity 2 seed 1 protocol\n", "bad", NULL,
                                &err) == SBC_ERR_INPUT);
    CHECK(sbc_script_run_string("generate periodic n0 2000001 rmin 1e-3 polydispersity 2 seed 1\n", "bad", NULL,
                                &err) == SBC_ERR_INPUT &&
          strstr(err.message, "n0 '2000001' is not valid (expected an integer from 4 to 2000000)"));
}

void test_generate(void)
{
    pressure_protocol();
    strained();
    spheres();
    corner_not_crossed();
    sbc_generate_def d = sbc_generate_def_default();
    sbc_packing a, b;
    sbc_generate_info ia, ib;
    sbc_error err;
    double L, rmax = 0.0;
    int i;
    d.n = 25;
    CHECK(sbc_generate_periodic(&d, &a, &ia, &err) == SBC_OK);
    CHECK(sbc_generate_periodic(&d, &b, &ib, &err) == SBC_OK);
    CHECK(a.n == b.n && memcmp(a.x, b.x, sizeof(double) * 2 * (size_t)a.n) == 0 &&
          memcmp(a.r, b.r, sizeof(double) * (size_t)a.n) == 0);
    d.seed = 2;
    sbc_packing_free(&b);
    CHECK(sbc_generate_periodic(&d, &b, &ib, &err) == SBC_OK);
    CHECK(b.n != a.n || memcmp(a.x, b.x, sizeof(double) * 2 * (size_t)a.n) != 0);
    L = ia.L;
    CHECK(ia.n > ia.n0 && ia.fraction > 0.80 && ia.fraction < 0.87);
    d.seed = 1;
    check_reconstruction(&a, &d, L);
    test_generated_frame(&a, L);
    sbc_packing_free(&a);
    sbc_packing_free(&b);
    /* R_max / R_min = 10: disc 0 of seed 2 is too small to be the corner
       (R_max > (1 + sqrt 2) r_0), and the largest disc takes its place; the
       frame is found as for 2 */
    d.n = 40;
    d.seed = 2;
    d.polydispersity = 10.0;
    CHECK(sbc_generate_periodic(&d, &a, &ia, &err) == SBC_OK);
    for (i = 0; i < a.n; ++i)
        rmax = fmax(rmax, a.r[i]);
    CHECK(check_reconstruction(&a, &d, ia.L) == rmax);
    CHECK(ia.fraction > 0.80 && ia.fraction < 0.90);
    {
        sbc_frame f;
        int sides[5] = {0, 0, 0, 0, 0};
        const int detected = sbc_frame_detect_packing(&f, &a, &err) == SBC_OK;
        CHECK(detected);
        if (detected) {
            for (i = 0; i < f.n; ++i)
                ++sides[f.side[i]];
            CHECK(sides[SBC_SIDE_CORNER] == 4 && sides[SBC_SIDE_BOTTOM] == sides[SBC_SIDE_TOP] &&
                  sides[SBC_SIDE_LEFT] == sides[SBC_SIDE_RIGHT] && sides[SBC_SIDE_BOTTOM] > 0);
            CHECK_REL(f.V, ia.L * ia.L, 1e-12);
            sbc_frame_free(&f);
        }
    }
    sbc_packing_free(&a);
}
