#define _POSIX_C_SOURCE 200809L
/* Restart: the frame and the controller saved mid-run and loaded into new
 * objects continue exactly as the originals; contradicting settings fail. */
#include "check.h"
#include "tests.h"

#include "sbc/controller.h"
#include "sbc/engine.h"
#include "sbc/packing.h"

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
    CHECK(g.n == f.n && g.V == f.V && memcmp(g.X, f.X, sizeof(double) * 2 * (size_t)f.n) == 0 &&
          memcmp(g.A, f.A, sizeof(double) * 2 * (size_t)f.n) == 0 && memcmp(g.partner, f.partner, sizeof(int) * (size_t)f.n) == 0);
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
        mismatches += ea != eb || memcmp(ca.x, cb.x, sizeof(double) * 2 * (size_t)f.n) != 0 ||
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
    free(state);
    free(fstate);
    sbc_controller_free(a);
    sbc_engine_free(e);
    sbc_frame_free(&g);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
}
