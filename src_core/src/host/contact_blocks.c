/* The contact blocks of the condensed tangent and of interior newton's
 * Jacobian (condensed.h): the derivative of one contact's loads on its two
 * particles over their degrees of freedom (docs/fe2.md, "The condensed
 * tangent"). */
#include "contact_blocks.h"

#include <math.h>
#include <string.h>

#include "sbc/tensor.h"

/* 2D: the slip the increment gave a sticking contact, I(l) = integral of
 * t . dl along the straight path from the branch l0 at the increment's
 * start (t = J l / |l|, J l = (-l_y, l_x), the engine's dus summed over its
 * steps), and its gradient over l: with J l0 . l0 = 0,
 *   I(l) = (J l0 . l) G(l),  G(l) = int_0^1 ds / |l0 + s (l - l0)|,
 *   grad I = G J l0 + (J l0 . l) grad G,  grad G = -int_0^1 s l(s) / |l(s)|^3 ds,
 * by 4-point Gauss-Legendre on [0, 1] (|l(s)| changes by the increment's
 * strain: the rule is exact to round-off there). At l = l0 it is 0 and t. */
double sbc_path_slip(const double x0a[2], const double x0b[2], double lx, double ly, double grad[2])
{
    static const double node[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                   0.9305681557970263};
    static const double weight[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                     0.1739274225687269};
    const double l0x = x0b[0] - x0a[0], l0y = x0b[1] - x0a[1];
    const double jx = -l0y, jy = l0x, jl = jx * lx + jy * ly;
    double G = 0.0, gx = 0.0, gy = 0.0;
    int k;
    for (k = 0; k < 4; ++k) {
        const double s = node[k], sx = l0x + s * (lx - l0x), sy = l0y + s * (ly - l0y);
        const double inv = 1.0 / sqrt(sx * sx + sy * sy);
        G += weight[k] * inv;
        gx -= weight[k] * s * sx * inv * inv * inv;
        gy -= weight[k] * s * sy * inv * inv * inv;
    }
    grad[0] = G * jx + jl * gx;
    grad[1] = G * jy + jl * gy;
    return jl * G;
}

/* 2D: d(loads)/d(dofs) of one contact, loads (f_i, tau_i, f_j, tau_j) over
 * dofs (u_i, theta_i, u_j, theta_j). With l = x_j - x_i, d = |l|, n = l/d,
 * t = (-n_y, n_x), overlap dn = R_i + R_j - d, fn = kn dn, the engine's
 * tangential force fs = (the spring's force on i) . t, and the force on j
 * f_j = fn n - fs t (eq. 6; the engine's moments tau = R fs on both):
 *   d f_j = -kn n (n.dl) + (fn/d) t (t.dl) + (fs/d) n (t.dl) - dfs t,  f_i = -f_j
 *   dfs = ks (t.dl - R_i dtheta_i - R_j dtheta_j)        sticking (with x0: grad I . dl for t.dl)
 *   dfs = -sgn(fs) mu kn (n.dl)                           sliding (|fs| at mu fn)
 * with dl = du_j - du_i; the first two terms turn the normal force with the
 * branch, the third the tangential one. An intact bond (eqs. 7-8) sticks
 * whatever its force, pulls as it pushes, and adds its bending spring's
 * moment m = kr (theta_j - theta_i) + m0 on i, -m on j. */
static int block_2d(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST])
{
    const int a = net->i[k], b = net->j[k];
    const double *xa = &net->x[2 * a], *xb = &net->x[2 * b];
    const double lx = xb[0] - xa[0], ly = xb[1] - xa[1], d = sqrt(lx * lx + ly * ly);
    const double Ra = net->r[a], Rb = net->r[b], dn = Ra + Rb - d;
    const sbc_frictional *law = &net->law;
    const int bond = net->bond && net->bond[k];
    double n[2], t[2], fn, fs, M[2][2], w[2][2] = {{0, 0}, {0, 0}}, g[2] = {0, 0}, gr[2] = {0, 0};
    int p, q, stick, slide;
    if ((!bond && !(dn > 0.0)) || !(d > 0.0))
        return 0; /* open */
    n[0] = lx / d;
    n[1] = ly / d;
    t[0] = -n[1];
    t[1] = n[0];
    fn = law->kn * dn;
    fs = net->fs ? net->fs[3 * k] * t[0] + net->fs[3 * k + 1] * t[1] : 0.0;
    slide = !bond && law->ks > 0.0 && fabs(fs) >= law->mu * fn * (1.0 - SBC_SLIDING_BAND);
    stick = law->ks > 0.0 && !slide;
    for (p = 0; p < 2; ++p)
        for (q = 0; q < 2; ++q)
            M[p][q] = -law->kn * n[p] * n[q] + fn / d * t[p] * t[q] + fs / d * n[p] * t[q];
    if (stick) { /* dfs = g . dl + gr . (dtheta_i, dtheta_j) */
        if (net->x0)
            sbc_path_slip(&net->x0[2 * a], &net->x0[2 * b], lx, ly, g);
        else {
            g[0] = t[0];
            g[1] = t[1];
        }
        g[0] *= law->ks;
        g[1] *= law->ks;
        for (p = 0; p < 2; ++p) {
            for (q = 0; q < 2; ++q)
                M[p][q] -= t[p] * g[q];
            w[p][0] = law->ks * Ra * t[p];
            w[p][1] = law->ks * Rb * t[p];
        }
        gr[0] = -law->ks * Ra;
        gr[1] = -law->ks * Rb;
    } else if (slide) {
        const double s = fs < 0.0 ? -1.0 : 1.0;
        for (p = 0; p < 2; ++p) {
            g[p] = -s * law->mu * law->kn * n[p];
            for (q = 0; q < 2; ++q)
                M[p][q] += s * law->mu * law->kn * t[p] * n[q];
        }
    }
    for (p = 0; p < 2; ++p) {
        for (q = 0; q < 2; ++q) {
            B[3 + p][3 + q] = M[p][q];  /* f_j over u_j */
            B[3 + p][q] = -M[p][q];     /* f_j over u_i */
            B[p][3 + q] = -M[p][q];     /* f_i = -f_j */
            B[p][q] = M[p][q];
        }
        B[3 + p][2] = w[p][0];
        B[3 + p][5] = w[p][1];
        B[p][2] = -w[p][0];
        B[p][5] = -w[p][1];
        /* tau_i = R_i fs, tau_j = R_j fs */
        B[2][3 + p] = Ra * g[p];
        B[2][p] = -Ra * g[p];
        B[5][3 + p] = Rb * g[p];
        B[5][p] = -Rb * g[p];
    }
    B[2][2] = Ra * gr[0] - (bond ? net->kr : 0.0);
    B[2][5] = Ra * gr[1] + (bond ? net->kr : 0.0);
    B[5][2] = Rb * gr[0] + (bond ? net->kr : 0.0);
    B[5][5] = Rb * gr[1] - (bond ? net->kr : 0.0);
    return 1;
}

void sbc_spring_3d_at(const double xi[3], const double xj[3], double Ri, double Rj, const double l0[3],
                      const double dthi[3], const double dthj[3], const double fs0[3], const sbc_frictional *law,
                      sbc_spring_3d *out)
{
    double l[3], ri[3], rj[3], ti[3], tj[3], vn, mag, limit;
    int p;
    memset(out, 0, sizeof *out);
    out->c = 1.0;
    for (p = 0; p < 3; ++p)
        l[p] = xj[p] - xi[p];
    out->L = sqrt(sbc_dot3(l, l));
    out->dn = Ri + Rj - out->L;
    if (!(out->dn > 0.0) || !(out->L > 0.0)) {
        out->open = 1;
        return;
    }
    out->s = Ri - 0.5 * out->dn;
    for (p = 0; p < 3; ++p) {
        out->n[p] = l[p] / out->L;
        ri[p] = out->s * out->n[p];
        rj[p] = (out->s - out->L) * out->n[p];
    }
    if (!fs0 || !(law->ks > 0.0))
        return;
    ti[0] = ti[1] = ti[2] = tj[0] = tj[1] = tj[2] = 0.0;
    if (dthi)
        sbc_cross3(dthi, ri, ti);
    if (dthj)
        sbc_cross3(dthj, rj, tj);
    for (p = 0; p < 3; ++p) /* v = fs0 - ks du, du = -(l - l0) + dtheta_i x r_i - dtheta_j x r_j */
        out->v[p] = fs0[p] - law->ks * ((l0 ? l0[p] - l[p] : 0.0) + ti[p] - tj[p]);
    vn = sbc_dot3(out->v, out->n);
    for (p = 0; p < 3; ++p)
        out->fs[p] = out->v[p] - vn * out->n[p];
    mag = sqrt(sbc_dot3(out->fs, out->fs));
    limit = law->mu * law->kn * out->dn;
    if (mag > limit) {
        out->c = limit / mag;
        for (p = 0; p < 3; ++p)
            out->fs[p] *= out->c;
    }
}

/* [v]x w = v x w */
static void cross_matrix(const double v[3], double X[3][3])
{
    X[0][0] = X[1][1] = X[2][2] = 0.0;
    X[0][1] = -v[2];
    X[0][2] = v[1];
    X[1][0] = v[2];
    X[1][2] = -v[0];
    X[2][0] = -v[1];
    X[2][1] = v[0];
}

/* 3D: the same over (u_i, theta_i, u_j, theta_j), each 3, for the spring of
 * sbc_spring_3d_at (with net->x0 the increment's; without, the current
 * spring as its own trial, v = fs, dtheta = 0: the linearization of the
 * sphere engine's incremental law, spheres.c). With A_i = n n^T / 2 +
 * (s / L) P and A_j = -n n^T / 2 + ((s - L) / L) P (d r_i = A_i dl,
 * d r_j = A_j dl, dl = du_j - du_i) and the force on i f = -kn dn n + fs:
 *   d f  = [kn n n^T - (kn dn / L) P] dl + d fs
 *   d(P v) = -[ks P (-I + [dtheta_i]x A_i - [dtheta_j]x A_j) + (n . v / L) P
 *           + n (P v)^T / L] dl + ks s [n]x dtheta_i - ks (s - L) [n]x dtheta_j
 *   d fs = d(P v)                                                  sticking
 *   d fs = -mu kn e n^T dl + c (I - e e^T) d(P v)                  sliding (e = fs / |fs|)
 * the loads are f on i, -f on j, the moments r_i x f and f x r_j, whose
 * arms change with dl too. */
static int block_3d(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST])
{
    const int a = net->i[k], b = net->j[k];
    const double *xa = &net->x[3 * a], *xb = &net->x[3 * b];
    const sbc_frictional *law = &net->law;
    sbc_spring_3d sp;
    double n[3], L, dn, s, fn, fs[3], f[3], e[3] = {0, 0, 0}, mag, vn, c, Pv[3];
    double P[3][3], N[3][3], Fx[3][3], M[3][3], Wa[3][3], Wb[3][3], Ra[3][3], Rb[3][3], Ga[3][3], Gb[3][3];
    double D[3][3], Aa[3][3], Ab[3][3], J[3][3], Ta[3][3], Tb[3][3];
    double row[3][SBC_BLOCK_MOST];
    int p, q, m, stick, slide;
    if (net->dim == 3 && net->x0) { /* the increment's spring from the committed state */
        double l0[3], dta[3], dtb[3];
        for (p = 0; p < 3; ++p) {
            l0[p] = net->x0[3 * b + p] - net->x0[3 * a + p];
            dta[p] = net->theta[3 * a + p] - net->theta0[3 * a + p];
            dtb[p] = net->theta[3 * b + p] - net->theta0[3 * b + p];
        }
        sbc_spring_3d_at(xa, xb, net->r[a], net->r[b], l0, dta, dtb, net->fs0 ? &net->fs0[3 * k] : NULL, law, &sp);
        cross_matrix(dta, Ta);
        cross_matrix(dtb, Tb);
    } else {
        sbc_spring_3d_at(xa, xb, net->r[a], net->r[b], NULL, NULL, NULL, net->fs ? &net->fs[3 * k] : NULL, law, &sp);
        memset(Ta, 0, sizeof Ta);
        memset(Tb, 0, sizeof Tb);
    }
    if (sp.open)
        return 0;
    L = sp.L;
    dn = sp.dn;
    s = sp.s;
    memcpy(n, sp.n, sizeof n);
    fn = law->kn * dn;
    vn = sbc_dot3(sp.v, n);
    for (p = 0; p < 3; ++p)
        Pv[p] = sp.v[p] - vn * n[p];
    memcpy(fs, sp.fs, sizeof fs);
    mag = sqrt(sbc_dot3(Pv, Pv));
    slide = law->ks > 0.0 && mag >= law->mu * fn * (1.0 - SBC_SLIDING_BAND);
    stick = law->ks > 0.0 && !slide;
    c = slide && mag > law->mu * fn ? law->mu * fn / mag : 1.0;
    for (p = 0; p < 3; ++p) {
        f[p] = -fn * n[p] + fs[p];
        if (slide && mag > 0.0)
            e[p] = Pv[p] / mag;
    }
    cross_matrix(n, N);
    cross_matrix(f, Fx);
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            P[p][q] = (p == q ? 1.0 : 0.0) - n[p] * n[q];
            Aa[p][q] = 0.5 * n[p] * n[q] + s / L * P[p][q];
            Ab[p][q] = -0.5 * n[p] * n[q] + (s - L) / L * P[p][q];
        }
    for (p = 0; p < 3; ++p) /* J = d(du)/dl = -I + [dtheta_i]x A_i - [dtheta_j]x A_j */
        for (q = 0; q < 3; ++q) {
            J[p][q] = p == q ? -1.0 : 0.0;
            for (m = 0; m < 3; ++m)
                J[p][q] += Ta[p][m] * Aa[m][q] - Tb[p][m] * Ab[m][q];
        }
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            double tan_dl = -vn / L * P[p][q] - n[p] * Pv[q] / L; /* d(P v)/dl */
            for (m = 0; m < 3; ++m)
                tan_dl -= law->ks * P[p][m] * J[m][q];
            D[p][q] = tan_dl;
            Ra[p][q] = law->ks * s * N[p][q];
            Rb[p][q] = -law->ks * (s - L) * N[p][q];
            M[p][q] = law->kn * n[p] * n[q] - law->kn * dn / L * P[p][q] + (stick ? tan_dl : 0.0);
            Wa[p][q] = stick ? Ra[p][q] : 0.0;
            Wb[p][q] = stick ? Rb[p][q] : 0.0;
        }
    if (slide) /* c (I - e e) d(P v) - mu kn e n^T */
        for (p = 0; p < 3; ++p)
            for (q = 0; q < 3; ++q) {
                double pd = 0.0, pa = 0.0, pb = 0.0;
                for (m = 0; m < 3; ++m) {
                    const double Pe = c * ((p == m ? 1.0 : 0.0) - e[p] * e[m]);
                    pd += Pe * D[m][q];
                    pa += Pe * Ra[m][q];
                    pb += Pe * Rb[m][q];
                }
                M[p][q] += pd - law->mu * law->kn * e[p] * n[q];
                Wa[p][q] = pa;
                Wb[p][q] = pb;
            }
    /* the moments' arms: d r_i x f = -[f]x A_i dl, f x d r_j = [f]x A_j dl */
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            double ga = 0.0, gb = 0.0;
            for (m = 0; m < 3; ++m) {
                ga += -Fx[p][m] * Aa[m][q];
                gb += Fx[p][m] * Ab[m][q];
            }
            Ga[p][q] = ga;
            Gb[p][q] = gb;
        }
    for (p = 0; p < 3; ++p) /* df over (u_i, theta_i, u_j, theta_j) */
        for (q = 0; q < 3; ++q) {
            row[p][q] = -M[p][q];
            row[p][3 + q] = Wa[p][q];
            row[p][6 + q] = M[p][q];
            row[p][9 + q] = Wb[p][q];
        }
    for (p = 0; p < 3; ++p)
        for (q = 0; q < SBC_BLOCK_MOST; ++q) {
            double ta = 0.0, tb = 0.0;
            for (m = 0; m < 3; ++m) {
                ta += s * N[p][m] * row[m][q];          /* r_i x df */
                tb += -(s - L) * N[p][m] * row[m][q];   /* df x r_j = -r_j x df */
            }
            if (q < 3) {
                ta -= Ga[p][q];
                tb -= Gb[p][q];
            } else if (q >= 6 && q < 9) {
                ta += Ga[p][q - 6];
                tb += Gb[p][q - 6];
            }
            B[p][q] = row[p][q];       /* f on i */
            B[3 + p][q] = ta;          /* moment on i */
            B[6 + p][q] = -row[p][q];  /* -f on j */
            B[9 + p][q] = tb;          /* moment on j */
        }
    return 1;
}

int sbc_pair_index(int npair, const int *i, const int *j, int a, int b)
{
    int lo = 0, hi = npair;
    while (lo < hi) { /* the first pair not before (a, b) */
        const int mid = lo + (hi - lo) / 2;
        if (i[mid] < a || (i[mid] == a && j[mid] < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < npair && i[lo] == a && j[lo] == b ? lo : -1;
}

int sbc_contact_block(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST])
{
    memset(B, 0, sizeof(double) * SBC_BLOCK_MOST * SBC_BLOCK_MOST);
    return net->dim == 3 ? block_3d(net, k, B) : block_2d(net, k, B);
}
