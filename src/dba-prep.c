/* Per-recording work around DTW barycenter averaging (R/align.R), done for
 * all recordings of a type in one call instead of one R call per recording:
 *
 *   hm_shape_features(recs, k)  the shape features of every recording
 *     (shape_normaliser() + normalise_recording()): list(features, centre,
 *     scale), centre and scale N x p;
 *   hm_linear_mean(recs, warps, which)  the mean of the recordings linearly
 *     resampled to L frames (mean_linear_template()): recording k is
 *     evaluated at warps[[which[k]]] (its linear warping function, computed in
 *     R by linear_warp_function()); returns the L x p sum, R divides by N;
 *   hm_stall_lengths(warps)  per row of an N x L matrix of warping
 *     functions, the longest run of template frames held on one original
 *     frame (stall_lengths());
 *   hm_unshape_warped(warped, scale, centre, kept)  the warped shape
 *     features (n x L x p) back in data units, x * scale + centre with the
 *     scale and centre of recording kept[i] and DoF c (align_checked(): in R
 *     two n x Lp matrices expanded from N x p and four array temporaries,
 *     14 ms a type of ten times the default data); the product and the sum
 *     are separate passes, as R's two operations, so no compiler fuses them
 *     into one rounding.
 *
 * Each reproduces the arithmetic of the R code it replaces, operation for
 * operation (long double where colMeans/colSums use it, sums in the same
 * order), so the alignment is unchanged to the last bit; the R versions stay
 * in R/align.R and the tests compare the two. */
#include <math.h>
#include <R.h>
#include <Rinternals.h>
#include "named-list.h"

static void check_recs(SEXP recs, int *p_out) {
  if (!isNewList(recs) || LENGTH(recs) < 1) error("'recs' must be a non-empty list");
  int p = -1;
  for (int k = 0; k < LENGTH(recs); k++) {
    SEXP x = VECTOR_ELT(recs, k);
    if (!isReal(x) || !isMatrix(x) || nrows(x) < 1 || ncols(x) < 1)
      error("recording %d must be a double matrix with at least one frame", k + 1);
    if (p < 0) p = ncols(x);
    else if (ncols(x) != p) error("recording %d has %d columns, not %d", k + 1, ncols(x), p);
  }
  *p_out = p;
}

/* colMeans() of rows [from, to) of column c: long double sum over the rows,
 * divided in long double, rounded once */
static double col_mean(const double *x, int n, int c, int from, int to) {
  long double s = 0;
  for (int i = from; i < to; i++) s += x[(size_t) c * n + i];
  s /= (to - from);
  return (double) s;
}

SEXP hm_shape_features(SEXP recs, SEXP k_) {
  int p;
  check_recs(recs, &p);
  const int N = LENGTH(recs), kk = asInteger(k_);
  SEXP feats = PROTECT(allocVector(VECSXP, N));
  SEXP centre = PROTECT(allocMatrix(REALSXP, N, p));
  SEXP scale = PROTECT(allocMatrix(REALSXP, N, p));
  double *pc = REAL(centre), *ps = REAL(scale);
  double *sdev = (double *) R_alloc(p, sizeof(double));
  for (int r = 0; r < N; r++) {
    SEXP xs = VECTOR_ELT(recs, r);
    const int n = nrows(xs);
    const double *x = REAL(xs);
    const int k = kk < n ? kk : n;
    /* centre: midpoint of the mean first and mean last k frames */
    for (int c = 0; c < p; c++)
      pc[r + (size_t) N * c] = (col_mean(x, n, c, 0, k) + col_mean(x, n, c, n - k, n)) / 2;
    /* sd per DoF: sqrt(colSums((x - colMeans(x))^2) / (n - 1)) */
    double top = R_NegInf;
    int has_nan = 0;
    for (int c = 0; c < p; c++) {
      if (n > 1) {
        double m = col_mean(x, n, c, 0, n);
        long double s = 0;
        for (int i = 0; i < n; i++) {
          double dv = x[(size_t) c * n + i] - m;
          s += dv * dv;
        }
        sdev[c] = sqrt((double) s / (double) (n - 1));
      } else {
        sdev[c] = 0;
      }
      if (ISNAN(sdev[c])) has_nan = 1;
      else if (sdev[c] > top) top = sdev[c];
    }
    /* floor: 10% of the largest sd, 1 if that is not a positive number */
    double fl = has_nan ? R_NaN : 0.1 * top;
    if (!R_FINITE(fl) || fl <= 0) fl = 1;
    for (int c = 0; c < p; c++)
      ps[r + (size_t) N * c] = ISNAN(sdev[c]) ? NA_REAL : (sdev[c] > fl ? sdev[c] : fl);
    SEXP f = PROTECT(allocMatrix(REALSXP, n, p));
    double *pf = REAL(f);
    for (int c = 0; c < p; c++) {
      const double cc = pc[r + (size_t) N * c], sc = ps[r + (size_t) N * c];
      for (int i = 0; i < n; i++) pf[(size_t) c * n + i] = (x[(size_t) c * n + i] - cc) / sc;
    }
    SET_VECTOR_ELT(feats, r, f);
    UNPROTECT(1);
  }
  const char *names[] = {"features", "centre", "scale"};
  const SEXP values[] = {feats, centre, scale};
  SEXP out = hm_named_list(3, names, values);
  UNPROTECT(3);
  return out;
}

SEXP hm_linear_mean(SEXP recs, SEXP warps, SEXP which) {
  int p;
  check_recs(recs, &p);
  const int N = LENGTH(recs);
  if (!isNewList(warps) || LENGTH(warps) < 1) error("'warps' must be a non-empty list");
  if (!isInteger(which) || LENGTH(which) != N) error("'which' must give one warp per recording");
  const int L = LENGTH(VECTOR_ELT(warps, 0));
  for (int q = 0; q < LENGTH(warps); q++)
    if (!isReal(VECTOR_ELT(warps, q)) || LENGTH(VECTOR_ELT(warps, q)) != L)
      error("warp %d must be a double vector of length %d", q + 1, L);
  SEXP acc = PROTECT(allocMatrix(REALSXP, L, p));
  double *pa = REAL(acc);
  for (size_t q = 0; q < (size_t) L * p; q++) pa[q] = 0.0;
  for (int r = 0; r < N; r++) {
    SEXP xs = VECTOR_ELT(recs, r);
    const int n = nrows(xs);
    const double *x = REAL(xs);
    int wi = INTEGER(which)[r];
    if (wi < 1 || wi > LENGTH(warps)) error("'which' is out of range for recording %d", r + 1);
    const double *w = REAL(VECTOR_ELT(warps, wi - 1));
    for (int l = 0; l < L; l++) {
      if (n == 1) { /* a one-frame recording is constant */
        for (int c = 0; c < p; c++) pa[l + (size_t) L * c] += x[(size_t) c];
        continue;
      }
      /* apply_warp(): clamp to [1, n], interpolate between neighbours */
      double t = w[l] > 1 ? w[l] : 1;
      if (t > n) t = n;
      double i0 = floor(t);
      if (i0 > n - 1) i0 = n - 1;
      double f = t - i0, g = 1 - f;
      int a = (int) i0 - 1; /* 0-based row of frame i0 */
      for (int c = 0; c < p; c++) {
        double lo = x[(size_t) c * n + a] * g;
        double hi = x[(size_t) c * n + a + 1] * f;
        pa[l + (size_t) L * c] += lo + hi;
      }
    }
  }
  UNPROTECT(1);
  return acc;
}

SEXP hm_stall_lengths(SEXP warps) {
  if (!isReal(warps) || !isMatrix(warps)) error("'warps' must be a double matrix");
  const int N = nrows(warps), L = ncols(warps);
  const double *w = REAL(warps);
  SEXP out = PROTECT(allocVector(INTSXP, N));
  int *po = INTEGER(out);
  for (int r = 0; r < N; r++) {
    int run = 1, best = 1;
    for (int l = 1; l < L; l++) {
      run = (w[r + (size_t) N * l] == w[r + (size_t) N * (l - 1)]) ? run + 1 : 1;
      if (run > best) best = run;
    }
    po[r] = best;
  }
  UNPROTECT(1);
  return out;
}

SEXP hm_unshape_warped(SEXP warped, SEXP scale, SEXP centre, SEXP kept) {
  SEXP dim = getAttrib(warped, R_DimSymbol);
  if (!isReal(warped) || LENGTH(dim) != 3) error("'warped' must be a double n x L x p array");
  int n = INTEGER(dim)[0], L = INTEGER(dim)[1], p = INTEGER(dim)[2];
  if (!isReal(scale) || !isReal(centre) || !isMatrix(scale) || !isMatrix(centre) ||
      ncols(scale) != p || ncols(centre) != p || nrows(centre) != nrows(scale))
    error("'scale' and 'centre' must be double matrices with one column per DoF");
  if (!isInteger(kept) || LENGTH(kept) != n) error("'kept' must be integer, one per row of 'warped'");
  int N = nrows(scale);
  const int *kp = INTEGER(kept);
  for (int i = 0; i < n; i++)
    if (kp[i] == NA_INTEGER || kp[i] < 1 || kp[i] > N) error("'kept' must be rows of 'scale'");
  const double *w = REAL(warped), *sc = REAL(scale), *ce = REAL(centre);
  SEXP out = PROTECT(allocVector(REALSXP, XLENGTH(warped)));
  double *o = REAL(out);
  for (int c = 0; c < p; c++)
    for (int l = 0; l < L; l++) {
      R_xlen_t at = (R_xlen_t) n * ((R_xlen_t) c * L + l);
      for (int i = 0; i < n; i++) o[at + i] = w[at + i] * sc[(kp[i] - 1) + (R_xlen_t) c * N];
    }
  for (int c = 0; c < p; c++)
    for (int l = 0; l < L; l++) {
      R_xlen_t at = (R_xlen_t) n * ((R_xlen_t) c * L + l);
      for (int i = 0; i < n; i++) o[at + i] = o[at + i] + ce[(kp[i] - 1) + (R_xlen_t) c * N];
    }
  setAttrib(out, R_DimSymbol, duplicate(dim));
  UNPROTECT(1);
  return out;
}
