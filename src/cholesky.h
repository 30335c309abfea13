/* The package's one Cholesky factorisation, for the Gaussian mixtures'
 * M-step (gmm-em.c) and the hand-over's local regressions (handover-lwr.c),
 * and the solve with its factor. */
#ifndef HANDMOTION_CHOLESKY_H
#define HANDMOTION_CHOLESKY_H

#include <math.h>
#include <stddef.h>

/* Cholesky factor R (upper triangular, S = R'R, d x d column-major, the
 * lower triangle zero) of the symmetric S, read from its upper triangle; 0
 * when a pivot is not positive (or NaN), as LAPACK's dpotrf behind chol()
 * fails. R must not overlap S. */
static inline int hm_chol_upper(int d, const double *S, double *R) {
  for (int q = 0; q < d * d; q++) R[q] = 0.0;
  for (int j = 0; j < d; j++) {
    double piv = S[j + (size_t) j * d];
    for (int c = 0; c < j; c++) piv -= R[c + (size_t) j * d] * R[c + (size_t) j * d];
    if (!(piv > 0.0)) return 0;
    double rjj = sqrt(piv);
    R[j + (size_t) j * d] = rjj;
    for (int i = j + 1; i < d; i++) {
      double v = S[j + (size_t) i * d];
      for (int c = 0; c < j; c++) v -= R[c + (size_t) j * d] * R[c + (size_t) i * d];
      R[j + (size_t) i * d] = v / rjj;
    }
  }
  return 1;
}

/* Solve R'R x = b for q right-hand sides (b is d x q, overwritten), R from
 * hm_chol_upper(): forward through R', then back through R. */
static inline void hm_chol_solve(const double *R, int d, double *b, int q) {
  for (int c = 0; c < q; c++) {
    double *x = b + (size_t) c * d;
    for (int i = 0; i < d; i++) {
      double t = x[i];
      for (int k = 0; k < i; k++) t -= R[k + (size_t) i * d] * x[k];
      x[i] = t / R[i + (size_t) i * d];
    }
    for (int i = d - 1; i >= 0; i--) {
      double t = x[i];
      for (int k = i + 1; k < d; k++) t -= R[i + (size_t) k * d] * x[k];
      x[i] = t / R[i + (size_t) i * d];
    }
  }
}

#endif
