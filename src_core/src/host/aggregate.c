/* The embedded engines as an aggregate's operations (aggregate.h), and the
 * host steps of one increment. */
#include "aggregate.h"
#include "condensed.h"

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
static const double *discs_centres(const void *e) { return sbc_engine_get_view(e).x; }
static const double *discs_radii(const void *e) { return sbc_engine_get_view(e).r; }

const sbc_engine_ops sbc_engine_ops_discs = {2, discs_create, discs_free, discs_set_frame, discs_seal, discs_callbacks,
                                   discs_forces,
                                   discs_move, discs_masses, discs_dt, discs_size, discs_save, discs_load,
                                   discs_pairs, discs_pair, discs_centres, discs_radii};

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

const sbc_engine_ops sbc_engine_ops_spheres = {3, spheres_create, spheres_free, spheres_set_frame, spheres_seal,
                                     spheres_callbacks,
                                     spheres_forces, spheres_move, spheres_masses, spheres_dt, spheres_size,
                                     spheres_save, spheres_load, spheres_pairs, spheres_pair, spheres_centres,
                                     spheres_radii};

sbc_status sbc_aggregate_network(const sbc_aggregate *a, sbc_network *net, int **ij, double **fs, sbc_error *err)
{
    const int npair = a->ops->pair_count(a->engine);
    int k;
    *ij = NULL;
    *fs = NULL;
    if (a->bonded)
        return sbc_fail(err, SBC_ERR_INPUT, "contact network: the contacts are linearized by eq. 6 alone; this "
                        "aggregate's cohesive bonds (eqs. 7-8) are not (use the perturbation tangent)");
    *ij = malloc(sizeof **ij * 2 * (size_t)(npair > 0 ? npair : 1));
    *fs = malloc(sizeof **fs * 3 * (size_t)(npair > 0 ? npair : 1));
    if (!*ij || !*fs)
        return sbc_fail(err, SBC_ERR_NOMEM, "contact network: out of memory for %d pairs", npair);
    for (k = 0; k < npair; ++k) {
        int pair[2];
        a->ops->pair(a->engine, k, pair, &(*fs)[3 * k]);
        (*ij)[k] = pair[0];
        (*ij)[npair + k] = pair[1];
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
    return cb;
}

sbc_event sbc_aggregate_run_increment(const sbc_aggregate *a, sbc_controller *ctl, sbc_driver *driver, int first,
                                      sbc_error *err)
{
    for (;;) {
        sbc_event ev;
        if (!first) {
            sbc_commands cmd = sbc_controller_commands(ctl);
            a->ops->move_frame(a->engine, &cmd);
            if (a->ops->forces(a->engine, err) != SBC_OK)
                return SBC_EVENT_FAILED;
        }
        first = 0;
        ev = sbc_driver_step(driver, 0, err);
        if (ev == SBC_EVENT_FAILED || ev == SBC_EVENT_FINISHED || ev == SBC_EVENT_INCREMENT)
            return ev;
    }
}
