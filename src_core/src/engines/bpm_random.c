/* servo_bc: random close packing of equal spheres in a box by radius
 * expansion (thesis Sect. 4.1, our own algorithm; bpm_packing.h). */
#include "sbc/embedded/bpm_packing.h"
#include "fire.h"
#include "sbc/packing.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct pack {
    size_t n;
    double L[3], r, *x, *v, *f;
    size_t nc[3], *head, *next;
} pack;

/* overlap forces (unit stiffness) with the other spheres and the walls;
 * energy sum(overlap^2)/2 */
static double forces(void *ctx)
{
    pack *p = ctx;
    double e = 0.0, cell = 2.0 * p->r, d2max = 4.0 * p->r * p->r;
    size_t i, k, ncell = p->nc[0] * p->nc[1] * p->nc[2];
    memset(p->f, 0, 3 * p->n * sizeof *p->f);
    for (k = 0; k < ncell; ++k)
        p->head[k] = (size_t)-1;
    for (i = 0; i < p->n; ++i) {
        size_t c[3];
        for (k = 0; k < 3; ++k) {
            double xk = p->x[3 * i + k], lo = p->r - xk, hi = xk + p->r - p->L[k];
            double s = xk / cell;
            c[k] = s <= 0.0 ? 0 : s >= (double)p->nc[k] ? p->nc[k] - 1 : (size_t)s;
            if (lo > 0.0) { p->f[3 * i + k] += lo; e += 0.5 * lo * lo; } /* walls */
            if (hi > 0.0) { p->f[3 * i + k] -= hi; e += 0.5 * hi * hi; }
        }
        k = (c[2] * p->nc[1] + c[1]) * p->nc[0] + c[0];
        p->next[i] = p->head[k];
        p->head[k] = i;
    }
    for (i = 0; i < p->n; ++i) {
        long c[3], d0, d1, d2;
        for (k = 0; k < 3; ++k) {
            double s = p->x[3 * i + k] / cell;
            c[k] = s <= 0.0 ? 0 : s >= (double)p->nc[k] ? (long)p->nc[k] - 1 : (long)s;
        }
        for (d2 = -1; d2 <= 1; ++d2)
            for (d1 = -1; d1 <= 1; ++d1)
                for (d0 = -1; d0 <= 1; ++d0) {
                    long q0 = c[0] + d0, q1 = c[1] + d1, q2 = c[2] + d2;
                    size_t j;
                    if (q0 < 0 || q1 < 0 || q2 < 0 || q0 >= (long)p->nc[0] || q1 >= (long)p->nc[1] ||
                        q2 >= (long)p->nc[2])
                        continue;
                    for (j = p->head[((size_t)q2 * p->nc[1] + (size_t)q1) * p->nc[0] + (size_t)q0]; j != (size_t)-1;
                         j = p->next[j]) {
                        double dx[3], d2_ = 0.0, d, ov;
                        if (j <= i)
                            continue;
                        for (k = 0; k < 3; ++k) {
                            dx[k] = p->x[3 * j + k] - p->x[3 * i + k];
                            d2_ += dx[k] * dx[k];
                        }
                        if (d2_ >= d2max || d2_ == 0.0)
                            continue;
                        d = sqrt(d2_);
                        ov = 2.0 * p->r - d;
                        e += 0.5 * ov * ov;
                        for (k = 0; k < 3; ++k) {
                            p->f[3 * i + k] -= ov * dx[k] / d;
                            p->f[3 * j + k] += ov * dx[k] / d;
                        }
                    }
                }
    }
    return e;
}

/* a bound on the largest overlap between spheres or with a wall: sqrt(2 E),
 * m (a jammed packing balances its forces, so they cannot tell) */
static double worst_overlap(pack *p)
{
    double energy = forces(p);
    size_t i;
    for (i = 0; i < 3 * p->n; ++i)
        if (!isfinite(p->x[i]))
            return HUGE_VAL;
    return isfinite(energy) ? sqrt(2.0 * energy) : HUGE_VAL;
}

sbc_status sbc_bpm_pack_random(sbc_bpm *e, const double box[3], double rp, double rho, double porosity,
                               unsigned long seed, double extent[6], sbc_error *err)
{
    unsigned long long s = (unsigned long long)seed * 0x9E3779B97F4A7C15ULL + 1;
    double vol = box[0] * box[1] * box[2], grow;
    pack p;
    size_t i, k, ncell = 1, steps = 60;
    sbc_fire_problem fp;
    sbc_status st = SBC_OK;
    if (!(rp > 0.0) || !(box[0] > 2.0 * rp) || !(box[1] > 2.0 * rp) || !(box[2] > 2.0 * rp))
        return sbc_fail(err, SBC_ERR_INPUT, "random packing: radius %g and box %g x %g x %g (expected a box wider "
                        "than a sphere in every direction)", rp, box[0], box[1], box[2]);
    if (!(porosity >= 0.36 && porosity < 1.0))
        return sbc_fail(err, SBC_ERR_INPUT, "random packing: porosity %g (expected 0.36 <= p < 1; equal spheres "
                        "do not pack randomly below 0.36)", porosity);
    memset(&p, 0, sizeof p);
    {
        /* counted as doubles and checked before any cast */
        const double n = floor((1.0 - porosity) * vol / (4.0 / 3.0 * SBC_PI * rp * rp * rp) + 0.5);
        double cells = 1.0;
        for (k = 0; k < 3; ++k)
            cells *= fmax(1.0, floor(box[k] / (2.0 * rp)));
        if (!(n <= (double)SBC_PACKING_MAX) || !(cells <= (double)SBC_PACKING_MAX))
            return sbc_fail(err, SBC_ERR_INPUT, "random packing: %g spheres of radius %g in the box %g x %g x %g "
                            "exceed the limit of %ld", n, rp, box[0], box[1], box[2], (long)SBC_PACKING_MAX);
        p.n = (size_t)n;
    }
    if (p.n < 1)
        return sbc_fail(err, SBC_ERR_INPUT, "random packing: porosity %g leaves no sphere in the box", porosity);
    for (k = 0; k < 3; ++k) {
        p.L[k] = box[k];
        p.nc[k] = (size_t)(box[k] / (2.0 * rp));
        if (p.nc[k] < 1) p.nc[k] = 1;
        ncell *= p.nc[k];
    }
    p.x = malloc(3 * p.n * sizeof *p.x);
    p.v = malloc(3 * p.n * sizeof *p.v);
    p.f = malloc(3 * p.n * sizeof *p.f);
    p.head = malloc(ncell * sizeof *p.head);
    p.next = malloc(p.n * sizeof *p.next);
    if (!p.x || !p.v || !p.f || !p.head || !p.next) {
        st = sbc_fail(err, SBC_ERR_NOMEM, "random packing: out of memory for %zu spheres", p.n);
        goto done;
    }
    for (i = 0; i < p.n; ++i)
        for (k = 0; k < 3; ++k)
            p.x[3 * i + k] = rp + (box[k] - 2.0 * rp) * sbc_uniform(&s);
    fp.n = 3 * p.n;
    fp.x = p.x;
    fp.v = p.v;
    fp.f = p.f;
    fp.forces = forces;
    fp.place = NULL;
    fp.ctx = &p;
    fp.dt_max = 0.2; /* stable with a dozen unit springs on a sphere: 2 / sqrt(12 + 2) = 0.53 */
    /* radius expansion: from half the radius to r_p in equal steps of r^3
     * (of packing fraction), overlaps relaxed after each */
    for (k = 1; k <= steps; ++k) {
        grow = 0.125 + 0.875 * (double)k / (double)steps;
        p.r = rp * cbrt(grow);
        sbc_fire_minimize(&fp, (k < steps ? 1e-4 : 1e-7) * rp, 20000);
    }
    grow = worst_overlap(&p);
    if (grow > 1e-4 * rp) {
        st = sbc_fail(err, SBC_ERR_GEOMETRY, "random packing: %zu spheres of radius %g jam in the box %g x %g x %g "
                      "(overlaps of %.2g r_p remain): raise the porosity above %g", p.n, rp, box[0], box[1], box[2],
                      grow / rp, porosity);
        goto done;
    }
    for (i = 0; i < p.n && st == SBC_OK; ++i)
        st = sbc_bpm_add(e, &p.x[3 * i], rp, rho, NULL, err);
    if (st == SBC_OK && extent)
        sbc_bpm_extent(e, extent);
done:
    free(p.x);
    free(p.v);
    free(p.f);
    free(p.head);
    free(p.next);
    return st;
}
