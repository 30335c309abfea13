/* Draws of a Gaussian copula model's scores (R/dependence.R): z ~ N(0, R)
 * as standard normals (R's norm_rand, in the order rnorm(n * D) would give
 * them, column by column) times a root U with t(U) U = R (Cholesky, or an
 * eigen root when R is singular, so not always triangular),
 * then each column mapped through its marginal's quantile function,
 * tabulated on an evenly spaced grid of normal scores (linear interpolation,
 * the ends held beyond the grid). One pass in C: in R the draw cost as much
 * as generating the grasps from the scores. */
#include <R.h>
#include <Rinternals.h>
#include <Rmath.h>

SEXP hm_copula_draw(SEXP n_, SEXP root, SEXP grid, SEXP quantiles) {
  const int n = asInteger(n_);
  if (n == NA_INTEGER || n < 0) error("copula draw: n must be a count");
  SEXP rdim = getAttrib(root, R_DimSymbol);
  if (TYPEOF(root) != REALSXP || TYPEOF(rdim) != INTSXP || XLENGTH(rdim) != 2 ||
      INTEGER(rdim)[0] != INTEGER(rdim)[1])
    error("copula draw: root must be a square double matrix");
  const int D = INTEGER(rdim)[0];
  const R_xlen_t G = XLENGTH(grid);
  if (TYPEOF(grid) != REALSXP || G < 2) error("copula draw: the grid needs two or more points");
  if (TYPEOF(quantiles) != REALSXP || XLENGTH(quantiles) != G * D)
    error("copula draw: quantiles must be a %lld x %d double matrix", (long long) G, D);
  const double *U = REAL(root), *z = REAL(grid), *Q = REAL(quantiles);
  const double z0 = z[0], h = (z[G - 1] - z[0]) / (double) (G - 1);
  if (!(h > 0)) error("copula draw: the grid must increase");

  SEXP out = PROTECT(allocMatrix(REALSXP, n, D));
  double *V = REAL(out);
  double *E = (double *) R_alloc((size_t) n * (D > 0 ? D : 1), sizeof(double));
  GetRNGstate();
  for (R_xlen_t t = 0; t < (R_xlen_t) n * D; t++) E[t] = norm_rand();
  PutRNGstate();
  /* column by column, each an axpy over contiguous memory (E %*% U)[, d] =
   * sum_c E[, c] U[c, d]: the row-wise dot product strode n doubles per term
   * and missed the cache on every one once n * D outgrew it */
  for (int d = 0; d < D; d++) {
    double *v = V + (R_xlen_t) n * d;
    for (int i = 0; i < n; i++) v[i] = 0;
    for (int c = 0; c < D; c++) {
      const double u = U[c + (R_xlen_t) D * d];
      if (u == 0) continue; /* a triangular root has D(D-1)/2 zeros */
      const double *e = E + (R_xlen_t) n * c;
      for (int i = 0; i < n; i++) v[i] += e[i] * u;
    }
    R_CheckUserInterrupt();
    const double *q = Q + G * d;
    for (int i = 0; i < n; i++) {
      double pos = (v[i] - z0) / h;
      if (pos < 0) pos = 0;
      if (pos > (double) (G - 1)) pos = (double) (G - 1);
      R_xlen_t lo = (R_xlen_t) pos;
      if (lo > G - 2) lo = G - 2;
      const double f = pos - (double) lo;
      v[i] = q[lo] * (1 - f) + q[lo + 1] * f;
    }
  }
  UNPROTECT(1);
  return out;
}
