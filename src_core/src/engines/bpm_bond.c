/* servo_bc: 3D bond kernels (thesis Sect. 3.2): bond frame, parallel bond,
 * Timoshenko beam, viscous bond damping. */
#include "sbc/bpm_bond.h"

#include <math.h>
#include <string.h>


static double normalize(double a[3])
{
    double l = sqrt(sbc_dot3(a, a));
    if (l > 0.0) {
        a[0] /= l;
        a[1] /= l;
        a[2] /= l;
    }
    return l;
}

/* eqs. 4-8 */
double sbc_bond_frame(const double xa[3], const double xb[3], double T[3][3])
{
    static const double ez[3] = {0.0, 0.0, 1.0};
    double L;
    int k;
    for (k = 0; k < 3; ++k)
        T[0][k] = xb[k] - xa[k];
    L = normalize(T[0]);                               /* eq. 5 */
    sbc_cross3(T[0], ez, T[1]);                        /* eq. 6 */
    if (normalize(T[1]) < 1e-12) {                     /* eq. 7: x^ along e_z */
        T[1][0] = 0.0;
        T[1][1] = 1.0;
        T[1][2] = 0.0;
    }
    sbc_cross3(T[0], T[1], T[2]);                      /* eq. 8 */
    normalize(T[2]);
    return L;
}

/* ---- parallel bond ------------------------------------------------------- */

double sbc_parallel_bond_geometry(const double xa[3], double ra, const double xb[3], double rb, double n[3],
                                  double xc[3])
{
    double L, s;
    int k;
    for (k = 0; k < 3; ++k)
        n[k] = xb[k] - xa[k];
    L = normalize(n);
    s = ra + 0.5 * (L - ra - rb);
    for (k = 0; k < 3; ++k)
        xc[k] = xa[k] + s * n[k];
    return L;
}

void sbc_parallel_bond_increment(const sbc_parallel_bond_law *law, sbc_parallel_bond *bond, const double n[3],
                                 const double du[3], const double dth[3])
{
    double area = sbc_bond_area(bond->rb), I = sbc_bond_inertia(bond->rb), J = sbc_bond_polar(bond->rb);
    double un = sbc_dot3(du, n), tn = sbc_dot3(dth, n);
    int k;
    for (k = 0; k < 3; ++k) {
        double dun = un * n[k], dus = du[k] - dun;
        double dtn = tn * n[k], dts = dth[k] - dtn;
        bond->fn[k] -= law->kn * area * dun; /* eq. 10 */
        bond->fs[k] -= law->ks * area * dus; /* eq. 11 */
        bond->mn[k] -= law->ks * J * dtn;    /* eq. 16 */
        bond->ms[k] -= law->kn * I * dts;    /* eq. 17 */
    }
}

void sbc_parallel_bond_apply(const sbc_parallel_bond *bond, const double xa[3], const double xb[3],
                             const double xc[3], double fa[3], double ma[3], double fb[3], double mb[3])
{
    double arm_a[3], arm_b[3], tfs_a[3], tfs_b[3], fs_b[3];
    int k;
    for (k = 0; k < 3; ++k) {
        arm_a[k] = xc[k] - xa[k];
        arm_b[k] = xc[k] - xb[k];
        fs_b[k] = -bond->fs[k];
    }
    sbc_cross3(arm_a, bond->fs, tfs_a); /* eq. 20 */
    sbc_cross3(arm_b, fs_b, tfs_b);
    for (k = 0; k < 3; ++k) {
        double f = bond->fn[k] + bond->fs[k], m = bond->mn[k] + bond->ms[k];
        fa[k] += f;
        fb[k] -= f;
        ma[k] += m + tfs_a[k]; /* eq. 22 */
        mb[k] += -m + tfs_b[k];
    }
}

/* eq. 50 */
double sbc_parallel_bond_energy(const sbc_parallel_bond_law *law, const sbc_parallel_bond *bond)
{
    double area = sbc_bond_area(bond->rb), I = sbc_bond_inertia(bond->rb), J = sbc_bond_polar(bond->rb);
    double w = 0.0;
    if (law->kn > 0.0)
        w += sbc_dot3(bond->fn, bond->fn) / (2.0 * law->kn * area) + sbc_dot3(bond->ms, bond->ms) / (2.0 * law->kn * I);
    if (law->ks > 0.0)
        w += sbc_dot3(bond->fs, bond->fs) / (2.0 * law->ks * area) + sbc_dot3(bond->mn, bond->mn) / (2.0 * law->ks * J);
    return w;
}

/* ---- Timoshenko beam ------------------------------------------------------ */

/* eq. 31 with f_s = 10/9 */
double sbc_beam_phi(double nu, double rb, double L) { return 20.0 * rb * rb * (1.0 + nu) / (3.0 * L * L); }

/* eqs. 26-30 */
void sbc_beam_stiffness(const sbc_beam_law *law, double rb, double L, double K[12][12])
{
    double E = law->E, A = sbc_bond_area(rb), I = sbc_bond_inertia(rb), phi = sbc_beam_phi(law->nu, rb, L);
    double K1[3][3] = {{0}}, K2[3][3] = {{0}}, K3[3][3] = {{0}}, K4[3][3] = {{0}};
    /* block (row, column) of eq. 26 and its sign */
    static const int which[4][4] = {{1, 2, 1, 2}, {2, 3, 2, 4}, {1, 2, 1, 2}, {2, 4, 2, 3}};
    static const int sign[4][4] = {{1, -1, -1, -1}, {1, 1, -1, 1}, {-1, 1, 1, 1}, {1, 1, -1, 1}};
    int bi, bj, i, j;
    K1[0][0] = E * A / L;                                          /* eq. 27 */
    K1[1][1] = K1[2][2] = 12.0 * E * I / (L * L * L * (1.0 + phi));
    K2[1][2] = -6.0 * E * I / (L * L * (1.0 + phi));               /* eq. 28 */
    K2[2][1] = -K2[1][2];
    K3[0][0] = E * I / (L * (1.0 + law->nu));                      /* eq. 29: G J / L */
    K3[1][1] = K3[2][2] = E * I * (4.0 + phi) / (L * (1.0 + phi));
    K4[0][0] = -K3[0][0];                                          /* eq. 30 */
    K4[1][1] = K4[2][2] = E * I * (2.0 - phi) / (L * (1.0 + phi));
    for (bi = 0; bi < 4; ++bi)
        for (bj = 0; bj < 4; ++bj) {
            double (*S)[3] = which[bi][bj] == 1 ? K1 : which[bi][bj] == 2 ? K2 : which[bi][bj] == 3 ? K3 : K4;
            for (i = 0; i < 3; ++i)
                for (j = 0; j < 3; ++j)
                    K[3 * bi + i][3 * bj + j] = sign[bi][bj] * S[i][j];
        }
}

void sbc_beam_bond_init(const sbc_beam_law *law, double rb, const double xa[3], const double xb[3],
                        sbc_beam_bond *bond)
{
    double L = sbc_bond_frame(xa, xb, bond->T), K[12][12];
    sbc_beam_stiffness(law, rb, L, K);
    bond->k[0] = K[0][0];  /* E A / L */
    bond->k[1] = K[1][1];  /* 12 E I / L^3 (1 + Phi) */
    bond->k[2] = K[1][5];  /* 6 E I / L^2 (1 + Phi) */
    bond->k[3] = K[3][3];  /* G J / L */
    bond->k[4] = K[4][4];  /* E I (4 + Phi) / L (1 + Phi) */
    bond->k[5] = K[4][10]; /* E I (2 - Phi) / L (1 + Phi) */
    memset(bond->f, 0, sizeof bond->f);
    bond->w = 0.0;
}

/* eq. 26 written out: A's forces and moments, then B's */
void sbc_beam_bond_product(const sbc_beam_bond *bond, const double u[12], double df[12])
{
    const double *k = bond->k;
    double du = u[0] - u[6], dv = u[1] - u[7], dw = u[2] - u[8];
    double sy = u[4] + u[10], sz = u[5] + u[11], tx = k[3] * (u[3] - u[9]);
    df[0] = k[0] * du;
    df[1] = k[1] * dv + k[2] * sz;
    df[2] = k[1] * dw - k[2] * sy;
    df[3] = tx;
    df[4] = -k[2] * dw + k[4] * u[4] + k[5] * u[10];
    df[5] = k[2] * dv + k[4] * u[5] + k[5] * u[11];
    df[6] = -df[0];
    df[7] = -df[1];
    df[8] = -df[2];
    df[9] = -tx;
    df[10] = -k[2] * dw + k[5] * u[4] + k[4] * u[10];
    df[11] = k[2] * dv + k[5] * u[5] + k[4] * u[11];
}

double sbc_beam_bond_increment(sbc_beam_bond *bond, const double dxa[3], const double dtha[3], const double dxb[3],
                               const double dthb[3])
{
    const double *g[4] = {dxa, dtha, dxb, dthb};
    double ul[12], df[12], w = 0.0;
    int b, i;
    for (b = 0; b < 4; ++b) /* eq. 32 */
        for (i = 0; i < 3; ++i)
            ul[3 * b + i] = sbc_dot3(bond->T[i], g[b]);
    sbc_beam_bond_product(bond, ul, df); /* eq. 23 */
    for (i = 0; i < 12; ++i) {
        w += (bond->f[i] + 0.5 * df[i]) * ul[i];
        bond->f[i] += df[i];
    }
    bond->w += w;
    return w;
}

void sbc_beam_bond_apply(const sbc_beam_bond *bond, double fa[3], double ma[3], double fb[3], double mb[3])
{
    double *out[4] = {fa, ma, fb, mb};
    int b, i, k;
    for (b = 0; b < 4; ++b) /* eqs. 33-34: T^-1 = T^T */
        for (k = 0; k < 3; ++k) {
            double s = 0.0;
            for (i = 0; i < 3; ++i)
                s += bond->T[i][k] * bond->f[3 * b + i];
            out[b][k] -= s;
        }
}

/* ---- failure ----------------------------------------------------------------- */

double sbc_bond_criterion(const sbc_bond_strength *s, double ft, double fs, double mb, double mt)
{
    double c = 0.0;
    if (s->tension > 0.0) c += ft / s->tension;
    if (s->shear > 0.0) c += fabs(fs) / s->shear;
    if (s->bending > 0.0) c += fabs(mb) / s->bending;
    if (s->twisting > 0.0) c += fabs(mt) / s->twisting;
    return c;
}

void sbc_parallel_bond_loads(const sbc_parallel_bond *bond, const double n[3], double out[4])
{
    out[0] = sbc_dot3(bond->fn, n); /* force on A toward B: tension */
    out[1] = sqrt(sbc_dot3(bond->fs, bond->fs));
    out[2] = sqrt(sbc_dot3(bond->ms, bond->ms));
    out[3] = sqrt(sbc_dot3(bond->mn, bond->mn));
}

void sbc_beam_bond_loads(const sbc_beam_bond *bond, double out[4])
{
    const double *f = bond->f;
    out[0] = -f[0]; /* A receives -f_l: along x^ toward B is tension */
    out[1] = sqrt(f[1] * f[1] + f[2] * f[2]);
    out[2] = fmax(sqrt(f[4] * f[4] + f[5] * f[5]), sqrt(f[10] * f[10] + f[11] * f[11]));
    out[3] = fabs(f[3]);
}

void sbc_broken_bond_increment(const sbc_friction_law *law, sbc_broken_bond *c, double dn, const double n[3],
                               const double du[3], double f[3])
{
    double un = sbc_dot3(du, n), cap, mag;
    int k;
    if (dn <= 0.0) {
        memset(c->fs, 0, sizeof c->fs);
    } else {
        for (k = 0; k < 3; ++k)
            c->fs[k] -= law->ks * (du[k] - un * n[k]);
        /* keep the spring in the contact plane as n turns */
        mag = sbc_dot3(c->fs, n);
        for (k = 0; k < 3; ++k)
            c->fs[k] -= mag * n[k];
        cap = law->mu * law->kn * dn;
        mag = sqrt(sbc_dot3(c->fs, c->fs));
        if (mag > cap)
            for (k = 0; k < 3; ++k)
                c->fs[k] *= cap / mag;
    }
    for (k = 0; k < 3; ++k)
        f[k] = (dn > 0.0 ? -law->kn * dn * n[k] : 0.0) + c->fs[k];
    c->w -= 0.5 * (sbc_dot3(c->f, du) + sbc_dot3(f, du)); /* work done on the contact */
    memcpy(c->f, f, sizeof c->f);
}

double sbc_broken_bond_energy(const sbc_friction_law *law, const sbc_broken_bond *c, double dn)
{
    double w = dn > 0.0 ? 0.5 * law->kn * dn * dn : 0.0;
    if (law->ks > 0.0)
        w += 0.5 * sbc_dot3(c->fs, c->fs) / law->ks;
    return w;
}

/* ---- damping ---------------------------------------------------------------- */

/* eqs. 36-37 */
double sbc_bond_damping(double xi, double k, double ma, double mb, double cn)
{
    double mred = ma * mb / (ma + mb);
    return xi * 2.0 * sqrt(k * mred) / sqrt((cn > 0.0 ? cn : 1.0) / 3.0);
}
