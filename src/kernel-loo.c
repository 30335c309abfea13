/* The leave-one-out log-sum-exp of kernel_bandwidth() (R/dependence-kernel.R)
 * for every bandwidth of its grid: for row i of the n x n squared distances
 * D2 (the diagonal Inf, so a vector does not count itself) and each h,
 *   lse[i, h] = m + log(sum_j exp(a_ij - m)),  a_ij = -D2_ij / (2 h^2),
 * m the row's largest a_ij. The R expression built three n x n matrices and
 * an apply() over the rows per grid point: with the 35 grid points and the
 * 500 vectors a type is capped at, a third of fitting ten times the default
 * data. The arithmetic is R's (the same division, exp() and a long double
 * row sum, as rowSums()), so the chosen bandwidth is the one R chose.
 *
 * A term whose exponent is below -60 is not added: it is below 1e-26 of the
 * row's largest term (which is 1), so it cannot change the long double sum
 * it would be added to once that term is in, nor the double it is rounded
 * to. It is recognised before its exponent is computed, by its distance:
 * D2_ij above the row's minimum by more than 60 (2 h^2), so most of a small
 * h's n x n divisions and exp() calls are never made. At the 500 vectors a
 * type of ten times the default data is capped at (32 scores), a third of
 * the grid's terms are computed: 0.059 -> 0.026 s per type, the sums
 * identical to the bit (tests/testthat/test-dependence-kernel.R). */
#include <R.h>
#include <Rinternals.h>
#include <math.h>

/* the exponent below which a term is not added (see above) */
#define KERNEL_LOO_FLOOR 60.0

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
  double *near = (double *) R_alloc(n > 0 ? n : 1, sizeof(double));
  for (int g = 0; g < G; g++) {
    double h = grid[g], den = 2 * (h * h);
    for (int i = 0; i < n; i++) {
      m[i] = -dmin[i] / den;
      sum[i] = 0.0;
      /* the distances whose terms can count (see above) */
      near[i] = dmin[i] + KERNEL_LOO_FLOOR * den;
    }
    /* column by column (D2 is symmetric, but its columns are contiguous) */
    for (int j = 0; j < n; j++) {
      const double *col = D2 + (R_xlen_t) j * n;
      for (int i = 0; i < n; i++) {
        if (col[i] < near[i]) sum[i] += exp(-col[i] / den - m[i]);
      }
    }
    for (int i = 0; i < n; i++) lse[i + (R_xlen_t) g * n] = m[i] + log((double) sum[i]);
  }
  UNPROTECT(1);
  return out;
}
