/* The per-channel statistics find_motion() reads from every recording
 * (R/segment-signals.R): the running median of 3 frames with Tukey's end rule
 * (stats::runmed(v, 3, endrule = "median")), the median of each smoothed
 * channel over the first `rest_n` frames (the rest level), and the MAD of
 * each raw channel's lag-`lag` second differences (the noise, before its
 * scaling and floor). In R these were three apply() calls per recording,
 * each calling median() or runmed() per channel: three quarters of fitting
 * the 626 flexglove recordings went to their call overhead. The arithmetic is
 * R's: medians of an even count are mean()'s long-double mean of the two
 * middle values, so the results are identical to the R expressions.
 *
 * Also each channel's quantisation floor as recorded (quantum_floor(v,
 * resampled = FALSE) of its finite values: half the smallest step between
 * consecutive values above 1e-9 of their largest magnitude, 0.5 without
 * one): a vapply() over the channels per recording, a quarter of
 * find_motion() on the default data. */
#include <R.h>
#include <Rinternals.h>
#include <math.h>
#include "named-list.h"

/* median of v[0..n-1] (sorted in place), as stats::median() computes it */
static double median_inplace(double *v, int n) {
  R_rsort(v, n);
  int half = n / 2;
  if (n % 2) return v[half];
  double a = v[half - 1], b = v[half];
  long double s = ((long double) a + (long double) b) / 2.0;
  if (R_FINITE((double) s)) {
    long double t = ((long double) a - s) + ((long double) b - s);
    s += t / 2.0;
  }
  return (double) s;
}

static double med3(double a, double b, double c) {
  double m = b;
  if (a < b) {
    if (c < b) m = (a >= c) ? a : c;
  } else {
    if (c > b) m = (a <= c) ? a : c;
  }
  return m;
}

SEXP hm_motion_base(SEXP X_, SEXP rest_n_, SEXP lag_) {
  int n = nrows(X_), p = ncols(X_), rest_n = asInteger(rest_n_), lag = asInteger(lag_);
  if (TYPEOF(X_) != REALSXP) error("hm_motion_base: a double matrix is needed");
  if (rest_n > n) rest_n = n;
  const double *X = REAL(X_);
  SEXP S_ = PROTECT(allocMatrix(REALSXP, n, p));
  SEXP rest_ = PROTECT(allocVector(REALSXP, p));
  SEXP mad_ = PROTECT(allocVector(REALSXP, p));
  SEXP floor_ = PROTECT(allocVector(REALSXP, p));
  double *S = REAL(S_), *rest = REAL(rest_), *mad = REAL(mad_), *qfloor = REAL(floor_);
  double *buf = (double *) R_alloc(n > 0 ? n : 1, sizeof(double));
  double *d1 = (double *) R_alloc(n > 0 ? n : 1, sizeof(double));
  for (int j = 0; j < p; j++) {
    const double *x = X + (R_xlen_t) j * n;
    double *s = S + (R_xlen_t) j * n;
    /* running median of 3 (a recording of 3 frames or fewer as is) */
    if (n <= 3) {
      for (int i = 0; i < n; i++) s[i] = x[i];
    } else {
      for (int i = 1; i < n - 1; i++) s[i] = med3(x[i - 1], x[i], x[i + 1]);
      s[0] = med3(x[0], s[1], s[1] - 2.0 * (s[2] - s[1]));
      s[n - 1] = med3(x[n - 1], s[n - 2], s[n - 2] - 2.0 * (s[n - 3] - s[n - 2]));
    }
    /* rest level */
    for (int i = 0; i < rest_n; i++) buf[i] = s[i];
    rest[j] = rest_n > 0 ? median_inplace(buf, rest_n) : NA_REAL;
    /* MAD of the second differences at `lag` of the finite values */
    int m = 0;
    for (int i = 0; i < n; i++) if (R_FINITE(x[i])) d1[m++] = x[i];
    /* quantisation floor as recorded (as quantum_floor() computes it:
     * tol = 1e-9 * max(1, abs(v)), the smallest abs(diff(v)) above tol) */
    double big = 1.0, step = R_PosInf;
    for (int i = 0; i < m; i++) if (fabs(d1[i]) > big) big = fabs(d1[i]);
    double tol = 1e-9 * big;
    for (int i = 1; i < m; i++) {
      double d = fabs(d1[i] - d1[i - 1]);
      if (d > tol && d < step) step = d;
    }
    qfloor[j] = R_FINITE(step) ? step / 2 : 0.5;
    if (m < 2 * lag + 2) { mad[j] = R_PosInf; continue; }
    int k = m - lag;
    for (int i = 0; i < k; i++) d1[i] = d1[i + lag] - d1[i];
    k -= lag;
    for (int i = 0; i < k; i++) d1[i] = d1[i + lag] - d1[i];
    for (int i = 0; i < k; i++) buf[i] = d1[i];
    double center = median_inplace(buf, k);
    for (int i = 0; i < k; i++) buf[i] = fabs(d1[i] - center);
    mad[j] = 1.4826 * median_inplace(buf, k);
  }
  SEXP dn = getAttrib(X_, R_DimNamesSymbol);
  if (!isNull(dn)) setAttrib(S_, R_DimNamesSymbol, dn);
  const char *names[] = {"S", "rest", "mad", "floor"};
  SEXP vals[] = {S_, rest_, mad_, floor_};
  SEXP out = hm_named_list(4, names, vals);
  UNPROTECT(4);
  return out;
}
