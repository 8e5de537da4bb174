/* The embedded engines as an aggregate's operations (aggregate.h), and the
 * host steps of one increment. */
#include "aggregate.h"
#include "condensed.h"
#include "statics.h"

#include "sbc/embedded/engine.h"
#include "sbc/embedded/spheres.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void *discs_create(const sbc_point_def *d, const sbc_settings *s, sbc_error *err)
{
    sbc_engine_def e = sbc_engine_def_default();
    e.n = d->n;
    e.x = d->x;
    e.r = d->r;
    e.density = d->density;
    e.law = d->law;
    e.bonds = d->bonds;
    e.dt = d->dt;
    e.alpha = s->damping ? s->alpha : 0.0;
    e.beta = s->damping ? s->beta : 0.0;
    e.fire = s->damping == SBC_DAMPING_FIRE;
    return sbc_engine_create(&e, err);
}
static void discs_free(void *e) { sbc_engine_free(e); }
static void discs_set_frame(void *e, const sbc_frame *f) { sbc_engine_set_frame(e, f); }
static sbc_status discs_seal(void *e, sbc_error *err) { return sbc_engine_seal(e, err); }
static sbc_driver_callbacks discs_callbacks(void *e) { return sbc_engine_callbacks(e); }
static sbc_status discs_forces(void *e, sbc_error *err) { return sbc_engine_forces(e, err); }
static void discs_move(void *e, const sbc_commands *cmd) { sbc_engine_move_frame(e, cmd); }
static void discs_masses(const void *e, double *mass) { sbc_engine_frame_masses(e, mass); }
static double discs_dt(const void *e) { return sbc_engine_critical_dt(e); }
static size_t discs_size(const void *e) { return sbc_engine_state_size(e); }
static void discs_save(const void *e, double *out) { sbc_engine_save(e, out); }
static sbc_status discs_load(void *e, const double *in, size_t n, sbc_error *err) { return sbc_engine_load(e, in, n, err); }
static int discs_pairs(const void *e) { return sbc_engine_get_view(e).pair_count; }
static void discs_pair(const void *e, int k, int ij[2], double fs[3])
{
    const sbc_engine_view w = sbc_engine_get_view(e);
    const double *a = &w.x[2 * w.pair_i[k]], *b = &w.x[2 * w.pair_j[k]];
    const double lx = b[0] - a[0], ly = b[1] - a[1], d = sqrt(lx * lx + ly * ly);
    const double s = w.pair_fs && d > 0.0 ? w.pair_fs[k] / d : 0.0;
    ij[0] = w.pair_i[k];
    ij[1] = w.pair_j[k];
    fs[0] = -s * ly; /* the engine's force on i is -fn n + fs t, t = (-n_y, n_x) */
    fs[1] = s * lx;
    fs[2] = 0.0;
}
static int discs_bond(const void *e, int k, double *m)
{
    const sbc_engine_view w = sbc_engine_get_view(e);
    *m = w.pair_bond && w.pair_bond[k] ? w.pair_m[k] : 0.0;
    return w.pair_bond && w.pair_bond[k];
}
static const double *discs_centres(const void *e) { return sbc_engine_get_view(e).x; }
static const double *discs_radii(const void *e) { return sbc_engine_get_view(e).r; }
static const double *discs_rotations(const void *e) { return sbc_engine_get_view(e).theta; }
static sbc_status discs_place(void *e, const double *x, const double *theta, const double *records, int count,
                              sbc_error *err)
{
    sbc_engine_place(e, x, theta);
    return sbc_engine_set_pair_records(e, records, count, sbc_engine_get_view(e).bonds_initial, err);
}

const sbc_engine_ops sbc_engine_ops_discs = {2, discs_create, discs_free, discs_set_frame, discs_seal, discs_callbacks,
                                   discs_forces,
                                   discs_move, discs_masses, discs_dt, discs_size, discs_save, discs_load,
                                   discs_pairs, discs_pair, discs_centres, discs_radii, discs_rotations,
                                   discs_bond, discs_place};

static void *spheres_create(const sbc_point_def *d, const sbc_settings *s, sbc_error *err)
{
    sbc_spheres_def e = sbc_spheres_def_default();
    e.n = d->n;
    e.x = d->x;
    e.r = d->r;
    e.density = d->density;
    e.law = d->law;
    e.dt = d->dt;
    e.alpha = s->damping ? s->alpha : 0.0;
    e.beta = s->damping ? s->beta : 0.0;
    e.fire = s->damping == SBC_DAMPING_FIRE;
    return sbc_spheres_create(&e, err);
}
static void spheres_free(void *e) { sbc_spheres_free(e); }
static void spheres_set_frame(void *e, const sbc_frame *f) { sbc_spheres_set_frame(e, f); }
static sbc_status spheres_seal(void *e, sbc_error *err) { return sbc_spheres_seal(e, err); }
static sbc_driver_callbacks spheres_callbacks(void *e) { return sbc_spheres_callbacks(e); }
static sbc_status spheres_forces(void *e, sbc_error *err) { return sbc_spheres_forces(e, err); }
static void spheres_move(void *e, const sbc_commands *cmd) { sbc_spheres_move_frame(e, cmd); }
static void spheres_masses(const void *e, double *mass) { sbc_spheres_frame_masses(e, mass); }
static double spheres_dt(const void *e) { return sbc_spheres_critical_dt(e); }
static size_t spheres_size(const void *e) { return sbc_spheres_state_size(e); }
static void spheres_save(const void *e, double *out) { sbc_spheres_save(e, out); }
static sbc_status spheres_load(void *e, const double *in, size_t n, sbc_error *err)
{
    return sbc_spheres_load(e, in, n, err);
}
static int spheres_pairs(const void *e) { return sbc_spheres_get_view(e).pair_count; }
static void spheres_pair(const void *e, int k, int ij[2], double fs[3]) { sbc_spheres_pair(e, k, ij, fs); }
static const double *spheres_centres(const void *e) { return sbc_spheres_get_view(e).x; }
static const double *spheres_radii(const void *e) { return sbc_spheres_get_view(e).r; }
static const double *spheres_rotations(const void *e) { return sbc_spheres_get_view(e).theta; }
static sbc_status spheres_place(void *e, const double *x, const double *theta, const double *records, int count,
                                sbc_error *err)
{
    return sbc_spheres_place(e, x, theta, records, count, err);
}

const sbc_engine_ops sbc_engine_ops_spheres = {3, spheres_create, spheres_free, spheres_set_frame, spheres_seal,
                                     spheres_callbacks,
                                     spheres_forces, spheres_move, spheres_masses, spheres_dt, spheres_size,
                                     spheres_save, spheres_load, spheres_pairs, spheres_pair, spheres_centres,
                                     spheres_radii, spheres_rotations, NULL, spheres_place};

sbc_status sbc_aggregate_network(const sbc_aggregate *a, sbc_network *net, int **ij, double **fs, sbc_error *err)
{
    const int npair = a->ops->pair_count(a->engine);
    int k;
    const int bonded = a->bonds && a->ops->bond;
    double m;
    *ij = NULL;
    *fs = NULL;
    *ij = malloc(sizeof **ij * (bonded ? 3 : 2) * (size_t)(npair > 0 ? npair : 1));
    *fs = malloc(sizeof **fs * 3 * (size_t)(npair > 0 ? npair : 1));
    if (!*ij || !*fs)
        return sbc_fail(err, SBC_ERR_NOMEM, "contact network: out of memory for %d pairs", npair);
    for (k = 0; k < npair; ++k) {
        int pair[2];
        a->ops->pair(a->engine, k, pair, &(*fs)[3 * k]);
        (*ij)[k] = pair[0];
        (*ij)[npair + k] = pair[1];
        if (bonded)
            (*ij)[2 * npair + k] = a->ops->bond(a->engine, k, &m);
    }
    memset(net, 0, sizeof *net);
    net->dim = a->frame->dim;
    net->n = a->n;
    net->x = a->ops->centres(a->engine);
    net->r = a->ops->radii(a->engine);
    net->npair = npair;
    net->i = *ij;
    net->j = *ij + npair;
    net->fs = *fs;
    net->law = a->law;
    if (bonded) {
        net->bond = *ij + 2 * npair;
        net->kr = a->bonds->kr;
    }
    net->frame_rotation_zero = a->settings->bc == SBC_BC_T && a->settings->rotation_zero;
    return SBC_OK;
}

int sbc_aggregate_newton(void *aggregate, const double *reaction, const double *moment, double *du, double *dtheta,
                         char *message, size_t cap)
{
    const sbc_aggregate *a = aggregate;
    int *ij = NULL, mechanisms;
    double *fs = NULL;
    sbc_network net;
    sbc_error err;
    sbc_status st;
    sbc_error_clear(&err);
    if ((st = sbc_aggregate_network(a, &net, &ij, &fs, &err)) == SBC_OK)
        st = sbc_condensed_correction(&net, a->frame, a->settings->bc, reaction, moment, du, dtheta, &mechanisms,
                                      &err);
    free(ij);
    free(fs);
    if (st != SBC_OK)
        snprintf(message, cap, "%s", err.message);
    return st;
}

sbc_driver_callbacks sbc_aggregate_callbacks(const sbc_aggregate *a)
{
    sbc_driver_callbacks cb = a->ops->callbacks(a->engine);
    cb.newton = sbc_aggregate_newton;
    cb.newton_data = (void *)a; /* read only: the callback takes a const aggregate */
    cb.solves_interior = a->ops->place && a->tally;
    return cb;
}

/* 1 when the commands move a frame particle or turn a held rotation */
static int frame_moves(const sbc_aggregate *a, const sbc_commands *cmd)
{
    const sbc_frame *f = a->frame;
    const int rd = SBC_ROTATIONS(f->dim);
    const double *x = a->ops->centres(a->engine), *theta = a->ops->rotations(a->engine);
    int q, k;
    for (q = 0; q < f->n; ++q) {
        const int p = f->particle[q];
        for (k = 0; k < f->dim; ++k)
            if (cmd->x[3 * q + k] != x[f->dim * p + k])
                return 1;
        for (k = 0; k < rd && !cmd->free_rotation[q]; ++k)
            if (cmd->theta[rd * q + k] != theta[rd * p + k])
                return 1;
    }
    return 0;
}

/* 2D: each committed spring fv [3 npair] (the force on i) as statics.h reads it, its component along
   t = (-l_y, l_x) / |l| of the committed branch l (N), into fs0 [npair] */
static void springs_along_t(const double *x0, int npair, const int *i0, const int *j0, const double *fv, double *fs0)
{
    int k;
    for (k = 0; k < npair; ++k) {
        const double *xa = &x0[2 * i0[k]], *xb = &x0[2 * j0[k]];
        const double lx = xb[0] - xa[0], ly = xb[1] - xa[1], d = sqrt(lx * lx + ly * ly);
        fs0[k] = d > 0.0 ? (-fv[3 * k] * ly + fv[3 * k + 1] * lx) / d : 0.0;
    }
}

/* The frame where the solve put it, as the controller's commands */
static sbc_status adopt_frame(const sbc_aggregate *a, sbc_controller *ctl, const double *x, const double *th,
                              sbc_error *err)
{
    const sbc_frame *f = a->frame;
    const int dim = f->dim, rd = SBC_ROTATIONS(dim);
    double *xq = calloc(3 * (size_t)f->n, sizeof *xq), *tq = calloc((size_t)(rd * f->n), sizeof *tq);
    int q, k;
    if (!xq || !tq) {
        free(xq);
        free(tq);
        return sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for a frame of %d", f->n);
    }
    for (q = 0; q < f->n; ++q) {
        for (k = 0; k < dim; ++k)
            xq[3 * q + k] = x[dim * f->particle[q] + k];
        for (k = 0; k < rd; ++k)
            tq[rd * q + k] = th[rd * f->particle[q] + k];
    }
    sbc_controller_adopt(ctl, xq, tq);
    free(xq);
    free(tq);
    return SBC_OK;
}

static void tally_solve(sbc_statics_tally *t, const sbc_statics_result *res)
{
    t->iterations += res->iterations;
    t->solves++;
    t->retried += res->converged && res->substeps > 0;
    t->mechanisms = res->mechanisms;
    t->residual = res->residual;
    t->broken += res->broken;
    if (!res->converged) {
        t->unconverged++;
        t->fallback = 1;
        snprintf(t->why, sizeof t->why, "%s", res->why);
    }
}

/* interior newton: the frame moved by cmd from the committed state (x0, theta0, the engine's pairs), the
   interior solved there and the engine placed at the solution (statics.h) */
static sbc_status solve_interior(const sbc_aggregate *a, sbc_controller *ctl, const sbc_commands *cmd,
                                 sbc_error *err)
{
    const sbc_frame *f = a->frame;
    const int n = a->n, dim = f->dim, rd = SBC_ROTATIONS(dim);
    const int history = sbc_frictional_has_history(&a->law) || a->bonds; /* bonds imply history, as engine.c */
    const size_t nx = (size_t)(dim * n), nt = (size_t)(rd * n);
    double *x0 = malloc(sizeof(double) * nx), *th0 = malloc(sizeof(double) * nt);
    double *x = malloc(sizeof(double) * nx), *th = malloc(sizeof(double) * nt), *fv = NULL, *fs0 = NULL;
    int *ij0 = NULL; /* the committed pairs: i0 [npair], then j0, with bonds their flags */
    unsigned char *mode = NULL;
    sbc_network committed;
    sbc_statics_problem p;
    sbc_statics_result res;
    sbc_status st = SBC_OK;
    memset(&res, 0, sizeof res);
    if (!x0 || !th0 || !x || !th) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d particles", n);
        goto done;
    }
    if (a->settings->bc == SBC_BC_MIXED) { /* D and P components; a T one held at its command, the servo's */
        int k;
        if (!(mode = calloc(3 * (size_t)f->n, 1))) { /* 2D: the third of each three left D */
            st = sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for a frame of %d", f->n);
            goto done;
        }
        sbc_mixed_modes(f, a->settings, mode);
        for (k = 0; k < 3 * f->n; ++k)
            if (mode[k] == SBC_MODE_T)
                mode[k] = SBC_MODE_D;
    }
    if ((st = sbc_aggregate_network(a, &committed, &ij0, &fv, err)) != SBC_OK)
        goto done;
    memcpy(x0, committed.x, sizeof(double) * nx);
    memcpy(th0, a->ops->rotations(a->engine), sizeof(double) * nt);
    fs0 = fv; /* 3D: the spring vectors as they are */
    if (dim == 2) { /* the springs along t [npair], then with bonds their moments [npair] */
        int k;
        if (!(fs0 = malloc(sizeof(double) * 2 * (size_t)(committed.npair > 0 ? committed.npair : 1)))) {
            st = sbc_fail(err, SBC_ERR_NOMEM, "interior newton: out of memory for %d pairs", committed.npair);
            goto done;
        }
        springs_along_t(x0, committed.npair, committed.i, committed.j, fv, fs0);
        for (k = 0; committed.bond && k < committed.npair; ++k)
            a->ops->bond(a->engine, k, &fs0[committed.npair + k]);
    }
    a->ops->move_frame(a->engine, cmd);
    memcpy(x, a->ops->centres(a->engine), sizeof(double) * nx);
    memcpy(th, a->ops->rotations(a->engine), sizeof(double) * nt);
    memset(&p, 0, sizeof p);
    p.dim = dim;
    p.n = n;
    p.r = a->ops->radii(a->engine);
    p.law = a->law;
    p.frame = f;
    p.x0 = x0;
    p.theta0 = th0;
    p.npair0 = committed.npair;
    p.bc = a->settings->bc;
    p.rotation_zero = a->settings->rotation_zero;
    p.mode = mode;
    p.free_rotation = mode ? cmd->free_rotation : NULL;
    p.tol = SBC_STATICS_TOL;
    p.max_iterations = SBC_STATICS_ITERATIONS;
    p.fs0 = history ? fs0 : NULL;
    p.i0 = committed.i;
    p.j0 = committed.j;
    if (committed.bond) {
        p.bonds = a->bonds;
        p.bond0 = committed.bond;
        p.m0 = fs0 + committed.npair;
    }
    st = sbc_statics_solve(&p, x, th, &res, err);
    if (st == SBC_OK)
        st = a->ops->place(a->engine, x, th, res.records, history ? res.contacts : 0, err); /* no springs without friction */
    if (st == SBC_OK && a->settings->bc != SBC_BC_D)
        st = adopt_frame(a, ctl, x, th, err);
    if (st == SBC_OK)
        tally_solve(a->tally, &res);
done:
    sbc_statics_result_free(&res);
    free(x0);
    free(th0);
    free(x);
    free(th);
    if (fs0 != fv)
        free(fs0);
    free(fv);
    free(ij0);
    free(mode);
    return st;
}

sbc_status sbc_aggregate_advance(const sbc_aggregate *a, sbc_controller *ctl, int settle, sbc_error *err)
{
    sbc_commands cmd = sbc_controller_commands(ctl);
    sbc_status st;
    if (a->tally && !a->tally->fallback && (settle || frame_moves(a, &cmd)))
        st = solve_interior(a, ctl, &cmd, err);
    else {
        a->ops->move_frame(a->engine, &cmd);
        st = SBC_OK;
    }
    return st == SBC_OK ? a->ops->forces(a->engine, err) : st;
}

sbc_event sbc_aggregate_run_increment(const sbc_aggregate *a, sbc_controller *ctl, sbc_driver *driver, int first,
                                      sbc_error *err)
{
    if (a->tally)
        a->tally->fallback = 0; /* each increment starts with the static solves */
    for (;;) {
        sbc_event ev;
        if (!first && sbc_aggregate_advance(a, ctl, 0, err) != SBC_OK)
            return SBC_EVENT_FAILED;
        first = 0;
        ev = sbc_driver_step(driver, 0, err);
        if (ev == SBC_EVENT_FAILED || ev == SBC_EVENT_FINISHED || ev == SBC_EVENT_INCREMENT)
            return ev;
    }
}
