/* servo_bc: the 2D contact laws with cohesive bonds behind a host's own
 * integrator (cohesive_host.h): the embedded engine's pair loop, nothing
 * integrated. */
#include "sbc/cohesive_host.h"
#include "sbc/contact.h"
#include "sbc/embedded/engine.h"
#include "base/words.h"
#include "engines/neighbor.h"
#include "engines/pair_contact.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_WORDS 16

struct sbc_cohesive_host {
    sbc_engine *engine;
    sbc_cohesive law;
    char message[SBC_ERROR_LEN];
};

sbc_cohesive_host *sbc_cohesive_host_create(const char *words, int n, const double *xy, const double *r, char *msg,
                                            size_t cap)
{
    char copy[512], *w[MAX_WORDS];
    int nw;
    sbc_error err;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_cohesive law;
    sbc_cohesive_host *h;
    err.message[0] = '\0';
    if (!words || strlen(words) >= sizeof copy) {
        snprintf(msg, cap, "cohesive: the law's words are missing or longer than %zu characters", sizeof copy - 1);
        return NULL;
    }
    strcpy(copy, words);
    nw = sbc_split_words(copy, w, MAX_WORDS);
    if (nw > MAX_WORDS)
        nw = MAX_WORDS; /* sbc_cohesive_parse names the first extra word */
    if (sbc_cohesive_parse(nw, w, "cohesive", &law, &err) != SBC_OK) {
        snprintf(msg, cap, "%s", err.message);
        return NULL;
    }
    h = calloc(1, sizeof *h);
    if (!h) {
        snprintf(msg, cap, "cohesive: out of memory");
        return NULL;
    }
    h->law = law;
    if (n < 2 || !xy || !r) {
        snprintf(msg, cap, "cohesive: fewer than 2 discs, or their centres or radii missing");
        free(h);
        return NULL;
    }
    def.n = n;
    def.x = xy;
    def.r = r;
    def.density = 1.0; /* masses are the host's: the pair loop does not use them */
    def.bonds = &h->law;
    def.alpha = def.beta = 0.0;
    h->engine = sbc_engine_create(&def, &err);
    if (!h->engine) {
        snprintf(msg, cap, "%s", err.message);
        free(h);
        return NULL;
    }
    if (sbc_engine_get_view(h->engine).bonds_initial == 0) {
        snprintf(msg, cap, "cohesive: no two of the %d discs touch, so no bond formed", n);
        sbc_cohesive_host_free(h);
        return NULL;
    }
    return h;
}

void sbc_cohesive_host_free(sbc_cohesive_host *h)
{
    if (!h)
        return;
    sbc_engine_free(h->engine);
    free(h);
}

double sbc_cohesive_host_kn(const sbc_cohesive_host *h) { return h->law.kn; }

int sbc_cohesive_host_bond_count(const sbc_cohesive_host *h) { return sbc_engine_get_view(h->engine).bond_count; }

int sbc_cohesive_host_bonds_initial(const sbc_cohesive_host *h)
{
    return sbc_engine_get_view(h->engine).bonds_initial;
}

const char *sbc_cohesive_host_message(const sbc_cohesive_host *h) { return h->message; }

int sbc_cohesive_host_loads(sbc_cohesive_host *h, const double *xy, const double *v, const double *w, double dt,
                            double *load)
{
    sbc_error err;
    sbc_engine_view view;
    int k;
    if (sbc_engine_host_loads(h->engine, xy, v, w, dt, &err) != SBC_OK) {
        snprintf(h->message, sizeof h->message, "%s", err.message);
        return 1;
    }
    view = sbc_engine_get_view(h->engine);
    for (k = 0; k < view.n; ++k) {
        load[3 * k] = view.f[2 * k];
        load[3 * k + 1] = view.f[2 * k + 1];
        load[3 * k + 2] = view.torque[k];
        if (!isfinite(load[3 * k]) || !isfinite(load[3 * k + 1]) || !isfinite(load[3 * k + 2])) {
            snprintf(h->message, sizeof h->message,
                     "cohesive: the load on disc %d is not finite (fx %g N, fy %g N, m %g N m); the time step %g s "
                     "against the critical %g s",
                     k, load[3 * k], load[3 * k + 1], load[3 * k + 2], dt, sbc_engine_critical_dt(h->engine));
            return 1;
        }
    }
    return 0;
}

void sbc_cohesive_host_sums(const sbc_cohesive_host *h, double *sums)
{
    sbc_snapshot s;
    sbc_engine_snapshot(h->engine, &s);
    sums[0] = s.potential_energy;
    sums[1] = s.overlap_sum;
    sums[2] = (double)s.contact_count;
    sums[3] = s.contact_force_sum;
}

/* layout: bonds at creation, record count, then SBC_PAIR_RECORD per record */
size_t sbc_cohesive_host_state_size(const sbc_cohesive_host *h)
{
    return 2 + (size_t)SBC_PAIR_RECORD * (size_t)sbc_engine_pair_records(h->engine, NULL);
}

void sbc_cohesive_host_state_get(const sbc_cohesive_host *h, double *state)
{
    state[0] = sbc_cohesive_host_bonds_initial(h);
    state[1] = sbc_engine_pair_records(h->engine, &state[2]);
}

int sbc_cohesive_host_state_set(sbc_cohesive_host *h, const double *state, size_t size)
{
    sbc_error err;
    if (size < 2 || !(state[1] >= 0.0) || size != 2 + (size_t)SBC_PAIR_RECORD * (size_t)state[1]) {
        snprintf(h->message, sizeof h->message, "cohesive: a saved state of %zu values is not a pair state", size);
        return 1;
    }
    if (sbc_engine_set_pair_records(h->engine, &state[2], (int)state[1], (int)state[0], &err) != SBC_OK) {
        snprintf(h->message, sizeof h->message, "%s", err.message);
        return 1;
    }
    return 0;
}

long sbc_cohesive_host_pairs(int n, const double *xy, const double *r, double reach, int **pairs, char *msg,
                             size_t cap)
{
    sbc_pairs p;
    sbc_error err;
    double rmax = 0.0;
    int k;
    long count;
    *pairs = NULL;
    if (n < 0 || (n > 0 && (!xy || !r)) || !(reach >= 0.0) || !isfinite(reach)) {
        snprintf(msg, cap, "cohesive: %d discs without centres or radii, or a reach of %g m (expected >= 0)", n,
                 reach);
        return -1;
    }
    if (n < 2)
        return 0;
    for (k = 0; k < n; ++k) {
        if (!(r[k] > 0.0) || !isfinite(r[k]) || !isfinite(xy[2 * k]) || !isfinite(xy[2 * k + 1])) {
            snprintf(msg, cap, "cohesive: disc %d has radius %g m (expected > 0) or a non-finite centre (%g, %g)", k,
                     r[k], xy[2 * k], xy[2 * k + 1]);
            return -1;
        }
        if (r[k] > rmax)
            rmax = r[k];
    }
    if (sbc_pairs_init(&p, 2, n, reach, 0, 0, &err) != SBC_OK || sbc_pairs_build(&p, xy, r, rmax, &err) != SBC_OK) {
        sbc_pairs_free(&p);
        snprintf(msg, cap, "%s", err.message);
        return -1;
    }
    count = p.count;
    *pairs = malloc(sizeof(int) * 2 * (size_t)(count > 0 ? count : 1));
    if (!*pairs) {
        sbc_pairs_free(&p);
        snprintf(msg, cap, "cohesive: out of memory for %ld pairs", count);
        return -1;
    }
    for (k = 0; k < p.count; ++k) {
        (*pairs)[2 * k] = p.i[k];
        (*pairs)[2 * k + 1] = p.j[k];
    }
    sbc_pairs_free(&p);
    return count;
}

void sbc_cohesive_host_pairs_free(int *pairs) { free(pairs); }

int sbc_cohesive_pair_start(const double xa[2], double ra, const double xb[2], double rb, double rmin, double *state)
{
    const double dx = xb[0] - xa[0], dy = xb[1] - xa[1];
    const double d = sqrt(dx * dx + dy * dy); /* as sbc_pairs_bond_touching */
    state[0] = d - ra - rb < SBC_BOND_TOUCH * rmin;
    state[1] = state[2] = 0.0;
    return state[0] != 0.0;
}

long sbc_cohesive_pairs_step(const sbc_cohesive *law, long count, const int *ends, const double *x, const double *v,
                             int stride, const double *w, int wstride, const double *r, double dt, double *state,
                             double *loads, double sums[4])
{
    sbc_pair_laws L;
    sbc_pair_sums s = {0.0, 0.0, 0.0, 0, 0};
    long k, intact = 0;
    int c;
    L.bond = *law;
    L.law.kn = law->kn; /* broken bonds and new contacts: eq. 6 with the bond's kn, ks, mu (engine.c) */
    L.law.ks = law->ks;
    L.law.mu = law->mu;
    L.inv_ks = law->ks > 0.0 ? 1.0 / law->ks : 0.0;
    for (k = 0; k < count; ++k) {
        const size_t a = (size_t)ends[2 * k], b = (size_t)ends[2 * k + 1];
        const double *xa = &x[stride * a], *xb = &x[stride * b], ra = r[a];
        const double wa = w ? w[wstride * a] : 0.0, wb = w ? w[wstride * b] : 0.0;
        double *st = &state[3 * k], *la = &loads[6 * k], *lb = la + 3, out[4];
        unsigned char bond = st[0] != 0.0;
        if (!sbc_pair_contact(&L, 1, 1, xb[0] - xa[0], xb[1] - xa[1], ra, r[b], v ? v[stride * a] : 0.0,
                              v ? v[stride * a + 1] : 0.0, wa, ra * wa, v ? v[stride * b] : 0.0,
                              v ? v[stride * b + 1] : 0.0, wb, dt, &st[1], &st[2], &bond, &s, out)) {
            st[0] = st[2] = 0.0; /* apart and unbonded: a broken bond's moment is 0 already */
            for (c = 0; c < 6; ++c)
                la[c] = 0.0;
            continue;
        }
        st[0] = bond;
        intact += bond;
        la[0] = out[0];
        la[1] = out[1];
        la[2] = out[2];
        lb[0] = -out[0];
        lb[1] = -out[1];
        lb[2] = out[3];
    }
    if (sums) {
        sums[0] += s.ep;
        sums[1] += 2.0 * s.ov; /* eq. 39: dn / Rbar_c = 2 dn / (R_a + R_b) */
        sums[2] += (double)s.nc;
        sums[3] += s.fc;
    }
    return intact;
}
