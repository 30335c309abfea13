/* The one way the DTW routines return a single alignment:
 * list(index1, index2, distance), the path 1-based from the origin to the
 * end. The backtracking routines hold it 0-based, some from the origin and
 * some from the end, so the direction is the caller's to say. */
#ifndef HANDMOTION_WARP_PATH_H
#define HANDMOTION_WARP_PATH_H

#include <R.h>
#include <Rinternals.h>
#include "named-list.h"

/* pi, pj: len 0-based cells; from_end: nonzero when pi[0], pj[0] is the
 * path's last cell rather than its first. */
static inline SEXP hm_warp_path(const int *pi, const int *pj, int len, int from_end,
                                double distance) {
  SEXP i1 = PROTECT(allocVector(INTSXP, len));
  SEXP i2 = PROTECT(allocVector(INTSXP, len));
  int *o1 = INTEGER(i1), *o2 = INTEGER(i2);
  for (int a = 0; a < len; a++) {
    const int s = from_end ? len - 1 - a : a;
    o1[a] = pi[s] + 1;
    o2[a] = pj[s] + 1;
  }
  SEXP d = PROTECT(ScalarReal(distance));
  const char *names[] = {"index1", "index2", "distance"};
  const SEXP values[] = {i1, i2, d};
  SEXP out = hm_named_list(3, names, values);
  UNPROTECT(3);
  return out;
}

#endif
