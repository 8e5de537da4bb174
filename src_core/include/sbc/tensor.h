/* servo_bc: dimension as data. Vectors are stored in 3 slots and tensors in
 * 3 x 3 row-major slots whatever the dimension; a 2D quantity leaves its
 * third slots at 0 and loops run over k < dim, so that 2D arithmetic is that
 * of a 2-vector and a 2 x 2 tensor, operation for operation. */
#ifndef SBC_TENSOR_H
#define SBC_TENSOR_H

#ifdef __cplusplus
extern "C" {
#endif

/* slots of a vector; a tensor has SBC_DIM_MAX * SBC_DIM_MAX */
enum { SBC_DIM_MAX = 3, SBC_TENSOR_SLOTS = 9 };

/* the components of a rotation (a rotation vector, moment, angular velocity)
 * in dim dimensions: the one about e3 in 2D, three in 3D. Per-particle
 * rotation arrays have this stride. */
#define SBC_ROTATIONS(dim) ((dim) == 3 ? 3 : 1)

/* slot of component T_ij (0-based) of a tensor */
#define SBC_IJ(i, j) (SBC_DIM_MAX * (i) + (j))

/* 3-vectors: c = a x b, and a . b */
static inline void sbc_cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double sbc_dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* T = I in the first dim x dim block, 0 elsewhere */
void sbc_tensor_identity(int dim, double T[9]);

/* det of the dim x dim block (dim 2 or 3) */
double sbc_tensor_det(int dim, const double T[9]);

/* out = S M^-1 (dim x dim blocks; the other slots 0). Returns 0, leaving out
 * untouched, when det M is 0 or not finite. */
int sbc_tensor_right_divide(int dim, const double S[9], const double M[9], double out[9]);

/* out = T^-1 (dim x dim block; the other slots 0). Returns 0, leaving out
 * untouched, when det T is 0 or not finite. */
int sbc_tensor_inverse(int dim, const double T[9], double out[9]);

/* out_i = sum_j T_ij v_j over i, j < dim (out's other slots 0) */
void sbc_tensor_apply(int dim, const double T[9], const double v[3], double out[3]);

/* u [dim] = (M - I)(x - origin) over the first dim components: the
 * displacement of x under the map x -> origin + M (x - origin) (keyword remap
 * x, sbc_controller_remap), m */
void sbc_remap_displacement(int dim, const double M[9], const double origin[3], const double *x, double *u);

/* Frobenius norm of the dim x dim block, and of T - I */
double sbc_tensor_norm(int dim, const double T[9]);
double sbc_tensor_norm_from_identity(int dim, const double T[9]);

/* Name of component ij, "F12" for ("F", 0, 1), in out (cap >= 8) */
const char *sbc_tensor_component_name(const char *symbol, int i, int j, char out[8]);

#ifdef __cplusplus
}
#endif

#endif
