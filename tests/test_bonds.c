/* Cohesive bonds in the embedded engine (eqs. 7-8): creation between the
 * pairs touching at the start, bond forces and moments, eq. 12 energy with the
 * rotational term, failure exactly at eq. 8 = 1, frictional behaviour after
 * failure, bond state carried across neighbour-list rebuilds. Two kinematic
 * discs are moved by hand through the frame interface; the third is a
 * distractor 1e-3 R away from touching (not bonded). */
#include "check.h"
#include "tests.h"

#include "sbc/embedded/engine.h"

#include <math.h>
#include <string.h>

#define R 1e-3
#define PI 3.14159265358979323846

typedef struct rig {
    sbc_engine *e;
    sbc_frame frame;
    int particle[3];
    double x[6], theta[3];
    unsigned char free_rotation[3];
} rig;

/* Moves the three discs to rig.x / rig.theta within one step and evaluates the forces. */
static void move(rig *g)
{
    sbc_commands c;
    sbc_error err;
    double x3[9] = {0.0}; /* the commands' 3 slots per particle from rig.x [2n] */
    int k;
    for (k = 0; k < 3; ++k) {
        x3[3 * k] = g->x[2 * k];
        x3[3 * k + 1] = g->x[2 * k + 1];
    }
    c.x = x3;
    c.theta = g->theta;
    c.free_rotation = g->free_rotation;
    sbc_engine_move_frame(g->e, &c);
    CHECK(sbc_engine_step(g->e, &err) == SBC_OK);
}

static double ep(rig *g)
{
    sbc_snapshot s;
    sbc_engine_snapshot(g->e, &s);
    return s.potential_energy;
}

void test_bonds(void)
{
    const double x0[6] = {0.0, 0.0, 2 * R, 0.0, 0.0, 2 * R + 1e-6};
    const double r[3] = {R, R, R};
    sbc_cohesive law = sbc_cohesive_default(); /* Table 6: kn 1e8, ks 4e7, kr 20, 300 N, 60 N, 0.2 N m, mu 0.6 */
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine_view w;
    sbc_error err;
    rig g;
    double crit, d_break;
    memset(&g, 0, sizeof g);
    def.n = 3;
    def.x = x0;
    def.r = r;
    def.density = 1e4;
    def.dt = 1e-6;
    def.alpha = def.beta = 0.0;
    def.bonds = &law;
    g.e = sbc_engine_create(&def, &err);
    CHECK(g.e != NULL);
    if (!g.e)
        return;
    g.frame.dim = 2;
    g.frame.n = 3;
    g.particle[0] = 0, g.particle[1] = 1, g.particle[2] = 2;
    g.frame.particle = g.particle;
    sbc_engine_set_frame(g.e, &g.frame);
    memcpy(g.x, x0, sizeof x0);
    w = sbc_engine_get_view(g.e);
    CHECK(w.bonds_initial == 1 && w.bond_count == 1); /* 0-1 touch; 2 is 1e-6 m = 1e-3 R away */
    CHECK(w.law.kn == law.kn && w.law.ks == law.ks && w.law.mu == law.mu);
    /* critical step: min(2 sqrt(M/(2 kn)), 2 sqrt(I/(2 kr))) with M = rho pi R^2, I = M R^2/2 */
    {
        double M = 1e4 * PI * R * R, I = 0.5 * M * R * R;
        CHECK_REL(sbc_engine_critical_dt(g.e), fmin(2 * sqrt(M / 2e8), 2 * sqrt(I / 40.0)), 1e-14);
    }

    /* tension: delta = 1e-6 m, fn = -kn delta = -100 N; force on j = fn n (n = e1) */
    g.x[2] = 2 * R + 1e-6;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK_REL(w.f[2], -100.0, 1e-9);
    CHECK_REL(w.f[0], 100.0, 1e-9);
    CHECK_ABS(w.f[4] + w.f[5], 0.0, 0.0); /* the distractor feels nothing */
    CHECK_REL(ep(&g), 0.5 * 1e8 * 1e-12, 1e-9);

    /* rotate j by 2e-4 rad: dus = -R dtheta, fs = -ks R dtheta = -8 N, m = kr dtheta = 0.004 N m;
     * moments: i: R fs + m = -0.004, j: R fs - m = -0.012 N m; force on j: -fs t = (0, 8) */
    g.theta[1] = 2e-4;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK_REL(w.torque[0], -0.004, 1e-9);
    CHECK_REL(w.torque[1], -0.012, 1e-9);
    CHECK_REL(w.f[3], 8.0, 1e-9);
    CHECK_REL(w.f[2], -100.0, 1e-9);
    /* eq. 12 with the rotational term: kn dn^2/2 + fs^2/(2 ks) + m^2/(2 kr) */
    CHECK_REL(ep(&g), 5e-5 + 0.5 * 64 / 4e7 + 0.5 * 0.004 * 0.004 / 20.0, 1e-9);

    /* rigid translation by 0.6 mm (> skin/2: the list is rebuilt): bond, spring and moment survive */
    g.x[1] += 6e-4, g.x[3] += 6e-4, g.x[5] += 6e-4;
    move(&g);
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK(w.bond_count == 1);
    CHECK_REL(w.torque[1], -0.012, 1e-9);
    CHECK_REL(w.f[2], -100.0, 1e-9);

    /* eq. 8 so far: 100/300 + 8/60 + 0.004/0.2; stretch to 0.999 of the remaining tensile room */
    crit = 8.0 / 60 + 0.004 / 0.2;
    d_break = (1.0 - crit) * 300.0 / 1e8; /* stretch at which eq. 8 reaches 1 */
    g.x[2] = 2 * R + 0.999 * d_break;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK(w.bond_count == 1);
    CHECK_REL(w.f[2], -1e8 * 0.999 * d_break, 1e-6);
    g.x[2] = 2 * R + 1.001 * d_break;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK(w.bond_count == 0);
    CHECK(w.f[2] == 0.0 && w.torque[1] == 0.0); /* broken in tension: a lost frictional contact */
    CHECK_ABS(ep(&g), 0.0, 0.0);

    /* pushed back into overlap dn = 1e-6: frictional (eq. 6), fn = kn dn = 100 N on j along -n... */
    g.x[2] = 2 * R - 1e-6;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK_REL(w.f[2], 100.0, 1e-6);
    /* ...and a rotation of j by 1e-4 rad gives fs = -ks R dtheta = -4 N and no bond moment: equal moments */
    g.theta[1] += 1e-4;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK_REL(w.torque[1], -0.004, 1e-6);
    CHECK_REL(w.torque[0], -0.004, 1e-6);
    /* sliding: a rotation of 2e-3 rad would need |fs| = 80 N > mu fn = 60 N: capped */
    g.theta[1] += 2e-3;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK_REL(w.torque[1], -0.6 * 100.0 * R, 1e-6);
    /* separated: nothing, for good (the pair does not re-bond) */
    g.x[2] = 2 * R + 1e-7;
    move(&g);
    g.x[2] = 2 * R;
    move(&g);
    w = sbc_engine_get_view(g.e);
    CHECK(w.bond_count == 0 && w.f[2] == 0.0);
    sbc_engine_free(g.e);
}

/* Ek for the relaxation criterion (eq. 12) leaves out a disc without
 * contacts: knocked off by a frame disc, it flies on at constant speed, which
 * local damping (eq. 10, through the force) can never remove. */
void test_rattler_energy(void)
{
    const double x0[4] = {0.0, 0.0, 2 * R, 0.0}, r[2] = {R, R};
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine *e;
    sbc_frame frame;
    sbc_snapshot snap;
    sbc_commands c;
    sbc_error err;
    double x[4], theta[2] = {0.0, 0.0};
    int particle[1] = {0};
    unsigned char free_rotation[1] = {0};
    memset(&frame, 0, sizeof frame);
    def.n = 2;
    def.x = x0;
    def.r = r;
    def.law.kn = 1e4;
    def.law.ks = 0.0;
    e = sbc_engine_create(&def, &err);
    CHECK(e != NULL);
    if (!e)
        return;
    frame.dim = 2;
    frame.n = 1;
    frame.particle = particle;
    sbc_engine_set_frame(e, &frame);
    memcpy(x, x0, sizeof x);
    c.x = x;
    c.theta = theta;
    c.free_rotation = free_rotation;
    x[0] = 1e-6; /* push: overlap 1e-6 m, fn = 0.01 N on the free disc */
    sbc_engine_move_frame(e, &c);
    sbc_engine_step(e, &err);
    sbc_engine_snapshot(e, &snap);
    CHECK(snap.kinetic_energy > 0.0); /* in contact: counted */
    x[0] = -1e-3; /* pull back: the free disc flies on */
    sbc_engine_move_frame(e, &c);
    sbc_engine_step(e, &err);
    sbc_engine_move_frame(e, NULL);
    sbc_engine_step(e, &err);
    sbc_engine_snapshot(e, &snap);
    CHECK(sbc_engine_get_view(e).v[2] > 0.0 && snap.kinetic_energy == 0.0);
    sbc_engine_free(e);
}

/* The runner wires 'contact cohesive' to the engine: a touching 4 x 4 lattice
 * has 24 bonds; under (D) simple shear its vertical pairs separate (a
 * frictional lattice would carry nothing) while the bonds carry shear; the log
 * counts the bonds, the VTK and SVG snapshots show them. */
#include "csv_read.h"
#include "sbc/embedded/script.h"

#include <stdio.h>


static int shear_lattice(const char *law, const char *tag, double *sigma12)
{
    char script[2048], csv[512], prefix[512], logname[512];
    static double rows[8][CSV_COLS];
    sbc_error err;
    FILE *log;
    int n, ok;
    snprintf(csv, sizeof csv, "%s/bonds_%s.csv", test_tmpdir, tag);
    snprintf(prefix, sizeof prefix, "%s/bonds_%s", test_tmpdir, tag);
    snprintf(logname, sizeof logname, "%s/bonds_%s.log", test_tmpdir, tag);
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 4 4 spacing 2e-3 radius 1e-3\n%s\ndensity 1e4\ntimestep 5e-6\n"
             "servo_bc D F 1 1e-4 0 1 increments 2 file %s\nvtk 2 %s\nnetwork 2 %s\nrun\n",
             law, csv, prefix, prefix);
    log = fopen(logname, "w");
    ok = log && sbc_script_run_string(script, tag, log, &err) == SBC_OK;
    if (log)
        fclose(log);
    if (!ok)
        printf("  %s: %s\n", tag, err.message);
    n = csv_read(csv, rows, 8);
    *sigma12 = n == 3 ? rows[2][COL("sigma12")] : NAN;
    return ok && n == 3;
}

void test_bonds_runner(void)
{
    char path[600];
    double s_coh;
    CHECK(shear_lattice("contact cohesive kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2 mu 0.6", "cohesive", &s_coh));
    CHECK(isfinite(s_coh) && s_coh > 1e3); /* the bonds carry the shear (N/m) */
    snprintf(path, sizeof path, "%s/bonds_cohesive.log", test_tmpdir);
    CHECK(file_contains(path, "24 cohesive bonds"));
    CHECK(file_contains(path, "bonds intact 24")); /* 1e-4 shear breaks none */
    snprintf(path, sizeof path, "%s/bonds_cohesive_contacts_000002.vtk", test_tmpdir);
    CHECK(file_contains(path, "LINES 24 72"));     /* the stretched vertical bonds are listed */
    CHECK(file_contains(path, "SCALARS bond int 1"));
    snprintf(path, sizeof path, "%s/bonds_cohesive_000002.svg", test_tmpdir);
    CHECK(file_contains(path, "0 frictional contacts"));
    CHECK(file_contains(path, "24 cohesive bonds"));
    CHECK(file_contains(path, "stroke-dasharray")); /* bonds in tension drawn dashed */
}
