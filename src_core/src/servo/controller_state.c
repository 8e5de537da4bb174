/* The controller's restart state: one array of doubles, saved and loaded
 * with every value checked (saved.h; controller_private.h). */
#include "controller_private.h"
#include "sbc/saved.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Restart layout (doubles): version, Q, bc, increments, F (4), dt | increment, servo,
 * iteration, r_first, steps, norms (4), relax (steps, count, rising, past_peak,
 * ek_prev, at_rest), lambda, have_prev, win_min, prev_min, F_prev (4), F_now (4), relax (tol, known_step, ep_known,
 * ek_known, fc_known, unbalanced), motion (steps, done), P_shift (4), path (force, work, sigma) | result (23) |
 * x_cmd (2Q),
 * theta_cmd (Q), free_rot (Q), x_prev (2Q), reference X (2Q), d_prev (3Q), motion (x_from, x_goal 4Q,
 * th_from, th_goal 2Q). */
#define STATE_VERSION 8.0
#define STATE_HEAD 9
#define STATE_SCALARS 42
#define STATE_RESULT 23

size_t sbc_controller_state_size(const sbc_controller *c)
{
    return STATE_HEAD + STATE_SCALARS + STATE_RESULT + 17 * (size_t)c->frame->n;
}

static double *put_result(const sbc_result *r, double *o)
{
    int k;
    *o++ = r->increment;
    for (k = 0; k < 4; ++k) *o++ = r->F[k];
    for (k = 0; k < 4; ++k) *o++ = r->P[k];
    for (k = 0; k < 4; ++k) *o++ = r->sigma[k];
    *o++ = r->overlap_mean;
    *o++ = r->rotation_mean;
    *o++ = r->iterations;
    *o++ = (double)r->relax_steps;
    *o++ = r->r_force;
    *o++ = r->r_moment;
    *o++ = r->r_deformation;
    *o++ = r->hill_mandel;
    *o++ = r->unbalanced;
    *o++ = r->frame_residual;
    return o;
}

/* counters saved as doubles: at most 2^50, far below where a long or a
 * double stops counting steps one by one */
#define SAVED_COUNT 1125899906842624L

static void get_result(sbc_result *r, sbc_saved *rd, int total)
{
    int k;
    r->increment = (int)sbc_saved_int(rd, "result increment", 0, total);
    for (k = 0; k < 4; ++k) r->F[k] = sbc_saved_real(rd, "result F");
    for (k = 0; k < 4; ++k) r->P[k] = sbc_saved_real(rd, "result P");
    for (k = 0; k < 4; ++k) r->sigma[k] = sbc_saved_real(rd, "result sigma");
    r->overlap_mean = sbc_saved_real(rd, "result overlap_mean");
    r->rotation_mean = sbc_saved_real(rd, "result rotation_mean");
    r->iterations = (int)sbc_saved_int(rd, "result iterations", 0, INT_MAX);
    r->relax_steps = sbc_saved_int(rd, "result relax_steps", 0, SAVED_COUNT);
    r->r_force = sbc_saved_real(rd, "result r_force");
    r->r_moment = sbc_saved_real(rd, "result r_moment");
    r->r_deformation = sbc_saved_real(rd, "result r_deformation");
    r->hill_mandel = sbc_saved_real(rd, "result hill_mandel");
    r->unbalanced = sbc_saved_real(rd, "result unbalanced");
    r->frame_residual = sbc_saved_real(rd, "result frame_residual");
}

void sbc_controller_save(const sbc_controller *c, double *o)
{
    int k, q = c->frame->n;
    *o++ = STATE_VERSION;
    *o++ = q;
    *o++ = c->s.bc;
    *o++ = c->s.increments;
    for (k = 0; k < 4; ++k) *o++ = c->s.F[k];
    *o++ = c->dt;
    *o++ = c->increment;
    *o++ = c->servo;
    *o++ = c->iteration;
    *o++ = c->r_first;
    *o++ = (double)c->steps;
    *o++ = c->norms.r_force;
    *o++ = c->norms.r_moment;
    *o++ = c->norms.r_deformation;
    *o++ = c->norms.max_step;
    *o++ = (double)c->relax.steps;
    *o++ = c->relax.count;
    *o++ = c->relax.rising;
    *o++ = c->relax.past_peak;
    *o++ = c->relax.ek_prev;
    *o++ = c->relax.at_rest;
    *o++ = c->lambda;
    *o++ = c->have_prev;
    *o++ = c->win_min;
    *o++ = c->prev_min;
    for (k = 0; k < 4; ++k) *o++ = c->F_prev[k];
    for (k = 0; k < 4; ++k) *o++ = c->F_now[k];
    *o++ = c->relax.tol;
    *o++ = (double)c->relax.known_step;
    *o++ = c->relax.ep_known;
    *o++ = c->relax.ek_known;
    *o++ = c->relax.fc_known;
    *o++ = c->relax.unbalanced;
    *o++ = (double)c->motion.steps;
    *o++ = (double)c->motion.done;
    for (k = 0; k < 4; ++k) *o++ = c->P_shift[k];
    *o++ = c->relax.path_force;
    *o++ = c->work_path;
    *o++ = c->sigma_path;
    o = put_result(&c->result, o);
    for (k = 0; k < 2 * q; ++k) *o++ = c->x_cmd[k];
    for (k = 0; k < q; ++k) *o++ = c->theta_cmd[k];
    for (k = 0; k < q; ++k) *o++ = c->free_rot[k];
    for (k = 0; k < 2 * q; ++k) *o++ = c->x_prev[k];
    for (k = 0; k < 2 * q; ++k) *o++ = c->ref.X[k];
    for (k = 0; k < 3 * q; ++k) *o++ = c->d_prev[k];
    for (k = 0; k < 2 * q; ++k) *o++ = c->motion.x_from[k];
    for (k = 0; k < 2 * q; ++k) *o++ = c->motion.x_goal[k];
    for (k = 0; k < q; ++k) *o++ = c->motion.th_from[k];
    for (k = 0; k < q; ++k) *o++ = c->motion.th_goal[k];
}

sbc_status sbc_controller_load(sbc_controller *c, const double *in, size_t n, sbc_error *err)
{
    static const char *names[4] = {"F11", "F12", "F21", "F22"};
    const char *what = "servo_bc restart state";
    int k, q = c->frame->n;
    long saved_q, saved_bc, saved_increments;
    const double *ref;
    sbc_saved rd;
    if (n < STATE_HEAD || in[0] != STATE_VERSION)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: the saved servo_bc state (version %g, %zu values) is not this "
                        "version's (%g)", n > 0 ? in[0] : 0.0, n, STATE_VERSION);
    sbc_saved_start(&rd, in + 1, STATE_HEAD - 1, what, err);
    saved_q = sbc_saved_int(&rd, "frame particles", 0, INT_MAX);
    saved_bc = sbc_saved_int(&rd, "boundary condition", SBC_BC_D, SBC_BC_MIXED);
    saved_increments = sbc_saved_int(&rd, "increments", 1, INT_MAX);
    if (rd.st != SBC_OK)
        return rd.st;
    if (saved_q != q)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: the saved frame has %ld particles, this one %d", saved_q, q);
    if (n != sbc_controller_state_size(c))
        return sbc_fail(err, SBC_ERR_INPUT, "restart: the saved servo_bc state has %zu values, a frame of %d particles "
                        "%zu", n, q, sbc_controller_state_size(c));
    if (saved_bc != (long)c->s.bc)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: boundary condition %s contradicts the saved %s",
                        sbc_bc_name(c->s.bc), sbc_bc_name((sbc_bc)saved_bc));
    if (saved_increments != c->s.increments)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: keyword 'increments': %d contradicts the saved %ld",
                        c->s.increments, saved_increments);
    for (k = 0; k < 4; ++k)
        if (in[4 + k] != c->s.F[k])
            return sbc_fail(err, SBC_ERR_INPUT, "restart: keyword 'F': %s = %.17g contradicts the saved %.17g", names[k],
                            c->s.F[k], in[4 + k]);
    /* the gains scale with dt^2 (eq. 37): a host that forgets the time step
       across a restart (LIGGGHTS 3.8 does) would servo with other gains */
    if (in[8] != c->dt)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: time step %.17g s contradicts the saved %.17g s (set the time "
                        "step before the fix)", c->dt, in[8]);
    sbc_saved_start(&rd, in + STATE_HEAD, n - STATE_HEAD, what, err);
    c->increment = (int)sbc_saved_int(&rd, "increment", 0, c->total + 1L);
    c->servo = (int)sbc_saved_int(&rd, "servo", 0, 1);
    c->iteration = (int)sbc_saved_int(&rd, "iteration", 0, INT_MAX);
    c->r_first = sbc_saved_real(&rd, "r_first");
    c->steps = sbc_saved_int(&rd, "steps", 0, SAVED_COUNT);
    c->norms.r_force = sbc_saved_real(&rd, "r_force");
    c->norms.r_moment = sbc_saved_real(&rd, "r_moment");
    c->norms.r_deformation = sbc_saved_real(&rd, "r_deformation");
    c->norms.max_step = sbc_saved_real(&rd, "max_step");
    c->relax.criterion = c->s.criterion;
    c->relax.window = c->s.window;
    c->relax.steps = sbc_saved_int(&rd, "relaxation steps", 0, SAVED_COUNT);
    c->relax.count = (int)sbc_saved_int(&rd, "relaxation count", 0, INT_MAX);
    c->relax.rising = (int)sbc_saved_int(&rd, "relaxation rising", 0, 1);
    c->relax.past_peak = (int)sbc_saved_int(&rd, "relaxation past_peak", 0, 1);
    c->relax.ek_prev = sbc_saved_real(&rd, "relaxation ek_prev");
    c->relax.at_rest = (int)sbc_saved_int(&rd, "relaxation at_rest", 0, 1);
    c->lambda = sbc_saved_real(&rd, "lambda");
    c->have_prev = (int)sbc_saved_int(&rd, "have_prev", 0, 1);
    c->win_min = sbc_saved_real(&rd, "win_min");
    c->prev_min = sbc_saved_real(&rd, "prev_min");
    for (k = 0; k < 4; ++k) c->F_prev[k] = sbc_saved_real(&rd, "F_prev");
    for (k = 0; k < 4; ++k) c->F_now[k] = sbc_saved_real(&rd, "F_now");
    c->relax.tol = sbc_saved_positive(&rd, "relaxation tol");
    c->relax.known_step = sbc_saved_int(&rd, "relaxation known_step", 0, SAVED_COUNT);
    c->relax.ep_known = sbc_saved_real(&rd, "relaxation ep_known");
    c->relax.ek_known = sbc_saved_real(&rd, "relaxation ek_known");
    c->relax.fc_known = sbc_saved_real(&rd, "relaxation fc_known");
    c->relax.unbalanced = sbc_saved_real(&rd, "relaxation unbalanced");
    c->motion.steps = sbc_saved_int(&rd, "motion steps", 0, SAVED_COUNT);
    c->motion.done = sbc_saved_int(&rd, "motion done", 0, SAVED_COUNT);
    for (k = 0; k < 4; ++k) c->P_shift[k] = sbc_saved_real(&rd, "P_shift");
    c->relax.path_force = sbc_saved_real(&rd, "path force");
    c->work_path = sbc_saved_real(&rd, "path work scale");
    c->sigma_path = sbc_saved_real(&rd, "path stress");
    get_result(&c->result, &rd, c->total);
    for (k = 0; k < 2 * q; ++k) c->x_cmd[k] = sbc_saved_real(&rd, "x_cmd");
    for (k = 0; k < q; ++k) c->theta_cmd[k] = sbc_saved_real(&rd, "theta_cmd");
    for (k = 0; k < q; ++k) c->free_rot[k] = (unsigned char)sbc_saved_int(&rd, "free_rot", 0, 1);
    for (k = 0; k < 2 * q; ++k) c->x_prev[k] = sbc_saved_real(&rd, "x_prev");
    ref = rd.in + rd.at; /* the reference, checked here, set below */
    for (k = 0; k < 2 * q; ++k) (void)sbc_saved_real(&rd, "reference X");
    for (k = 0; k < 3 * q; ++k) c->d_prev[k] = sbc_saved_real(&rd, "d_prev");
    for (k = 0; k < 2 * q; ++k) c->motion.x_from[k] = sbc_saved_real(&rd, "motion x_from");
    for (k = 0; k < 2 * q; ++k) c->motion.x_goal[k] = sbc_saved_real(&rd, "motion x_goal");
    for (k = 0; k < q; ++k) c->motion.th_from[k] = sbc_saved_real(&rd, "motion th_from");
    for (k = 0; k < q; ++k) c->motion.th_goal[k] = sbc_saved_real(&rd, "motion th_goal");
    if (rd.st != SBC_OK)
        return rd.st;
    if (c->motion.done > c->motion.steps)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: the frame's travel has done %ld of %ld steps", what, c->motion.done,
                        c->motion.steps);
    if (!(c->lambda > 0.0) || !(c->F_now[0] * c->F_now[3] - c->F_now[1] * c->F_now[2] > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: secant factor %g or det F %g is not > 0", what, c->lambda,
                        c->F_now[0] * c->F_now[3] - c->F_now[1] * c->F_now[2]);
    {
        /* every saved position within ten frame sizes of the frame's place at creation */
        const double *sets[5] = {c->x_cmd, c->x_prev, ref, c->motion.x_from, c->motion.x_goal};
        double lo[2] = {DBL_MAX, DBL_MAX}, hi[2] = {-DBL_MAX, -DBL_MAX}, reach;
        int d, m;
        for (k = 0; k < q; ++k)
            for (d = 0; d < 2; ++d) {
                lo[d] = fmin(lo[d], c->frame->X[2 * k + d]);
                hi[d] = fmax(hi[d], c->frame->X[2 * k + d]);
            }
        reach = 10.0 * fmax(hi[0] - lo[0], hi[1] - lo[1]);
        for (m = 0; m < 5; ++m)
            for (k = 0; k < 2 * q; ++k)
                if (fabs(sets[m][k] - 0.5 * (lo[k % 2] + hi[k % 2])) > reach)
                    return sbc_fail(err, SBC_ERR_INPUT, "%s: a saved frame position, %.17g m, lies more than ten "
                                    "frame sizes (%g m) from the frame", what, sets[m][k], reach);
    }
    sbc_ctl_new_reference(c, ref);
    if (c->s.bc == SBC_BC_MIXED)
        sbc_ctl_mixed_stress_targets(c);
    return SBC_OK;
}
