/* The host driver (driver.h) against the protocol written out by hand: a
 * (P) run on the 5 x 5 lattice with FIRE, once through sbc_driver_step with
 * the engine's parts as callbacks and once with sbc_engine_step and a fully
 * measured snapshot every step: the same rows, bit for bit, and the same
 * number of steps. Then the contract: the reductions asked for, a revisited
 * step, a refusal of the confinement and of the row. */
#include "check.h"
#include "tests.h"

#include "sbc/driver.h"
#include "sbc/embedded/engine.h"
#include "sbc/packing.h"

#include <string.h>

typedef struct rig {
    sbc_engine *e;
    sbc_snapshot snap;
    int Q;
    int reduced_sum, reduced_max; /* reduce calls seen */
    int refuse_confined, refuse_row;
    int contact_calls, net_calls, net_saw_other_sums;
    double net_force; /* net_force's answer; 0: interior's own */
    sbc_result rows[8];
    int nrows;
} rig;

static void fire_sums(void *u, double *sums) { sbc_engine_fire_sums(((rig *)u)->e, sums); }

static void interior(void *u, const sbc_fire_mix *mix, int again, double out[2])
{
    rig *g = u;
    (void)again;
    sbc_engine_integrate(g->e, mix);
    sbc_engine_snapshot(g->e, &g->snap);
    out[0] = g->snap.kinetic_energy;
    out[1] = g->snap.unbalanced_max;
}

static void contacts(void *u, double out[4])
{
    const sbc_snapshot *s = &((rig *)u)->snap;
    ++((rig *)u)->contact_calls;
    out[0] = s->potential_energy, out[1] = s->overlap_sum, out[2] = (double)s->contact_count;
    out[3] = s->contact_force_sum;
}

static double net_force(void *u, const double *sums)
{
    rig *g = u;
    g->net_saw_other_sums |= !(sums[0] == g->snap.potential_energy && sums[3] == g->snap.contact_force_sum);
    ++g->net_calls;
    return g->net_force > 0.0 ? g->net_force : g->snap.unbalanced_max;
}

static void frame(void *u, double *buf)
{
    const rig *g = u;
    sbc_driver_frame_from_snapshot(&g->snap, 2, g->Q, buf);
}

static void reduce(void *u, const double *in, double *out, int n, sbc_reduce_op op)
{
    rig *g = u;
    g->reduced_sum += op == SBC_REDUCE_SUM;
    g->reduced_max += op == SBC_REDUCE_MAX;
    memcpy(out, in, sizeof(double) * (size_t)n);
}

static int confined(void *u, const double *fx, int increment, char *message, size_t cap)
{
    (void)fx;
    if (!((rig *)u)->refuse_confined)
        return SBC_OK;
    snprintf(message, cap, "test: particle 7 left at increment %d", increment);
    return SBC_ERR_GEOMETRY;
}

static int row(void *u, const sbc_result *r, const char *line, char *message, size_t cap)
{
    rig *g = u;
    if (g->refuse_row) {
        snprintf(message, cap, "test: the row of increment %d cannot be written", r->increment);
        return SBC_ERR_IO;
    }
    CHECK(strstr(line, "servo_bc P: increment ") == line);
    if (g->nrows < 8)
        g->rows[g->nrows++] = *r;
    return SBC_OK;
}

static void setup(rig *g, sbc_packing *p, sbc_frame *f, sbc_settings *s, sbc_controller **c)
{
    /* the rig has no remap callback: remap none */
    static const char *words[] = {"P", "F", "0.999", "0.002", "0", "0.999", "increments", "2", "remap", "none"};
    sbc_engine_def def = sbc_engine_def_default();
    sbc_error err;
    double mass[64];
    memset(g, 0, sizeof *g);
    CHECK(sbc_settings_parse(s, 10, words, &err) == SBC_OK);
    sbc_packing_lattice_square(p, 5, 5, 2e-3, 1.02e-3, &err);
    sbc_frame_detect(f, p->n, p->x, p->r, 0.0, &err);
    def.n = p->n, def.x = p->x, def.r = p->r, def.dt = 1e-5, def.fire = 1;
    g->e = sbc_engine_create(&def, &err);
    sbc_engine_set_frame(g->e, f);
    sbc_engine_frame_masses(g->e, mass);
    g->Q = f->n;
    *c = sbc_controller_create(f, s, mass, def.dt, def.law.kn, &err);
    CHECK(*c != NULL);
}

static void teardown(rig *g, sbc_packing *p, sbc_frame *f, sbc_controller *c, sbc_driver *d)
{
    sbc_driver_free(d);
    sbc_controller_free(c);
    sbc_engine_free(g->e);
    sbc_frame_free(f);
    sbc_packing_free(p);
}

/* host steps through the driver until an increment converges or the run stops */
static sbc_event until_converged_or_stopped(rig *g, sbc_controller *c, sbc_driver *d, sbc_error *err)
{
    sbc_event ev = d ? SBC_EVENT_RELAXING : SBC_EVENT_FAILED; /* no driver: its creation failed */
    while (ev == SBC_EVENT_RELAXING || ev == SBC_EVENT_CORRECTED) {
        sbc_commands cmd;
        sbc_engine_forces(g->e, err);
        ev = sbc_driver_step(d, 0, err);
        cmd = sbc_controller_commands(c);
        sbc_engine_move_frame(g->e, &cmd);
    }
    return ev;
}

void test_driver(void)
{
    sbc_packing p, p2;
    sbc_frame f, f2;
    sbc_settings s;
    sbc_controller *c, *h;
    sbc_driver *d;
    sbc_driver_callbacks cb = {NULL, fire_sums, interior, contacts, frame, reduce, confined, row, net_force, NULL, NULL, NULL, NULL, 0};
    sbc_error err;
    rig g, by_hand;
    long steps = 0, hand_steps = 0;
    sbc_event ev = SBC_EVENT_RELAXING;
    int k;

    /* the driver */
    setup(&g, &p, &f, &s, &c);
    cb.user_data = &g;
    s.remap = 1; /* a host without the remap callback refuses remap x by name */
    CHECK(sbc_driver_create(c, &s, &cb, &err) == NULL &&
          strstr(err.message, "keyword 'remap': x needs a host that moves its interior particles") != NULL);
    s.remap = 0;
    d = sbc_driver_create(c, &s, &cb, &err);
    CHECK(d != NULL);
    while (d && ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED && steps < 2000000) {
        sbc_commands cmd;
        sbc_engine_forces(g.e, &err);
        ev = sbc_driver_step(d, 0, &err);
        cmd = sbc_controller_commands(c);
        sbc_engine_move_frame(g.e, &cmd);
        ++steps;
    }
    CHECK(ev == SBC_EVENT_FINISHED && g.nrows == 3);
    /* FIRE's sums and Ek summed, the largest net force maxed, every step, and
       again on every step that measured the contacts (net_force) */
    CHECK(g.net_calls == g.contact_calls && g.net_calls > 0 && !g.net_saw_other_sums && g.reduced_max == steps + g.net_calls &&
          g.reduced_sum >= 2 * steps);

    /* by hand: sbc_engine_step and the whole snapshot every step */
    setup(&by_hand, &p2, &f2, &s, &h);
    ev = SBC_EVENT_RELAXING;
    for (k = 0; ev != SBC_EVENT_FINISHED && ev != SBC_EVENT_FAILED && hand_steps < 2000000; ++hand_steps) {
        sbc_commands cmd;
        sbc_snapshot snap;
        sbc_engine_step(by_hand.e, &err);
        sbc_engine_snapshot(by_hand.e, &snap);
        ev = sbc_controller_step(h, &snap, &err);
        if ((ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) && k < 8)
            by_hand.rows[k++] = *sbc_controller_result(h);
        cmd = sbc_controller_commands(h);
        sbc_engine_move_frame(by_hand.e, &cmd);
    }
    CHECK(ev == SBC_EVENT_FINISHED && k == 3 && hand_steps == steps);
    for (k = 0; k < 3; ++k)
        CHECK(memcmp(&g.rows[k], &by_hand.rows[k], sizeof g.rows[k]) == 0);
    printf("  driver: (P) 5 x 5, FIRE: %ld steps, the 3 rows of the hand-written protocol bit for bit\n", steps);
    sbc_driver_free(d);
    sbc_controller_free(c);
    sbc_controller_free(h);
    sbc_engine_free(g.e);
    sbc_engine_free(by_hand.e);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
    sbc_frame_free(&f2);
    sbc_packing_free(&p2);

    /* the contract: a revisit, the refusals */
    setup(&g, &p, &f, &s, &c);
    cb.user_data = &g;
    d = sbc_driver_create(c, &s, &cb, &err);
    CHECK(d != NULL);
    if (!d) {
        teardown(&g, &p, &f, c, d);
        return;
    }
    sbc_engine_forces(g.e, &err);
    CHECK(sbc_driver_step(d, 1, &err) == SBC_EVENT_RELAXING && g.reduced_sum == 1); /* no FIRE, no controller */
    g.refuse_row = 1;
    ev = until_converged_or_stopped(&g, c, d, &err);
    CHECK(ev == SBC_EVENT_FAILED && err.status == SBC_ERR_IO && strstr(err.message, "row of increment 0"));
    teardown(&g, &p, &f, c, d);
    setup(&g, &p, &f, &s, &c);
    cb.user_data = &g;
    g.refuse_confined = 1;
    d = sbc_driver_create(c, &s, &cb, &err);
    ev = until_converged_or_stopped(&g, c, d, &err);
    CHECK(ev == SBC_EVENT_FAILED && err.status == SBC_ERR_GEOMETRY && strstr(err.message, "particle 7 left at "
                                                                                           "increment 0"));
    teardown(&g, &p, &f, c, d);
    /* net_force's answer is the one the controller judges: 1 N, no increment converges */
    setup(&g, &p, &f, &s, &c);
    cb.user_data = &g;
    g.net_force = 1.0;
    d = sbc_driver_create(c, &s, &cb, &err);
    CHECK(d != NULL);
    for (ev = SBC_EVENT_RELAXING, k = 0; d && k < steps && ev != SBC_EVENT_INCREMENT && ev != SBC_EVENT_FAILED; ++k) {
        sbc_commands cmd;
        sbc_engine_forces(g.e, &err);
        ev = sbc_driver_step(d, 0, &err);
        cmd = sbc_controller_commands(c);
        sbc_engine_move_frame(g.e, &cmd);
    }
    CHECK(ev == SBC_EVENT_RELAXING && g.nrows == 0 && g.net_calls > 0);
    /* missing callbacks are refused */
    cb.frame = NULL;
    CHECK(sbc_driver_create(c, &s, &cb, &err) == NULL && strstr(err.message, "callbacks"));
    teardown(&g, &p, &f, c, d);
}
