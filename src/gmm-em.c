/* Compiled EM for the fast Gaussian-mixture engine (R/gmm.R), for d = 1 and
 * d = 2 (the thesis' warp scores and FPC score pairs).
 *
 * It reproduces the R implementation gmm_em_batch_r() step for step, so the
 * two give the same fits (log-likelihoods equal to rounding): the same
 * monomial design (1, y_a, y_a y_b), the same M-step formulas from the
 * sufficient statistics, the same E-step (for k = 2 the log-likelihood as
 * psum . C1 + sum log1p(exp(neg)), with R's plogis formulation when exp
 * overflows in any running start; otherwise a log-sum-exp), the same
 * stopping rule (an iteration raising the log-likelihood by less than tol;
 * gmm_em_fast() passes n times its per-observation tolerance),
 * the same failure tests (weight below 1/n, covariance determinant below the
 * floor, non-finite log-likelihood) and the same merging of starts that have
 * come together (checked every 10 iterations). The starts run in lock step,
 * as the columns of the R version's matrices do, because the overflow switch
 * and the merge test look at all running starts at once.
 *
 * What differs is rounding only, for speed: the k = 2 E-step is one pass
 * over the points fused with the next M-step's sums; sum log1p(exp(neg)) is
 * the log of a running product. Plain C with libm's exp(): log-likelihoods
 * agree with the R version to about 1e-11 (tests/testthat/test-gmm.R).
 * Sums over points are plain double sums in point order.
 *
 * Entry points:
 *   hm_gmm_em(P, labels, k, max_iter, tol, logdet0)
 *     P: n x nm monomials of the standardised data (nm = 3 for d = 1, 6 for
 *     d = 2); labels: n x S integer starting partitions (1..k).
 *     Returns list(status, iterations, converged, loglik, bad, weights, mu,
 *     sigma): status 0 = stopped with parameters (converged or at max_iter),
 *     1 = failed (bad = first degenerate component, 0 = non-finite
 *     log-likelihood), 2 = merged into an earlier start.
 *   hm_gmm_kmeans(Y, centres, iters)
 *     Lloyd iterations as gmm_kmeans() in R, for a list of starting centre
 *     matrices; returns an n x S integer matrix of labels.
 * Scratch memory comes from R_alloc. */
#include <math.h>
#include <R.h>
#include <Rinternals.h>
#include "named-list.h"

#define ST_DONE 0
#define ST_FAILED 1
#define ST_MERGED 2
#define ST_RUNNING -1

#ifndef M_LN_2PI
#define M_LN_2PI 1.837877066409345483560659472811
#endif

/* R's log1pexp() (nmath), as used by plogis(log.p = TRUE) */
static double hm_log1pexp(double x) {
  if (x <= 18.) return log1p(exp(x));
  if (x > 33.3) return x;
  return x + exp(-x);
}

/* M-step of one component from its sufficient statistics s[0..nm-1]
 * (sums of the monomials weighted by the responsibilities): fills the
 * log-density coefficients C[0..nm-1], the constant, the parameters, and
 * returns 1 when the component is degenerate. Formulas as gmm_mstep(). */
static int mstep_one(int d, const double *s, int n, double floor_logdet, double *C,
                     double *cnst, double *w, double *mu, double *sig) {
  double nk = s[0], logdet;
  if (d == 1) {
    double m = s[1] / nk;
    double v = s[2] / nk - m * m;
    logdet = log(v > 0 ? v : 0); /* log(pmax(v, 0)); NaN stays NaN */
    if (ISNAN(v)) logdet = v;
    C[0] = -0.5 * (m * m) / v;
    C[1] = m / v;
    C[2] = -0.5 / v;
    mu[0] = m;
    sig[0] = v;
  } else {
    double m1 = s[1] / nk, m2 = s[2] / nk;
    double s11 = s[3] / nk - m1 * m1;
    double s12 = s[4] / nk - m1 * m2;
    double s22 = s[5] / nk - m2 * m2;
    double det = s11 * s22 - s12 * s12;
    logdet = ISNAN(det) ? det : log(det > 0 ? det : 0);
    if (!(s11 > 0)) logdet = R_NegInf;
    double a11 = s22 / det, a12 = -s12 / det, a22 = s11 / det;
    double am1 = a11 * m1 + a12 * m2;
    double am2 = a12 * m1 + a22 * m2;
    C[0] = -0.5 * (m1 * am1 + m2 * am2);
    C[1] = am1;
    C[2] = am2;
    C[3] = -0.5 * a11;
    C[4] = -a12;
    C[5] = -0.5 * a22;
    mu[0] = m1;
    mu[1] = m2;
    sig[0] = s11;
    sig[1] = s12;
    sig[2] = s12;
    sig[3] = s22;
  }
  *w = nk / n;
  *cnst = log(nk / n) - 0.5 * d * M_LN_2PI - 0.5 * logdet;
  return !(nk >= 1) || !(logdet >= floor_logdet);
}

/* Do starts a and b sit within 1e-2 of each other (weights, means,
 * covariances, components matched by their order along the first mean
 * coordinate)? A NaN anywhere means no. */
static int starts_close(int k, int d, const double *wa, const double *mua, const double *sa,
                        const double *wb, const double *mub, const double *sb, int *oa, int *ob) {
  /* stable order of components by first mean coordinate (insertion sort) */
  int *ord[2] = {oa, ob};
  const double *mus[2] = {mua, mub};
  for (int t = 0; t < 2; t++) {
    int *o = ord[t];
    const double *mu = mus[t];
    for (int j = 0; j < k; j++) o[j] = j;
    for (int j = 1; j < k; j++) {
      int v = o[j], q = j - 1;
      while (q >= 0 && mu[(size_t) o[q] * d] > mu[(size_t) v * d]) {
        o[q + 1] = o[q];
        q--;
      }
      o[q + 1] = v;
    }
  }
  for (int j = 0; j < k; j++)
    if (!(fabs(wa[oa[j]] - wb[ob[j]]) < 1e-2)) return 0;
  for (int j = 0; j < k; j++)
    for (int c = 0; c < d; c++)
      if (!(fabs(mua[(size_t) oa[j] * d + c] - mub[(size_t) ob[j] * d + c]) < 1e-2)) return 0;
  for (int j = 0; j < k; j++)
    for (int c = 0; c < d * d; c++)
      if (!(fabs(sa[(size_t) oa[j] * d * d + c] - sb[(size_t) ob[j] * d * d + c]) < 1e-2))
        return 0;
  return 1;
}

/* One pass of the two-component E-step over the points, fused with the
 * sufficient statistics of the next M-step: for each point the log-ratio
 * neg = log(w2 f2) - log(w1 f1) = Pt_i . D (summed from the intercept on,
 * as BLAS does), e = exp(neg), the first component's responsibility
 * z = 1 / (1 + e) (R's 1 / (1 + E) and plogis(neg, lower.tail = FALSE)
 * alike), and s_next[m] += Pt_im z in point order (crossprod(P, Z)).
 * Returns sum_i log1p(e_i), computed as the log of a running product of the
 * (1 + e_i) -- one multiplication a point instead of a log1p, flushed to the
 * sum of logs before it can overflow -- and sets *inf when some e_i
 * overflowed. Pt is point-major (nm values per point); inlined with nm = 3
 * and nm = 6 so the inner loops unroll. */
static inline double estep2(const double *Pt, int n, const int nm, const double *D,
                            double *s_next, int *inf) {
  double s[6] = {0, 0, 0, 0, 0, 0};
  double prod = 1.0, logs = 0.0;
  int hit = 0;
  for (int i = 0; i < n; i++) {
    const double *pi = Pt + (size_t) i * nm;
    double v = 0.0;
    for (int m = 0; m < nm; m++) v += pi[m] * D[m];
    double e = exp(v);
    double z = 1.0 / (1.0 + e);
    for (int m = 0; m < nm; m++) s[m] += pi[m] * z;
    if (e < 1e100) {
      prod *= 1.0 + e;
      if (prod > 1e200) {
        logs += log(prod);
        prod = 1.0;
      }
    } else {
      if (e == R_PosInf) hit = 1;
      logs += log1p(e);
    }
  }
  for (int m = 0; m < nm; m++) s_next[m] = s[m];
  *inf = hit;
  return logs + log(prod);
}

/* The E-step pass of one start (inlined with nm = 3 and nm = 6 so the
 * compiler unrolls and vectorises the inner loops). */
static double estep2_any(const double *Pt, int n, int nm, const double *D, double *s_next,
                         int *inf) {
  return nm == 3 ? estep2(Pt, n, 3, D, s_next, inf) : estep2(Pt, n, 6, D, s_next, inf);
}

/* R's overflow-safe alternative: sum_i log1pexp(-neg_i), i.e.
 * -sum(plogis(neg, log.p = TRUE)). */
static double estep2_plogis(const double *Pt, int n, int nm, const double *D) {
  double acc = 0;
  for (int i = 0; i < n; i++) {
    const double *pi = Pt + (size_t) i * nm;
    double v = 0.0;
    for (int m = 0; m < nm; m++) v += pi[m] * D[m];
    acc += hm_log1pexp(-v);
  }
  return (double) acc;
}

SEXP hm_gmm_em(SEXP P_, SEXP labels_, SEXP k_, SEXP max_iter_, SEXP tol_, SEXP logdet0_) {
  if (!isReal(P_) || !isMatrix(P_)) error("'P' must be a double matrix");
  if (!isInteger(labels_) || !isMatrix(labels_)) error("'labels' must be an integer matrix");
  const int n = nrows(P_), nm = ncols(P_), S = ncols(labels_);
  const int k = asInteger(k_), max_iter = asInteger(max_iter_);
  const double tol = asReal(tol_), logdet0 = asReal(logdet0_);
  int d;
  if (nm == 3) d = 1;
  else if (nm == 6) d = 2;
  else error("the compiled EM handles d = 1 and d = 2 only (got %d monomials)", nm);
  if (nrows(labels_) != n) error("'labels' must have one row per point");
  if (k < 1 || S < 1 || max_iter < 1) error("'k', the number of starts and 'max_iter' must be positive");
  const double *P = REAL(P_);
  const int *lab = INTEGER(labels_);
  const double floor_logdet = logdet0 + log(1e-8); /* gmm_det_floor */
  const int two = (k == 2);

  /* column sums of the monomials */
  double *psum = (double *) R_alloc(nm, sizeof(double));
  for (int m = 0; m < nm; m++) {
    double acc = 0;
    for (int i = 0; i < n; i++) acc += P[(size_t) m * n + i];
    psum[m] = (double) acc;
  }

  /* k = 2 keeps per start only the first component's statistics (the
   * second's are psum minus them) and the E-step's log-ratio coefficients;
   * other k keep the responsibilities */
  double *Pt = (double *) R_alloc((size_t) n * nm, sizeof(double)); /* point-major P */
  for (int i = 0; i < n; i++)
    for (int m = 0; m < nm; m++) Pt[(size_t) i * nm + m] = P[(size_t) m * n + i];
  double *Z = two ? NULL : (double *) R_alloc((size_t) n * k * S, sizeof(double));
  double *S1 = (double *) R_alloc((size_t) nm * S, sizeof(double));
  double *Dc = (double *) R_alloc((size_t) nm * S, sizeof(double));
  int *inf_hit = (int *) R_alloc(S, sizeof(int));
  double *Lw = (double *) R_alloc((size_t) n * k, sizeof(double)); /* general k */
  double *stats = (double *) R_alloc((size_t) nm * k, sizeof(double));
  double *C = (double *) R_alloc((size_t) nm * k * S, sizeof(double));
  double *cn = (double *) R_alloc((size_t) k * S, sizeof(double));
  int *bad = (int *) R_alloc((size_t) k * S, sizeof(int));
  double *llv = (double *) R_alloc(S, sizeof(double));
  double *ll_new = (double *) R_alloc(S, sizeof(double));
  int *failed = (int *) R_alloc(S, sizeof(int));
  int *stop_now = (int *) R_alloc(S, sizeof(int));
  int *conv_now = (int *) R_alloc(S, sizeof(int));
  int *oa = (int *) R_alloc(k, sizeof(int));
  int *ob = (int *) R_alloc(k, sizeof(int));
  int *merged = (int *) R_alloc(S, sizeof(int));
  int *act = (int *) R_alloc(S, sizeof(int));

  SEXP status = PROTECT(allocVector(INTSXP, S));
  SEXP iters = PROTECT(allocVector(INTSXP, S));
  SEXP conv = PROTECT(allocVector(LGLSXP, S));
  SEXP loglik = PROTECT(allocVector(REALSXP, S));
  SEXP badc = PROTECT(allocVector(INTSXP, S));
  SEXP W = PROTECT(allocMatrix(REALSXP, k, S));
  SEXP MU = PROTECT(allocVector(REALSXP, (R_xlen_t) d * k * S));
  SEXP SG = PROTECT(allocVector(REALSXP, (R_xlen_t) d * d * k * S));
  int *pst = INTEGER(status), *pit = INTEGER(iters), *pcv = LOGICAL(conv), *pbad = INTEGER(badc);
  double *pll = REAL(loglik), *pw = REAL(W), *pmu = REAL(MU), *psg = REAL(SG);

  for (int a = 0; a < S; a++) {
    pst[a] = ST_RUNNING;
    pit[a] = 0;
    pcv[a] = FALSE;
    pll[a] = NA_REAL;
    pbad[a] = NA_INTEGER;
    llv[a] = R_NegInf;
    act[a] = a;
    for (int i = 0; i < n; i++) {
      int l = lab[(size_t) a * n + i];
      if (l < 1 || l > k) error("start %d has label %d outside 1..%d", a + 1, l, k);
    }
    if (two) {
      double *s1 = S1 + (size_t) nm * a;
      for (int m = 0; m < nm; m++) {
        double acc = 0.0;
        for (int i = 0; i < n; i++)
          acc += P[(size_t) m * n + i] * (lab[(size_t) a * n + i] == 1 ? 1.0 : 0.0);
        s1[m] = acc;
      }
    } else {
      double *za = Z + (size_t) n * k * a;
      for (int i = 0; i < n; i++)
        for (int j = 0; j < k; j++)
          za[(size_t) j * n + i] = (lab[(size_t) a * n + i] == j + 1) ? 1.0 : 0.0;
    }
  }

  int A = S, it = 0;
  while (A > 0 && it < max_iter) {
    it++;
    if (it % 64 == 0) R_CheckUserInterrupt();
    /* M-step of every running start; its parameters go straight into the
     * output slots (a start's slots are final once it stops) */
    for (int q = 0; q < A; q++) {
      int a = act[q];
      if (two) {
        const double *s1 = S1 + (size_t) nm * a;
        for (int m = 0; m < nm; m++) {
          stats[m] = s1[m];
          stats[nm + m] = psum[m] - s1[m];
        }
      } else {
        const double *za = Z + (size_t) n * k * a;
        for (int j = 0; j < k; j++)
          for (int m = 0; m < nm; m++) {
            const double *pm = P + (size_t) m * n;
            const double *zj = za + (size_t) j * n;
            double acc = 0.0;
            for (int i = 0; i < n; i++) acc += pm[i] * zj[i];
            stats[(size_t) j * nm + m] = acc;
          }
      }
      failed[q] = 0;
      for (int j = 0; j < k; j++) {
        int b = mstep_one(d, stats + (size_t) j * nm, n, floor_logdet,
                          C + ((size_t) a * k + j) * nm, cn + (size_t) a * k + j,
                          pw + (size_t) a * k + j, pmu + ((size_t) a * k + j) * d,
                          psg + ((size_t) a * k + j) * d * d);
        bad[(size_t) a * k + j] = b;
        if (b) failed[q] = 1;
      }
    }

    /* E-step */
    if (two) {
      int overflow = 0;
      for (int q = 0; q < A; q++) {
        if (failed[q]) { /* leaves the batch: no E-step */
          ll_new[q] = NA_REAL;
          continue;
        }
        int a = act[q];
        double *Ca = C + (size_t) a * k * nm;
        Ca[0] += cn[(size_t) a * k];         /* constants folded into the intercept */
        Ca[nm] += cn[(size_t) a * k + 1];
        double *D = Dc + (size_t) nm * a;
        for (int m = 0; m < nm; m++) D[m] = Ca[nm + m] - Ca[m];
        double lin = 0.0;
        for (int m = 0; m < nm; m++) lin += psum[m] * Ca[m];
        double *s1 = S1 + (size_t) nm * a;
        double lse = estep2_any(Pt, n, nm, D, s1, inf_hit + q);
        ll_new[q] = lin + lse;
        if (inf_hit[q]) overflow = 1;
      }
      /* the R version switches every start to the overflow-safe form when
       * exp() overflowed in any of them (the responsibilities agree) */
      if (overflow) {
        for (int q = 0; q < A; q++) {
          if (failed[q]) continue;
          int a = act[q];
          const double *Ca = C + (size_t) a * k * nm;
          double lin = 0.0;
          for (int m = 0; m < nm; m++) lin += psum[m] * Ca[nm + m];
          ll_new[q] = lin + estep2_plogis(Pt, n, nm, Dc + (size_t) nm * a);
        }
      }
    } else {
      for (int q = 0; q < A; q++) {
        int a = act[q];
        const double *Ca = C + (size_t) a * k * nm;
        double *za = Z + (size_t) n * k * a;
        for (int j = 0; j < k; j++) {
          const double *Cj = Ca + (size_t) j * nm;
          double cj = cn[(size_t) a * k + j];
          double *lj = Lw + (size_t) j * n;
          for (int i = 0; i < n; i++) {
            double v = 0.0;
            for (int m = 0; m < nm; m++) v += P[(size_t) m * n + i] * Cj[m];
            lj[i] = v + cj;
          }
        }
        double tot = 0;
        for (int i = 0; i < n; i++) {
          double top = Lw[i];
          for (int j = 1; j < k; j++)
            if (Lw[(size_t) j * n + i] > top) top = Lw[(size_t) j * n + i];
          double se = 0;
          for (int j = 0; j < k; j++) se += exp(Lw[(size_t) j * n + i] - top);
          double lse = top + log((double) se);
          tot += lse;
          for (int j = 0; j < k; j++) za[(size_t) j * n + i] = exp(Lw[(size_t) j * n + i] - lse);
        }
        ll_new[q] = (double) tot;
      }
    }

    /* convergence, failure, merging, as gmm_em_batch_r() */
    int any_stop = 0;
    for (int q = 0; q < A; q++) {
      int a = act[q];
      failed[q] = failed[q] || !R_FINITE(ll_new[q]);
      conv_now[q] = !failed[q] && (ll_new[q] - llv[a] < tol);
      llv[a] = ll_new[q];
      stop_now[q] = failed[q] || conv_now[q] || it == max_iter;
      merged[q] = 0;
    }
    if (A > 1 && it % 10 == 0) {
      for (int qb = 1; qb < A; qb++) {
        int b = act[qb];
        for (int qa = 0; qa < qb; qa++) {
          int a = act[qa];
          if (!merged[qa] &&
              starts_close(k, d, pw + (size_t) a * k, pmu + (size_t) a * k * d,
                           psg + (size_t) a * k * d * d, pw + (size_t) b * k,
                           pmu + (size_t) b * k * d, psg + (size_t) b * k * d * d, oa, ob)) {
            merged[qb] = 1;
            break;
          }
        }
      }
      for (int q = 0; q < A; q++) {
        merged[q] = merged[q] && !stop_now[q];
        if (merged[q]) {
          pst[act[q]] = ST_MERGED;
          pit[act[q]] = it;
          stop_now[q] = 1;
        }
      }
    }
    for (int q = 0; q < A; q++) {
      if (!stop_now[q]) continue;
      any_stop = 1;
      int a = act[q];
      if (pst[a] != ST_RUNNING) continue;
      pit[a] = it;
      if (failed[q]) {
        pst[a] = ST_FAILED;
        pbad[a] = 0;
        for (int j = 0; j < k; j++)
          if (bad[(size_t) a * k + j]) { pbad[a] = j + 1; break; }
      } else {
        pst[a] = ST_DONE;
        pll[a] = ll_new[q];
        pcv[a] = conv_now[q];
      }
    }
    if (any_stop) {
      int B = 0;
      for (int q = 0; q < A; q++)
        if (!stop_now[q]) act[B++] = act[q];
      A = B;
    }
  }

  const char *names[8] = {"status", "iterations", "converged", "loglik", "bad",
                          "weights", "mu", "sigma"};
  const SEXP values[8] = {status, iters, conv, loglik, badc, W, MU, SG};
  SEXP out = hm_named_list(8, names, values);
  UNPROTECT(8);
  return out;
}

/* Lloyd iterations from each of a list of k x d centre matrices, as
 * gmm_kmeans(): squared distances up to a per-point constant,
 * -2 y.c + |c|^2, nearest centre with ties to the first, centres updated to
 * their group's mean (double, as colMeans), empty groups keep their
 * centre; stop when the labels repeat or after `iters` passes. */
SEXP hm_gmm_kmeans(SEXP Y_, SEXP centres_, SEXP iters_) {
  if (!isReal(Y_) || !isMatrix(Y_)) error("'Y' must be a double matrix");
  if (!isNewList(centres_)) error("'centres' must be a list");
  const int n = nrows(Y_), d = ncols(Y_), S = LENGTH(centres_), iters = asInteger(iters_);
  const double *Y = REAL(Y_);
  SEXP out = PROTECT(allocMatrix(INTSXP, n, S));
  int *lab_all = INTEGER(out);
  int *cur = (int *) R_alloc(n, sizeof(int));
  for (int s = 0; s < S; s++) {
    SEXP c0 = VECTOR_ELT(centres_, s);
    if (!isReal(c0) || !isMatrix(c0) || ncols(c0) != d) error("centres %d must be a double matrix with %d columns", s + 1, d);
    const int k = nrows(c0);
    double *cen = (double *) R_alloc((size_t) k * d, sizeof(double));
    double *cn2 = (double *) R_alloc(k, sizeof(double));
    double *acc = (double *) R_alloc((size_t) k * d, sizeof(double));
    int *cnt = (int *) R_alloc(k, sizeof(int));
    for (int q = 0; q < k * d; q++) cen[q] = REAL(c0)[q];
    int *lab = lab_all + (size_t) s * n;
    for (int i = 0; i < n; i++) lab[i] = 0;
    for (int pass = 0; pass < iters; pass++) {
      for (int g = 0; g < k; g++) { /* rowSums(centres^2): double */
        double s2 = 0;
        for (int c = 0; c < d; c++) s2 += cen[(size_t) c * k + g] * cen[(size_t) c * k + g];
        cn2[g] = (double) s2;
      }
      int same = 1;
      for (int i = 0; i < n; i++) {
        int best = 0;
        double bestv = 0.0;
        for (int g = 0; g < k; g++) {
          double dot = 0.0;
          for (int c = 0; c < d; c++) dot += Y[(size_t) c * n + i] * cen[(size_t) c * k + g];
          double v = -(-2 * dot + cn2[g]); /* max.col(-dist, "first") */
          if (g == 0 || v > bestv) { bestv = v; best = g; }
        }
        cur[i] = best + 1;
        if (cur[i] != lab[i]) same = 0;
      }
      if (same) break;
      for (int i = 0; i < n; i++) lab[i] = cur[i];
      for (int q = 0; q < k * d; q++) acc[q] = 0;
      for (int g = 0; g < k; g++) cnt[g] = 0;
      for (int i = 0; i < n; i++) {
        int g = lab[i] - 1;
        cnt[g]++;
        for (int c = 0; c < d; c++) acc[(size_t) c * k + g] += Y[(size_t) c * n + i];
      }
      for (int g = 0; g < k; g++)
        if (cnt[g] > 0)
          for (int c = 0; c < d; c++) cen[(size_t) c * k + g] = (double) (acc[(size_t) c * k + g] / cnt[g]);
    }
  }
  UNPROTECT(1);
  return out;
}
