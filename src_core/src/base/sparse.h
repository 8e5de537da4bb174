/* Private: a sparse direct solve for an aggregate's condensed stiffness
 * (host/condensed.c), by UMFPACK (SuiteSparse, Debian libsuitesparse-dev)
 * when the core is built with it (SBC_HAVE_UMFPACK, the Makefile's choice
 * when its header is installed); without it, nothing is solved here and
 * the caller solves densely (dense.h). */
#ifndef SBC_SPARSE_H
#define SBC_SPARSE_H

/* 1 when the core was built with a sparse direct solver */
int sbc_sparse_available(void);

/* The name of the sparse solver the core was built with ("UMFPACK 5.7.9"),
 * or "none". */
const char *sbc_sparse_solver_name(void);

/* Solves A Y = B, A [n n] in compressed columns (colptr [n + 1], rows
 * [colptr[n]] ascending within a column, vals), B [n nrhs] row-major
 * overwritten by Y. Returns 0 when solved; 1 when some pivots of the LU
 * factors (of A with its rows scaled by their sums) are at most tol times
 * the largest: A's mechanisms, as the dense LU's pivots at or below its
 * tolerance; their columns and rows are written to drop_cols, drop_rows
 * (room for n each), their count to *ndrop, and B is untouched; -1 without
 * a sparse solver or memory (B untouched). */
int sbc_sparse_solve(int n, const int *colptr, const int *rows, const double *vals, int nrhs, double *B, double tol,
                     int *drop_cols, int *drop_rows, int *ndrop);

#endif
