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
 *   hm_dtw_batch(recs, tmpl, window, full) every recording against one
 *     template, returning what one DTW barycenter averaging (DBA) step needs:
 *     the sum and count of recording frames matched to each template frame,
 *     and, when `full` is TRUE, each recording's warped frames, warping
 *     function and distance (only the last DBA step needs those; skipping
 *     them spares a large allocation per step).
 * All scratch memory comes from R_alloc (reclaimed by R when .Call returns,
 * also on error), so an error raised midway leaks nothing. */
#include <float.h>
#include <math.h>
#include <R.h>
#include <Rinternals.h>
#include "named-list.h"
#include "warp-path.h"
#ifdef __SSE2__
#include <emmintrin.h>
#endif

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
    if (!(fabs(x[q]) <= DBL_MAX)) return 0; /* false for NaN and +-Inf */
  return 1;
}

/* Euclidean distances between every frame of x (n x p, column-major) and
 * template frame yj (p values, contiguous), into dcol[0..n-1]. The sum over
 * DoFs runs in the same order (k = 0..p-1, from 0) for every cell, as
 * proxy::dist does, so values are bit-identical to the reference. Cells are
 * done eight at a time with the partial sums in registers: the eight sums
 * are independent, so the additions pipeline, and no partial sum goes
 * through memory between DoFs. */
static void local_column(const double *x, int n, const double *yj, int p, double *dcol) {
  int i = 0;
#ifdef __SSE2__
  /* x86-64: two cells per SSE2 instruction (baseline on x86-64, no
   * special compiler flags); packed and scalar IEEE arithmetic agree */
  for (; i + 8 <= n; i += 8) {
    __m128d a0 = _mm_setzero_pd(), a1 = _mm_setzero_pd(), a2 = _mm_setzero_pd(),
            a3 = _mm_setzero_pd();
    for (int k = 0; k < p; k++) {
      const double *xk = x + (size_t) k * n + i;
      const __m128d yk = _mm_set1_pd(yj[k]);
      __m128d d0 = _mm_sub_pd(_mm_loadu_pd(xk), yk);
      __m128d d1 = _mm_sub_pd(_mm_loadu_pd(xk + 2), yk);
      __m128d d2 = _mm_sub_pd(_mm_loadu_pd(xk + 4), yk);
      __m128d d3 = _mm_sub_pd(_mm_loadu_pd(xk + 6), yk);
      a0 = _mm_add_pd(a0, _mm_mul_pd(d0, d0));
      a1 = _mm_add_pd(a1, _mm_mul_pd(d1, d1));
      a2 = _mm_add_pd(a2, _mm_mul_pd(d2, d2));
      a3 = _mm_add_pd(a3, _mm_mul_pd(d3, d3));
    }
    _mm_storeu_pd(dcol + i, _mm_sqrt_pd(a0));
    _mm_storeu_pd(dcol + i + 2, _mm_sqrt_pd(a1));
    _mm_storeu_pd(dcol + i + 4, _mm_sqrt_pd(a2));
    _mm_storeu_pd(dcol + i + 6, _mm_sqrt_pd(a3));
  }
#else
  /* (spelt out so that the compiler keeps the eight sums in registers) */
  for (; i + 8 <= n; i += 8) {
    double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0, a4 = 0.0, a5 = 0.0, a6 = 0.0, a7 = 0.0;
    for (int k = 0; k < p; k++) {
      const double *xk = x + (size_t) k * n + i;
      const double yk = yj[k];
      double d0 = xk[0] - yk, d1 = xk[1] - yk, d2 = xk[2] - yk, d3 = xk[3] - yk;
      double d4 = xk[4] - yk, d5 = xk[5] - yk, d6 = xk[6] - yk, d7 = xk[7] - yk;
      a0 += d0 * d0;
      a1 += d1 * d1;
      a2 += d2 * d2;
      a3 += d3 * d3;
      a4 += d4 * d4;
      a5 += d5 * d5;
      a6 += d6 * d6;
      a7 += d7 * d7;
    }
    dcol[i] = sqrt(a0);
    dcol[i + 1] = sqrt(a1);
    dcol[i + 2] = sqrt(a2);
    dcol[i + 3] = sqrt(a3);
    dcol[i + 4] = sqrt(a4);
    dcol[i + 5] = sqrt(a5);
    dcol[i + 6] = sqrt(a6);
    dcol[i + 7] = sqrt(a7);
  }
#endif
  for (; i < n; i++) {
    double a = 0.0;
    for (int k = 0; k < p; k++) {
      double d = x[(size_t) k * n + i] - yj[k];
      a += d * d;
    }
    dcol[i] = sqrt(a);
  }
}

/* Fill the cumulative cost matrix and backtrack. x is n x p, y is m x p
 * (column-major). window < 0 means no window. Returns the path length (path
 * stored forwards in w->pi/w->pj, 0-based) or -1 when no admissible path
 * exists. */
static int dtw_core(const double *x, int n, const double *yt, int m, int p,
                    double window, dtw_work *w, double *distance) {
  double *cm = w->cm;
  unsigned char *dir = w->dir;
  double *dcol = w->dcol;
  const double ratio_num = (double) m;
  if (window < 0) {
    /* no window: every cell is reached, so no NaN bookkeeping; same
     * candidates in the same order with the same strict comparisons */
    local_column(x, n, yt, p, dcol);
    cm[0] = dcol[0];
    dir[0] = DIR_NONE;
    for (int i = 1; i < n; i++) { /* first column: only steps up */
      cm[i] = cm[i - 1] + dcol[i];
      dir[i] = DIR_UP;
    }
    for (int j = 1; j < m; j++) {
      local_column(x, n, yt + (size_t) j * p, p, dcol);
      double *cj = cm + (size_t) j * n;
      const double *cp = cj - n;
      unsigned char *dj = dir + (size_t) j * n;
      cj[0] = cp[0] + dcol[0]; /* first row: only steps left */
      dj[0] = DIR_LEFT;
      double below = cj[0];
      for (int i = 1; i < n; i++) {
        /* written as selects, not branches: which step wins is data
         * dependent, and mispredicted branches cost more than the cell */
        double d = dcol[i];
        double diag = cp[i - 1] + 2.0 * d;
        double left = cp[i] + d;
        double up = below + d;
        int take_left = left < diag;
        double best = take_left ? left : diag;
        int take_up = up < best;
        best = take_up ? up : best;
        cj[i] = best;
        dj[i] = (unsigned char) (take_up ? DIR_UP : (take_left ? DIR_LEFT : DIR_DIAG));
        below = best;
      }
    }
  } else {
  for (int j = 0; j < m; j++) {
    local_column(x, n, yt + (size_t) j * p, p, dcol);
    for (int i = 0; i < n; i++) {
      size_t c = (size_t) j * n + i;
      if (i == 0 && j == 0) { /* seed, independent of the window (as dtw) */
        cm[c] = dcol[0];
        dir[c] = DIR_NONE;
        continue;
      }
      cm[c] = NA_REAL;
      dir[c] = DIR_NONE;
      /* same arithmetic as dtw::slantedBandWindow: (i * m) / n, 1-based */
      double diagj = ((double) (i + 1) * ratio_num) / (double) n;
      if (fabs((double) (j + 1) - diagj) > window) continue;
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

/* The template frame-major (p values per frame, contiguous), as
 * local_column() reads it. */
static const double *frame_major(const double *y, int m, int p) {
  double *yt = (double *) R_alloc((size_t) m * p, sizeof(double));
  for (int j = 0; j < m; j++)
    for (int k = 0; k < p; k++) yt[(size_t) j * p + k] = y[(size_t) k * m + j];
  return yt;
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
  int len = dtw_core(REAL(x), n, frame_major(REAL(y), m, p), m, p, win, &w, &distance);
  if (len < 0) error("no warping path exists within the window");

  return hm_warp_path(w.pi, w.pj, len, 0, distance);
}

/* recs: list of n_k x p double matrices; tmpl: L x p. Returns
 * list(sum = L x p, count = int L, warped = N x L x p, warps = N x L,
 *      distance = N), the last three NULL unless `full`. Errors name the
 * (1-based) recording that failed. */
SEXP hm_dtw_batch(SEXP recs, SEXP tmpl, SEXP window, SEXP full_) {
  if (!isNewList(recs)) error("'recordings' must be a list");
  check_matrix(tmpl, "template");
  int N = LENGTH(recs), L = nrows(tmpl), p = ncols(tmpl);
  double win = window_arg(window);
  const int full = asLogical(full_) == TRUE;
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
  const double *yt = frame_major(y, L, p);
  int *cnt_k = (int *) R_alloc((size_t) L, sizeof(int));
  /* one recording's warped frames, contiguous (L x p), copied once into the
   * N x L x p result: avoids scattered read-modify-writes at stride N */
  double *wk = (double *) R_alloc((size_t) L * p, sizeof(double));

  SEXP sum = PROTECT(allocMatrix(REALSXP, L, p));
  SEXP count = PROTECT(allocVector(INTSXP, L));
  SEXP warps = PROTECT(full ? allocMatrix(REALSXP, N, L) : R_NilValue);
  SEXP dist = PROTECT(full ? allocVector(REALSXP, N) : R_NilValue);
  SEXP warped = PROTECT(full ? alloc3DArray(REALSXP, N, L, p) : R_NilValue);
  double *pw = full ? REAL(warps) : NULL, *pd = full ? REAL(dist) : NULL;
  double *pa = full ? REAL(warped) : NULL;
  if (full)
    for (size_t q = 0; q < (size_t) N * L; q++) pw[q] = 0.0;
  double *ps = REAL(sum);
  int *pc = INTEGER(count);
  for (size_t q = 0; q < (size_t) L * p; q++) ps[q] = 0.0;
  for (int j = 0; j < L; j++) pc[j] = 0;

  for (int k = 0; k < N; k++) {
    /* a batch of thousands of alignments takes seconds: let the user stop it
     * (R_alloc'd workspace is released by R on the jump) */
    if ((k & 63) == 63) R_CheckUserInterrupt();
    SEXP xk = VECTOR_ELT(recs, k);
    int n = nrows(xk);
    const double *x = REAL(xk);
    if (!all_finite(x, (size_t) n * p))
      error("recording %d contains non-finite values", k + 1);
    double d = NA_REAL;
    int len = dtw_core(x, n, yt, L, p, win, &w, &d);
    if (len < 0) error("no warping path exists for recording %d within the window", k + 1);
    if (!full) {
      for (int s = 0; s < len; s++) {
        int i = w.pi[s], j = w.pj[s];
        pc[j]++;
        for (int c = 0; c < p; c++) ps[j + (size_t) L * c] += x[i + (size_t) n * c];
      }
      continue;
    }
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

  const char *names[] = {"sum", "count", "warped", "warps", "distance"};
  const SEXP values[] = {sum, count, warped, warps, dist};
  SEXP out = hm_named_list(5, names, values);
  UNPROTECT(5);
  return out;
}
