#include "sbc/relax.h"

#include <math.h>

void sbc_relax_start(sbc_relax *r, double tol_E, int window, int at_rest)
{
    r->at_rest = at_rest;
    r->tol_E = tol_E;
    r->window = window;
    r->steps = 0;
    r->count = 0;
    r->rising = 0;
    r->past_peak = 0;
    r->ek_prev = 0.0;
    r->known_step = 0;
    r->ep_known = 0.0;
    r->ek_known = 0.0;
}

/* the ratio Ek/Ep below which this step may count: eq. 11 past the maximum,
 * before it the round-off floor at rest, else none */
static double counting_limit(const sbc_relax *r, int past_peak)
{
    if (past_peak)
        return r->tol_E;
    return r->at_rest ? fmin(r->tol_E, SBC_RELAX_ROUNDOFF) : 0.0;
}

int sbc_relax_needs_potential(const sbc_relax *r, double ek)
{
    double bound;
    const int past_peak = r->past_peak || (r->steps > 0 && r->rising && ek <= r->ek_prev);
    if (ek == 0.0 || counting_limit(r, past_peak) == 0.0)
        return 0;
    if (r->known_step == 0 || r->steps + 1 - r->known_step >= SBC_RELAX_EP_REFRESH)
        return 1;
    bound = r->ep_known + r->ek_known - ek;
    return bound <= 0.0 || ek <= 2.0 * counting_limit(r, past_peak) * bound;
}

/* eq. 11: Ek/Ep <= tolE, held for r->window consecutive steps after a
 * kinetic-energy maximum or at the round-off floor (see relax.h). */
int sbc_relax_update(sbc_relax *r, double ek, double ep)
{
    int ok;
    if (r->steps > 0) {
        if (ek > r->ek_prev)
            r->rising = 1;
        else if (r->rising)
            r->past_peak = 1;
    }
    r->ek_prev = ek;
    r->steps++;
    if (ep >= 0.0) {
        r->known_step = r->steps;
        r->ep_known = ep;
        r->ek_known = ek;
    }
    if (ek == 0.0)
        ok = 1;
    else
        ok = ep > 0.0 && ek <= counting_limit(r, r->past_peak) * ep;
    r->count = ok ? r->count + 1 : 0;
    return r->count >= r->window;
}
