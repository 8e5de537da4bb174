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

/* Restart layout (doubles): a head (version, Q, bc, increments, F (dim x
 * dim), dt), checked against the controller's own words, then the fields of
 * state_fields in their order; save and load both walk that one list. A
 * tensor is saved as its dim x dim block and a vector of each frame particle
 * as its dim components, so a 2D state has the layout it had when the core
 * stored 2 x 2 tensors. */
#define STATE_VERSION 8.0
#define STATE_HEAD(dim) (5 + (dim) * (dim))

/* counters saved as doubles: at most 2^50, far below where a long or a
 * double stops counting steps one by one */
#define SAVED_COUNT 1125899906842624L

/* One saved field: count values of one kind at `at`. Kinds: 'r' a finite
 * real, 'p' a real > 0, 'i' an int and 'l' a long in [lo, hi], 'u' an
 * unsigned char in [lo, hi]. Shape: ' ' count values in a row, 't' a tensor
 * (count = dim x dim of its 9 slots), 'v' one vector per frame particle
 * (count = dim Q of its 3Q slots). */
typedef struct state_field {
    const char *name;
    char kind;
    void *at;
    size_t count;
    long lo, hi;
    char shape;
    int dim;
} state_field;

/* the slot of saved value j of field f */
static size_t slot(const state_field *f, size_t j)
{
    const size_t d = (size_t)f->dim;
    if (f->shape == 't')
        return (size_t)SBC_IJ(j / d, j % d);
    if (f->shape == 'v')
        return 3 * (j / d) + j % d;
    return j;
}

#define STATE_FIELDS 80

/* The controller's saved state, in the file's order; returns the number of
 * fields. The reference X is read from and loaded into ref. */
static int state_fields(sbc_controller *c, double *ref, state_field f[STATE_FIELDS])
{
    const int dim = c->frame->dim;
    const size_t q = (size_t)c->frame->n, d = (size_t)dim, rq = (size_t)c->rot * q;
    sbc_result *r = &c->result;
    int n = 0;
#define REAL(name, at, count) f[n++] = (state_field){name, 'r', at, count, 0, 0, ' ', dim}
#define TENSOR(name, at) f[n++] = (state_field){name, 'r', at, d * d, 0, 0, 't', dim}
#define VECTORS(name, at) f[n++] = (state_field){name, 'r', at, d * q, 0, 0, 'v', dim}
#define INT(name, at, lo, hi) f[n++] = (state_field){name, 'i', at, 1, lo, hi, ' ', dim}
#define LONG(name, at, lo, hi) f[n++] = (state_field){name, 'l', at, 1, lo, hi, ' ', dim}
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
    REAL("lambda", &c->secant.lambda, 1);
    INT("have_prev", &c->secant.have_prev, 0, 1);
    REAL("win_min", &c->win_min, 1);
    REAL("prev_min", &c->prev_min, 1);
    TENSOR("F_prev", c->F_prev);
    TENSOR("F_now", c->F_now);
    f[n++] = (state_field){"relaxation tol", 'p', &c->relax.tol, 1, 0, 0, ' ', dim};
    LONG("relaxation known_step", &c->relax.known_step, 0, SAVED_COUNT);
    REAL("relaxation ep_known", &c->relax.ep_known, 1);
    REAL("relaxation ek_known", &c->relax.ek_known, 1);
    REAL("relaxation fc_known", &c->relax.fc_known, 1);
    REAL("relaxation unbalanced", &c->relax.unbalanced, 1);
    LONG("motion steps", &c->motion.steps, 0, SAVED_COUNT);
    LONG("motion done", &c->motion.done, 0, SAVED_COUNT);
    TENSOR("P_shift", c->P_shift);
    REAL("path force", &c->relax.path_force, 1);
    REAL("path work scale", &c->work_path, 1);
    REAL("path stress", &c->sigma_path, 1);
    INT("result increment", &r->increment, 0, c->total);
    TENSOR("result F", r->F);
    TENSOR("result P", r->P);
    TENSOR("result sigma", r->sigma);
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
    VECTORS("x_cmd", c->x_cmd);
    REAL("theta_cmd", c->theta_cmd, rq);
    f[n++] = (state_field){"free_rot", 'u', c->free_rot, q, 0, 1, ' ', dim};
    VECTORS("x_prev", c->x_prev);
    VECTORS("reference X", ref);
    REAL("d_prev", c->secant.d_prev, (size_t)SBC_CTL_STEP_PARTS(dim) * q);
    VECTORS("motion x_from", c->motion.x_from);
    VECTORS("motion x_goal", c->motion.x_goal);
    REAL("motion th_from", c->motion.th_from, rq);
    REAL("motion th_goal", c->motion.th_goal, rq);
#undef REAL
#undef TENSOR
#undef VECTORS
#undef INT
#undef LONG
    return n;
}

size_t sbc_controller_state_size(const sbc_controller *c)
{
    state_field f[STATE_FIELDS];
    const int n = state_fields((sbc_controller *)c, c->ref.X, f); /* read only */
    size_t size = STATE_HEAD(c->frame->dim);
    int k;
    for (k = 0; k < n; ++k)
        size += f[k].count;
    return size;
}

void sbc_controller_save(const sbc_controller *c, double *o)
{
    state_field f[STATE_FIELDS];
    const int n = state_fields((sbc_controller *)c, c->ref.X, f); /* read only */
    const int dim = c->frame->dim;
    int k;
    size_t j;
    *o++ = STATE_VERSION;
    *o++ = c->frame->n;
    *o++ = c->s.bc;
    *o++ = c->s.increments;
    for (k = 0; k < dim * dim; ++k) *o++ = c->s.F[SBC_IJ(k / dim, k % dim)];
    *o++ = c->dt;
    for (k = 0; k < n; ++k)
        for (j = 0; j < f[k].count; ++j) {
            const size_t at = slot(&f[k], j);
            if (f[k].kind == 'i') *o++ = ((const int *)f[k].at)[at];
            else if (f[k].kind == 'l') *o++ = (double)((const long *)f[k].at)[at];
            else if (f[k].kind == 'u') *o++ = ((const unsigned char *)f[k].at)[at];
            else *o++ = ((const double *)f[k].at)[at];
        }
}

/* Reads the fields f [n] from rd. */
static void load_fields(const state_field *f, int n, sbc_saved *rd)
{
    int k;
    size_t j;
    for (k = 0; k < n; ++k)
        for (j = 0; j < f[k].count; ++j) {
            const size_t at = slot(&f[k], j);
            if (f[k].kind == 'i') ((int *)f[k].at)[at] = (int)sbc_saved_int(rd, f[k].name, f[k].lo, f[k].hi);
            else if (f[k].kind == 'l') ((long *)f[k].at)[at] = sbc_saved_int(rd, f[k].name, f[k].lo, f[k].hi);
            else if (f[k].kind == 'u')
                ((unsigned char *)f[k].at)[at] = (unsigned char)sbc_saved_int(rd, f[k].name, f[k].lo, f[k].hi);
            else if (f[k].kind == 'p') ((double *)f[k].at)[at] = sbc_saved_positive(rd, f[k].name);
            else ((double *)f[k].at)[at] = sbc_saved_real(rd, f[k].name);
        }
}

/* What the fields cannot check one by one: the travel's progress, the
 * secant factor and det F, and every saved position within ten frame sizes
 * of the frame's place at creation. */
static sbc_status check_loaded(const sbc_controller *c, const double *ref, sbc_error *err)
{
    const char *what = "servo_bc restart state";
    const sbc_frame *f = c->frame;
    const double *sets[5] = {c->x_cmd, c->x_prev, ref, c->motion.x_from, c->motion.x_goal};
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX}, reach = 0.0;
    const double det = sbc_tensor_det(f->dim, c->F_now);
    int k, d, m;
    if (c->motion.done > c->motion.steps)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: the frame's travel has done %ld of %ld steps", what, c->motion.done,
                        c->motion.steps);
    if (!(c->secant.lambda > 0.0) || !(det > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: secant factor %g or det F %g is not > 0", what, c->secant.lambda,
                        det);
    for (k = 0; k < f->n; ++k)
        for (d = 0; d < f->dim; ++d) {
            lo[d] = fmin(lo[d], f->X[3 * k + d]);
            hi[d] = fmax(hi[d], f->X[3 * k + d]);
        }
    for (d = 0; d < f->dim; ++d)
        reach = fmax(reach, 10.0 * (hi[d] - lo[d]));
    for (m = 0; m < 5; ++m)
        for (k = 0; k < f->n; ++k)
            for (d = 0; d < f->dim; ++d)
                if (fabs(sets[m][3 * k + d] - 0.5 * (lo[d] + hi[d])) > reach)
                    return sbc_fail(err, SBC_ERR_INPUT, "%s: a saved frame position, %.17g m, lies more than ten "
                                    "frame sizes (%g m) from the frame", what, sets[m][3 * k + d], reach);
    return SBC_OK;
}

sbc_status sbc_controller_load(sbc_controller *c, const double *in, size_t n, sbc_error *err)
{
    const char *what = "servo_bc restart state";
    const int dim = c->frame->dim, head = STATE_HEAD(dim);
    int k, q = c->frame->n;
    long saved_q, saved_bc, saved_increments;
    double *ref;
    sbc_saved rd;
    sbc_status st;
    if (n < (size_t)head || in[0] != STATE_VERSION)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: the saved servo_bc state (version %g, %zu values) is not this "
                        "version's (%g)", n > 0 ? in[0] : 0.0, n, STATE_VERSION);
    sbc_saved_start(&rd, in + 1, (size_t)head - 1, what, err);
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
    for (k = 0; k < dim * dim; ++k) {
        const int i = k / dim, j = k % dim;
        char name[8];
        if (in[4 + k] != c->s.F[SBC_IJ(i, j)])
            return sbc_fail(err, SBC_ERR_INPUT, "restart: keyword 'F': %s = %.17g contradicts the saved %.17g",
                            sbc_tensor_component_name("F", i, j, name), c->s.F[SBC_IJ(i, j)], in[4 + k]);
    }
    /* the gains scale with dt^2 (eq. 37): a host that forgets the time step
       across a restart (LIGGGHTS 3.8 does) would servo with other gains */
    if (in[head - 1] != c->dt)
        return sbc_fail(err, SBC_ERR_INPUT, "restart: time step %.17g s contradicts the saved %.17g s (set the time "
                        "step before the fix)", c->dt, in[head - 1]);
    /* the reference X: checked with the rest, set after every check */
    if (!(ref = calloc(3 * (size_t)q, sizeof(double))))
        return sbc_fail(err, SBC_ERR_NOMEM, "%s: out of memory", what);
    sbc_saved_start(&rd, in + head, n - (size_t)head, what, err);
    c->relax.criterion = c->s.criterion;
    c->relax.window = c->s.window;
    {
        state_field f[STATE_FIELDS];
        load_fields(f, state_fields(c, ref, f), &rd);
    }
    st = rd.st != SBC_OK ? rd.st : check_loaded(c, ref, err);
    if (st == SBC_OK) {
        sbc_ctl_new_reference(c, ref);
        if (c->s.bc == SBC_BC_MIXED)
            sbc_ctl_mixed_stress_targets(c);
    }
    free(ref);
    return st;
}
