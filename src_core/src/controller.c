/* The servo_bc controller as a state machine: (D) of Table 1. */
#include "sbc/controller.h"

#include "sbc/homogenize.h"
#include "sbc/relax.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sbc_controller {
    const sbc_frame *frame;
    sbc_settings s;
    double dt;           /* s */
    double *mass;        /* [Q] kg */
    int increment;       /* 0 .. i_tot */
    sbc_relax relax;
    double *x_cmd;       /* [2Q] m */
    double *theta_cmd;   /* [Q] rad */
    unsigned char *free_rot;
    double *a;           /* [2Q] boundary forces a_q = -sum of contact forces (eq. 5), N */
    sbc_result result;
};

sbc_controller *sbc_controller_create(const sbc_frame *frame, const sbc_settings *settings, const double *mass,
                                      double dt, sbc_error *err)
{
    sbc_controller *c;
    size_t q = (size_t)frame->n;
    if (!(dt > 0.0) || !isfinite(dt)) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s is not positive", dt);
        return NULL;
    }
    c = calloc(1, sizeof *c);
    if (!c) {
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return NULL;
    }
    c->frame = frame;
    c->s = *settings;
    c->dt = dt;
    c->mass = malloc(sizeof(double) * q);
    c->x_cmd = malloc(sizeof(double) * 2 * q);
    c->theta_cmd = calloc(q, sizeof(double));
    c->free_rot = calloc(q, 1);
    c->a = malloc(sizeof(double) * 2 * q);
    if (!c->mass || !c->x_cmd || !c->theta_cmd || !c->free_rot || !c->a) {
        sbc_controller_free(c);
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory for a frame of %d particles", frame->n);
        return NULL;
    }
    memcpy(c->mass, mass, sizeof(double) * q);
    memcpy(c->x_cmd, frame->X, sizeof(double) * 2 * q); /* increment 0: F = I */
    sbc_relax_start(&c->relax, c->s.tol_E, c->s.window);
    return c;
}

void sbc_controller_free(sbc_controller *c)
{
    if (!c)
        return;
    free(c->mass);
    free(c->x_cmd);
    free(c->theta_cmd);
    free(c->free_rot);
    free(c->a);
    free(c);
}

sbc_commands sbc_controller_commands(const sbc_controller *c)
{
    sbc_commands cmd;
    cmd.x = c->x_cmd;
    cmd.theta = c->theta_cmd;
    cmd.free_rotation = c->free_rot;
    return cmd;
}

const sbc_result *sbc_controller_result(const sbc_controller *c) { return &c->result; }

int sbc_controller_increment(const sbc_controller *c) { return c->increment; }

void sbc_controller_target_F(const sbc_controller *c, int increment, double F[4])
{
    static const double I[4] = {1.0, 0.0, 0.0, 1.0};
    double t = (double)increment / (double)c->s.increments;
    int k;
    for (k = 0; k < 4; ++k)
        F[k] = I[k] + t * (c->s.F[k] - I[k]);
}

/* Table 1, step 1.1: x_q = F X_q and Q_q = I on the whole frame. */
static void command_homogeneous(sbc_controller *c, const double F[4])
{
    const sbc_frame *f = c->frame;
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[2 * q];
        c->x_cmd[2 * q] = F[0] * X[0] + F[1] * X[1];
        c->x_cmd[2 * q + 1] = F[2] * X[0] + F[3] * X[1];
        c->theta_cmd[q] = 0.0;
        c->free_rot[q] = 0;
    }
}

static int snapshot_finite(const sbc_frame *f, const sbc_snapshot *s, const char **what)
{
    int k;
    if (!isfinite(s->kinetic_energy)) { *what = "kinetic energy"; return 0; }
    if (!isfinite(s->potential_energy)) { *what = "potential energy"; return 0; }
    for (k = 0; k < 2 * f->n; ++k) {
        if (!isfinite(s->x[k])) { *what = "frame position"; return 0; }
        if (!isfinite(s->force[k])) { *what = "frame reaction force"; return 0; }
    }
    for (k = 0; k < f->n; ++k)
        if (!isfinite(s->theta[k]) || !isfinite(s->torque[k])) { *what = "frame rotation or moment"; return 0; }
    return 1;
}

/* Homogenized measures of a relaxed state (eqs. 15, 23, 30, 31, 39, 41). */
static sbc_status measure(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const sbc_frame *f = c->frame;
    sbc_result *r = &c->result;
    double scale;
    int k;
    for (k = 0; k < 2 * f->n; ++k)
        c->a[k] = -snap->force[k]; /* eq. 5: sum of contact forces = -a_q */
    r->increment = c->increment;
    sbc_homogenize_F(f, snap->x, r->F);
    sbc_homogenize_P(f, c->a, r->P);
    if (sbc_homogenize_cauchy(r->P, r->F, r->sigma, err) != SBC_OK)
        return sbc_fail(err, SBC_ERR_GEOMETRY, "servo_bc %s: increment %d: %s", sbc_bc_name(c->s.bc),
                        c->increment, err ? err->message : "det F <= 0");
    scale = sbc_homogenize_work_scale(r->P, r->F);
    r->hill_mandel = sbc_homogenize_hill_mandel(f, c->a, snap->x, r->F, r->P);
    if (scale > 0.0)
        r->hill_mandel /= scale;
    r->overlap_mean = snap->contact_count > 0 ? snap->overlap_sum / (double)snap->contact_count : 0.0;
    r->rotation_mean = snap->particle_count > 0 ? snap->rotation_sum / (double)snap->particle_count : 0.0;
    r->iterations = 0;
    r->relax_steps = c->relax.steps;
    r->r_force = r->r_moment = r->r_deformation = 0.0;
    return SBC_OK;
}

sbc_event sbc_controller_step(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const char *what = NULL;
    double F[4];
    if (c->increment > c->s.increments) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: the loading path is already finished", sbc_bc_name(c->s.bc));
        return SBC_EVENT_FAILED;
    }
    if (!snapshot_finite(c->frame, snap, &what)) {
        sbc_fail(err, SBC_ERR_NUMERIC,
                 "servo_bc %s: increment %d, relaxation step %ld: non-finite %s (the packing blew up; "
                 "lower the time step)",
                 sbc_bc_name(c->s.bc), c->increment, c->relax.steps + 1, what);
        return SBC_EVENT_FAILED;
    }
    if (!sbc_relax_update(&c->relax, snap->kinetic_energy, snap->potential_energy)) {
        if (c->relax.steps >= c->s.max_relax_steps) {
            sbc_fail(err, SBC_ERR_DIVERGED,
                     "servo_bc %s: increment %d: relaxation did not reach Ek/Ep <= %g for %d steps within %ld "
                     "steps (Ek = %g J, Ep = %g J); check damping and time step, or raise max_relax_steps",
                     sbc_bc_name(c->s.bc), c->increment, c->s.tol_E, c->s.window, c->relax.steps,
                     snap->kinetic_energy, snap->potential_energy);
            return SBC_EVENT_FAILED;
        }
        return SBC_EVENT_RELAXING;
    }
    /* Table 1, step 1.3: the relaxed configuration is the result of increment i. */
    if (measure(c, snap, err) != SBC_OK)
        return SBC_EVENT_FAILED;
    if (c->increment == c->s.increments) {
        c->increment++;
        return SBC_EVENT_FINISHED;
    }
    c->increment++;
    sbc_controller_target_F(c, c->increment, F);
    command_homogeneous(c, F);
    sbc_relax_start(&c->relax, c->s.tol_E, c->s.window);
    return SBC_EVENT_INCREMENT;
}
