/* servo_bc: the aggregate as a material point (material_point.h): the
 * embedded engine, its frame and the controller behind one F -> P call, with
 * the committed state kept as doubles. */
#include "sbc/material_point.h"

#include "aggregate.h"
#include "condensed.h"
#include "../base/sparse.h"
#include "base/words.h"
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

#define POINT_STATE_VERSION 2.0
/* a state's head after its seal (sbc/saved.h): the version, the dimension, the particle count and the hashes of
   the definition it was saved from (definition_of) */
#define POINT_HEAD (SBC_SEALED_HEAD + 6)

struct sbc_point {
    sbc_aggregate a;       /* its engine, frame, settings, masses, dt and contact law */
    sbc_cohesive bonds;    /* the definition's bond law (a.bonds) */
    sbc_settings settings;
    sbc_frame frame;
    sbc_controller *ctl;
    sbc_driver *driver;
    double *mass;          /* [Q] kg (a.mass) */
    double *committed;     /* [size] the committed state (sbc_point_save's layout) */
    double *x_committed;   /* [dim n] its centres, m (the condensed tangent's start of the increment) */
    double *theta_committed; /* 3D: [3n] its rotations, rad */
    int *pairs_committed;    /* 3D: [2 npair] its pairs (i [npair], then j: sbc_aggregate_network) */
    double *fs_committed;    /* 3D: [3 npair] their springs, N */
    int npair_committed;
    size_t size;
    int at_committed;      /* the engine and the controller hold the committed state */
    double F[9], P[9];     /* committed */
    double Fc[9], Pc[9];   /* current: of the last converged integrate since commit or revert, else F, P */
    int certified, certified_c; /* the committed and the current state certified (sbc_point_certified) */
    sbc_statics_tally tally;    /* interior newton: the static solves */
    double definition[3];       /* hashes of the packing, the contact law and the run's words (definition_of) */
};

/* what a saved state depends on beyond its own values, as three hashes (sbc_saved_hash): the packing (x, r,
   box), the contact law (eq. 6, the bonds' eqs. 7-8) and the run (words, density, time step) */
static void definition_of(const sbc_point_def *d, double h[3])
{
    const double law[3] = {d->law.kn, d->law.ks, d->law.mu}, run[2] = {d->density, d->dt};
    h[0] = sbc_saved_hash(d->x, sizeof(double) * (size_t)(d->dim * d->n), 0.0);
    h[0] = sbc_saved_hash(d->r, sizeof(double) * (size_t)d->n, h[0]);
    if (d->box)
        h[0] = sbc_saved_hash(d->box, sizeof(double) * 4, h[0]);
    h[1] = sbc_saved_hash(law, sizeof law, 0.0);
    if (d->bonds) {
        const double b[7] = {d->bonds->kn, d->bonds->ks, d->bonds->kr, d->bonds->fn_u, d->bonds->fs_u, d->bonds->m_u,
                             d->bonds->mu};
        h[1] = sbc_saved_hash(b, sizeof b, h[1]);
    }
    h[2] = sbc_saved_hash(run, sizeof run, 0.0);
    h[2] = sbc_saved_hash(d->words ? d->words : "", d->words ? strlen(d->words) : 0, h[2]);
}

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
    if (p->a.engine)
        p->a.ops->free(p->a.engine);
    sbc_frame_free(&p->frame);
    free(p->mass);
    free(p->committed);
    free(p->x_committed);
    free(p->theta_committed);
    free(p->pairs_committed);
    free(p->fs_committed);
    free(p);
}

/* the position of the word key among the words (0: the first), -1 when
   they do not hold it or out of memory */
static int word_at(const char *words, const char *key)
{
    char *copy = malloc(strlen(words) + 1), *w[256];
    int n, k, at = -1;
    if (!copy)
        return -1;
    strcpy(copy, words);
    n = sbc_split_words(copy, w, 256);
    for (k = 0; k < n && k < 256 && at < 0; ++k)
        if (strcmp(w[k], key) == 0)
            at = k;
    free(copy);
    return at;
}

/* 3D mixed words without F: the same words with the identity as F after
   `mixed`, since the face keywords (xlo ... zhi) are 3D only after a 3D F
   (docs/servo_bc.md, "Mixed"); NULL for any other words or out of memory */
static char *mixed_words_3d(const char *words)
{
    char *out = NULL;
    if (word_at(words, "mixed") == 0 && word_at(words, "F") < 0 && (out = malloc(strlen(words) + 32)))
        sprintf(out, "mixed F 1 0 0 0 1 0 0 0 1 %s", strstr(words, "mixed") + 5);
    return out;
}

/* the words a point takes: a BC of (D), (P), (T) or mixed and its keywords;
   the path (F, increments, stress, file) is the point's. A point's remap is
   none unless its words say x: its consistent tangent (condensed) is the
   derivative of the path without remap (docs/fe2.md, "The consistent tangent") */
static sbc_status point_words(sbc_settings *s, const sbc_point_def *d, sbc_error *err)
{
    char *words3 = NULL;
    double I[9];
    int k;
    sbc_status st;
    if (d->dim != 2 && d->dim != 3)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: dimension %d (expected 2 or 3)", d->dim);
    if (d->dim == 3 && d->words)
        words3 = mixed_words_3d(d->words);
    st = sbc_settings_parse_words(s, words3 ? words3 : d->words, err);
    free(words3);
    if (st != SBC_OK || sbc_settings_check_dimension(s, d->dim, err) != SBC_OK)
        return err->status;
    if (!d->words || word_at(d->words, "remap") <= 0)
        s->remap = 0;
    /* a point of frictional (or bonded) discs or spheres under D or P solves its increments statically unless its words
       say otherwise (interior, speed or remap given): its P is then a function of F, and its condensed tangent
       the derivative (docs/servo_bc.md, "Interior"); under T the static solves of irregular packings stall, so
       T keeps the relaxation unless the words ask */
    if ((s->bc == SBC_BC_D || s->bc == SBC_BC_P) && sbc_sparse_available() &&
        (!d->words || (word_at(d->words, "interior") < 0 && word_at(d->words, "speed") < 0 &&
                       word_at(d->words, "remap") < 0))) {
        s->interior = SBC_INTERIOR_NEWTON;
        s->speed = 0.0;
    }
    sbc_tensor_identity(d->dim, I);
    for (k = 0; k < 9; ++k)
        if (s->F[k] != I[k])
            return sbc_fail(err, SBC_ERR_INPUT, "material point: keyword 'F' is the FE code's (each integrate gives "
                            "it); leave it out of the words");
    if (d->bonds && d->dim != 2)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: cohesive bonds are the paper's 2D bonds (eqs. 7-8); "
                        "this point is 3D");
    if (s->frame_group[0])
        return sbc_fail(err, SBC_ERR_INPUT, "material point: words '%s': keyword 'frame' names a host's group; a "
                        "point finds its frame from the packing", d->words);
    if (s->nstress > 0 || s->increments != 1 || s->file[0] || s->tangent)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: words '%s': stress, increments, file and tangent "
                        "are the path's, which the FE code gives and asks for; expected D, P, T or mixed (its faces "
                        "D or P: a T component needs a stress) and their keywords", d->words);
    return SBC_OK;
}

/* steps until the controller finishes the point's path or fails */
static sbc_event run_increment(sbc_point *p, int first, sbc_error *err)
{
    sbc_event ev;
    while ((ev = sbc_aggregate_run_increment(&p->a, p->ctl, p->driver, first, err)) == SBC_EVENT_INCREMENT)
        first = 0;
    return ev;
}

size_t sbc_point_state_size(const sbc_point *p) { return p ? p->size : 0; }

/* the values of the current state (sbc_point_save's layout): the engine's
   grow and shrink with its pair list */
static size_t current_size(const sbc_point *p)
{
    return POINT_HEAD + 1 + p->a.ops->state_size(p->a.engine) + 1 + sbc_controller_state_size(p->ctl) + 2 + 18;
}

/* the current state into out [current_size] (sbc_point_save's layout) */
static void save_current(const sbc_point *p, const double F[9], const double P[9], double *out)
{
    const size_t ne = p->a.ops->state_size(p->a.engine), nc = sbc_controller_state_size(p->ctl);
    sbc_fire_state *fire = sbc_driver_fire(p->driver);
    double *const block = out;
    out += SBC_SEALED_HEAD;
    *out++ = POINT_STATE_VERSION;
    *out++ = p->frame.dim;
    *out++ = p->a.n;
    memcpy(out, p->definition, sizeof p->definition);
    out += 3;
    *out++ = (double)ne;
    p->a.ops->save(p->a.engine, out);
    out += ne;
    *out++ = (double)nc;
    sbc_controller_save(p->ctl, out);
    out += nc;
    *out++ = fire->alpha;
    *out++ = (double)fire->positive;
    memcpy(out, F, sizeof(double) * 9);
    memcpy(out + 9, P, sizeof(double) * 9);
    sbc_saved_seal(block, current_size(p));
}

/* the head of a saved state in [n]: sealed, this version, and saved by a point of p's definition */
static sbc_status check_head(const sbc_point *p, const double *in, size_t n, sbc_error *err)
{
    static const char *const part[3] = {"packing (x, r, box)", "contact law (kn, ks, mu, bonds)",
                                        "run (words, density, time step)"};
    size_t sealed = 0;
    int k;
    if (n < POINT_HEAD + 1)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: a saved state of %zu values (a state has at least %d)", n,
                        POINT_HEAD + 1);
    if (sbc_saved_open(in, n, &sealed, "material point: the saved state", err) != SBC_OK)
        return err->status;
    if (sealed != n)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state holds %zu values and %zu were given", sealed,
                        n);
    in += SBC_SEALED_HEAD;
    if (in[0] != POINT_STATE_VERSION)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state is of version %g, this point's %g (save it "
                        "again with this version)", in[0], POINT_STATE_VERSION);
    if (in[1] != p->frame.dim || in[2] != p->a.n)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state is of a %gD point of %g particles, this "
                        "one %dD of %d", in[1], in[2], p->frame.dim, p->a.n);
    for (k = 0; k < 3; ++k)
        if (in[3 + k] != p->definition[k])
            return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state was made by a point of another %s "
                            "(load it into a point created from the same definition)", part[k]);
    return SBC_OK;
}

/* in [n] into the engine, the controller, FIRE, F and P */
static sbc_status load_state(sbc_point *p, const double *in, size_t n, double F[9], double P[9], sbc_error *err)
{
    const size_t nc = sbc_controller_state_size(p->ctl);
    sbc_fire_state *fire = sbc_driver_fire(p->driver);
    sbc_saved s;
    double ne_saved;
    size_t at, ne;
    int k;
    if (check_head(p, in, n, err) != SBC_OK)
        return err->status;
    in += POINT_HEAD;
    n -= POINT_HEAD;
    /* the engine's share is as long as its pair list was (in[0]); the rest is this point's */
    ne_saved = in[0];
    if (n < 2 + nc + 20 || !(ne_saved >= 0.0) || ne_saved != floor(ne_saved) || ne_saved != (double)(n - (2 + nc + 20)) ||
        in[1 + (size_t)ne_saved] != (double)nc)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: the saved state's %zu values are not one of this point "
                        "(%zu controller values)", n, nc);
    ne = (size_t)ne_saved;
    if (p->a.ops->load(p->a.engine, in + 1, ne, err) != SBC_OK ||
        sbc_controller_load(p->ctl, in + 2 + ne, nc, err) != SBC_OK)
        return err->status;
    at = 2 + ne + nc;
    sbc_saved_start(&s, in + at, n - at, "material point state", err);
    fire->alpha = sbc_saved_real(&s, "FIRE alpha");
    fire->positive = sbc_saved_int(&s, "FIRE steps", 0, 1L << 52);
    for (k = 0; k < 9; ++k)
        F[k] = sbc_saved_real(&s, "F");
    for (k = 0; k < 9; ++k)
        P[k] = sbc_saved_real(&s, "P");
    return s.st;
}

int sbc_point_certified(const sbc_point *p) { return p ? p->certified_c : 0; }

/* the committed buffer sized for n values; 0 when out of memory (the buffer as it was) */
static int committed_room(sbc_point *p, size_t n)
{
    double *grown;
    if (n == p->size && p->committed)
        return 1;
    if (!(grown = realloc(p->committed, sizeof(double) * n)))
        return 0;
    p->committed = grown;
    p->size = n;
    return 1;
}

/* where the next increment starts, from the engine that holds the committed state: its centres and, in 3D,
   rotations and pairs with their springs (sbc_increment_start) */
static sbc_status keep_start(sbc_point *p, sbc_error *err)
{
    sbc_network net;
    memcpy(p->x_committed, p->a.ops->centres(p->a.engine), sizeof(double) * (size_t)(p->frame.dim * p->a.n));
    if (p->frame.dim != 3)
        return SBC_OK;
    memcpy(p->theta_committed, p->a.ops->rotations(p->a.engine), sizeof(double) * 3 * (size_t)p->a.n);
    free(p->pairs_committed);
    free(p->fs_committed);
    p->npair_committed = 0;
    if (sbc_aggregate_network(&p->a, &net, &p->pairs_committed, &p->fs_committed, err) != SBC_OK)
        return err->status;
    p->npair_committed = net.npair;
    return SBC_OK;
}

sbc_status sbc_point_commit(sbc_point *p)
{
    sbc_error err;
    if (!p)
        return SBC_ERR_INPUT;
    if (!committed_room(p, current_size(p)))
        return SBC_ERR_NOMEM;
    p->certified = p->certified_c;
    memcpy(p->F, p->Fc, sizeof p->F);
    memcpy(p->P, p->Pc, sizeof p->P);
    save_current(p, p->F, p->P, p->committed);
    if (keep_start(p, &err) != SBC_OK)
        return err.status;
    p->at_committed = 1;
    return SBC_OK;
}

void sbc_point_revert(sbc_point *p)
{
    sbc_error err;
    double F[9], P[9];
    if (!p || p->at_committed)
        return;
    /* a state this point saved itself: it loads */
    load_state(p, p->committed, p->size, F, P, &err);
    p->certified_c = p->certified;
    memcpy(p->Fc, p->F, sizeof p->F);
    memcpy(p->Pc, p->P, sizeof p->P);
    p->at_committed = 1;
}

void sbc_point_committed(const sbc_point *p, double F[9], double P[9])
{
    if (!p) {
        memset(F, 0, sizeof(double) * 9);
        memset(P, 0, sizeof(double) * 9);
        return;
    }
    memcpy(F, p->F, sizeof p->F);
    memcpy(P, p->P, sizeof p->P);
}

void sbc_point_save(const sbc_point *p, double *out)
{
    if (p)
        memcpy(out, p->committed, sizeof(double) * p->size);
}

/* SBC_ERR_INPUT with the message when p is NULL (a handle never created, or freed and cleared) */
static sbc_status no_point(const sbc_point *p, const char *what, sbc_error *err)
{
    return p ? SBC_OK : sbc_fail(err, SBC_ERR_INPUT, "material point: %s of a NULL point", what);
}

sbc_status sbc_point_load(sbc_point *p, const double *in, size_t n, sbc_error *err)
{
    double F[9], P[9];
    if (no_point(p, "load", err) != SBC_OK)
        return err->status;
    if (!in)
        return sbc_fail(err, SBC_ERR_INPUT, "material point: load of a NULL state");
    if (load_state(p, in, n, F, P, err) != SBC_OK) {
        p->at_committed = 0;
        sbc_point_revert(p);
        return err->status;
    }
    if (!committed_room(p, n)) { /* the committed state as it was: back to it */
        p->at_committed = 0;
        sbc_point_revert(p);
        return sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory for a state of %zu values", n);
    }
    memcpy(p->committed, in, sizeof(double) * n);
    if (keep_start(p, err) != SBC_OK) {
        p->at_committed = 0;
        sbc_point_revert(p);
        return err->status;
    }
    memcpy(p->F, F, sizeof F);
    memcpy(p->P, P, sizeof P);
    memcpy(p->Fc, F, sizeof F);
    memcpy(p->Pc, P, sizeof P);
    p->certified = p->certified_c = 1; /* a saved state is a committed one: the FE code took it */
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
    definition_of(d, p->definition);
    p->a.ops = d->dim == 3 ? &sbc_engine_ops_spheres : &sbc_engine_ops_discs;
    p->a.law = d->law;
    if (d->bonds) { /* the engine's law then (engine.h): broken bonds and new contacts follow eq. 6 with these */
        p->bonds = *d->bonds;
        p->a.bonds = &p->bonds;
        p->a.law.kn = d->bonds->kn;
        p->a.law.ks = d->bonds->ks;
        p->a.law.mu = d->bonds->mu;
    }
    p->a.n = d->n;
    p->a.frame = &p->frame;
    p->a.settings = &p->settings;
    p->a.dt = d->dt;
    p->a.tally = p->settings.interior == SBC_INTERIOR_NEWTON ? &p->tally : NULL;
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
        if (st == SBC_ERR_FRAME && !d->box && strstr(err->message, "corner")) { /* the likely cause, named */
            char message[SBC_ERROR_LEN];
            snprintf(message, sizeof message, "%s", err->message);
            sbc_fail(err, st, "material point: %s (a geometrically periodic packing, as 'generate' writes it, "
                     "needs its box: sbc_point_def.box, MaterialPoint(box=[xlo, xhi, ylo, yhi]))", message);
        }
    }
    if (st != SBC_OK || !(p->a.engine = p->a.ops->create(d, &p->settings, err)) ||
        sbc_time_step_bound(d->dt, p->a.ops->critical_dt(p->a.engine), "2 sqrt(M_min / (2 kn))",
                            p->settings.max_relax_steps, err) != SBC_OK) {
        sbc_point_free(p);
        return NULL;
    }
    p->a.ops->set_frame(p->a.engine, &p->frame);
    if (p->settings.seal && p->a.ops->seal(p->a.engine, err) != SBC_OK) {
        sbc_point_free(p);
        return NULL;
    }
    if (!(p->mass = malloc(sizeof(double) * (size_t)p->frame.n)) ||
        !(p->x_committed = malloc(sizeof(double) * (size_t)(p->frame.dim * d->n))) ||
        (d->dim == 3 && !(p->theta_committed = malloc(sizeof(double) * 3 * (size_t)d->n)))) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        sbc_point_free(p);
        return NULL;
    }
    p->a.ops->frame_masses(p->a.engine, p->mass);
    p->a.mass = p->mass;
    cb = sbc_aggregate_callbacks(&p->a);
    if ((p->ctl = sbc_controller_create(&p->frame, &p->settings, p->mass, d->dt, d->law.kn, err)))
        sbc_controller_accept_uncertified(p->ctl, 1); /* an FE code is told, and decides (integrate's status) */
    if (!p->ctl || !(p->driver = sbc_driver_create(p->ctl, &p->settings, &cb, err)) ||
        p->a.ops->forces(p->a.engine, err) != SBC_OK ||
        (p->a.tally && sbc_aggregate_advance(&p->a, p->ctl, 1, err) != SBC_OK) ||
        run_increment(p, 1, err) != SBC_EVENT_FINISHED) {
        sbc_point_free(p);
        return NULL;
    }
    memcpy(p->Fc, sbc_controller_result(p->ctl)->F, sizeof p->Fc);
    memcpy(p->Pc, sbc_controller_result(p->ctl)->P, sizeof p->Pc);
    p->certified_c = !sbc_controller_uncertified(p->ctl, NULL, 0);
    if (sbc_point_commit(p) != SBC_OK) {
        sbc_fail(err, SBC_ERR_NOMEM, "material point: out of memory");
        sbc_point_free(p);
        return NULL;
    }
    return p;
}

sbc_point_status sbc_point_integrate(sbc_point *p, const double F[9], double P[9], double *step_ratio,
                                     sbc_error *err)
{
    *step_ratio = 0.5;
    memset(P, 0, sizeof(double) * 9);
    if (no_point(p, "integrate", err) != SBC_OK)
        return SBC_POINT_FAILED;
    sbc_point_revert(p);
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
    p->certified_c = !sbc_controller_uncertified(p->ctl, err->message, sizeof err->message);
    if (!p->certified_c) {
        err->status = SBC_ERR_DIVERGED;
        return SBC_POINT_UNCERTIFIED; /* the step ratio stays 0.5 */
    }
    *step_ratio = 1.0;
    return SBC_POINT_CONVERGED;
}

sbc_status sbc_point_tangent_perturbation(sbc_point *p, double h, double C[81], sbc_error *err)
{
    const int dim = p->frame.dim;
    double F0[9], Pc[9], F[9], P[2][9], ratio, *current = NULL;
    size_t current_n = 0;
    int k, l, side, ij;
    sbc_status st = SBC_OK;
    memset(C, 0, sizeof(double) * 81);
    if (no_point(p, "tangent", err) != SBC_OK)
        return err->status;
    if (!(h >= SBC_POINT_H_SMALLEST && h <= SBC_POINT_H_LARGEST))
        return sbc_fail(err, SBC_ERR_INPUT, "material point: perturbation step %g (expected %g to %g: F's entries are "
                        "near 1, so a smaller step is lost to round-off and a larger one is not a derivative)", h,
                        SBC_POINT_H_SMALLEST, SBC_POINT_H_LARGEST);
    memcpy(F0, p->Fc, sizeof F0);
    memcpy(Pc, p->Pc, sizeof Pc);
    if (!p->at_committed) { /* the current state comes back afterwards */
        current_n = current_size(p);
        if (!(current = malloc(sizeof(double) * current_n)))
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
        load_state(p, current, current_n, Fs, Ps, &ignored);
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
    if (no_point(p, "tangent", err) != SBC_OK)
        return err->status;
    return sbc_aggregate_affine(&p->a, p->Fc, C, err);
}

sbc_status sbc_point_tangent_condensed(sbc_point *p, double C[81], int *mechanisms, sbc_error *err)
{
    sbc_increment_start start;
    if (no_point(p, "condensed tangent", err) != SBC_OK)
        return err->status;
    start.x = p->x_committed;
    start.theta = p->theta_committed;
    start.npair = p->npair_committed;
    start.i = p->pairs_committed;
    start.j = p->pairs_committed ? p->pairs_committed + p->npair_committed : NULL;
    start.fs = p->fs_committed;
    return sbc_aggregate_condensed(&p->a, &start, C, mechanisms, err);
}
