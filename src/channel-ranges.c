/* The smallest and largest value of each channel over every frame of a list of
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
