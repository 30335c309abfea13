/* Batch generation kernel for generate() (R/generate.R): for every draw d,
 * build eq. 2.5 at the original frames t = 1..n_new[d] directly from the
 * model's basis, interpolating the mean and components at the template time
 * where the draw's warping function reaches t. One pass, no intermediate
 * template-grid curves; returns one n_new[d] x p matrix per draw, with
 * colnames `dofs`.
 * Same arithmetic as the R reference unwarp_batch(): the template interval
 * is the last j with W[d, j] <= t, clamped to 1..L-1; beyond W[d, L] the
 * value is the last template frame's; a flat interval gives f = 0. */
#include <R.h>
#include <Rinternals.h>

SEXP hm_generate_batch(SEXP mean, SEXP comps, SEXP alpha, SEXP W, SEXP n_new, SEXP dofs) {
  const int L = nrows(mean), p = ncols(mean);
  const int n = nrows(W);
  const int k = (p > 0 && L > 0) ? (int) (XLENGTH(comps) / ((R_xlen_t) L * p)) : 0;
  const double *mu = REAL(mean), *P = REAL(comps), *A = REAL(alpha), *w = REAL(W);
  const int *nn = INTEGER(n_new);
  SEXP out = PROTECT(allocVector(VECSXP, n));
  /* one shared, immutable dimnames list(NULL, dofs) for every matrix */
  SEXP dn = PROTECT(allocVector(VECSXP, 2));
  SET_VECTOR_ELT(dn, 1, dofs);
  MARK_NOT_MUTABLE(dn);
  /* per-draw basis with the scores folded in: L x p curve on the template grid */
  double *curve = (double *) R_alloc((size_t) L * p, sizeof(double));
  for (int d = 0; d < n; d++) {
    for (int j = 0; j < p; j++) {
      for (int s = 0; s < L; s++) {
        double v = mu[s + (R_xlen_t) L * j];
        for (int c = 0; c < k; c++) {
          v += A[d + (R_xlen_t) n * (j + (R_xlen_t) p * c)] *
               P[s + (R_xlen_t) L * (j + (R_xlen_t) p * c)];
        }
        curve[s + (R_xlen_t) L * j] = v;
      }
    }
    const int m = nn[d];
    SEXP rec = PROTECT(allocMatrix(REALSXP, m, p));
    double *r = REAL(rec);
    int j = 0; /* 0-based template interval [j, j+1] */
    for (int t = 1; t <= m; t++) {
      while (j + 1 < L && w[d + (R_xlen_t) n * (j + 1)] <= t) j++;
      int lo;
      double f;
      if (L == 1) {
        lo = 0; f = 0;
      } else if (j >= L - 1) {
        lo = L - 2; f = 1;
      } else {
        lo = j;
        double a = w[d + (R_xlen_t) n * lo], b = w[d + (R_xlen_t) n * (lo + 1)];
        f = (b > a) ? (t - a) / (b - a) : 0;
        if (f < 0) f = 0;
        if (f > 1) f = 1;
      }
      int hi = (L == 1) ? 0 : lo + 1;
      for (int jj = 0; jj < p; jj++) {
        r[(t - 1) + (R_xlen_t) m * jj] = (1 - f) * curve[lo + (R_xlen_t) L * jj] +
                                         f * curve[hi + (R_xlen_t) L * jj];
      }
    }
    setAttrib(rec, R_DimNamesSymbol, dn);
    SET_VECTOR_ELT(out, d, rec);
    UNPROTECT(1);
  }
  UNPROTECT(2);
  return out;
}
