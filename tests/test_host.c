/* The handle interface of host.h: a host that gives the driver its
 * callbacks (sbc_host_drive) gets the runner's CSV to the bit, measuring the
 * contacts on the steps asked for only; bad words, lists and keywords come
 * back as messages. */
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

/* the lazy host below has no remap callback: remap none */
#define WORDS "P F 0.99 -0.02 -0.02 0.99 increments 2 tol_force 1e-8 gain_force 1e3 gain_moment 1e3 remap none"

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

/* the engine standing in for a host behind a handle (sbc_host_callbacks):
 * it measures only what the driver asks for. escape: the interior it reports
 * holds a particle outside the frame. */
typedef struct lazy_host {
    sbc_engine *e;
    sbc_snapshot s;
    int Q, escape, rows, interior, bad_line;
    long contact_steps;
} lazy_host;

static void lazy_fire_sums(void *u, double *sums) { sbc_engine_fire_sums(((lazy_host *)u)->e, sums); }

static void lazy_interior(void *u, const double *mix, double *out)
{
    lazy_host *l = u;
    if (mix) {
        const sbc_fire_mix m = {mix[0], mix[1], mix[2], mix[3]};
        sbc_engine_integrate(l->e, &m);
    } else
        sbc_engine_integrate(l->e, NULL);
    sbc_engine_snapshot(l->e, &l->s);
    out[0] = l->s.kinetic_energy;
    out[1] = l->s.unbalanced_max;
}

static void lazy_contacts(void *u, double *out)
{
    lazy_host *l = u;
    ++l->contact_steps;
    out[0] = l->s.potential_energy, out[1] = l->s.overlap_sum, out[2] = (double)l->s.contact_count;
    out[3] = l->s.contact_force_sum;
}

static void lazy_frame(void *u, double *buf)
{
    const lazy_host *l = u;
    sbc_driver_frame_from_snapshot(&l->s, 2, l->Q, buf);
}

static void lazy_interior_state(void *u, long *ids, double *x, double *v)
{
    lazy_host *l = u;
    const sbc_engine_view w = sbc_engine_get_view(l->e);
    int k, i = 0;
    for (k = 0; k < w.n; ++k)
        if (!w.kinematic[k]) {
            ids[i] = k;
            x[3 * i] = w.x[2 * k], x[3 * i + 1] = w.x[2 * k + 1], x[3 * i + 2] = 0.0;
            v[3 * i] = w.v[2 * k], v[3 * i + 1] = w.v[2 * k + 1], v[3 * i + 2] = 0.0;
            ++i;
        }
    l->interior = i;
    if (l->escape) {
        ids[0] = 99;
        x[0] = 10e-3, x[1] = 4e-3, v[0] = v[1] = 0.0;
    }
}

static void lazy_row(void *u, const double *row, const char *line)
{
    lazy_host *l = u;
    l->bad_line |= row[COL("increment")] != l->rows || strstr(line, "servo_bc P: increment ") != line;
    ++l->rows;
}

/* the same run through sbc_host; the run stops (escape) or finishes, with
 * the message in *message */
static int lazy_rows(double rows[][CSV_COLS], const char *csv, double *measured, int escape, char *message)
{
    sbc_packing p;
    sbc_error err;
    sbc_engine_def def = sbc_engine_def_default();
    lazy_host l;
    sbc_host *h;
    sbc_host_callbacks cb = {0};
    char words[1024], msg[512];
    double *mass;
    long steps = 0;
    int k, ev = SBC_EVENT_RELAXING;
    memset(&l, 0, sizeof l);
    l.escape = escape;
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    mass = malloc(sizeof *mass * (size_t)p.n);
    for (k = 0; k < p.n; ++k)
        mass[k] = 2e3 * 3.14159265358979323846 * p.r[k] * p.r[k];
    snprintf(words, sizeof words, WORDS " file %s", csv);
    h = sbc_host_create(words, 2, p.n, p.x, p.r, mass, 0, NULL, 1e-5, 1e4, msg, sizeof msg);
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
    l.e = sbc_engine_create(&def, &err);
    CHECK(l.e != NULL);
    /* a step before the callbacks is refused */
    CHECK(!h || (sbc_host_step(h) == SBC_EVENT_FAILED && strstr(sbc_host_message(h), "sbc_host_drive")));
    cb.user_data = &l;
    cb.fire_sums = lazy_fire_sums;
    cb.interior = lazy_interior;
    cb.contacts = lazy_contacts;
    cb.frame = lazy_frame;
    cb.row = lazy_row;
    /* a required callback missing is refused */
    CHECK(!h || (sbc_host_drive(h, &cb) == 0 && (cb.frame = NULL, sbc_host_drive(h, &cb)) == 1 &&
                 strstr(sbc_host_message(h), "frame")));
    cb.frame = lazy_frame;
    cb.interior_state = lazy_interior_state;
    if (h && l.e && sbc_host_drive(h, &cb) == 0) {
        sbc_frame frame; /* the engine needs the frame; the host found the same one */
        CHECK(sbc_frame_detect(&frame, p.n, p.x, p.r, 0.0, &err) == SBC_OK);
        CHECK(frame.n == sbc_host_frame_size(h) &&
              memcmp(frame.particle, sbc_host_frame_particles(h), sizeof(int) * (size_t)frame.n) == 0);
        l.Q = frame.n;
        sbc_engine_set_frame(l.e, &frame);
        while (ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED && steps < 20000000) {
            sbc_commands cmd;
            if (sbc_engine_forces(l.e, &err) != SBC_OK)
                break;
            ev = sbc_host_step(h);
            cmd.x = sbc_host_command_x(h);
            cmd.theta = sbc_host_command_theta(h);
            cmd.free_rotation = sbc_host_command_free(h);
            sbc_engine_move_frame(l.e, &cmd);
            ++steps;
        }
        CHECK(ev == (escape ? SBC_EVENT_FAILED : SBC_EVENT_FINISHED));
        if (escape)
            snprintf(message, 512, "%s", sbc_host_message(h));
        else if (ev == SBC_EVENT_FAILED)
            printf("  %s\n", sbc_host_message(h));
        CHECK(l.interior == 9 && !l.bad_line && l.rows == (escape ? 0 : 3));
        if (!escape) {
            double row[SBC_HOST_ROW];
            sbc_host_result(h, row);
            /* last increment, F12 (eq. 15 from the frame, round-off), Hill-Mandel */
            CHECK(row[COL("increment")] == 2.0 && fabs(row[COL("F12")] + 0.02) < 1e-14 &&
                  fabs(row[COL("hill_mandel")]) < 1e-6);
        }
        sbc_frame_free(&frame);
    }
    *measured = steps > 0 ? (double)l.contact_steps / (double)steps : 1.0;
    sbc_host_free(h); /* closes the CSV */
    sbc_engine_free(l.e);
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
    h = sbc_host_create(words, 2, p.n, p.x, p.r, mass, nlist, list, dt, 1e4, msg, sizeof msg);
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
    refused("P tangent condensed C.csv", 0, NULL, "keyword 'tangent' (condensed C.csv) is the embedded runner's");
    refused("P update newton", 0, NULL, "keyword 'update': newton needs the host's linearized contact network");
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
        sbc_host *h = sbc_host_create(cases[i].words, 2, p.n, p.x, p.r, mass, 0, NULL, cases[i].dt, 1e4, msg, sizeof msg);
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
