#include "sparse.h"

#include <math.h>
#include <stdlib.h>

#ifdef SBC_HAVE_UMFPACK
#include <umfpack.h>

int sbc_sparse_available(void) { return 1; }

#define SBC_TEXT(x) #x
#define SBC_NUMBER(x) SBC_TEXT(x)

const char *sbc_sparse_solver_name(void)
{
    return "UMFPACK " SBC_NUMBER(UMFPACK_MAIN_VERSION) "." SBC_NUMBER(UMFPACK_SUB_VERSION) "." SBC_NUMBER(
        UMFPACK_SUBSUB_VERSION);
}

/* the pivots at most tol times the largest (the U factor's diagonal, of the row-scaled matrix) into drop_cols,
   drop_rows: column Q[k], row P[k] of the pivot k; their count */
static int small_pivots(int n, void *numeric, double tol, int *drop_cols, int *drop_rows)
{
    int *P = malloc(sizeof(int) * (size_t)n), *Q = malloc(sizeof(int) * (size_t)n), recip, k, count = -1;
    double *D = malloc(sizeof(double) * (size_t)n), largest = 0.0;
    if (P && Q && D &&
        umfpack_di_get_numeric(NULL, NULL, NULL, NULL, NULL, NULL, P, Q, D, &recip, NULL, numeric) == UMFPACK_OK) {
        for (k = 0; k < n; ++k)
            largest = fabs(D[k]) > largest ? fabs(D[k]) : largest;
        for (k = count = 0; k < n; ++k)
            if (!(fabs(D[k]) > tol * largest)) {
                drop_cols[count] = Q[k];
                drop_rows[count++] = P[k];
            }
    }
    free(P);
    free(Q);
    free(D);
    return count;
}

int sbc_sparse_solve(int n, const int *colptr, const int *rows, const double *vals, int nrhs, double *B, double tol,
                     int *drop_cols, int *drop_rows, int *ndrop)
{
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    const size_t size = (size_t)(n > 0 ? n : 1);
    double *b = malloc(sizeof(double) * size), *x = malloc(sizeof(double) * size * (size_t)(nrhs > 0 ? nrhs : 1));
    void *symbolic = NULL, *numeric = NULL;
    int status, k, i, result = -1;
    *ndrop = 0;
    if (!b || !x)
        goto done;
    if (n == 0) {
        result = 0;
        goto done;
    }
    umfpack_di_defaults(control);
    status = umfpack_di_symbolic(n, n, colptr, rows, vals, &symbolic, control, info);
    if (status == UMFPACK_OK)
        status = umfpack_di_numeric(colptr, rows, vals, symbolic, &numeric, control, info);
    if (status != UMFPACK_OK && status != UMFPACK_WARNING_singular_matrix)
        goto done;
    if ((*ndrop = small_pivots(n, numeric, tol, drop_cols, drop_rows)) != 0) {
        result = *ndrop > 0 ? 1 : -1;
        *ndrop = *ndrop > 0 ? *ndrop : 0;
        goto done;
    }
    for (k = 0; k < nrhs; ++k) { /* column k of B */
        for (i = 0; i < n; ++i)
            b[i] = B[(long)i * nrhs + k];
        if (umfpack_di_solve(UMFPACK_A, colptr, rows, vals, &x[(long)k * n], b, numeric, control, info) !=
            UMFPACK_OK)
            goto done;
    }
    for (k = 0; k < nrhs; ++k)
        for (i = 0; i < n; ++i)
            B[(long)i * nrhs + k] = x[(long)k * n + i];
    result = 0;
done:
    umfpack_di_free_symbolic(&symbolic);
    umfpack_di_free_numeric(&numeric);
    free(b);
    free(x);
    return result;
}

#else

int sbc_sparse_available(void) { return 0; }

const char *sbc_sparse_solver_name(void) { return "none"; }

int sbc_sparse_solve(int n, const int *colptr, const int *rows, const double *vals, int nrhs, double *B, double tol,
                     int *drop_cols, int *drop_rows, int *ndrop)
{
    (void)n, (void)colptr, (void)rows, (void)vals, (void)nrhs, (void)B, (void)tol, (void)drop_cols, (void)drop_rows;
    *ndrop = 0;
    return -1;
}

#endif
