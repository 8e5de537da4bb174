/* Embedded 3D engine: frictional spheres with rotation (spheres.h). */
#include "sbc/embedded/spheres.h"
#include "sbc/bpm_bond.h"
#include "sbc/confine.h"
#include "sbc/damping.h"
#include "sbc/saved.h"
#include "sbc/seal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* one pair of the list: i < j, within the cut-off r_i + r_j + skin at the
   last build, with the contact's state (tangential spring, last force) */
typedef struct pair {
    int i, j;
    sbc_broken_bond c;
} pair;

struct sbc_spheres {
    int n;
    double *x, *v, *f;        /* [3n] m, m/s, N */
    double *theta, *w, *tq;   /* [3n] rad, rad/s, N m */
    double *r, *mass, *inv_m, *inv_I;
    unsigned char *kinematic;
    double rmin, rmax, skin, dt, alpha, beta;
    int fire;
    sbc_friction_law law;
    pair *pairs;
    int npair, cap;
    double *x_build;          /* [3n] centres at the last build */
    int stale;
    double *stream;          /* keyword remap x: the velocity added to each particle, taken back next step (driver.h) */
    int streaming;           /* ... some of it is in v now */
    long builds;
    const sbc_frame *frame;
    int sealed;               /* seal.h walls on the frame's triangles */
    sbc_seal seal;
    int *frame_slot;          /* [n] frame position, -1 interior */
    double *fx, *seal_reaction; /* [3Q] frame centres (m), the walls' reactions (N) */
    /* the last forces' contact sums */
    double ep, overlap_sum, force_sum;
    long contacts, step;
    double rotation_sum;      /* sum |theta| after the last integration, rad */
};

sbc_spheres_def sbc_spheres_def_default(void)
{
    sbc_spheres_def d;
    memset(&d, 0, sizeof d);
    d.density = 2.5e3;
    d.law = sbc_frictional_default();
    d.dt = 1.0e-6;
    d.alpha = d.beta = 0.7;
    return d;
}

void sbc_spheres_free(sbc_spheres *e)
{
    if (!e)
        return;
    free(e->x); free(e->v); free(e->f);
    free(e->theta); free(e->w); free(e->tq);
    free(e->r); free(e->mass); free(e->inv_m); free(e->inv_I);
    free(e->kinematic);
    free(e->stream);
    free(e->pairs);
    free(e->x_build);
    sbc_seal_free(&e->seal);
    free(e->frame_slot); free(e->fx); free(e->seal_reaction);
    free(e);
}

/* ---- the pair list: a cell list over the bounding box, the contact state
   carried over to the new list for the pairs both lists hold ---- */

static int by_pair(const void *a, const void *b)
{
    const pair *p = a, *q = b;
    return p->i != q->i ? (p->i > q->i) - (p->i < q->i) : (p->j > q->j) - (p->j < q->j);
}

static int add_pair(pair **list, int *count, int *cap, int i, int j)
{
    if (*count == *cap) {
        int grown = *cap ? 2 * *cap : 64;
        pair *p = realloc(*list, sizeof(pair) * (size_t)grown);
        if (!p)
            return 0;
        *list = p;
        *cap = grown;
    }
    memset(&(*list)[*count], 0, sizeof(pair));
    (*list)[*count].i = i < j ? i : j;
    (*list)[*count].j = i < j ? j : i;
    ++*count;
    return 1;
}

static sbc_status build_pairs(sbc_spheres *e, sbc_error *err)
{
    const double cut = 2.0 * e->rmax + e->skin;
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    int dims[3], k, a, i, count = 0, cap = 0, old = 0;
    long ncell = 1;
    int *head = NULL, *next = NULL;
    pair *list = NULL;
    for (i = 0; i < e->n; ++i)
        for (k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], e->x[3 * i + k]);
            hi[k] = fmax(hi[k], e->x[3 * i + k]);
        }
    for (k = 0; k < 3; ++k) {
        double span = hi[k] - lo[k];
        dims[k] = span / cut > 1.0 ? (int)fmin(span / cut, 1000.0) : 1;
        ncell *= dims[k];
    }
    head = malloc(sizeof(int) * (size_t)ncell);
    next = malloc(sizeof(int) * (size_t)e->n);
    if (!head || !next) {
        free(head), free(next);
        return sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory for the cell list of %d spheres", e->n);
    }
    for (k = 0; k < ncell; ++k)
        head[k] = -1;
    for (i = 0; i < e->n; ++i) {
        long c = 0;
        for (k = 2; k >= 0; --k) {
            int b = (int)((e->x[3 * i + k] - lo[k]) / (hi[k] - lo[k] > 0.0 ? hi[k] - lo[k] : 1.0) * dims[k]);
            b = b < 0 ? 0 : b >= dims[k] ? dims[k] - 1 : b;
            c = c * dims[k] + b;
        }
        next[i] = (int)head[c];
        head[c] = i;
    }
    for (i = 0; i < e->n; ++i) {
        int b[3], d[3];
        for (k = 0; k < 3; ++k) {
            b[k] = (int)((e->x[3 * i + k] - lo[k]) / (hi[k] - lo[k] > 0.0 ? hi[k] - lo[k] : 1.0) * dims[k]);
            b[k] = b[k] < 0 ? 0 : b[k] >= dims[k] ? dims[k] - 1 : b[k];
        }
        for (d[2] = -1; d[2] <= 1; ++d[2])
            for (d[1] = -1; d[1] <= 1; ++d[1])
                for (d[0] = -1; d[0] <= 1; ++d[0]) {
                    long c = 0;
                    int j, ok = 1;
                    for (k = 2; k >= 0; --k) {
                        const int bk = b[k] + d[k];
                        ok &= bk >= 0 && bk < dims[k];
                        c = c * dims[k] + bk;
                    }
                    if (!ok)
                        continue;
                    for (j = head[c]; j >= 0; j = next[j]) {
                        double d2 = 0.0, reach = e->r[i] + e->r[j] + e->skin;
                        if (j <= i)
                            continue;
                        for (k = 0; k < 3; ++k)
                            d2 += (e->x[3 * j + k] - e->x[3 * i + k]) * (e->x[3 * j + k] - e->x[3 * i + k]);
                        if (d2 < reach * reach && !add_pair(&list, &count, &cap, i, j)) {
                            free(head), free(next), free(list);
                            return sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory for the pairs of %d spheres",
                                            e->n);
                        }
                    }
                }
    }
    free(head);
    free(next);
    if (count > 1)
        qsort(list, (size_t)count, sizeof(pair), by_pair);
    for (a = 0; a < count && old < e->npair; ++a) { /* both lists sorted: carry the contacts' state over */
        while (old < e->npair && by_pair(&e->pairs[old], &list[a]) < 0)
            ++old;
        if (old < e->npair && by_pair(&e->pairs[old], &list[a]) == 0)
            list[a].c = e->pairs[old].c;
    }
    free(e->pairs);
    e->pairs = list;
    e->npair = count;
    e->cap = cap;
    memcpy(e->x_build, e->x, sizeof(double) * 3 * (size_t)e->n);
    e->stale = 0;
    e->builds++;
    return SBC_OK;
}

/* a sphere moved more than half the skin since the last build */
static void check_moved(sbc_spheres *e, int i)
{
    double d2 = 0.0;
    int k;
    for (k = 0; k < 3; ++k)
        d2 += (e->x[3 * i + k] - e->x_build[3 * i + k]) * (e->x[3 * i + k] - e->x_build[3 * i + k]);
    if (d2 > 0.25 * e->skin * e->skin)
        e->stale = 1;
}

sbc_spheres *sbc_spheres_create(const sbc_spheres_def *d, sbc_error *err)
{
    sbc_spheres *e;
    const size_t n = (size_t)(d->n > 0 ? d->n : 0);
    int i;
    if (d->n < 1) {
        sbc_fail(err, SBC_ERR_INPUT, "engine: no spheres");
        return NULL;
    }
    if (!(d->density > 0.0) || !(d->dt > 0.0) || !(d->law.kn > 0.0) || !(d->law.ks >= 0.0) || !(d->law.mu >= 0.0) ||
        !isfinite(d->density) || !isfinite(d->dt) || !isfinite(d->law.kn)) {
        sbc_fail(err, SBC_ERR_INPUT, "engine: density, time step and kn must be positive and finite, ks and mu "
                 "non-negative");
        return NULL;
    }
    if (!(e = calloc(1, sizeof *e))) {
        sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory");
        return NULL;
    }
    e->n = d->n;
    e->x = malloc(sizeof(double) * 3 * n);
    e->x_build = malloc(sizeof(double) * 3 * n);
    e->v = calloc(3 * n, sizeof(double));
    e->f = calloc(3 * n, sizeof(double));
    e->theta = calloc(3 * n, sizeof(double));
    e->w = calloc(3 * n, sizeof(double));
    e->tq = calloc(3 * n, sizeof(double));
    e->r = malloc(sizeof(double) * n);
    e->mass = malloc(sizeof(double) * n);
    e->inv_m = malloc(sizeof(double) * n);
    e->inv_I = malloc(sizeof(double) * n);
    e->kinematic = calloc(n, 1);
    if (!e->x || !e->x_build || !e->v || !e->f || !e->theta || !e->w || !e->tq || !e->r || !e->mass || !e->inv_m ||
        !e->inv_I || !e->kinematic) {
        sbc_spheres_free(e);
        sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory for %d spheres", d->n);
        return NULL;
    }
    memcpy(e->x, d->x, sizeof(double) * 3 * n);
    e->rmin = DBL_MAX;
    for (i = 0; i < d->n; ++i) {
        const double R = d->r[i];
        if (!(R > 0.0) || !isfinite(R) || !isfinite(d->x[3 * i]) || !isfinite(d->x[3 * i + 1]) ||
            !isfinite(d->x[3 * i + 2])) {
            sbc_fail(err, SBC_ERR_INPUT, "engine: sphere %d has radius %g (expected > 0) or a non-finite centre", i, R);
            sbc_spheres_free(e);
            return NULL;
        }
        e->r[i] = R;
        e->mass[i] = d->density * 4.0 / 3.0 * M_PI * R * R * R; /* M = rho 4/3 pi R^3, kg */
        e->inv_m[i] = 1.0 / e->mass[i];
        e->inv_I[i] = 1.0 / (0.4 * e->mass[i] * R * R);         /* I = 2/5 M R^2 */
        if (!(e->inv_m[i] > 0.0) || !isfinite(e->inv_m[i]) || !(e->inv_I[i] > 0.0) || !isfinite(e->inv_I[i])) {
            sbc_fail(err, SBC_ERR_INPUT, "engine: sphere %d: its mass rho 4/3 pi R^3 = %g kg or moment of inertia "
                     "overflows or vanishes in double precision (density %g kg/m^3, radius %g m)", i, e->mass[i],
                     d->density, R);
            sbc_spheres_free(e);
            return NULL;
        }
        e->rmin = fmin(e->rmin, R);
        e->rmax = fmax(e->rmax, R);
    }
    e->law.kn = d->law.kn;
    e->law.ks = d->law.ks;
    e->law.mu = d->law.mu;
    e->skin = d->skin > 0.0 ? d->skin : 0.25 * e->rmin;
    e->dt = d->dt;
    e->alpha = d->alpha;
    e->beta = d->beta;
    e->fire = d->fire;
    if (build_pairs(e, err) != SBC_OK) {
        sbc_spheres_free(e);
        return NULL;
    }
    return e;
}

void sbc_spheres_set_frame(sbc_spheres *e, const sbc_frame *frame)
{
    int q;
    memset(e->kinematic, 0, (size_t)e->n);
    e->frame = frame;
    for (q = 0; frame && q < frame->n; ++q)
        e->kinematic[frame->particle[q]] = 1;
}

sbc_status sbc_spheres_seal(sbc_spheres *e, sbc_error *err)
{
    const sbc_frame *fr = e->frame;
    if (!fr)
        return sbc_fail(err, SBC_ERR_INPUT, "spheres: seal without a frame");
    e->frame_slot = sbc_seal_slots(fr, e->n);
    e->fx = malloc(sizeof(double) * 3 * (size_t)fr->n);
    e->seal_reaction = malloc(sizeof(double) * 3 * (size_t)fr->n);
    if (!e->frame_slot || !e->fx || !e->seal_reaction)
        return sbc_fail(err, SBC_ERR_NOMEM, "spheres: out of memory");
    if (sbc_seal_init(&e->seal, fr, e->skin, err) != SBC_OK)
        return err->status;
    e->sealed = 1;
    return SBC_OK;
}

/* seal.h: the walls' forces on the spheres, their reactions on the frame
 * spheres, and their energy in Ep */
static sbc_status seal_step(sbc_spheres *e, sbc_error *err)
{
    const sbc_seal_particles p = sbc_seal_packed(e->n, e->x, e->f, 3, e->r, e->frame_slot);
    double energy;
    sbc_status st;
    sbc_frame_centres(e->frame, e->x, e->fx);
    st = sbc_seal_forces_packed(&e->seal, e->frame, e->fx, &p, e->law.kn, e->seal_reaction, &energy, err);
    e->ep += energy;
    return st;
}

/* eq. 6 in 3D on every pair (the thesis' contact springs), eq. 12, eq. 39 */
sbc_status sbc_spheres_forces(sbc_spheres *e, sbc_error *err)
{
    const double dt = e->dt;
    int k, q;
    if (e->stale && build_pairs(e, err) != SBC_OK)
        return err->status;
    memset(e->f, 0, sizeof(double) * 3 * (size_t)e->n);
    memset(e->tq, 0, sizeof(double) * 3 * (size_t)e->n);
    e->ep = e->overlap_sum = e->force_sum = 0.0;
    e->contacts = 0;
    for (k = 0; k < e->npair; ++k) {
        pair *p = &e->pairs[k];
        const int a = p->i, b = p->j;
        const double *xa = &e->x[3 * a], *xb = &e->x[3 * b];
        double n[3], ra[3], rb[3], dta[3], dtb[3], wa[3], wb[3], du[3], f[3], t[3], d2 = 0.0, L, inv, dn, sa;
        const double rs = e->r[a] + e->r[b];
        for (q = 0; q < 3; ++q) {
            n[q] = xb[q] - xa[q];
            d2 += n[q] * n[q];
        }
        if (d2 >= rs * rs) {
            memset(&p->c, 0, sizeof p->c); /* contact lost: its history with it */
            continue;
        }
        L = sqrt(d2);
        inv = 1.0 / L;
        dn = rs - L;
        sa = e->r[a] - 0.5 * dn; /* the contact point halfway across the overlap, x_c = x_a + sa n */
        for (q = 0; q < 3; ++q) {
            n[q] *= inv;
            ra[q] = sa * n[q];
            rb[q] = (sa - L) * n[q];
            dta[q] = dt * e->w[3 * a + q];
            dtb[q] = dt * e->w[3 * b + q];
        }
        sbc_cross3(dta, ra, wa);
        sbc_cross3(dtb, rb, wb);
        for (q = 0; q < 3; ++q) /* the contact point of a against b in the step just taken */
            du[q] = (dt * e->v[3 * a + q] + wa[q]) - (dt * e->v[3 * b + q] + wb[q]);
        sbc_broken_bond_increment(&e->law, &p->c, dn, n, du, f);
        for (q = 0; q < 3; ++q) {
            e->f[3 * a + q] += f[q];
            e->f[3 * b + q] -= f[q];
        }
        sbc_cross3(ra, f, t); /* moments about the centres: (xc - xa) x f, (xc - xb) x (-f) */
        for (q = 0; q < 3; ++q)
            e->tq[3 * a + q] += t[q];
        sbc_cross3(f, rb, t);
        for (q = 0; q < 3; ++q)
            e->tq[3 * b + q] += t[q];
        e->ep += sbc_broken_bond_energy(&e->law, &p->c, dn);
        e->overlap_sum += 2.0 * dn / (e->r[a] + e->r[b]); /* eq. 39: dn / Rbar */
        e->force_sum += sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        e->contacts++;
    }
    e->step++;
    return e->sealed ? seal_step(e, err) : SBC_OK;
}

/* ---- the driver's callbacks ---- */

static void fire_sums(void *user_data, double *sums)
{
    const sbc_spheres *e = user_data;
    int i;
    for (i = 0; i < e->n; ++i)
        if (!e->kinematic[i])
            sbc_fire_add(sums, 3, &e->f[3 * i], &e->v[3 * i], &e->tq[3 * i], &e->w[3 * i]);
}

/* damping (eq. 10, or FIRE's mix), then the interior advanced: v += dt f/M,
   x += dt v, w += dt m/I, theta += dt w; Ek of the spheres that carry a force
   (relax.h) and the largest |net contact force| before damping */
static void interior(void *user_data, const sbc_fire_mix *mix, int again, double out[2])
{
    sbc_spheres *e = user_data;
    const double dt = e->dt, alpha = e->fire ? 0.0 : e->alpha, beta = e->fire ? 0.0 : e->beta;
    double ek = 0.0, net = 0.0;
    int i, k;
    (void)again; /* the engine never revisits a step */
    for (i = 0; i < e->n; ++i) {
        double *v = &e->v[3 * i], *w = &e->w[3 * i], f[3], t[3];
        int loaded = 0;
        if (e->kinematic[i])
            continue;
        for (k = 0; k < 3; ++k) {
            f[k] = e->f[3 * i + k];
            t[k] = e->tq[3 * i + k];
        }
        net = fmax(net, f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (mix) {
            const double push = sbc_fire_factor(mix->push, mix, dt * e->inv_m[i]);
            const double spin = sbc_fire_factor(mix->spin, mix, dt * e->inv_I[i]);
            for (k = 0; k < 3; ++k) {
                v[k] = sbc_fire_velocity(mix, push, v[k], f[k]);
                w[k] = sbc_fire_velocity(mix, spin, w[k], t[k]);
            }
        }
        for (k = 0; k < 3; ++k) {
            f[k] = sbc_damp_local(f[k], v[k], alpha);
            t[k] = sbc_damp_local(t[k], w[k], beta);
            v[k] += dt * f[k] * e->inv_m[i];
            w[k] += dt * t[k] * e->inv_I[i];
            e->x[3 * i + k] += dt * v[k];
            e->theta[3 * i + k] += dt * w[k];
            loaded |= f[k] != 0.0 || t[k] != 0.0;
        }
        if (loaded)
            ek += sbc_kinetic_energy(3, e->mass[i], 0.4 * e->mass[i] * e->r[i] * e->r[i], v, w);
        check_moved(e, i);
    }
    out[0] = ek;
    out[1] = sqrt(net);
}

static void contacts(void *user_data, double out[4])
{
    const sbc_spheres *e = user_data;
    out[0] = e->ep;
    out[1] = e->overlap_sum;
    out[2] = (double)e->contacts;
    out[3] = e->force_sum;
}

static double rotation_length(const double *th) { return sqrt(th[0] * th[0] + th[1] * th[1] + th[2] * th[2]); }

/* the frame in frame order (driver.h's layout), sum |theta| over every
   sphere and the count */
static void frame(void *user_data, double *buf)
{
    const sbc_spheres *e = user_data;
    const sbc_frame *fr = e->frame;
    const int Q = fr->n;
    double turned = 0.0;
    int q, k, i;
    for (q = 0; q < Q; ++q) {
        const int p = fr->particle[q];
        for (k = 0; k < 3; ++k) {
            buf[3 * q + k] = e->x[3 * p + k];
            buf[3 * Q + 3 * q + k] = e->f[3 * p + k];
            buf[SBC_DRIVER_TORQUE(3, Q) + 3 * q + k] = e->tq[3 * p + k];
            buf[SBC_DRIVER_THETA(3, Q) + 3 * q + k] = e->theta[3 * p + k];
        }
    }
    for (i = 0; i < e->n; ++i)
        turned += rotation_length(&e->theta[3 * i]);
    buf[SBC_DRIVER_SUMS(3, Q)] = turned;
    buf[SBC_DRIVER_SUMS(3, Q) + 1] = e->n;
}

/* confine.h on the interior against the frame's centres fx */
static int confined(void *user_data, const double *fx, int increment, char *message, size_t cap)
{
    const sbc_spheres *e = user_data;
    sbc_confine c;
    sbc_error err;
    int i;
    sbc_confine_prepare(&c, e->frame, fx);
    for (i = 0; i < e->n; ++i)
        if (!e->kinematic[i] && sbc_confine_check(&c, increment, i, &e->x[3 * i], &e->v[3 * i], &err) != SBC_OK) {
            snprintf(message, cap, "%s", err.message);
            return err.status;
        }
    return SBC_OK;
}

/* keyword remap x (driver.h): the interior moves with the frame's affine
   move now and carries its velocity, kept in e->stream, into the next
   contact forces */
static void remap(void *user_data, const double *M, const double *origin, int sign)
{
    sbc_spheres *e = user_data;
    int i, c;
    if (sign < 0) {
        if (e->streaming)
            for (i = 0; i < 3 * e->n; ++i) {
                e->v[i] -= e->stream[i];
                e->stream[i] = 0.0;
            }
        e->streaming = 0;
        return;
    }
    if (!e->stream && !(e->stream = calloc(3 * (size_t)e->n, sizeof(double))))
        return; /* out of memory: the interior waits for the frame, as without remap */
    for (i = 0; i < e->n; ++i)
        if (!e->kinematic[i]) {
            double u[3];
            sbc_remap_displacement(3, M, origin, &e->x[3 * i], u);
            for (c = 0; c < 3; ++c) {
                e->stream[3 * i + c] = u[c] / e->dt;
                e->v[3 * i + c] += e->stream[3 * i + c];
                e->x[3 * i + c] += u[c];
            }
            check_moved(e, i);
        }
    e->streaming = 1;
}

sbc_driver_callbacks sbc_spheres_callbacks(sbc_spheres *e)
{
    sbc_driver_callbacks cb;
    memset(&cb, 0, sizeof cb);
    cb.user_data = e;
    cb.fire_sums = fire_sums;
    cb.interior = interior;
    cb.contacts = contacts;
    cb.frame = frame;
    cb.confined = confined;
    cb.remap = remap;
    return cb;
}

void sbc_spheres_move_frame(sbc_spheres *e, const sbc_commands *cmd)
{
    const double dt = e->dt;
    int q, k;
    if (!e->frame)
        return;
    for (q = 0; q < e->frame->n; ++q) {
        const int p = e->frame->particle[q];
        for (k = 0; k < 3; ++k) {
            double *w = &e->w[3 * p + k], *th = &e->theta[3 * p + k];
            e->v[3 * p + k] = (cmd->x[3 * q + k] - e->x[3 * p + k]) / dt;
            e->x[3 * p + k] = cmd->x[3 * q + k];
            if (cmd->free_rotation[q]) { /* (T): free, with the rotational damping of eq. 10 */
                *w += dt * sbc_damp_local(e->tq[3 * p + k], *w, e->beta) * e->inv_I[p];
                *th += dt * *w;
            } else {
                *w = (cmd->theta[3 * q + k] - *th) / dt;
                *th = cmd->theta[3 * q + k];
            }
        }
        check_moved(e, p);
    }
}

void sbc_spheres_frame_masses(const sbc_spheres *e, double *mass)
{
    int q;
    for (q = 0; q < e->frame->n; ++q)
        mass[q] = e->mass[e->frame->particle[q]];
}

double sbc_spheres_critical_dt(const sbc_spheres *e)
{
    double m = DBL_MAX;
    int i;
    for (i = 0; i < e->n; ++i)
        m = fmin(m, e->mass[i]);
    return 2.0 * sqrt(m / (2.0 * e->law.kn));
}

sbc_spheres_view sbc_spheres_get_view(const sbc_spheres *e)
{
    sbc_spheres_view w;
    w.n = e->n;
    w.x = e->x;
    w.v = e->v;
    w.r = e->r;
    w.theta = e->theta;
    w.omega = e->w;
    w.mass = e->mass;
    w.f = e->f;
    w.torque = e->tq;
    w.pair_count = e->npair;
    w.contact_count = (int)e->contacts;
    w.potential_energy = e->ep;
    w.step = e->step;
    w.builds = e->builds;
    return w;
}

void sbc_spheres_pair(const sbc_spheres *e, int k, int ij[2], double fs[3])
{
    const pair *p = &e->pairs[k];
    ij[0] = p->i;
    ij[1] = p->j;
    memcpy(fs, p->c.fs, sizeof p->c.fs);
}

sbc_status sbc_spheres_place(sbc_spheres *e, const double *x, const double *theta, const double *records, int count,
                             sbc_error *err)
{
    const size_t n3 = 3 * (size_t)e->n;
    int k, q;
    memcpy(e->x, x, sizeof(double) * n3);
    memcpy(e->theta, theta, sizeof(double) * n3);
    memset(e->v, 0, sizeof(double) * n3);
    memset(e->w, 0, sizeof(double) * n3);
    if (e->stream)
        memset(e->stream, 0, sizeof(double) * n3);
    e->streaming = 0;
    if (build_pairs(e, err) != SBC_OK)
        return err->status;
    for (k = 0; k < e->npair; ++k)
        memset(e->pairs[k].c.fs, 0, sizeof e->pairs[k].c.fs);
    for (k = 0; k < count; ++k) {
        pair key, *hit;
        const double *rec = &records[5 * k];
        key.i = (int)rec[0];
        key.j = (int)rec[1];
        hit = e->npair ? bsearch(&key, e->pairs, (size_t)e->npair, sizeof(pair), by_pair) : NULL;
        if (!hit)
            return sbc_fail(err, SBC_ERR_INPUT, "engine: a spring for spheres %d and %d, which are not within reach",
                            key.i, key.j);
        for (q = 0; q < 3; ++q)
            hit->c.fs[q] = rec[2 + q];
    }
    return SBC_OK;
}

/* ---- the state (sbc_spheres_save, sbc_spheres_load) ---- */

#define SPHERES_STATE_HEAD 10 /* n, stale, builds, step, Ep, overlaps, forces, contacts, rotations, pairs */
#define SPHERES_PAIR_STATE 9  /* i, j, fs [3], f [3], w */

size_t sbc_spheres_state_size(const sbc_spheres *e)
{
    return SPHERES_STATE_HEAD + 21 * (size_t)e->n + SPHERES_PAIR_STATE * (size_t)e->npair;
}

void sbc_spheres_save(const sbc_spheres *e, double *out)
{
    const size_t n3 = 3 * (size_t)e->n;
    double *const arrays[7] = {e->x, e->v, e->f, e->theta, e->w, e->tq, e->x_build};
    int k, m;
    *out++ = e->n;
    *out++ = e->stale;
    *out++ = (double)e->builds;
    *out++ = (double)e->step;
    *out++ = e->ep;
    *out++ = e->overlap_sum;
    *out++ = e->force_sum;
    *out++ = (double)e->contacts;
    *out++ = e->rotation_sum;
    *out++ = e->npair;
    for (m = 0; m < 7; ++m) {
        memcpy(out, arrays[m], sizeof(double) * n3);
        out += n3;
    }
    for (k = 0; k < e->npair; ++k) {
        const pair *p = &e->pairs[k];
        *out++ = p->i;
        *out++ = p->j;
        for (m = 0; m < 3; ++m)
            *out++ = p->c.fs[m];
        for (m = 0; m < 3; ++m)
            *out++ = p->c.f[m];
        *out++ = p->c.w;
    }
}

sbc_status sbc_spheres_load(sbc_spheres *e, const double *in, size_t count, sbc_error *err)
{
    static const char *const names[7] = {"position", "velocity", "force", "rotation", "angular velocity",
                                         "moment", "pair list build position"};
    const size_t n3 = 3 * (size_t)e->n;
    double *const arrays[7] = {e->x, e->v, e->f, e->theta, e->w, e->tq, e->x_build};
    const long most = (long)e->n * (long)(e->n > 1 ? e->n - 1 : 1) / 2;
    sbc_saved s;
    pair *list = NULL;
    long npair;
    size_t j;
    int k, m;
    sbc_saved_start(&s, in, count, "sphere engine state", err);
    sbc_saved_int(&s, "sphere count", e->n, e->n);
    e->stale = (int)sbc_saved_int(&s, "stale flag", 0, 1);
    e->builds = sbc_saved_int(&s, "pair list builds", 0, 1L << 52);
    e->streaming = 0; /* the saved velocities are the velocities (remap, driver.h) */
    e->step = sbc_saved_int(&s, "step", 0, 1L << 52);
    e->ep = sbc_saved_real(&s, "potential energy");
    e->overlap_sum = sbc_saved_real(&s, "overlap sum");
    e->force_sum = sbc_saved_real(&s, "contact force sum");
    e->contacts = sbc_saved_int(&s, "contact count", 0, 1L << 52);
    e->rotation_sum = sbc_saved_real(&s, "rotation sum");
    npair = sbc_saved_int(&s, "pair count", 0, most);
    for (m = 0; m < 7 && s.st == SBC_OK; ++m)
        for (j = 0; j < n3; ++j)
            arrays[m][j] = sbc_saved_real(&s, names[m]);
    if (s.st == SBC_OK && npair > 0 && !(list = calloc((size_t)npair, sizeof *list)))
        return sbc_fail(err, SBC_ERR_NOMEM, "sphere engine state: out of memory for %ld pairs", npair);
    for (k = 0; k < npair && s.st == SBC_OK; ++k) {
        pair *p = &list[k];
        p->i = (int)sbc_saved_int(&s, "pair sphere i", 0, e->n - 1);
        p->j = (int)sbc_saved_int(&s, "pair sphere j", p->i + 1, e->n - 1);
        for (m = 0; m < 3; ++m)
            p->c.fs[m] = sbc_saved_real(&s, "pair tangential force");
        for (m = 0; m < 3; ++m)
            p->c.f[m] = sbc_saved_real(&s, "pair force");
        p->c.w = sbc_saved_real(&s, "pair work");
    }
    if (s.st != SBC_OK) {
        free(list);
        return s.st;
    }
    if (s.at != count) {
        free(list);
        return sbc_fail(err, SBC_ERR_INPUT, "sphere engine state: %zu values given, %zu read", count, s.at);
    }
    free(e->pairs);
    e->pairs = list;
    e->npair = (int)npair;
    e->cap = (int)npair;
    return SBC_OK;
}
