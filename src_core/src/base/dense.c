#include "dense.h"

#include <math.h>

static void swap_rows(double *M, int cols, int a, int b)
{
    int k;
    for (k = 0; k < cols; ++k) {
        const double t = M[(long)a * cols + k];
        M[(long)a * cols + k] = M[(long)b * cols + k];
        M[(long)b * cols + k] = t;
    }
}

int sbc_dense_solve(int n, double *A, int nrhs, double *B, double tol)
{
    int i, j, k, mechanisms = 0;
    for (k = 0; k < n; ++k) {
        int p = k;
        double best = fabs(A[(long)k * n + k]);
        for (i = k + 1; i < n; ++i)
            if (fabs(A[(long)i * n + k]) > best) {
                best = fabs(A[(long)i * n + k]);
                p = i;
            }
        if (!(best > tol)) { /* no pivot: unknown k = 0, row k unused */
            ++mechanisms;
            for (j = k; j < n; ++j)
                A[(long)k * n + j] = 0.0;
            A[(long)k * n + k] = 1.0;
            for (j = 0; j < nrhs; ++j)
                B[(long)k * nrhs + j] = 0.0;
            for (i = k + 1; i < n; ++i)
                A[(long)i * n + k] = 0.0;
            continue;
        }
        if (p != k) {
            swap_rows(A, n, p, k);
            swap_rows(B, nrhs, p, k);
        }
        for (i = k + 1; i < n; ++i) {
            const double m = A[(long)i * n + k] / A[(long)k * n + k];
            if (m == 0.0)
                continue;
            A[(long)i * n + k] = 0.0;
            for (j = k + 1; j < n; ++j)
                A[(long)i * n + j] -= m * A[(long)k * n + j];
            for (j = 0; j < nrhs; ++j)
                B[(long)i * nrhs + j] -= m * B[(long)k * nrhs + j];
        }
    }
    for (k = n - 1; k >= 0; --k)
        for (j = 0; j < nrhs; ++j) {
            double s = B[(long)k * nrhs + j];
            for (i = k + 1; i < n; ++i)
                s -= A[(long)k * n + i] * B[(long)i * nrhs + j];
            B[(long)k * nrhs + j] = s / A[(long)k * n + k];
        }
    return mechanisms;
}
