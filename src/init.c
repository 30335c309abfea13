/* Registration of the package's native routines (R_registerRoutines), so that
 * .Call() entries are looked up by symbol and R CMD check finds them declared.
 * Each routine's prototype is declared here; add new ones to call_methods. */
#include <R.h>
#include <Rinternals.h>
#include <R_ext/Rdynload.h>

static const R_CallMethodDef call_methods[] = {
  {NULL, NULL, 0}
};

void R_init_handmotion(DllInfo *dll) {
  R_registerRoutines(dll, NULL, call_methods, NULL, NULL);
  R_useDynamicSymbols(dll, FALSE);
}
