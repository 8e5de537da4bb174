/* The handle interface of host.h: a host that measures only what the core
 * asks for (sbc_host_needs) gets the runner's CSV to the bit; bad words,
 * lists and keywords come back as messages. */
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/embedded/engine.h"
#include "sbc/host.h"
#include "sbc/packing.h"
#include "sbc/embedded/script.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WORDS "P F 0.99 -0.02 -0.02 0.99 increments 2 tol_force 1e-8 gain_force 1e3 gain_moment 1e3"

/* the runner's own run of WORDS on a 5 x 5 lattice */
static int runner_rows(double rows[][CSV_COLS], const char *csv)
{
    char script[1024];
    sbc_error err;
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\n"
             "contact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
             "servo_bc " WORDS " file %s\nrun\n",
             csv);
    CHECK(sbc_script_run_string(script, "host", NULL, &err) == SBC_OK);
    return csv_read(csv, rows, 8);
}

/* the same run through sbc_host, the engine standing in for a host that
 * measures lazily: Ep only on SBC_NEED_POTENTIAL, the frame only on
 * SBC_NEED_FRAME (NULL arrays otherwise), and checks confinement at every
 * converged increment (sbc_host_confined, which writes its row). escape: at
 * the first one, a particle outside the frame is passed instead; the run
 * stops there with the message in *message. */
static int lazy_rows(double rows[][CSV_COLS], const char *csv, double *measured, int escape, char *message)
{
    sbc_packing p;
    sbc_error err;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine *e;
    sbc_host *h;
    char words[1024], msg[512];
    double *mass;
    long steps = 0, with_ep = 0;
    int k, ev = SBC_EVENT_RELAXING;
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    mass = malloc(sizeof *mass * (size_t)p.n);
    for (k = 0; k < p.n; ++k)
        mass[k] = 2e3 * 3.14159265358979323846 * p.r[k] * p.r[k];
    snprintf(words, sizeof words, WORDS " file %s", csv);
    h = sbc_host_create(words, p.n, p.x, p.r, mass, 0, NULL, 1e-5, 1e4, msg, sizeof msg);
    CHECK(h != NULL);
    def.n = p.n;
    def.x = p.x;
    def.r = p.r;
    def.density = 2e3;
    def.law.kn = 1e4;
    def.law.ks = 2e3;
    def.law.mu = 0.4;
    def.dt = 1e-5;
    if (h) /* the damping the words ask for, as a host applies it */
        def.fire = sbc_host_damping(h, &def.alpha, &def.beta) == SBC_DAMPING_FIRE;
    e = sbc_engine_create(&def, &err);
    CHECK(e != NULL);
    if (h && e) {
        sbc_frame frame; /* the engine needs the frame; the host found the same one */
        CHECK(sbc_frame_detect(&frame, p.n, p.x, p.r, 0.0, &err) == SBC_OK);
        CHECK(frame.n == sbc_host_frame_size(h) &&
              memcmp(frame.particle, sbc_host_frame_particles(h), sizeof(int) * (size_t)frame.n) == 0);
        sbc_engine_set_frame(e, &frame);
        while (ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED && steps < 20000000) {
            sbc_snapshot s;
            sbc_commands cmd;
            unsigned need;
            double m[SBC_HOST_MEASURES] = {0.0};
            if (sbc_engine_step(e, &err) != SBC_OK)
                break;
            sbc_engine_snapshot(e, &s);
            m[SBC_HOST_EK] = s.kinetic_energy;
            m[SBC_HOST_NET_MAX] = s.unbalanced_max;
            m[SBC_HOST_EP] = SBC_RELAX_EP_UNMEASURED;
            need = sbc_host_needs(h, m);
            if (need & SBC_NEED_CONTACTS) {
                m[SBC_HOST_EP] = s.potential_energy;
                m[SBC_HOST_CONTACT_SUM] = s.contact_force_sum;
                m[SBC_HOST_CONTACT_COUNT] = (double)s.contact_count;
                m[SBC_HOST_OVERLAP_SUM] = s.overlap_sum;
                ++with_ep;
                need = sbc_host_needs(h, m);
            }
            if (need & SBC_NEED_FRAME) {
                m[SBC_HOST_ROTATION_SUM] = s.rotation_sum;
                m[SBC_HOST_PARTICLE_COUNT] = (double)s.particle_count;
                ev = sbc_host_step(h, m, s.x, s.theta, s.force, s.torque);
            } else {
                ev = sbc_host_step(h, m, NULL, NULL, NULL, NULL);
            }
            if (ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) {
                sbc_engine_view w = sbc_engine_get_view(e);
                long id = 99;
                const double out[2] = {10e-3, 4e-3}, still[2] = {0.0, 0.0};
                int interior = 0, ok = 1;
                for (k = 0; k < w.n && !escape; ++k) /* one call per particle: ids and arrays of one */
                    if (!w.kinematic[k]) {
                        long kid = k;
                        ok &= sbc_host_confined(h, s.x, 1, &kid, &w.x[2 * k], &w.v[2 * k]) == 0;
                        ++interior;
                    }
                if (escape) {
                    CHECK(sbc_host_confined(h, s.x, 1, &id, out, still) == 1);
                    snprintf(message, 512, "%s", sbc_host_message(h));
                    break;
                }
                CHECK(ok && interior == 9);
            }
            cmd.x = sbc_host_command_x(h);
            cmd.theta = sbc_host_command_theta(h);
            cmd.free_rotation = sbc_host_command_free(h);
            sbc_engine_move_frame(e, &cmd);
            ++steps;
        }
        CHECK(ev == (escape ? SBC_EVENT_INCREMENT : SBC_EVENT_FINISHED));
        if (ev == SBC_EVENT_FAILED)
            printf("  %s\n", sbc_host_message(h));
        {
            double row[SBC_HOST_ROW];
            sbc_host_result(h, row);
            /* last increment, F12 (eq. 15 from the frame, round-off), Hill-Mandel */
            if (!escape)
                CHECK(row[COL("increment")] == 2.0 && fabs(row[COL("F12")] + 0.02) < 1e-14 &&
                      fabs(row[COL("hill_mandel")]) < 1e-6);
        }
        sbc_frame_free(&frame);
    }
    *measured = steps > 0 ? (double)with_ep / (double)steps : 1.0;
    sbc_host_free(h); /* closes the CSV */
    sbc_engine_free(e);
    free(mass);
    sbc_packing_free(&p);
    return csv_read(csv, rows, 8);
}

static void lazy_equals_full(void)
{
    static double a[8][CSV_COLS], b[8][CSV_COLS];
    char ca[512], cb[512];
    double measured = 1.0;
    int na, nb, i, k, same = 1;
    snprintf(ca, sizeof ca, "%s/host_runner.csv", test_tmpdir);
    snprintf(cb, sizeof cb, "%s/host_lazy.csv", test_tmpdir);
    na = runner_rows(a, ca);
    nb = lazy_rows(b, cb, &measured, 0, NULL);
    CHECK(na == 3 && nb == na);
    for (i = 0; i < na && i < nb; ++i)
        for (k = 0; k < CSV_COLS; ++k)
            same &= a[i][k] == b[i][k];
    CHECK(same); /* every column, including relax_steps and iterations, to the bit */
    printf("  host: Ep measured on %.1f %% of the steps of a (P) run\n", 100.0 * measured);
    CHECK(measured < 0.5);
}

/* confine.h through the handle: the escaped particle stops the run at
 * increment 0, whose row is dropped (the CSV keeps its header alone) */
static void escape(void)
{
    static double rows[8][CSV_COLS];
    char csv[512], message[512] = "";
    double measured;
    snprintf(csv, sizeof csv, "%s/host_escape.csv", test_tmpdir);
    CHECK(lazy_rows(rows, csv, &measured, 1, message) == 0);
    CHECK(strstr(message, "servo_bc: increment 0: interior particle 99 escaped through a gap between frame particles "
                          "(its centre (0.01, 0.004) m") != NULL);
}

/* sbc_host_create refuses WORDS on the particles of a 5 x 5 lattice (disc
 * masses) whose field FIELD of particle 7 (0 x, 1 radius, 2 mass, -1 none)
 * is VALUE, at time step DT, with a message holding EXPECT */
static void refused_on(const char *words, int nlist, const int *list, int field, double value, double dt,
                       const char *expect)
{
    sbc_packing p;
    sbc_error err;
    char msg[512] = "";
    double mass[25];
    int k;
    sbc_host *h;
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    for (k = 0; k < p.n; ++k)
        mass[k] = 2e3 * 3.14159265358979323846 * 1.02e-3 * 1.02e-3;
    if (field == 0)
        p.x[14] = value;
    else if (field == 1)
        p.r[7] = value;
    else if (field == 2)
        mass[7] = value;
    h = sbc_host_create(words, p.n, p.x, p.r, mass, nlist, list, dt, 1e4, msg, sizeof msg);
    CHECK(h == NULL && strstr(msg, expect) != NULL);
    if (h || !strstr(msg, expect))
        printf("  '%s', field %d = %g, dt %g: got '%s'\n", words, field, value, dt, msg);
    sbc_host_free(h);
    sbc_packing_free(&p);
}

static void refused(const char *words, int nlist, const int *list, const char *expect)
{
    refused_on(words, nlist, list, -1, 0.0, 1e-5, expect);
}

static void bad_particle(int field, double value, double dt, const char *expect)
{
    refused_on("P F 1.01 0 0 1", 0, NULL, field, value, dt, expect);
}

static void bad_input(void)
{
    /* particles and time step, checked before anything is built */
    bad_particle(0, NAN, 1e-5, "particle 7: centre (nan, 0.002) m");
    bad_particle(1, NAN, 1e-5, "particle 7:");
    bad_particle(1, 0.0, 1e-5, "radius 0 m");
    bad_particle(1, -1e-3, 1e-5, "radius -0.001 m");
    bad_particle(2, 0.0, 1e-5, "mass 0 kg");
    bad_particle(2, INFINITY, 1e-5, "mass inf kg");
    /* critical step 2 sqrt(M / (2 kn)) = 1.14e-3 s; particle 7 ten times lighter: 3.6e-4 s */
    bad_particle(2, 6.537e-4, 5e-4, "exceeds the critical step 0.00036158 s = 2 sqrt(M / (2 kn)) of particle 7");
    bad_particle(2, 6.537e-3, 1e-300, "do not span one critical step");
    const int ring[3] = {0, 1, 2}, outside[1] = {25};
    refused("Q F 1 0 0 1", 0, NULL, "'Q'");
    refused("P increments zero", 0, NULL, "increments");
    refused("P gain_force", 0, NULL, "gain_force");
    refused("", 0, NULL, "missing boundary condition");
    refused("D frame ring", 0, NULL, "keyword 'frame': 'ring' names no particle");
    refused("D", 3, ring, "no keyword 'frame'");
    refused("D frame ring", 1, outside, "index 25 is not in [0, 25)");
    refused("D frame ring", 3, ring, "frame");
    refused("D file /dev/null/dir/x.csv", 0, NULL, "cannot write '/dev/null/dir/x.csv'");
}

/* sbc_host_warning: the words' note and the time step's, one per line; a
 * time step of 1e-6 s is 1/1143 of the lattice's critical step 1.143e-3 s
 * (noted below 1/500), 1e-5 s 1/114 (not); none under update fixed */
static void warnings(void)
{
    static const struct {
        const char *words;
        double dt;
        const char *first, *second;
    } cases[] = {
        {"D F 0.99 0 0 0.99", 1e-5, NULL, NULL},
        {"D F 0.99 0 0 0.99", 1e-6, "servo_bc: time step 1e-06 s is 1/1143 of the critical step 0.00114342 s", NULL},
        {"D F 0.99 0 0 0.99 tol_relative 1e-3", 1e-6, "tol_relative", "\nservo_bc: time step 1e-06 s is 1/1143"},
        {"D F 0.99 0 0 0.99 tol_relative 1e-3", 1e-5, "tol_relative", NULL},
        {"P F 0.99 0 0 0.99 update fixed", 1e-6, NULL, NULL},
        {"P F 0.99 0 0 0.99 accuracy paper", 1e-6, NULL, NULL},
    };
    sbc_packing p;
    sbc_error err;
    double mass[25];
    int k, i;
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    for (k = 0; k < p.n; ++k)
        mass[k] = 2e3 * 3.14159265358979323846 * 1.02e-3 * 1.02e-3;
    for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); ++i) {
        char msg[1024] = "";
        sbc_host *h = sbc_host_create(cases[i].words, p.n, p.x, p.r, mass, 0, NULL, cases[i].dt, 1e4, msg, sizeof msg);
        int warned;
        CHECK(h != NULL);
        if (!h)
            continue;
        warned = sbc_host_warning(h, msg, sizeof msg);
        CHECK(warned == (cases[i].first != NULL));
        {
            const char *at = cases[i].first ? strstr(msg, cases[i].first) : NULL, *nl = strchr(msg, '\n');
            CHECK(!cases[i].first || (at && (!nl || at < nl))); /* on the first line */
        }
        CHECK(!cases[i].second || strstr(msg, cases[i].second) != NULL);
        CHECK(cases[i].second || !warned || !strchr(msg, '\n'));
        if (warned != (cases[i].first != NULL))
            printf("  '%s' at %g s: warning %d '%s'\n", cases[i].words, cases[i].dt, warned, msg);
        sbc_host_free(h);
    }
    sbc_packing_free(&p);
}

void test_host(void)
{
    lazy_equals_full();
    escape();
    bad_input();
    warnings();
}
