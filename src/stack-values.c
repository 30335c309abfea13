/* The values of a list of double matrices one after the other (what
 * unlist(recordings, use.names = FALSE) gives), in one pass of memcpy():
 * packing a type's recordings for a worker (R/transport.R) with unlist()
 * took a second at ten times the default data, serially, before the first
 * worker could start. */
#include <R.h>
#include <Rinternals.h>
#include <string.h>

SEXP hm_stack_values(SEXP recs) {
  R_xlen_t n = XLENGTH(recs), total = 0;
  for (R_xlen_t r = 0; r < n; r++) {
    SEXP x = VECTOR_ELT(recs, r);
    if (TYPEOF(x) != REALSXP) error("hm_stack_values: recording %ld is not double", (long) r + 1);
    total += XLENGTH(x);
  }
  SEXP out = PROTECT(allocVector(REALSXP, total));
  double *v = REAL(out);
  for (R_xlen_t r = 0; r < n; r++) {
    SEXP x = VECTOR_ELT(recs, r);
    R_xlen_t m = XLENGTH(x);
    if (m) memcpy(v, REAL(x), m * sizeof(double));
    v += m;
  }
  UNPROTECT(1);
  return out;
}
