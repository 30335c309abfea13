/* Per-channel statistics over every frame of a list of recordings, without
 * stacking them (R/glove.R, R/joint-limits.R).
 *
 * hm_channel_ranges: the smallest and largest value of each channel over every frame of a list of
 * recordings (frames x channels double matrices of one width, finite values:
 * what grasps() holds). One pass over the values, no copy: stacking the
 * recordings or two apply() calls per recording cost as much as reading the
 * 5,000 files of a GraspDB14 directory (grasps() asks this of every set it
 * builds, to find stuck sensors). min() and max() are exact, so the result is
 * what apply(do.call(rbind, recordings), 2, min / max) gives. */
#include <R.h>
#include <Rinternals.h>

SEXP hm_channel_ranges(SEXP recs, SEXP p_) {
  int p = asInteger(p_);
  R_xlen_t n = XLENGTH(recs);
  SEXP out = PROTECT(allocMatrix(REALSXP, 2, p));
  double *lo_hi = REAL(out);
  for (int j = 0; j < p; j++) { lo_hi[2 * j] = R_PosInf; lo_hi[2 * j + 1] = R_NegInf; }
  for (R_xlen_t r = 0; r < n; r++) {
    SEXP x = VECTOR_ELT(recs, r);
    if (TYPEOF(x) != REALSXP || !isMatrix(x) || ncols(x) != p)
      error("hm_channel_ranges: recording %ld is not a double matrix of %d columns", (long) r + 1, p);
    int m = nrows(x);
    const double *v = REAL(x);
    for (int j = 0; j < p; j++) {
      const double *col = v + (R_xlen_t) j * m;
      double lo = lo_hi[2 * j], hi = lo_hi[2 * j + 1];
      for (int i = 0; i < m; i++) {
        if (col[i] < lo) lo = col[i];
        if (col[i] > hi) hi = col[i];
      }
      lo_hi[2 * j] = lo;
      lo_hi[2 * j + 1] = hi;
    }
  }
  UNPROTECT(1);
  return out;
}

/* For each limit k (column cols[k], 1-based, and bounds lo[k] < hi[k]): how
 * many frames of all the recordings lie below lo[k] or above hi[k], what
 * colSums(sweep(X, 2, lo, "<") | sweep(X, 2, hi, ">")) of the stacked frames
 * X gives (NA for a limit whose column or bounds are missing, as there).
 * recorded_limits() asked this of every model fitted: stacking
 * 2,700 recordings with rbind() and two sweep()s over them were a twentieth
 * of a fit at ten times the default data. */
SEXP hm_channel_outside(SEXP recs, SEXP cols, SEXP lo_, SEXP hi_) {
  R_xlen_t n = XLENGTH(recs);
  int K = LENGTH(cols);
  if (TYPEOF(cols) != INTSXP || TYPEOF(lo_) != REALSXP || TYPEOF(hi_) != REALSXP ||
      LENGTH(lo_) != K || LENGTH(hi_) != K) error("hm_channel_outside: bad limits");
  const int *col = INTEGER(cols);
  const double *lo = REAL(lo_), *hi = REAL(hi_);
  SEXP out = PROTECT(allocVector(REALSXP, K));
  double *count = REAL(out);
  /* a limit without its column or bounds counts NA, as in R */
  for (int k = 0; k < K; k++)
    count[k] = col[k] == NA_INTEGER || ISNAN(lo[k]) || ISNAN(hi[k]) ? NA_REAL : 0;
  for (R_xlen_t r = 0; r < n; r++) {
    SEXP x = VECTOR_ELT(recs, r);
    if (TYPEOF(x) != REALSXP || !isMatrix(x))
      error("hm_channel_outside: recording %ld is not a double matrix", (long) r + 1);
    int m = nrows(x), p = ncols(x);
    const double *v = REAL(x);
    for (int k = 0; k < K; k++) {
      if (ISNA(count[k])) continue;
      if (col[k] < 1 || col[k] > p) error("hm_channel_outside: column %d of %d", col[k], p);
      const double *c = v + (R_xlen_t) (col[k] - 1) * m;
      double a = lo[k], b = hi[k], outside = 0;
      for (int i = 0; i < m; i++) outside += (c[i] < a) | (c[i] > b);
      count[k] += outside;
    }
  }
  UNPROTECT(1);
  return out;
}
