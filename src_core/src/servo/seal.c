/* servo_bc: the frame's seal, frictionless walls on the edges of the frame's polygon (seal.h) */
#include "sbc/seal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

sbc_status sbc_seal_init(sbc_seal *s, const sbc_frame *f, double reach, sbc_error *err)
{
    double area2 = 0.0; /* twice the signed area of the reference polygon (shoelace) */
    int q;
    memset(s, 0, sizeof *s);
    for (q = 0; q < f->n; ++q) {
        const double *a = &f->X[3 * q], *b = &f->X[3 * ((q + 1) % f->n)];
        area2 += a[0] * b[1] - a[1] * b[0];
    }
    if (f->n < 3 || !(fabs(area2) > 0.0) || !(reach > 0.0) || !isfinite(reach))
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: seal: the frame's polygon (%d particles) has no area", f->n);
    s->inward = area2 > 0.0 ? 1.0 : -1.0;
    s->reach = reach;
    s->tracked = -1;
    s->fx_built = malloc(sizeof(double) * 3 * (size_t)f->n);
    if (!s->fx_built)
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: seal: out of memory");
    return SBC_OK;
}

void sbc_seal_free(sbc_seal *s)
{
    free(s->particle);
    free(s->edge);
    free(s->x_built);
    free(s->fx_built);
    memset(s, 0, sizeof *s);
}

/* distance from p to the segment a -> b (m), the parameter t of its closest
 * point clamped to [0, 1], and the signed distance s from the line (> 0 on
 * the inner side) */
static double segment(const sbc_seal *S, const double *a, const double *b, const double *p, double *t, double *s)
{
    const double ux = b[0] - a[0], uy = b[1] - a[1], len2 = ux * ux + uy * uy;
    const double px = p[0] - a[0], py = p[1] - a[1];
    double tc = len2 > 0.0 ? (px * ux + py * uy) / len2 : 0.0;
    *t = tc;
    *s = len2 > 0.0 ? S->inward * (ux * py - uy * px) / sqrt(len2) : 0.0;
    tc = fmin(1.0, fmax(0.0, tc));
    return hypot(px - tc * ux, py - tc * uy);
}

static int add(sbc_seal *s, int k, int q)
{
    if (s->count == s->cap) {
        int cap = s->cap ? 2 * s->cap : 64;
        int *pk = realloc(s->particle, sizeof(int) * (size_t)cap), *pq;
        if (!pk)
            return 0;
        s->particle = pk;
        pq = realloc(s->edge, sizeof(int) * (size_t)cap);
        if (!pq)
            return 0;
        s->edge = pq;
        s->cap = cap;
    }
    s->particle[s->count] = k;
    s->edge[s->count] = q;
    s->count++;
    return 1;
}

static sbc_status collect(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                          sbc_error *err)
{
    int k, q;
    double *xb = realloc(s->x_built, sizeof(double) * 2 * (size_t)(p->n > 0 ? p->n : 1));
    if (!xb)
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: seal: out of memory for %d particles", p->n);
    s->x_built = xb;
    s->count = 0;
    for (k = 0; k < p->n; ++k) {
        const double *x = &p->x[(size_t)p->stride * (size_t)k];
        xb[2 * k] = x[0];
        xb[2 * k + 1] = x[1];
        const int own = p->frame(p->ctx, k); /* a frame particle skips the two edges it ends */
        for (q = 0; q < f->n && own >= -1; ++q) {
            double t, sd;
            if (own >= 0 && (q == own || (q + 1) % f->n == own))
                continue;
            if (segment(s, &fx[3 * q], &fx[3 * ((q + 1) % f->n)], x, &t, &sd) < p->r[k] + s->reach &&
                !add(s, k, q))
                return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: seal: out of memory");
        }
    }
    memcpy(s->fx_built, fx, sizeof(double) * 3 * (size_t)f->n);
    s->tracked = p->n;
    return SBC_OK;
}

/* has anything moved more than reach / 2 since the collection? */
static int moved(const sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p)
{
    const double lim = 0.25 * s->reach * s->reach;
    int k;
    if (s->tracked != p->n)
        return 1;
    for (k = 0; k < f->n; ++k) {
        const double dx = fx[3 * k] - s->fx_built[3 * k], dy = fx[3 * k + 1] - s->fx_built[3 * k + 1];
        if (dx * dx + dy * dy > lim)
            return 1;
    }
    for (k = 0; k < p->n; ++k) {
        const double *x = &p->x[(size_t)p->stride * (size_t)k];
        const double dx = x[0] - s->x_built[2 * k], dy = x[1] - s->x_built[2 * k + 1];
        if (dx * dx + dy * dy > lim)
            return 1;
    }
    return 0;
}

sbc_status sbc_seal_forces(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                           double kn, int recollect, double *reaction, double *energy, sbc_error *err)
{
    double e = 0.0;
    int c;
    *energy = 0.0;
    s->contacts = 0;
    if (recollect || moved(s, f, fx, p)) {
        sbc_status st = collect(s, f, fx, p, err);
        if (st != SBC_OK)
            return st;
    }
    for (c = 0; c < s->count; ++c) {
        const int k = s->particle[c], q = s->edge[c], q1 = (q + 1) % f->n;
        const double *a = &fx[3 * q], *b = &fx[3 * q1], *x = &p->x[(size_t)p->stride * (size_t)k];
        double t, sd, len, nx, ny, fn, *fk;
        segment(s, a, b, x, &t, &sd);
        if (!(t > 0.0 && t < 1.0) || sd >= SBC_SEAL_WALL * p->r[k])
            continue;
        len = hypot(b[0] - a[0], b[1] - a[1]);
        /* inward unit normal: the left normal (-u_y, u_x) / |u| of a -> b, times the orientation */
        nx = -s->inward * (b[1] - a[1]) / len;
        ny = s->inward * (b[0] - a[0]) / len;
        fn = kn * (SBC_SEAL_WALL * p->r[k] - sd); /* N */
        fk = &p->f[(size_t)p->stride * (size_t)k];
        fk[0] += fn * nx;
        fk[1] += fn * ny;
        if (reaction) {
            reaction[3 * q] -= (1.0 - t) * fn * nx;
            reaction[3 * q + 1] -= (1.0 - t) * fn * ny;
            reaction[3 * q1] -= t * fn * nx;
            reaction[3 * q1 + 1] -= t * fn * ny;
        }
        e += 0.5 * fn * (SBC_SEAL_WALL * p->r[k] - sd); /* J */
        s->contacts++;
    }
    *energy = e;
    return SBC_OK;
}
