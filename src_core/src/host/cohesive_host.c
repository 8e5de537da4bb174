/* servo_bc: the 2D contact laws with cohesive bonds behind a host's own
 * integrator (cohesive_host.h): the embedded engine's pair loop, nothing
 * integrated. */
#include "sbc/cohesive_host.h"
#include "sbc/contact.h"
#include "sbc/embedded/engine.h"
#include "base/words.h"

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
