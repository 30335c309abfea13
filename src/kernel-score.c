/* The log-sum-exp of the FPCA likelihood's score kernel
 * (score_kernel_log_density(), R/classifier-fpca-likelihood.R): for row i of
 * the m x n cross products A = Ys Y' of m whitened score vectors against a
 * type's n training vectors, with rs = rowSums(Ys^2) and cs = rowSums(Y^2),
 *   a_ij = min(0, 2 A_ij - rs_i - cs_j) / (2 h^2)    (-|y_i - x_j|^2 / 2h^2)
 *   lse_i = t_i + log(sum_j exp(a_ij - t_i)),  t_i = max_j a_ij.
 * The R expression made six m x n temporaries per type (the default data's
 * classify(): 8,910 recordings x 270 vectors x 33 types, three quarters of
 * its time). The arithmetic is R's, in R's order (the same subtractions,
 * division, exp() and a long double row sum, as rowSums()), so the
 * densities are the ones the R expression gave, to the bit. A row with a
 * NaN gives NA, as max.col() made it. */
#include <R.h>
#include <Rinternals.h>
#include <math.h>

static R_INLINE double kernel_term(double a, double rs, double cs, double den) {
  double v = 2 * a - rs - cs;
  if (v > 0) v = 0;
  return v / den;
}

SEXP hm_kernel_score_lse(SEXP A_, SEXP rs_, SEXP cs_, SEXP h_) {
  int m = nrows(A_), n = ncols(A_);
  const double *A = REAL(A_), *rs = REAL(rs_), *cs = REAL(cs_);
  double h = asReal(h_), den = 2 * (h * h);
  SEXP out = PROTECT(allocVector(REALSXP, m));
  double *lse = REAL(out);
  double *top = (double *) R_alloc(m > 0 ? m : 1, sizeof(double));
  int *nan = (int *) R_alloc(m > 0 ? m : 1, sizeof(int));
  long double *sum = (long double *) R_alloc(m > 0 ? m : 1, sizeof(long double));
  for (int i = 0; i < m; i++) { top[i] = R_NegInf; nan[i] = 0; sum[i] = 0.0; }
  /* column by column, the matrix's contiguous direction: the row maxima
   * first, then the sums of exp() under them */
  for (int j = 0; j < n; j++) {
    const double *col = A + (R_xlen_t) j * m;
    for (int i = 0; i < m; i++) {
      double v = kernel_term(col[i], rs[i], cs[j], den);
      if (ISNAN(v)) nan[i] = 1;
      else if (v > top[i]) top[i] = v;
    }
  }
  for (int j = 0; j < n; j++) {
    const double *col = A + (R_xlen_t) j * m;
    for (int i = 0; i < m; i++) {
      double t = kernel_term(col[i], rs[i], cs[j], den) - top[i];
      /* exp() of less than -746 is exactly 0 in double: skipping it changes
       * no sum */
      if (t > -746.0) sum[i] += exp(t);
    }
  }
  for (int i = 0; i < m; i++) lse[i] = nan[i] || n == 0 ? NA_REAL : top[i] + log((double) sum[i]);
  UNPROTECT(1);
  return out;
}
