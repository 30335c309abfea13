/* Compiled EM for the fast Gaussian-mixture engine (R/gmm.R), for d = 1 and
 * d = 2 (the thesis' warp scores and FPC score pairs).
 *
 * It reproduces the R implementation gmm_em_batch_r() step for step, so the
 * two give the same fits (log-likelihoods equal to rounding): the same
 * monomial design (1, y_a, y_a y_b), the same M-step formulas from the
 * sufficient statistics, the same E-step (for k = 2 the log-likelihood as
 * psum . C1 + sum log1p(exp(neg)), with R's plogis formulation when exp
 * overflows in any running start; otherwise a log-sum-exp), the same
 * stopping rule (an iteration raising the log-likelihood by less than tol),
 * the same failure tests (weight below 1/n, covariance determinant below the
 * floor, non-finite log-likelihood) and the same merging of starts that have
 * come together (checked every 10 iterations). The starts run in lock step,
 * as the columns of the R version's matrices do, because the overflow switch
 * and the merge test look at all running starts at once.
 *
 * What differs is rounding only, for speed: the k = 2 E-step is one pass
 * over the points fused with the next M-step's sums; sum log1p(exp(neg)) is
 * the log of a running product; on x86-64 four points go through AVX2 at
 * once when the CPU has it (estep2_avx2, chosen at run time), else two
 * through SSE2 (estep2_sse2), with an inline exp(); -DHM_NO_AVX2,
 * -DHM_NO_SIMD or another architecture fall back to SSE2 or the scalar
 * estep2 with libm's exp. Whatever the path, log-likelihoods agree with the
 * R version to about 1e-11 (tests/testthat/test-gmm.R runs all three).
 * Elsewhere, sums over points that R computes with BLAS (crossprod, %*%)
 * are plain double sums in point order (as the reference BLAS does); those
 * R computes with colSums use long double, as R does.
 *
 * Entry points:
 *   hm_gmm_em(P, labels, k, max_iter, tol, logdet0, simd)
 *     P: n x nm monomials of the standardised data (nm = 3 for d = 1, 6 for
 *     d = 2); labels: n x S integer starting partitions (1..k); simd: the
 *     widest instruction set to use (0 scalar, 1 SSE2, 2 AVX2).
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
#if defined(__SSE2__) && !defined(HM_NO_SIMD)
#include <emmintrin.h>
#endif
/* AVX2 (four points at once) where the compiler can target it for one
 * function and the CPU has it, checked at run time: GCC and clang on x86-64 */
#if defined(__SSE2__) && !defined(HM_NO_SIMD) && defined(__x86_64__) && \
    (defined(__GNUC__) || defined(__clang__)) && !defined(HM_NO_AVX2)
#define HM_AVX2 1
#include <immintrin.h>
#endif

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

#if defined(__SSE2__) && !defined(HM_NO_SIMD)
/* exp() of two values at once for |x| <= 230 (SSE2, the x86-64 baseline):
 * x = n ln2 + r with |r| <= ln2 / 2 (Cody-Waite, n*LN2_HI exact), exp(r) by
 * its Taylor series to degree 13 (truncation below 1e-17 relative), times
 * 2^n built in the exponent bits. Within a few ulps of libm's exp(); the
 * E-step's sums then agree with the R version's to about 1e-13. */
static inline __m128d exp_pd(__m128d x) {
  const __m128d shifter = _mm_set1_pd(6755399441055744.0); /* 1.5 * 2^52 */
  __m128d t = _mm_add_pd(_mm_mul_pd(x, _mm_set1_pd(1.4426950408889634)), shifter);
  __m128d n = _mm_sub_pd(t, shifter); /* round(x / ln2) */
  __m128d r = _mm_sub_pd(x, _mm_mul_pd(n, _mm_set1_pd(6.93147180369123816490e-01)));
  r = _mm_sub_pd(r, _mm_mul_pd(n, _mm_set1_pd(1.90821492927058770002e-10)));
  /* sum_{k=0}^{13} r^k / k! by Estrin's scheme: a shallow tree of
   * multiply-adds rather than Horner's chain of thirteen, whose latency
   * would dominate */
#define HM_C(k) _mm_set1_pd(1.0 / (k))
  const __m128d r2 = _mm_mul_pd(r, r), r4 = _mm_mul_pd(r2, r2), r8 = _mm_mul_pd(r4, r4);
  __m128d q0 = _mm_add_pd(_mm_set1_pd(1.0), r);                                 /* 1 + r */
  __m128d q1 = _mm_add_pd(HM_C(2.0), _mm_mul_pd(HM_C(6.0), r));                 /* r^2, r^3 */
  __m128d q2 = _mm_add_pd(HM_C(24.0), _mm_mul_pd(HM_C(120.0), r));              /* r^4, r^5 */
  __m128d q3 = _mm_add_pd(HM_C(720.0), _mm_mul_pd(HM_C(5040.0), r));            /* r^6, r^7 */
  __m128d q4 = _mm_add_pd(HM_C(40320.0), _mm_mul_pd(HM_C(362880.0), r));        /* r^8, r^9 */
  __m128d q5 = _mm_add_pd(HM_C(3628800.0), _mm_mul_pd(HM_C(39916800.0), r));    /* r^10, r^11 */
  __m128d q6 = _mm_add_pd(HM_C(479001600.0), _mm_mul_pd(HM_C(6227020800.0), r)); /* r^12, r^13 */
#undef HM_C
  __m128d t0 = _mm_add_pd(q0, _mm_mul_pd(q1, r2));
  __m128d t1 = _mm_add_pd(q2, _mm_mul_pd(q3, r2));
  __m128d t2 = _mm_add_pd(q4, _mm_mul_pd(q5, r2));
  __m128d u0 = _mm_add_pd(t0, _mm_mul_pd(t1, r4));
  __m128d u1 = _mm_add_pd(t2, _mm_mul_pd(q6, r4));
  __m128d p = _mm_add_pd(u0, _mm_mul_pd(u1, r8));
  /* t's low mantissa bits hold n + 2^51: add 1023 - 2^51, shift into the
   * exponent field: the bits of 2^n */
  __m128i bits = _mm_add_epi64(_mm_castpd_si128(t),
                               _mm_set1_epi64x((long long) 1023 - ((long long) 1 << 51)));
  __m128d scale = _mm_castsi128_pd(_mm_slli_epi64(bits, 52));
  return _mm_mul_pd(p, scale);
}

/* estep2() two points at a time, reading the monomials column-major (P);
 * for d = 1 (three monomials) the other three columns are `zero` and their
 * coefficients 0, which adds exact zeros. The six sums live in registers
 * (spelt out, not an array, which the compiler kept in memory); they run
 * over even and odd points separately and are added at the end
 * (rounding-level differences from the point-order sums). Pairs with
 * |neg| > 230 (exp near overflow, or the product's flush limit) go through
 * the scalar formulas. */
static double estep2_sse2(const double *P, int n, int nm, const double *zero, const double *D,
                          double *s_next, int *inf) {
  const double *c0 = P, *c1 = P + n, *c2 = P + 2 * (size_t) n;
  const double *c3 = nm == 6 ? P + 3 * (size_t) n : zero;
  const double *c4 = nm == 6 ? P + 4 * (size_t) n : zero;
  const double *c5 = nm == 6 ? P + 5 * (size_t) n : zero;
  const __m128d d0 = _mm_set1_pd(D[0]), d1 = _mm_set1_pd(D[1]), d2 = _mm_set1_pd(D[2]);
  const __m128d d3 = _mm_set1_pd(nm == 6 ? D[3] : 0.0), d4 = _mm_set1_pd(nm == 6 ? D[4] : 0.0),
                d5 = _mm_set1_pd(nm == 6 ? D[5] : 0.0);
  __m128d s0 = _mm_setzero_pd(), s1 = s0, s2 = s0, s3 = s0, s4 = s0, s5 = s0;
  __m128d prod = _mm_set1_pd(1.0);
  const __m128d one = _mm_set1_pd(1.0), lim = _mm_set1_pd(230.0), big = _mm_set1_pd(1e200);
  const __m128d absmask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  double logs = 0.0;
  int hit = 0, i = 0;
  for (; i + 2 <= n; i += 2) {
    const __m128d p0 = _mm_loadu_pd(c0 + i), p1 = _mm_loadu_pd(c1 + i), p2 = _mm_loadu_pd(c2 + i);
    const __m128d p3 = _mm_loadu_pd(c3 + i), p4 = _mm_loadu_pd(c4 + i), p5 = _mm_loadu_pd(c5 + i);
    __m128d v = _mm_mul_pd(p0, d0);
    v = _mm_add_pd(v, _mm_mul_pd(p1, d1));
    v = _mm_add_pd(v, _mm_mul_pd(p2, d2));
    v = _mm_add_pd(v, _mm_mul_pd(p3, d3));
    v = _mm_add_pd(v, _mm_mul_pd(p4, d4));
    v = _mm_add_pd(v, _mm_mul_pd(p5, d5));
    __m128d z;
    /* not (|v| <= 230): large or NaN */
    if (_mm_movemask_pd(_mm_cmpnle_pd(_mm_and_pd(v, absmask), lim))) {
      double vv[2], zz[2];
      _mm_storeu_pd(vv, v);
      for (int b = 0; b < 2; b++) {
        double e = exp(vv[b]);
        zz[b] = 1.0 / (1.0 + e);
        if (e == R_PosInf) hit = 1;
        logs += log1p(e);
      }
      z = _mm_loadu_pd(zz);
    } else {
      __m128d e1 = _mm_add_pd(one, exp_pd(v));
      z = _mm_div_pd(one, e1);
      prod = _mm_mul_pd(prod, e1);
      if (_mm_movemask_pd(_mm_cmpgt_pd(prod, big))) {
        double pp[2];
        _mm_storeu_pd(pp, prod);
        logs += log(pp[0]) + log(pp[1]);
        prod = one;
      }
    }
    s0 = _mm_add_pd(s0, _mm_mul_pd(p0, z));
    s1 = _mm_add_pd(s1, _mm_mul_pd(p1, z));
    s2 = _mm_add_pd(s2, _mm_mul_pd(p2, z));
    s3 = _mm_add_pd(s3, _mm_mul_pd(p3, z));
    s4 = _mm_add_pd(s4, _mm_mul_pd(p4, z));
    s5 = _mm_add_pd(s5, _mm_mul_pd(p5, z));
  }
  double pp[2], ss[6], t2[2];
  _mm_storeu_pd(pp, prod);
  __m128d sv[6] = {s0, s1, s2, s3, s4, s5};
  for (int m = 0; m < 6; m++) {
    _mm_storeu_pd(t2, sv[m]);
    ss[m] = t2[0] + t2[1];
  }
  double tail = 0.0;
  for (; i < n; i++) { /* the last point of an odd n */
    double v = 0.0;
    for (int m = 0; m < nm; m++) v += P[(size_t) m * n + i] * D[m];
    double e = exp(v);
    double z = 1.0 / (1.0 + e);
    for (int m = 0; m < nm; m++) ss[m] += P[(size_t) m * n + i] * z;
    if (e == R_PosInf) hit = 1;
    tail += log1p(e);
  }
  for (int m = 0; m < nm; m++) s_next[m] = ss[m];
  *inf = hit;
  return logs + log(pp[0]) + log(pp[1]) + tail;
}

#ifdef HM_AVX2
/* exp_pd() four values at once (same steps, same constants) */
__attribute__((target("avx2"))) static inline __m256d exp_pd4(__m256d x) {
  const __m256d shifter = _mm256_set1_pd(6755399441055744.0);
  __m256d t = _mm256_add_pd(_mm256_mul_pd(x, _mm256_set1_pd(1.4426950408889634)), shifter);
  __m256d n = _mm256_sub_pd(t, shifter);
  __m256d r = _mm256_sub_pd(x, _mm256_mul_pd(n, _mm256_set1_pd(6.93147180369123816490e-01)));
  r = _mm256_sub_pd(r, _mm256_mul_pd(n, _mm256_set1_pd(1.90821492927058770002e-10)));
#define HM_C4(k) _mm256_set1_pd(1.0 / (k))
  const __m256d r2 = _mm256_mul_pd(r, r), r4 = _mm256_mul_pd(r2, r2), r8 = _mm256_mul_pd(r4, r4);
  __m256d q0 = _mm256_add_pd(_mm256_set1_pd(1.0), r);
  __m256d q1 = _mm256_add_pd(HM_C4(2.0), _mm256_mul_pd(HM_C4(6.0), r));
  __m256d q2 = _mm256_add_pd(HM_C4(24.0), _mm256_mul_pd(HM_C4(120.0), r));
  __m256d q3 = _mm256_add_pd(HM_C4(720.0), _mm256_mul_pd(HM_C4(5040.0), r));
  __m256d q4 = _mm256_add_pd(HM_C4(40320.0), _mm256_mul_pd(HM_C4(362880.0), r));
  __m256d q5 = _mm256_add_pd(HM_C4(3628800.0), _mm256_mul_pd(HM_C4(39916800.0), r));
  __m256d q6 = _mm256_add_pd(HM_C4(479001600.0), _mm256_mul_pd(HM_C4(6227020800.0), r));
#undef HM_C4
  __m256d t0 = _mm256_add_pd(q0, _mm256_mul_pd(q1, r2));
  __m256d t1 = _mm256_add_pd(q2, _mm256_mul_pd(q3, r2));
  __m256d t2 = _mm256_add_pd(q4, _mm256_mul_pd(q5, r2));
  __m256d u0 = _mm256_add_pd(t0, _mm256_mul_pd(t1, r4));
  __m256d u1 = _mm256_add_pd(t2, _mm256_mul_pd(q6, r4));
  __m256d p = _mm256_add_pd(u0, _mm256_mul_pd(u1, r8));
  __m256i bits = _mm256_add_epi64(_mm256_castpd_si256(t),
                                  _mm256_set1_epi64x((long long) 1023 - ((long long) 1 << 51)));
  return _mm256_mul_pd(p, _mm256_castsi256_pd(_mm256_slli_epi64(bits, 52)));
}

/* estep2_sse2() four points at a time; the sums run over the four residues
 * of the point index mod 4. */
__attribute__((target("avx2"))) static double estep2_avx2(const double *P, int n, int nm,
                                                         const double *zero, const double *D,
                                                         double *s_next, int *inf) {
  const double *c0 = P, *c1 = P + n, *c2 = P + 2 * (size_t) n;
  const double *c3 = nm == 6 ? P + 3 * (size_t) n : zero;
  const double *c4 = nm == 6 ? P + 4 * (size_t) n : zero;
  const double *c5 = nm == 6 ? P + 5 * (size_t) n : zero;
  const __m256d d0 = _mm256_set1_pd(D[0]), d1 = _mm256_set1_pd(D[1]), d2 = _mm256_set1_pd(D[2]);
  const __m256d d3 = _mm256_set1_pd(nm == 6 ? D[3] : 0.0),
                d4 = _mm256_set1_pd(nm == 6 ? D[4] : 0.0),
                d5 = _mm256_set1_pd(nm == 6 ? D[5] : 0.0);
  __m256d s0 = _mm256_setzero_pd(), s1 = s0, s2 = s0, s3 = s0, s4 = s0, s5 = s0;
  __m256d prod = _mm256_set1_pd(1.0);
  const __m256d one = _mm256_set1_pd(1.0), lim = _mm256_set1_pd(230.0),
                big = _mm256_set1_pd(1e200);
  const __m256d absmask = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  double logs = 0.0;
  int hit = 0, i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d p0 = _mm256_loadu_pd(c0 + i), p1 = _mm256_loadu_pd(c1 + i),
                  p2 = _mm256_loadu_pd(c2 + i), p3 = _mm256_loadu_pd(c3 + i),
                  p4 = _mm256_loadu_pd(c4 + i), p5 = _mm256_loadu_pd(c5 + i);
    __m256d v = _mm256_mul_pd(p0, d0);
    v = _mm256_add_pd(v, _mm256_mul_pd(p1, d1));
    v = _mm256_add_pd(v, _mm256_mul_pd(p2, d2));
    v = _mm256_add_pd(v, _mm256_mul_pd(p3, d3));
    v = _mm256_add_pd(v, _mm256_mul_pd(p4, d4));
    v = _mm256_add_pd(v, _mm256_mul_pd(p5, d5));
    __m256d z;
    if (_mm256_movemask_pd(_mm256_cmp_pd(_mm256_and_pd(v, absmask), lim, _CMP_NLE_UQ))) {
      double vv[4], zz[4];
      _mm256_storeu_pd(vv, v);
      for (int b = 0; b < 4; b++) {
        double e = exp(vv[b]);
        zz[b] = 1.0 / (1.0 + e);
        if (e == R_PosInf) hit = 1;
        logs += log1p(e);
      }
      z = _mm256_loadu_pd(zz);
    } else {
      __m256d e1 = _mm256_add_pd(one, exp_pd4(v));
      z = _mm256_div_pd(one, e1);
      prod = _mm256_mul_pd(prod, e1);
      if (_mm256_movemask_pd(_mm256_cmp_pd(prod, big, _CMP_GT_OQ))) {
        double pp[4];
        _mm256_storeu_pd(pp, prod);
        logs += log(pp[0]) + log(pp[1]) + log(pp[2]) + log(pp[3]);
        prod = one;
      }
    }
    s0 = _mm256_add_pd(s0, _mm256_mul_pd(p0, z));
    s1 = _mm256_add_pd(s1, _mm256_mul_pd(p1, z));
    s2 = _mm256_add_pd(s2, _mm256_mul_pd(p2, z));
    s3 = _mm256_add_pd(s3, _mm256_mul_pd(p3, z));
    s4 = _mm256_add_pd(s4, _mm256_mul_pd(p4, z));
    s5 = _mm256_add_pd(s5, _mm256_mul_pd(p5, z));
  }
  double pp[4], ss[6], t4[4];
  _mm256_storeu_pd(pp, prod);
  __m256d sv[6] = {s0, s1, s2, s3, s4, s5};
  for (int m = 0; m < 6; m++) {
    _mm256_storeu_pd(t4, sv[m]);
    ss[m] = (t4[0] + t4[1]) + (t4[2] + t4[3]);
  }
  double tail = 0.0;
  for (; i < n; i++) { /* the last n mod 4 points */
    double v = 0.0;
    for (int m = 0; m < nm; m++) v += P[(size_t) m * n + i] * D[m];
    double e = exp(v);
    double z = 1.0 / (1.0 + e);
    for (int m = 0; m < nm; m++) ss[m] += P[(size_t) m * n + i] * z;
    if (e == R_PosInf) hit = 1;
    tail += log1p(e);
  }
  for (int m = 0; m < nm; m++) s_next[m] = ss[m];
  *inf = hit;
  return logs + (log(pp[0]) + log(pp[1])) + (log(pp[2]) + log(pp[3])) + tail;
}

static int hm_cpu_avx2(void) {
  static int has = -1;
  if (has < 0) has = __builtin_cpu_supports("avx2") ? 1 : 0;
  return has;
}
#endif /* HM_AVX2 */
#endif /* SSE2 */

/* The E-step pass of one start: `simd` caps the instruction set (0 scalar,
 * 1 SSE2, 2 AVX2; tests run all three), within what was compiled and what
 * the CPU has. */
static double estep2_any(int simd, const double *P, const double *Pt, const double *zero, int n,
                         int nm, const double *D, double *s_next, int *inf) {
#if defined(__SSE2__) && !defined(HM_NO_SIMD)
#ifdef HM_AVX2
  if (simd >= 2 && hm_cpu_avx2()) return estep2_avx2(P, n, nm, zero, D, s_next, inf);
#endif
  if (simd >= 1) return estep2_sse2(P, n, nm, zero, D, s_next, inf);
#endif
  (void) P;
  (void) zero;
  (void) simd;
  return nm == 3 ? estep2(Pt, n, 3, D, s_next, inf) : estep2(Pt, n, 6, D, s_next, inf);
}

/* R's overflow-safe alternative: sum_i log1pexp(-neg_i), i.e.
 * -sum(plogis(neg, log.p = TRUE)), long double as .colSums. */
static double estep2_plogis(const double *Pt, int n, int nm, const double *D) {
  long double acc = 0;
  for (int i = 0; i < n; i++) {
    const double *pi = Pt + (size_t) i * nm;
    double v = 0.0;
    for (int m = 0; m < nm; m++) v += pi[m] * D[m];
    acc += hm_log1pexp(-v);
  }
  return (double) acc;
}

SEXP hm_gmm_em(SEXP P_, SEXP labels_, SEXP k_, SEXP max_iter_, SEXP tol_, SEXP logdet0_,
               SEXP simd_) {
  if (!isReal(P_) || !isMatrix(P_)) error("'P' must be a double matrix");
  if (!isInteger(labels_) || !isMatrix(labels_)) error("'labels' must be an integer matrix");
  const int n = nrows(P_), nm = ncols(P_), S = ncols(labels_);
  const int k = asInteger(k_), max_iter = asInteger(max_iter_);
  const double tol = asReal(tol_), logdet0 = asReal(logdet0_);
  const int simd = asInteger(simd_);
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

  /* column sums of the monomials (colSums: long double) */
  double *psum = (double *) R_alloc(nm, sizeof(double));
  for (int m = 0; m < nm; m++) {
    long double acc = 0;
    for (int i = 0; i < n; i++) acc += P[(size_t) m * n + i];
    psum[m] = (double) acc;
  }

  /* k = 2 keeps per start only the first component's statistics (the
   * second's are psum minus them) and the E-step's log-ratio coefficients;
   * other k keep the responsibilities */
  double *Pt = (double *) R_alloc((size_t) n * nm, sizeof(double)); /* point-major P */
  for (int i = 0; i < n; i++)
    for (int m = 0; m < nm; m++) Pt[(size_t) i * nm + m] = P[(size_t) m * n + i];
  double *zero = (double *) R_alloc(n, sizeof(double)); /* (see estep2_sse2) */
  for (int i = 0; i < n; i++) zero[i] = 0.0;
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
        double lse = estep2_any(simd, P, Pt, zero, n, nm, D, s1, inf_hit + q);
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
        long double tot = 0;
        for (int i = 0; i < n; i++) {
          double top = Lw[i];
          for (int j = 1; j < k; j++)
            if (Lw[(size_t) j * n + i] > top) top = Lw[(size_t) j * n + i];
          long double se = 0;
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
 * their group's mean (long double, as colMeans), empty groups keep their
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
    long double *acc = (long double *) R_alloc((size_t) k * d, sizeof(long double));
    int *cnt = (int *) R_alloc(k, sizeof(int));
    for (int q = 0; q < k * d; q++) cen[q] = REAL(c0)[q];
    int *lab = lab_all + (size_t) s * n;
    for (int i = 0; i < n; i++) lab[i] = 0;
    for (int pass = 0; pass < iters; pass++) {
      for (int g = 0; g < k; g++) { /* rowSums(centres^2): long double */
        long double s2 = 0;
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
