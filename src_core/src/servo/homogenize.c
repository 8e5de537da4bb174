/* Homogenized measures of the particle aggregate (paper eqs. 15, 23, 30, 31, 42). */
#include "sbc/homogenize.h"

#include <math.h>

double sbc_det2(const double T[4]) { return T[0] * T[3] - T[1] * T[2]; }

/* sum_q y_qi A_qj for positions y [2Q] */
static void moment(const sbc_frame *f, const double *y, double s[4])
{
    int q;
    s[0] = s[1] = s[2] = s[3] = 0.0;
    for (q = 0; q < f->n; ++q) {
        const double *yq = &y[2 * q], *A = &f->A[2 * q];
        s[0] += yq[0] * A[0];
        s[1] += yq[0] * A[1];
        s[2] += yq[1] * A[0];
        s[3] += yq[1] * A[1];
    }
}

/* eq. 15: F_ij = (1/V) sum_q x_qi A_qj, with V generalized to the tensor
 * G = sum_q X_q (x) A_q: F = (sum_q x_q (x) A_q) G^-1. For the frames the
 * library builds (a lattice ring or a periodic square) G = V I to round-off
 * and this is eq. 15; for the reference renewed after the stress stage of a
 * mixed BC, whose top edge is no longer a periodic copy of the bottom, G
 * departs from V I by ~5e-4 and eq. 15 taken literally would report
 * F = diag(0.9995, ...) for the undeformed reference itself. */
/* out = s M^-1 for 2x2 s and M (row-major); 0 when M is singular */
static int right_divide(const double s[4], const double M[4], double out[4])
{
    const double det = sbc_det2(M);
    if (!(fabs(det) > 0.0))
        return 0;
    out[0] = (s[0] * M[3] - s[1] * M[2]) / det;
    out[1] = (-s[0] * M[1] + s[1] * M[0]) / det;
    out[2] = (s[2] * M[3] - s[3] * M[2]) / det;
    out[3] = (-s[2] * M[1] + s[3] * M[0]) / det;
    return 1;
}

void sbc_homogenize_F(const sbc_frame *f, const double *x, double F[4])
{
    double s[4], G[4];
    int q;
    moment(f, x, s);
    moment(f, f->X, G);
    if (!right_divide(s, G, F)) /* degenerate frame: eq. 15 as written */
        for (q = 0; q < 4; ++q)
            F[q] = s[q] / f->V;
}

/* eq. 23: P_ij = (1/V) sum_q a_qi X_qj, with V generalized to G as in eq. 15:
 * P = (sum_q a_q (x) X_q) G^-T, so that a uniform traction a_q = P* A_q gives
 * back P = P* exactly (sum_q A_q (x) X_q = G^T). For G = V I this is eq. 23;
 * after the reference renewal of a mixed BC, eq. 23 taken literally returned
 * P* G/V (-99.598 N/m for P22* = -100 N/m on a 6 x 6 lattice layer). */
void sbc_homogenize_P_about(const sbc_frame *f, const double *a, const double centre[2], double P[4])
{
    double s[4] = {0.0, 0.0, 0.0, 0.0}, G[4], Gt[4];
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *aq = &a[2 * q], X0 = f->X[2 * q] - centre[0], X1 = f->X[2 * q + 1] - centre[1];
        s[0] += aq[0] * X0;
        s[1] += aq[0] * X1;
        s[2] += aq[1] * X0;
        s[3] += aq[1] * X1;
    }
    moment(f, f->X, G);
    Gt[0] = G[0];
    Gt[1] = G[2];
    Gt[2] = G[1];
    Gt[3] = G[3];
    if (!right_divide(s, Gt, P)) /* degenerate frame: eq. 23 as written */
        for (q = 0; q < 4; ++q)
            P[q] = s[q] / f->V;
}

void sbc_homogenize_P(const sbc_frame *f, const double *a, double P[4])
{
    static const double origin[2] = {0.0, 0.0};
    sbc_homogenize_P_about(f, a, origin, P);
}

/* eq. 31: sigma = (1/det F) P F^T, i.e. sigma_ij = P_ik F_jk / det F */
sbc_status sbc_homogenize_cauchy(const double P[4], const double F[4], double sigma[4], sbc_error *err)
{
    double J = sbc_det2(F);
    if (!(J > 0.0))
        return sbc_fail(err, SBC_ERR_GEOMETRY,
                        "det F = %g <= 0 (F = [%g %g; %g %g]): the frame is inverted or collapsed", J, F[0],
                        F[1], F[2], F[3]);
    sigma[0] = (P[0] * F[0] + P[1] * F[1]) / J;
    sigma[1] = (P[0] * F[2] + P[1] * F[3]) / J;
    sigma[2] = (P[2] * F[0] + P[3] * F[1]) / J;
    sigma[3] = (P[2] * F[2] + P[3] * F[3]) / J;
    return SBC_OK;
}

/* eq. 30 with delta w_q -> w_q = x_q - F X_q (eq. 14) */
double sbc_homogenize_hill_mandel(const sbc_frame *f, const double *a, const double *x, const double F[4],
                                  const double P[4])
{
    double sum = 0.0;
    int q;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[2 * q], *A = &f->A[2 * q], *aq = &a[2 * q], *xq = &x[2 * q];
        double r0 = aq[0] - (P[0] * A[0] + P[1] * A[1]);
        double r1 = aq[1] - (P[2] * A[0] + P[3] * A[1]);
        double w0 = xq[0] - (F[0] * X[0] + F[1] * X[1]);
        double w1 = xq[1] - (F[2] * X[0] + F[3] * X[1]);
        sum += r0 * w0 + r1 * w1;
    }
    return sum / f->V;
}

double sbc_homogenize_work_scale(const double P[4], const double F[4])
{
    double p = sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2] + P[3] * P[3]);
    double d0 = F[0] - 1.0, d3 = F[3] - 1.0;
    double u = sqrt(d0 * d0 + F[1] * F[1] + F[2] * F[2] + d3 * d3);
    return p * (1.0 + u);
}

/* eq. 42, trapezoidal rule in F12 */
double sbc_homogenize_path_norm(int n, const double *param, const double *sigma)
{
    double sum = 0.0;
    int k, c;
    for (k = 1; k < n; ++k) {
        double h = fabs(param[k] - param[k - 1]);
        for (c = 0; c < 4; ++c) {
            double s0 = sigma[4 * (k - 1) + c], s1 = sigma[4 * k + c];
            sum += 0.5 * h * (s0 * s0 + s1 * s1);
        }
    }
    return sqrt(sum);
}
