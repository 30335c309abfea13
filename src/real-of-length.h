/* The compiled kernels' one check of an array the R side hands them: a
 * double vector of exactly `len` values, or an R error naming the kernel
 * (`who`) and the array (`what`), never a read past its end. */
#ifndef HANDMOTION_REAL_OF_LENGTH_H
#define HANDMOTION_REAL_OF_LENGTH_H

#include <R.h>
#include <Rinternals.h>

static inline const double *hm_real_of_length(SEXP x, R_xlen_t len, const char *who,
                                              const char *what) {
  if (TYPEOF(x) != REALSXP || XLENGTH(x) != len)
    error("%s: %s must be a double vector of %lld values", who, what, (long long) len);
  return REAL(x);
}

#endif
