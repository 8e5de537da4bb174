/* interior newton: one contact's loads over the increment (statics_work.h) */
#include "statics_work.h"

#include <math.h>
#include <string.h>

#include "contact_blocks.h"
#include "sbc/tensor.h"

/* the committed pair (a, b), a < b: its index, -1 for a pair that was not committed */
static int committed_pair(const statics_work *w, int a, int b)
{
    return sbc_pair_index(w->p->npair0, w->p->i0, w->p->j0, a, b);
}

/* 3D: candidate k's contact at (x, theta), its loads added to w->res; returns |f| (N), or -1 when open */
static double contact_3d(statics_work *w, int k, const double *x, const double *theta)
{
    const sbc_statics_problem *p = w->p;
    const int a = w->cand.i[k], b = w->cand.j[k], c0 = committed_pair(w, a, b);
    double l0[3], dta[3], dtb[3], f[3], ra[3], rb[3], ma[3], mb[3], *F0 = &w->fs0c[3 * k];
    sbc_spring_3d sp;
    int q;
    for (q = 0; q < 3; ++q) {
        l0[q] = p->x0[3 * b + q] - p->x0[3 * a + q];
        dta[q] = theta[3 * a + q] - p->theta0[3 * a + q];
        dtb[q] = theta[3 * b + q] - p->theta0[3 * b + q];
        F0[q] = p->fs0 && c0 >= 0 ? p->fs0[3 * c0 + q] : 0.0;
    }
    sbc_spring_3d_at(&x[3 * a], &x[3 * b], p->r[a], p->r[b], l0, dta, dtb, p->fs0 ? F0 : NULL, &p->law, &sp);
    memcpy(&w->fsv[3 * k], sp.fs, sizeof sp.fs);
    w->psi[k] = 0.0;
    if (sp.open)
        return -1.0;
    if (p->fs0 && p->law.ks > 0.0) {
        const double vn = sbc_dot3(sp.v, sp.n), cap = p->law.mu * p->law.kn * sp.dn;
        double y2 = 0.0, over;
        for (q = 0; q < 3; ++q)
            y2 += (sp.v[q] - vn * sp.n[q]) * (sp.v[q] - vn * sp.n[q]);
        over = fmax(0.0, sqrt(y2) - cap);
        w->psi[k] = -(y2 - over * over) / (2.0 * p->law.ks);
    }
    for (q = 0; q < 3; ++q) {
        f[q] = -p->law.kn * sp.dn * sp.n[q] + sp.fs[q]; /* the force on a */
        ra[q] = sp.s * sp.n[q];
        rb[q] = (sp.s - sp.L) * sp.n[q];
    }
    sbc_cross3(ra, f, ma); /* the moments about the centres, as spheres.c */
    sbc_cross3(f, rb, mb);
    for (q = 0; q < 3; ++q) {
        w->res[6 * a + q] += f[q];
        w->res[6 * a + 3 + q] += ma[q];
        w->res[6 * b + q] -= f[q];
        w->res[6 * b + 3 + q] += mb[q];
    }
    return sqrt(sbc_dot3(f, f));
}

/* 2D: candidate k's contact at (x, theta), its loads added to w->res; returns |f| (N), or -1 when open */
static double contact_2d(statics_work *w, int k, const double *x, const double *theta)
{
    const sbc_statics_problem *p = w->p;
    const int a = w->cand.i[k], b = w->cand.j[k], c0 = p->fs0 ? committed_pair(w, a, b) : -1;
    const int bond = c0 >= 0 && w->intact && w->intact[c0];
    const double lx = x[2 * b] - x[2 * a], ly = x[2 * b + 1] - x[2 * a + 1], rs = p->r[a] + p->r[b];
    const double d2 = lx * lx + ly * ly;
    double d, nx, ny, dn, fn, fs = 0.0, m = 0.0, fx, fy;
    w->fs[k] = 0.0;
    w->psi[k] = 0.0;
    w->fsv[3 * k] = w->fsv[3 * k + 1] = w->fsv[3 * k + 2] = 0.0;
    if (w->bondc) {
        w->bondc[k] = bond;
        w->mc[k] = 0.0;
    }
    if (!bond && d2 >= rs * rs)
        return -1.0; /* open: the spring is lost */
    d = sqrt(d2);
    nx = lx / d;
    ny = ly / d;
    dn = rs - d;
    if (p->fs0) { /* the spring from its committed value by the increment's slip, capped (eq. 6) */
        double g[2];
        const double slip = sbc_path_slip(&p->x0[2 * a], &p->x0[2 * b], lx, ly, g) -
                            (p->r[a] * (theta[a] - p->theta0[a]) + p->r[b] * (theta[b] - p->theta0[b]));
        const double y = (c0 >= 0 ? p->fs0[c0] : 0.0) + p->law.ks * slip;
        fs = c0 >= 0 ? p->fs0[c0] : 0.0;
        if (bond) { /* eq. 7: the shear spring uncapped, the bending spring from its committed moment */
            fn = p->law.kn * dn;
            fs = y;
            m = p->m0[c0] + p->bonds->kr * ((theta[b] - p->theta0[b]) - (theta[a] - p->theta0[a]));
            w->mc[k] = m;
            w->psi[k] = -(p->law.ks > 0.0 ? y * y / (2.0 * p->law.ks) : 0.0) -
                        (p->bonds->kr > 0.0 ? m * m / (2.0 * p->bonds->kr) : 0.0);
        } else {
            if (p->law.ks > 0.0) {
                const double over = fmax(0.0, fabs(y) - p->law.mu * p->law.kn * dn);
                w->psi[k] = -(y * y - over * over) / (2.0 * p->law.ks);
            }
            fn = sbc_frictional_force(&p->law, dn, slip, &fs, NULL);
        }
    } else
        fn = p->law.kn * dn;
    w->fs[k] = fs;
    w->fsv[3 * k] = -fs * ny; /* fs t, t = (-n_y, n_x) */
    w->fsv[3 * k + 1] = fs * nx;
    fx = -fn * nx - fs * ny; /* the force on a: -fn n + fs t */
    fy = -fn * ny + fs * nx;
    w->res[3 * a] += fx;
    w->res[3 * a + 1] += fy;
    w->res[3 * a + 2] += p->r[a] * fs + m;
    w->res[3 * b] -= fx;
    w->res[3 * b + 1] -= fy;
    w->res[3 * b + 2] += p->r[b] * fs - m;
    return sqrt(fn * fn + fs * fs);
}

double sbc_statics_contact(statics_work *w, int k, const double *x, const double *theta)
{
    return w->dim == 3 ? contact_3d(w, k, x, theta) : contact_2d(w, k, x, theta);
}
