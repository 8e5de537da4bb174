/* servo_bc: the aggregate as a material point (material_point.h): the
 * embedded engine, its frame and the controller behind one F -> P call, with
 * the committed state kept as doubles. */
#include "sbc/material_point.h"

#include "condensed.h"
#include "sbc/controller.h"
#include "sbc/driver.h"
#include "sbc/embedded/engine.h"
#include "sbc/embedded/spheres.h"
#include "sbc/frame.h"
#include "sbc/packing.h"
#include "sbc/saved.h"
#include "sbc/settings.h"
#include "sbc/time_step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define POINT_STATE_VERSION 1.0

/* The engine behind a point, by dimension (as GSL's step types): the 2D
 * disc engine or the 3D sphere engine, through the same operations. */
typedef struct point_engine {
    int dim;
    void *(*create)(const sbc_point_def *d, const sbc_settings *s, sbc_error *err);
    void (*free)(void *e);
    void (*set_frame)(void *e, const sbc_frame *f);
    sbc_driver_callbacks (*callbacks)(void *e);
    sbc_status (*forces)(void *e, sbc_error *err);
    void (*move_frame)(void *e, const sbc_commands *cmd);
    void (*frame_masses)(const void *e, double *mass);
    double (*critical_dt)(const void *e);
    size_t (*state_size)(const void *e);
    void (*save)(const void *e, double *out);
    sbc_status (*load)(void *e, const double *in, size_t n, sbc_error *err);
    /* the pairs for the affine tangent: their count, pair k's particles and |tangential spring| (N),
       the centres [dim n] and radii */
    int (*pair_count)(const void *e);
    void (*pair)(const void *e, int k, int ij[2], double fs[3]); /* fs: the tangential spring's force on ij[0], N */
    const double *(*centres)(const void *e);
    const double *(*radii)(const void *e);
} point_engine;

static void *discs_create(const sbc_point_def *d, const sbc_settings *s, sbc_error *err)
{
    sbc_engine_def e = sbc_engine_def_default();
    e.n = d->n;
    e.x = d->x;
    e.r = d->r;
    e.density = d->density;
    e.law = d->law;
    e.dt = d->dt;
    e.alpha = s->damping ? s->alpha : 0.0;
    e.beta = s->damping ? s->beta : 0.0;
    e.fire = s->damping == SBC_DAMPING_FIRE;
    return sbc_engine_create(&e, err);
}
static void discs_free(void *e) { sbc_engine_free(e); }
static void discs_set_frame(void *e, const sbc_frame *f) { sbc_engine_set_frame(e, f); }
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

static const point_engine discs = {2, discs_create, discs_free, discs_set_frame, discs_callbacks, discs_forces,
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

static const point_engine spheres = {3, spheres_create, spheres_free, spheres_set_frame, spheres_callbacks,
                                     spheres_forces, spheres_move, spheres_masses, spheres_dt, spheres_size,
                                     spheres_save, spheres_load, spheres_pairs, spheres_pair, spheres_centres,
                                     spheres_radii};

struct sbc_point {
    const point_engine *type;
    sbc_settings settings;
    sbc_frame frame;
    void *engine;
    sbc_controller *ctl;
    sbc_driver *driver;
    double *mass;          /* [Q] kg */
    double *committed;     /* [size] the committed state (sbc_point_save's layout) */
    size_t size;
    int at_committed;      /* the engine and the controller hold the committed state */
    double F[9], P[9];     /* committed */
    double Fc[9], Pc[9];   /* current: of the last converged integrate since commit or revert, else F, P */
    sbc_frictional law; /* the contact law (eq. 6), for the affine tangent */
    int n;                 /* particles */
};

sbc_point_def sbc_point_def_default(void)
{
    sbc_point_def d;
    const sbc_engine_def e = sbc_engine_def_default();
    memset(&d, 0, sizeof d);
    d.dim = 2;
    d.words = "D";
    d.law = e.law;
    d.density = e.density;
    d.dt = e.dt;
    return d;
}

void sbc_point_free(sbc_point *p)
{
    if (!p)
        return;
    sbc_driver_free(p->driver);
    sbc_controller_free(p->ctl);
    if (p->engine)
        p->type->free(p->engine);
    sbc_frame_free(&p->frame);
    free(p->mass);
    free(p->committed);
    free(p);
}

/* the words a point takes: a BC of (D), (P), (T) and its keywords; the path
   (F, increments, stress, file) is the point's */
static sbc_status point_words(sbc_settings *s, const sbc_point_def *d, sbc_error *err)
{
    double I[9];
    int k;
    if (d->dim != 2 && d->dim != 3)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: dimension %d (expected 2 or 3)", d->dim);
    if (sbc_settings_parse_words(s, d->words, err) != SBC_OK ||
        sbc_settings_check_dimension(s, d->dim, err) != SBC_OK)
        return err->status;
    sbc_tensor_identity(d->dim, I);
    for (k = 0; k < 9; ++k)
        if (s->F[k] != I[k])
            return sbc_fail(err, SBC_ERR_INPUT, "material point: keyword 'F' is the FE code's (each integrate gives "
                            "it); leave it out of the words");
    if (s->bc == SBC_BC_MIXED || s->nstress > 0 || s->increments != 1 || s->file[0])
        return sbc_fail(err, SBC_ERR_INPUT, "material point: words '%s': mixed, stress, increments and file are the "
                        "path's, which the FE code gives; expected D, P or T and their keywords", d->words);
    return SBC_OK;
}

/* steps until the controller accepts an increment or fails */
static sbc_event run_increment(sbc_point *p, int first, sbc_error *err)
{
    for (;;) {
        sbc_event ev;
        if (!first) {
            sbc_commands cmd = sbc_controller_commands(p->ctl);
            p->type->move_frame(p->engine, &cmd);
            if (p->type->forces(p->engine, err) != SBC_OK)
                return SBC_EVENT_FAILED;
        }
        first = 0;
        ev = sbc_driver_step(p->driver, 0, err);
        if (ev == SBC_EVENT_FAILED || ev == SBC_EVENT_FINISHED)
            return ev;
    }
}

size_t sbc_point_state_size(const sbc_point *p) { return p->size; }

/* the current state into out (sbc_point_save's layout) */
static void save_current(const sbc_point *p, const double F[9], const double P[9], double *out)
{
    const size_t ne = p->type->state_size(p->engine), nc = sbc_controller_state_size(p->ctl);
    sbc_fire_state *fire = sbc_driver_fire(p->driver);
    *out++ = POINT_STATE_VERSION;
    *out++ = (double)ne;
    p->type->save(p->engine, out);
    out += ne;
    *out++ = (double)nc;
    sbc_controller_save(p->ctl, out);
    out += nc;
    *out++ = fire->alpha;
    *out++ = (double)fire->positive;
    memcpy(out, F, sizeof(double) * 9);
    memcpy(out + 9, P, sizeof(double) * 9);
}

/* in [n] into the engine, the controller, FIRE, F and P */
static sbc_status load_state(sbc_point *p, const double *in, size_t n, double F[9], double P[9], sbc_error *err)
{
    const size_t ne = p->type->state_size(p->engine), nc = sbc_controller_state_size(p->ctl);
    sbc_fire_state *fire = sbc_driver_fire(p->driver);
    sbc_saved s;
    size_t at;
    int k;
    if (n != p->size || in[0] != POINT_STATE_VERSION || in[1] != (double)ne || in[2 + ne] != (double)nc)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state (%zu values, version %g) is not one of "
                        "this point (%zu values, version %g)", n, n > 0 ? in[0] : 0.0, p->size, POINT_STATE_VERSION);
    if (p->type->load(p->engine, in + 2, ne, err) != SBC_OK ||
        sbc_controller_load(p->ctl, in + 3 + ne, nc, err) != SBC_OK)
        return err->status;
    at = 3 + ne + nc;
    sbc_saved_start(&s, in + at, n - at, "material point state", err);
    fire->alpha = sbc_saved_real(&s, "FIRE alpha");
    fire->positive = sbc_saved_int(&s, "FIRE steps", 0, 1L << 52);
    for (k = 0; k < 9; ++k)
        F[k] = sbc_saved_real(&s, "F");
    for (k = 0; k < 9; ++k)
        P[k] = sbc_saved_real(&s, "P");
    return s.st;
}

void sbc_point_commit(sbc_point *p)
{
    memcpy(p->F, p->Fc, sizeof p->F);
    memcpy(p->P, p->Pc, sizeof p->P);
    save_current(p, p->F, p->P, p->committed);
    p->at_committed = 1;
}

void sbc_point_revert(sbc_point *p)
{
    sbc_error err;
    double F[9], P[9];
    if (p->at_committed)
        return;
    /* a state this point saved itself: it loads */
    load_state(p, p->committed, p->size, F, P, &err);
    memcpy(p->Fc, p->F, sizeof p->F);
    memcpy(p->Pc, p->P, sizeof p->P);
    p->at_committed = 1;
}

void sbc_point_committed(const sbc_point *p, double F[9], double P[9])
{
    memcpy(F, p->F, sizeof p->F);
    memcpy(P, p->P, sizeof p->P);
}

void sbc_point_save(const sbc_point *p, double *out) { memcpy(out, p->committed, sizeof(double) * p->size); }

sbc_status sbc_point_load(sbc_point *p, const double *in, size_t n, sbc_error *err)
{
    double F[9], P[9];
    if (load_state(p, in, n, F, P, err) != SBC_OK) {
        p->at_committed = 0;
        sbc_point_revert(p);
        return err->status;
    }
    memcpy(p->committed, in, sizeof(double) * n);
    memcpy(p->F, F, sizeof F);
    memcpy(p->P, P, sizeof P);
    memcpy(p->Fc, F, sizeof F);
    memcpy(p->Pc, P, sizeof P);
    p->at_committed = 1;
    return SBC_OK;
}

sbc_point *sbc_point_create(const sbc_point_def *d, sbc_error *err)
{
    sbc_point *p = calloc(1, sizeof *p);
    sbc_packing pk;
    sbc_driver_callbacks cb;
    sbc_status st;
    if (!p) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        return NULL;
    }
    if (point_words(&p->settings, d, err) != SBC_OK || !d->x || !d->r || d->n < 4) {
        if (err->status == SBC_OK)
            sbc_fail(err, SBC_ERR_INPUT, "material point: %d particles given (a frame needs at least 4)", d->n);
        sbc_point_free(p);
        return NULL;
    }
    p->type = d->dim == 3 ? &spheres : &discs;
    p->law = d->law;
    p->n = d->n;
    if (d->dim == 3) {
        st = sbc_frame_detect_3d(&p->frame, d->n, d->x, d->r, 0.0, err);
    } else {
        memset(&pk, 0, sizeof pk);
        pk.n = d->n;
        pk.x = (double *)d->x; /* read only */
        pk.r = (double *)d->r;
        if (d->box) {
            pk.has_box = 1;
            memcpy(pk.box, d->box, sizeof pk.box);
        }
        st = sbc_packing_distinct(d->n, d->x, d->r, err);
        if (st == SBC_OK)
            st = sbc_frame_detect_packing(&p->frame, &pk, err);
    }
    if (st != SBC_OK || !(p->engine = p->type->create(d, &p->settings, err)) ||
        sbc_time_step_bound(d->dt, p->type->critical_dt(p->engine), "2 sqrt(M_min / (2 kn))",
                            p->settings.max_relax_steps, err) != SBC_OK) {
        sbc_point_free(p);
        return NULL;
    }
    p->type->set_frame(p->engine, &p->frame);
    if (!(p->mass = malloc(sizeof(double) * (size_t)p->frame.n))) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        sbc_point_free(p);
        return NULL;
    }
    p->type->frame_masses(p->engine, p->mass);
    cb = p->type->callbacks(p->engine);
    if (!(p->ctl = sbc_controller_create(&p->frame, &p->settings, p->mass, d->dt, d->law.kn, err)) ||
        !(p->driver = sbc_driver_create(p->ctl, &p->settings, &cb, err)) ||
        p->type->forces(p->engine, err) != SBC_OK || run_increment(p, 1, err) != SBC_EVENT_FINISHED) {
        sbc_point_free(p);
        return NULL;
    }
    p->size = 2 + p->type->state_size(p->engine) + 1 + sbc_controller_state_size(p->ctl) + 2 + 18;
    if (!(p->committed = malloc(sizeof(double) * p->size))) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        sbc_point_free(p);
        return NULL;
    }
    memcpy(p->Fc, sbc_controller_result(p->ctl)->F, sizeof p->Fc);
    memcpy(p->Pc, sbc_controller_result(p->ctl)->P, sizeof p->Pc);
    sbc_point_commit(p);
    return p;
}

sbc_point_status sbc_point_integrate(sbc_point *p, const double F[9], double P[9], double *step_ratio,
                                     sbc_error *err)
{
    sbc_point_revert(p);
    *step_ratio = 0.5;
    memset(P, 0, sizeof(double) * 9);
    if (sbc_controller_aim(p->ctl, F, err) != SBC_OK)
        return SBC_POINT_FAILED;
    sbc_driver_remap(p->driver);
    p->at_committed = 0;
    if (run_increment(p, 0, err) != SBC_EVENT_FINISHED) {
        sbc_point_revert(p);
        return SBC_POINT_FAILED;
    }
    memcpy(p->Fc, sbc_controller_result(p->ctl)->F, sizeof p->Fc);
    memcpy(p->Pc, sbc_controller_result(p->ctl)->P, sizeof p->Pc);
    memcpy(P, p->Pc, sizeof(double) * 9);
    *step_ratio = 1.0;
    return SBC_POINT_CONVERGED;
}

sbc_status sbc_point_tangent_perturbation(sbc_point *p, double h, double C[81], sbc_error *err)
{
    const int dim = p->frame.dim;
    double F0[9], Pc[9], F[9], P[2][9], ratio, *current = NULL;
    int k, l, side, ij;
    sbc_status st = SBC_OK;
    memset(C, 0, sizeof(double) * 81);
    if (!(h > 0.0) || !isfinite(h))
        return sbc_fail(err, SBC_ERR_INPUT, "material point: perturbation step %g is not positive", h);
    memcpy(F0, p->Fc, sizeof F0);
    memcpy(Pc, p->Pc, sizeof Pc);
    if (!p->at_committed) { /* the current state comes back afterwards */
        if (!(current = malloc(sizeof(double) * p->size)))
            return sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        save_current(p, F0, Pc, current);
    }
    for (k = 0; k < dim && st == SBC_OK; ++k)
        for (l = 0; l < dim && st == SBC_OK; ++l) {
            for (side = 0; side < 2 && st == SBC_OK; ++side) {
                memcpy(F, F0, sizeof F);
                F[SBC_IJ(k, l)] += side ? -h : h;
                if (sbc_point_integrate(p, F, P[side], &ratio, err) != SBC_POINT_CONVERGED)
                    st = err->status;
            }
            for (ij = 0; ij < 9 && st == SBC_OK; ++ij) /* eq. 23's P at F + h e_kl and F - h e_kl */
                C[9 * ij + SBC_IJ(k, l)] = (P[0][ij] - P[1][ij]) / (2.0 * h);
        }
    sbc_point_revert(p);
    if (current) { /* a state this point saved itself: it loads */
        sbc_error ignored;
        double Fs[9], Ps[9];
        load_state(p, current, p->size, Fs, Ps, &ignored);
        memcpy(p->Fc, F0, sizeof F0);
        memcpy(p->Pc, Pc, sizeof Pc);
        p->at_committed = 0;
        free(current);
    }
    if (st != SBC_OK)
        memset(C, 0, sizeof(double) * 81);
    return st;
}

sbc_status sbc_point_tangent_affine(sbc_point *p, double C[81], sbc_error *err)
{
    const int dim = p->frame.dim, npair = p->type->pair_count(p->engine);
    const double *x = p->type->centres(p->engine), *r = p->type->radii(p->engine);
    const sbc_frictional *law = &p->law;
    double Finv[9];
    int c, i, j, k, l;
    memset(C, 0, sizeof(double) * 81);
    if (!sbc_tensor_inverse(dim, p->Fc, Finv))
        return sbc_fail(err, SBC_ERR_GEOMETRY, "material point: the current F cannot be inverted");
    for (c = 0; c < npair; ++c) {
        double lv[3] = {0, 0, 0}, L[3], n[3] = {0, 0, 0}, K[9], len = 0.0, dn, fv[3], fs;
        int ij[2], stick;
        p->type->pair(p->engine, c, ij, fv);
        fs = sqrt(fv[0] * fv[0] + fv[1] * fv[1] + fv[2] * fv[2]);
        for (k = 0; k < dim; ++k) {
            lv[k] = x[dim * ij[1] + k] - x[dim * ij[0] + k];
            len += lv[k] * lv[k];
        }
        len = sqrt(len);
        dn = r[ij[0]] + r[ij[1]] - len;
        if (!(dn > 0.0))
            continue; /* open */
        for (k = 0; k < dim; ++k)
            n[k] = lv[k] / len;
        sbc_tensor_apply(dim, Finv, lv, L);
        stick = law->ks > 0.0 && fs < law->mu * law->kn * dn * (1.0 - 1e-12);
        for (i = 0; i < dim; ++i)
            for (k = 0; k < dim; ++k) {
                const double t = (i == k ? 1.0 : 0.0) - n[i] * n[k]; /* I - n (x) n */
                K[SBC_IJ(i, k)] = -law->kn * n[i] * n[k] + law->kn * dn / len * t - (stick ? law->ks * t : 0.0);
            }
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j)
                for (k = 0; k < dim; ++k)
                    for (l = 0; l < dim; ++l)
                        C[9 * SBC_IJ(i, j) + SBC_IJ(k, l)] -= K[SBC_IJ(i, k)] * L[l] * L[j] / p->frame.V;
    }
    return SBC_OK;
}

sbc_status sbc_point_tangent_condensed(sbc_point *p, double C[81], int *mechanisms, sbc_error *err)
{
    const int npair = p->type->pair_count(p->engine);
    int *ij = malloc(sizeof *ij * 2 * (size_t)(npair > 0 ? npair : 1)), ignored, k;
    double *fs = malloc(sizeof *fs * 3 * (size_t)(npair > 0 ? npair : 1));
    sbc_network net;
    sbc_status st;
    if (!mechanisms)
        mechanisms = &ignored;
    if (!ij || !fs) {
        free(ij);
        free(fs);
        memset(C, 0, sizeof(double) * 81);
        *mechanisms = 0;
        return sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory (condensed tangent)");
    }
    for (k = 0; k < npair; ++k) {
        int pair[2];
        p->type->pair(p->engine, k, pair, &fs[3 * k]);
        ij[k] = pair[0];
        ij[npair + k] = pair[1];
    }
    net.dim = p->frame.dim;
    net.n = p->n;
    net.x = p->type->centres(p->engine);
    net.r = p->type->radii(p->engine);
    net.npair = npair;
    net.i = ij;
    net.j = ij + npair;
    net.fs = fs;
    net.law = p->law;
    st = sbc_condensed_tangent(&net, &p->frame, p->settings.bc, C, mechanisms, err);
    free(ij);
    free(fs);
    return st;
}
