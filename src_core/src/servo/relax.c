/* When a relaxation is over: force balance, or eq. 11 (see relax.h). */
#include "sbc/relax.h"

#include <math.h>

void sbc_relax_start(sbc_relax *r, sbc_criterion criterion, double tol, int window, int at_rest)
{
    r->criterion = criterion;
    r->at_rest = at_rest;
    r->tol = tol;
    r->window = window;
    r->steps = 0;
    r->count = 0;
    r->rising = 0;
    r->past_peak = 0;
    r->ek_prev = 0.0;
    r->known_step = 0;
    r->ep_known = 0.0;
    r->ek_known = 0.0;
    r->fc_known = 0.0;
    r->unbalanced = 0.0;
    r->net_known = 0.0;
}

void sbc_relax_floor(sbc_relax *r, double floor_force, double floor_energy)
{
    r->floor_force = floor_force;
    r->floor_energy = floor_energy;
    r->path_force = 0.0; /* a new path: no increment converged yet */
}

double sbc_relax_scale_floor(const sbc_relax *r) { return fmax(r->floor_force, SBC_RELAX_PATH_FLOOR * r->path_force); }

void sbc_relax_path(sbc_relax *r, double fc)
{
    if (fc > r->path_force)
        r->path_force = fc;
}

/* ---- force balance: (a) and (b) of relax.h ---- */

/* the mean contact force that scales U, with the floor, N */
static double contact_scale(const sbc_relax *r, const sbc_relax_sample *s)
{
    const double fc = s->contact_count > 0 ? s->contact_sum / (double)s->contact_count : 0.0;
    return fmax(fc, sbc_relax_scale_floor(r));
}

int sbc_relax_balanced(const sbc_relax *r)
{
    return r->unbalanced <= r->tol || r->net_known <= SBC_RELAX_NET_FLOOR * r->floor_force;
}

static int force_counts(const sbc_relax *r, const sbc_relax_sample *s)
{
    const double fc = contact_scale(r, s), mean = s->contact_count > 0 ? s->contact_sum / (double)s->contact_count : 0.0;
    /* below the path floor, the energy floor rises with it (a state of its forces is at rest) */
    const double lift = r->floor_force > 0.0 && mean < sbc_relax_scale_floor(r) ? sbc_relax_scale_floor(r) / r->floor_force : 1.0;
    return s->net_max <= fmax(r->tol * fc, SBC_RELAX_NET_FLOOR * r->floor_force) &&
           s->ek <= fmax(0.5 * r->tol * r->tol * s->ep, r->floor_energy * lift * lift);
}

/* ---- energy: eq. 11 past the kinetic-energy maximum ---- */

/* the ratio Ek/Ep below which this step may count: eq. 11 past the maximum,
 * before it the round-off floor at rest, else none */
static double counting_limit(const sbc_relax *r, int past_peak)
{
    if (past_peak)
        return r->tol;
    return r->at_rest ? fmin(r->tol, SBC_RELAX_ROUNDOFF) : 0.0;
}

static int energy_counts(const sbc_relax *r, const sbc_relax_sample *s)
{
    if (s->ek == 0.0)
        return 1;
    return s->ep > 0.0 && s->ek <= counting_limit(r, r->past_peak) * s->ep;
}

int sbc_relax_needs_contacts(const sbc_relax *r, const sbc_relax_sample *s)
{
    const double ek = s->ek;
    double bound;
    if (r->known_step == 0 || r->steps + 1 - r->known_step >= SBC_RELAX_EP_REFRESH)
        return 1;
    if (r->criterion == SBC_CRITERION_FORCE)
        return s->net_max <= 2.0 * fmax(r->tol * fmax(r->fc_known, sbc_relax_scale_floor(r)),
                                        SBC_RELAX_NET_FLOOR * r->floor_force);
    {
        const int past_peak = r->past_peak || (r->steps > 0 && r->rising && ek <= r->ek_prev);
        if (ek == 0.0 || counting_limit(r, past_peak) == 0.0)
            return 0;
        bound = r->ep_known + r->ek_known - ek;
        return bound <= 0.0 || ek <= 2.0 * counting_limit(r, past_peak) * bound;
    }
}

int sbc_relax_update(sbc_relax *r, const sbc_relax_sample *s)
{
    int ok;
    if (r->steps > 0) {
        if (s->ek > r->ek_prev)
            r->rising = 1;
        else if (r->rising)
            r->past_peak = 1;
    }
    r->ek_prev = s->ek;
    r->steps++;
    if (s->ep >= 0.0) {
        r->known_step = r->steps;
        r->ep_known = s->ep;
        r->ek_known = s->ek;
        r->fc_known = s->contact_count > 0 ? s->contact_sum / (double)s->contact_count : 0.0;
        /* reported: against the state's own forces, or the path's once they
           collapsed below the floor, and never against less than the force
           whose tol is the round-off rule's net force (force_counts: then U <=
           tol exactly when (a) holds) */
        double fc = r->fc_known >= sbc_relax_scale_floor(r) ? r->fc_known : fmax(r->path_force, r->floor_force);
        if (r->tol > 0.0)
            fc = fmax(fc, SBC_RELAX_NET_FLOOR * r->floor_force / r->tol);
        r->unbalanced = fc > 0.0 ? s->net_max / fc : 0.0;
        r->net_known = s->net_max;
    }
    if (r->criterion == SBC_CRITERION_FORCE)
        ok = s->ep >= 0.0 && force_counts(r, s);
    else
        ok = energy_counts(r, s);
    r->count = ok ? r->count + 1 : 0;
    return r->count >= r->window;
}
