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
 * The arithmetic follows the R reference kept in the tests
 * (tests/testthat/helper-generate-reference.R) operation for operation, in
 * the same order, so both give the same numbers up to rounding.
 *
 * Every length and index is checked here as well as in R (validate_sampler()
 * in R/generate.R): a damaged model gives an R error, never a crash. */
#include <R.h>
#include <Rinternals.h>
#include "named-list.h"
#include "real-of-length.h"
#include <Rmath.h>
#include <math.h>
#include <string.h>

/* the name its argument errors begin with */
static const char who[] = "generate kernel";

/* the longest recording one draw may have (R: max_generated_frames) */
#define HM_MAX_GENERATED_FRAMES 100000

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
  if (TYPEOF(smp) != VECSXP || TYPEOF(getAttrib(smp, R_NamesSymbol)) != STRSXP)
    error("generate kernel: a sampler must be a named list");
  m.p = asInteger(list_elt(smp, "p"));
  m.k = asInteger(list_elt(smp, "k"));
  m.d = asInteger(list_elt(smp, "d"));
  if (m.p == NA_INTEGER || m.k == NA_INTEGER || m.d == NA_INTEGER || m.p < 1 || m.k < 1 || m.d < 1)
    error("generate kernel: sampler sizes p, k, d must be positive");
  const R_xlen_t pk = (R_xlen_t) m.p * m.k;
  m.cumw = hm_real_of_length(list_elt(smp, "cumw"), pk, who, "sampler cumw (p x k)");
  m.mu = hm_real_of_length(list_elt(smp, "mu"), pk * m.d, who, "sampler mu (p x k x d)");
  m.root = hm_real_of_length(list_elt(smp, "root"), pk * m.d * m.d, who, "sampler root (p x k x d x d)");
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

/* The smooth limit map of generate(limits = TRUE): the identity inside
 * [lo + m, hi - m], and beyond it an exponential approach to the limit with
 * slope 1 where it starts (continuous first derivative: no kink), so a
 * value never leaves [lo, hi] and values well inside are untouched. */
static double soft_limit(double v, double lo, double hi, double m) {
  if (v > hi - m) return hi - m * exp(-(v - (hi - m)) / m);
  if (v < lo + m) return lo + m * exp((v - (lo + m)) / m);
  return v;
}

SEXP hm_generate_batch(SEXP n_, SEXP dof_smp, SEXP warp_smp, SEXP mean, SEXP comps,
                       SEXP warp_mean, SEXP warp_comps, SEXP do_warp_, SEXP dofs,
                       SEXP alpha_in, SEXP beta_in, SEXP lim_lo, SEXP lim_hi, SEXP margin_) {
  const int n = asInteger(n_), do_warp = asLogical(do_warp_);
  if (n < 0 || n == NA_INTEGER) error("generate kernel: bad batch size");
  if (do_warp == NA_LOGICAL) error("generate kernel: warp must be TRUE or FALSE");
  if (TYPEOF(mean) != REALSXP || !isMatrix(mean)) error("generate kernel: mean must be a double matrix");
  const int L = nrows(mean), p = ncols(mean);
  if (L < 1 || p < 1) error("generate kernel: empty basis");
  if (TYPEOF(dofs) != STRSXP || XLENGTH(dofs) != p) error("generate kernel: dofs must be %d names", p);
  const mixtures md = as_mixtures(dof_smp), mw = as_mixtures(warp_smp);
  const int k = md.d, kw = mw.d;
  if (md.p != p) error("generate kernel: the sampler has %d DoFs, the basis %d", md.p, p);
  if (mw.p != 1) error("generate kernel: the warp sampler must hold one mixture");
  const double *mu = REAL(mean);
  const double *P = hm_real_of_length(comps, (R_xlen_t) L * p * k, who, "basis components (L x p x ncomp)");
  const double *wmu = hm_real_of_length(warp_mean, L, who, "warp mean (L)");
  const double *wP = hm_real_of_length(warp_comps, (R_xlen_t) L * kw, who, "warp components (L x warp_ncomp)");

  SEXP alpha = PROTECT(alloc3DArray(REALSXP, n, p, k));
  SEXP beta = PROTECT(allocMatrix(REALSXP, n, kw));
  SEXP n_new = PROTECT(allocVector(INTSXP, n));
  SEXP recs = PROTECT(allocVector(VECSXP, n));
  double *A = REAL(alpha), *B = REAL(beta);
  int *nn = INTEGER(n_new);

  /* 1. all scores first: the RNG order of the R reference; or the scores
   * drawn in R (the copula model, R/dependence.R) */
  if (alpha_in != R_NilValue || beta_in != R_NilValue) {
    memcpy(A, hm_real_of_length(alpha_in, (R_xlen_t) n * p * k, who, "drawn FPC scores (n x p x ncomp)"),
           sizeof(double) * (size_t) n * p * k);
    memcpy(B, hm_real_of_length(beta_in, (R_xlen_t) n * kw, who, "drawn warp scores (n x warp_ncomp)"),
           sizeof(double) * (size_t) n * kw);
  } else {
    int *comp = (int *) R_alloc((size_t) n * p + 1, sizeof(int));
    GetRNGstate();
    sample_mixtures(md, n, A, comp);
    sample_mixtures(mw, n, B, comp);
    PutRNGstate();
  }
  /* per-DoF limits of the smooth limit map (NA: none) */
  const double *llo = hm_real_of_length(lim_lo, p, who, "lower limits (p)");
  const double *lhi = hm_real_of_length(lim_hi, p, who, "upper limits (p)");
  const double margin = asReal(margin_);
  if (!(margin > 0 && margin < 0.5)) error("generate kernel: the limit margin must be in (0, 0.5)");
  for (int j = 0; j < p; j++)
    if (!ISNAN(llo[j]) && !(lhi[j] > llo[j])) error("generate kernel: limits of DoF %d are empty", j + 1);

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
    if (d % 1024 == 1023) R_CheckUserInterrupt(); /* Ctrl-C reaches long batches */
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
      /* a warp score far outside the data would ask for an absurd length */
      if (!(r <= HM_MAX_GENERATED_FRAMES))
        error("generate kernel: draw %d asks for %.0f frames (at most %d)", d + 1, r,
              HM_MAX_GENERATED_FRAMES);
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
      /* limits on the template curve: the values at original frames are
       * convex combinations of its neighbours, so they stay inside too */
      if (!ISNAN(llo[j]) && !ISNAN(lhi[j])) {
        const double m = margin * (lhi[j] - llo[j]);
        for (int s = 0; s < L; s++) cv[s] = soft_limit(cv[s], llo[j], lhi[j], m);
      }
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
