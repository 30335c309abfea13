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
#include "named-list.h"
#include "real-of-length.h"

/* the name its argument errors begin with */
static const char who[] = "project kernel";

/* What the projection of one DoF needs, once per DoF: its mean curve,
 * phi_c(s) w_s (the scores are plain dot products with it), phi_c(s) nw_s
 * (NULL when the norm weights are the quadrature weights, as in eq. 4.4)
 * and the Gram matrix G_cd = sum_s phi_c(s) phi_d(s) nw_s. */
typedef struct {
  const double *mu, *nw;
  double *pw, *pn, *G;
} dof_basis;

static void fill_basis(dof_basis *b, const double *mu, const double *Pj, const double *w,
                       const double *nw, int same, int L, int p, int k) {
  b->mu = mu;
  b->nw = nw;
  b->pw = (double *) R_alloc((size_t) L * (k > 0 ? k : 1), sizeof(double));
  b->pn = same ? NULL : (double *) R_alloc((size_t) L * (k > 0 ? k : 1), sizeof(double));
  b->G = (double *) R_alloc((size_t) (k > 0 ? k * k : 1), sizeof(double));
  for (int c = 0; c < k; c++) {
    const double *phi = Pj + (R_xlen_t) L * p * c;
    for (int s = 0; s < L; s++) {
      b->pw[s + (R_xlen_t) L * c] = phi[s] * w[s];
      if (!same) b->pn[s + (R_xlen_t) L * c] = phi[s] * nw[s];
    }
    for (int d = 0; d < k; d++) {
      const double *phd = Pj + (R_xlen_t) L * p * d;
      double g = 0;
      for (int s = 0; s < L; s++) g += phi[s] * phd[s] * nw[s];
      b->G[c + k * d] = g;
    }
  }
}

/* The one projection of a curve y (L points on the template grid): its k
 * scores into a, and its residual norm returned; both entry points below
 * come through here. With yc = y - mean, a_c = sum_s yc phi_c w,
 * b_c = sum_s yc phi_c nw (= a_c in eq. 4.4) and r = yc - sum_c a_c phi_c,
 *   sum_s r^2 nw = sum_s yc^2 nw - 2 sum_c a_c b_c + sum_cd a_c a_d G_cd,
 * so one pass over the curve gives scores and norm (a second pass for the
 * residual cost a third of classify()'s time). The subtraction loses digits
 * only when the residual is tiny against the curve, and then only relative
 * to the curve's norm (about 1e-8 of it); the scores are summed in the
 * same order as before. */
static double project_curve(const double *y, const dof_basis *b, int L, int k, double *a, double *bb) {
  const double *mu = b->mu, *nw = b->nw, *pw = b->pw, *pn = b->pn;
  double yy = 0;
  if (k == 2 && !pn) { /* the default: two FPCs, eq. 4.4 */
    const double *q0 = pw, *q1 = pw + L;
    double a0 = 0, a1 = 0;
    for (int s = 0; s < L; s++) {
      const double v = y[s] - mu[s];
      yy += v * v * nw[s];
      a0 += v * q0[s];
      a1 += v * q1[s];
    }
    a[0] = bb[0] = a0;
    a[1] = bb[1] = a1;
  } else {
    for (int c = 0; c < k; c++) a[c] = bb[c] = 0;
    for (int s = 0; s < L; s++) {
      const double v = y[s] - mu[s];
      yy += v * v * nw[s];
      for (int c = 0; c < k; c++) {
        a[c] += v * pw[s + (R_xlen_t) L * c];
        if (pn) bb[c] += v * pn[s + (R_xlen_t) L * c];
      }
    }
    if (!pn) for (int c = 0; c < k; c++) bb[c] = a[c];
  }
  double ss = yy;
  for (int c = 0; c < k; c++) {
    ss -= 2 * a[c] * bb[c];
    for (int d = 0; d < k; d++) ss += a[c] * a[d] * b->G[c + k * d];
  }
  return sqrt(ss > 0 ? ss : 0);
}

static int same_weights(const double *w, const double *nw, R_xlen_t len) {
  for (R_xlen_t q = 0; q < len; q++)
    if (w[q] != nw[q]) return 0;
  return 1;
}

/* The model's template as both entry points take it: mean L x p, comps
 * L x p x k, weights and norm weights L x p. Checks them against the p DoFs
 * and gives L (template points) and k (components). */
static void template_dims(SEXP mean, SEXP comps, SEXP weights, SEXP norm_weights, int p,
                          int *L_out, int *k_out) {
  SEXP mdim = getAttrib(mean, R_DimSymbol);
  if (TYPEOF(mdim) != INTSXP || XLENGTH(mdim) != 2 || INTEGER(mdim)[1] != p)
    error("project kernel: mean must be an L x p matrix");
  const int L = INTEGER(mdim)[0];
  if (L < 1) error("project kernel: the template has no points");
  hm_real_of_length(mean, (R_xlen_t) L * p, who, "mean (L x p)");
  hm_real_of_length(weights, (R_xlen_t) L * p, who, "weights (L x p)");
  hm_real_of_length(norm_weights, (R_xlen_t) L * p, who, "norm weights (L x p)");
  if (TYPEOF(comps) != REALSXP || XLENGTH(comps) % ((R_xlen_t) L * p) != 0)
    error("project kernel: comps must be an L x p x k double array");
  const int k = (int) (XLENGTH(comps) / ((R_xlen_t) L * p));
  *L_out = L;
  *k_out = k;
}

SEXP hm_project_batch(SEXP values, SEXP rows, SEXP nxt, SEXP frac, SEXP mean, SEXP comps,
                      SEXP weights, SEXP norm_weights) {
  SEXP dim = getAttrib(values, R_DimSymbol);
  if (TYPEOF(values) != REALSXP || TYPEOF(dim) != INTSXP || XLENGTH(dim) != 2)
    error("project kernel: values must be a double matrix");
  const R_xlen_t N = INTEGER(dim)[0];
  const int p = INTEGER(dim)[1];
  int L, k;
  template_dims(mean, comps, weights, norm_weights, p, &L, &k);
  const R_xlen_t Ln = XLENGTH(rows);
  if (TYPEOF(rows) != INTSXP || TYPEOF(nxt) != INTSXP || XLENGTH(nxt) != Ln || Ln % L != 0)
    error("project kernel: rows and nxt must be integer vectors of L x n indices");
  const R_xlen_t n = Ln / L;
  hm_real_of_length(frac, Ln, who, "f");
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
  double *a = (double *) R_alloc(k > 0 ? k : 1, sizeof(double));
  double *bb = (double *) R_alloc(k > 0 ? k : 1, sizeof(double));
  const int same = same_weights(W, NW, (R_xlen_t) L * p);

  for (int j = 0; j < p; j++) {
    const double *v = V + N * j;
    dof_basis b;
    fill_basis(&b, M + (R_xlen_t) L * j, P + (R_xlen_t) L * j, W + (R_xlen_t) L * j,
               NW + (R_xlen_t) L * j, same, L, p, k);
    for (R_xlen_t i = 0; i < n; i++) {
      if ((i & 4095) == 4095) R_CheckUserInterrupt();
      const R_xlen_t o = (R_xlen_t) L * i;
      for (int s = 0; s < L; s++) {
        const double g = F[o + s];
        y[s] = v[ri[o + s] - 1] * (1 - g) + v[ni[o + s] - 1] * g;
      }
      R[i + n * j] = project_curve(y, &b, L, k, a, bb);
      for (int c = 0; c < k; c++) S[i + n * (j + (R_xlen_t) p * c)] = a[c];
    }
  }
  const char *out_names[] = {"scores", "residual"};
  const SEXP out_values[] = {scores, resid};
  SEXP out = hm_named_list(2, out_names, out_values);
  UNPROTECT(2);
  return out;
}

/* Recordings projected straight from the grasps object's list (no stacked
 * copy, no precomputed warp index: the stacked index arrays were 16 bytes
 * per template point and model, re-read for every DoF, and building them in
 * R took longer than the projection). recs: list of double matrices
 * (frames x all DoFs); cols: the model's DoFs as 1-based columns of them; u:
 * the model's mean warp on its template grid, normalised to [0, 1]. For
 * template point s of a recording of m frames the position is
 * t = 1 + u_s (m - 1), read between frames floor(t) (at most m - 1) and the
 * next (at most m), as warp_index() in R/project.R had it.
 * mode 0: the distance only (sqrt of the sum over DoFs of the squared
 * residual norms); 1: also scores (n x p x k) and residual norms (n x p);
 * 2: also the warped curves ((L n) x p, entry s + L i). */
SEXP hm_project_warped(SEXP recs, SEXP cols, SEXP u, SEXP mean, SEXP comps, SEXP weights,
                       SEXP norm_weights, SEXP mode_) {
  if (TYPEOF(recs) != VECSXP) error("project kernel: recs must be a list of matrices");
  const R_xlen_t n = XLENGTH(recs);
  if (TYPEOF(cols) != INTSXP) error("project kernel: cols must be integer column numbers");
  const int p = (int) XLENGTH(cols);
  const int *cj = INTEGER(cols);
  int L, k;
  template_dims(mean, comps, weights, norm_weights, p, &L, &k);
  hm_real_of_length(u, L, who, "u");
  const int mode = asInteger(mode_);
  if (mode < 0 || mode > 2) error("project kernel: mode must be 0, 1 or 2");
  /* every recording checked before any work */
  for (R_xlen_t i = 0; i < n; i++) {
    SEXP r = VECTOR_ELT(recs, i);
    SEXP d = getAttrib(r, R_DimSymbol);
    if (TYPEOF(r) != REALSXP || TYPEOF(d) != INTSXP || XLENGTH(d) != 2 || INTEGER(d)[0] < 1)
      error("project kernel: recording %lld is not a double matrix with frames", (long long) i + 1);
    for (int j = 0; j < p; j++)
      if (cj[j] < 1 || cj[j] > INTEGER(d)[1])
        error("project kernel: column %d is not one of recording %lld's", cj[j], (long long) i + 1);
  }
  const double *U = REAL(u), *M = REAL(mean), *P = REAL(comps);
  const double *W = REAL(weights), *NW = REAL(norm_weights);

  SEXP dist = PROTECT(allocVector(REALSXP, n));
  SEXP scores = PROTECT(allocVector(REALSXP, mode >= 1 ? n * p * (R_xlen_t) k : 0));
  SEXP resid = PROTECT(allocVector(REALSXP, mode >= 1 ? n * p : 0));
  SEXP warped = PROTECT(allocMatrix(REALSXP, mode == 2 ? (int) (n * L) : 0, mode == 2 ? p : 0));
  double *D = REAL(dist), *S = REAL(scores), *R = REAL(resid), *Wp = REAL(warped);
  double *y = (double *) R_alloc(L, sizeof(double));
  double *fr = (double *) R_alloc(L, sizeof(double));
  int *lo = (int *) R_alloc(L, sizeof(int)), *hi = (int *) R_alloc(L, sizeof(int));
  double *a = (double *) R_alloc(k > 0 ? k : 1, sizeof(double));
  double *bb = (double *) R_alloc(k > 0 ? k : 1, sizeof(double));
  const int same = same_weights(W, NW, (R_xlen_t) L * p);
  dof_basis *basis = (dof_basis *) R_alloc(p > 0 ? p : 1, sizeof(dof_basis));
  for (int j = 0; j < p; j++)
    fill_basis(basis + j, M + (R_xlen_t) L * j, P + (R_xlen_t) L * j, W + (R_xlen_t) L * j,
               NW + (R_xlen_t) L * j, same, L, p, k);

  for (R_xlen_t i = 0; i < n; i++) {
    if ((i & 255) == 255) R_CheckUserInterrupt();
    SEXP r = VECTOR_ELT(recs, i);
    const int m = INTEGER(getAttrib(r, R_DimSymbol))[0];
    const double *V = REAL(r);
    const int cap = m - 1 > 1 ? m - 1 : 1;
    for (int s = 0; s < L; s++) {
      const double t = 1 + U[s] * (double) (m - 1);
      double fl = floor(t);
      if (fl > cap) fl = cap;
      fr[s] = m == 1 ? 0 : t - fl;
      lo[s] = (int) fl - 1;
      hi[s] = (int) fl < m - 1 ? (int) fl : m - 1;
    }
    long double acc = 0;
    for (int j = 0; j < p; j++) {
      const double *v = V + (R_xlen_t) m * (cj[j] - 1);
      for (int s = 0; s < L; s++) y[s] = v[lo[s]] * (1 - fr[s]) + v[hi[s]] * fr[s];
      if (mode == 2)
        for (int s = 0; s < L; s++) Wp[(R_xlen_t) L * i + s + (R_xlen_t) L * n * j] = y[s];
      const double res = project_curve(y, basis + j, L, k, a, bb);
      acc += res * res;
      if (mode >= 1) {
        R[i + n * j] = res;
        for (int c = 0; c < k; c++) S[i + n * (j + (R_xlen_t) p * c)] = a[c];
      }
    }
    D[i] = sqrt((double) acc);
  }
  const char *names[] = {"distance", "scores", "residual", "warped"};
  const SEXP values[] = {dist, scores, resid, warped};
  SEXP out = hm_named_list(4, names, values);
  UNPROTECT(4);
  return out;
}
