/* Registration of the package's native routines (R_registerRoutines), so that
 * .Call() entries are looked up by symbol and R CMD check finds them declared.
 * Each routine's prototype is declared here; add new ones to call_methods. */
#include <R.h>
#include <Rinternals.h>
#include <R_ext/Rdynload.h>

SEXP hm_dtw_pair(SEXP x, SEXP y, SEXP window); /* dtw.c */
SEXP hm_dtw_batch(SEXP recs, SEXP tmpl, SEXP window); /* dtw.c */
SEXP hm_lwr_predict(SEXP ref_x, SEXP ref_y, SEXP query, SEXP k, SEXP ridge, SEXP eps); /* handover-lwr.c */
SEXP hm_generate_batch(SEXP mean, SEXP comps, SEXP alpha, SEXP W, SEXP n_new, SEXP dofs); /* generate-kernel.c */

static const R_CallMethodDef call_methods[] = {
  {"hm_dtw_pair", (DL_FUNC) &hm_dtw_pair, 3}, {"hm_dtw_batch", (DL_FUNC) &hm_dtw_batch, 3},
  {"hm_lwr_predict", (DL_FUNC) &hm_lwr_predict, 6},
  {"hm_generate_batch", (DL_FUNC) &hm_generate_batch, 6},
  {NULL, NULL, 0}
};

void R_init_handmotion(DllInfo *dll) {
  R_registerRoutines(dll, NULL, call_methods, NULL, NULL);
  R_useDynamicSymbols(dll, FALSE);
}
