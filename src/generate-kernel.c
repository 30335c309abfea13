/* Batch generation kernel for generate() (R/generate.R), eq. 2.5 of
 * Jeppsson (2017) for a whole batch of draws from one grasp model in one
 * native pass:
 *   1. FPC scores alpha (n x p x ncomp) and warp scores beta (n x warp_ncomp)
 *      from the stacked Gaussian mixtures (build_sampler() in R), drawing
 *      from R's RNG in exactly the order of the R reference sample_scores():
 *      runif(n p), rnorm(n p ncomp), runif(n), rnorm(n warp_ncomp);
 *   2. per draw, the warping function w (monotone, w(1) = 1) and the frame
 *      count max(2, round(w(L)));
 *   3. per draw, the curves on the template grid (mean + components x alpha)
 *      and their values at original frames t = 1..n_new, interpolated at the
 *      template time where w reaches t.
 * Returns list(recordings, n_frames, beta, alpha); the recordings are
 * n_new x p matrices with colnames `dofs`, ready for new_grasps().
 *
 * The arithmetic follows the R reference (kernel = "r") operation for
 * operation, in the same order, so both paths give the same numbers
 * (bit for bit with R's reference BLAS, which sums matrix products in the
 * same order as the loops below). */
#include <R.h>
#include <Rinternals.h>
#include "named-list.h"
#include <Rmath.h>
#include <math.h>
#include <string.h>

/* one stacked mixture set: p mixtures of k components in d dimensions */
typedef struct {
  int p, k, d;
  const double *cumw; /* p x k cumulative weights */
  const double *mu;   /* p x k x d means */
  const double *root; /* p x k x d x d symmetric roots of the covariances */
} mixtures;

static SEXP list_elt(SEXP list, const char *name) {
  SEXP nms = getAttrib(list, R_NamesSymbol);
  for (R_xlen_t i = 0; i < XLENGTH(list); i++) {
    if (strcmp(CHAR(STRING_ELT(nms, i)), name) == 0) return VECTOR_ELT(list, i);
  }
  error("generate kernel: sampler element '%s' missing", name);
  return R_NilValue; /* not reached */
}

static mixtures as_mixtures(SEXP smp) {
  mixtures m;
  m.p = asInteger(list_elt(smp, "p"));
  m.k = asInteger(list_elt(smp, "k"));
  m.d = asInteger(list_elt(smp, "d"));
  m.cumw = REAL(list_elt(smp, "cumw"));
  m.mu = REAL(list_elt(smp, "mu"));
  m.root = REAL(list_elt(smp, "root"));
  return m;
}

/* stats::runif(1) and stats::rnorm(1) draw by draw (same rejection and the
 * same `a + (b - a) u`, `mu + sigma z` arithmetic, so the same numbers) */
static double runif01(void) {
  double u;
  do { u = unif_rand(); } while (u <= 0 || u >= 1);
  return 0.0 + 1.0 * u;
}

static double rnorm01(void) { return 0.0 + 1.0 * norm_rand(); }

/* n draws from each of the p mixtures into out (n x p x d): the component of
 * draw (i, j) from one uniform, then mean + root %*% z, with the standard
 * normals z generated dimension by dimension as in the R reference, whose
 * Z matrix is (n p) x d filled column-major. */
static void sample_mixtures(mixtures m, int n, double *out, int *comp) {
  const R_xlen_t np = (R_xlen_t) n * m.p, pk = (R_xlen_t) m.p * m.k;
  for (R_xlen_t r = 0; r < np; r++) {
    const int j = (int) (r / n);
    const double u = runif01();
    int c = 0;
    for (int cc = 0; cc < m.k - 1; cc++) c += (u > m.cumw[j + (R_xlen_t) m.p * cc]);
    comp[r] = c;
  }
  for (int a = 0; a < m.d; a++) {
    for (R_xlen_t r = 0; r < np; r++) {
      const int j = (int) (r / n);
      out[r + np * a] = m.mu[j + (R_xlen_t) m.p * comp[r] + pk * a];
    }
  }
  for (int b = 0; b < m.d; b++) {
    for (R_xlen_t r = 0; r < np; r++) {
      const double z = rnorm01();
      const R_xlen_t base = (r / n) + (R_xlen_t) m.p * comp[r];
      for (int a = 0; a < m.d; a++) {
        out[r + np * a] = out[r + np * a] + m.root[base + pk * a + pk * m.d * b] * z;
      }
    }
  }
}

SEXP hm_generate_batch(SEXP n_, SEXP dof_smp, SEXP warp_smp, SEXP mean, SEXP comps,
                       SEXP warp_mean, SEXP warp_comps, SEXP do_warp_, SEXP dofs) {
  const int n = asInteger(n_), do_warp = asLogical(do_warp_);
  const int L = nrows(mean), p = ncols(mean);
  const mixtures md = as_mixtures(dof_smp), mw = as_mixtures(warp_smp);
  const int k = md.d, kw = mw.d;
  if (n < 0 || n == NA_INTEGER) error("generate kernel: bad batch size");
  if (md.p != p || XLENGTH(comps) != (R_xlen_t) L * p * k)
    error("generate kernel: basis (%d x %d x %d) does not match the sampler", L, p, k);
  if (mw.p != 1 || XLENGTH(warp_mean) != L || XLENGTH(warp_comps) != (R_xlen_t) L * kw)
    error("generate kernel: warp basis does not match the sampler");
  const double *mu = REAL(mean), *P = REAL(comps), *wmu = REAL(warp_mean), *wP = REAL(warp_comps);

  SEXP alpha = PROTECT(alloc3DArray(REALSXP, n, p, k));
  SEXP beta = PROTECT(allocMatrix(REALSXP, n, kw));
  SEXP n_new = PROTECT(allocVector(INTSXP, n));
  SEXP recs = PROTECT(allocVector(VECSXP, n));
  double *A = REAL(alpha), *B = REAL(beta);
  int *nn = INTEGER(n_new);

  /* 1. all scores first: the RNG order of the R reference */
  int *comp = (int *) R_alloc((size_t) n * p + 1, sizeof(int));
  GetRNGstate();
  sample_mixtures(md, n, A, comp);
  sample_mixtures(mw, n, B, comp);
  PutRNGstate();

  /* one shared, immutable dimnames list(NULL, dofs) for every matrix */
  SEXP dn = PROTECT(allocVector(VECSXP, 2));
  SET_VECTOR_ELT(dn, 1, dofs);
  MARK_NOT_MUTABLE(dn);

  double *w = (double *) R_alloc((size_t) L, sizeof(double));
  double *curve = (double *) R_alloc((size_t) L * p, sizeof(double));
  int *lo = NULL;
  double *f = NULL;
  R_xlen_t cap = 0; /* capacity of lo / f, grown to the longest draw */

  for (int d = 0; d < n; d++) {
    /* 2. warp: mean + beta %*% t(components), floored at frame 1, starting
     * at 1, made monotone by a running maximum */
    int m = L;
    if (do_warp) {
      for (int s = 0; s < L; s++) {
        double v = 0;
        for (int c = 0; c < kw; c++) v = v + wP[s + (R_xlen_t) L * c] * B[d + (R_xlen_t) n * c];
        v = wmu[s] + v;
        w[s] = (v < 1) ? 1 : v;
      }
      w[0] = 1;
      for (int s = 1; s < L; s++) if (w[s - 1] > w[s]) w[s] = w[s - 1];
      const double r = nearbyint(w[L - 1]); /* R's round(): half to even */
      m = (r < 2) ? 2 : (int) r;
    }
    nn[d] = m;

    /* 3a. curves on the template grid, summed as BLAS does P %*% t(alpha) */
    for (int j = 0; j < p; j++) {
      double *cv = curve + (R_xlen_t) L * j;
      for (int s = 0; s < L; s++) cv[s] = 0;
      for (int c = 0; c < k; c++) {
        const double a = A[d + (R_xlen_t) n * (j + (R_xlen_t) p * c)];
        const double *Pc = P + (R_xlen_t) L * (j + (R_xlen_t) p * c);
        for (int s = 0; s < L; s++) cv[s] = cv[s] + Pc[s] * a;
      }
      const double *mj = mu + (R_xlen_t) L * j;
      for (int s = 0; s < L; s++) cv[s] = cv[s] + mj[s];
    }

    SEXP rec = PROTECT(allocMatrix(REALSXP, m, p));
    double *out = REAL(rec);
    if (!do_warp) {
      memcpy(out, curve, sizeof(double) * (size_t) L * p);
    } else {
      /* 3b. template interval and weight of every original frame: the last
       * template frame j with w(j) <= t, clamped to 1..L-1; past w(L) the
       * last frame's value; a flat interval takes its left end */
      if (m > cap) {
        cap = 2 * (R_xlen_t) m;
        lo = (int *) R_alloc((size_t) cap, sizeof(int));
        f = (double *) R_alloc((size_t) cap, sizeof(double));
      }
      int j = 0; /* 0-based: last s with w[s] <= t */
      for (int t = 1; t <= m; t++) {
        while (j + 1 < L && w[j + 1] <= t) j++;
        if (L == 1) {
          lo[t - 1] = 0; f[t - 1] = 0;
        } else if (j >= L - 1) {
          lo[t - 1] = L - 2; f[t - 1] = 1;
        } else {
          const double a = w[j], b = w[j + 1], span = b - a;
          double ft = (span > 0) ? (t - a) / span : 0;
          if (ft < 0) ft = 0;
          if (ft > 1) ft = 1;
          lo[t - 1] = j; f[t - 1] = ft;
        }
      }
      const int step = (L == 1) ? 0 : 1;
      for (int jj = 0; jj < p; jj++) {
        const double *cv = curve + (R_xlen_t) L * jj;
        double *o = out + (R_xlen_t) m * jj;
        for (int t = 0; t < m; t++) o[t] = cv[lo[t]] * (1 - f[t]) + cv[lo[t] + step] * f[t];
      }
    }
    setAttrib(rec, R_DimNamesSymbol, dn);
    SET_VECTOR_ELT(recs, d, rec);
    UNPROTECT(1);
  }

  const char *names[] = {"recordings", "n_frames", "beta", "alpha"};
  const SEXP values[] = {recs, n_new, beta, alpha};
  SEXP res = hm_named_list(4, names, values);
  UNPROTECT(5);
  return res;
}

/* Pre-size R's vector heap for a batch of about `bytes` bytes: allocate an
 * uninitialised raw vector of that size (its pages are never touched, so it
 * costs address space, not memory) and drop it at once. The allocation makes
 * R's collector grow the heap trigger to fit the batch in one step; without
 * it the trigger grows about a fifth per collection, so a large batch runs
 * several full collections, each re-marking the whole session, and batches
 * in a loop outlive the young generation. The block itself is reclaimed by
 * the next (young-generation) collection. See generate_reserve() in R. */
SEXP hm_reserve_heap(SEXP bytes) {
  const double b = asReal(bytes);
  if (R_FINITE(b) && b >= 1) allocVector(RAWSXP, (R_xlen_t) b);
  return R_NilValue;
}
