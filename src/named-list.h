/* The one way the package's native routines return several results: a named
 * R list built from values the caller has already PROTECTed. The list itself
 * comes back unprotected, so callers return it right after their UNPROTECT. */
#ifndef HANDMOTION_NAMED_LIST_H
#define HANDMOTION_NAMED_LIST_H

#include <R.h>
#include <Rinternals.h>

static inline SEXP hm_named_list(int n, const char *const *names, const SEXP *values) {
  SEXP out = PROTECT(allocVector(VECSXP, n));
  SEXP nms = PROTECT(allocVector(STRSXP, n));
  for (int i = 0; i < n; i++) {
    SET_VECTOR_ELT(out, i, values[i]);
    SET_STRING_ELT(nms, i, mkChar(names[i]));
  }
  setAttrib(out, R_NamesSymbol, nms);
  UNPROTECT(2);
  return out;
}

#endif
