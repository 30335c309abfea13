/* The one pass over the rows that the shrinkage LDA's shrinkage intensity
 * needs (R/classifier-shrunk-lda.R): with x_ki the residual of row k from its class
 * mean, scaled by inv_s_i (1 / the residual's standard deviation of feature
 * i, 0 for a feature without variance),
 *
 *   w2 = sum_k [ (sum_i x_ki^2)^2 - sum_i x_ki^4 ],
 *
 * the sum over i != j of sum_k x_ki^2 x_kj^2 in Schafer and Strimmer's
 * variance of the correlations. The cross products come from moments that
 * add over folds; this term does not (it is quartic in the fold's class
 * means), so each fold's fit makes this pass over its training rows.
 * F: n x d (the features, centred as the means are); rows: 1-based rows of
 * F to use; cls: each used row's 1-based row of means (K x d). */
#include <R.h>
#include <Rinternals.h>

SEXP hm_lda_w2(SEXP F, SEXP rows, SEXP cls, SEXP means, SEXP inv_s) {
  SEXP dim = getAttrib(F, R_DimSymbol), mdim = getAttrib(means, R_DimSymbol);
  if (TYPEOF(F) != REALSXP || TYPEOF(dim) != INTSXP || XLENGTH(dim) != 2)
    error("lda kernel: F must be a double matrix");
  if (TYPEOF(means) != REALSXP || TYPEOF(mdim) != INTSXP || XLENGTH(mdim) != 2)
    error("lda kernel: means must be a double matrix");
  const R_xlen_t n = INTEGER(dim)[0];
  const int d = INTEGER(dim)[1], K = INTEGER(mdim)[0];
  if (INTEGER(mdim)[1] != d) error("lda kernel: means must have the features' columns");
  if (TYPEOF(inv_s) != REALSXP || XLENGTH(inv_s) != d) error("lda kernel: inv_s must be %d doubles", d);
  if (TYPEOF(rows) != INTSXP || TYPEOF(cls) != INTSXP || XLENGTH(cls) != XLENGTH(rows))
    error("lda kernel: rows and cls must be integer vectors of one length");
  const R_xlen_t m = XLENGTH(rows);
  const int *ri = INTEGER(rows), *ci = INTEGER(cls);
  for (R_xlen_t q = 0; q < m; q++) {
    if (ri[q] < 1 || ri[q] > n) error("lda kernel: row %d out of range", ri[q]);
    if (ci[q] < 1 || ci[q] > K) error("lda kernel: class %d out of range", ci[q]);
  }
  const double *X = REAL(F), *M = REAL(means), *s = REAL(inv_s);
  /* Feature by feature (down each column of F, whose rows are used in
   * increasing order), each row's two sums kept in sq[] and q4[]: row by
   * row, every feature of a row is on another cache line, and with 10^5
   * rows each step missed the cache (ten times the rows took 14 times the
   * time). Each row's sums add the features in the same order as before,
   * and the rows add up in the same order: the same result to the bit. */
  double *sq = (double *) R_alloc(m > 0 ? m : 1, sizeof(double));
  double *q4 = (double *) R_alloc(m > 0 ? m : 1, sizeof(double));
  for (R_xlen_t q = 0; q < m; q++) sq[q] = q4[q] = 0;
  for (int i = 0; i < d; i++) {
    if ((i & 15) == 15) R_CheckUserInterrupt();
    const double *col = X + n * (R_xlen_t) i, *mean = M + (R_xlen_t) K * i, si = s[i];
    for (R_xlen_t q = 0; q < m; q++) {
      const double x = (col[ri[q] - 1] - mean[ci[q] - 1]) * si;
      const double x2 = x * x;
      sq[q] += x2;
      q4[q] += x2 * x2;
    }
  }
  long double w2 = 0;
  for (R_xlen_t q = 0; q < m; q++) w2 += (long double) sq[q] * sq[q] - q4[q];
  return ScalarReal((double) w2);
}
