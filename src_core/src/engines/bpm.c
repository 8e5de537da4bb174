/* servo_bc: the embedded 3D bonded particle engine (thesis Chapter 3). */
#include "sbc/bpm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sbc_bpm_settings sbc_bpm_settings_default(void)
{
    sbc_bpm_settings s;
    memset(&s, 0, sizeof s);
    s.model = SBC_BOND_BEAM;
    s.beam.E = 4e9;
    s.beam.nu = 0.3;
    s.parallel = sbc_bpm_parallel_law(4e9, 5e-3, 4.2);
    s.alpha = 1.0;
    s.xi = 0.0;
    s.touch = 1e-9;
    return s;
}

sbc_parallel_bond_law sbc_bpm_parallel_law(double E, double rp, double kn_over_ks)
{
    sbc_parallel_bond_law law;
    law.kn = E / (2.0 * rp);
    law.ks = law.kn / kn_over_ks;
    return law;
}

sbc_status sbc_bpm_create(const sbc_bpm_settings *set, sbc_bpm **out, sbc_error *err)
{
    sbc_bpm *e;
    *out = NULL;
    if (set->alpha <= 0.0 || set->alpha > 1.0)
        return sbc_fail(err, SBC_ERR_INPUT, "bond radius multiplier %g is out of range (expected 0 < alpha <= 1)",
                        set->alpha);
    if (set->strength.tension > 0.0 && (set->strength.shear < 0.0 || set->strength.bending < 0.0 ||
                                        set->strength.twisting < 0.0 || set->mu < 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "bond strength: shear %g, bending %g, twisting %g, friction %g (expected "
                        "values >= 0)", set->strength.shear, set->strength.bending, set->strength.twisting, set->mu);
    if (set->xi < 0.0)
        return sbc_fail(err, SBC_ERR_INPUT, "damping ratio %g is negative", set->xi);
    if (set->model == SBC_BOND_BEAM && (set->beam.E <= 0.0 || set->beam.nu <= -1.0 || set->beam.nu >= 0.5))
        return sbc_fail(err, SBC_ERR_INPUT, "beam E %g, nu %g (expected E > 0, -1 < nu < 0.5)", set->beam.E,
                        set->beam.nu);
    if (set->model == SBC_BOND_PARALLEL && (set->parallel.kn <= 0.0 || set->parallel.ks < 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "parallel bond k^n %g, k^s %g (expected k^n > 0, k^s >= 0)",
                        set->parallel.kn, set->parallel.ks);
    e = calloc(1, sizeof *e);
    if (!e)
        return sbc_fail(err, SBC_ERR_NOMEM, "out of memory for the 3D engine");
    e->set = *set;
    *out = e;
    return SBC_OK;
}

void sbc_bpm_free(sbc_bpm *e)
{
    if (!e)
        return;
    free(e->x);
    free(e->v);
    free(e->w);
    free(e->theta);
    free(e->r);
    free(e->m);
    free(e->inertia);
    free(e->fext);
    free(e->fix);
    free(e->vfix);
    free(e->reaction);
    free(e->load);
    free(e->fwork_prev);
    free(e->fdamp);
    free(e->fdamp_prev);
    free(e->coordination);
    free(e->bonds);
    free(e->parallel);
    free(e->beam);
    free(e->broken);
    free(e->contact);
    free(e);
}

static int grow(void **p, size_t count, size_t size)
{
    void *q = realloc(*p, count * size);
    if (!q)
        return 0;
    *p = q;
    return 1;
}

static int reserve(sbc_bpm *e, size_t cap)
{
    if (cap <= e->cap)
        return 1;
    if (!grow((void **)&e->x, 3 * cap, sizeof(double)) || !grow((void **)&e->v, 3 * cap, sizeof(double)) ||
        !grow((void **)&e->w, 3 * cap, sizeof(double)) || !grow((void **)&e->theta, 3 * cap, sizeof(double)) ||
        !grow((void **)&e->r, cap, sizeof(double)) || !grow((void **)&e->m, cap, sizeof(double)) ||
        !grow((void **)&e->inertia, cap, sizeof(double)) || !grow((void **)&e->fext, 6 * cap, sizeof(double)) ||
        !grow((void **)&e->fix, cap, 1) || !grow((void **)&e->vfix, 6 * cap, sizeof(double)) ||
        !grow((void **)&e->reaction, 6 * cap, sizeof(double)) || !grow((void **)&e->load, 6 * cap, sizeof(double)) ||
        !grow((void **)&e->fwork_prev, 6 * cap, sizeof(double)) ||
        !grow((void **)&e->fdamp, 3 * cap, sizeof(double)) || !grow((void **)&e->fdamp_prev, 3 * cap, sizeof(double)) ||
        !grow((void **)&e->coordination, cap, sizeof(unsigned)))
        return 0;
    e->cap = cap;
    return 1;
}

sbc_status sbc_bpm_add(sbc_bpm *e, const double x[3], double r, double rho, size_t *index, sbc_error *err)
{
    size_t i = e->n;
    int k;
    if (!(r > 0.0) || !(rho > 0.0) || !isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
        return sbc_fail(err, SBC_ERR_INPUT, "sphere %zu: radius %g, density %g, position (%g, %g, %g) "
                        "(expected r > 0, rho > 0, a finite position)", i + 1, r, rho, x[0], x[1], x[2]);
    if (!reserve(e, e->cap ? (i + 1 > e->cap ? 2 * e->cap : e->cap) : 64))
        return sbc_fail(err, SBC_ERR_NOMEM, "out of memory for %zu spheres", i + 1);
    for (k = 0; k < 3; ++k) {
        e->x[3 * i + k] = x[k];
        e->v[3 * i + k] = e->w[3 * i + k] = e->theta[3 * i + k] = 0.0;
        e->fdamp_prev[3 * i + k] = 0.0;
    }
    for (k = 0; k < 6; ++k)
        e->fext[6 * i + k] = e->vfix[6 * i + k] = e->reaction[6 * i + k] = e->load[6 * i + k] =
            e->fwork_prev[6 * i + k] = 0.0;
    e->r[i] = r;
    e->m[i] = rho * 4.0 / 3.0 * SBC_PI * r * r * r;
    e->inertia[i] = 0.4 * e->m[i] * r * r; /* eq. 42 */
    e->fix[i] = 0;
    e->coordination[i] = 0;
    e->n = i + 1;
    if (index)
        *index = i;
    return SBC_OK;
}

/* bond k of the engine as a view */
static sbc_bpm_bond_view view_of(const sbc_bpm *e, size_t k)
{
    sbc_bpm_bond_view b;
    b.beam = e->beam ? &e->beam[k] : NULL;
    b.parallel = e->parallel ? &e->parallel[k] : NULL;
    b.broken = e->broken ? &e->broken[k] : NULL;
    b.contact = e->contact ? &e->contact[k] : NULL;
    return b;
}

int sbc_bpm_touch(const sbc_bpm_settings *set, const double xa[3], double ra, const double xb[3], double rb)
{
    double d = 0.0, reach = (ra + rb) * (1.0 + set->touch);
    int k;
    for (k = 0; k < 3; ++k) {
        double dx = xb[k] - xa[k];
        d += dx * dx;
    }
    return d <= reach * reach;
}

void sbc_bpm_bond_start(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b, const double xa[3], double ra,
                        const double xb[3], double rb)
{
    double rbond = set->alpha * (ra < rb ? ra : rb); /* eq. 9 */
    if (b->broken) {
        *b->broken = 0;
        memset(b->contact, 0, sizeof *b->contact);
    }
    if (set->model == SBC_BOND_PARALLEL) {
        memset(b->parallel, 0, sizeof *b->parallel);
        b->parallel->rb = rbond;
    } else {
        sbc_beam_bond_init(&set->beam, rbond, xa, xb, b->beam);
    }
}

double sbc_bpm_bond_stiffness(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b)
{
    if (set->model == SBC_BOND_PARALLEL)
        return set->parallel.kn * sbc_bond_area(b->parallel->rb);
    return b->beam->k[0];
}

static sbc_status add_bond(size_t a, size_t b, void *user, sbc_error *err)
{
    sbc_bpm *e = user;
    int parallel = e->set.model == SBC_BOND_PARALLEL;
    if (e->nb == e->bcap) {
        size_t cap = e->bcap ? 2 * e->bcap : 256;
        if (!grow((void **)&e->bonds, cap, sizeof *e->bonds) ||
            !(parallel ? grow((void **)&e->parallel, cap, sizeof *e->parallel)
                       : grow((void **)&e->beam, cap, sizeof *e->beam)) ||
            (e->set.strength.tension > 0.0 && (!grow((void **)&e->broken, cap, 1) ||
                                               !grow((void **)&e->contact, cap, sizeof *e->contact))))
            return sbc_fail(err, SBC_ERR_NOMEM, "out of memory for %zu bonds", cap);
        e->bcap = cap;
    }
    memset(&e->bonds[e->nb], 0, sizeof e->bonds[e->nb]);
    e->bonds[e->nb].a = a;
    e->bonds[e->nb].b = b;
    sbc_bpm_bond_view v = view_of(e, e->nb);
    sbc_bpm_bond_start(&e->set, &v, &e->x[3 * a], e->r[a], &e->x[3 * b], e->r[b]);
    ++e->nb;
    ++e->coordination[a];
    ++e->coordination[b];
    return SBC_OK;
}

sbc_status sbc_bpm_pairs(const sbc_bpm_settings *set, size_t n, const double *x, const double *r,
                         sbc_bpm_pair_fn found, void *user, sbc_error *err)
{
    double lo[3], hi[3], cell, rmax = 0.0;
    size_t nc[3], ncells, i, *head = NULL, *next = NULL, k;
    sbc_status st = SBC_OK;
    if (n == 0)
        return SBC_OK;
    for (k = 0; k < 3; ++k)
        lo[k] = hi[k] = x[k];
    for (i = 0; i < n; ++i) {
        for (k = 0; k < 3; ++k) {
            if (x[3 * i + k] < lo[k]) lo[k] = x[3 * i + k];
            if (x[3 * i + k] > hi[k]) hi[k] = x[3 * i + k];
        }
        if (r[i] > rmax) rmax = r[i];
    }
    cell = 2.0 * rmax * (1.0 + set->touch) * (1.0 + 1e-12);
    ncells = 1;
    for (k = 0; k < 3; ++k) {
        double span = (hi[k] - lo[k]) / cell;
        nc[k] = span < 1e6 ? (size_t)span + 1 : 1000000;
        ncells *= nc[k];
    }
    if (ncells > 8 * n + 64) { /* sparse spheres: a coarser grid */
        double f = cbrt((double)ncells / (double)(8 * n + 64));
        cell *= f;
        ncells = 1;
        for (k = 0; k < 3; ++k) {
            nc[k] = (size_t)((hi[k] - lo[k]) / cell) + 1;
            ncells *= nc[k];
        }
    }
    head = malloc(ncells * sizeof *head);
    next = malloc(n * sizeof *next);
    if (!head || !next) {
        free(head);
        free(next);
        return sbc_fail(err, SBC_ERR_NOMEM, "out of memory for the bonding grid (%zu cells)", ncells);
    }
    for (k = 0; k < ncells; ++k)
        head[k] = (size_t)-1;
    for (i = 0; i < n; ++i) {
        size_t c[3], id;
        for (k = 0; k < 3; ++k) {
            c[k] = (size_t)((x[3 * i + k] - lo[k]) / cell);
            if (c[k] >= nc[k]) c[k] = nc[k] - 1;
        }
        id = (c[2] * nc[1] + c[1]) * nc[0] + c[0];
        next[i] = head[id];
        head[id] = i;
    }
    for (i = 0; i < n && st == SBC_OK; ++i) {
        long c[3], d0, d1, d2;
        for (k = 0; k < 3; ++k) {
            c[k] = (long)((x[3 * i + k] - lo[k]) / cell);
            if (c[k] >= (long)nc[k]) c[k] = (long)nc[k] - 1;
        }
        for (d2 = -1; d2 <= 1 && st == SBC_OK; ++d2)
            for (d1 = -1; d1 <= 1 && st == SBC_OK; ++d1)
                for (d0 = -1; d0 <= 1 && st == SBC_OK; ++d0) {
                    long q0 = c[0] + d0, q1 = c[1] + d1, q2 = c[2] + d2;
                    size_t j;
                    if (q0 < 0 || q1 < 0 || q2 < 0 || q0 >= (long)nc[0] || q1 >= (long)nc[1] || q2 >= (long)nc[2])
                        continue;
                    for (j = head[((size_t)q2 * nc[1] + (size_t)q1) * nc[0] + (size_t)q0]; j != (size_t)-1;
                         j = next[j])
                        if (j > i && sbc_bpm_touch(set, &x[3 * i], r[i], &x[3 * j], r[j]) &&
                            (st = found(i, j, user, err)) != SBC_OK)
                            break;
                }
    }
    free(head);
    free(next);
    return st;
}

sbc_status sbc_bpm_bond_touching(sbc_bpm *e, sbc_error *err)
{
    size_t k;
    sbc_status st = sbc_bpm_pairs(&e->set, e->n, e->x, e->r, add_bond, e, err);
    if (st != SBC_OK)
        return st;
    for (k = 0; k < e->nb; ++k) { /* eq. 37 */
        sbc_bpm_bond *bd = &e->bonds[k];
        double cn = 0.5 * (e->coordination[bd->a] + e->coordination[bd->b]);
        sbc_bpm_bond_view v = view_of(e, k);
        bd->c = sbc_bond_damping(e->set.xi, sbc_bpm_bond_stiffness(&e->set, &v), e->m[bd->a], e->m[bd->b], cn);
    }
    return SBC_OK;
}

double sbc_bpm_critical_dt(const sbc_bpm *e)
{
    double mmin = 0.0, kmax = 0.0;
    size_t i;
    for (i = 0; i < e->n; ++i)
        if (i == 0 || e->m[i] < mmin)
            mmin = e->m[i];
    for (i = 0; i < e->nb; ++i) {
        sbc_bpm_bond_view v = view_of(e, i);
        double k = sbc_bpm_bond_stiffness(&e->set, &v);
        if (k > kmax)
            kmax = k;
    }
    return sbc_bpm_critical_dt_of(mmin, kmax);
}

double sbc_bpm_critical_dt_of(double mmin, double kmax)
{
    return kmax > 0.0 ? 0.22 * sqrt(mmin / kmax) : 0.0; /* eq. 48 */
}

/* contact law of a bond once broken */
static sbc_friction_law broken_law(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b)
{
    sbc_friction_law law;
    law.kn = sbc_bpm_bond_stiffness(set, b);
    law.ks = set->model == SBC_BOND_PARALLEL ? law.kn * set->parallel.ks / set->parallel.kn
                                             : law.kn / (2.0 * (1.0 + set->beam.nu));
    law.mu = set->mu;
    return law;
}

/* strain energy an intact bond holds, J */
static double bond_energy(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b)
{
    return set->model == SBC_BOND_BEAM ? b->beam->w : sbc_parallel_bond_energy(&set->parallel, b->parallel);
}

/* the bond fails: its loads vanish; returns the energy it held (dissipated) */
static double break_bond(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b)
{
    double w = bond_energy(set, b);
    if (set->model == SBC_BOND_BEAM) {
        memset(b->beam->f, 0, sizeof b->beam->f);
        b->beam->w = 0.0;
    } else {
        double rb = b->parallel->rb;
        memset(b->parallel, 0, sizeof *b->parallel);
        b->parallel->rb = rb;
    }
    *b->broken = 1;
    memset(b->contact, 0, sizeof *b->contact);
    return w;
}

int sbc_bpm_bond_advance(const sbc_bpm_settings *set, const sbc_bpm_bond_view *bv, const double xa[3], double ra,
                         const double va[3], const double wa_[3], const double xb[3], double rb, const double vb[3],
                         const double wb_[3], double dt, double fa[3], double ma[3], double fb[3], double mb[3],
                         double *fracture)
{
    double dxa[3], dta[3], dxb[3], dtb[3], xc[3], n[3], ra_[3], rb_[3], wa[3], wb[3], du[3], dth[3], L = 0.0;
    int q, beam = set->model == SBC_BOND_BEAM, failure = set->strength.tension > 0.0;
    int broken = failure && *bv->broken;
    for (q = 0; q < 3; ++q) {
        dxa[q] = dt * va[q];
        dta[q] = dt * wa_[q];
        dxb[q] = dt * vb[q];
        dtb[q] = dt * wb_[q];
    }
    if (!beam || broken) { /* the contact point's motion, eqs. 14-15 */
        L = sbc_parallel_bond_geometry(xa, ra, xb, rb, n, xc);
        for (q = 0; q < 3; ++q) {
            ra_[q] = xc[q] - xa[q];
            rb_[q] = xc[q] - xb[q];
        }
        sbc_cross3(dta, ra_, wa);
        sbc_cross3(dtb, rb_, wb);
        for (q = 0; q < 3; ++q) {
            du[q] = (dxa[q] + wa[q]) - (dxb[q] + wb[q]);
            dth[q] = dta[q] - dtb[q];
        }
    }
    if (broken) {
        sbc_friction_law law = broken_law(set, bv);
        double f[3], tf[3];
        sbc_broken_bond_increment(&law, bv->contact, ra + rb - L, n, du, f);
        for (q = 0; q < 3; ++q) {
            fa[q] += f[q];
            fb[q] -= f[q];
        }
        sbc_cross3(ra_, f, tf); /* eq. 20 */
        for (q = 0; q < 3; ++q) ma[q] += tf[q];
        sbc_cross3(f, rb_, tf); /* (xc - xb) x (-f) */
        for (q = 0; q < 3; ++q) mb[q] += tf[q];
        return 0;
    }
    if (beam)
        sbc_beam_bond_increment(bv->beam, dxa, dta, dxb, dtb);
    else
        sbc_parallel_bond_increment(&set->parallel, bv->parallel, n, du, dth);
    if (failure) {
        double l[4];
        if (beam) sbc_beam_bond_loads(bv->beam, l);
        else sbc_parallel_bond_loads(bv->parallel, n, l);
        if (sbc_bond_criterion(&set->strength, l[0], l[1], l[2], l[3]) >= 1.0) {
            *fracture = break_bond(set, bv);
            return 1;
        }
    }
    if (beam)
        sbc_beam_bond_apply(bv->beam, fa, ma, fb, mb);
    else
        sbc_parallel_bond_apply(bv->parallel, xa, xb, xc, fa, ma, fb, mb);
    return 0;
}

void sbc_bpm_bond_energies(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b, const double xa[3], double ra,
                           const double xb[3], double rb, double *strain, double *friction)
{
    if (b->broken && *b->broken) { /* elastic part as strain, the rest (friction) dissipated */
        sbc_friction_law law = broken_law(set, b);
        double n[3], xc[3], L = sbc_parallel_bond_geometry(xa, ra, xb, rb, n, xc);
        double el = sbc_broken_bond_energy(&law, b->contact, ra + rb - L);
        *strain = el;
        *friction = b->contact->w - el;
    } else {
        *strain = bond_energy(set, b);
        *friction = 0.0;
    }
}

/* Bond loads at t from the increments dt v(t - dt/2), eqs. 10-34; adds the
 * forces to load (6 per sphere). */
void sbc_bpm_bond_loads(sbc_bpm *e, double *load)
{
    size_t k;
    for (k = 0; k < e->nb; ++k) {
        size_t a = e->bonds[k].a, b = e->bonds[k].b;
        double w = 0.0;
        sbc_bpm_bond_view v = view_of(e, k);
        if (sbc_bpm_bond_advance(&e->set, &v, &e->x[3 * a], e->r[a], &e->v[3 * a], &e->w[3 * a],
                                 &e->x[3 * b], e->r[b], &e->v[3 * b], &e->w[3 * b], e->dt, &load[6 * a],
                                 &load[6 * a + 3], &load[6 * b], &load[6 * b + 3], &w)) {
            e->w_fracture += w;
            ++e->nbroken;
        }
    }
}

/* Dashpot forces from v(t - dt/2), eq. 35; written to fdamp (3 per sphere). */
static void dashpot_forces(sbc_bpm *e, double *fdamp)
{
    size_t k;
    memset(fdamp, 0, 3 * e->n * sizeof *fdamp);
    for (k = 0; k < e->nb; ++k) {
        const sbc_bpm_bond *bd = &e->bonds[k];
        int q;
        if (bd->c == 0.0)
            continue;
        for (q = 0; q < 3; ++q) {
            double f = -bd->c * (e->v[3 * bd->a + q] - e->v[3 * bd->b + q]);
            fdamp[3 * bd->a + q] += f;
            fdamp[3 * bd->b + q] -= f;
        }
    }
}

sbc_status sbc_bpm_step(sbc_bpm *e, sbc_error *err)
{
    double *load = e->load, *fdamp = e->fdamp, dt = e->dt, kin = 0.0;
    size_t i;
    int k;
    if (!(dt > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "3D engine: time step %g (expected > 0)", dt);
    memset(load, 0, 6 * e->n * sizeof *load);
    sbc_bpm_bond_loads(e, load);
    dashpot_forces(e, fdamp);
    for (i = 0; i < e->n; ++i) {
        for (k = 0; k < 6; ++k) {
            size_t d = 6 * i + (size_t)k;
            double *vel = k < 3 ? &e->v[3 * i + (size_t)k] : &e->w[3 * i + (size_t)k - 3];
            double mass = k < 3 ? e->m[i] : e->inertia[i];
            double fd = k < 3 ? fdamp[3 * i + (size_t)k] : 0.0;
            double f = load[d] + e->fext[d] + fd, v_old = *vel, v_new, fw;
            if (e->fix[i] & (1u << k)) { /* prescribed: the constraint supplies the rest */
                v_new = e->vfix[d];
                e->reaction[d] = mass * (v_new - v_old) / dt - f;
            } else {
                v_new = v_old + dt * f / mass; /* eqs. 40, 44 */
                e->reaction[d] = 0.0;
            }
            if (!isfinite(v_new))
                goto not_finite;
            /* eqs. 51-52: loads of t - dt and t on the increment dt v(t - dt/2) */
            fw = e->fext[d] + e->reaction[d];
            e->w_ext += 0.5 * (e->fwork_prev[d] + fw) * v_old * dt;
            e->fwork_prev[d] = fw;
            if (k < 3) {
                e->w_dis -= 0.5 * (e->fdamp_prev[3 * i + (size_t)k] + fd) * v_old * dt;
                e->fdamp_prev[3 * i + (size_t)k] = fd;
            }
            kin += 0.5 * mass * v_old * v_new; /* eq. 49 in the scheme's own form */
            load[d] = f + e->reaction[d];
            *vel = v_new;
        }
        for (k = 0; k < 3; ++k) {
            e->x[3 * i + (size_t)k] += dt * e->v[3 * i + (size_t)k];     /* eq. 41 */
            e->theta[3 * i + (size_t)k] += dt * e->w[3 * i + (size_t)k]; /* eq. 45 */
        }
    }
    e->w_kin = kin;
    ++e->step;
    return SBC_OK;
not_finite:
    return sbc_fail(err, SBC_ERR_NUMERIC,
                    "3D engine: sphere %zu has a non-finite velocity at step %ld (time step %g s against the "
                    "estimate %g s of eq. 48)", i + 1, e->step + 1, dt, sbc_bpm_critical_dt(e));
}

sbc_bpm_energy sbc_bpm_energies(const sbc_bpm *e)
{
    sbc_bpm_energy en;
    double big;
    size_t k;
    en.kinetic = e->w_kin;
    en.dissipated = e->w_dis + e->w_fracture;
    en.external = e->w_ext;
    en.strain = 0.0;
    for (k = 0; k < e->nb; ++k) {
        size_t a = e->bonds[k].a, b = e->bonds[k].b;
        double strain, friction;
        sbc_bpm_bond_view v = view_of(e, k);
        sbc_bpm_bond_energies(&e->set, &v, &e->x[3 * a], e->r[a], &e->x[3 * b], e->r[b], &strain,
                              &friction);
        en.strain += strain;
        en.dissipated += friction;
    }
    big = fabs(en.kinetic);
    if (fabs(en.strain) > big) big = fabs(en.strain);
    if (fabs(en.dissipated) > big) big = fabs(en.dissipated);
    if (fabs(en.external) > big) big = fabs(en.external);
    en.balance = big > 0.0 ? fabs(en.kinetic + en.strain + en.dissipated - en.external) / big : 0.0; /* eq. 53 */
    return en;
}

double sbc_bpm_mean_coordination(const sbc_bpm *e)
{
    size_t i;
    double s = 0.0;
    for (i = 0; i < e->n; ++i)
        s += e->coordination[i];
    return e->n ? s / (double)e->n : 0.0;
}
