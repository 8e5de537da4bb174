/* servo_bc: the frame's seal, frictionless walls on the edges of the frame's
 * polygon (2D) or the triangles of its surface (3D) (seal.h) */
#include "sbc/seal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* 3D: does the triangle a, b, c with vector area m [3] (outward as stored)
 * face away from the box, as the face its corners share does? An edge
 * sphere moved onto its edge line for the triangulation can fold the
 * triangle beside it inward (docs/frame3d.md, "Irregular packings"); as a
 * wall it would push the spheres inside out, so it is left out. */
static int faces_out(const sbc_frame *f, int a, int b, int c, const double m[3])
{
    const int shared = f->side[a] & f->side[b] & f->side[c];
    double out = 0.0;
    int axis;
    for (axis = 0; axis < 3; ++axis) {
        if (shared & (1 << (2 * axis)))
            out -= m[axis];
        if (shared & (2 << (2 * axis)))
            out += m[axis];
    }
    return !shared || out > 0.0;
}

/* 3D: the triangles of the frame's cells, a quadrilateral (a, b, c, d) as
 * (a, b, c) and (a, c, d), those facing out of the box, and the orientation
 * from the volume they enclose, (1/6) sum a . (b x c) */
static sbc_status triangles(sbc_seal *s, const sbc_frame *f, sbc_error *err)
{
    double volume6 = 0.0;
    int c, k, pass, t = 0;
    s->corner = malloc(sizeof(int) * 6 * (size_t)(f->ncell > 0 ? f->ncell : 1));
    if (!s->corner)
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: seal: out of memory");
    for (pass = 0; pass < 2; ++pass)
        for (c = 0; c < f->ncell; ++c) {
            const int *v = &f->cell[4 * c];
            for (k = 0; k < (v[3] == v[0] ? 1 : 2); ++k) {
                const double *a = &f->X[3 * v[0]], *b = &f->X[3 * v[1 + k]], *cc = &f->X[3 * v[2 + k]];
                double m[3], u[3], w[3];
                int j;
                if (pass == 0) {
                    sbc_cross3(b, cc, m);
                    volume6 += sbc_dot3(a, m);
                    continue;
                }
                for (j = 0; j < 3; ++j) {
                    u[j] = (b[j] - a[j]) * (volume6 > 0.0 ? 1.0 : -1.0);
                    w[j] = cc[j] - a[j];
                }
                sbc_cross3(u, w, m); /* outward */
                if (faces_out(f, v[0], v[1 + k], v[2 + k], m)) {
                    s->corner[3 * t] = v[0];
                    s->corner[3 * t + 1] = v[1 + k];
                    s->corner[3 * t + 2] = v[2 + k];
                    ++t;
                }
            }
        }
    s->nwall = t;
    if (t < 4 || !(fabs(volume6) > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: seal: the frame's surface (%d particles, %d triangles) "
                        "encloses no volume", f->n, t);
    s->inward = volume6 > 0.0 ? -1.0 : 1.0;
    return SBC_OK;
}

static int slot_of(const void *ctx, int k) { return ((const int *)ctx)[k]; }

sbc_seal_particles sbc_seal_packed(int n, const double *x, double *f, int dim, const double *r, const int *slot)
{
    sbc_seal_particles p;
    p.n = n;
    p.x = x;
    p.f = f;
    p.stride = dim;
    p.r = r;
    p.frame = slot_of;
    p.ctx = slot;
    return p;
}

int *sbc_seal_slots(const sbc_frame *f, int n)
{
    int *slot = malloc(sizeof(int) * (size_t)(n > 0 ? n : 1)), k;
    for (k = 0; slot && k < n; ++k)
        slot[k] = -1;
    for (k = 0; slot && k < f->n; ++k)
        slot[f->particle[k]] = k;
    return slot;
}

sbc_status sbc_seal_init(sbc_seal *s, const sbc_frame *f, double reach, sbc_error *err)
{
    double area2 = 0.0; /* twice the signed area of the reference polygon (shoelace) */
    int q;
    memset(s, 0, sizeof *s);
    s->dim = f->dim == 3 ? 3 : 2;
    if (!(reach > 0.0) || !isfinite(reach))
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: seal: the Verlet margin %g m is not positive", reach);
    if (s->dim == 3) {
        sbc_status st = triangles(s, f, err);
        if (st != SBC_OK) {
            sbc_seal_free(s);
            return st;
        }
    } else {
        for (q = 0; q < f->n; ++q) {
            const double *a = &f->X[3 * q], *b = &f->X[3 * ((q + 1) % f->n)];
            area2 += a[0] * b[1] - a[1] * b[0];
        }
        if (f->n < 3 || !(fabs(area2) > 0.0))
            return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: seal: the frame's polygon (%d particles) has no area", f->n);
        s->inward = area2 > 0.0 ? 1.0 : -1.0;
        s->nwall = f->n;
    }
    s->reach = reach;
    s->tracked = -1;
    s->fx_built = malloc(sizeof(double) * 3 * (size_t)f->n);
    if (!s->fx_built) {
        sbc_seal_free(s);
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: seal: out of memory");
    }
    return SBC_OK;
}

void sbc_seal_free(sbc_seal *s)
{
    free(s->corner);
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

/* 3D: distance from p to the segment a -> b (m) */
static double segment3(const double *a, const double *b, const double *p)
{
    double u[3], w[3], len2, t;
    int k;
    for (k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        w[k] = p[k] - a[k];
    }
    len2 = sbc_dot3(u, u);
    t = len2 > 0.0 ? fmin(1.0, fmax(0.0, sbc_dot3(w, u) / len2)) : 0.0;
    for (k = 0; k < 3; ++k)
        w[k] -= t * u[k];
    return sqrt(sbc_dot3(w, w));
}

/* 3D: the triangle a, b, c against p: the barycentric coordinates l [3] of
 * p's projection on its plane, the signed distance s from the plane (> 0 on
 * the inner side), the inward unit normal n [3]; returns the distance from p
 * to the triangle (m), or -1 for a triangle of no area */
static double triangle(const sbc_seal *S, const double *a, const double *b, const double *c, const double *p,
                       double l[3], double *s, double n[3])
{
    double v0[3], v1[3], v2[3], m[3], area2, d00, d01, d11, d20, d21, det;
    int k;
    for (k = 0; k < 3; ++k) {
        v0[k] = b[k] - a[k];
        v1[k] = c[k] - a[k];
        v2[k] = p[k] - a[k];
    }
    sbc_cross3(v0, v1, m);
    area2 = sqrt(sbc_dot3(m, m));
    d00 = sbc_dot3(v0, v0);
    d01 = sbc_dot3(v0, v1);
    d11 = sbc_dot3(v1, v1);
    det = d00 * d11 - d01 * d01;
    if (!(area2 > 0.0) || !(det > 0.0))
        return -1.0;
    for (k = 0; k < 3; ++k)
        n[k] = S->inward * m[k] / area2;
    *s = sbc_dot3(v2, n);
    d20 = sbc_dot3(v2, v0);
    d21 = sbc_dot3(v2, v1);
    l[1] = (d11 * d20 - d01 * d21) / det;
    l[2] = (d00 * d21 - d01 * d20) / det;
    l[0] = 1.0 - l[1] - l[2];
    if (l[0] >= 0.0 && l[1] >= 0.0 && l[2] >= 0.0)
        return fabs(*s);
    return fmin(segment3(a, b, p), fmin(segment3(b, c, p), segment3(c, a, p)));
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

/* does wall q leave the frame particle at frame position own alone? In 2D
 * the two edges it ends; in 3D the triangles of the faces it lies on (its
 * own among them) */
static int owns(const sbc_seal *s, const sbc_frame *f, int own, int q)
{
    if (s->dim == 3) {
        const int *v = &s->corner[3 * q];
        return v[0] == own || v[1] == own || v[2] == own || (f->side[v[0]] & f->side[v[1]] & f->side[v[2]] & f->side[own]);
    }
    return q == own || (q + 1) % f->n == own;
}

/* the distance from x to wall q (m) */
static double wall_distance(const sbc_seal *s, const sbc_frame *f, const double *fx, int q, const double *x)
{
    double t, sd, l[3], n[3];
    if (s->dim == 3) {
        const int *v = &s->corner[3 * q];
        return fabs(triangle(s, &fx[3 * v[0]], &fx[3 * v[1]], &fx[3 * v[2]], x, l, &sd, n));
    }
    return segment(s, &fx[3 * q], &fx[3 * ((q + 1) % f->n)], x, &t, &sd);
}

static sbc_status collect(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                          sbc_error *err)
{
    const int d = s->dim;
    int k, q, j;
    double *xb = realloc(s->x_built, sizeof(double) * (size_t)d * (size_t)(p->n > 0 ? p->n : 1));
    if (!xb)
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: seal: out of memory for %d particles", p->n);
    s->x_built = xb;
    s->count = 0;
    for (k = 0; k < p->n; ++k) {
        const double *x = &p->x[(size_t)p->stride * (size_t)k];
        for (j = 0; j < d; ++j)
            xb[d * k + j] = x[j];
        const int own = p->frame(p->ctx, k); /* a frame particle skips the walls it ends */
        for (q = 0; q < s->nwall && own >= -1; ++q) {
            if (own >= 0 && owns(s, f, own, q))
                continue;
            if (wall_distance(s, f, fx, q, x) < p->r[k] + s->reach && !add(s, k, q))
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
    const int d = s->dim;
    int k, j;
    if (s->tracked != p->n)
        return 1;
    for (k = 0; k < f->n; ++k) {
        double d2 = 0.0;
        for (j = 0; j < d; ++j)
            d2 += (fx[3 * k + j] - s->fx_built[3 * k + j]) * (fx[3 * k + j] - s->fx_built[3 * k + j]);
        if (d2 > lim)
            return 1;
    }
    for (k = 0; k < p->n; ++k) {
        const double *x = &p->x[(size_t)p->stride * (size_t)k];
        double d2 = 0.0;
        for (j = 0; j < d; ++j)
            d2 += (x[j] - s->x_built[d * k + j]) * (x[j] - s->x_built[d * k + j]);
        if (d2 > lim)
            return 1;
    }
    return 0;
}

/* 3D: candidate c's wall force on its sphere and the reactions on the
 * triangle's corners; returns the wall's energy (J), 0 when it does not touch */
static double triangle_force(sbc_seal *s, const double *fx, const sbc_seal_particles *p, double kn, int c,
                             double *reaction)
{
    const int k = s->particle[c], *v = &s->corner[3 * s->edge[c]];
    const double *x = &p->x[(size_t)p->stride * (size_t)k], w = SBC_SEAL_WALL * p->r[k];
    double l[3], sd, n[3], fn, *fk;
    int i, j;
    if (triangle(s, &fx[3 * v[0]], &fx[3 * v[1]], &fx[3 * v[2]], x, l, &sd, n) < 0.0 ||
        !(l[0] > 0.0 && l[1] > 0.0 && l[2] > 0.0) || sd >= w)
        return 0.0;
    fn = kn * (w - sd); /* N */
    fk = &p->f[(size_t)p->stride * (size_t)k];
    for (j = 0; j < 3; ++j)
        fk[j] += fn * n[j];
    for (i = 0; i < 3 && reaction; ++i)
        for (j = 0; j < 3; ++j)
            reaction[3 * v[i] + j] -= l[i] * fn * n[j];
    s->contacts++;
    return 0.5 * fn * (w - sd); /* J */
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
        if (s->dim == 3) {
            e += triangle_force(s, fx, p, kn, c, reaction);
            continue;
        }
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

sbc_status sbc_seal_forces_packed(sbc_seal *s, const sbc_frame *f, const double *fx, const sbc_seal_particles *p,
                                  double kn, double *reaction, double *energy, sbc_error *err)
{
    sbc_status st;
    int q, k;
    memset(reaction, 0, sizeof(double) * 3 * (size_t)f->n);
    st = sbc_seal_forces(s, f, fx, p, kn, 0, reaction, energy, err);
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < s->dim; ++k)
            p->f[(size_t)p->stride * (size_t)f->particle[q] + (size_t)k] += reaction[3 * q + k];
    return st;
}
