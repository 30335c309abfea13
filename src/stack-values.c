/* Stacking recordings for a worker and unstacking them there (R/transport.R).
 *
 * The values of a list of double matrices one after the other (what
 * unlist(recordings, use.names = FALSE) gives), in one pass of memcpy():
 * packing a type's recordings for a worker (R/transport.R) with unlist()
 * took a second at ten times the default data, serially, before the first
 * worker could start.
 *
 * Only plain recordings are packed: double matrices whose dimnames are
 * exactly list(NULL, dofs) and nothing else among their attributes besides
 * dim, since the worker rebuilds every recording from the values, its frame
 * count and the set's DoFs alone. Anything else returns NULL (the set then
 * travels as it is). Checked here because an R-level vapply() of
 * identical(dimnames(r), ...) cost half a second of the main process at ten
 * times the default data. */
#include <R.h>
#include <Rinternals.h>
#include <string.h>

static int same_strings(SEXP a, SEXP b) {
  if (TYPEOF(a) != STRSXP || XLENGTH(a) != XLENGTH(b)) return 0;
  for (R_xlen_t j = 0; j < XLENGTH(a); j++) {
    SEXP x = STRING_ELT(a, j), y = STRING_ELT(b, j);
    if (x == y) continue;  /* the same cached string */
    if (x == NA_STRING || y == NA_STRING || strcmp(CHAR(x), CHAR(y)) != 0 ||
        Rf_getCharCE(x) != Rf_getCharCE(y)) return 0;
  }
  return 1;
}

static int plain_recording(SEXP x, SEXP dofs) {
  if (TYPEOF(x) != REALSXP || OBJECT(x)) return 0;
  int n_attr = 0;
  for (SEXP a = ATTRIB(x); a != R_NilValue; a = CDR(a)) n_attr++;
  if (n_attr != 2) return 0;  /* dim and dimnames, nothing else */
  SEXP dim = getAttrib(x, R_DimSymbol);
  if (TYPEOF(dim) != INTSXP || XLENGTH(dim) != 2 || INTEGER(dim)[1] != XLENGTH(dofs)) return 0;
  SEXP dn = getAttrib(x, R_DimNamesSymbol);
  if (TYPEOF(dn) != VECSXP || XLENGTH(dn) != 2 || VECTOR_ELT(dn, 0) != R_NilValue) return 0;
  if (getAttrib(dn, R_NamesSymbol) != R_NilValue) return 0;
  return same_strings(VECTOR_ELT(dn, 1), dofs);
}

SEXP hm_stack_values(SEXP recs, SEXP dofs) {
  if (TYPEOF(recs) != VECSXP || TYPEOF(dofs) != STRSXP) return R_NilValue;
  R_xlen_t n = XLENGTH(recs), total = 0;
  for (R_xlen_t r = 0; r < n; r++) {
    SEXP x = VECTOR_ELT(recs, r);
    if (!plain_recording(x, dofs)) return R_NilValue;
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

/* The inverse on the worker: the recordings of `values` (stacked as above),
 * `n_frames` rows each, with the columns `dofs` and the names `ids`. Each
 * matrix is allocated once and filled by memcpy(), all sharing one dimnames
 * list (marked immutable, so a change to one recording's dimnames copies
 * it): matrix() over R-level slices of the values allocated every
 * recording twice and took 1.7 s of the two workers' CPU at ten times the
 * default data, on a machine where each fresh page costs microseconds. */
SEXP hm_unstack_values(SEXP values, SEXP n_frames, SEXP dofs, SEXP ids) {
  if (TYPEOF(values) != REALSXP || TYPEOF(n_frames) != INTSXP || TYPEOF(dofs) != STRSXP ||
      (ids != R_NilValue && (TYPEOF(ids) != STRSXP || XLENGTH(ids) != XLENGTH(n_frames))))
    Rf_error("hm_unstack_values: values (double), n_frames (integer), dofs and ids (character) expected");
  R_xlen_t n = XLENGTH(n_frames), p = XLENGTH(dofs), total = 0;
  const int *nf = INTEGER(n_frames);
  for (R_xlen_t r = 0; r < n; r++) {
    if (nf[r] == NA_INTEGER || nf[r] < 0) Rf_error("hm_unstack_values: frame count %lld is not a count", (long long) r + 1);
    total += (R_xlen_t) nf[r] * p;
  }
  if (total != XLENGTH(values))
    Rf_error("hm_unstack_values: %lld values for %lld expected", (long long) XLENGTH(values), (long long) total);
  SEXP dn = PROTECT(allocVector(VECSXP, 2));
  SET_VECTOR_ELT(dn, 1, dofs);
  MARK_NOT_MUTABLE(dn);
  SEXP out = PROTECT(allocVector(VECSXP, n));
  const double *v = REAL(values);
  for (R_xlen_t r = 0; r < n; r++) {
    SEXP x = PROTECT(allocMatrix(REALSXP, nf[r], (int) p));
    R_xlen_t m = (R_xlen_t) nf[r] * p;
    if (m) memcpy(REAL(x), v, m * sizeof(double));
    v += m;
    setAttrib(x, R_DimNamesSymbol, dn);
    SET_VECTOR_ELT(out, r, x);
    UNPROTECT(1);
  }
  if (ids != R_NilValue) setAttrib(out, R_NamesSymbol, ids);
  UNPROTECT(2);
  return out;
}
