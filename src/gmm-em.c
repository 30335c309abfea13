/* Compiled EM for the fast Gaussian-mixture engine (R/gmm-em.R), for any
 * dimension d and any number of components k: the one production path of
 * the fast engine (d = 1 and 2 are the thesis' warp scores and FPC score
 * pairs; d > 2 comes with ncomp > 2).
 *
 * It reproduces the R transcription gmm_em_batch_r()
 * (tests/testthat/helper-gmm-reference.R, a test reference only) step for
 * step: the same monomial design (1, y_a, y_a y_b), the same M-step
 * formulas from the sufficient statistics (closed forms for d = 1 and 2;
 * above, the Cholesky factor and its inverse, as chol() and chol2inv()),
 * the same E-step (for k = 2 the log-likelihood as
 * psum . C1 + sum log1p(exp(neg)), with R's plogis formulation when exp
 * overflows in any start of the evaluation; otherwise a log-sum-exp), the
 * same SQUAREM acceleration (Varadhan & Roland 2008, scheme S3, on the
 * sufficient statistics: two EM steps, an extrapolated state kept only when
 * its log-likelihood reaches the second step's, so the log-likelihood never
 * decreases), the same stopping rule (an EM step raising the log-likelihood
 * by less than tol; gmm_em_fast() passes n times its per-observation
 * tolerance), the same failure tests (weight below 1/n, covariance
 * determinant below the floor, non-finite log-likelihood) and the same
 * merging of starts that have come together (checked every third cycle).
 * The starts run in lock step, cycle by cycle, as the columns of the R
 * version's matrices do, because the overflow switch and the merge test
 * look at all running starts at once.
 *
 * What differs is rounding only, for speed: the E-step is one pass over the
 * points fused with the next M-step's sums; for k = 2 sum log1p(exp(neg)) is
 * the log of a running product. Plain C with libm's exp(). An EM step agrees
 * with the R version to about 1e-11 (for d = 3 and 4 the fits of the test
 * clouds to about 1e-13); SQUAREM's step length divides by a second
 * difference that near the optimum is mostly rounding, so on a crawling
 * cloud the two may stop some iterations apart (tests/testthat/test-gmm-fit.R).
 * Sums over points are plain double sums in point order.
 *
 * Entry points:
 *   hm_gmm_em(P, state, k, max_iter, tol, logdet0)
 *     P: n x nm monomials of the standardised data, nm = 1 + d + d (d + 1) / 2
 *     (1, y_a, then y_a y_b for a <= b, a-major: gmm_design()); state: the
 *     starting sufficient statistics, nm rows and, per start, one column
 *     (k = 2: the first component's) or k columns. Every argument is
 *     checked (types, lengths, finiteness): a bad call is an R error.
 *     Returns list(status, iterations, converged, loglik, bad, weights, mu,
 *     sigma): status 0 = stopped with parameters (converged or at max_iter),
 *     1 = failed (bad = first degenerate component, 0 = non-finite
 *     log-likelihood), 2 = merged into an earlier start; iterations count
 *     EM evaluations (E-steps), extrapolations included.
 *   hm_gmm_kmeans(Y, centres, iters)
 *     Lloyd iterations as gmm_kmeans() in R, for a list of starting centre
 *     matrices; returns an n x S integer matrix of labels.
 * Scratch memory comes from R_alloc (scratch.h). */
#include <math.h>
#include <R.h>
#include <Rinternals.h>
#include "named-list.h"
#include "cholesky.h"
#include "scratch.h"

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

/* The M-step of one component for d > 2, as gmm_mstep_general() in the test
 * reference: the mean mu = s_y / nk, the covariance S = s_yy / nk - mu mu'
 * (into sig, d x d column-major), its Cholesky factor S = R'R (as chol();
 * a pivot that is not positive, or NaN, means the component is degenerate),
 * A = S^-1 from R^-1 (as chol2inv()), and the log-density coefficients
 * -0.5 (y'Ay - 2 mu'Ay + mu'A mu) in the monomial basis: C[0] = -0.5 mu'A mu,
 * C[1 + a] = (A mu)_a, C[pair (a, b)] = -0.5 A_aa on the diagonal, -A_ab off
 * it. Returns log det S, or -Inf when nk < 1 or S is not positive definite
 * (C is then left at zero and not used). `work`: 2 d^2 doubles. */
static double mstep_general(int d, const double *s, double nk, double *C, double *mu,
                            double *sig, double *work) {
  const int nm = 1 + d + d * (d + 1) / 2;
  double *R = work, *Ri = work + (size_t) d * d;
  for (int a = 0; a < d; a++) mu[a] = s[1 + a] / nk;
  int m = 1 + d;
  for (int a = 0; a < d; a++)
    for (int b = a; b < d; b++) {
      double v = s[m++] / nk - mu[a] * mu[b];
      sig[a + (size_t) b * d] = v;
      sig[b + (size_t) a * d] = v;
    }
  for (int q = 0; q < nm; q++) C[q] = 0.0;
  if (!(nk >= 1) || !hm_chol_upper(d, sig, R)) return R_NegInf;
  double logdet = 0.0;
  for (int a = 0; a < d; a++) logdet += log(R[a + (size_t) a * d]);
  logdet *= 2.0;
  /* Ri = R^-1 (upper triangular), by back substitution column by column */
  for (int q = 0; q < d * d; q++) Ri[q] = 0.0;
  for (int b = 0; b < d; b++) {
    Ri[b + (size_t) b * d] = 1.0 / R[b + (size_t) b * d];
    for (int a = b - 1; a >= 0; a--) {
      double acc = 0.0;
      for (int c = a + 1; c <= b; c++) acc += R[a + (size_t) c * d] * Ri[c + (size_t) b * d];
      Ri[a + (size_t) b * d] = -acc / R[a + (size_t) a * d];
    }
  }
  /* A = Ri Ri' (symmetric; the upper triangle a <= b is what C needs), A mu
   * and mu'A mu, with A_ab written into the coefficients directly */
  double mAm = 0.0;
  m = 1 + d;
  for (int a = 0; a < d; a++)
    for (int b = a; b < d; b++) {
      double acc = 0.0;
      for (int c = b; c < d; c++) acc += Ri[a + (size_t) c * d] * Ri[b + (size_t) c * d];
      C[m++] = a == b ? -0.5 * acc : -acc;
      C[1 + a] += acc * mu[b];
      if (a != b) C[1 + b] += acc * mu[a];
    }
  for (int a = 0; a < d; a++) mAm += mu[a] * C[1 + a];
  C[0] = -0.5 * mAm;
  return logdet;
}

/* M-step of one component from its sufficient statistics s[0..nm-1]
 * (sums of the monomials weighted by the responsibilities): fills the
 * log-density coefficients C[0..nm-1], the constant, the parameters, and
 * returns 1 when the component is degenerate. Formulas as gmm_mstep() in the
 * test reference; `work` is scratch for 2 d^2 values (d > 2 only). */
static int mstep_one(int d, const double *s, int n, double floor_logdet, double *C,
                     double *cnst, double *w, double *mu, double *sig, double *work) {
  double nk = s[0], logdet;
  if (d > 2) {
    /* (d = 1 and 2 keep their closed forms below: the default models'
     * fits depend on their exact rounding) */
    logdet = mstep_general(d, s, nk, C, mu, sig, work);
  } else if (d == 1) {
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
  /* d <= 2 (nm <= 6) sums in a local array the compiler keeps in registers
   * (as fast as before d > 2 came to C); larger nm sum in place */
  double local[6];
  double *s = nm <= 6 ? local : s_next;
  for (int m = 0; m < nm; m++) s[m] = 0.0;
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
  if (s != s_next)
    for (int m = 0; m < nm; m++) s_next[m] = s[m];
  *inf = hit;
  return logs + log(prod);
}

/* The E-step pass of one start (inlined with nm = 3 and nm = 6, d = 1 and
 * 2, so the compiler unrolls and vectorises the inner loops; any other nm
 * takes the same code with nm a variable). */
static double estep2_any(const double *Pt, int n, int nm, const double *D, double *s_next,
                         int *inf) {
  if (nm == 3) return estep2(Pt, n, 3, D, s_next, inf);
  if (nm == 6) return estep2(Pt, n, 6, D, s_next, inf);
  return estep2(Pt, n, nm, D, s_next, inf);
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

/* What one EM evaluation needs: the data (point-major monomials and their
 * column sums), the sizes, the determinant floor and scratch space. */
typedef struct {
  int n, nm, d, k, two, ns;
  const double *Pt, *psum;
  double floor_logdet;
  double *stats, *C, *cn, *Dc, *zk; /* scratch: nm*k, nm*k*S, k*S, nm*S, k */
  double *work;                     /* 2 d^2: the M-step for d > 2 */
  int *inf_hit;                     /* S */
} em_ctx;

/* The M-step of one start from its state `st` (ns values: for k = 2 the
 * first component's sufficient statistics, the second's being psum minus
 * them; otherwise every component's, component after component): the
 * log-density coefficients into C/cn at the start's slots, the parameters
 * into w/mu/sig. Returns the first degenerate component (1-based), 0 if
 * none. */
static int mstep_start(const em_ctx *c, int a, const double *st, double *w, double *mu,
                       double *sig) {
  const int nm = c->nm, k = c->k, d = c->d;
  if (c->two) {
    for (int m = 0; m < nm; m++) {
      c->stats[m] = st[m];
      c->stats[nm + m] = c->psum[m] - st[m];
    }
  } else {
    for (int q = 0; q < nm * k; q++) c->stats[q] = st[q];
  }
  int bad = 0;
  for (int j = 0; j < k; j++) {
    int b = mstep_one(d, c->stats + (size_t) j * nm, c->n, c->floor_logdet,
                      c->C + ((size_t) a * k + j) * nm, c->cn + (size_t) a * k + j,
                      w + (size_t) a * k + j, mu + ((size_t) a * k + j) * d,
                      sig + ((size_t) a * k + j) * d * d, c->work);
    if (b && !bad) bad = j + 1;
  }
  return bad;
}

/* E-step of one start for k != 2: per point the k log-densities, their
 * log-sum-exp (the point's log-likelihood) and the responsibilities,
 * accumulated at once into the next statistics `out` (nm * k). */
static double estep_k(const em_ctx *c, int a, double *out) {
  const int n = c->n, nm = c->nm, k = c->k;
  const double *Ca = c->C + (size_t) a * k * nm, *cna = c->cn + (size_t) a * k;
  double *v = c->zk;
  for (int q = 0; q < nm * k; q++) out[q] = 0.0;
  double tot = 0.0;
  for (int i = 0; i < n; i++) {
    const double *pi = c->Pt + (size_t) i * nm;
    double top = R_NegInf;
    for (int j = 0; j < k; j++) {
      double s = 0.0;
      for (int m = 0; m < nm; m++) s += pi[m] * Ca[(size_t) j * nm + m];
      v[j] = s + cna[j];
      if (j == 0 || v[j] > top) top = v[j];
    }
    double se = 0.0;
    for (int j = 0; j < k; j++) se += exp(v[j] - top);
    double lse = top + log(se);
    tot += lse;
    for (int j = 0; j < k; j++) {
      double z = exp(v[j] - lse);
      for (int m = 0; m < nm; m++) out[(size_t) j * nm + m] += pi[m] * z;
    }
  }
  return tot;
}

/* One EM evaluation of the starts idx[0..cnt-1]: the M-step from their
 * states in `src`, the log-likelihood of its parameters into ll[a], the
 * E-step's statistics (the next state) into `dst`, the first degenerate
 * component into bad[a] (a degenerate start gets no E-step, ll NA). For
 * k = 2, as the R version, every start of the evaluation takes the
 * overflow-safe form of the log-likelihood when exp() overflowed in any. */
static void em_eval(const em_ctx *c, const int *idx, int cnt, const double *src, double *dst,
                    double *ll, int *bad, double *w, double *mu, double *sig) {
  const int nm = c->nm, k = c->k, ns = c->ns;
  int overflow = 0;
  for (int q = 0; q < cnt; q++) {
    int a = idx[q];
    bad[a] = mstep_start(c, a, src + (size_t) a * ns, w, mu, sig);
    if (bad[a]) {
      ll[a] = NA_REAL;
      continue;
    }
    if (c->two) {
      double *Ca = c->C + (size_t) a * k * nm;
      Ca[0] += c->cn[(size_t) a * k]; /* constants folded into the intercept */
      Ca[nm] += c->cn[(size_t) a * k + 1];
      double *D = c->Dc + (size_t) nm * a;
      for (int m = 0; m < nm; m++) D[m] = Ca[nm + m] - Ca[m];
      double lin = 0.0;
      for (int m = 0; m < nm; m++) lin += c->psum[m] * Ca[m];
      ll[a] = lin + estep2_any(c->Pt, c->n, nm, D, dst + (size_t) a * ns, c->inf_hit + a);
      if (c->inf_hit[a]) overflow = 1;
    } else {
      ll[a] = estep_k(c, a, dst + (size_t) a * ns);
    }
  }
  if (overflow) {
    for (int q = 0; q < cnt; q++) {
      int a = idx[q];
      if (bad[a]) continue;
      const double *Ca = c->C + (size_t) a * k * nm;
      double lin = 0.0;
      for (int m = 0; m < nm; m++) lin += c->psum[m] * Ca[nm + m];
      ll[a] = lin + estep2_plogis(c->Pt, c->n, nm, c->Dc + (size_t) nm * a);
    }
  }
}

/* The SQUAREM step length (Varadhan & Roland 2008, scheme S3) of one start
 * from its state s0 and two EM steps s1 = F(s0), s2 = F(s1):
 * alpha = |r| / |v| with r = s1 - s0, v = s2 - 2 s1 + s0, clamped to
 * [1, step_max]; the extrapolated state s0 + 2 alpha r + alpha^2 v goes into
 * `out` (alpha = 1 gives s2). */
static double squarem_extrapolate(int ns, const double *s0, const double *s1, const double *s2,
                                  double step_max, double *out) {
  double sr2 = 0.0, sv2 = 0.0;
  for (int q = 0; q < ns; q++) {
    double r = s1[q] - s0[q], v = s2[q] - 2.0 * s1[q] + s0[q];
    sr2 += r * r;
    sv2 += v * v;
  }
  double alpha = sv2 > 0.0 ? sqrt(sr2 / sv2) : 1.0;
  if (!(alpha >= 1.0)) alpha = 1.0;
  if (alpha > step_max) alpha = step_max;
  for (int q = 0; q < ns; q++) {
    double r = s1[q] - s0[q], v = s2[q] - 2.0 * s1[q] + s0[q];
    out[q] = s0[q] + 2.0 * alpha * r + alpha * alpha * v;
  }
  return alpha;
}

SEXP hm_gmm_em(SEXP P_, SEXP state_, SEXP k_, SEXP max_iter_, SEXP tol_, SEXP logdet0_) {
  if (!isReal(P_) || !isMatrix(P_)) error("'P' must be a double matrix");
  if (!isReal(state_) || !isMatrix(state_)) error("'state' must be a double matrix");
  if (LENGTH(k_) != 1 || LENGTH(max_iter_) != 1 || LENGTH(tol_) != 1 || LENGTH(logdet0_) != 1)
    error("'k', 'max_iter', 'tol' and 'logdet0' must be single values");
  const int n = nrows(P_), nm = ncols(P_);
  const int k = asInteger(k_), max_iter = asInteger(max_iter_);
  const double tol = asReal(tol_), logdet0 = asReal(logdet0_);
  /* nm = 1 + d + d (d + 1) / 2 monomials (gmm_design()) */
  int d = 1;
  while (1 + d + d * (d + 1) / 2 < nm) d++;
  if (1 + d + d * (d + 1) / 2 != nm)
    error("'P' has %d columns, not 1 + d + d (d + 1) / 2 monomials for any d", nm);
  if (n < 1 || k == NA_INTEGER || k < 1 || k > n || max_iter == NA_INTEGER || max_iter < 1)
    error("'P' must have rows, 'k' must be in 1..nrow(P) and 'max_iter' positive");
  if (ISNAN(tol) || !R_FINITE(logdet0)) error("'tol' and 'logdet0' must be numbers");
  for (R_xlen_t q = 0; q < XLENGTH(P_); q++)
    if (!R_FINITE(REAL(P_)[q])) error("'P' must be finite");
  const double *P = REAL(P_);
  const int two = (k == 2);
  const int ns = nm * (two ? 1 : k); /* state values per start */
  if (nrows(state_) != nm || ncols(state_) < 1 || ncols(state_) % (two ? 1 : k) != 0)
    error("'state' must have %d rows and %d column%s per start", nm, two ? 1 : k,
          two ? "" : "s");
  const int S = ncols(state_) / (two ? 1 : k);
  const double *st0 = REAL(state_);
  for (R_xlen_t q = 0; q < XLENGTH(state_); q++)
    if (!R_FINITE(st0[q])) error("'state' must be finite");

  em_ctx c;
  c.n = n;
  c.nm = nm;
  c.d = d;
  c.k = k;
  c.two = two;
  c.ns = ns;
  c.floor_logdet = logdet0 + log(1e-8); /* gmm_det_floor */
  double *psum, *Pt;
  HM_SCRATCH_REALS(nm, &psum);
  for (int m = 0; m < nm; m++) {
    double acc = 0;
    for (int i = 0; i < n; i++) acc += P[(size_t) m * n + i];
    psum[m] = acc;
  }
  c.psum = psum;
  HM_SCRATCH_REALS((size_t) n * nm, &Pt); /* point-major P */
  for (int i = 0; i < n; i++)
    for (int m = 0; m < nm; m++) Pt[(size_t) i * nm + m] = P[(size_t) m * n + i];
  c.Pt = Pt;

  /* states: s0 (the cycle's start), s1, s2 (after one and two EM steps), sx
   * (extrapolated), sn (one EM step from sx); the extrapolated parameters
   * (wx, mux, sgx) stay out of the output slots. Per start: the log-lik of
   * the last EM step (llv) and of an evaluation (lle), the extrapolation's
   * step (alpha) and its cap (step_max), why an evaluation failed (bad),
   * whether it merged into another (merged); the lists of starts still
   * running (act) and extrapolated (ext); per component, the matching
   * orders of starts_close() (oa, ob). */
  double *s0, *s1, *s2, *sx, *sn, *wx, *mux, *sgx, *llv, *lle, *step_max, *alpha;
  int *bad, *act, *ext, *merged, *oa, *ob;
  HM_SCRATCH_REALS((size_t) nm * k, &c.stats);
  HM_SCRATCH_REALS((size_t) nm * k * S, &c.C);
  HM_SCRATCH_REALS((size_t) nm * S, &c.Dc);
  HM_SCRATCH_REALS(k, &c.zk);
  HM_SCRATCH_REALS((size_t) 2 * d * d, &c.work);
  HM_SCRATCH_REALS((size_t) ns * S, &s0, &s1, &s2, &sx, &sn);
  HM_SCRATCH_REALS((size_t) k * S, &c.cn, &wx);
  HM_SCRATCH_REALS((size_t) d * k * S, &mux);
  HM_SCRATCH_REALS((size_t) d * d * k * S, &sgx);
  HM_SCRATCH_REALS(S, &llv, &lle, &step_max, &alpha);
  HM_SCRATCH_INTS(S, &c.inf_hit, &bad, &act, &ext, &merged);
  HM_SCRATCH_INTS(k, &oa, &ob);

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

  /* the starting states, as given */
  for (int a = 0; a < S; a++) {
    pst[a] = ST_RUNNING;
    pit[a] = 0;
    pcv[a] = FALSE;
    pll[a] = NA_REAL;
    pbad[a] = NA_INTEGER;
    llv[a] = R_NegInf;
    step_max[a] = 1.0;
    act[a] = a;
    for (int q = 0; q < ns; q++) s0[(size_t) a * ns + q] = st0[(size_t) a * ns + q];
  }

  /* SQUAREM cycles: two EM steps s0 -> s1 -> s2, each tested for
   * convergence, failure and the cap as plain EM; then the extrapolated
   * state's parameters are evaluated and the state moves one EM step past
   * them if they raise the log-likelihood to at least the second step's,
   * and to s2 otherwise (so the log-likelihood never decreases). Every
   * evaluation counts as an iteration. */
  int A = S, cycle = 0;
  while (A > 0) {
    cycle++;
    R_CheckUserInterrupt();
    for (int ph = 0; ph < 2 && A > 0; ph++) {
      em_eval(&c, act, A, ph == 0 ? s0 : s1, ph == 0 ? s1 : s2, lle, bad, pw, pmu, psg);
      int B = 0;
      for (int q = 0; q < A; q++) {
        int a = act[q];
        pit[a]++;
        int failed = bad[a] || !R_FINITE(lle[a]);
        int conv_now = !failed && (lle[a] - llv[a] < tol);
        llv[a] = lle[a];
        if (failed) {
          pst[a] = ST_FAILED;
          pbad[a] = bad[a];
        } else if (conv_now || pit[a] >= max_iter) {
          pst[a] = ST_DONE;
          pll[a] = lle[a];
          pcv[a] = conv_now;
        } else {
          act[B++] = a;
        }
      }
      A = B;
    }
    /* starts whose parameters have come together follow the same path to
     * the same optimum: keep the first of them only */
    if (A > 1 && cycle % 3 == 0) {
      for (int q = 0; q < A; q++) merged[q] = 0;
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
      int B = 0;
      for (int q = 0; q < A; q++) {
        if (merged[q]) pst[act[q]] = ST_MERGED;
        else act[B++] = act[q];
      }
      A = B;
    }
    /* the extrapolation; a start one evaluation from the cap takes s2 */
    int E = 0;
    for (int q = 0; q < A; q++) {
      int a = act[q];
      size_t o = (size_t) a * ns;
      if (pit[a] + 1 >= max_iter) {
        for (int v = 0; v < ns; v++) s0[o + v] = s2[o + v];
        continue;
      }
      alpha[a] = squarem_extrapolate(ns, s0 + o, s1 + o, s2 + o, step_max[a], sx + o);
      ext[E++] = a;
    }
    em_eval(&c, ext, E, sx, sn, lle, bad, wx, mux, sgx);
    for (int q = 0; q < E; q++) {
      int a = ext[q];
      size_t o = (size_t) a * ns;
      pit[a]++;
      int at_max = alpha[a] == step_max[a];
      if (!bad[a] && R_FINITE(lle[a]) && lle[a] >= llv[a]) {
        for (int v = 0; v < ns; v++) s0[o + v] = sn[o + v];
        llv[a] = lle[a];
        if (at_max) step_max[a] *= 4.0;
      } else {
        for (int v = 0; v < ns; v++) s0[o + v] = s2[o + v];
        if (at_max && step_max[a] > 1.0) step_max[a] = fmax(1.0, step_max[a] / 4.0);
      }
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
  if (LENGTH(iters_) != 1) error("'iters' must be a single value");
  const int n = nrows(Y_), d = ncols(Y_), S = LENGTH(centres_), iters = asInteger(iters_);
  const double *Y = REAL(Y_);
  SEXP out = PROTECT(allocMatrix(INTSXP, n, S));
  int *lab_all = INTEGER(out);
  int *cur;
  HM_SCRATCH_INTS(n, &cur);
  for (int s = 0; s < S; s++) {
    SEXP c0 = VECTOR_ELT(centres_, s);
    if (!isReal(c0) || !isMatrix(c0) || ncols(c0) != d) error("centres %d must be a double matrix with %d columns", s + 1, d);
    const int k = nrows(c0);
    /* the centres, their squared norms, the groups' sums and sizes */
    double *cen, *cn2, *acc;
    int *cnt;
    HM_SCRATCH_REALS((size_t) k * d, &cen, &acc);
    HM_SCRATCH_REALS(k, &cn2);
    HM_SCRATCH_INTS(k, &cnt);
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
