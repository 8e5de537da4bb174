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
 * branch, the third the tangential one. */
static int block_2d(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST])
{
    const int a = net->i[k], b = net->j[k];
    const double *xa = &net->x[2 * a], *xb = &net->x[2 * b];
    const double lx = xb[0] - xa[0], ly = xb[1] - xa[1], d = sqrt(lx * lx + ly * ly);
    const double Ra = net->r[a], Rb = net->r[b], dn = Ra + Rb - d;
    const sbc_frictional *law = &net->law;
    double n[2], t[2], fn, fs, M[2][2], w[2][2] = {{0, 0}, {0, 0}}, g[2] = {0, 0}, gr[2] = {0, 0};
    int p, q, stick, slide;
    if (!(dn > 0.0) || !(d > 0.0))
        return 0; /* open */
    n[0] = lx / d;
    n[1] = ly / d;
    t[0] = -n[1];
    t[1] = n[0];
    fn = law->kn * dn;
    fs = net->fs ? net->fs[3 * k] * t[0] + net->fs[3 * k + 1] * t[1] : 0.0;
    slide = law->ks > 0.0 && fabs(fs) >= law->mu * fn * (1.0 - SBC_SLIDING_BAND);
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
    B[2][2] = Ra * gr[0];
    B[2][5] = Ra * gr[1];
    B[5][2] = Rb * gr[0];
    B[5][5] = Rb * gr[1];
    return 1;
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

/* 3D: the same over (u_i, theta_i, u_j, theta_j), each 3 (spheres.c and
 * bpm_bond.c's sbc_broken_bond_increment). With l, L, n, overlap dn as in
 * 2D, P = I - n n, the contact point halfway across the overlap
 * (r_i = s n, r_j = (s - L) n, s = R_i - dn/2) and the force on i
 * f = -kn dn n + fs (fs the spring, in the contact plane):
 *   d f = [kn n n - (kn dn / L) P] dl + dfs
 *   dfs = ks P dl + ks s [n]x dtheta_i - ks (s - L) [n]x dtheta_j - n (fs . dl) / L   sticking
 * (the spring loads with the contact point's tangential slip and is kept in
 * the turning plane), and sliding (|fs| at mu fn, direction e):
 *   dfs = -mu kn (n . dl) e + (I - e e) (the sticking dfs);
 * the loads are f on i, -f on j, the moments r_i x f and f x r_j, whose
 * arms change with dl too. */
static int block_3d(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST])
{
    const int a = net->i[k], b = net->j[k];
    const double *xa = &net->x[3 * a], *xb = &net->x[3 * b];
    const sbc_frictional *law = &net->law;
    double l[3], n[3], L = 0.0, dn, s, fn, fs[3] = {0, 0, 0}, f[3], e[3] = {0, 0, 0}, mag;
    double P[3][3], N[3][3], Fx[3][3], M[3][3], Wa[3][3], Wb[3][3], Ra[3][3], Rb[3][3], Ga[3][3], Gb[3][3];
    double D[3][3]; /* rows of df over (u_i, theta_i, u_j, theta_j) as 3 x 12 */
    double row[3][SBC_BLOCK_MOST];
    int p, q, m, stick, slide;
    for (p = 0; p < 3; ++p) {
        l[p] = xb[p] - xa[p];
        L += l[p] * l[p];
    }
    L = sqrt(L);
    dn = net->r[a] + net->r[b] - L;
    if (!(dn > 0.0) || !(L > 0.0))
        return 0; /* open */
    for (p = 0; p < 3; ++p)
        n[p] = l[p] / L;
    s = net->r[a] - 0.5 * dn;
    fn = law->kn * dn;
    if (net->fs)
        for (p = 0; p < 3; ++p)
            fs[p] = net->fs[3 * k + p];
    mag = sqrt(sbc_dot3(fs, fs));
    slide = law->ks > 0.0 && mag >= law->mu * fn * (1.0 - SBC_SLIDING_BAND);
    stick = law->ks > 0.0 && !slide;
    for (p = 0; p < 3; ++p) {
        f[p] = -fn * n[p] + fs[p];
        if (slide && mag > 0.0)
            e[p] = fs[p] / mag;
    }
    cross_matrix(n, N);
    cross_matrix(f, Fx);
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            const double I = p == q ? 1.0 : 0.0;
            double tan_dl, tan_a, tan_b; /* the sticking dfs */
            P[p][q] = I - n[p] * n[q];
            tan_dl = (law->ks > 0.0 ? law->ks * P[p][q] : 0.0) - n[p] * fs[q] / L;
            tan_a = law->ks * s * N[p][q];
            tan_b = -law->ks * (s - L) * N[p][q];
            M[p][q] = law->kn * n[p] * n[q] - law->kn * dn / L * P[p][q] + (stick ? tan_dl : 0.0);
            Wa[p][q] = stick ? tan_a : 0.0;
            Wb[p][q] = stick ? tan_b : 0.0;
            D[p][q] = tan_dl; /* kept for the sliding projection */
            Ra[p][q] = tan_a;
            Rb[p][q] = tan_b;
        }
    if (slide) /* (I - e e) (sticking dfs) - mu kn e n^T */
        for (p = 0; p < 3; ++p)
            for (q = 0; q < 3; ++q) {
                double pd = 0.0, pa = 0.0, pb = 0.0;
                for (m = 0; m < 3; ++m) {
                    const double Pe = (p == m ? 1.0 : 0.0) - e[p] * e[m];
                    pd += Pe * D[m][q];
                    pa += Pe * Ra[m][q];
                    pb += Pe * Rb[m][q];
                }
                M[p][q] += pd - law->mu * law->kn * e[p] * n[q];
                Wa[p][q] = pa;
                Wb[p][q] = pb;
            }
    /* the moments' arms: d r_i = (n n^T / 2 + (s / L) P) dl, d r_j = (-n n^T / 2 + ((s - L) / L) P) dl */
    for (p = 0; p < 3; ++p)
        for (q = 0; q < 3; ++q) {
            double ga = 0.0, gb = 0.0;
            for (m = 0; m < 3; ++m) {
                ga += -Fx[p][m] * (0.5 * n[m] * n[q] + s / L * P[m][q]); /* d r_i x f = -[f]x d r_i */
                gb += Fx[p][m] * (-0.5 * n[m] * n[q] + (s - L) / L * P[m][q]); /* f x d r_j */
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

int sbc_contact_block(const sbc_network *net, int k, double B[SBC_BLOCK_MOST][SBC_BLOCK_MOST])
{
    memset(B, 0, sizeof(double) * SBC_BLOCK_MOST * SBC_BLOCK_MOST);
    return net->dim == 3 ? block_3d(net, k, B) : block_2d(net, k, B);
}
