/* The two summaries fit_fpca_or_constant() (R/grasp-model-fpca.R) takes of
 * a DoF's aligned curves Y (n x L) before its FPCA, in one pass per column
 * instead of four n x L temporaries per DoF and type (0.9 s of fitting ten
 * times the default data):
 *   the total variance over time points,
 *     sum(colSums((Y - rep(colMeans(Y), each = n))^2)) / (n - 1)
 *   and the mean square, mean(Y^2).
 * The arithmetic is R's, in R's order: colMeans() and colSums() sum each
 * column in long double (the mean divided in long double), sum() and mean()
 * add in long double and mean() makes its second, correcting pass; x^2 is
 * x * x. So the values, and the models, are the R expression's to the bit.
 * Returns c(variance, mean square); the variance is NA for one curve. */
#include <R.h>
#include <Rinternals.h>

SEXP hm_curve_spread(SEXP Y_) {
  if (!isReal(Y_) || !isMatrix(Y_)) error("'Y' must be a double matrix");
  int n = nrows(Y_), L = ncols(Y_);
  const double *Y = REAL(Y_);
  R_xlen_t N = (R_xlen_t) n * L;
  /* sum(colSums((Y - mean)^2)) */
  long double total = 0.0;
  for (int j = 0; j < L; j++) {
    const double *y = Y + (R_xlen_t) j * n;
    long double s = 0.0;
    for (int i = 0; i < n; i++) s += y[i];
    s /= n;
    double m = (double) s;
    long double ss = 0.0;
    for (int i = 0; i < n; i++) {
      double d = y[i] - m;
      ss += d * d;
    }
    total += (double) ss;
  }
  double v = n > 1 ? (double) total / (n - 1) : NA_REAL;
  /* mean(Y^2), as R's mean() of a double vector */
  long double s = 0.0;
  for (R_xlen_t k = 0; k < N; k++) s += Y[k] * Y[k];
  s /= N;
  if (R_FINITE((double) s)) {
    long double t = 0.0;
    for (R_xlen_t k = 0; k < N; k++) t += (Y[k] * Y[k] - s);
    s += t / N;
  }
  SEXP out = PROTECT(allocVector(REALSXP, 2));
  REAL(out)[0] = v;
  REAL(out)[1] = (double) s;
  UNPROTECT(1);
  return out;
}
