/* Multivariate dynamic time warping (the package's "fast" engine).
 *
 * Reproduces dtw::dtw(x, y, dist.method = "Euclidean",
 * step.pattern = dtw::symmetric2) exactly, including its choice among tied
 * predecessors, so that the fast and the reference engine return the same
 * warping path:
 *   g[i,j] = min( g[i-1,j-1] + 2 d[i,j],   (step 1, diagonal)
 *                 g[i  ,j-1] +   d[i,j],   (step 2, template advances)
 *                 g[i-1,j  ] +   d[i,j] )  (step 3, recording advances)
 *   g[1,1] = d[1,1]; a candidate wins only if strictly smaller than the ones
 *   before it, in the order 1, 2, 3 (as the dtw package's argmin does).
 * The optional window is dtw's "slantedband": cell (i,j) (1-based) is allowed
 * when |j - i*m/n| <= window; cell (1,1) is always seeded, as in dtw.
 *
 * Two entry points:
 *   hm_dtw_pair(x, y, window)        one path: list(index1, index2, distance)
 *   hm_dtw_batch(recs, tmpl, window) every recording against one template,
 *     returning what one DTW barycenter averaging (DBA) step needs: the sum and
 *     count of recording frames matched to each template frame, and each
 *     recording's warped frames and warping function.
 * All scratch memory comes from R_alloc (reclaimed by R when .Call returns,
 * also on error), so an error raised midway leaks nothing. */
#include <math.h>
#include <R.h>
#include <Rinternals.h>

#define DIR_NONE 0
#define DIR_DIAG 1
#define DIR_LEFT 2 /* from (i, j-1) */
#define DIR_UP 3   /* from (i-1, j) */

/* Workspace for one alignment of an n x p recording against an m x p template;
 * sized for the largest recording so the batch reuses it. */
typedef struct {
  double *cm;         /* cumulative cost, n x m column-major (NaN = unreached) */
  unsigned char *dir; /* step taken into each cell */
  int *pi, *pj;       /* path, 0-based, built backwards */
  double *dcol;       /* local distances of one template column */
} dtw_work;

static void work_alloc(dtw_work *w, int nmax, int m) {
  size_t cells = (size_t) nmax * (size_t) m;
  w->cm = (double *) R_alloc(cells, sizeof(double));
  w->dir = (unsigned char *) R_alloc(cells, sizeof(unsigned char));
  w->pi = (int *) R_alloc((size_t) nmax + m, sizeof(int));
  w->pj = (int *) R_alloc((size_t) nmax + m, sizeof(int));
  w->dcol = (double *) R_alloc((size_t) nmax, sizeof(double));
}

/* DTW on NaN/Inf has no meaningful path. */
static int all_finite(const double *x, size_t len) {
  for (size_t q = 0; q < len; q++)
    if (!R_FINITE(x[q])) return 0;
  return 1;
}

/* Euclidean distances between every frame of x (n x p, column-major) and
 * template frame j of y (m x p, column-major), into dcol[0..n-1]. The sum over
 * DoFs runs in the same order (k = 0..p-1) for every cell, as proxy::dist
 * does, so values are bit-identical to the reference; looping over frames
 * innermost makes the cells independent, so the work pipelines (and
 * vectorises) instead of waiting on one long chain of additions. */
static void local_column(const double *x, int n, const double *y, int m, int p,
                         int j, double *dcol) {
  for (int i = 0; i < n; i++) dcol[i] = 0.0;
  for (int k = 0; k < p; k++) {
    const double *xk = x + (size_t) k * n;
    const double yk = y[(size_t) k * m + j];
    for (int i = 0; i < n; i++) {
      double d = xk[i] - yk;
      dcol[i] += d * d;
    }
  }
  for (int i = 0; i < n; i++) dcol[i] = sqrt(dcol[i]);
}

/* Fill the cumulative cost matrix and backtrack. x is n x p, y is m x p
 * (column-major). window < 0 means no window. Returns the path length (path
 * stored forwards in w->pi/w->pj, 0-based) or -1 when no admissible path
 * exists. */
static int dtw_core(const double *x, int n, const double *y, int m, int p,
                    double window, dtw_work *w, double *distance) {
  double *cm = w->cm;
  unsigned char *dir = w->dir;
  double *dcol = w->dcol;
  const double ratio_num = (double) m;
  for (int j = 0; j < m; j++) {
    local_column(x, n, y, m, p, j, dcol);
    for (int i = 0; i < n; i++) {
      size_t c = (size_t) j * n + i;
      if (i == 0 && j == 0) { /* seed, independent of the window (as dtw) */
        cm[c] = dcol[0];
        dir[c] = DIR_NONE;
        continue;
      }
      cm[c] = NA_REAL;
      dir[c] = DIR_NONE;
      if (window >= 0) {
        /* same arithmetic as dtw::slantedBandWindow: (i * m) / n, 1-based */
        double diagj = ((double) (i + 1) * ratio_num) / (double) n;
        if (fabs((double) (j + 1) - diagj) > window) continue;
      }
      double d = dcol[i];
      double best = R_PosInf;
      unsigned char arg = DIR_NONE;
      /* NaN compares false, so unreached predecessors never win */
      if (i > 0 && j > 0) {
        double v = cm[c - n - 1] + 2.0 * d;
        if (v < best) { best = v; arg = DIR_DIAG; }
      }
      if (j > 0) {
        double v = cm[c - n] + d;
        if (v < best) { best = v; arg = DIR_LEFT; }
      }
      if (i > 0) {
        double v = cm[c - 1] + d;
        if (v < best) { best = v; arg = DIR_UP; }
      }
      if (arg != DIR_NONE) {
        cm[c] = best;
        dir[c] = arg;
      }
    }
  }
  double total = cm[(size_t) (m - 1) * n + (n - 1)];
  if (ISNAN(total)) return -1;
  *distance = total;

  /* backtrack from (n-1, m-1) to (0, 0), storing the path backwards */
  int i = n - 1, j = m - 1, len = 0;
  int cap = n + m; /* path length is at most n + m - 1 */
  while (1) {
    w->pi[len] = i;
    w->pj[len] = j;
    len++;
    if (i == 0 && j == 0) break;
    unsigned char s = dir[(size_t) j * n + i];
    if (s == DIR_DIAG) { i--; j--; }
    else if (s == DIR_LEFT) { j--; }
    else if (s == DIR_UP) { i--; }
    else return -1; /* cannot happen for a reached cell; be safe */
    if (len >= cap) return -1;
  }
  /* reverse into forward order */
  for (int a = 0, b = len - 1; a < b; a++, b--) {
    int t = w->pi[a]; w->pi[a] = w->pi[b]; w->pi[b] = t;
    t = w->pj[a]; w->pj[a] = w->pj[b]; w->pj[b] = t;
  }
  return len;
}

static double window_arg(SEXP window) {
  if (isNull(window)) return -1.0;
  if (!isReal(window) || XLENGTH(window) != 1 || ISNAN(REAL(window)[0]) ||
      REAL(window)[0] < 0)
    error("'window' must be NULL or one non-negative number");
  return REAL(window)[0];
}

static void check_matrix(SEXP x, const char *what) {
  if (!isReal(x) || !isMatrix(x))
    error("'%s' must be a double matrix", what);
  if (nrows(x) < 1 || ncols(x) < 1)
    error("'%s' must have at least one row and one column", what);
}

SEXP hm_dtw_pair(SEXP x, SEXP y, SEXP window) {
  check_matrix(x, "x");
  check_matrix(y, "template");
  int n = nrows(x), m = nrows(y), p = ncols(x);
  if (ncols(y) != p)
    error("'x' has %d columns but 'template' has %d", p, ncols(y));
  double win = window_arg(window);

  dtw_work w;
  work_alloc(&w, n, m);
  if (!all_finite(REAL(x), (size_t) n * p))
    error("'x' contains non-finite values");
  if (!all_finite(REAL(y), (size_t) m * p))
    error("'template' contains non-finite values");

  double distance = NA_REAL;
  int len = dtw_core(REAL(x), n, REAL(y), m, p, win, &w, &distance);
  if (len < 0) error("no warping path exists within the window");

  SEXP i1 = PROTECT(allocVector(INTSXP, len));
  SEXP i2 = PROTECT(allocVector(INTSXP, len));
  int *pi1 = INTEGER(i1), *pi2 = INTEGER(i2);
  for (int k = 0; k < len; k++) {
    pi1[k] = w.pi[k] + 1;
    pi2[k] = w.pj[k] + 1;
  }
  SEXP out = PROTECT(allocVector(VECSXP, 3));
  SET_VECTOR_ELT(out, 0, i1);
  SET_VECTOR_ELT(out, 1, i2);
  SET_VECTOR_ELT(out, 2, ScalarReal(distance));
  SEXP nms = PROTECT(allocVector(STRSXP, 3));
  SET_STRING_ELT(nms, 0, mkChar("index1"));
  SET_STRING_ELT(nms, 1, mkChar("index2"));
  SET_STRING_ELT(nms, 2, mkChar("distance"));
  setAttrib(out, R_NamesSymbol, nms);
  UNPROTECT(4);
  return out;
}

/* recs: list of n_k x p double matrices; tmpl: L x p. Returns
 * list(sum = L x p, count = int L, warped = N x L x p, warps = N x L,
 *      distance = N). Errors name the (1-based) recording that failed. */
SEXP hm_dtw_batch(SEXP recs, SEXP tmpl, SEXP window) {
  if (!isNewList(recs)) error("'recordings' must be a list");
  check_matrix(tmpl, "template");
  int N = LENGTH(recs), L = nrows(tmpl), p = ncols(tmpl);
  double win = window_arg(window);
  int nmax = 1;
  for (int k = 0; k < N; k++) {
    SEXP xk = VECTOR_ELT(recs, k);
    if (!isReal(xk) || !isMatrix(xk) || nrows(xk) < 1 || ncols(xk) != p)
      error("recording %d must be a double matrix with at least one row and %d columns",
            k + 1, p);
    if (nrows(xk) > nmax) nmax = nrows(xk);
  }

  dtw_work w;
  work_alloc(&w, nmax, L);
  const double *y = REAL(tmpl);
  if (!all_finite(y, (size_t) L * p))
    error("the template contains non-finite values");
  int *cnt_k = (int *) R_alloc((size_t) L, sizeof(int));
  /* one recording's warped frames, contiguous (L x p), copied once into the
   * N x L x p result: avoids scattered read-modify-writes at stride N */
  double *wk = (double *) R_alloc((size_t) L * p, sizeof(double));

  SEXP sum = PROTECT(allocMatrix(REALSXP, L, p));
  SEXP count = PROTECT(allocVector(INTSXP, L));
  SEXP warps = PROTECT(allocMatrix(REALSXP, N, L));
  SEXP dist = PROTECT(allocVector(REALSXP, N));
  SEXP dims = PROTECT(allocVector(INTSXP, 3));
  INTEGER(dims)[0] = N; INTEGER(dims)[1] = L; INTEGER(dims)[2] = p;
  SEXP warped = PROTECT(allocArray(REALSXP, dims));
  double *ps = REAL(sum), *pw = REAL(warps), *pd = REAL(dist), *pa = REAL(warped);
  int *pc = INTEGER(count);
  for (size_t q = 0; q < (size_t) L * p; q++) ps[q] = 0.0;
  for (int j = 0; j < L; j++) pc[j] = 0;
  for (size_t q = 0; q < (size_t) N * L; q++) pw[q] = 0.0;

  for (int k = 0; k < N; k++) {
    SEXP xk = VECTOR_ELT(recs, k);
    int n = nrows(xk);
    const double *x = REAL(xk);
    if (!all_finite(x, (size_t) n * p))
      error("recording %d contains non-finite values", k + 1);
    double d = NA_REAL;
    int len = dtw_core(x, n, y, L, p, win, &w, &d);
    if (len < 0) error("no warping path exists for recording %d within the window", k + 1);
    pd[k] = d;
    for (int j = 0; j < L; j++) cnt_k[j] = 0;
    for (size_t q = 0; q < (size_t) L * p; q++) wk[q] = 0.0;
    for (int s = 0; s < len; s++) {
      int i = w.pi[s], j = w.pj[s];
      cnt_k[j]++;
      pc[j]++;
      pw[k + (size_t) N * j] += (double) (i + 1);
      for (int c = 0; c < p; c++) {
        double v = x[i + (size_t) n * c];
        ps[j + (size_t) L * c] += v;
        wk[j + (size_t) L * c] += v;
      }
    }
    /* every template frame is on the path at least once (path runs from
     * column 1 to column L in unit steps), so cnt_k[j] >= 1 */
    for (int j = 0; j < L; j++) pw[k + (size_t) N * j] /= (double) cnt_k[j];
    for (int c = 0; c < p; c++)
      for (int j = 0; j < L; j++)
        pa[k + (size_t) N * (j + (size_t) L * c)] = wk[j + (size_t) L * c] / (double) cnt_k[j];
  }

  SEXP out = PROTECT(allocVector(VECSXP, 5));
  SET_VECTOR_ELT(out, 0, sum);
  SET_VECTOR_ELT(out, 1, count);
  SET_VECTOR_ELT(out, 2, warped);
  SET_VECTOR_ELT(out, 3, warps);
  SET_VECTOR_ELT(out, 4, dist);
  SEXP nms = PROTECT(allocVector(STRSXP, 5));
  SET_STRING_ELT(nms, 0, mkChar("sum"));
  SET_STRING_ELT(nms, 1, mkChar("count"));
  SET_STRING_ELT(nms, 2, mkChar("warped"));
  SET_STRING_ELT(nms, 3, mkChar("warps"));
  SET_STRING_ELT(nms, 4, mkChar("distance"));
  setAttrib(out, R_NamesSymbol, nms);
  UNPROTECT(8);
  return out;
}
