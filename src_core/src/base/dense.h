/* Private: a dense linear solve with partial pivoting, for the small
 * systems of an aggregate's condensed stiffness (host/condensed.c). */
#ifndef SBC_DENSE_H
#define SBC_DENSE_H

/* Solves A Y = B in place: A [n n] row-major is overwritten by its LU
 * factors, B [n nrhs] row-major by Y. A column whose largest remaining
 * entry is at most tol (absolute) is a mechanism: its unknown is set to 0
 * and its equation left out. Returns the number of such columns. */
int sbc_dense_solve(int n, double *A, int nrhs, double *B, double tol);

#endif
