/* The per-channel walks of find_motion() (R/segment-signals.R), each over
 * the columns of a double matrix X (frames x channels) with one start frame
 * or threshold per column (1-based frames, as R's):
 *   hm_first_above(X, thr)         the first frame with X > thr (NA: none)
 *   hm_last_at_least(X, thr)       the last frame with X >= thr (NA: none)
 *   hm_walk_back(X, start, thr)    from start, back while the frame before
 *                                  is above thr (not below frame 1)
 *   hm_walk_forward(X, start, thr) from start, forward while the frame after
 *                                  is above thr (not past the last frame)
 *   hm_col_max(X)                  each column's max() (NA before NaN, as
 *                                  max(); -Inf for no frames)
 * In R each was a vapply() over the moving channels of every recording with
 * a while loop or which() inside, and apply(, 2, max): half of
 * find_motion()'s time (0.16 s for the 200 recordings a fit decides its
 * motion on, before any worker starts). The comparisons are R's (NaN is
 * never above or at a threshold), so the frames are the ones R found. */
#include <R.h>
#include <Rinternals.h>

static void check_columns(SEXP X, SEXP v, SEXPTYPE type, const char *what) {
  if (TYPEOF(X) != REALSXP || !isMatrix(X)) error("'X' must be a double matrix");
  if (TYPEOF(v) != type || XLENGTH(v) != ncols(X))
    error("'%s' must be %s, one value per column of 'X'", what, type == REALSXP ? "double" : "integer");
}

/* Per column, the first frame above thr (from_end 0) or the last frame at
 * or above it (from_end 1); NA where there is none. */
static SEXP find_frame(SEXP X_, SEXP thr_, int from_end) {
  check_columns(X_, thr_, REALSXP, "thr");
  int n = nrows(X_), p = ncols(X_);
  const double *X = REAL(X_), *thr = REAL(thr_);
  SEXP out = PROTECT(allocVector(INTSXP, p));
  for (int j = 0; j < p; j++) {
    const double *x = X + (R_xlen_t) j * n;
    int at = NA_INTEGER;
    for (int q = 0; q < n; q++) {
      int i = from_end ? n - 1 - q : q;
      if (from_end ? x[i] >= thr[j] : x[i] > thr[j]) {
        at = i + 1;
        break;
      }
    }
    INTEGER(out)[j] = at;
  }
  UNPROTECT(1);
  return out;
}

SEXP hm_first_above(SEXP X_, SEXP thr_) { return find_frame(X_, thr_, 0); }
SEXP hm_last_at_least(SEXP X_, SEXP thr_) { return find_frame(X_, thr_, 1); }

/* step -1: back, +1: forward */
static SEXP walk(SEXP X_, SEXP start_, SEXP thr_, int step) {
  check_columns(X_, start_, INTSXP, "start");
  check_columns(X_, thr_, REALSXP, "thr");
  int n = nrows(X_), p = ncols(X_);
  const double *X = REAL(X_), *thr = REAL(thr_);
  const int *start = INTEGER(start_);
  SEXP out = PROTECT(allocVector(INTSXP, p));
  for (int j = 0; j < p; j++) {
    const double *x = X + (R_xlen_t) j * n;
    int t = start[j];
    if (t == NA_INTEGER || t < 1 || t > n) error("'start' must be frames of 'X'");
    if (step < 0) {
      while (t > 1 && x[t - 2] > thr[j]) t--;
    } else {
      while (t < n && x[t] > thr[j]) t++;
    }
    INTEGER(out)[j] = t;
  }
  UNPROTECT(1);
  return out;
}

SEXP hm_walk_back(SEXP X_, SEXP start_, SEXP thr_) { return walk(X_, start_, thr_, -1); }
SEXP hm_walk_forward(SEXP X_, SEXP start_, SEXP thr_) { return walk(X_, start_, thr_, 1); }

SEXP hm_col_max(SEXP X_) {
  if (TYPEOF(X_) != REALSXP || !isMatrix(X_)) error("'X' must be a double matrix");
  int n = nrows(X_), p = ncols(X_);
  const double *X = REAL(X_);
  SEXP out = PROTECT(allocVector(REALSXP, p));
  for (int j = 0; j < p; j++) {
    const double *x = X + (R_xlen_t) j * n;
    double s = R_NegInf;
    int na = 0, nan = 0;
    for (int i = 0; i < n; i++) {
      if (ISNAN(x[i])) {
        if (R_IsNA(x[i])) na = 1; else nan = 1;
      } else if (x[i] > s) {
        s = x[i];
      }
    }
    REAL(out)[j] = na ? NA_REAL : (nan ? R_NaN : s);
  }
  UNPROTECT(1);
  return out;
}
