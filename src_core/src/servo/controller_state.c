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

/* Restart layout (doubles): a head (version, Q, bc, increments, F (4),
 * dt), checked against the controller's own words, then the fields of
 * state_fields in their order; save and load both walk that one list. */
#define STATE_VERSION 8.0
#define STATE_HEAD 9

/* counters saved as doubles: at most 2^50, far below where a long or a
 * double stops counting steps one by one */
#define SAVED_COUNT 1125899906842624L

/* One saved field: count values of one kind at `at`. Kinds: 'r' a finite
 * real, 'p' a real > 0, 'i' an int and 'l' a long in [lo, hi], 'u' an
 * unsigned char in [lo, hi], 'k' reals checked on load but kept by the
 * caller (the reference X, set after every check). */
typedef struct state_field {
    const char *name;
    char kind;
    void *at;
    size_t count;
    long lo, hi;
} state_field;

#define STATE_FIELDS 80

/* The controller's saved state, in the file's order; returns the number of
 * fields. */
static int state_fields(sbc_controller *c, state_field f[STATE_FIELDS])
{
    const size_t q = (size_t)c->frame->n;
    sbc_result *r = &c->result;
    int n = 0;
#define REAL(name, at, count) f[n++] = (state_field){name, 'r', at, count, 0, 0}
#define INT(name, at, lo, hi) f[n++] = (state_field){name, 'i', at, 1, lo, hi}
#define LONG(name, at, lo, hi) f[n++] = (state_field){name, 'l', at, 1, lo, hi}
    INT("increment", &c->increment, 0, c->total + 1L);
    INT("servo", &c->servo, 0, 1);
    INT("iteration", &c->iteration, 0, INT_MAX);
    REAL("r_first", &c->r_first, 1);
    LONG("steps", &c->steps, 0, SAVED_COUNT);
    REAL("r_force", &c->norms.r_force, 1);
    REAL("r_moment", &c->norms.r_moment, 1);
    REAL("r_deformation", &c->norms.r_deformation, 1);
    REAL("max_step", &c->norms.max_step, 1);
    LONG("relaxation steps", &c->relax.steps, 0, SAVED_COUNT);
    INT("relaxation count", &c->relax.count, 0, INT_MAX);
    INT("relaxation rising", &c->relax.rising, 0, 1);
    INT("relaxation past_peak", &c->relax.past_peak, 0, 1);
    REAL("relaxation ek_prev", &c->relax.ek_prev, 1);
    INT("relaxation at_rest", &c->relax.at_rest, 0, 1);
    REAL("lambda", &c->lambda, 1);
    INT("have_prev", &c->have_prev, 0, 1);
    REAL("win_min", &c->win_min, 1);
    REAL("prev_min", &c->prev_min, 1);
    REAL("F_prev", c->F_prev, 4);
    REAL("F_now", c->F_now, 4);
    f[n++] = (state_field){"relaxation tol", 'p', &c->relax.tol, 1, 0, 0};
    LONG("relaxation known_step", &c->relax.known_step, 0, SAVED_COUNT);
    REAL("relaxation ep_known", &c->relax.ep_known, 1);
    REAL("relaxation ek_known", &c->relax.ek_known, 1);
    REAL("relaxation fc_known", &c->relax.fc_known, 1);
    REAL("relaxation unbalanced", &c->relax.unbalanced, 1);
    LONG("motion steps", &c->motion.steps, 0, SAVED_COUNT);
    LONG("motion done", &c->motion.done, 0, SAVED_COUNT);
    REAL("P_shift", c->P_shift, 4);
    REAL("path force", &c->relax.path_force, 1);
    REAL("path work scale", &c->work_path, 1);
    REAL("path stress", &c->sigma_path, 1);
    INT("result increment", &r->increment, 0, c->total);
    REAL("result F", r->F, 4);
    REAL("result P", r->P, 4);
    REAL("result sigma", r->sigma, 4);
    REAL("result overlap_mean", &r->overlap_mean, 1);
    REAL("result rotation_mean", &r->rotation_mean, 1);
    INT("result iterations", &r->iterations, 0, INT_MAX);
    LONG("result relax_steps", &r->relax_steps, 0, SAVED_COUNT);
    REAL("result r_force", &r->r_force, 1);
    REAL("result r_moment", &r->r_moment, 1);
    REAL("result r_deformation", &r->r_deformation, 1);
    REAL("result hill_mandel", &r->hill_mandel, 1);
    REAL("result unbalanced", &r->unbalanced, 1);
    REAL("result frame_residual", &r->frame_residual, 1);
    REAL("x_cmd", c->x_cmd, 2 * q);
    REAL("theta_cmd", c->theta_cmd, q);
    f[n++] = (state_field){"free_rot", 'u', c->free_rot, q, 0, 1};
    REAL("x_prev", c->x_prev, 2 * q);
    f[n++] = (state_field){"reference X", 'k', c->ref.X, 2 * q, 0, 0};
    REAL("d_prev", c->d_prev, 3 * q);
    REAL("motion x_from", c->motion.x_from, 2 * q);
    REAL("motion x_goal", c->motion.x_goal, 2 * q);
    REAL("motion th_from", c->motion.th_from, q);
    REAL("motion th_goal", c->motion.th_goal, q);
#undef REAL
#undef INT
#undef LONG
    return n;
}

size_t sbc_controller_state_size(const sbc_controller *c)
{
    state_field f[STATE_FIELDS];
    const int n = state_fields((sbc_controller *)c, f); /* read only */
    size_t size = STATE_HEAD;
    int k;
    for (k = 0; k < n; ++k)
        size += f[k].count;
    return size;
}

void sbc_controller_save(const sbc_controller *c, double *o)
{
    state_field f[STATE_FIELDS];
    const int n = state_fields((sbc_controller *)c, f); /* read only */
    int k;
    size_t j;
    *o++ = STATE_VERSION;
    *o++ = c->frame->n;
    *o++ = c->s.bc;
    *o++ = c->s.increments;
    for (k = 0; k < 4; ++k) *o++ = c->s.F[k];
    *o++ = c->dt;
    for (k = 0; k < n; ++k)
        for (j = 0; j < f[k].count; ++j) {
            if (f[k].kind == 'i') *o++ = ((const int *)f[k].at)[j];
            else if (f[k].kind == 'l') *o++ = (double)((const long *)f[k].at)[j];
            else if (f[k].kind == 'u') *o++ = ((const unsigned char *)f[k].at)[j];
            else *o++ = ((const double *)f[k].at)[j];
        }
}

/* Reads the fields f [n] from rd; the kept ones ('k') are left where they
 * are (in rd's input). */
static void load_fields(const state_field *f, int n, sbc_saved *rd)
{
    int k;
    size_t j;
    for (k = 0; k < n; ++k)
        for (j = 0; j < f[k].count; ++j) {
            if (f[k].kind == 'i') ((int *)f[k].at)[j] = (int)sbc_saved_int(rd, f[k].name, f[k].lo, f[k].hi);
            else if (f[k].kind == 'l') ((long *)f[k].at)[j] = sbc_saved_int(rd, f[k].name, f[k].lo, f[k].hi);
            else if (f[k].kind == 'u')
                ((unsigned char *)f[k].at)[j] = (unsigned char)sbc_saved_int(rd, f[k].name, f[k].lo, f[k].hi);
            else if (f[k].kind == 'p') ((double *)f[k].at)[j] = sbc_saved_positive(rd, f[k].name);
            else if (f[k].kind == 'k') (void)sbc_saved_real(rd, f[k].name);
            else ((double *)f[k].at)[j] = sbc_saved_real(rd, f[k].name);
        }
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
    c->relax.criterion = c->s.criterion;
    c->relax.window = c->s.window;
    {
        /* the reference X: checked with the rest, set after every check */
        state_field f[STATE_FIELDS];
        const int nf = state_fields(c, f);
        size_t before = 0;
        for (k = 0; k < nf && f[k].kind != 'k'; ++k)
            before += f[k].count;
        ref = in + STATE_HEAD + before;
        load_fields(f, nf, &rd);
    }
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
