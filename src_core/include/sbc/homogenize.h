/* servo_bc: macroscopic measures from the frame (paper Sect. 2.3-2.4, 4).
 *
 * Tensors are 3 x 3 slots, row-major (tensor.h): T_ij is T[SBC_IJ(i, j)];
 * a 2D tensor fills the 2 x 2 block and leaves the other slots 0. Vectors
 * are [3Q] in frame order (see frame.h); the dimension is the frame's. */
#ifndef SBC_HOMOGENIZE_H
#define SBC_HOMOGENIZE_H
#include "sbc/frame.h"
#include "sbc/tensor.h"
#ifdef __cplusplus
extern "C" {
#endif
/* Deformation gradient, eq. 15: F = (1/V) sum_q x_q (x) A_q. x is [3Q], m. */
void sbc_homogenize_F(const sbc_frame *frame, const double *x, double F[9]);
/* First Piola-Kirchhoff stress, eq. 23: P = (1/V) sum_q a_q (x) X_q.
 * a is [3Q], the boundary forces a_q in N; P in N/m (2D), Pa (3D). */
void sbc_homogenize_P(const sbc_frame *frame, const double *a, double P[9]);
/* The same with X_q - centre for X_q: equal to it when the forces balance
 * (sum a_q = 0), independent of where the frame lies while they do not (the
 * mixed servo's stress target, controller.c). */
void sbc_homogenize_P_about(const sbc_frame *f, const double *a, const double centre[3], double P[9]);
/* Cauchy stress, eq. 31: sigma = P F^T / det F. Fails with SBC_ERR_GEOMETRY
 * when det F <= 0. */
sbc_status sbc_homogenize_cauchy(int dim, const double P[9], const double F[9], double sigma[9], sbc_error *err);
/* Hill-Mandel residual, eq. 30, evaluated for the state itself (delta w_q
 * replaced by the fluctuation w_q = x_q - F X_q of eq. 14):
 *   (1/V) sum_q (a_q - P A_q) . w_q,   in N/m (J/m^2) in 2D.
 * It vanishes for admissible (D), (P) and (T) states. */
double sbc_homogenize_hill_mandel(const sbc_frame *frame, const double *a, const double *x,
                                  const double F[9], const double P[9]);
/* Scale of the Hill-Mandel residual: |P| |F - I| + |P| (Frobenius norms),
 * the work P:F could do; used to make the residual relative. */
double sbc_homogenize_work_scale(int dim, const double P[9], const double F[9]);
/* Path norm of eq. 42 by the trapezoidal rule over n points:
 *   ( sum_ij int sigma_ij^2 dF12 )^(1/2),
 * param[k] is F12 at point k, sigma is [9n], tensor k at sigma + 9k (any
 * normalization). */
double sbc_homogenize_path_norm(int dim, int n, const double *param, const double *sigma);
#ifdef __cplusplus
}
#endif
#endif
