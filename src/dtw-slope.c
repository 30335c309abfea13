/* DTW with a slope-constrained step pattern (the fallback for degenerate
 * warps, R/align-slope.R).
 *
 * Symmetric2 DTW (src/dtw.c) may hold one recording frame over any number of
 * template frames; where the template holds still (a rest or a hold plateau)
 * every path costs about the same and the cheapest one runs along the single
 * best-matching frame: a degenerate warp. Sakoe and Chiba's slope constraint
 * (dtw's symmetricP05: local slopes between 1/3 and 3) lets a frame match at
 * most three template frames in a row, whatever the shift.
 *
 * The recursion is the dtw package's for any multi-step pattern given as its
 * table (rows: pattern number, di, dj, weight; the first row of each pattern
 * is its origin, weight -1): for each cell, each pattern's cost is the
 * origin's cumulative cost plus its weighted local distances; the first
 * strictly smallest wins (patterns in table order), unreachable origins
 * (outside the matrix or unreached) never do; g[1,1] = d[1,1]. The path is
 * backtracked with the pattern's intermediate cells, as dtw does, so
 * dtw::dtw(x, y, step.pattern = dtw::symmetricP05) gives the same path.
 * Scratch memory from R_alloc. */

#include <math.h>
#include <R.h>
#include <Rinternals.h>
#include "warp-path.h"

#define MAXSTEP 8

typedef struct {
  int nsteps;           /* steps after the origin */
  int odi, odj;         /* origin offset */
  int di[MAXSTEP], dj[MAXSTEP];
  double w[MAXSTEP];
} pattern_t;

SEXP hm_dtw_pattern(SEXP x, SEXP y, SEXP table) {
  if (!isReal(x) || !isMatrix(x) || !isReal(y) || !isMatrix(y))
    error("'x' and 'template' must be double matrices");
  if (!isReal(table) || !isMatrix(table) || ncols(table) != 4)
    error("'pattern' must be a 4-column double matrix");
  int n = nrows(x), m = nrows(y), p = ncols(x);
  if (ncols(y) != p) error("'x' has %d columns but 'template' has %d", p, ncols(y));
  if (n < 1 || m < 1 || p < 1) error("empty recording or template");
  const double *xv = REAL(x), *yv = REAL(y);
  for (size_t q = 0; q < (size_t) n * p; q++) if (!R_FINITE(xv[q])) error("'x' contains non-finite values");
  for (size_t q = 0; q < (size_t) m * p; q++) if (!R_FINITE(yv[q])) error("'template' contains non-finite values");

  /* the pattern table into patterns */
  int rows = nrows(table);
  const double *tb = REAL(table);
  int npat = 0;
  for (int r = 0; r < rows; r++) if ((int) tb[r] > npat) npat = (int) tb[r];
  pattern_t *pat = (pattern_t *) R_alloc((size_t) npat, sizeof(pattern_t));
  for (int k = 0; k < npat; k++) pat[k].nsteps = -1;
  for (int r = 0; r < rows; r++) {
    int k = (int) tb[r] - 1;
    int di = (int) tb[rows + r], dj = (int) tb[2 * rows + r];
    double w = tb[3 * rows + r];
    if (k < 0) error("bad pattern number");
    if (w == -1.0) {
      pat[k].odi = di; pat[k].odj = dj; pat[k].nsteps = 0;
    } else {
      if (pat[k].nsteps < 0 || pat[k].nsteps >= MAXSTEP) error("bad pattern table");
      pat[k].di[pat[k].nsteps] = di; pat[k].dj[pat[k].nsteps] = dj; pat[k].w[pat[k].nsteps] = w;
      pat[k].nsteps++;
    }
  }
  for (int k = 0; k < npat; k++) if (pat[k].nsteps < 1) error("pattern %d has no steps", k + 1);

  size_t cells = (size_t) n * m;
  double *d = (double *) R_alloc(cells, sizeof(double));
  double *g = (double *) R_alloc(cells, sizeof(double));
  int *sm = (int *) R_alloc(cells, sizeof(int));
  /* column by column, DoF-outer so the inner loop runs over contiguous
   * recording frames (vectorised by the compiler); each cell still sums its
   * DoFs in order from 0, as frame_dist() and proxy::dist do */
  for (int j = 0; j < m; j++) {
    double *dj = d + (size_t) j * n;
    for (int i = 0; i < n; i++) dj[i] = 0.0;
    for (int k = 0; k < p; k++) {
      const double *xk = xv + (size_t) k * n;
      const double yk = yv[(size_t) k * m + j];
      for (int i = 0; i < n; i++) {
        double e = xk[i] - yk;
        dj[i] += e * e;
      }
    }
    for (int i = 0; i < n; i++) dj[i] = sqrt(dj[i]);
  }
  for (int j = 0; j < m; j++) {
    for (int i = 0; i < n; i++) {
      size_t c = (size_t) j * n + i;
      if (i == 0 && j == 0) { g[c] = d[0]; sm[c] = 0; continue; }
      double best = R_PosInf;
      int arg = 0;
      for (int k = 0; k < npat; k++) {
        int oi = i - pat[k].odi, oj = j - pat[k].odj;
        if (oi < 0 || oj < 0) continue;
        double v = g[(size_t) oj * n + oi];
        if (ISNAN(v)) continue;
        for (int s = 0; s < pat[k].nsteps; s++)
          v += pat[k].w[s] * d[(size_t) (j - pat[k].dj[s]) * n + (i - pat[k].di[s])];
        if (v < best) { best = v; arg = k + 1; }
      }
      g[c] = arg ? best : NA_REAL;
      sm[c] = arg;
    }
  }
  double total = g[cells - 1];
  if (ISNAN(total)) error("no warping path exists under the slope constraint");

  /* backtrack: each pattern's intermediate cells, then its origin */
  int cap = n + m + 8;
  int *pi = (int *) R_alloc((size_t) cap, sizeof(int));
  int *pj = (int *) R_alloc((size_t) cap, sizeof(int));
  int i = n - 1, j = m - 1, len = 0;
  pi[len] = i; pj[len] = j; len++;
  while (!(i == 0 && j == 0)) {
    int k = sm[(size_t) j * n + i] - 1;
    if (k < 0) error("broken warping path");
    /* steps are listed from the origin towards the cell; the last is (0, 0) */
    for (int s = pat[k].nsteps - 2; s >= 0; s--) {
      if (len >= cap) error("warping path too long");
      pi[len] = i - pat[k].di[s]; pj[len] = j - pat[k].dj[s]; len++;
    }
    i -= pat[k].odi; j -= pat[k].odj;
    if (len >= cap) error("warping path too long");
    pi[len] = i; pj[len] = j; len++;
  }
  return hm_warp_path(pi, pj, len, 1, total);
}
