/* Projection of stacked recordings onto one grasp model (R/project.R,
 * thesis eq. 4.4). For every DoF j and recording i: the recording is read on
 * the model's template grid through the warp index (for template point s,
 * stacked rows rows[s,i] and nxt[s,i] with weight f[s,i] on the later one),
 * centred by the DoF's mean curve, projected on its FPCs with the quadrature
 * weights, and the weighted L2 norm of what the FPCs leave is taken.
 *
 *   scores[i,j,c] = sum_s (y_s - mean_s) phi_c(s) w_s
 *   residual[i,j] = sqrt(sum_s (y_s - mean_s - sum_c scores_c phi_c(s))^2 nw_s)
 *
 * nw is w times the time weights of the weighted FPCA distance (w itself
 * for eq. 4.4). A constant DoF comes with zero components: its scores are 0
 * and its residual the distance to the mean. R (project_stacked()) builds
 * every input; all lengths and indices are checked here again. */
#include <R.h>
#include <Rinternals.h>
#include <math.h>
#include <stdlib.h>

static void need_real(SEXP x, R_xlen_t len, const char *what) {
  if (TYPEOF(x) != REALSXP || XLENGTH(x) != len)
    error("project kernel: %s must be a double vector of %lld values", what, (long long) len);
}

SEXP hm_project_batch(SEXP values, SEXP rows, SEXP nxt, SEXP frac, SEXP mean, SEXP comps,
                      SEXP weights, SEXP norm_weights) {
  SEXP dim = getAttrib(values, R_DimSymbol);
  if (TYPEOF(values) != REALSXP || TYPEOF(dim) != INTSXP || XLENGTH(dim) != 2)
    error("project kernel: values must be a double matrix");
  const R_xlen_t N = INTEGER(dim)[0];
  const int p = INTEGER(dim)[1];
  SEXP mdim = getAttrib(mean, R_DimSymbol);
  if (TYPEOF(mdim) != INTSXP || XLENGTH(mdim) != 2 || INTEGER(mdim)[1] != p)
    error("project kernel: mean must be an L x p matrix");
  const int L = INTEGER(mdim)[0];
  if (L < 1) error("project kernel: the template has no points");
  const R_xlen_t Ln = XLENGTH(rows);
  if (TYPEOF(rows) != INTSXP || TYPEOF(nxt) != INTSXP || XLENGTH(nxt) != Ln || Ln % L != 0)
    error("project kernel: rows and nxt must be integer vectors of L x n indices");
  const R_xlen_t n = Ln / L;
  need_real(frac, Ln, "f");
  need_real(mean, (R_xlen_t) L * p, "mean (L x p)");
  need_real(weights, (R_xlen_t) L * p, "weights (L x p)");
  need_real(norm_weights, (R_xlen_t) L * p, "norm weights (L x p)");
  if (TYPEOF(comps) != REALSXP || XLENGTH(comps) % ((R_xlen_t) L * p) != 0)
    error("project kernel: comps must be an L x p x k double array");
  const int k = (int) (XLENGTH(comps) / ((R_xlen_t) L * p));
  const int *ri = INTEGER(rows), *ni = INTEGER(nxt);
  for (R_xlen_t t = 0; t < Ln; t++) {
    if (ri[t] < 1 || ri[t] > N || ni[t] < 1 || ni[t] > N)
      error("project kernel: warp index %lld out of the %lld stacked frames", (long long) t + 1,
            (long long) N);
  }
  const double *V = REAL(values), *F = REAL(frac), *M = REAL(mean), *P = REAL(comps);
  const double *W = REAL(weights), *NW = REAL(norm_weights);

  SEXP scores = PROTECT(allocVector(REALSXP, n * p * (R_xlen_t) k));
  SEXP resid = PROTECT(allocVector(REALSXP, n * p));
  double *S = REAL(scores), *R = REAL(resid);
  double *y = (double *) R_alloc(L, sizeof(double));
  double *pw = (double *) R_alloc((size_t) L * (k > 0 ? k : 1), sizeof(double));
  double *a = (double *) R_alloc(k > 0 ? k : 1, sizeof(double));

  for (int j = 0; j < p; j++) {
    const double *v = V + N * j, *mu = M + (R_xlen_t) L * j;
    const double *w = W + (R_xlen_t) L * j, *nw = NW + (R_xlen_t) L * j;
    /* phi_c(s) w_s for this DoF, once */
    for (int c = 0; c < k; c++) {
      const double *phi = P + (R_xlen_t) L * (j + (R_xlen_t) p * c);
      for (int s = 0; s < L; s++) pw[s + (R_xlen_t) L * c] = phi[s] * w[s];
    }
    for (R_xlen_t i = 0; i < n; i++) {
      if ((i & 4095) == 4095) R_CheckUserInterrupt();
      const R_xlen_t o = (R_xlen_t) L * i;
      for (int s = 0; s < L; s++) {
        const double g = F[o + s];
        y[s] = v[ri[o + s] - 1] * (1 - g) + v[ni[o + s] - 1] * g - mu[s];
      }
      for (int c = 0; c < k; c++) {
        const double *q = pw + (R_xlen_t) L * c;
        double acc = 0;
        for (int s = 0; s < L; s++) acc += y[s] * q[s];
        a[c] = acc;
        S[i + n * (j + (R_xlen_t) p * c)] = acc;
      }
      double ss = 0;
      for (int s = 0; s < L; s++) {
        double r = y[s];
        for (int c = 0; c < k; c++) r -= a[c] * P[s + (R_xlen_t) L * (j + (R_xlen_t) p * c)];
        ss += r * r * nw[s];
      }
      R[i + n * j] = sqrt(ss > 0 ? ss : 0);
    }
  }
  SEXP out = PROTECT(allocVector(VECSXP, 2));
  SET_VECTOR_ELT(out, 0, scores);
  SET_VECTOR_ELT(out, 1, resid);
  SEXP nms = PROTECT(allocVector(STRSXP, 2));
  SET_STRING_ELT(nms, 0, mkChar("scores"));
  SET_STRING_ELT(nms, 1, mkChar("residual"));
  setAttrib(out, R_NamesSymbol, nms);
  UNPROTECT(4);
  return out;
}
