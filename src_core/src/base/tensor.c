/* Tensors in 3 x 3 slots, dimension as a value (tensor.h). The 2D branches
 * keep the operation order of the 2 x 2 formulas, so 2D results are those of
 * 2 x 2 arithmetic to the bit. */
#include "sbc/tensor.h"

#include <math.h>
#include <stddef.h>

void sbc_tensor_identity(int dim, double T[9])
{
    int i, j;
    for (i = 0; i < SBC_DIM_MAX; ++i)
        for (j = 0; j < SBC_DIM_MAX; ++j)
            T[SBC_IJ(i, j)] = i == j && i < dim ? 1.0 : 0.0;
}

double sbc_tensor_det(int dim, const double T[9])
{
    if (dim == 3)
        return T[0] * (T[4] * T[8] - T[5] * T[7]) - T[1] * (T[3] * T[8] - T[5] * T[6]) +
               T[2] * (T[3] * T[7] - T[4] * T[6]);
    return T[0] * T[4] - T[1] * T[3];
}

int sbc_tensor_inverse(int dim, const double M[9], double inv[9])
{
    const double det = sbc_tensor_det(dim, M);
    if (!(fabs(det) > 0.0) || !isfinite(det))
        return 0;
    if (dim != 3) {
        inv[0] = M[4] / det;
        inv[1] = -M[1] / det;
        inv[3] = -M[3] / det;
        inv[4] = M[0] / det;
        inv[2] = inv[5] = inv[6] = inv[7] = inv[8] = 0.0;
        return 1;
    }
    /* M^-1 = adj(M) / det M */
    inv[0] = (M[4] * M[8] - M[5] * M[7]) / det;
    inv[1] = (M[2] * M[7] - M[1] * M[8]) / det;
    inv[2] = (M[1] * M[5] - M[2] * M[4]) / det;
    inv[3] = (M[5] * M[6] - M[3] * M[8]) / det;
    inv[4] = (M[0] * M[8] - M[2] * M[6]) / det;
    inv[5] = (M[2] * M[3] - M[0] * M[5]) / det;
    inv[6] = (M[3] * M[7] - M[4] * M[6]) / det;
    inv[7] = (M[1] * M[6] - M[0] * M[7]) / det;
    inv[8] = (M[0] * M[4] - M[1] * M[3]) / det;
    return 1;
}

int sbc_tensor_right_divide(int dim, const double S[9], const double M[9], double out[9])
{
    const double det = sbc_tensor_det(dim, M);
    double inv[9];
    int i, j, k;
    if (!(fabs(det) > 0.0) || !isfinite(det))
        return 0;
    if (dim != 3) { /* the 2 x 2 formulas, as written before dimension was data */
        out[0] = (S[0] * M[4] - S[1] * M[3]) / det;
        out[1] = (-S[0] * M[1] + S[1] * M[0]) / det;
        out[3] = (S[3] * M[4] - S[4] * M[3]) / det;
        out[4] = (-S[3] * M[1] + S[4] * M[0]) / det;
        out[2] = out[5] = out[6] = out[7] = out[8] = 0.0;
        return 1;
    }
    sbc_tensor_inverse(3, M, inv);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double s = 0.0;
            for (k = 0; k < 3; ++k)
                s += S[SBC_IJ(i, k)] * inv[SBC_IJ(k, j)];
            out[SBC_IJ(i, j)] = s;
        }
    return 1;
}

void sbc_tensor_apply(int dim, const double T[9], const double v[3], double out[3])
{
    int i, j;
    for (i = 0; i < SBC_DIM_MAX; ++i) {
        double s = 0.0;
        for (j = 0; j < dim && i < dim; ++j)
            s += T[SBC_IJ(i, j)] * v[j];
        out[i] = s;
    }
}

static double norm_minus(int dim, const double T[9], double diagonal)
{
    double s = 0.0;
    int i, j;
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j) {
            const double d = T[SBC_IJ(i, j)] - (i == j ? diagonal : 0.0);
            s += d * d;
        }
    return sqrt(s);
}

double sbc_tensor_norm(int dim, const double T[9]) { return norm_minus(dim, T, 0.0); }

double sbc_tensor_norm_from_identity(int dim, const double T[9]) { return norm_minus(dim, T, 1.0); }

const char *sbc_tensor_component_name(const char *symbol, int i, int j, char out[8])
{
    size_t n = 0;
    while (symbol[n] && n < 5) {
        out[n] = symbol[n];
        ++n;
    }
    out[n++] = (char)('1' + (i >= 0 && i < SBC_DIM_MAX ? i : 0));
    out[n++] = (char)('1' + (j >= 0 && j < SBC_DIM_MAX ? j : 0));
    out[n] = '\0';
    return out;
}

void sbc_remap_displacement(int dim, const double M[9], const double origin[3], const double *x, double *u)
{
    int i, j;
    for (i = 0; i < dim; ++i) {
        u[i] = 0.0;
        for (j = 0; j < dim; ++j)
            u[i] += (M[SBC_IJ(i, j)] - (i == j ? 1.0 : 0.0)) * (x[j] - origin[j]);
    }
}
