/* Locally weighted linear regression for sparse-marker hand-over
 * (R/handover.R, lwr_predict()). For each query row: the k nearest
 * reference rows by exact partial-distance search with a max-heap, inverse
 * distance weights, weighted moments of the local linear model centred on
 * the query, and its intercept (the prediction at the query) through the
 * equivalent kernel after a ridge-stabilised Cholesky solve.
 * The R function lwr_predict_r() is the reference implementation.
 */
#include <R.h>
#include <Rinternals.h>
#include <math.h>
#include <stdlib.h>
#include "cholesky.h"
#include "scratch.h"

/* Max-heap of (distance, index) pairs, the current k nearest candidates. */
static void heap_sift_down(double *hd, int *hi, int k, int pos) {
  for (;;) {
    int l = 2 * pos + 1, r = l + 1, m = pos;
    if (l < k && hd[l] > hd[m]) m = l;
    if (r < k && hd[r] > hd[m]) m = r;
    if (m == pos) return;
    double td = hd[pos]; hd[pos] = hd[m]; hd[m] = td;
    int ti = hi[pos]; hi[pos] = hi[m]; hi[m] = ti;
    pos = m;
  }
}

static void heap_build(double *hd, int *hi, int k) {
  for (int pos = k / 2 - 1; pos >= 0; pos--) heap_sift_down(hd, hi, k, pos);
}

SEXP hm_lwr_predict(SEXP ref_x, SEXP ref_y, SEXP query, SEXP k_, SEXP ridge_, SEXP eps_) {
  /* every argument checked here too: a wrong type or size is an R error, not a crash */
  if (!isReal(ref_x) || !isMatrix(ref_x) || !isReal(ref_y) || !isMatrix(ref_y) ||
      !isReal(query) || !isMatrix(query))
    error("lwr: reference markers, reference scores and query must be double matrices");
  const int N = nrows(ref_x), d = ncols(ref_x), q = ncols(ref_y), n = nrows(query);
  if (nrows(ref_y) != N || ncols(query) != d) error("lwr: dimension mismatch");
  if (N < 1 || d < 1) error("lwr: empty reference");
  int k = asInteger(k_);
  if (k > N) k = N;
  if (k < 1) error("lwr: k must be positive");
  const double ridge = asReal(ridge_), eps = asReal(eps_);
  if (!(ridge > 0) || !R_FINITE(ridge) || !(eps > 0) || !R_FINITE(eps)) error("lwr: ridge and eps must be positive");
  const double *X = REAL(ref_x), *Y = REAL(ref_y), *Q = REAL(query);
  SEXP out = PROTECT(allocMatrix(REALSXP, n, q));
  double *O = REAL(out);

  /* scratch: per coordinate, its order by spread (perm), its spread (var),
   * the query (qv), a neighbour centred on it (xc), the weighted sums (sx)
   * and the equivalent kernel's solve (beta); d x d, the weighted cross
   * products (sxx), the local system (a) and its Cholesky factor (rf); the
   * heap of the k nearest (hd, hi), the previous query's (prev); the query
   * that last saw each reference row (seen); the prediction (hy) */
  double *var, *qv, *xc, *sx, *beta, *sxx, *a, *rf, *XR, *hd, *hy;
  int *perm, *hi, *prev, *seen;
  HM_SCRATCH_REALS(d, &var, &qv, &xc, &sx, &beta);
  HM_SCRATCH_REALS((size_t) d * d, &sxx, &a, &rf);
  HM_SCRATCH_REALS((size_t) N * d, &XR);
  HM_SCRATCH_REALS(k, &hd);
  HM_SCRATCH_REALS(q, &hy);
  HM_SCRATCH_INTS(d, &perm);
  HM_SCRATCH_INTS(k, &hi, &prev);
  HM_SCRATCH_INTS(N, &seen);

  /* Reference points stored row-major with the coordinates reordered by
   * decreasing spread, so a partial distance exceeds the current k-th best
   * after few coordinates and the search moves on (partial distance search). */
  for (int j = 0; j < d; j++) {
    double m = 0.0, v = 0.0;
    for (int i = 0; i < N; i++) m += X[i + (size_t) j * N];
    m /= N;
    for (int i = 0; i < N; i++) { double t = X[i + (size_t) j * N] - m; v += t * t; }
    var[j] = v;
    perm[j] = j;
  }
  for (int j = 1; j < d; j++) {            /* insertion sort, d is small */
    int pj = perm[j], i = j - 1;
    while (i >= 0 && var[perm[i]] < var[pj]) { perm[i + 1] = perm[i]; i--; }
    perm[i + 1] = pj;
  }
  for (int i = 0; i < N; i++)
    for (int j = 0; j < d; j++) XR[(size_t) i * d + j] = X[i + (size_t) perm[j] * N];

  for (int i = 0; i < N; i++) seen[i] = -1;
  for (int m = 0; m < k; m++) prev[m] = m;

  for (int r = 0; r < n; r++) {
    if (r % 256 == 0) R_CheckUserInterrupt();
    for (int j = 0; j < d; j++) qv[j] = Q[r + (size_t) perm[j] * n];
    /* seed the heap with the previous frame's neighbours: consecutive frames
     * are close, so the threshold starts tight */
    for (int m = 0; m < k; m++) {
      int i = prev[m];
      const double *xi = XR + (size_t) i * d;
      double s = 0.0;
      for (int j = 0; j < d; j++) { double t = xi[j] - qv[j]; s += t * t; }
      hd[m] = s;
      hi[m] = i;
      seen[i] = r;
    }
    if (k < N) {
      heap_build(hd, hi, k);
      double thr = hd[0];
      for (int i = 0; i < N; i++) {
        if (seen[i] == r) continue;
        const double *xi = XR + (size_t) i * d;
        double s = 0.0;
        int j = 0;
        for (; j < d; j++) {
          double t = xi[j] - qv[j];
          s += t * t;
          if (s >= thr) break;
        }
        if (j == d) {
          hd[0] = s;
          hi[0] = i;
          heap_sift_down(hd, hi, k, 0);
          thr = hd[0];
        }
      }
    }
    for (int m = 0; m < k; m++) prev[m] = hi[m];

    /* first pass: weighted moments of the centred markers */
    double sw = 0.0;
    for (int j = 0; j < d; j++) sx[j] = 0.0;
    for (int j = 0; j < d * d; j++) sxx[j] = 0.0;
    for (int m = 0; m < k; m++) {
      const double *xi = XR + (size_t) hi[m] * d;
      double dist = sqrt(hd[m]);
      double w = 1.0 / (dist > eps ? dist : eps);
      hd[m] = w;                          /* keep the weight for the second pass */
      for (int j = 0; j < d; j++) xc[j] = xi[j] - qv[j];
      sw += w;
      for (int j = 0; j < d; j++) {
        double wx = w * xc[j];
        sx[j] += wx;
        for (int l = 0; l <= j; l++) sxx[j + l * d] += wx * xc[l];
      }
    }
    double tr = 0.0;
    for (int j = 0; j < d; j++) tr += sxx[j + j * d];
    double lam = ridge * tr / d + 1e-12;
    int ok = 0;
    for (int attempt = 0; attempt < 8 && !ok; attempt++) {
      for (int j = 0; j < d; j++)
        for (int l = 0; l <= j; l++) {
          double v = sxx[j + l * d] - sx[j] * sx[l] / sw;
          a[j + l * d] = v;
          a[l + j * d] = v;
        }
      for (int j = 0; j < d; j++) a[j + j * d] += lam;
      ok = hm_chol_upper(d, a, rf);
      if (!ok) lam = lam * 100 + 1e-8 * (tr / d + 1.0);
    }
    if (!ok) error("lwr: local regression is singular at query row %d", r + 1);
    /* The intercept of the centred fit is linear in the targets:
     * prediction = sum_m alpha_m y_m with alpha_m = w_m (1 + v'sx / sw - v'xc_m) / sw,
     * v = A^-1 sx (the equivalent kernel), so each neighbour costs O(d + q). */
    for (int j = 0; j < d; j++) beta[j] = sx[j];
    hm_chol_solve(rf, d, beta, 1);
    double vsx = 0.0;
    for (int j = 0; j < d; j++) vsx += beta[j] * sx[j];
    for (int c = 0; c < q; c++) hy[c] = 0.0;
    for (int m = 0; m < k; m++) {
      const int i = hi[m];
      const double *xi = XR + (size_t) i * d;
      double vx = 0.0;
      for (int j = 0; j < d; j++) vx += beta[j] * (xi[j] - qv[j]);
      double alpha = hd[m] * (1.0 + vsx / sw - vx) / sw;
      for (int c = 0; c < q; c++) hy[c] += alpha * Y[i + (size_t) c * N];
    }
    for (int c = 0; c < q; c++) O[r + (size_t) c * n] = hy[c];
  }
  UNPROTECT(1);
  return out;
}
