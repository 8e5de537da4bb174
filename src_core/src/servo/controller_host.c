/* The controller's face to its host between steps (controller.h): the
 * commands and results it is asked for, a new F aimed at or branched to, a
 * static solve's frame adopted (interior newton), the remap of an
 * increment's opening move, the progress line. */
#include "controller_private.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

sbc_commands sbc_controller_commands(const sbc_controller *c)
{
    sbc_commands cmd;
    cmd.x = c->x_cmd;
    cmd.theta = c->theta_cmd;
    cmd.free_rotation = c->free_rot;
    return cmd;
}

void sbc_controller_adopt(sbc_controller *c, const double *x, const double *theta)
{
    int q, k;
    memcpy(c->x_cmd, x, sizeof(double) * 3 * (size_t)c->frame->n);
    for (q = 0; q < c->frame->n; ++q)
        for (k = 0; k < c->rot && !c->free_rot[q]; ++k)
            c->theta_cmd[c->rot * q + k] = theta[c->rot * q + k];
    memcpy(c->motion.x_goal, c->x_cmd, sizeof(double) * 3 * (size_t)c->frame->n);
    memcpy(c->motion.th_goal, c->theta_cmd, sizeof(double) * (size_t)(c->rot * c->frame->n));
    c->motion.done = c->motion.steps;
}

const sbc_result *sbc_controller_result(const sbc_controller *c) { return &c->result; }

int sbc_controller_increment(const sbc_controller *c) { return c->increment; }

const sbc_frame *sbc_controller_frame(const sbc_controller *c) { return c->frame; }

void sbc_controller_progress(const sbc_controller *c, int *iteration, double *r_force, double *r_moment,
                             double *r_deformation)
{
    *iteration = c->iteration;
    *r_force = c->norms.r_force;
    *r_moment = c->norms.r_moment;
    *r_deformation = c->norms.r_deformation;
}

/* F's dim x dim block into G, checked: (D), (P) or (T), det F > 0 */
static sbc_status aim_check(const sbc_controller *c, const double F[9], double G[9], sbc_error *err)
{
    const int dim = c->frame->dim;
    int i, j;
    memset(G, 0, sizeof(double) * 9);
    for (i = 0; c->s.bc == SBC_BC_MIXED && i < 3 * c->frame->n; ++i)
        if (i % 3 < dim && c->mode[i] == SBC_MODE_T)
            return sbc_fail(err, SBC_ERR_INPUT, "servo_bc mixed: frame particle %d has a T component; a new F is "
                            "aimed at with D and P components only (the whole of F given)", i / 3);
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j)
            G[SBC_IJ(i, j)] = F[SBC_IJ(i, j)];
    if (!(sbc_tensor_det(dim, G) > 0.0) || !isfinite(sbc_tensor_norm(dim, G)))
        return sbc_fail(err, SBC_ERR_GEOMETRY, "servo_bc %s: det F = %g is not positive and finite",
                        sbc_bc_name(c->s.bc), sbc_tensor_det(dim, G));
    return SBC_OK;
}

sbc_status sbc_controller_aim(sbc_controller *c, const double F[9], sbc_error *err)
{
    double G[9];
    if (c->increment <= c->total)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: increment %d of %d is under way; a new F is aimed at between "
                        "increments", sbc_bc_name(c->s.bc), c->increment, c->total);
    if (aim_check(c, F, G, err) != SBC_OK)
        return err->status;
    c->increment = c->total;
    memcpy(c->F_now, G, sizeof c->F_now);
    sbc_ctl_start_increment(c);
    return SBC_OK;
}

sbc_status sbc_controller_branch(sbc_controller *c, const double F[9], sbc_error *err)
{
    double G[9];
    if (c->increment > c->total)
        return sbc_controller_aim(c, F, err);
    if (c->steps > 0 || c->motion.done > 1 || c->iteration > 0) /* begin_move placed the first step (motion.c) */
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: increment %d has taken %ld steps; a branch starts where an "
                        "increment was accepted", sbc_bc_name(c->s.bc), c->increment, c->steps);
    if (aim_check(c, F, G, err) != SBC_OK)
        return err->status;
    /* the accepted commands, which start_increment saved, are the commands again */
    memcpy(c->x_cmd, c->motion.x_from, sizeof(double) * 3 * (size_t)c->frame->n);
    memcpy(c->theta_cmd, c->motion.th_from, sizeof(double) * (size_t)(c->rot * c->frame->n));
    memcpy(c->F_now, G, sizeof c->F_now);
    sbc_ctl_start_increment(c);
    return SBC_OK;
}

/* F along the increment's opening move at t = done / steps of the motion:
 * F_prev + t (F_now - F_prev), the affine part of the frame's commands */
static void F_along_move(const sbc_controller *c, long done, double F[9])
{
    const double t = (double)done / (double)c->motion.steps;
    int k;
    for (k = 0; k < 9; ++k)
        F[k] = done >= c->motion.steps ? c->F_now[k] : c->F_prev[k] + t * (c->F_now[k] - c->F_prev[k]);
}

void sbc_controller_accept_uncertified(sbc_controller *c, int yes) { c->accept_uncertified = yes; }

int sbc_controller_uncertified(const sbc_controller *c, char *why, size_t cap)
{
    if (c->uncertified && why && cap > 0)
        snprintf(why, cap, "%s", c->why);
    return c->uncertified;
}

void sbc_controller_set_newton(sbc_controller *c, sbc_newton_fn fn, void *user_data)
{
    c->newton = fn;
    c->newton_data = user_data;
}

int sbc_controller_remap(const sbc_controller *c, double M[9], double origin[3])
{
    const int dim = c->frame->dim;
    double from[9], to[9], whole[9];
    if (!c->s.remap || !c->remap_due || c->increment > c->total || !sbc_ctl_opening_map(c, whole, origin))
        return 0;
    F_along_move(c, c->motion.done - 1, from);
    F_along_move(c, c->motion.done, to);
    return sbc_tensor_right_divide(dim, to, from, M);
}

void sbc_controller_progress_line(const sbc_controller *c, long step, double elapsed, char *out, size_t cap)
{
    snprintf(out, cap, "increment %d: servo iteration %d, residuals force %.3e moment %.3e deformation %.3e, step %ld, "
             "elapsed %.0f s", c->increment, c->iteration, c->norms.r_force, c->norms.r_moment, c->norms.r_deformation,
             step, elapsed);
}

void sbc_controller_target_F(const sbc_controller *c, int increment, double F[9])
{
    sbc_settings_target_F(&c->s, increment, F);
}
