/* servo_bc: the aggregate as a material point (material_point.h): the
 * embedded engine, its frame and the controller behind one F -> P call, with
 * the committed state kept as doubles. */
#include "sbc/material_point.h"
#include "sbc/controller.h"
#include "sbc/driver.h"
#include "sbc/embedded/engine.h"
#include "sbc/frame.h"
#include "sbc/packing.h"
#include "sbc/saved.h"
#include "sbc/settings.h"
#include "sbc/time_step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define POINT_STATE_VERSION 1.0

struct sbc_point {
    sbc_settings settings;
    sbc_frame frame;
    sbc_engine *engine;
    sbc_controller *ctl;
    sbc_driver *driver;
    double *mass;          /* [Q] kg */
    double *committed;     /* [size] the committed state (sbc_point_save's layout) */
    size_t size;
    int at_committed;      /* the engine and the controller hold the committed state */
    double F[9], P[9];     /* committed */
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
    sbc_engine_free(p->engine);
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
    if (d->dim != 2)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: dimension %d (this version takes 2D packings)", d->dim);
    if (sbc_settings_parse_words(s, d->words, err) != SBC_OK || sbc_settings_check_dimension(s, 2, err) != SBC_OK)
        return err->status;
    sbc_tensor_identity(2, I);
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
            sbc_engine_move_frame(p->engine, &cmd);
            if (sbc_engine_forces(p->engine, err) != SBC_OK)
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
    const size_t ne = sbc_engine_state_size(p->engine), nc = sbc_controller_state_size(p->ctl);
    sbc_fire_state *fire = sbc_driver_fire(p->driver);
    *out++ = POINT_STATE_VERSION;
    *out++ = (double)ne;
    sbc_engine_save(p->engine, out);
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
    const size_t ne = sbc_engine_state_size(p->engine), nc = sbc_controller_state_size(p->ctl);
    sbc_fire_state *fire = sbc_driver_fire(p->driver);
    sbc_saved s;
    size_t at;
    int k;
    if (n != p->size || in[0] != POINT_STATE_VERSION || in[1] != (double)ne || in[2 + ne] != (double)nc)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state (%zu values, version %g) is not one of "
                        "this point (%zu values, version %g)", n, n > 0 ? in[0] : 0.0, p->size, POINT_STATE_VERSION);
    if (sbc_engine_load(p->engine, in + 2, ne, err) != SBC_OK ||
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
    const sbc_result *r = sbc_controller_result(p->ctl);
    memcpy(p->F, r->F, sizeof p->F);
    memcpy(p->P, r->P, sizeof p->P);
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
    p->at_committed = 1;
    return SBC_OK;
}

sbc_point *sbc_point_create(const sbc_point_def *d, sbc_error *err)
{
    sbc_point *p = calloc(1, sizeof *p);
    sbc_engine_def e = sbc_engine_def_default();
    sbc_packing pk;
    sbc_driver_callbacks cb;
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
    memset(&pk, 0, sizeof pk);
    pk.n = d->n;
    pk.x = (double *)d->x; /* read only */
    pk.r = (double *)d->r;
    if (d->box) {
        pk.has_box = 1;
        memcpy(pk.box, d->box, sizeof pk.box);
    }
    e.n = d->n;
    e.x = d->x;
    e.r = d->r;
    e.density = d->density;
    e.law = d->law;
    e.dt = d->dt;
    e.alpha = p->settings.damping ? p->settings.alpha : 0.0;
    e.beta = p->settings.damping ? p->settings.beta : 0.0;
    e.fire = p->settings.damping == SBC_DAMPING_FIRE;
    if (sbc_packing_distinct(d->n, d->x, d->r, err) != SBC_OK || sbc_frame_detect_packing(&p->frame, &pk, err) != SBC_OK ||
        !(p->engine = sbc_engine_create(&e, err)) ||
        sbc_time_step_bound(d->dt, sbc_engine_critical_dt(p->engine), "2 sqrt(M_min / (2 kn))",
                            p->settings.max_relax_steps, err) != SBC_OK) {
        sbc_point_free(p);
        return NULL;
    }
    sbc_engine_set_frame(p->engine, &p->frame);
    if (!(p->mass = malloc(sizeof(double) * (size_t)p->frame.n))) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        sbc_point_free(p);
        return NULL;
    }
    sbc_engine_frame_masses(p->engine, p->mass);
    cb = sbc_engine_callbacks(p->engine);
    if (!(p->ctl = sbc_controller_create(&p->frame, &p->settings, p->mass, d->dt, d->law.kn, err)) ||
        !(p->driver = sbc_driver_create(p->ctl, &p->settings, &cb, err)) || sbc_engine_forces(p->engine, err) != SBC_OK ||
        run_increment(p, 1, err) != SBC_EVENT_FINISHED) {
        sbc_point_free(p);
        return NULL;
    }
    p->size = 2 + sbc_engine_state_size(p->engine) + 1 + sbc_controller_state_size(p->ctl) + 2 + 18;
    if (!(p->committed = malloc(sizeof(double) * p->size))) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        sbc_point_free(p);
        return NULL;
    }
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
    p->at_committed = 0;
    if (run_increment(p, 0, err) != SBC_EVENT_FINISHED) {
        sbc_point_revert(p);
        return SBC_POINT_FAILED;
    }
    memcpy(P, sbc_controller_result(p->ctl)->P, sizeof(double) * 9);
    *step_ratio = 1.0;
    return SBC_POINT_CONVERGED;
}

sbc_status sbc_point_tangent_perturbation(sbc_point *p, double h, double C[81], sbc_error *err)
{
    const int dim = p->frame.dim;
    double F[9], P[2][9], ratio;
    int k, l, side, ij;
    memset(C, 0, sizeof(double) * 81);
    if (!(h > 0.0) || !isfinite(h))
        return sbc_fail(err, SBC_ERR_INPUT, "material point: perturbation step %g is not positive", h);
    for (k = 0; k < dim; ++k)
        for (l = 0; l < dim; ++l) {
            for (side = 0; side < 2; ++side) {
                memcpy(F, p->F, sizeof F);
                F[SBC_IJ(k, l)] += side ? -h : h;
                if (sbc_point_integrate(p, F, P[side], &ratio, err) != SBC_POINT_CONVERGED)
                    return err->status;
                sbc_point_revert(p);
            }
            for (ij = 0; ij < 9; ++ij) /* eq. 23's P at F + h e_kl and F - h e_kl */
                C[9 * ij + SBC_IJ(k, l)] = (P[0][ij] - P[1][ij]) / (2.0 * h);
        }
    return SBC_OK;
}

sbc_status sbc_point_tangent_affine(sbc_point *p, double C[81], sbc_error *err)
{
    const int dim = p->frame.dim;
    double Finv[9];
    sbc_engine_view w;
    int c, i, j, k, l;
    sbc_point_revert(p);
    memset(C, 0, sizeof(double) * 81);
    if (!sbc_tensor_inverse(dim, p->F, Finv))
        return sbc_fail(err, SBC_ERR_GEOMETRY, "material point: the committed F cannot be inverted");
    w = sbc_engine_get_view(p->engine);
    for (c = 0; c < w.pair_count; ++c) {
        const int a = w.pair_i[c], b = w.pair_j[c];
        double lv[3] = {0, 0, 0}, L[3], n[3] = {0, 0, 0}, K[9], len = 0.0, dn;
        int stick;
        for (k = 0; k < dim; ++k) {
            lv[k] = w.x[dim * b + k] - w.x[dim * a + k];
            len += lv[k] * lv[k];
        }
        len = sqrt(len);
        dn = w.r[a] + w.r[b] - len;
        if (!(dn > 0.0) || (w.pair_bond && w.pair_bond[c]))
            continue; /* open (bonded pairs: not in this version's points) */
        for (k = 0; k < dim; ++k)
            n[k] = lv[k] / len;
        sbc_tensor_apply(dim, Finv, lv, L);
        stick = w.law.ks > 0.0 && w.pair_fs && fabs(w.pair_fs[c]) < w.law.mu * w.law.kn * dn * (1.0 - 1e-12);
        for (i = 0; i < dim; ++i)
            for (k = 0; k < dim; ++k) {
                const double t = (i == k ? 1.0 : 0.0) - n[i] * n[k]; /* I - n (x) n */
                K[SBC_IJ(i, k)] = -w.law.kn * n[i] * n[k] + w.law.kn * dn / len * t - (stick ? w.law.ks * t : 0.0);
            }
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j)
                for (k = 0; k < dim; ++k)
                    for (l = 0; l < dim; ++l)
                        C[9 * SBC_IJ(i, j) + SBC_IJ(k, l)] -= K[SBC_IJ(i, k)] * L[l] * L[j] / p->frame.V;
    }
    return SBC_OK;
}
