/* The checks every recording of a grasps set passes (validate_grasps(),
 * R/grasps.R), in one pass over the set: an R-level vapply() per check
 * (is.matrix, is.numeric, dim, dimnames, sum for finiteness) cost 0.39 s
 * for the 89,100 recordings of ten times the default data, before every
 * fit, classification and subset of such a set.
 *
 * Returns, for each recording, the first check it fails, in the order
 * validate_grasps() reports them (0 when it passes them all):
 *   1 not a numeric (double or integer) matrix
 *   2 no frames
 *   3 not one column per DoF            (skipped when `dofs` is NULL)
 *   4 column names other than `dofs`    (identical(), skipped likewise)
 *   5 a frame count other than `n_frames`'s (skipped when it is NULL)
 *   6 a missing or infinite value       (only when `finite` is TRUE)
 * R builds the messages, naming the recordings, from these codes. */
#include <R.h>
#include <Rinternals.h>
#include <math.h>

static int recording_fault(SEXP x, SEXP dofs, SEXP n_frames, R_xlen_t i, int finite) {
  if (TYPEOF(x) != REALSXP && TYPEOF(x) != INTSXP) return 1;
  SEXP dim = getAttrib(x, R_DimSymbol);
  if (TYPEOF(dim) != INTSXP || XLENGTH(dim) != 2) return 1;
  int rows = INTEGER(dim)[0];
  if (rows == 0) return 2;
  if (dofs != R_NilValue) {
    if (INTEGER(dim)[1] != XLENGTH(dofs)) return 3;
    SEXP dn = getAttrib(x, R_DimNamesSymbol);
    SEXP cols = dn == R_NilValue ? R_NilValue : VECTOR_ELT(dn, 1);
    /* flags 16: identical()'s defaults */
    if (cols != dofs && !R_compute_identical(cols, dofs, 16)) return 4;
  }
  if (n_frames != R_NilValue) {
    if (TYPEOF(n_frames) == INTSXP) {
      int nf = INTEGER(n_frames)[i];
      if (nf == NA_INTEGER || nf != rows) return 5;
    } else {
      double nf = REAL(n_frames)[i];
      if (ISNAN(nf) || nf != (double) rows) return 5;
    }
  }
  if (finite) {
    R_xlen_t n = XLENGTH(x);
    if (TYPEOF(x) == REALSXP) {
      /* isfinite() of math.h, not R_FINITE: in a package R_FINITE is a
       * call of R_finite() per value, and at ten times the default data
       * (75 million values) the checks took 0.16 s before every fit; a
       * block's values are tested without a branch each (the compiler
       * keeps the block's loop free of exits), one exit per block */
      const double *v = REAL(x);
      for (R_xlen_t j0 = 0; j0 < n; j0 += 256) {
        R_xlen_t j1 = j0 + 256 < n ? j0 + 256 : n;
        int bad = 0;
        for (R_xlen_t j = j0; j < j1; j++) bad |= !isfinite(v[j]);
        if (bad) return 6;
      }
    } else {
      const int *v = INTEGER(x);
      for (R_xlen_t j = 0; j < n; j++) if (v[j] == NA_INTEGER) return 6;
    }
  }
  return 0;
}

SEXP hm_recording_faults(SEXP recs, SEXP dofs, SEXP n_frames, SEXP finite) {
  if (TYPEOF(recs) != VECSXP) error("recordings must be a list");
  R_xlen_t n = XLENGTH(recs);
  if (dofs != R_NilValue && TYPEOF(dofs) != STRSXP) error("dofs must be character or NULL");
  if (n_frames != R_NilValue &&
      ((TYPEOF(n_frames) != INTSXP && TYPEOF(n_frames) != REALSXP) || XLENGTH(n_frames) != n)) {
    error("n_frames must be numeric, one per recording, or NULL");
  }
  int check_finite = asLogical(finite) == TRUE;
  SEXP out = PROTECT(allocVector(INTSXP, n));
  int *code = INTEGER(out);
  for (R_xlen_t i = 0; i < n; i++) code[i] = recording_fault(VECTOR_ELT(recs, i), dofs, n_frames, i, check_finite);
  UNPROTECT(1);
  return out;
}
