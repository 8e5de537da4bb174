/* The embedded 2D engine's state as doubles (engine.h: sbc_engine_state_size,
 * sbc_engine_save, sbc_engine_load), for a material point's commit and
 * revert and its saved bytes. */
#include "engine_private.h"
#include "sbc/saved.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- the state (sbc_engine_save, sbc_engine_load) ---- */

#define ENGINE_STATE_HEAD 16 /* n, history, bonds, step, stale, bonds, fire (2), the measures (7) */

size_t sbc_engine_state_size(const sbc_engine *e)
{
    return ENGINE_STATE_HEAD + 9 * (size_t)e->n + sbc_pairs_state_size(&e->pairs);
}

static double *put(double *out, const double *a, size_t n)
{
    memcpy(out, a, sizeof(double) * n);
    return out + n;
}

void sbc_engine_save(const sbc_engine *e, double *out)
{
    const size_t n = (size_t)e->n;
    *out++ = e->n;
    *out++ = e->pairs.fs != NULL;
    *out++ = e->pairs.bond != NULL;
    *out++ = (double)e->step;
    *out++ = e->stale;
    *out++ = e->bond_count;
    *out++ = e->fire_state.alpha;
    *out++ = (double)e->fire_state.positive;
    *out++ = e->ek;
    *out++ = e->ep;
    *out++ = e->overlap_sum;
    *out++ = e->rotation_sum;
    *out++ = e->net_max;
    *out++ = e->contact_force_sum;
    *out++ = (double)e->contact_count;
    *out++ = e->bonds_initial;
    out = put(out, e->x, 2 * n);
    out = put(out, e->v, 2 * n);
    out = put(out, e->f, 2 * n);
    out = put(out, e->theta, n);
    out = put(out, e->omega, n);
    out = put(out, e->tq, n);
    sbc_pairs_save(&e->pairs, out);
}

static void take(sbc_saved *s, const char *name, double *a, size_t n)
{
    size_t k;
    for (k = 0; k < n; ++k)
        a[k] = sbc_saved_real(s, name);
}

sbc_status sbc_engine_load(sbc_engine *e, const double *in, size_t count, sbc_error *err)
{
    const size_t n = (size_t)e->n;
    sbc_saved s;
    sbc_saved_start(&s, in, count, "engine state", err);
    sbc_saved_int(&s, "particle count", e->n, e->n);
    sbc_saved_int(&s, "history flag", e->pairs.fs != NULL, e->pairs.fs != NULL);
    sbc_saved_int(&s, "bond flag", e->pairs.bond != NULL, e->pairs.bond != NULL);
    e->streaming = 0; /* the saved velocities are the velocities (remap, driver.h) */
    e->step = sbc_saved_int(&s, "step", 0, 1L << 52);
    e->stale = (int)sbc_saved_int(&s, "stale flag", 0, 1);
    e->bond_count = (int)sbc_saved_int(&s, "intact bonds", 0, e->bonds_initial);
    e->fire_state.alpha = sbc_saved_real(&s, "FIRE alpha");
    e->fire_state.positive = sbc_saved_int(&s, "FIRE steps", 0, 1L << 52);
    e->ek = sbc_saved_real(&s, "kinetic energy");
    e->ep = sbc_saved_real(&s, "potential energy");
    e->overlap_sum = sbc_saved_real(&s, "overlap sum");
    e->rotation_sum = sbc_saved_real(&s, "rotation sum");
    e->net_max = sbc_saved_real(&s, "largest net force");
    e->contact_force_sum = sbc_saved_real(&s, "contact force sum");
    e->contact_count = sbc_saved_int(&s, "contact count", 0, 1L << 52);
    sbc_saved_int(&s, "bonds at the start", e->bonds_initial, e->bonds_initial);
    take(&s, "position", e->x, 2 * n);
    take(&s, "velocity", e->v, 2 * n);
    take(&s, "force", e->f, 2 * n);
    take(&s, "rotation", e->theta, n);
    take(&s, "angular velocity", e->omega, n);
    take(&s, "moment", e->tq, n);
    if (s.st == SBC_OK)
        sbc_pairs_load(&e->pairs, &s);
    if (s.st == SBC_OK && s.at != count)
        return sbc_fail(err, SBC_ERR_INPUT, "engine state: %zu values given, %zu read", count, s.at);
    return s.st;
}
