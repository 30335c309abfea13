/* The leave-one-out log-sum-exp of kernel_bandwidth() (R/dependence-kernel.R)
 * for every bandwidth of its grid: for row i of the n x n squared distances
 * D2 (the diagonal Inf, so a vector does not count itself) and each h,
 *   lse[i, h] = m + log(sum_j exp(a_ij - m)),  a_ij = -D2_ij / (2 h^2),
 * m the row's largest a_ij. The R expression built three n x n matrices and
 * an apply() over the rows per grid point: with the 35 grid points and the
 * 500 vectors a type is capped at, a third of fitting ten times the default
 * data. The arithmetic is R's (the same division, exp() and a long double
 * row sum, as rowSums()), so the chosen bandwidth is the one R chose. */
#include <R.h>
#include <Rinternals.h>
#include <math.h>

SEXP hm_kernel_loo_lse(SEXP D2_, SEXP grid_) {
  int n = nrows(D2_), G = LENGTH(grid_);
  const double *D2 = REAL(D2_), *grid = REAL(grid_);
  SEXP out = PROTECT(allocMatrix(REALSXP, n, G));
  double *lse = REAL(out);
  double *dmin = (double *) R_alloc(n > 0 ? n : 1, sizeof(double));
  /* the row minimum of D2 is where every a_ij is largest: the division by
   * 2 h^2 is monotone, so max_j a_ij is the image of min_j D2_ij */
  for (int i = 0; i < n; i++) dmin[i] = R_PosInf;
  for (int j = 0; j < n; j++) {
    const double *col = D2 + (R_xlen_t) j * n;
    for (int i = 0; i < n; i++) if (col[i] < dmin[i]) dmin[i] = col[i];
  }
  long double *sum = (long double *) R_alloc(n > 0 ? n : 1, sizeof(long double));
  double *m = (double *) R_alloc(n > 0 ? n : 1, sizeof(double));
  for (int g = 0; g < G; g++) {
    double h = grid[g], den = 2 * (h * h);
    for (int i = 0; i < n; i++) { m[i] = -dmin[i] / den; sum[i] = 0.0; }
    /* column by column (D2 is symmetric, but its columns are contiguous) */
    for (int j = 0; j < n; j++) {
      const double *col = D2 + (R_xlen_t) j * n;
      for (int i = 0; i < n; i++) {
        double t = -col[i] / den - m[i];
        /* exp() of less than -746 is exactly 0 in double: skipping it
         * changes no sum (at the grid's small h, most terms) */
        if (t > -746.0) sum[i] += exp(t);
      }
    }
    for (int i = 0; i < n; i++) lse[i + (R_xlen_t) g * n] = m[i] + log((double) sum[i]);
  }
  UNPROTECT(1);
  return out;
}
