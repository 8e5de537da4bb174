/* Private: the controller's state and the functions its files share.
 * controller.c          the state machine (Tables 1-3, 5): create, step, accept
 * controller_mixed.c    the mixed condition's bookkeeping (Table 5, Sect. 5.1)
 * controller_checks.c   refusals, failure messages, the certification of a row
 * controller_update.c   the secant update's scaling and eq. 15 under (T)
 * update_rules.c        the update rules as a table (update_rules.h)
 * controller_state.c    the restart state (save, load)
 * controller_host.c     the host's queries and changes between steps (commands, results, aim, branch, adopt,
 *                       remap, progress) */
#ifndef SBC_CONTROLLER_PRIVATE_H
#define SBC_CONTROLLER_PRIVATE_H

#include "sbc/controller.h"
#include "sbc/relax.h"
#include "motion.h"
#include "servo.h"
#include "tuning.h"
#include "update_rules.h"

/* parts of one frame particle's correction for the secant update: du (dim
   components) and R dtheta (SBC_ROTATIONS(dim) components) */
#define SBC_CTL_STEP_PARTS(dim) ((dim) + SBC_ROTATIONS(dim))

struct sbc_controller {
    sbc_frame ref;       /* the controller's copy of the frame: the reference of
                            mixed stage 2 is the state after stage 1 (Sect. 5.1) */
    const sbc_frame *frame; /* = &ref */
    unsigned char *mode; /* [3Q] mixed: sbc_mode of each component of each frame position */
    double P_star[9];    /* mixed: prescribed stress of this increment, N/m */
    unsigned char P_fixed[9]; /* mixed: 1 where P_star holds (prescribed, or 0 in the stress stage) */
    double P_shift[9];   /* mixed: the top's traction targets P_star + P_shift, so that the measured
                            P of eq. 23 (which the support's reactions enter) meets P_star, N/m */
    double P_miss;       /* mixed: |P measured - P_star| over |P_star| in the traction rows */
    double *a_hat;       /* [3Q] mixed: the boundary forces with the top's traction components at their targets */
    sbc_settings s;
    const sbc_update_rule *rule; /* the update rule of s.update (update_rules.h) */
    int accept_uncertified;      /* sbc_controller_accept_uncertified */
    int uncertified;             /* the last accepted increment was not certified: why */
    char why[SBC_ERROR_LEN];
    sbc_newton_fn newton;        /* update newton: the host's correction (sbc_controller_set_newton) */
    void *newton_data;
    double dt;           /* s */
    double kn;           /* the host's normal contact stiffness, N/m (0: unknown) */
    sbc_motion motion;   /* the frame's travel to the commands (motion.h) */
    double *mass;        /* [Q] kg */
    int increment;       /* 0 .. i_tot */
    sbc_relax relax;
    double *x_cmd;       /* [3Q] m */
    int rot;             /* SBC_ROTATIONS(dim): the stride of the rotation arrays */
    double *theta_cmd;   /* [rot Q] rad */
    unsigned char *free_rot;
    double *a;           /* [3Q] boundary forces a_q = -sum of contact forces (eq. 5), N */
    double *m;           /* [rot Q] boundary moments m_q = -sum of contact moments (eq. 5), N m */
    double *x_prev;      /* [3Q] converged positions of the previous increment (prediction), m */
    double *du, *dtheta; /* [3Q], [rot Q] servo corrections, m, rad */
    sbc_secant secant;   /* the secant update's state (update_rules.h) */
    double newton_best;  /* update newton: the smallest relative force residual of the increment so far */
    int newton_stalled;  /* ... the corrections since it fell; NEWTON_PATIENCE of them: secant for the rest */
    double F_prev[9];    /* F imposed at the previous increment */
    double F_now[9];     /* F imposed at this increment */
    int total;           /* increments of the whole path, sbc_settings_total_increments */
    int servo;           /* 0: initial relaxation of the increment, 1: servo iterations */
    int iteration;       /* servo iterations in this increment */
    double r_first;      /* first force residual of the increment (growth check) */
    double win_min;      /* smallest residual/tolerance ratio in this window of iterations */
    double prev_min;     /* ... in the window before (stagnation check) */
    long steps;          /* host steps spent on this increment */
    int remap_due;       /* the commands of this step move the frame towards an increment's first
                            commands (sbc_controller_remap) */
    sbc_servo_norms norms; /* last residual norms of this increment (zero for D) */
    sbc_result result;
    double work_path;    /* the largest work scale |P||F| of the path's converged increments, N/m */
    double sigma_path;   /* the largest |sigma| (largest component) of those increments, N/m */
};

/* controller.c: an increment's start (its commands, the servo's state, the frame's move) and the interior's
   map over its opening move (remap x; 0 when it is the identity) */
void sbc_ctl_start_increment(sbc_controller *c);
int sbc_ctl_opening_map(const sbc_controller *c, double M[9], double origin[3]);

/* controller_mixed.c: the mixed condition's bookkeeping (Table 5) */
int sbc_ctl_row_measured(const sbc_controller *c, int i);
void sbc_ctl_mixed_follow_F(sbc_controller *c);
void sbc_ctl_start_mixed(sbc_controller *c);
void sbc_ctl_mixed_stress_targets(sbc_controller *c);
double sbc_ctl_mixed_lag_tol(const sbc_controller *c);
double sbc_ctl_mixed_lag(const sbc_controller *c, const double *x, double Fm[9]);
double sbc_ctl_mixed_stress_miss(sbc_controller *c, double P[9], double P_hat[9]);
void sbc_ctl_new_reference(sbc_controller *c, const double *x);
void sbc_ctl_mixed_centre(const sbc_controller *c, double centre[3]);

/* controller_checks.c: refusals, failure messages and the certification of a row */
double sbc_ctl_tol_force(const sbc_controller *c);
double sbc_ctl_tol_moment(const sbc_controller *c);
int sbc_ctl_increments_too_coarse(const sbc_controller *c, sbc_error *err);
void sbc_ctl_diverged(const sbc_controller *c, const sbc_servo_norms *n, const char *why, int too_slow, sbc_error *err);
void sbc_ctl_stagnated(const sbc_controller *c, const sbc_servo_norms *n, sbc_error *err);
double sbc_ctl_largest_component(int dim, const double t[9]);
int sbc_ctl_certified(const sbc_controller *c, const sbc_snapshot *snap, sbc_error *err);

/* controller_update.c: the update rules (fixed, secant) and eq. 15 under (T) */
void sbc_ctl_restore_eq15(sbc_controller *c);
sbc_status sbc_ctl_secant_scale(sbc_controller *c, sbc_servo_norms *n, sbc_error *err);
sbc_status sbc_ctl_newton_scale(sbc_controller *c, sbc_servo_norms *n, sbc_error *err);
void sbc_ctl_newton_start(sbc_controller *c);
void sbc_ctl_secant_start(sbc_controller *c);

#endif
