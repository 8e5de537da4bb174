/* Homogenized measures of the particle aggregate (paper eqs. 15, 23, 30, 31, 42),
 * one code path for 2D and 3D: tensors in 3 x 3 slots, loops over k < dim. */
#include "sbc/homogenize.h"

#include <math.h>

/* s_ij = sum_q y_qi A_qj for positions y [3Q] */
static void moment(const sbc_frame *f, const double *y, double s[9])
{
    const int dim = f->dim;
    int q, i, j;
    for (i = 0; i < 9; ++i)
        s[i] = 0.0;
    for (q = 0; q < f->n; ++q) {
        const double *yq = &y[3 * q], *A = &f->A[3 * q];
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j)
                s[SBC_IJ(i, j)] += yq[i] * A[j];
    }
}

/* eq. 15: F_ij = (1/V) sum_q x_qi A_qj, with V generalized to the tensor
 * G = sum_q X_q (x) A_q: F = (sum_q x_q (x) A_q) G^-1. For the frames the
 * library builds (a lattice ring or a periodic square) G = V I to round-off
 * and this is eq. 15; for the reference renewed after the stress stage of a
 * mixed BC, whose top edge is no longer a periodic copy of the bottom, G
 * departs from V I (docs/servo_bc.md) and eq. 15 taken literally would report
 * F != I for the undeformed reference itself. */
void sbc_homogenize_F(const sbc_frame *f, const double *x, double F[9])
{
    double s[9], G[9];
    int q;
    moment(f, x, s);
    moment(f, f->X, G);
    if (!sbc_tensor_right_divide(f->dim, s, G, F)) /* degenerate frame: eq. 15 as written */
        for (q = 0; q < 9; ++q)
            F[q] = s[q] / f->V;
}

/* eq. 23: P_ij = (1/V) sum_q a_qi X_qj, with V generalized to G as in eq. 15:
 * P = (sum_q a_q (x) X_q) G^-T, so that a uniform traction a_q = P* A_q gives
 * back P = P* exactly (sum_q A_q (x) X_q = G^T). For G = V I this is eq. 23. */
void sbc_homogenize_P_about(const sbc_frame *f, const double *a, const double centre[3], double P[9])
{
    const int dim = f->dim;
    double s[9] = {0.0}, G[9], Gt[9];
    int q, i, j;
    for (q = 0; q < f->n; ++q) {
        const double *aq = &a[3 * q], *Xq = &f->X[3 * q];
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j)
                s[SBC_IJ(i, j)] += aq[i] * (Xq[j] - centre[j]);
    }
    moment(f, f->X, G);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j)
            Gt[SBC_IJ(i, j)] = G[SBC_IJ(j, i)];
    if (!sbc_tensor_right_divide(dim, s, Gt, P)) /* degenerate frame: eq. 23 as written */
        for (q = 0; q < 9; ++q)
            P[q] = s[q] / f->V;
}

void sbc_homogenize_P(const sbc_frame *f, const double *a, double P[9])
{
    static const double origin[3] = {0.0, 0.0, 0.0};
    sbc_homogenize_P_about(f, a, origin, P);
}

/* eq. 31: sigma = (1/det F) P F^T, i.e. sigma_ij = P_ik F_jk / det F */
sbc_status sbc_homogenize_cauchy(int dim, const double P[9], const double F[9], double sigma[9], sbc_error *err)
{
    const double J = sbc_tensor_det(dim, F);
    int i, j, k;
    if (!(J > 0.0)) {
        if (dim == 3)
            return sbc_fail(err, SBC_ERR_GEOMETRY,
                            "det F = %g <= 0 (F = [%g %g %g; %g %g %g; %g %g %g]): the frame is inverted or "
                            "collapsed", J, F[0], F[1], F[2], F[3], F[4], F[5], F[6], F[7], F[8]);
        return sbc_fail(err, SBC_ERR_GEOMETRY,
                        "det F = %g <= 0 (F = [%g %g; %g %g]): the frame is inverted or collapsed", J, F[0],
                        F[1], F[3], F[4]);
    }
    for (i = 0; i < 9; ++i)
        sigma[i] = 0.0;
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j) {
            double s = 0.0;
            for (k = 0; k < dim; ++k)
                s += P[SBC_IJ(i, k)] * F[SBC_IJ(j, k)];
            sigma[SBC_IJ(i, j)] = s / J;
        }
    return SBC_OK;
}

/* eq. 30 with delta w_q -> w_q = x_q - F X_q (eq. 14) */
double sbc_homogenize_hill_mandel(const sbc_frame *f, const double *a, const double *x, const double F[9],
                                  const double P[9])
{
    const int dim = f->dim;
    double sum = 0.0;
    int q, i, j;
    for (q = 0; q < f->n; ++q) {
        const double *X = &f->X[3 * q], *A = &f->A[3 * q], *aq = &a[3 * q], *xq = &x[3 * q];
        double dot = 0.0;
        for (i = 0; i < dim; ++i) {
            double PA = 0.0, FX = 0.0;
            for (j = 0; j < dim; ++j) {
                PA += P[SBC_IJ(i, j)] * A[j];
                FX += F[SBC_IJ(i, j)] * X[j];
            }
            dot += (aq[i] - PA) * (xq[i] - FX);
        }
        sum += dot;
    }
    return sum / f->V;
}

double sbc_homogenize_work_scale(int dim, const double P[9], const double F[9])
{
    return sbc_tensor_norm(dim, P) * (1.0 + sbc_tensor_norm_from_identity(dim, F));
}

/* eq. 42, trapezoidal rule in F12 */
double sbc_homogenize_path_norm(int dim, int n, const double *param, const double *sigma)
{
    double sum = 0.0;
    int k, i, j;
    for (k = 1; k < n; ++k) {
        double h = fabs(param[k] - param[k - 1]);
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j) {
                double s0 = sigma[9 * (k - 1) + SBC_IJ(i, j)], s1 = sigma[9 * k + SBC_IJ(i, j)];
                sum += 0.5 * h * (s0 * s0 + s1 * s1);
            }
    }
    return sqrt(sum);
}
