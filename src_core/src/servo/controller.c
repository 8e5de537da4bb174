/* The servo_bc controller as a state machine: (D) of Table 1, (P) and (T)
 * of Tables 2 (with displacement prediction) and 3 (without), mixed of
 * Table 5 with the edge modes as data. Its other jobs are in the files
 * controller_private.h lists. */
#include "controller_private.h"
#include "sbc/homogenize.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double relax_tol(const sbc_settings *s)
{
    return s->criterion == SBC_CRITERION_FORCE ? s->tol_balance : s->tol_E;
}

/* Step 1.1 of Tables 1-3 (2.1 of Table 2): the frame commands that open an
 * increment. (D), (P): x_q = F X_q and Q_q = I; (T): x_q = F X_q with free
 * rotations. With prediction (n_f > 0, increments >= 1), the edge particles
 * of (P) and every particle of (T) start from
 *   x_q = F_i X_q + n_f (x_q^(i-1) - F_(i-1) X_q)          (Table 2, 2.1)
 * and the corners of (P) from F_i X_c. n_f = 0 gives Table 3 exactly. */
static void start_classic(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    const double *F = c->F_now, *G = c->F_prev;
    const int predict = c->increment > 0 && c->s.predict > 0.0 && c->s.bc != SBC_BC_D;
    int q, k;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[3 * q];
        double *x = &c->x_cmd[3 * q], GX[3];
        sbc_tensor_apply(f->dim, F, X, x);
        if (predict && (c->s.bc == SBC_BC_T || f->side[q] != SBC_SIDE_CORNER)) {
            sbc_tensor_apply(f->dim, G, X, GX);
            for (k = 0; k < f->dim; ++k)
                x[k] += c->s.predict * (c->x_prev[3 * q + k] - GX[k]);
        }
        if (c->s.bc == SBC_BC_T && !c->s.rotation_zero) {
            c->free_rot[q] = 1;
        } else {
            for (k = 0; k < c->rot; ++k)
                c->theta_cmd[c->rot * q + k] = 0.0;
            c->free_rot[q] = 0;
        }
    }
}

/* The frame travels from the commands saved in c->motion to those in
 * x_cmd, theta_cmd (motion.h); the relaxation starts once it is there, and
 * ends at the tolerance tol. */
static void begin_move(sbc_controller *c, int at_rest, double tol, const double *carry, const double *origin)
{
    sbc_motion_begin(&c->motion, c->frame, c->mass, c->kn, c->dt, c->s.speed, carry, origin, c->x_cmd, c->theta_cmd);
    sbc_relax_start(&c->relax, c->s.criterion, tol, c->s.window, at_rest);
    /* energy criterion: a frame that travelled has set the interior moving,
       so its kinetic energy has risen already (relax.h); the maximum is the
       first step on which it no longer rises */
    c->relax.rising = c->motion.steps > 1;
}

/* the tolerance of a relaxation that precedes a correction anyway: INEXACT
 * of the residual it precedes, INEXACT_LOOSE with FIRE when the frame
 * tolerance is a relative one of at least LOOSE_FRAME_TOL (fast, balanced) */
static double inexact_tol(const sbc_controller *c, double residual)
{
    const double tol = relax_tol(&c->s);
    const double factor =
        c->s.damping == SBC_DAMPING_FIRE && c->s.tol_relative >= LOOSE_FRAME_TOL ? INEXACT_LOOSE : INEXACT;
    return c->s.criterion == SBC_CRITERION_FORCE ? fmin(fmax(tol, factor * residual), 0.1) : tol;
}

/* the first relaxation of an increment of (P), (T) or mixed */
static double first_tol(const sbc_controller *c)
{
    const double tol = relax_tol(&c->s);
    return c->s.criterion == SBC_CRITERION_FORCE ? fmin(fmax(tol, INEXACT_FIRST), 0.1) : tol;
}

static void save_commands(sbc_controller *c)
{
    memcpy(c->motion.x_from, c->x_cmd, sizeof(double) * 3 * (size_t)c->frame->n);
    memcpy(c->motion.th_from, c->theta_cmd, sizeof(double) * (size_t)(c->rot * c->frame->n));
}

/* the interior's map over an increment's whole opening move (keyword remap
 * x): F_now F_prev^-1 about the origin of x_q = F X_q (mixed: the support's
 * centre); 0 when it is the identity */
int sbc_ctl_opening_map(const sbc_controller *c, double M[9], double origin[3])
{
    const int dim = c->frame->dim;
    double I[9];
    int k;
    if (!sbc_tensor_right_divide(dim, c->F_now, c->F_prev, M))
        return 0;
    sbc_tensor_identity(dim, I);
    for (k = 0; k < 9 && M[k] == I[k]; ++k)
        ;
    origin[0] = origin[1] = origin[2] = 0.0;
    if (c->s.bc == SBC_BC_MIXED) /* x_q = c + F (X_q - c) about the support's centre (Sect. 5.1) */
        sbc_ctl_mixed_centre(c, origin);
    return k < 9;
}

void sbc_ctl_start_increment(sbc_controller *c)
{
    save_commands(c);
    if (c->s.bc == SBC_BC_MIXED) {
        sbc_ctl_start_mixed(c);
        sbc_ctl_mixed_stress_targets(c);
    } else {
        start_classic(c);
    }
    c->servo = 0;
    c->iteration = 0;
    if (c->rule->start)
        c->rule->start(c);
    c->r_first = 0.0;
    c->win_min = c->prev_min = DBL_MAX;
    c->steps = 0;
    memset(&c->norms, 0, sizeof c->norms);
    {
        double M[9], origin[3];
        const int carried = c->s.remap && sbc_ctl_opening_map(c, M, origin);
        begin_move(c, c->increment == 0, c->s.bc == SBC_BC_D ? relax_tol(&c->s) : first_tol(c), carried ? M : NULL,
                   origin);
    }
    c->remap_due = 1;
}

/* The absolute floors of the force criterion (relax.h): the force of an
 * overlap of 1e-10 of the sample's size plus a radius, kn 1e-10 (L + R), and
 * the energy of such forces on every particle (the interior estimated from
 * the frame, ~(Q/4)^2). A strain of 1e-10 lies below what any preset resolves
 * (tight: 1e-6 of a stress at strains >= 1e-4); a packing that comes apart in
 * tension under (T) keeps grazing contacts of ~1e-10 R that never balance to
 * a ratio (the 5 x 5 lattice at F11 = 1.05, docs/stability.md). */
static void set_floors(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    double size = 0.0, R = 0.0, force, n = 1.0 + (double)f->n * (double)f->n / 16.0;
    int q;
    for (q = 0; q < f->n; ++q) {
        int k;
        for (k = 0; k < f->dim; ++k)
            size = fmax(size, fabs(f->X[3 * q + k]));
        R += f->R[q] / f->n;
    }
    force = 1e-10 * c->kn * (size + R);
    sbc_relax_floor(&c->relax, force, c->kn > 0.0 ? n * force * force / (2.0 * c->kn) : 0.0);
}

sbc_controller *sbc_controller_create(const sbc_frame *frame, const sbc_settings *settings, const double *mass,
                                      double dt, double kn, sbc_error *err)
{
    sbc_controller *c;
    size_t q = (size_t)frame->n, r = (size_t)SBC_ROTATIONS(frame->dim);
    if (!(dt > 0.0) || !isfinite(dt)) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s is not positive", dt);
        return NULL;
    }
    if (!(kn >= 0.0) || !isfinite(kn)) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: contact stiffness kn = %g N/m is not >= 0", kn);
        return NULL;
    }
    if (frame->dim != settings->dim) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: a frame of dimension %d under words of dimension %d "
                 "(sbc_settings_check_dimension holds the words to the packing)", frame->dim, settings->dim);
        return NULL;
    }
    c = calloc(1, sizeof *c);
    if (!c) {
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return NULL;
    }
    c->s = *settings;
    if (!(c->rule = sbc_update_rule_of(settings->update))) {
        free(c);
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: update rule %d is not one of the table (update_rules.c)",
                 (int)settings->update);
        return NULL;
    }
    c->result.dim = frame->dim;
    c->rot = SBC_ROTATIONS(frame->dim);
    c->dt = dt;
    c->kn = kn;
    c->total = sbc_settings_total_increments(settings);
    if (sbc_frame_copy(&c->ref, frame, err) != SBC_OK) {
        free(c);
        return NULL;
    }
    c->frame = &c->ref;
    c->mode = calloc(3 * q, 1);
    c->mass = malloc(sizeof(double) * q);
    c->x_cmd = calloc(3 * q, sizeof(double));
    c->theta_cmd = calloc(r * q, sizeof(double));
    c->free_rot = calloc(q, 1);
    c->a = calloc(3 * q, sizeof(double));
    c->m = calloc(r * q, sizeof(double));
    c->x_prev = calloc(3 * q, sizeof(double));
    c->du = calloc(3 * q, sizeof(double));
    c->a_hat = calloc(3 * q, sizeof(double));
    c->dtheta = calloc(r * q, sizeof(double));
    c->secant.d_prev = calloc((size_t)SBC_CTL_STEP_PARTS(frame->dim) * q, sizeof(double));
    c->secant.lambda = 1.0;
    if (!sbc_motion_alloc(&c->motion, frame->n, c->rot) || !c->secant.d_prev || !c->mass || !c->x_cmd || !c->theta_cmd ||
        !c->free_rot || !c->a || !c->m || !c->x_prev || !c->du || !c->a_hat || !c->dtheta || !c->mode) {
        sbc_controller_free(c);
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory for a frame of %d particles", frame->n);
        return NULL;
    }
    memcpy(c->mass, mass, sizeof(double) * q);
    memcpy(c->x_cmd, c->frame->X, sizeof(double) * 3 * q); /* where the frame stands before increment 0 */
    set_floors(c);
    if (c->s.bc == SBC_BC_MIXED)
        sbc_mixed_modes(frame, &c->s, c->mode);
    if (c->s.bc == SBC_BC_P || c->s.bc == SBC_BC_MIXED) {
        int k, member[8];
        for (k = 0; k < frame->n; ++k) {
            if (sbc_frame_family(frame, k, member) < 0 && (c->s.bc == SBC_BC_P || c->mode[3 * k] == SBC_MODE_P)) {
                if (frame->dim == 2)
                    sbc_fail(err, SBC_ERR_FRAME,
                             "servo_bc %s: frame particle %d (packing index %d) has no periodic partner on the "
                             "opposite edge (opposite edges must hold equally many particles)",
                             sbc_bc_name(c->s.bc), k, frame->particle[k]);
                else
                    sbc_fail(err, SBC_ERR_FRAME,
                             "servo_bc %s: frame particle %d (packing index %d) has no periodic image on an opposite "
                             "face (opposite faces must hold their centres at the same places)",
                             sbc_bc_name(c->s.bc), k, frame->particle[k]);
                sbc_controller_free(c);
                return NULL;
            }
        }
    }
    if (sbc_ctl_increments_too_coarse(c, err)) {
        sbc_controller_free(c);
        return NULL;
    }
    sbc_settings_target_F(&c->s, 0, c->F_now);
    memcpy(c->F_prev, c->F_now, sizeof c->F_prev);
    sbc_ctl_start_increment(c);
    return c;
}

void sbc_controller_free(sbc_controller *c)
{
    if (!c)
        return;
    sbc_frame_free(&c->ref);
    free(c->mode);
    free(c->mass);
    free(c->x_cmd);
    free(c->theta_cmd);
    free(c->free_rot);
    free(c->a);
    free(c->m);
    free(c->x_prev);
    free(c->du);
    free(c->a_hat);
    free(c->dtheta);
    free(c->secant.d_prev);
    sbc_motion_free(&c->motion);
    free(c);
}

/* The frame part of a snapshot, read once the relaxation is over. */
static int frame_finite(const sbc_frame *f, const sbc_snapshot *s, const char **what)
{
    int k;
    for (k = 0; k < 3 * f->n; ++k) {
        if (k % 3 >= f->dim)
            continue;
        if (!isfinite(s->x[k])) { *what = "frame position"; return 0; }
        if (!isfinite(s->force[k])) { *what = "frame reaction force"; return 0; }
    }
    for (k = 0; k < SBC_ROTATIONS(f->dim) * f->n; ++k)
        if (!isfinite(s->theta[k]) || !isfinite(s->torque[k])) { *what = "frame rotation or moment"; return 0; }
    return 1;
}

static sbc_relax_sample sample_of(const sbc_snapshot *s)
{
    sbc_relax_sample r;
    r.ek = s->kinetic_energy;
    r.ep = s->potential_energy;
    r.net_max = s->unbalanced_max;
    r.contact_sum = s->contact_force_sum;
    r.contact_count = s->contact_count;
    return r;
}

static int contacts_needed(const sbc_controller *c, const sbc_relax_sample *s)
{
    return sbc_relax_needs_contacts(&c->relax, s) || c->relax.steps + 1 >= c->s.max_relax_steps;
}

unsigned sbc_controller_needs(const sbc_controller *c, const sbc_snapshot *snap)
{
    sbc_relax next = c->relax;
    sbc_relax_sample s = sample_of(snap);
    unsigned need = 0;
    if (!isfinite(s.ek) || !isfinite(s.net_max) || c->increment > c->total)
        return SBC_NEED_CONTACTS | SBC_NEED_FRAME; /* step reports it */
    if (c->motion.done < c->motion.steps)
        return 0; /* the frame is travelling: nothing is read */
    if (contacts_needed(c, &s)) {
        need |= SBC_NEED_CONTACTS;
        if (!(s.ep >= 0.0))
            return need;
    }
    if (sbc_relax_update(&next, &s))
        need |= SBC_NEED_FRAME;
    return need;
}

/* Homogenized measures of a relaxed state (eqs. 15, 23, 30, 31, 39, 41). */
static sbc_status measure(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const sbc_frame *f = c->frame;
    sbc_result *r = &c->result;
    sbc_error why;
    double scale;
    r->dim = f->dim;
    r->increment = c->increment;
    sbc_homogenize_F(f, snap->x, r->F);
    sbc_homogenize_P(f, c->a, r->P);
    if (sbc_homogenize_cauchy(f->dim, r->P, r->F, r->sigma, &why) != SBC_OK)
        return sbc_fail(err, SBC_ERR_GEOMETRY, "servo_bc %s: increment %d: %s", sbc_bc_name(c->s.bc), c->increment,
                        why.message);
    /* a stress collapsed below the path floor is judged on the path's scale
       (relax.h), and none below the round-off floor's stress, kn 1e-10 (the
       force floor of set_floors over the sample's size): a stress-free state
       has a Hill-Mandel residual of round-off size, not of its own scale */
    scale = sbc_homogenize_work_scale(f->dim, r->P, r->F);
    if (scale < SBC_RELAX_PATH_FLOOR * c->work_path)
        scale = c->work_path;
    scale = fmax(scale, 1e-10 * c->kn);
    r->hill_mandel = sbc_homogenize_hill_mandel(f, c->a, snap->x, r->F, r->P);
    if (scale > 0.0)
        r->hill_mandel /= scale;
    r->overlap_mean = snap->contact_count > 0 ? snap->overlap_sum / (double)snap->contact_count : 0.0;
    r->rotation_mean = snap->particle_count > 0 ? snap->rotation_sum / (double)snap->particle_count : 0.0;
    r->iterations = c->iteration;
    r->relax_steps = c->steps;
    r->r_force = c->norms.r_force;
    r->r_moment = c->norms.r_moment;
    r->r_deformation = c->norms.r_deformation;
    r->unbalanced = c->relax.unbalanced;
    r->frame_residual = c->s.bc == SBC_BC_D ? 0.0 : c->norms.relative_force;
    return SBC_OK;
}

/* Step 1.6 of Tables 2-3 with separate force, moment and deformation norms:
 * the largest ratio of a residual norm to its tolerance; converged at <= 1. */
static double residual_ratio(const sbc_controller *c, const sbc_servo_norms *n)
{
    double r = n->r_force / sbc_ctl_tol_force(c);
    if (c->s.bc == SBC_BC_MIXED) /* r_deformation: the frame's lag behind the measured F, in radii */
        return fmax(fmax(r, n->r_moment / sbc_ctl_tol_moment(c)),
                    fmax(n->r_deformation, c->P_miss) / sbc_ctl_mixed_lag_tol(c));
    if (c->s.bc == SBC_BC_P)
        return fmax(r, n->r_moment / sbc_ctl_tol_moment(c));
    return fmax(r, n->r_deformation / c->s.tol_deformation);
}

/* Table 1, 1.3 / Tables 2-3, 1.6.A: the relaxed, converged configuration is
 * the result of increment i; the next increment starts. */
static sbc_event accept(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    if (measure(c, snap, err) != SBC_OK)
        return SBC_EVENT_FAILED;
    c->uncertified = !sbc_ctl_certified(c, snap, err);
    if (c->uncertified && !c->accept_uncertified)
        return SBC_EVENT_FAILED;
    if (c->uncertified) /* a material point's: the state stands, with the reason */
        snprintf(c->why, sizeof c->why, "%s", err->message);
    sbc_relax_path(&c->relax, c->relax.fc_known);
    c->work_path = fmax(c->work_path, sbc_homogenize_work_scale(c->frame->dim, c->result.P, c->result.F));
    c->sigma_path = fmax(c->sigma_path, sbc_ctl_largest_component(c->frame->dim, c->result.sigma));
    memcpy(c->x_prev, snap->x, sizeof(double) * 3 * (size_t)c->frame->n);
    memcpy(c->F_prev, c->F_now, sizeof c->F_prev);
    if (c->s.bc == SBC_BC_MIXED && c->s.stress_increments > 0 && c->increment == c->s.stress_increments) {
        int i, j;
        sbc_ctl_new_reference(c, snap->x);
        for (i = 0; i < c->frame->dim; ++i) /* F of the state after stage 1 on itself: I */
            if (sbc_ctl_row_measured(c, i))
                for (j = 0; j < c->frame->dim; ++j)
                    c->F_prev[SBC_IJ(i, j)] = i == j ? 1.0 : 0.0;
    }
    if (c->increment == c->total) {
        c->increment++;
        return SBC_EVENT_FINISHED;
    }
    c->increment++;
    sbc_settings_target_F(&c->s, c->increment, c->F_now);
    sbc_ctl_start_increment(c);
    return SBC_EVENT_INCREMENT;
}

/* Whether the correction du, dtheta moves some frame particle beyond the
 * round-off of its position: |du| + R |dtheta| > 16 eps (|x| + R). A
 * balanced packing yields corrections of round-off forces, some 1e-21 m on
 * the 100-particle lattice, which leave the frame where it was (relax.h). */
static int correction_moves_frame(const sbc_controller *c)
{
    int q, k;
    for (q = 0; q < c->frame->n; ++q) {
        const double R = c->frame->R[q];
        double move = 0.0, size = 0.0;
        for (k = 0; k < c->frame->dim; ++k) {
            move += fabs(c->du[3 * q + k]);
            size += fabs(c->x_cmd[3 * q + k]);
        }
        for (k = 0; k < c->rot; ++k)
            move += R * fabs(c->dtheta[c->rot * q + k]);
        if (move > 16.0 * DBL_EPSILON * (size + R))
            return 1;
    }
    return 0;
}

/* The stages of sbc_controller_step. A stage that ends the step returns its
 * event; STAGE_ON lets the step go on to the next stage. */
#define STAGE_ON ((sbc_event) - 1)

/* The path still open, the energies finite. */
static sbc_event stage_open(const sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    if (c->increment > c->total) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: the loading path is already finished", sbc_bc_name(c->s.bc));
        return SBC_EVENT_FAILED;
    }
    if (!isfinite(snap->kinetic_energy) || isnan(snap->potential_energy) || isinf(snap->potential_energy)) {
        sbc_fail(err, SBC_ERR_NUMERIC,
                 "servo_bc %s: increment %d, relaxation step %ld: non-finite %s (the packing blew up; "
                 "lower the time step)",
                 sbc_bc_name(c->s.bc), c->increment, c->relax.steps + 1,
                 isfinite(snap->kinetic_energy) ? "potential energy" : "kinetic energy");
        return SBC_EVENT_FAILED;
    }
    return STAGE_ON;
}

/* The relaxation (relax.h): the host's measures checked, then the criterion;
 * over, or RELAXING, or FAILED after max_relax_steps. */
static sbc_event stage_relax(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const sbc_relax_sample sample = sample_of(snap);
    if (!(snap->unbalanced_max >= 0.0) || !isfinite(snap->unbalanced_max) || snap->contact_count < 0 ||
        !(snap->contact_force_sum >= 0.0 || snap->potential_energy < 0.0)) {
        sbc_fail(err, SBC_ERR_NUMERIC,
                 "servo_bc %s: increment %d, relaxation step %ld: the host passed invalid force measures (largest "
                 "net force %g N, contact forces %g N over %ld contacts)",
                 sbc_bc_name(c->s.bc), c->increment, c->relax.steps + 1, snap->unbalanced_max,
                 snap->contact_force_sum, snap->contact_count);
        return SBC_EVENT_FAILED;
    }
    if (snap->potential_energy < 0.0 && contacts_needed(c, &sample)) {
        sbc_fail(err, SBC_ERR_INPUT,
                 "servo_bc %s: increment %d, relaxation step %ld: the host left Ep unmeasured although "
                 "sbc_controller_needs asked for it",
                 sbc_bc_name(c->s.bc), c->increment, c->relax.steps + 1);
        return SBC_EVENT_FAILED;
    }
    if (sbc_relax_update(&c->relax, &sample))
        return STAGE_ON;
    if (c->relax.steps < c->s.max_relax_steps)
        return SBC_EVENT_RELAXING;
    if (c->s.criterion == SBC_CRITERION_FORCE)
        sbc_fail(err, SBC_ERR_DIVERGED,
                 "servo_bc %s: increment %d, iteration %d: relaxation did not reach force balance %g for %d "
                 "steps within %ld steps (unbalanced force ratio %.3g, Ek = %g J, Ep = %g J); check damping "
                 "and time step, loosen 'balance' or raise max_relax_steps",
                 sbc_bc_name(c->s.bc), c->increment, c->iteration, c->relax.tol, c->s.window,
                 c->relax.steps, c->relax.unbalanced, snap->kinetic_energy, snap->potential_energy);
    else
        sbc_fail(err, SBC_ERR_DIVERGED,
                 "servo_bc %s: increment %d, iteration %d: relaxation did not reach Ek/Ep <= %g for %d steps "
                 "within %ld steps (Ek = %g J, Ep = %g J); check damping and time step, or raise "
                 "max_relax_steps",
                 sbc_bc_name(c->s.bc), c->increment, c->iteration, c->s.tol_E, c->s.window, c->relax.steps,
                 snap->kinetic_energy, snap->potential_energy);
    return SBC_EVENT_FAILED;
}

/* The relaxed frame: positions and forces there and finite; the boundary
 * forces and moments of eq. 5 taken from it. */
static sbc_event stage_read_frame(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const char *what = NULL;
    int k;
    if (!snap->x || !snap->force || !snap->theta || !snap->torque) {
        sbc_fail(err, SBC_ERR_INPUT,
                 "servo_bc %s: increment %d, relaxation step %ld: the relaxation is over but the host passed no "
                 "frame snapshot (sbc_controller_needs asked for it)",
                 sbc_bc_name(c->s.bc), c->increment, c->relax.steps);
        return SBC_EVENT_FAILED;
    }
    if (!frame_finite(c->frame, snap, &what)) {
        sbc_fail(err, SBC_ERR_NUMERIC,
                 "servo_bc %s: increment %d, relaxation step %ld: non-finite %s (the packing blew up; "
                 "lower the time step)",
                 sbc_bc_name(c->s.bc), c->increment, c->relax.steps, what);
        return SBC_EVENT_FAILED;
    }
    for (k = 0; k < 3 * c->frame->n; ++k) /* eq. 5: sum of contact forces = -a_q */
        c->a[k] = k % 3 < c->frame->dim ? -snap->force[k] : 0.0;
    for (k = 0; k < c->rot * c->frame->n; ++k)
        c->m[k] = -snap->torque[k];
    c->steps += c->relax.steps;
    return STAGE_ON;
}

/* Steps 1.5 of Tables 2-3 and 5: the residuals and the corrections (servo.c)
 * into c->norms, c->du, c->dtheta; mixed: F and P measured (F_measured,
 * P_hat). */
static sbc_event stage_residuals(sbc_controller *c, const sbc_snapshot *snap, double F_measured[9], double P_hat[9],
                                 sbc_error *err)
{
    const sbc_servo_floors floors = {sbc_relax_scale_floor(&c->relax), SBC_RELAX_NET_FLOOR * c->relax.floor_force};
    sbc_servo_norms nrm;
    if (c->s.bc == SBC_BC_MIXED) {
        double target[9], P_measured[9];
        int k;
        for (k = 0; k < 9; ++k)
            target[k] = c->P_star[k] + c->P_shift[k];
        sbc_servo_mixed(c->frame, c->mode, &c->s, c->mass, c->dt, c->kn, &floors, target, c->P_fixed, c->a, c->m,
                        c->du, c->dtheta, &nrm);
        nrm.r_deformation = sbc_ctl_mixed_lag(c, snap->x, F_measured);
        c->P_miss = sbc_ctl_mixed_stress_miss(c, P_measured, P_hat);
    } else {
        sbc_servo_residuals(c->s.bc, c->frame, &c->s, c->mass, c->dt, c->kn, &floors, c->F_now, c->a, c->m, snap->x,
                            c->du, c->dtheta, &nrm);
    }
    c->norms = nrm;
    if (!isfinite(nrm.r_force) || !isfinite(nrm.r_moment) || !isfinite(nrm.r_deformation)) {
        sbc_fail(err, SBC_ERR_NUMERIC, "servo_bc %s: increment %d, iteration %d: non-finite residual",
                 sbc_bc_name(c->s.bc), c->increment, c->iteration);
        return SBC_EVENT_FAILED;
    }
    return STAGE_ON;
}

/* Step 1.6: after the initial relaxation (1.2) correct at once (1.3); after
 * each later relaxation (1.4) accept, relax in place once more, stop with
 * the reason, or go on to the correction. */
static sbc_event stage_decide(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const sbc_servo_norms *nrm = &c->norms;
    const double ratio = residual_ratio(c, nrm);
    const int first = !c->servo;
    if (!first && ratio < c->win_min)
        c->win_min = ratio;
    if (first) {
        c->r_first = nrm->r_force;
    } else if (ratio <= 1.0 && c->relax.tol > relax_tol(&c->s)) {
        /* converged on an inexact relaxation: relax in place to the
           tolerance, then check again */
        sbc_relax_start(&c->relax, c->s.criterion, relax_tol(&c->s), c->s.window, 1);
        return SBC_EVENT_RELAXING;
    } else if (ratio <= 1.0) {
        return accept(c, snap, err);
    } else if (!c->rule->bounded && nrm->r_force > 1e3 * fmax(c->r_first, 1e3 * sbc_ctl_tol_force(c))) {
        /* growth over the first residual of the increment (that one can be
         * round-off small: an already periodic state, hence the floor) under
         * fixed gains, which can run away; the secant update caps its
         * corrections, and a residual that grows under it is the packing
         * leaving an unstable equilibrium, which the servo follows to a
         * stable one (docs/servo_bc.md, "Divergence") */
        sbc_ctl_diverged(c, nrm, "the force residual grew more than 1000-fold", 0, err);
        return SBC_EVENT_FAILED;
    } else if (c->iteration >= c->s.max_iterations) {
        sbc_ctl_diverged(c, nrm, "max_iterations reached", 1, err);
        return SBC_EVENT_FAILED;
    } else if (c->iteration % STAGNATION_WINDOW == 0) {
        if (c->win_min > 0.99 * c->prev_min && nrm->relative_force < STAGNATION_ROUNDOFF) {
            sbc_ctl_stagnated(c, nrm, err);
            return SBC_EVENT_FAILED;
        }
        c->prev_min = c->win_min;
        c->win_min = DBL_MAX;
    }
    return STAGE_ON;
}

/* Steps 1.3 / 1.6.B: the correction scaled by the update rule, added to the
 * commands; the frame travels there and the next relaxation begins. */
static sbc_event stage_correct(sbc_controller *c, const double F_measured[9], const double P_hat[9], sbc_error *err)
{
    sbc_servo_norms nrm = c->norms; /* the scaled step is this correction's; c->norms keeps the residuals' */
    int moved, k;
    if (c->rule->scale && c->rule->scale(c, &nrm, err) != SBC_OK)
        return SBC_EVENT_FAILED;
    if (nrm.max_step > 0.5) { /* a rule that does not cap its steps (fixed) */
        sbc_ctl_diverged(c, &nrm, "a correction moved a frame particle by more than half its radius", 0, err);
        return SBC_EVENT_FAILED;
    }
    moved = correction_moves_frame(c);
    save_commands(c);
    for (k = 0; k < 3 * c->frame->n; ++k)
        c->x_cmd[k] += c->du[k];
    for (k = 0; k < c->rot * c->frame->n; ++k)
        c->theta_cmd[k] += c->dtheta[k];
    c->servo = 1;
    c->iteration++;
    if (c->s.bc == SBC_BC_T && c->rule->keeps_eq15)
        sbc_ctl_restore_eq15(c);
    if (c->s.bc == SBC_BC_MIXED) { /* the frame follows the measured rows of F */
        for (k = 0; k < c->frame->dim; ++k)
            if (sbc_ctl_row_measured(c, k))
                c->F_now[SBC_IJ(k, k)] = F_measured[SBC_IJ(k, k)];
        for (k = 0; k < c->frame->dim; ++k) /* the measured P_kk towards P_star (the normal stress of the traction row) */
            if (c->P_fixed[SBC_IJ(k, k)] && sbc_ctl_row_measured(c, k))
                c->P_shift[SBC_IJ(k, k)] += c->P_star[SBC_IJ(k, k)] - P_hat[SBC_IJ(k, k)];
        sbc_ctl_mixed_follow_F(c);
    }
    begin_move(c, !moved, inexact_tol(c, nrm.relative_force), NULL, NULL);
    return SBC_EVENT_CORRECTED;
}

sbc_event sbc_controller_step(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    double F_measured[9], P_hat[9];
    sbc_event ev;
    c->remap_due = 0;
    if ((ev = stage_open(c, snap, err)) != STAGE_ON)
        return ev;
    if (sbc_motion_advance(&c->motion, c->frame->n, c->x_cmd, c->theta_cmd)) {
        c->remap_due = !c->servo;
        c->steps++;
        return SBC_EVENT_CORRECTED; /* the frame travels on (motion.h) */
    }
    if ((ev = stage_relax(c, snap, err)) != STAGE_ON || (ev = stage_read_frame(c, snap, err)) != STAGE_ON)
        return ev;
    if (c->s.bc == SBC_BC_D)
        return accept(c, snap, err);
    if ((ev = stage_residuals(c, snap, F_measured, P_hat, err)) != STAGE_ON ||
        (ev = stage_decide(c, snap, err)) != STAGE_ON)
        return ev;
    return stage_correct(c, F_measured, P_hat, err);
}
