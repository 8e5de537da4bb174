/* Embedded 2D disc engine (paper Sect. 2.2). */
#include "sbc/embedded/engine.h"
#include "sbc/confine.h"
#include "sbc/damping.h"
#include "sbc/saved.h"
#include "sbc/seal.h"

#include "neighbor.h"
#include "pair_contact.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#include "engine_private.h"

sbc_engine_def sbc_engine_def_default(void)
{
    sbc_engine_def d;
    memset(&d, 0, sizeof d);
    d.density = 2.0e3;
    d.law = sbc_frictional_default();
    d.dt = 1.0e-6;
    d.alpha = d.beta = 0.7;
    return d;
}

void sbc_engine_free(sbc_engine *e)
{
    if (!e)
        return;
    free(e->x); free(e->v); free(e->f);
    free(e->theta); free(e->omega); free(e->tq);
    free(e->r); free(e->mass); free(e->inv_m); free(e->inv_I);
    free(e->kinematic);
    free(e->stream);
    free(e->snap_x); free(e->snap_theta); free(e->snap_f); free(e->snap_tq);
    sbc_seal_free(&e->seal);
    free(e->seal_reaction);
    free(e->frame_slot);
    sbc_pairs_free(&e->pairs);
    free(e);
}

sbc_engine *sbc_engine_create(const sbc_engine_def *d, sbc_error *err)
{
    sbc_engine *e;
    size_t n = (size_t)d->n;
    double skin;
    int k;
    if (d->n < 1) {
        sbc_fail(err, SBC_ERR_INPUT, "engine: no particles");
        return NULL;
    }
    if (!(d->density > 0.0) || !(d->dt > 0.0) || !(d->law.kn > 0.0) || !(d->law.ks >= 0.0) || !(d->law.mu >= 0.0)) {
        sbc_fail(err, SBC_ERR_INPUT, "engine: density, time step and kn must be positive, ks and mu non-negative");
        return NULL;
    }
    e = calloc(1, sizeof *e);
    if (!e) {
        sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory");
        return NULL;
    }
    e->n = d->n;
    e->x = malloc(sizeof(double) * 2 * n);
    e->v = calloc(2 * n, sizeof(double));
    e->f = calloc(2 * n, sizeof(double));
    e->theta = calloc(n, sizeof(double));
    e->omega = calloc(n, sizeof(double));
    e->tq = calloc(n, sizeof(double));
    e->r = malloc(sizeof(double) * n);
    e->mass = malloc(sizeof(double) * n);
    e->inv_m = malloc(sizeof(double) * n);
    e->inv_I = malloc(sizeof(double) * n);
    e->kinematic = calloc(n, 1);
    if (!e->x || !e->v || !e->f || !e->theta || !e->omega || !e->tq || !e->r || !e->mass || !e->inv_m ||
        !e->inv_I || !e->kinematic) {
        sbc_engine_free(e);
        sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory for %d particles", d->n);
        return NULL;
    }
    memcpy(e->x, d->x, sizeof(double) * 2 * n);
    e->rmax = 0.0;
    e->rmin = DBL_MAX;
    for (k = 0; k < d->n; ++k) {
        double R = d->r[k];
        if (!(R > 0.0) || !isfinite(R) || !isfinite(d->x[2 * k]) || !isfinite(d->x[2 * k + 1])) {
            sbc_fail(err, SBC_ERR_INPUT, "engine: particle %d has radius %g (expected > 0) or a non-finite centre", k,
                     R);
            sbc_engine_free(e);
            return NULL;
        }
        e->r[k] = R;
        e->mass[k] = d->density * M_PI * R * R;          /* M = rho pi R^2, kg */
        e->inv_m[k] = 1.0 / e->mass[k];
        e->inv_I[k] = 1.0 / (0.5 * e->mass[k] * R * R); /* I = M R^2 / 2 (eq. 9) */
        if (!isfinite(e->mass[k]) || !(e->inv_m[k] > 0.0) || !isfinite(e->inv_m[k]) || !(e->inv_I[k] > 0.0) ||
            !isfinite(e->inv_I[k]) || !isfinite(sqrt(e->mass[k] / (2.0 * d->law.kn))) ||
            !(sqrt(e->mass[k] / (2.0 * d->law.kn)) > 0.0)) {
            sbc_fail(err, SBC_ERR_INPUT, "engine: particle %d: its mass rho pi R^2 = %g kg, moment of inertia "
                     "M R^2 / 2 = %g kg m^2 or critical step 2 sqrt(M / (2 kn)) overflows or vanishes in double "
                     "precision (density %g kg/m^2, radius %g m, kn %g N/m); expected values whose products stay "
                     "finite and non-zero", k, e->mass[k], 0.5 * e->mass[k] * R * R, d->density, R, d->law.kn);
            sbc_engine_free(e);
            return NULL;
        }
        if (R > e->rmax) e->rmax = R;
        if (R < e->rmin) e->rmin = R;
    }
    e->law = d->law;
    skin = d->skin > 0.0 ? d->skin : 0.25 * e->rmin;
    if (d->bonds) {
        const sbc_cohesive *b = d->bonds;
        if (!(b->kn > 0.0) || !(b->ks >= 0.0) || !(b->kr >= 0.0) || !(b->mu >= 0.0) || !(b->fn_u > 0.0) ||
            !(b->fs_u > 0.0) || !(b->m_u > 0.0) || !isfinite(b->fn_u / b->kn)) {
            sbc_fail(err, SBC_ERR_INPUT,
                     "engine: bond law needs kn, fn_u, fs_u, m_u > 0 and finite, ks, kr, mu >= 0");
            sbc_engine_free(e);
            return NULL;
        }
        e->bonded = 1;
        e->bond_law = *b;
        e->law.kn = b->kn; /* broken bonds and new contacts: eq. 6 with the bond's kn, ks, mu */
        e->law.ks = b->ks;
        e->law.mu = b->mu;
        /* an intact bond stretches less than fn_u / kn (eq. 8, first term alone): a skin
         * beyond that keeps every intact bond in the neighbour list */
        if (skin < 1.5 * b->fn_u / b->kn)
            skin = 1.5 * b->fn_u / b->kn;
    }
    e->history = sbc_frictional_has_history(&e->law) || e->bonded;
    e->dt = d->dt;
    e->alpha = d->alpha;
    e->beta = d->beta;
    e->fire = d->fire;
    sbc_fire_start(&e->fire_state);
    if (sbc_pairs_init(&e->pairs, 2, d->n, skin, e->history, e->bonded, err) != SBC_OK ||
        sbc_pairs_build(&e->pairs, e->x, e->r, e->rmax, err) != SBC_OK) {
        sbc_engine_free(e);
        return NULL;
    }
    if (e->bonded) /* "two particles in contact at the start are bonded" (Sect. 2.2.2) */
        e->bond_count = e->bonds_initial = sbc_pairs_bond_touching(&e->pairs, e->x, e->r, SBC_BOND_TOUCH * e->rmin);
    return e;
}

void sbc_engine_set_frame(sbc_engine *e, const sbc_frame *frame)
{
    int q;
    size_t nq = frame ? (size_t)frame->n : 0;
    memset(e->kinematic, 0, (size_t)e->n);
    sbc_seal_free(&e->seal);
    free(e->seal_reaction);
    free(e->frame_slot);
    e->seal_reaction = NULL;
    e->frame_slot = NULL;
    e->sealed = 0;
    free(e->snap_x); free(e->snap_theta); free(e->snap_f); free(e->snap_tq);
    e->snap_x = e->snap_theta = e->snap_f = e->snap_tq = NULL;
    e->frame = frame;
    if (!frame)
        return;
    for (q = 0; q < frame->n; ++q)
        e->kinematic[frame->particle[q]] = 1;
    e->snap_x = calloc(3 * nq, sizeof(double));
    e->snap_theta = malloc(sizeof(double) * nq);
    e->snap_f = calloc(3 * nq, sizeof(double));
    e->snap_tq = malloc(sizeof(double) * nq);
}

sbc_status sbc_engine_seal(sbc_engine *e, sbc_error *err)
{
    sbc_status st;
    if (!e->frame)
        return sbc_fail(err, SBC_ERR_INPUT, "engine: seal without a frame");
    e->seal_reaction = malloc(sizeof(double) * 3 * (size_t)e->frame->n);
    e->frame_slot = sbc_seal_slots(e->frame, e->n);
    if (!e->seal_reaction || !e->frame_slot)
        return sbc_fail(err, SBC_ERR_NOMEM, "engine: out of memory");
    st = sbc_seal_init(&e->seal, e->frame, e->pairs.skin, err);
    e->sealed = st == SBC_OK;
    return st;
}

/* seal.h: the walls' forces on the interior, their reactions on the frame
 * particles, and their energy in Ep */
static sbc_status seal_step(sbc_engine *e, sbc_error *err)
{
    const sbc_seal_particles p = sbc_seal_packed(e->n, e->x, e->f, 2, e->r, e->frame_slot);
    double energy;
    sbc_status st;
    sbc_frame_centres(e->frame, e->x, e->snap_x);
    st = sbc_seal_forces_packed(&e->seal, e->frame, e->snap_x, &p, e->law.kn, e->seal_reaction, &energy, err);
    e->ep += energy;
    return st;
}

/* Pair loop: eq. 6 forces and moments (eqs. 7-8 for intact bonds), eq. 12
 * energy, eq. 39 overlap sum, one pair at a time by pair_contact.h. HISTORY
 * and BONDS are compile-time constants in each instance, so that
 * frictionless scenes run without the tangential spring and unbonded scenes
 * without the bond test. */
static inline void pair_loop(sbc_engine *e, const int history, const int bonds)
{
    sbc_pair_laws L;
    const double *restrict x = e->x, *restrict v = e->v, *restrict om = e->omega, *restrict r = e->r;
    const int *restrict start = e->pairs.start, *restrict pj = e->pairs.j;
    double *restrict f = e->f, *restrict tq = e->tq, *restrict fsv = e->pairs.fs, *restrict mv = e->pairs.m;
    unsigned char *restrict bond = e->pairs.bond;
    sbc_pair_sums s = {0.0, 0.0, 0.0, 0, 0};
    int i, k, n = e->n;
    L.law = e->law;
    L.inv_ks = e->law.ks > 0.0 ? 1.0 / e->law.ks : 0.0;
    L.bond = e->bond_law;
    for (i = 0; i < n; ++i) {
        /* pairs (i, j > i) are contiguous: particle i's sums stay in registers */
        const double xi = x[2 * i], yi = x[2 * i + 1], ri = r[i];
        const double vxi = v[2 * i], vyi = v[2 * i + 1], wi = om[i], wri = ri * wi;
        double fxi = 0.0, fyi = 0.0, tqi = 0.0;
        const int end = start[i + 1];
        for (k = start[i]; k < end; ++k) {
            const int j = pj[k];
            double out[4];
            if (!sbc_pair_contact(&L, history, bonds, x[2 * j] - xi, x[2 * j + 1] - yi, ri, r[j], vxi, vyi, wi, wri,
                                  v[2 * j], v[2 * j + 1], om[j], e->dt, history ? &fsv[k] : NULL,
                                  bonds ? &mv[k] : NULL, bonds ? &bond[k] : NULL, &s, out))
                continue;
            if (history) {
                tqi += out[2];
                tq[j] += out[3];
            }
            fxi += out[0];
            fyi += out[1];
            f[2 * j] -= out[0];
            f[2 * j + 1] -= out[1];
        }
        f[2 * i] += fxi;
        f[2 * i + 1] += fyi;
        tq[i] += tqi;
    }
    e->ep = s.ep;
    e->contact_force_sum = s.fc;
    e->overlap_sum = 2.0 * s.ov; /* eq. 39 sums dn / Rbar_c = 2 dn / (R_i + R_j) */
    e->contact_count = s.nc;
    e->bond_count -= s.broken;
}

/* FIRE's sums (fire_damping.h) of the interior's contact forces and the
 * velocities the step starts from. */
void sbc_engine_fire_sums(const sbc_engine *e, double *sums)
{
    int k;
    for (k = 0; k < SBC_FIRE_SUMS; ++k)
        sums[k] = 0.0;
    for (k = 0; k < e->n; ++k)
        if (!e->kinematic[k])
            sbc_fire_add(sums, 2, &e->f[2 * k], &e->v[2 * k], &e->tq[k], &e->omega[k]);
}

/* Explicit first-order update of eq. 9 with the local damping of eq. 10:
 *   v += dt (f - alpha |f| sign(v)) / M,  x += dt v
 *   w += dt (m - beta |m| sign(w)) / I,   theta += dt w
 * or, with FIRE, v <- keep v + push f and w <- keep w + spin m first
 * (fire_damping.h) and no eq. 10. DAMPED (0 none, 1 eq. 10, 2 FIRE) is a
 * compile-time constant in each instance. Also records Ek of the
 * interior (eq. 12), sum |theta| (eq. 41) and whether a particle has moved
 * more than half the skin since the last neighbour build. */
static inline void integrate_interior(sbc_engine *e, const int damped, const sbc_fire_mix mix)
{
    const double dt = e->dt, a = e->alpha, b = e->beta;
    const double lim = 0.25 * e->pairs.skin * e->pairs.skin;
    double *restrict x = e->x, *restrict v = e->v, *restrict th = e->theta, *restrict om = e->omega;
    const double *restrict f = e->f, *restrict tq = e->tq, *restrict xb = e->pairs.x_build;
    const double *restrict inv_m = e->inv_m, *restrict inv_I = e->inv_I, *restrict mass = e->mass;
    const double *restrict r = e->r;
    const unsigned char *restrict kin = e->kinematic;
    double ek = 0.0, rot = 0.0, moved = 0.0, net = 0.0;
    int k;
    for (k = 0; k < e->n; ++k) {
        double fx = f[2 * k], fy = f[2 * k + 1], m = tq[k], vx, vy, w, ddx, ddy;
        if (kin[k])
            continue;
        vx = v[2 * k];
        vy = v[2 * k + 1];
        w = om[k];
        net = fmax(net, fx * fx + fy * fy); /* relax.h: the largest net force, squared */
        if (damped == 2) {
            const double push = sbc_fire_factor(mix.push, &mix, dt * inv_m[k]);
            const double spin = sbc_fire_factor(mix.spin, &mix, dt * inv_I[k]);
            vx = sbc_fire_velocity(&mix, push, vx, fx);
            vy = sbc_fire_velocity(&mix, push, vy, fy);
            w = sbc_fire_velocity(&mix, spin, w, m);
        } else if (damped) {
            fx = sbc_damp_local(fx, vx, a);
            fy = sbc_damp_local(fy, vy, a);
            m = sbc_damp_local(m, w, b);
        }
        vx = sbc_flush(vx + dt * fx * inv_m[k]);
        vy = sbc_flush(vy + dt * fy * inv_m[k]);
        w = sbc_flush(w + dt * m * inv_I[k]);
        v[2 * k] = vx;
        v[2 * k + 1] = vy;
        om[k] = w;
        x[2 * k] += dt * vx;
        x[2 * k + 1] += dt * vy;
        th[k] += dt * w;
        /* Ek of eq. 12 over the particles that carry force: a disc without contacts
         * (a rattler) keeps its speed and spin, since the damping of eq. 10 acts
         * through the force, and would hold Ek up for good */
        if (fx != 0.0 || fy != 0.0 || m != 0.0) {
            const double vk[2] = {vx, vy};
            ek += sbc_kinetic_energy(2, mass[k], 0.5 * mass[k] * r[k] * r[k], vk, &w); /* I = M R^2 / 2 (eq. 9) */
        }
        rot += fabs(th[k]);
        ddx = x[2 * k] - xb[2 * k];
        ddy = x[2 * k + 1] - xb[2 * k + 1];
        if (ddx * ddx + ddy * ddy > moved)
            moved = ddx * ddx + ddy * ddy;
    }
    e->ek = ek;
    e->net_max = sqrt(net);
    e->rotation_sum = rot;
    if (moved > lim)
        e->stale = 1;
}

/* The contact forces and moments at the present centres (a stale pair list
 * rebuilt first), into f and tq. */
static sbc_status pair_forces(sbc_engine *e, sbc_error *err)
{
    if (e->stale && sbc_pairs_build(&e->pairs, e->x, e->r, e->rmax, err) != SBC_OK)
        return err->status;
    e->stale = 0;
    memset(e->f, 0, sizeof(double) * 2 * (size_t)e->n);
    memset(e->tq, 0, sizeof(double) * (size_t)e->n);
    if (e->bonded)
        pair_loop(e, 1, 1);
    else if (e->history)
        pair_loop(e, 1, 0);
    else
        pair_loop(e, 0, 0);
    return SBC_OK;
}

sbc_status sbc_engine_forces(sbc_engine *e, sbc_error *err)
{
    if (pair_forces(e, err) != SBC_OK)
        return err->status;
    if (e->sealed && seal_step(e, err) != SBC_OK)
        return err->status;
    return SBC_OK;
}

void sbc_engine_integrate(sbc_engine *e, const sbc_fire_mix *mix)
{
    static const sbc_fire_mix none = {1.0, 0.0, 0.0, 0.0};
    if (mix)
        integrate_interior(e, 2, *mix);
    else if (e->alpha > 0.0 || e->beta > 0.0)
        integrate_interior(e, 1, none);
    else
        integrate_interior(e, 0, none);
    e->step++;
}

/* One time step: forces at x^n, then the interior to x^(n+1). */
sbc_status sbc_engine_step(sbc_engine *e, sbc_error *err)
{
    if (sbc_engine_forces(e, err) != SBC_OK)
        return err->status;
    if (e->fire) {
        double sums[SBC_FIRE_SUMS];
        sbc_fire_mix mix;
        sbc_engine_fire_sums(e, sums);
        mix = sbc_fire_step(&e->fire_state, sums);
        sbc_engine_integrate(e, &mix);
    } else {
        sbc_engine_integrate(e, NULL);
    }
    return SBC_OK;
}

void sbc_engine_snapshot(sbc_engine *e, sbc_snapshot *s)
{
    const sbc_frame *fr = e->frame;
    int q;
    memset(s, 0, sizeof *s);
    if (fr) {
        for (q = 0; q < fr->n; ++q) {
            int p = fr->particle[q];
            e->snap_x[3 * q] = e->x[2 * p];
            e->snap_x[3 * q + 1] = e->x[2 * p + 1];
            e->snap_f[3 * q] = e->f[2 * p];
            e->snap_f[3 * q + 1] = e->f[2 * p + 1];
            e->snap_theta[q] = e->theta[p];
            e->snap_tq[q] = e->tq[p];
        }
    }
    s->x = e->snap_x;
    s->theta = e->snap_theta;
    s->force = e->snap_f;
    s->torque = e->snap_tq;
    s->kinetic_energy = e->ek;
    s->potential_energy = e->ep;
    s->unbalanced_max = e->net_max;
    s->contact_force_sum = e->contact_force_sum;
    s->overlap_sum = e->overlap_sum;
    s->contact_count = e->contact_count;
    s->rotation_sum = e->rotation_sum;
    s->particle_count = e->n;
}

/* Frame particles are placed on their targets, with the velocity that moves
 * them there in this step (so that contact increments see the motion). */
void sbc_engine_move_frame(sbc_engine *e, const sbc_commands *cmd)
{
    const double dt = e->dt, lim = 0.25 * e->pairs.skin * e->pairs.skin;
    double *x = e->x, *v = e->v, *th = e->theta, *om = e->omega;
    int q;
    if (!e->frame)
        return;
    for (q = 0; q < e->frame->n; ++q) {
        int p = e->frame->particle[q];
        double ddx, ddy;
        if (cmd) {
            v[2 * p] = (cmd->x[3 * q] - x[2 * p]) / dt;
            v[2 * p + 1] = (cmd->x[3 * q + 1] - x[2 * p + 1]) / dt;
            x[2 * p] = cmd->x[3 * q];
            x[2 * p + 1] = cmd->x[3 * q + 1];
            if (cmd->free_rotation[q]) {
                /* free rotation (T): integrated with the rotational damping of eq. 10 */
                const double m = sbc_damp_local(e->tq[p], om[p], e->beta);
                om[p] = sbc_flush(om[p] + dt * m * e->inv_I[p]);
                th[p] += dt * om[p];
            } else {
                om[p] = (cmd->theta[q] - th[p]) / dt;
                th[p] = cmd->theta[q];
            }
        } else {
            v[2 * p] = v[2 * p + 1] = om[p] = 0.0;
        }
        e->rotation_sum += fabs(th[p]);
        ddx = x[2 * p] - e->pairs.x_build[2 * p];
        ddy = x[2 * p + 1] - e->pairs.x_build[2 * p + 1];
        if (ddx * ddx + ddy * ddy > lim)
            e->stale = 1;
    }
}

sbc_engine_view sbc_engine_get_view(const sbc_engine *e)
{
    sbc_engine_view w;
    w.n = e->n;
    w.x = e->x;
    w.v = e->v;
    w.r = e->r;
    w.theta = e->theta;
    w.omega = e->omega;
    w.mass = e->mass;
    w.f = e->f;
    w.torque = e->tq;
    w.kinematic = e->kinematic;
    w.pair_count = e->pairs.count;
    w.pair_i = e->pairs.i;
    w.pair_j = e->pairs.j;
    w.pair_bond = e->pairs.bond;
    w.pair_fs = e->pairs.fs;
    w.pair_m = e->pairs.m;
    w.bond_count = e->bond_count;
    w.bonds_initial = e->bonds_initial;
    w.law = e->law;
    w.step = e->step;
    w.time = (double)e->step * e->dt;
    return w;
}

sbc_status sbc_engine_host_loads(sbc_engine *e, const double *x, const double *v, const double *omega, double dt,
                                 sbc_error *err)
{
    const double lim = 0.25 * e->pairs.skin * e->pairs.skin;
    const size_t n = (size_t)e->n;
    int k;
    if (!(dt > 0.0) || !isfinite(dt))
        return sbc_fail(err, SBC_ERR_INPUT, "engine: time step %g s (expected > 0)", dt);
    memcpy(e->x, x, sizeof(double) * 2 * n);
    memcpy(e->v, v, sizeof(double) * 2 * n);
    memcpy(e->omega, omega, sizeof(double) * n);
    e->dt = dt;
    for (k = 0; k < e->n && !e->stale; ++k) {
        const double ddx = x[2 * k] - e->pairs.x_build[2 * k], ddy = x[2 * k + 1] - e->pairs.x_build[2 * k + 1];
        if (!(ddx * ddx + ddy * ddy <= lim)) /* also a non-finite centre: the build reports it */
            e->stale = 1;
    }
    if (pair_forces(e, err) != SBC_OK)
        return err->status;
    e->step++;
    return SBC_OK;
}

int sbc_engine_pair_records(const sbc_engine *e, double *out)
{
    const sbc_pairs *p = &e->pairs;
    int k, count = 0;
    for (k = 0; p->fs && k < p->count; ++k) {
        const int bond = p->bond ? p->bond[k] : 0;
        const double m = p->m ? p->m[k] : 0.0;
        if (!bond && p->fs[k] == 0.0 && m == 0.0)
            continue;
        if (out) {
            double *o = &out[SBC_PAIR_RECORD * count];
            o[0] = p->i[k];
            o[1] = p->j[k];
            o[2] = bond;
            o[3] = p->fs[k];
            o[4] = m;
        }
        ++count;
    }
    return count;
}

void sbc_engine_place(sbc_engine *e, const double *x, const double *theta)
{
    const size_t n = (size_t)e->n;
    memcpy(e->x, x, sizeof(double) * 2 * n);
    memcpy(e->theta, theta, sizeof(double) * n);
    memset(e->v, 0, sizeof(double) * 2 * n);
    memset(e->omega, 0, sizeof(double) * n);
    e->stale = 1;
}

sbc_status sbc_engine_set_pair_records(sbc_engine *e, const double *rec, int count, int bonds_initial,
                                       sbc_error *err)
{
    sbc_pairs *p = &e->pairs;
    int k, c, bonds = 0;
    if (!p->fs)
        return count ? sbc_fail(err, SBC_ERR_INPUT, "engine: %d pair records for a scene without pair state", count)
                     : SBC_OK;
    for (k = 0; k < p->count; ++k) {
        p->fs[k] = 0.0;
        if (p->bond) {
            p->bond[k] = 0;
            p->m[k] = 0.0;
        }
    }
    if (sbc_pairs_build(p, e->x, e->r, e->rmax, err) != SBC_OK)
        return err->status;
    e->stale = 0;
    for (c = 0; c < count; ++c) {
        const double *o = &rec[SBC_PAIR_RECORD * c];
        const int i = (int)o[0], j = (int)o[1];
        int lo, hi;
        if (!(o[0] >= 0.0 && o[0] < o[1] && o[1] < e->n) || !(o[2] == 0.0 || (o[2] == 1.0 && p->bond)) ||
            !isfinite(o[3]) || !isfinite(o[4]))
            return sbc_fail(err, SBC_ERR_INPUT, "engine: pair record %d (%g %g %g %g %g) is not valid", c, o[0], o[1],
                            o[2], o[3], o[4]);
        /* pairs of i are sorted by j (neighbor.h) */
        for (lo = p->start[i], hi = p->start[i + 1]; lo < hi;) {
            const int mid = lo + (hi - lo) / 2;
            if (p->j[mid] < j)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo == p->start[i + 1] || p->j[lo] != j)
            return sbc_fail(err, SBC_ERR_INPUT,
                            "engine: pair record %d: particles %d and %d are farther apart than the pair list reaches",
                            c, i, j);
        p->fs[lo] = o[3];
        if (p->bond) {
            p->bond[lo] = (unsigned char)o[2];
            p->m[lo] = o[4];
            bonds += p->bond[lo];
        }
    }
    e->bond_count = bonds;
    e->bonds_initial = bonds_initial;
    return SBC_OK;
}

void sbc_engine_frame_masses(const sbc_engine *e, double *mass)
{
    int q;
    for (q = 0; e->frame && q < e->frame->n; ++q)
        mass[q] = e->mass[e->frame->particle[q]];
}

double sbc_engine_critical_dt(const sbc_engine *e)
{
    double mmin = DBL_MAX;
    double dtc, imin = DBL_MAX;
    int k;
    for (k = 0; k < e->n; ++k) {
        if (e->mass[k] < mmin) mmin = e->mass[k];
        if (1.0 / e->inv_I[k] < imin) imin = 1.0 / e->inv_I[k];
    }
    dtc = 2.0 * sqrt(mmin / (2.0 * e->law.kn));
    if (e->bonded && e->bond_law.kr > 0.0 && 2.0 * sqrt(imin / (2.0 * e->bond_law.kr)) < dtc)
        dtc = 2.0 * sqrt(imin / (2.0 * e->bond_law.kr));
    return dtc;
}

/* ---- the driver's callbacks (sbc_engine_callbacks) ---- */

static void cb_fire_sums(void *user_data, double *sums) { sbc_engine_fire_sums(user_data, sums); }

static void cb_interior(void *user_data, const sbc_fire_mix *mix, int again, double out[2])
{
    sbc_engine *e = user_data;
    (void)again; /* the engine never revisits a step */
    sbc_engine_integrate(e, mix);
    sbc_engine_snapshot(e, &e->snap);
    out[0] = e->snap.kinetic_energy;
    out[1] = e->snap.unbalanced_max;
}

static void cb_contacts(void *user_data, double out[4])
{
    const sbc_snapshot *s = &((const sbc_engine *)user_data)->snap;
    out[0] = s->potential_energy;
    out[1] = s->overlap_sum;
    out[2] = (double)s->contact_count;
    out[3] = s->contact_force_sum;
}

static void cb_frame(void *user_data, double *buf)
{
    const sbc_engine *e = user_data;
    sbc_driver_frame_from_snapshot(&e->snap, e->frame->dim, e->frame->n, buf);
}

static int cb_confined(void *user_data, const double *fx, int increment, char *message, size_t cap)
{
    const sbc_engine *e = user_data;
    sbc_confine c;
    sbc_error err;
    sbc_status st = SBC_OK;
    int k;
    sbc_confine_prepare(&c, e->frame, fx);
    for (k = 0; k < e->n && st == SBC_OK; ++k)
        if (!isfinite(e->x[2 * k]) || !isfinite(e->x[2 * k + 1]))
            st = sbc_confine_check(&c, increment, k, &e->x[2 * k], &e->v[2 * k], &err);
    for (k = 0; k < e->n && st == SBC_OK; ++k)
        if (!e->kinematic[k])
            st = sbc_confine_check(&c, increment, k, &e->x[2 * k], &e->v[2 * k], &err);
    if (st != SBC_OK)
        snprintf(message, cap, "%s", err.message);
    return st;
}

/* keyword remap x (driver.h): the interior moves with the frame's affine
   move now and carries its velocity, kept in e->stream, into the next
   contact forces; a disc carried beyond half the skin since the last build
   stales the list */
static void cb_remap(void *user_data, const double *M, const double *origin, int sign)
{
    sbc_engine *e = user_data;
    const double lim = 0.25 * e->pairs.skin * e->pairs.skin;
    int k, c;
    if (sign < 0) {
        if (e->streaming)
            for (k = 0; k < 2 * e->n; ++k) {
                e->v[k] -= e->stream[k];
                e->stream[k] = 0.0;
            }
        e->streaming = 0;
        return;
    }
    if (!e->stream && !(e->stream = calloc(2 * (size_t)e->n, sizeof(double))))
        return; /* out of memory: the interior waits for the frame, as without remap */
    for (k = 0; k < e->n; ++k)
        if (!e->kinematic[k]) {
            const double *xb = &e->pairs.x_build[2 * k];
            double *x = &e->x[2 * k], u[2];
            sbc_remap_displacement(2, M, origin, x, u);
            for (c = 0; c < 2; ++c) {
                e->stream[2 * k + c] = u[c] / e->dt;
                e->v[2 * k + c] += e->stream[2 * k + c];
                x[c] += u[c];
            }
            if ((x[0] - xb[0]) * (x[0] - xb[0]) + (x[1] - xb[1]) * (x[1] - xb[1]) > lim)
                e->stale = 1;
        }
    e->streaming = 1;
}

sbc_driver_callbacks sbc_engine_callbacks(sbc_engine *e)
{
    sbc_driver_callbacks cb;
    memset(&cb, 0, sizeof cb);
    cb.user_data = e;
    cb.fire_sums = cb_fire_sums;
    cb.interior = cb_interior;
    cb.contacts = cb_contacts;
    cb.frame = cb_frame;
    cb.confined = cb_confined;
    cb.remap = cb_remap;
    return cb;
}
