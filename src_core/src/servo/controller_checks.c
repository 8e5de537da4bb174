/* The controller's refusals before a run, its failure messages, and the
 * certification of a row before it is written (controller_private.h). */
#include "controller_private.h"
#include "sbc/homogenize.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the force and moment tolerances in force: tol_relative when set */
double sbc_ctl_tol_force(const sbc_controller *c)
{
    return c->s.tol_relative > 0.0 ? c->s.tol_relative : c->s.tol_force;
}

double sbc_ctl_tol_moment(const sbc_controller *c)
{
    return c->s.tol_relative > 0.0 ? c->s.tol_relative : c->s.tol_moment;
}

/* The first step of an increment places every frame particle on its start
 * position at once (Tables 1-3, 2.1), which moves it by the increment of F on
 * its reference position, |(F_i - F_(i-1)) X_q|, and grows with the sample.
 * A jump of more than half a radius pushes the frame particle that far into
 * its neighbours in one time step, and the packing is thrown apart (the
 * 100 x 100 lattice of docs/stability.md: 2.1 radii, increment 2 blew up).
 * F ramps linearly, so every loading increment jumps alike: checked once,
 * before the run. (The start position of Table 3 also drops the fluctuation
 * of the previous increment; that part is the paper's algorithm, up to 0.5
 * radii on eq. 38 under (T), and is not checked.) Corrections are bounded the
 * same way (max_step). Returns 1 with the message in err when the jump is too
 * long. */
int sbc_ctl_increments_too_coarse(const sbc_controller *c, sbc_error *err)
{
    const sbc_frame *f = c->frame;
    const int first = (c->s.bc == SBC_BC_MIXED ? c->s.stress_increments : 0) + 1;
    double F[9], G[9], dF[9], jump = 0.0;
    int q, k, worst = 0;
    sbc_settings_target_F(&c->s, first, F);
    sbc_settings_target_F(&c->s, first - 1, G);
    for (k = 0; k < 9; ++k)
        dF[k] = F[k] - G[k];
    for (q = 0; q < f->n; ++q) {
        double u[3], d;
        sbc_tensor_apply(f->dim, dF, &f->X[3 * q], u);
        d = hypot(hypot(u[0], u[1]), u[2]); /* hypot(h, 0) = |h| exactly (C11 F.10.4.3) */
        if (d / f->R[q] > jump) {
            jump = d / f->R[q];
            worst = q;
        }
    }
    if (jump <= 0.5 || (c->s.speed > 0.0 && c->kn > 0.0)) /* a travelling frame does not jump */
        return 0;
    sbc_fail(err, SBC_ERR_INPUT,
             "servo_bc %s: increment %d: its first step moves frame particle %d (position %d of the frame) by %.3g "
             "radii, more than half a radius in one time step (the increment of F on a sample this size); take at "
             "least %d times as many increments",
             sbc_bc_name(c->s.bc), first, f->particle[worst], worst, jump, (int)ceil(jump / 0.5));
    return 1;
}

/* too_slow: the iteration converges but not within max_iterations. */
void sbc_ctl_diverged(const sbc_controller *c, const sbc_servo_norms *n, const char *why, int too_slow,
                     sbc_error *err)
{
    const char *gain = c->s.bc == SBC_BC_T ? "gain_force or gain_deformation" : "gain_force or gain_moment";
    sbc_fail(err, SBC_ERR_DIVERGED,
             "servo_bc %s: increment %d, iteration %d: %s (r_force = %.3g, r_moment = %.3g, r_deformation = %.3g; "
             "tolerances %.3g, %.3g, %.3g); %s %s",
             sbc_bc_name(c->s.bc), c->increment, c->iteration, why, n->r_force, n->r_moment, n->r_deformation,
             sbc_ctl_tol_force(c), sbc_ctl_tol_moment(c), c->s.tol_deformation,
             too_slow ? "raise max_iterations, loosen the tolerances or raise" : "lower", gain);
}

void sbc_ctl_stagnated(const sbc_controller *c, const sbc_servo_norms *n, sbc_error *err)
{
    sbc_fail(err, SBC_ERR_DIVERGED,
             "servo_bc %s: increment %d, iteration %d: the residuals stagnated on round-off at %.3g times the "
             "tolerances (the force residual is %.2g of the frame's forces, and their smallest ratio to the tolerances "
             "in the last %d iterations is not 1 %% below that of the %d before; r_force = %.3g, r_moment = %.3g, "
             "r_deformation = %.3g; tolerances %.3g, %.3g, %.3g): loosen the tolerances",
             sbc_bc_name(c->s.bc), c->increment, c->iteration, c->win_min, n->relative_force, STAGNATION_WINDOW,
             STAGNATION_WINDOW, n->r_force, n->r_moment, n->r_deformation, sbc_ctl_tol_force(c), sbc_ctl_tol_moment(c),
             c->s.tol_deformation);
}

/* The accuracy the words in force state for a row (docs/servo_bc.md,
 * "Accuracy"): the preset's, loosened by a balance or frame tolerance given
 * with it; 0 when none is stated (accuracy paper, the energy criterion,
 * absolute frame tolerances). */
static double stated_accuracy(const sbc_controller *c)
{
    double a = sbc_settings_preset_accuracy(c->s.accuracy);
    if (!(a > 0.0) || c->s.criterion != SBC_CRITERION_FORCE)
        return 0.0;
    a = fmax(a, c->s.tol_balance);
    if (c->s.bc != SBC_BC_D) {
        if (!(c->s.tol_relative > 0.0))
            return 0.0; /* absolute frame tolerances (tol_force, tol_moment) state no stress accuracy */
        a = fmax(a, c->s.tol_relative);
    }
    return a;
}

double sbc_ctl_largest_component(int dim, const double t[9])
{
    double m = 0.0;
    int i, j;
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j)
            m = fmax(m, fabs(t[SBC_IJ(i, j)]));
    return m;
}

/* A row is written only when it meets what it reports against: the force
 * balance of the relaxation (relax.h), the frame residual of (P) and (T)
 * relative to the frame's forces, and the Hill-Mandel residual within the
 * stated accuracy; each measured against the path's scale once the state's
 * own forces have collapsed below the path floor. Otherwise the run stops
 * with what happened. */
int sbc_ctl_certified(const sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const sbc_result *r = &c->result;
    const sbc_frame *f = c->frame;
    const double stated = stated_accuracy(c), sigma = sbc_ctl_largest_component(f->dim, r->sigma);
    char why[320] = "", moved[160] = "", collapse[160] = "";
    size_t used = 0;
    double worst = -1.0;
    int q, at = 0;
    if (c->s.criterion == SBC_CRITERION_FORCE && !sbc_relax_balanced(&c->relax))
        used += (size_t)snprintf(why + used, sizeof why - used, "unbalanced %.3g > balance %.3g; ", r->unbalanced,
                                 c->relax.tol);
    if ((c->s.bc == SBC_BC_P || c->s.bc == SBC_BC_T) && c->s.tol_relative > 0.0 &&
        r->frame_residual > c->s.tol_relative * (1.0 + 1e-9) && used < sizeof why)
        used += (size_t)snprintf(why + used, sizeof why - used, "frame_residual %.3g > tol_relative %.3g; ",
                                 r->frame_residual, c->s.tol_relative);
    if (stated > 0.0 && fabs(r->hill_mandel) > stated && used < sizeof why)
        used += (size_t)snprintf(why + used, sizeof why - used, "|hill_mandel| %.3g > the stated accuracy %.3g; ",
                                 fabs(r->hill_mandel), stated);
    if (used == 0)
        return 1;
    why[used >= 2 && used < sizeof why ? used - 2 : sizeof why - 1] = '\0';
    if (c->sigma_path > 0.0 && sigma < 1e-3 * c->sigma_path)
        snprintf(collapse, sizeof collapse, "; the stress collapsed from %.4g N/m (the path's largest |sigma|) to "
                 "%.3g N/m", c->sigma_path, sigma);
    for (q = 0; q < f->n; ++q) { /* the frame particle farthest from F X, in its radii */
        double FX[3], d = 0.0;
        int k;
        sbc_tensor_apply(f->dim, c->F_now, &f->X[3 * q], FX);
        for (k = 0; k < f->dim; ++k)
            d += (snap->x[3 * q + k] - FX[k]) * (snap->x[3 * q + k] - FX[k]);
        d = sqrt(d) / f->R[q];
        if (d > worst)
            worst = d, at = q;
    }
    if (f->n > 0)
        snprintf(moved, sizeof moved, "; frame particle %d (position %d of the frame) is %.3g radii from F X",
                 f->particle[at], at, worst);
    sbc_fail(err, SBC_ERR_DIVERGED,
             "servo_bc %s: increment %d, iteration %d: the state reached cannot be certified at accuracy %s (%s)%s%s; "
             "the row is not written: tighten balance or the frame tolerances, lower the time step, or take "
             "smaller increments",
             sbc_bc_name(c->s.bc), c->increment, c->iteration, c->s.accuracy, why, collapse, moved);
    return 0;
}
