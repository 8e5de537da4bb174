#define _POSIX_C_SOURCE 200809L
/* Restart: the frame and the controller saved mid-run and loaded into new
 * objects continue exactly as the originals; contradicting settings fail. */
#include "check.h"
#include "layer.h"
#include "tests.h"

#include "sbc/controller.h"
#include "sbc/embedded/engine.h"
#include "sbc/packing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void parse(sbc_settings *s, const char *text)
{
    char buf[256], *w[32];
    int n = 0;
    sbc_error err;
    strcpy(buf, text);
    for (w[n] = strtok(buf, " "); w[n]; w[++n] = strtok(NULL, " "))
        ;
    CHECK(sbc_settings_parse(s, n, (const char *const *)w, &err) == SBC_OK);
}

/* Every value of a valid saved frame and controller state, replaced by a
 * bad one in turn: the load either refuses it by name or accepts a value in
 * range, and the accepted state's commands are finite. Under the sanitizers
 * (make check-sanitize) any out-of-range index or cast would stop the run. */
static void corrupted_states(const double *fstate, size_t nf, const double *state, size_t n, const sbc_frame *f,
                             const sbc_settings *s, const double *mass, double dt, double kn)
{
    const double bad[7] = {NAN, INFINITY, -1.0, 1e300, 0.5, 1e15, -2147483649.0};
    double *copy = malloc(sizeof(double) * (nf > n ? nf : n));
    long refused = 0, tried = 0, nonfinite_accepted = 0, bad_commands = 0;
    size_t k;
    int b, i;
    sbc_error err;
    for (k = 0; k < nf; ++k)
        for (b = 0; b < 7; ++b) {
            sbc_frame g;
            sbc_status st;
            memset(&g, 0, sizeof g);
            memcpy(copy, fstate, sizeof(double) * nf);
            copy[k] = bad[b];
            st = sbc_frame_load(&g, copy, nf, &err);
            CHECK(st == SBC_OK || (st == SBC_ERR_INPUT && strstr(err.message, "frame restart data")));
            nonfinite_accepted += st == SBC_OK && b < 2;
            refused += st != SBC_OK;
            ++tried;
            sbc_frame_free(&g);
        }
    for (k = 0; k < n; ++k)
        for (b = 0; b < 7; ++b) {
            sbc_controller *c = sbc_controller_create(f, s, mass, dt, kn, &err);
            sbc_status st;
            memcpy(copy, state, sizeof(double) * n);
            copy[k] = bad[b];
            st = sbc_controller_load(c, copy, n, &err);
            CHECK(st == SBC_OK || (st == SBC_ERR_INPUT && strstr(err.message, "restart")));
            nonfinite_accepted += st == SBC_OK && b < 2;
            refused += st != SBC_OK;
            ++tried;
            if (st == SBC_OK) {
                sbc_commands cmd = sbc_controller_commands(c);
                for (i = 0; i < 3 * f->n; ++i)
                    bad_commands += !isfinite(cmd.x[i]);
            }
            sbc_controller_free(c);
        }
    CHECK(nonfinite_accepted == 0 && bad_commands == 0);
    printf("  restart: %ld of %ld corrupted saved values refused by name, the rest in range\n", refused, tried);
    free(copy);
}

/* Mixed on a 37-disc layer, saved in the middle of the first shear
 * increment's servo iterations (the support following the measured F22, the
 * top's shifted traction target): a controller loaded from the saved state
 * continues with the same commands and rows, bit for bit. */
static void mixed_continues(void)
{
    sbc_packing p;
    sbc_frame f, h;
    sbc_settings s;
    sbc_error err;
    sbc_engine *e;
    sbc_controller *a, *b = NULL;
    double *mass, *state = NULL, *fstate = NULL;
    size_t n = 0, nf = 0;
    long step, mismatches = 0;
    int corrections = 0, done = 0;
    parse(&s, "mixed F 1 0.004 0 1 increments 2 stress P22 -1.05e6 2 accuracy tight");
    e = test_layer(&p, &f, 1);
    CHECK(e != NULL);
    if (!e) return;
    mass = malloc(sizeof(double) * (size_t)f.n);
    sbc_engine_frame_masses(e, mass);
    a = sbc_controller_create(&f, &s, mass, LAYER_DT, LAYER_KN, &err);
    CHECK(a != NULL);
    for (step = 0; a && step < 2000000 && !done; ++step) {
        sbc_snapshot snap;
        sbc_commands ca;
        sbc_event ea, eb = SBC_EVENT_RELAXING;
        sbc_engine_step(e, &err);
        sbc_engine_snapshot(e, &snap);
        ea = sbc_controller_step(a, &snap, &err);
        if (b) {
            sbc_commands cb;
            eb = sbc_controller_step(b, &snap, &err);
            cb = sbc_controller_commands(b);
            ca = sbc_controller_commands(a);
            mismatches += ea != eb || memcmp(ca.x, cb.x, sizeof(double) * 3 * (size_t)f.n) != 0;
            if (ea == SBC_EVENT_INCREMENT || ea == SBC_EVENT_FINISHED)
                mismatches += memcmp(sbc_controller_result(a), sbc_controller_result(b), sizeof(sbc_result)) != 0;
        } else if (ea == SBC_EVENT_CORRECTED && sbc_controller_increment(a) == 3 && ++corrections == 5) {
            nf = sbc_frame_state_size(sbc_controller_frame(a));
            n = sbc_controller_state_size(a);
            fstate = malloc(sizeof(double) * nf);
            state = malloc(sizeof(double) * n);
            sbc_frame_save(sbc_controller_frame(a), fstate);
            sbc_controller_save(a, state);
            CHECK(sbc_frame_load(&h, fstate, nf, &err) == SBC_OK);
            b = sbc_controller_create(&f, &s, mass, LAYER_DT, LAYER_KN, &err);
            CHECK(b != NULL && sbc_controller_load(b, state, n, &err) == SBC_OK);
        }
        done = ea == SBC_EVENT_FINISHED || ea == SBC_EVENT_FAILED;
        ca = sbc_controller_commands(a);
        sbc_engine_move_frame(e, &ca);
    }
    CHECK(b != NULL && done && mismatches == 0);
    printf("  restart: mixed, saved in the first shear increment, continued with %ld mismatches\n", mismatches);
    sbc_controller_free(a);
    sbc_controller_free(b);
    sbc_engine_free(e);
    if (b) sbc_frame_free(&h);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
    free(mass);
    free(state);
    free(fstate);
}

void test_restart(void)
{
    const char *words = "P F 0.99 -0.02 -0.02 0.99 increments 3 relax 1e-6 20 tol_force 1e-12 tol_moment 1e-12 "
                        "gain_force 1e3 gain_moment 1e3";
    sbc_packing p;
    sbc_frame f, g;
    sbc_settings s, bad;
    sbc_error err;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine *e;
    sbc_controller *a, *b;
    double mass[16], *state, *fstate;
    size_t n, nf;
    long step, mismatches = 0, corrections = 0;
    int done = 0;

    parse(&s, words);
    sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err);
    sbc_frame_detect(&f, p.n, p.x, p.r, 0.0, &err);
    def.n = p.n;
    def.x = p.x;
    def.r = p.r;
    def.dt = 1e-5;
    e = sbc_engine_create(&def, &err);
    sbc_engine_set_frame(e, &f);
    sbc_engine_frame_masses(e, mass);
    a = sbc_controller_create(&f, &s, mass, def.dt, def.law.kn, &err);
    /* run into the middle of increment 1's servo iterations */
    for (step = 0; step < 200000 && !done; ++step) {
        sbc_snapshot snap;
        sbc_commands cmd;
        sbc_event ev;
        sbc_engine_step(e, &err);
        sbc_engine_snapshot(e, &snap);
        ev = sbc_controller_step(a, &snap, &err);
        if (ev == SBC_EVENT_CORRECTED && sbc_controller_increment(a) == 1 && ++corrections == 3)
            done = 1;
        cmd = sbc_controller_commands(a);
        sbc_engine_move_frame(e, &cmd);
    }
    CHECK(done);
    /* the frame survives a save/load */
    nf = sbc_frame_state_size(&f);
    fstate = malloc(sizeof(double) * nf);
    sbc_frame_save(&f, fstate);
    CHECK(sbc_frame_load(&g, fstate, nf, &err) == SBC_OK);
    CHECK(g.n == f.n && g.V == f.V && memcmp(g.X, f.X, sizeof(double) * 3 * (size_t)f.n) == 0 &&
          memcmp(g.A, f.A, sizeof(double) * 3 * (size_t)f.n) == 0 && memcmp(g.partner, f.partner, sizeof(int) * (size_t)f.n) == 0);
    CHECK(sbc_frame_load(&g, fstate, nf - 1, &err) == SBC_ERR_INPUT);
    /* a controller on the loaded frame continues exactly as the original */
    n = sbc_controller_state_size(a);
    state = malloc(sizeof(double) * n);
    sbc_controller_save(a, state);
    b = sbc_controller_create(&g, &s, mass, def.dt, def.law.kn, &err);
    CHECK(sbc_controller_load(b, state, n, &err) == SBC_OK);
    for (done = 0; step < 2000000 && !done; ++step) {
        sbc_snapshot snap;
        sbc_commands ca, cb;
        sbc_event ea, eb;
        sbc_engine_step(e, &err);
        sbc_engine_snapshot(e, &snap);
        ea = sbc_controller_step(a, &snap, &err);
        eb = sbc_controller_step(b, &snap, &err);
        ca = sbc_controller_commands(a);
        cb = sbc_controller_commands(b);
        mismatches += ea != eb || memcmp(ca.x, cb.x, sizeof(double) * 3 * (size_t)f.n) != 0 ||
                      memcmp(ca.theta, cb.theta, sizeof(double) * (size_t)f.n) != 0;
        if (ea == SBC_EVENT_INCREMENT || ea == SBC_EVENT_FINISHED)
            mismatches += memcmp(sbc_controller_result(a), sbc_controller_result(b), sizeof(sbc_result)) != 0;
        done = ea == SBC_EVENT_FINISHED || ea == SBC_EVENT_FAILED;
        sbc_engine_move_frame(e, &ca);
    }
    CHECK(done && mismatches == 0);
    /* settings that contradict the saved path are refused, by name */
    parse(&bad, "P F 0.99 -0.03 -0.02 0.99 increments 3");
    sbc_controller_free(b);
    b = sbc_controller_create(&g, &bad, mass, def.dt, def.law.kn, &err);
    CHECK(sbc_controller_load(b, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "keyword 'F': F12"));
    sbc_controller_free(b);
    parse(&bad, "T F 0.99 -0.02 -0.02 0.99 increments 3");
    b = sbc_controller_create(&g, &bad, mass, def.dt, def.law.kn, &err);
    CHECK(sbc_controller_load(b, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "contradicts the saved P"));
    sbc_controller_free(b);
    parse(&bad, "P F 0.99 -0.02 -0.02 0.99 increments 4");
    b = sbc_controller_create(&g, &bad, mass, def.dt, def.law.kn, &err);
    CHECK(sbc_controller_load(b, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "'increments': 4"));
    sbc_controller_free(b);
    /* another time step: other gains (eq. 37), refused */
    b = sbc_controller_create(&g, &s, mass, 0.5 * def.dt, def.law.kn, &err);
    CHECK(sbc_controller_load(b, state, n, &err) == SBC_ERR_INPUT && strstr(err.message, "time step"));
    sbc_controller_free(b);
    corrupted_states(fstate, nf, state, n, &g, &s, mass, def.dt, def.law.kn);
    mixed_continues();
    free(state);
    free(fstate);
    sbc_controller_free(a);
    sbc_engine_free(e);
    sbc_frame_free(&g);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}
