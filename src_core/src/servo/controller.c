/* The servo_bc controller as a state machine: (D) of Table 1, (P) and (T)
 * of Tables 2 (with displacement prediction) and 3 (without), mixed of
 * Table 5 with the edge modes as data. */
#include "sbc/controller.h"

#include "sbc/homogenize.h"
#include "sbc/relax.h"
#include "motion.h"
#include "sbc/saved.h"
#include "servo.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sbc_controller {
    sbc_frame ref;       /* the controller's copy of the frame: the reference of
                            mixed stage 2 is the state after stage 1 (Sect. 5.1) */
    const sbc_frame *frame; /* = &ref */
    unsigned char *mode; /* [2Q] mixed: sbc_mode of each component of each frame position */
    double P_star[4];    /* mixed: prescribed stress of this increment, N/m */
    unsigned char P_fixed[4]; /* mixed: 1 where P_star holds (prescribed, or 0 in the stress stage) */
    double P_shift[4];   /* mixed: the top's traction targets P_star + P_shift, so that the measured
                            P of eq. 23 (which the support's reactions enter) meets P_star, N/m */
    double P_miss;       /* mixed: |P measured - P_star| over |P_star| in the traction rows */
    double *a_hat;       /* [2Q] mixed: the boundary forces with the top's traction components at their targets */
    sbc_settings s;
    double dt;           /* s */
    double kn;           /* the host's normal contact stiffness, N/m (0: unknown) */
    sbc_motion motion;   /* the frame's travel to the commands (motion.h) */
    double *mass;        /* [Q] kg */
    int increment;       /* 0 .. i_tot */
    sbc_relax relax;
    double *x_cmd;       /* [2Q] m */
    double *theta_cmd;   /* [Q] rad */
    unsigned char *free_rot;
    double *a;           /* [2Q] boundary forces a_q = -sum of contact forces (eq. 5), N */
    double *m;           /* [Q] boundary moments m_q = -sum of contact moments (eq. 5), N m */
    double *x_prev;      /* [2Q] converged positions of the previous increment (prediction), m */
    double *du, *dtheta; /* [2Q], [Q] servo corrections, m, rad */
    double lambda;       /* update secant: factor on the fixed-gain corrections */
    int have_prev;       /* update secant: d_prev holds this increment's last correction */
    double *d_prev;      /* [3Q] update secant: last fixed-gain correction (du, R dtheta), m */
    double F_prev[4];    /* F imposed at the previous increment */
    double F_now[4];     /* F imposed at this increment */
    int total;           /* increments of the whole path, sbc_settings_total_increments */
    int servo;           /* 0: initial relaxation of the increment, 1: servo iterations */
    int iteration;       /* servo iterations in this increment */
    double r_first;      /* first force residual of the increment (growth check) */
    double win_min;      /* smallest residual/tolerance ratio in this window of iterations */
    double prev_min;     /* ... in the window before (stagnation check) */
    long steps;          /* host steps spent on this increment */
    sbc_servo_norms norms; /* last residual norms of this increment (zero for D) */
    sbc_result result;
    double work_path;    /* the largest work scale |P||F| of the path's converged increments, N/m */
    double sigma_path;   /* the largest |sigma| (largest component) of those increments, N/m */
};

/* Mixed: row i of F (F_i1, F_i2) is a result of the (T) condition, eq. 45,
 * when some edge controls component i by traction (the layer: row 2). */
static int row_measured(const sbc_controller *c, int i)
{
    int e;
    for (e = 0; e < 4; ++e)
        if (c->s.edge_mode[e][i] == SBC_MODE_T)
            return 1;
    return 0;
}

/* Mixed: the point the D components deform about, x = c + F (X - c): the
 * centroid of the bottom edge's reference centres (corners included), so
 * that the support keeps its place on average while it follows F, and a
 * translated packing gives the same results. */
static void support_centre(const sbc_controller *c, double centre[2])
{
    const sbc_frame *f = c->frame;
    int q, n = 0;
    centre[0] = centre[1] = 0.0;
    for (q = 0; q < f->n; ++q)
        if (f->side[q] == SBC_SIDE_BOTTOM || q == f->corner[SBC_CORNER_BL] || q == f->corner[SBC_CORNER_BR]) {
            centre[0] += f->X[2 * q];
            centre[1] += f->X[2 * q + 1];
            ++n;
        }
    centre[0] /= n;
    centre[1] /= n;
}

/* Mixed, Sect. 5.1: the D components follow F, x_q = c + F (X_q - c) (eqs. 17,
 * 43_1), and the periodic pairs keep x_r - x_l = F (X_r - X_l) (eq. 19) about
 * their servo-controlled midpoint, with F the imposed components and, in the
 * rows of eq. 45, the measured ones (F_now holds both). With the measured F
 * every boundary term of eq. 46 vanishes: w_q = 0 on D components, periodic w
 * on the pairs (the proof of Sect. 5.1). */
static void mixed_follow_F(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    const double *F = c->F_now;
    double centre[2];
    int q, k;
    support_centre(c, centre);
    for (q = 0; q < f->n; ++q) {
        const double d0 = f->X[2 * q] - centre[0], d1 = f->X[2 * q + 1] - centre[1];
        for (k = 0; k < 2; ++k)
            if (c->mode[2 * q + k] == SBC_MODE_D)
                c->x_cmd[2 * q + k] = centre[k] + F[2 * k] * d0 + F[2 * k + 1] * d1;
        if (c->mode[2 * q] == SBC_MODE_P && (f->side[q] == SBC_SIDE_BOTTOM || f->side[q] == SBC_SIDE_RIGHT)) {
            const int p = f->partner[q];
            const double D0 = f->X[2 * q] - f->X[2 * p], D1 = f->X[2 * q + 1] - f->X[2 * p + 1];
            for (k = 0; k < 2; ++k) {
                const double mid = 0.5 * (c->x_cmd[2 * q + k] + c->x_cmd[2 * p + k]);
                const double half = 0.5 * (F[2 * k] * D0 + F[2 * k + 1] * D1);
                c->x_cmd[2 * q + k] = mid + half;
                c->x_cmd[2 * p + k] = mid - half;
            }
        }
    }
}

/* Table 5, 1.1 / 2.1: D components follow F (mixed_follow_F); P pairs and
 * T components carry on from the previous converged state, shifted by the
 * change of F; rotations are free on edges with a T component, held at zero
 * on D edges, servo-controlled on P. The measured rows of F carry on from the
 * previous converged increment. */
static void start_mixed(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    double *F = c->F_now;
    const double *G = c->F_prev;
    double centre[2];
    int q, k;
    for (k = 0; k < 2; ++k)
        if (row_measured(c, k)) {
            F[2 * k] = G[2 * k];
            F[2 * k + 1] = G[2 * k + 1];
        }
    support_centre(c, centre);
    for (q = 0; q < f->n; ++q) {
        const double d0 = f->X[2 * q] - centre[0], d1 = f->X[2 * q + 1] - centre[1];
        int any_t = 0;
        for (k = 0; k < 2; ++k) {
            double shift = (F[2 * k] - G[2 * k]) * d0 + (F[2 * k + 1] - G[2 * k + 1]) * d1;
            if (c->mode[2 * q + k] != SBC_MODE_D && c->increment > 0)
                c->x_cmd[2 * q + k] = c->x_prev[2 * q + k] + shift;
            any_t |= c->mode[2 * q + k] == SBC_MODE_T;
        }
        c->free_rot[q] = (unsigned char)any_t;
        if (c->mode[2 * q] == SBC_MODE_D && c->mode[2 * q + 1] == SBC_MODE_D)
            c->theta_cmd[q] = 0.0;
    }
    mixed_follow_F(c);
}

/* The prescribed stresses of this increment: `stress` components ramp to
 * their values over the stress stage and hold after it; the others are
 * measured (eq. 23). Sect. 5.2 prescribes P21 = 0 during the stress stage,
 * "to avoid the initial development of a shear stress"; the proof of eqs.
 * 46-47 needs the measured P21 in the top's traction, and prescribing 0 does
 * not keep the measured P21 at 0 (the support's reactions make it): on a
 * 37-disc layer at accuracy tight, P21 = -3.5e4 N/m either way (P22* =
 * -1.05e6), Hill-Mandel 1.6e-5 with P21 = 0 prescribed and 1.2e-10 with P21
 * measured; 120 discs: 1.0e-7 against 5e-11 (docs/servo_bc.md). */
static void mixed_stress_targets(sbc_controller *c)
{
    double t = c->s.stress_increments > 0 ? fmin(1.0, (double)c->increment / c->s.stress_increments) : 1.0;
    int k;
    for (k = 0; k < 4; ++k) {
        c->P_star[k] = 0.0;
        c->P_fixed[k] = 0;
    }
    for (k = 0; k < c->s.nstress; ++k) {
        int ij = 2 * c->s.stress[k].i + c->s.stress[k].j;
        c->P_star[ij] = t * c->s.stress[k].value;
        c->P_fixed[ij] = 1;
    }
}

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
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[2 * q];
        double x0 = F[0] * X[0] + F[1] * X[1], x1 = F[2] * X[0] + F[3] * X[1];
        if (predict && (c->s.bc == SBC_BC_T || f->side[q] != SBC_SIDE_CORNER)) {
            x0 += c->s.predict * (c->x_prev[2 * q] - (G[0] * X[0] + G[1] * X[1]));
            x1 += c->s.predict * (c->x_prev[2 * q + 1] - (G[2] * X[0] + G[3] * X[1]));
        }
        c->x_cmd[2 * q] = x0;
        c->x_cmd[2 * q + 1] = x1;
        if (c->s.bc == SBC_BC_T) {
            c->free_rot[q] = 1;
        } else {
            c->theta_cmd[q] = 0.0;
            c->free_rot[q] = 0;
        }
    }
}

/* Inexact relaxations between servo corrections (force criterion only): a
 * relaxation after a correction ends at INEXACT times the frame residual it
 * corrected (relative, servo.h), not below the tolerance; the first one of
 * an increment of (P), (T) or mixed, which is always corrected, at
 * INEXACT_FIRST. A converged frame residual after an inexact relaxation is
 * not accepted: the packing is first relaxed to the tolerance in place and
 * checked again (sbc_controller_step). The frame forces of an inexact
 * relaxation are off by about U times the contact forces, 3 % of the
 * residual being corrected, which leaves the correction's direction intact
 * (the inexact Newton method). Measured on the 232-disc irregular packing,
 * F12 = 0.005 in one increment at 0.1 of the critical step, `accuracy
 * balanced`: 0.1 stalled near the tolerance (3000 iterations), 0.03 took
 * 446 thousand steps, 0.01 566 thousand. */
#define INEXACT 0.03
#define INEXACT_FIRST 1e-3
/* With FIRE, a frame tolerance of 1e-5 or looser (relative) converges with
 * relaxations at 30 % of the residual: DEM steps at `balanced` for 0.03 /
 * 0.1 / 0.3: regular (P) 414 / 323 / 259 thousand, irregular (P) 2.54 /
 * 2.01 / 1.67 million, regular (T) 1.13 / 0.78 / 0.59 million, the mixed
 * layer 161 / 120 / 96 thousand, each path as close to `tight`. At `tight`
 * (1e-7) 0.3 and 0.1 stalled on the irregular packing (frame residuals 8e-7
 * and 1.3e-7 after 10 000 iterations), and so did 0.3 switched to 0.03
 * within 100 times the tolerance. With eq. 10, 0.1 had stalled on the
 * irregular packing at `balanced` (F12 = 0.005 in one increment): eq. 10
 * keeps 0.03. */
#define INEXACT_LOOSE 0.3
#define LOOSE_FRAME_TOL 1e-5

/* The frame travels from the commands saved in c->motion to those in
 * x_cmd, theta_cmd (motion.h); the relaxation starts once it is there, and
 * ends at the tolerance tol. */
static void begin_move(sbc_controller *c, int at_rest, double tol)
{
    sbc_motion_begin(&c->motion, c->frame, c->mass, c->kn, c->dt, c->s.speed, c->x_cmd, c->theta_cmd);
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
    memcpy(c->motion.x_from, c->x_cmd, sizeof(double) * 2 * (size_t)c->frame->n);
    memcpy(c->motion.th_from, c->theta_cmd, sizeof(double) * (size_t)c->frame->n);
}

static void start_increment(sbc_controller *c)
{
    save_commands(c);
    if (c->s.bc == SBC_BC_MIXED) {
        start_mixed(c);
        mixed_stress_targets(c);
    } else {
        start_classic(c);
    }
    c->servo = 0;
    c->iteration = 0;
    c->have_prev = 0;
    c->r_first = 0.0;
    c->win_min = c->prev_min = DBL_MAX;
    c->steps = 0;
    memset(&c->norms, 0, sizeof c->norms);
    begin_move(c, c->increment == 0, c->s.bc == SBC_BC_D ? relax_tol(&c->s) : first_tol(c));
}

/* Modes of each frame position from the edge modes of the settings. Corners
 * belong to their horizontal edge (bottom: BL, BR; top: TR, TL); on a periodic
 * horizontal edge they follow F (D), as the corners of (P) do (eq. 17). The
 * top corners of the layer stay T in y: made D (Sect. 5.1's "followed by the
 * four corner nodes"), their reactions put 8 % into eq. 23's P22 on 120 discs
 * (docs/servo_bc.md, "Mixed"). */
static void assign_modes(sbc_controller *c)
{
    static const int edge_of_side[5] = {-1, SBC_EDGE_BOTTOM, SBC_EDGE_RIGHT, SBC_EDGE_TOP, SBC_EDGE_LEFT};
    const sbc_frame *f = c->frame;
    int q, k;
    for (q = 0; q < f->n; ++q) {
        int e = edge_of_side[f->side[q]];
        if (e < 0)
            e = q == f->corner[SBC_CORNER_BL] || q == f->corner[SBC_CORNER_BR] ? SBC_EDGE_BOTTOM : SBC_EDGE_TOP;
        for (k = 0; k < 2; ++k) {
            unsigned char m = c->s.edge_mode[e][k];
            c->mode[2 * q + k] = f->side[q] == SBC_SIDE_CORNER && m == SBC_MODE_P ? SBC_MODE_D : m;
        }
    }
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
static int increments_too_coarse(const sbc_controller *c, sbc_error *err)
{
    const sbc_frame *f = c->frame;
    const int first = (c->s.bc == SBC_BC_MIXED ? c->s.stress_increments : 0) + 1;
    double F[4], G[4], jump = 0.0;
    int q, worst = 0;
    sbc_controller_target_F(c, first, F);
    sbc_controller_target_F(c, first - 1, G);
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[2 * q];
        const double d = hypot((F[0] - G[0]) * X[0] + (F[1] - G[1]) * X[1], (F[2] - G[2]) * X[0] + (F[3] - G[3]) * X[1]);
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
        size = fmax(size, fmax(fabs(f->X[2 * q]), fabs(f->X[2 * q + 1])));
        R += f->R[q] / f->n;
    }
    force = 1e-10 * c->kn * (size + R);
    sbc_relax_floor(&c->relax, force, c->kn > 0.0 ? n * force * force / (2.0 * c->kn) : 0.0);
}

sbc_controller *sbc_controller_create(const sbc_frame *frame, const sbc_settings *settings, const double *mass,
                                      double dt, double kn, sbc_error *err)
{
    sbc_controller *c;
    size_t q = (size_t)frame->n;
    if (!(dt > 0.0) || !isfinite(dt)) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s is not positive", dt);
        return NULL;
    }
    if (!(kn >= 0.0) || !isfinite(kn)) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: contact stiffness kn = %g N/m is not >= 0", kn);
        return NULL;
    }
    c = calloc(1, sizeof *c);
    if (!c) {
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return NULL;
    }
    c->s = *settings;
    c->dt = dt;
    c->kn = kn;
    c->total = sbc_settings_total_increments(settings);
    {
        /* a deep copy through the restart layout */
        size_t n = sbc_frame_state_size(frame);
        double *tmp = malloc(sizeof(double) * n);
        sbc_status st = tmp ? SBC_OK : SBC_ERR_NOMEM;
        if (tmp) {
            sbc_frame_save(frame, tmp);
            st = sbc_frame_load(&c->ref, tmp, n, err);
            free(tmp);
        }
        if (st != SBC_OK) {
            free(c);
            if (st == SBC_ERR_NOMEM)
                sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory for a frame of %d particles", frame->n);
            return NULL;
        }
        c->frame = &c->ref;
    }
    c->mode = calloc(2 * q, 1);
    c->mass = malloc(sizeof(double) * q);
    c->x_cmd = malloc(sizeof(double) * 2 * q);
    c->theta_cmd = calloc(q, sizeof(double));
    c->free_rot = calloc(q, 1);
    c->a = malloc(sizeof(double) * 2 * q);
    c->m = malloc(sizeof(double) * q);
    c->x_prev = malloc(sizeof(double) * 2 * q);
    c->du = calloc(2 * q, sizeof(double));
    c->a_hat = calloc(2 * q, sizeof(double));
    c->dtheta = calloc(q, sizeof(double));
    c->d_prev = calloc(3 * q, sizeof(double));
    c->lambda = 1.0;
    if (!sbc_motion_alloc(&c->motion, frame->n) || !c->d_prev || !c->mass || !c->x_cmd || !c->theta_cmd || !c->free_rot || !c->a || !c->m || !c->x_prev || !c->du || !c->a_hat ||
        !c->dtheta || !c->mode) {
        sbc_controller_free(c);
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory for a frame of %d particles", frame->n);
        return NULL;
    }
    memcpy(c->mass, mass, sizeof(double) * q);
    memcpy(c->x_cmd, c->frame->X, sizeof(double) * 2 * q); /* where the frame stands before increment 0 */
    set_floors(c);
    if (c->s.bc == SBC_BC_MIXED)
        assign_modes(c);
    if (c->s.bc == SBC_BC_P || c->s.bc == SBC_BC_MIXED) {
        size_t k;
        for (k = 0; k < q; ++k) {
            if (frame->side[k] != SBC_SIDE_CORNER && frame->partner[k] < 0 &&
                (c->s.bc == SBC_BC_P || c->mode[2 * k] == SBC_MODE_P)) {
                sbc_fail(err, SBC_ERR_FRAME,
                         "servo_bc %s: frame particle %d (packing index %d) has no periodic partner on the opposite "
                         "edge (opposite edges must hold equally many particles)",
                         sbc_bc_name(c->s.bc), (int)k, frame->particle[k]);
                sbc_controller_free(c);
                return NULL;
            }
        }
    }
    if (increments_too_coarse(c, err)) {
        sbc_controller_free(c);
        return NULL;
    }
    sbc_controller_target_F(c, 0, c->F_now);
    memcpy(c->F_prev, c->F_now, sizeof c->F_prev);
    start_increment(c);
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
    free(c->d_prev);
    sbc_motion_free(&c->motion);
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

const sbc_frame *sbc_controller_frame(const sbc_controller *c) { return c->frame; }

void sbc_controller_progress(const sbc_controller *c, int *iteration, double *r_force, double *r_moment,
                             double *r_deformation)
{
    *iteration = c->iteration;
    *r_force = c->norms.r_force;
    *r_moment = c->norms.r_moment;
    *r_deformation = c->norms.r_deformation;
}

void sbc_controller_target_F(const sbc_controller *c, int increment, double F[4])
{
    static const double I[4] = {1.0, 0.0, 0.0, 1.0};
    /* mixed: F stays I during the stress stage, then ramps over `increments` */
    int stage = c->s.bc == SBC_BC_MIXED ? c->s.stress_increments : 0;
    double t = increment <= stage ? 0.0 : (double)(increment - stage) / (double)c->s.increments;
    int k;
    for (k = 0; k < 4; ++k)
        F[k] = I[k] + t * (c->s.F[k] - I[k]);
}

/* The frame part of a snapshot, read once the relaxation is over. */
static int frame_finite(const sbc_frame *f, const sbc_snapshot *s, const char **what)
{
    int k;
    for (k = 0; k < 2 * f->n; ++k) {
        if (!isfinite(s->x[k])) { *what = "frame position"; return 0; }
        if (!isfinite(s->force[k])) { *what = "frame reaction force"; return 0; }
    }
    for (k = 0; k < f->n; ++k)
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
    double scale;
    r->increment = c->increment;
    sbc_homogenize_F(f, snap->x, r->F);
    sbc_homogenize_P(f, c->a, r->P);
    if (sbc_homogenize_cauchy(r->P, r->F, r->sigma, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_GEOMETRY,
                        "servo_bc %s: increment %d: det F = %g <= 0 (F = [%g %g; %g %g]): the frame is inverted or "
                        "collapsed",
                        sbc_bc_name(c->s.bc), c->increment, sbc_det2(r->F), r->F[0], r->F[1], r->F[2], r->F[3]);
    /* a stress collapsed below the path floor is judged on the path's scale
       (relax.h), and none below the round-off floor's stress, kn 1e-10 (the
       force floor of set_floors over the sample's size): a stress-free state
       has a Hill-Mandel residual of round-off size, not of its own scale */
    scale = sbc_homogenize_work_scale(r->P, r->F);
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
/* the force and moment tolerances in force: tol_relative when set */
static double tol_force(const sbc_controller *c)
{
    return c->s.tol_relative > 0.0 ? c->s.tol_relative : c->s.tol_force;
}

static double tol_moment(const sbc_controller *c)
{
    return c->s.tol_relative > 0.0 ? c->s.tol_relative : c->s.tol_moment;
}

/* Mixed: how far (in radii) the frame's D components and pair offsets may
 * lag behind the measured rows of F (eq. 45) at a converged increment: the
 * relative tolerance of the preset, or 1e-6 with absolute tolerances. */
static double mixed_lag_tol(const sbc_controller *c)
{
    return c->s.tol_relative > 0.0 ? c->s.tol_relative : 1e-6;
}

/* Mixed: measures F (eq. 15 on the positions x) and returns the largest
 * displacement, in radii, by which the D components and the pair offsets
 * lag behind it in the measured rows; Fm receives the measured F. */
static double mixed_lag(const sbc_controller *c, const double *x, double Fm[4])
{
    const sbc_frame *f = c->frame;
    double centre[2], lag = 0.0;
    int q, k;
    sbc_homogenize_F(f, x, Fm);
    support_centre(c, centre);
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < 2; ++k)
            if (row_measured(c, k) && c->mode[2 * q + k] != SBC_MODE_T) {
                const double d = (Fm[3 * k] - c->F_now[3 * k]) * (f->X[2 * q + k] - centre[k]);
                if (fabs(d) / f->R[q] > lag)
                    lag = fabs(d) / f->R[q];
            }
    return lag;
}

/* Mixed: P of eq. 23 from the boundary forces (into P), and how far it misses
 * the prescribed components of the traction rows, relative to |P_star|
 * there. P_hat: eq. 23 with the traction components of the top at their
 * targets (P_star + P_shift, measured where not prescribed), which measures
 * what the support and the pairs add to P apart from the top's lag. */
static double mixed_stress_miss(sbc_controller *c, double P[4], double P_hat[4])
{
    const sbc_frame *f = c->frame;
    double miss = 0.0, scale = 0.0, Pt[4], centre[2];
    int q, k;
    support_centre(c, centre);
    sbc_homogenize_P_about(f, c->a, centre, P);
    for (k = 0; k < 4; ++k)
        Pt[k] = c->P_fixed[k] ? c->P_star[k] + c->P_shift[k] : P[k];
    memcpy(c->a_hat, c->a, sizeof(double) * 2 * (size_t)f->n);
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < 2; ++k)
            if (c->mode[2 * q + k] == SBC_MODE_T)
                c->a_hat[2 * q + k] = Pt[2 * k] * f->A[2 * q] + Pt[2 * k + 1] * f->A[2 * q + 1];
    sbc_homogenize_P_about(f, c->a_hat, centre, P_hat);
    for (k = 0; k < 2; ++k)
        if (c->P_fixed[3 * k] && row_measured(c, k)) {
            miss = fmax(miss, fabs(P[3 * k] - c->P_star[3 * k]));
            scale = fmax(scale, fabs(c->P_star[3 * k]));
        }
    return scale > 0.0 ? miss / scale : 0.0;
}

static double residual_ratio(const sbc_controller *c, const sbc_servo_norms *n)
{
    double r = n->r_force / tol_force(c);
    if (c->s.bc == SBC_BC_MIXED) /* r_deformation: the frame's lag behind the measured F, in radii */
        return fmax(fmax(r, n->r_moment / tol_moment(c)), fmax(n->r_deformation, c->P_miss) / mixed_lag_tol(c));
    if (c->s.bc == SBC_BC_P)
        return fmax(r, n->r_moment / tol_moment(c));
    return fmax(r, n->r_deformation / c->s.tol_deformation);
}

/* Stagnation on round-off: the servo iterations of an increment, after the
 * first check, in windows of this many; when the smallest residual ratio of
 * a window is not 1 % below that of the window before while the force
 * residual is within STAGNATION_ROUNDOFF of the frame's own forces, the
 * tolerances lie below what double precision resolves, and no iteration
 * reaches them. Above round-off a plateau is left to run (to max_iterations):
 * relaxation noise takes a floor near the tolerances below them sooner or
 * later, and a frictional packing under load holds the residual for
 * hundreds of iterations before it rearranges and converges (the mixed layer
 * of Sect. 5.3, increment 36: 1400 iterations at 186 times the
 * tolerances; the whole path of eq. 38 under (T): 27 of 300 increments take
 * 1000 to 2822 iterations, and converge). */
#define STAGNATION_WINDOW 200
#define STAGNATION_ROUNDOFF 1e-9

/* too_slow: the iteration converges but not within max_iterations. */
static void diverged(const sbc_controller *c, const sbc_servo_norms *n, const char *why, int too_slow,
                     sbc_error *err)
{
    const char *gain = c->s.bc == SBC_BC_T ? "gain_force or gain_deformation" : "gain_force or gain_moment";
    sbc_fail(err, SBC_ERR_DIVERGED,
             "servo_bc %s: increment %d, iteration %d: %s (r_force = %.3g, r_moment = %.3g, r_deformation = %.3g; "
             "tolerances %.3g, %.3g, %.3g); %s %s",
             sbc_bc_name(c->s.bc), c->increment, c->iteration, why, n->r_force, n->r_moment, n->r_deformation,
             tol_force(c), tol_moment(c), c->s.tol_deformation,
             too_slow ? "raise max_iterations, loosen the tolerances or raise" : "lower", gain);
}

static void stagnated(const sbc_controller *c, const sbc_servo_norms *n, sbc_error *err)
{
    sbc_fail(err, SBC_ERR_DIVERGED,
             "servo_bc %s: increment %d, iteration %d: the residuals stagnated on round-off at %.3g times the "
             "tolerances (the force residual is %.2g of the frame's forces, and their smallest ratio to the tolerances "
             "in the last %d iterations is not 1 %% below that of the %d before; r_force = %.3g, r_moment = %.3g, "
             "r_deformation = %.3g; tolerances %.3g, %.3g, %.3g): loosen the tolerances",
             sbc_bc_name(c->s.bc), c->increment, c->iteration, c->win_min, n->relative_force, STAGNATION_WINDOW,
             STAGNATION_WINDOW, n->r_force, n->r_moment, n->r_deformation, tol_force(c), tol_moment(c),
             c->s.tol_deformation);
}

/* End of the stress stage of a mixed BC: the converged state becomes the
 * reference X of stage 2 (Sect. 5.1, after eq. 44), with its A_q and V. */
static void new_reference(sbc_controller *c, const double *x)
{
    memcpy(c->ref.X, x, sizeof(double) * 2 * (size_t)c->ref.n);
    sbc_frame_update_geometry(&c->ref);
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

static double largest_component(const double t[4])
{
    return fmax(fmax(fabs(t[0]), fabs(t[1])), fmax(fabs(t[2]), fabs(t[3])));
}

/* A row is written only when it meets what it reports against: the force
 * balance of the relaxation (relax.h), the frame residual of (P) and (T)
 * relative to the frame's forces, and the Hill-Mandel residual within the
 * stated accuracy; each measured against the path's scale once the state's
 * own forces have collapsed below the path floor. Otherwise the run stops
 * with what happened. */
static int certified(const sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const sbc_result *r = &c->result;
    const sbc_frame *f = c->frame;
    const double stated = stated_accuracy(c), sigma = largest_component(r->sigma);
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
        const double X = f->X[2 * q], Y = f->X[2 * q + 1];
        const double dx = snap->x[2 * q] - (c->F_now[0] * X + c->F_now[1] * Y);
        const double dy = snap->x[2 * q + 1] - (c->F_now[2] * X + c->F_now[3] * Y);
        const double d = sqrt(dx * dx + dy * dy) / f->R[q];
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

/* Table 1, 1.3 / Tables 2-3, 1.6.A: the relaxed, converged configuration is
 * the result of increment i; the next increment starts. */
static sbc_event accept(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    if (measure(c, snap, err) != SBC_OK || !certified(c, snap, err))
        return SBC_EVENT_FAILED;
    sbc_relax_path(&c->relax, c->relax.fc_known);
    c->work_path = fmax(c->work_path, sbc_homogenize_work_scale(c->result.P, c->result.F));
    c->sigma_path = fmax(c->sigma_path, largest_component(c->result.sigma));
    memcpy(c->x_prev, snap->x, sizeof(double) * 2 * (size_t)c->frame->n);
    memcpy(c->F_prev, c->F_now, sizeof c->F_prev);
    if (c->s.bc == SBC_BC_MIXED && c->s.stress_increments > 0 && c->increment == c->s.stress_increments) {
        int k;
        new_reference(c, snap->x);
        for (k = 0; k < 2; ++k) /* F of the state after stage 1 on itself: I */
            if (row_measured(c, k)) {
                c->F_prev[2 * k] = k == 0 ? 1.0 : 0.0;
                c->F_prev[2 * k + 1] = k == 1 ? 1.0 : 0.0;
            }
    }
    if (c->increment == c->total) {
        c->increment++;
        return SBC_EVENT_FINISHED;
    }
    c->increment++;
    sbc_controller_target_F(c, c->increment, c->F_now);
    start_increment(c);
    return SBC_EVENT_INCREMENT;
}

/* Whether the correction du, dtheta moves some frame particle beyond the
 * round-off of its position: |du| + R |dtheta| > 16 eps (|x| + R). A
 * balanced packing yields corrections of round-off forces, some 1e-21 m on
 * the 100-particle lattice, which leave the frame where it was (relax.h). */
static int correction_moves_frame(const sbc_controller *c)
{
    int q;
    for (q = 0; q < c->frame->n; ++q) {
        const double R = c->frame->R[q];
        const double move = fabs(c->du[2 * q]) + fabs(c->du[2 * q + 1]) + R * fabs(c->dtheta[q]);
        if (move > 16.0 * DBL_EPSILON * (fabs(c->x_cmd[2 * q]) + fabs(c->x_cmd[2 * q + 1]) + R))
            return 1;
    }
    return 0;
}

/* (T): after a force correction, the frame is put back on the imposed F
 * (eq. 15) exactly, by the smallest change of the commands in the metric of
 * the area vectors:
 *   x_q += M S^-1 A_q,  M = F G - sum_r x_r (x) A_r,  S = sum_r A_r (x) A_r,
 * G = sum_r X_r (x) A_r (eq. 15 normalized as sbc_homogenize_F does), since
 * sum_q (M S^-1 A_q) (x) A_q = M. The force correction then only moves the
 * frame within the set of positions that keep F, and the deformation
 * residual of eq. 35 stays at round-off instead of being won back at
 * g_F per iteration (the stall near F12 = 0.2 of the irregular packing). */
static void restore_eq15(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    const double *F = c->F_now;
    double S[4] = {0.0, 0.0, 0.0, 0.0}, G[4] = {0.0, 0.0, 0.0, 0.0}, X[4] = {0.0, 0.0, 0.0, 0.0}, M[4], Si[4], det;
    int q, i, j;
    for (q = 0; q < f->n; ++q) {
        const double *A = &f->A[2 * q];
        for (i = 0; i < 2; ++i)
            for (j = 0; j < 2; ++j) {
                S[2 * i + j] += A[i] * A[j];
                G[2 * i + j] += f->X[2 * q + i] * A[j];
                X[2 * i + j] += c->x_cmd[2 * q + i] * A[j];
            }
    }
    det = sbc_det2(S);
    if (!(fabs(det) > 0.0))
        return;
    Si[0] = S[3] / det;
    Si[1] = -S[1] / det;
    Si[2] = -S[2] / det;
    Si[3] = S[0] / det;
    for (i = 0; i < 2; ++i)
        for (j = 0; j < 2; ++j)
            M[2 * i + j] = F[2 * i] * G[j] + F[2 * i + 1] * G[2 + j] - X[2 * i + j];
    for (q = 0; q < f->n; ++q) {
        const double *A = &f->A[2 * q];
        const double b0 = Si[0] * A[0] + Si[1] * A[1], b1 = Si[2] * A[0] + Si[3] * A[1];
        c->x_cmd[2 * q] += M[0] * b0 + M[1] * b1;
        c->x_cmd[2 * q + 1] += M[2] * b0 + M[3] * b1;
    }
}

/* update secant: the largest correction of one frame particle, in radii.
 * Larger corrections cost fewer iterations but move the frame back and forth
 * through frictional contacts, which then slip along another path: on the
 * regular packing under (P) at dt = 1e-4 s, 0.05 R gave a path error of 1.2 %,
 * 0.01 R 0.65 %, 0.002 R 0.37 % and 0.0005 R 0.30 % against the reference
 * (whose own spread is about 0.4 %), at 15, 16, 29 and 103 thousand steps
 * (docs/speed-accuracy.md). */
#define SECANT_MAX_STEP 0.002

/* update secant with kn known: bounds of the factor on the scale-free
 * corrections (servo.c). Without a lower bound the factor halves on every
 * iteration whose residual did not fall, which frictional noise makes
 * common: on the 232-disc irregular packing it reached 1e-34 and the servo
 * stalled at a relative residual of 4e-4 for thousands of iterations. */
#define SECANT_LAMBDA_MIN 1e-2
#define SECANT_LAMBDA_MAX 1e2

/* update secant: scales the fixed-gain correction d_k (du, R dtheta of every
 * frame particle, m) by lambda_k. Within an increment, from the previous
 * correction d_(k-1) and its factor, the Barzilai-Borwein step of the
 * preconditioned iteration x <- x + lambda d(x):
 *   s = lambda_(k-1) d_(k-1),  y = d_(k-1) - d_k  (~ P J s),
 *   lambda_k = s.y / y.y = lambda_(k-1) d_(k-1).(d_(k-1) - d_k) / |d_(k-1) - d_k|^2,
 * when s.y > 0; when s.y <= 0 (the residual did not fall along s) lambda
 * halves. The first correction of an increment keeps the factor of the last
 * one. No frame particle moves more than SECANT_MAX_STEP of its radius in one
 * correction, which also bounds the first step whatever the gains. */
static void secant_scale(sbc_controller *c, sbc_servo_norms *n)
{
    const sbc_frame *f = c->frame;
    double dd = 0.0, dy = 0.0, yy = 0.0, lam = c->lambda, cap = DBL_MAX;
    int q, k;
    for (q = 0; q < f->n; ++q) {
        double d[3] = {c->du[2 * q], c->du[2 * q + 1], f->R[q] * c->dtheta[q]};
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (k = 0; k < 3; ++k) {
            double y = c->d_prev[3 * q + k] - d[k];
            dd += d[k] * d[k];
            dy += c->d_prev[3 * q + k] * y;
            yy += y * y;
            c->d_prev[3 * q + k] = d[k];
        }
        if (len > 0.0 && SECANT_MAX_STEP * f->R[q] / len < cap)
            cap = SECANT_MAX_STEP * f->R[q] / len;
    }
    if (c->have_prev)
        lam = dy > 0.0 && yy > 0.0 ? c->lambda * dy / yy : 0.5 * c->lambda;
    if (c->kn > 0.0) /* scale-free first steps (servo.c): the factor stays within two decades of them */
        lam = fmin(fmax(lam, SECANT_LAMBDA_MIN), SECANT_LAMBDA_MAX);
    if (dd > 0.0) {
        c->lambda = lam = fmin(lam, cap);
    } else {
        lam = c->lambda; /* no correction to scale; the factor stays */
    }
    c->have_prev = 1;
    for (k = 0; k < 2 * f->n; ++k)
        c->du[k] *= lam;
    for (k = 0; k < f->n; ++k)
        c->dtheta[k] *= lam;
    n->max_step *= lam;
}

sbc_event sbc_controller_step(sbc_controller *c, const sbc_snapshot *snap, sbc_error *err)
{
    const char *what = NULL;
    const sbc_relax_sample sample = sample_of(snap);
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
    if (sbc_motion_advance(&c->motion, c->frame->n, c->x_cmd, c->theta_cmd)) {
        c->steps++;
        return SBC_EVENT_CORRECTED; /* the frame travels on (motion.h) */
    }
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
    if (!sbc_relax_update(&c->relax, &sample)) {
        if (c->relax.steps >= c->s.max_relax_steps) {
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
        return SBC_EVENT_RELAXING;
    }
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
    {
        int k;
        for (k = 0; k < 2 * c->frame->n; ++k)
            c->a[k] = -snap->force[k]; /* eq. 5: sum of contact forces = -a_q */
        for (k = 0; k < c->frame->n; ++k)
            c->m[k] = -snap->torque[k];
    }
    c->steps += c->relax.steps;
    if (c->s.bc != SBC_BC_D) {
        sbc_servo_norms nrm;
        double ratio, F_measured[4], P_measured[4], P_hat[4];
        const int first = !c->servo;
        int k;
        /* Tables 2-3: after the initial relaxation (1.2) correct at once (1.3);
         * after each later relaxation (1.4) check the residuals (1.5-1.6). */
        const sbc_servo_floors floors = {sbc_relax_scale_floor(&c->relax),
                                         SBC_RELAX_NET_FLOOR * c->relax.floor_force};
        if (c->s.bc == SBC_BC_MIXED) {
            double target[4];
            for (k = 0; k < 4; ++k)
                target[k] = c->P_star[k] + c->P_shift[k];
            sbc_servo_mixed(c->frame, c->mode, &c->s, c->mass, c->dt, c->kn, &floors, target, c->P_fixed, c->a, c->m,
                            c->du, c->dtheta, &nrm);
            nrm.r_deformation = mixed_lag(c, snap->x, F_measured);
            c->P_miss = mixed_stress_miss(c, P_measured, P_hat);
        }
        else
            sbc_servo_residuals(c->s.bc, c->frame, &c->s, c->mass, c->dt, c->kn, &floors, c->F_now, c->a, c->m, snap->x,
                                c->du, c->dtheta, &nrm);
        c->norms = nrm;
        if (!isfinite(nrm.r_force) || !isfinite(nrm.r_moment) || !isfinite(nrm.r_deformation)) {
            sbc_fail(err, SBC_ERR_NUMERIC, "servo_bc %s: increment %d, iteration %d: non-finite residual",
                     sbc_bc_name(c->s.bc), c->increment, c->iteration);
            return SBC_EVENT_FAILED;
        }
        ratio = residual_ratio(c, &nrm);
        if (!first && ratio < c->win_min)
            c->win_min = ratio;
        if (first) {
            c->r_first = nrm.r_force;
        } else if (ratio <= 1.0 && c->relax.tol > relax_tol(&c->s)) {
            /* converged on an inexact relaxation: relax in place to the
               tolerance, then check again */
            sbc_relax_start(&c->relax, c->s.criterion, relax_tol(&c->s), c->s.window, 1);
            return SBC_EVENT_RELAXING;
        } else if (ratio <= 1.0) {
            return accept(c, snap, err);
        } else if (c->s.update == SBC_UPDATE_FIXED && nrm.r_force > 1e3 * fmax(c->r_first, 1e3 * tol_force(c))) {
            /* growth over the first residual of the increment (that one can be
             * round-off small: an already periodic state, hence the floor) under
             * fixed gains, which can run away; the secant update caps its
             * corrections, and a residual that grows under it is the packing
             * leaving an unstable equilibrium, which the servo follows to a
             * stable one (docs/servo_bc.md, "Divergence") */
            diverged(c, &nrm, "the force residual grew more than 1000-fold", 0, err);
            return SBC_EVENT_FAILED;
        } else if (c->iteration >= c->s.max_iterations) {
            diverged(c, &nrm, "max_iterations reached", 1, err);
            return SBC_EVENT_FAILED;
        } else if (c->iteration % STAGNATION_WINDOW == 0) {
            if (c->win_min > 0.99 * c->prev_min && nrm.relative_force < STAGNATION_ROUNDOFF) {
                stagnated(c, &nrm, err);
                return SBC_EVENT_FAILED;
            }
            c->prev_min = c->win_min;
            c->win_min = DBL_MAX;
        }
        if (c->s.update == SBC_UPDATE_SECANT)
            secant_scale(c, &nrm);
        if (nrm.max_step > 0.5) { /* fixed gains only: the secant update caps its steps */
            diverged(c, &nrm, "a correction moved a frame particle by more than half its radius", 0, err);
            return SBC_EVENT_FAILED;
        }
        {
            const int moved = correction_moves_frame(c);
            save_commands(c);
            for (k = 0; k < 2 * c->frame->n; ++k)
                c->x_cmd[k] += c->du[k];
            for (k = 0; k < c->frame->n; ++k)
                c->theta_cmd[k] += c->dtheta[k];
            c->servo = 1;
            c->iteration++;
            if (c->s.bc == SBC_BC_T && c->s.update != SBC_UPDATE_FIXED)
                restore_eq15(c);
            if (c->s.bc == SBC_BC_MIXED) { /* the frame follows the measured rows of F */
                for (k = 0; k < 2; ++k)
                    if (row_measured(c, k))
                        c->F_now[3 * k] = F_measured[3 * k];
                for (k = 0; k < 2; ++k) /* the measured P_kk towards P_star (the normal stress of the traction row) */
                    if (c->P_fixed[3 * k] && row_measured(c, k))
                        c->P_shift[3 * k] += c->P_star[3 * k] - P_hat[3 * k];
                mixed_follow_F(c);
            }
            begin_move(c, !moved, inexact_tol(c, nrm.relative_force));
        }
        return SBC_EVENT_CORRECTED;
    }
    return accept(c, snap, err);
}

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
    new_reference(c, ref);
    if (c->s.bc == SBC_BC_MIXED)
        mixed_stress_targets(c);
    return SBC_OK;
}
