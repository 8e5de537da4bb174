/* servo_bc: the 3D bond models behind a host's own integrator (bpm_host.h) */
#include "sbc/bpm_host.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static sbc_bpm *fail_create(sbc_bpm *e, char *msg, size_t cap, const char *text)
{
    if (msg && cap > 0)
        snprintf(msg, cap, "%s", text);
    sbc_bpm_free(e);
    return NULL;
}

sbc_bpm *sbc_bpm_host_law(const char *model, double E, double nu, double alpha, const double *strength, double rmin,
                          char *msg, size_t cap)
{
    sbc_bpm_settings set = sbc_bpm_settings_default();
    sbc_bpm *e = NULL;
    sbc_error err;
    char text[SBC_ERROR_LEN];
    if (!model || (strcmp(model, "beam") != 0 && strcmp(model, "parallel") != 0))
        return fail_create(NULL, msg, cap, "bonds: model must be beam or parallel");
    if (!(E > 0.0) || !isfinite(E) || !(nu > -1.0 && nu < 0.5) || !(alpha > 0.0) || !isfinite(alpha)) {
        snprintf(text, sizeof text, "bonds: E %g Pa, nu %g, alpha %g (expected E > 0, -1 < nu < 0.5, alpha > 0)", E,
                 nu, alpha);
        return fail_create(NULL, msg, cap, text);
    }
    if (!(rmin > 0.0) || !isfinite(rmin)) {
        snprintf(text, sizeof text, "bonds: smallest radius %g m (expected > 0)", rmin);
        return fail_create(NULL, msg, cap, text);
    }
    set.model = strcmp(model, "beam") == 0 ? SBC_BOND_BEAM : SBC_BOND_PARALLEL;
    set.beam.E = E;
    set.beam.nu = nu;
    set.parallel = sbc_bpm_parallel_law(E, rmin, 4.2);
    set.alpha = alpha;
    if (strength) {
        int q;
        for (q = 0; q < 5; ++q)
            if (!(strength[q] >= 0.0) || !isfinite(strength[q]) || (q == 0 && !(strength[q] > 0.0))) {
                snprintf(text, sizeof text,
                         "bonds: strength %g %g %g %g, friction %g (expected a tension > 0 N, shear N, bending N m, "
                         "twisting N m and friction >= 0)",
                         strength[0], strength[1], strength[2], strength[3], strength[4]);
                return fail_create(NULL, msg, cap, text);
            }
        set.strength.tension = strength[0];
        set.strength.shear = strength[1];
        set.strength.bending = strength[2];
        set.strength.twisting = strength[3];
        set.mu = strength[4];
    }
    if (sbc_bpm_create(&set, &e, &err) != SBC_OK)
        return fail_create(e, msg, cap, err.message);
    return e;
}

sbc_bpm *sbc_bpm_host_create(const char *model, double E, double nu, double alpha, const double *strength, int n,
                             const double *x, const double *r, const double *m, char *msg, size_t cap)
{
    sbc_bpm *e = NULL;
    sbc_error err;
    char text[SBC_ERROR_LEN];
    double rmin = HUGE_VAL;
    int i;
    if (n < 2 || !x || !r || !m)
        return fail_create(NULL, msg, cap, "bonds: fewer than 2 spheres, or their centres, radii or masses missing");
    for (i = 0; i < n; ++i)
        if (r[i] > 0.0 && r[i] < rmin)
            rmin = r[i];
    e = sbc_bpm_host_law(model, E, nu, alpha, strength, rmin, msg, cap);
    if (!e)
        return NULL;
    for (i = 0; i < n; ++i) {
        double rho = m[i] / (4.0 / 3.0 * SBC_PI * r[i] * r[i] * r[i]);
        if (!(r[i] > 0.0) || !(m[i] > 0.0) || !isfinite(rho) || !isfinite(x[3 * i]) || !isfinite(x[3 * i + 1]) ||
            !isfinite(x[3 * i + 2])) {
            snprintf(text, sizeof text, "bonds: sphere %d: radius %g m, mass %g kg (expected > 0) or a non-finite centre",
                     i, r[i], m[i]);
            return fail_create(e, msg, cap, text);
        }
        if (sbc_bpm_add(e, &x[3 * i], r[i], rho, NULL, &err) != SBC_OK)
            return fail_create(e, msg, cap, err.message);
    }
    if (sbc_bpm_bond_touching(e, &err) != SBC_OK)
        return fail_create(e, msg, cap, err.message);
    if (e->nb == 0)
        return fail_create(e, msg, cap, "bonds: no two spheres touch, so no bond formed");
    return e;
}

int sbc_bpm_host_bond_count(const sbc_bpm *e) { return (int)e->nb; }

int sbc_bpm_host_intact(const sbc_bpm *e) { return (int)(e->nb - e->nbroken); }

int sbc_bpm_host_loads(sbc_bpm *e, const double *x, const double *v, const double *w, double dt, double *load)
{
    size_t i, n3 = 3 * e->n;
    memcpy(e->x, x, n3 * sizeof *x);
    memcpy(e->v, v, n3 * sizeof *v);
    memcpy(e->w, w, n3 * sizeof *w);
    memset(load, 0, 6 * e->n * sizeof *load);
    e->dt = dt;
    sbc_bpm_bond_loads(e, load);
    for (i = 0; i < 6 * e->n; ++i)
        if (!isfinite(load[i]))
            return 1;
    return 0;
}

double sbc_bpm_host_strain_energy(const sbc_bpm *e) { return sbc_bpm_energies(e).strain; }

/* the host's bonds have no dashpots (w_dis stays 0): what is dissipated is fracture and friction */
double sbc_bpm_host_dissipated(const sbc_bpm *e) { return sbc_bpm_energies(e).dissipated; }

double sbc_bpm_host_fracture_energy(const sbc_bpm *e) { return e->w_fracture; }

void sbc_bpm_host_set_fracture_energy(sbc_bpm *e, double w) { e->w_fracture = w; }

/* the bond states are structs of doubles only (bpm_bond.h); with failure, a
 * flag and the broken bond's contact follow */
#define BROKEN_DOUBLES (1 + (int)(sizeof(sbc_broken_bond) / sizeof(double)))
_Static_assert(sizeof(sbc_beam_bond) % sizeof(double) == 0 && sizeof(sbc_parallel_bond) % sizeof(double) == 0 &&
                   sizeof(sbc_broken_bond) % sizeof(double) == 0,
               "a bond state is doubles only: a host's slot of doubles holds it in place");

static int bond_doubles(const sbc_bpm *e)
{
    return (int)((e->set.model == SBC_BOND_BEAM ? sizeof(sbc_beam_bond) : sizeof(sbc_parallel_bond)) / sizeof(double));
}

int sbc_bpm_host_state_doubles(const sbc_bpm *e)
{
    return bond_doubles(e) + (e->set.strength.tension > 0.0 ? BROKEN_DOUBLES : 0);
}

void sbc_bpm_host_state_get(const sbc_bpm *e, int k, double *state)
{
    if (e->set.model == SBC_BOND_BEAM)
        memcpy(state, &e->beam[k], sizeof e->beam[k]);
    else
        memcpy(state, &e->parallel[k], sizeof e->parallel[k]);
    if (e->broken) {
        double *b = &state[bond_doubles(e)];
        b[0] = e->broken[k];
        memcpy(&b[1], &e->contact[k], sizeof e->contact[k]);
    }
}

void sbc_bpm_host_state_set(sbc_bpm *e, int k, const double *state)
{
    if (e->set.model == SBC_BOND_BEAM)
        memcpy(&e->beam[k], state, sizeof e->beam[k]);
    else
        memcpy(&e->parallel[k], state, sizeof e->parallel[k]);
    if (e->broken) {
        const double *b = &state[bond_doubles(e)];
        const unsigned char now = b[0] != 0.0;
        if (now != e->broken[k]) {
            if (now) ++e->nbroken;
            else --e->nbroken;
        }
        e->broken[k] = now;
        memcpy(&e->contact[k], &b[1], sizeof e->contact[k]);
    }
}

/* ---- bonds kept with their spheres ---- */

typedef struct pair_list {
    int *pairs;
    long count, cap;
} pair_list;

static sbc_status keep_pair(size_t i, size_t j, void *user, sbc_error *err)
{
    pair_list *p = user;
    if (p->count == p->cap) {
        long cap = p->cap ? 2 * p->cap : 1024;
        int *q = realloc(p->pairs, (size_t)cap * 2 * sizeof *q);
        if (!q)
            return sbc_fail(err, SBC_ERR_NOMEM, "out of memory for %ld bonded pairs", cap);
        p->pairs = q;
        p->cap = cap;
    }
    p->pairs[2 * p->count] = (int)i;
    p->pairs[2 * p->count + 1] = (int)j;
    ++p->count;
    return SBC_OK;
}

long sbc_bpm_host_pairs(const sbc_bpm *law, int n, const double *x, const double *r, int **pairs, char *msg,
                        size_t cap)
{
    pair_list p = {NULL, 0, 0};
    sbc_error err;
    *pairs = NULL;
    if (n < 0 || (n > 0 && (!x || !r))) {
        if (msg && cap > 0)
            snprintf(msg, cap, "bonds: %d spheres without centres or radii", n);
        return -1;
    }
    if (sbc_bpm_pairs(&law->set, (size_t)n, x, r, keep_pair, &p, &err) != SBC_OK) {
        free(p.pairs);
        if (msg && cap > 0)
            snprintf(msg, cap, "%s", err.message);
        return -1;
    }
    *pairs = p.pairs;
    return p.count;
}

void sbc_bpm_host_pairs_free(int *pairs) { free(pairs); }

/* One bond's state in place: the bond structs hold doubles only (bpm_bond.h),
 * so a view points into the host's doubles; the broken flag, a double there,
 * goes through a byte and back (pack). */
typedef struct unpacked {
    unsigned char broken;
} unpacked;

static sbc_bpm_bond_view unpack(const sbc_bpm *law, double *state, unpacked *u)
{
    sbc_bpm_bond_view b = {NULL, NULL, NULL, NULL};
    if (law->set.model == SBC_BOND_BEAM)
        b.beam = (sbc_beam_bond *)state;
    else
        b.parallel = (sbc_parallel_bond *)state;
    if (law->set.strength.tension > 0.0) {
        double *f = &state[bond_doubles(law)];
        u->broken = f[0] != 0.0;
        b.broken = &u->broken;
        b.contact = (sbc_broken_bond *)&f[1];
    }
    return b;
}

static void pack(const sbc_bpm *law, const unpacked *u, double *state)
{
    if (law->set.strength.tension > 0.0)
        state[bond_doubles(law)] = u->broken;
}

void sbc_bpm_host_bond_start(const sbc_bpm *law, const double xa[3], double ra, const double xb[3], double rb,
                             double *state)
{
    unpacked u;
    memset(state, 0, (size_t)sbc_bpm_host_state_doubles(law) * sizeof *state);
    sbc_bpm_bond_view b = unpack(law, state, &u);
    sbc_bpm_bond_start(&law->set, &b, xa, ra, xb, rb);
    pack(law, &u, state);
}

int sbc_bpm_host_bond_step(const sbc_bpm *law, double *state, const double xa[3], double ra, const double va[3],
                           const double wa[3], const double xb[3], double rb, const double vb[3], const double wb[3],
                           double dt, double load_a[6], double load_b[6], double *fracture)
{
    unpacked u;
    sbc_bpm_bond_view b = unpack(law, state, &u);
    int broke = sbc_bpm_bond_advance(&law->set, &b, xa, ra, va, wa, xb, rb, vb, wb, dt, load_a,
                                     &load_a[3], load_b, &load_b[3], fracture);
    pack(law, &u, state);
    return broke;
}

int sbc_bpm_host_bond_apart(const sbc_bpm *law, double *state)
{
    unpacked u;
    sbc_bpm_bond_view b = unpack(law, state, &u);
    if (!b.broken || !*b.broken)
        return 1;
    memset(b.contact->fs, 0, sizeof b.contact->fs);
    memset(b.contact->f, 0, sizeof b.contact->f);
    return 0;
}

double sbc_bpm_host_bond_stiffness(const sbc_bpm *law, const double *state)
{
    unpacked u;
    sbc_bpm_bond_view b = unpack(law, (double *)state, &u); /* read only */
    return sbc_bpm_bond_stiffness(&law->set, &b);
}

int sbc_bpm_host_bond_broken(const sbc_bpm *law, const double *state)
{
    return law->set.strength.tension > 0.0 && state[bond_doubles(law)] != 0.0;
}

void sbc_bpm_host_bond_energies(const sbc_bpm *law, const double *state, const double xa[3], double ra,
                                const double xb[3], double rb, double *strain, double *friction)
{
    unpacked u;
    sbc_bpm_bond_view b = unpack(law, (double *)state, &u); /* read only */
    if (!xb) { /* out of reach: apart */
        *strain = 0.0;
        *friction = b.contact ? b.contact->w : 0.0;
        return;
    }
    sbc_bpm_bond_energies(&law->set, &b, xa, ra, xb, rb, strain, friction);
}
