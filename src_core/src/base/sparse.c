#include "sparse.h"

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

int sbc_sparse_solve(int n, const int *colptr, const int *rows, const double *vals, int nrhs, double *B)
{
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    const size_t size = (size_t)(n > 0 ? n : 1);
    double *b = malloc(sizeof(double) * size), *x = malloc(sizeof(double) * size * (size_t)(nrhs > 0 ? nrhs : 1));
    void *symbolic = NULL, *numeric = NULL;
    int status, k, i, result = -1;
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
    if (status == UMFPACK_WARNING_singular_matrix) {
        result = 1;
        goto done;
    }
    if (status != UMFPACK_OK)
        goto done;
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

int sbc_sparse_solve(int n, const int *colptr, const int *rows, const double *vals, int nrhs, double *B)
{
    (void)n, (void)colptr, (void)rows, (void)vals, (void)nrhs, (void)B;
    return -1;
}

#endif
