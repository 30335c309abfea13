/* The text of the plain GraspDB14 files of a group, concatenated into one string for
 * one fread() (R/read-graspdb14-fread.R). A file is plain when it holds only the
 * characters of numbers, blanks and line ends; its bytes are read straight into
 * the group's buffer, a line end added when its last line has none, and its line
 * count returned; any other file (or one that cannot be read in full) is left out
 * of the text with NA. In R the same took a readBin() per file, a byte count, a
 * copy to append the line end, an unlist() and a rawToChar(): four copies of
 * every byte of the directory where this makes one. */
#include <R.h>
#include <Rinternals.h>
#include <stdio.h>
#include <string.h>
#include <limits.h>
#include "named-list.h"

SEXP hm_plain_text(SEXP files, SEXP sizes) {
  R_xlen_t n = XLENGTH(files);
  if (TYPEOF(files) != STRSXP || TYPEOF(sizes) != REALSXP || XLENGTH(sizes) != n)
    error("hm_plain_text: 'files' must be character and 'sizes' numeric of the same length");
  const double *size = REAL(sizes);
  double total = 0;
  for (R_xlen_t i = 0; i < n; i++) if (R_FINITE(size[i]) && size[i] > 0) total += size[i] + 1;
  /* one R string holds less than 2 GB: a file past that is left out (NA), for
     the text parser, as readBin() and rawToChar() failing left it before */
  double cap = INT_MAX - 1;
  if (total > cap) total = cap;
  char *buf = R_alloc((size_t) total + 1, 1);
  unsigned char plain[256] = {0};
  for (const char *c = "0123456789.+-eE \t\r\n"; *c; c++) plain[(unsigned char) *c] = 1;
  SEXP n_lines = PROTECT(allocVector(REALSXP, n));
  size_t used = 0;
  for (R_xlen_t i = 0; i < n; i++) {
    REAL(n_lines)[i] = NA_REAL;
    if (!R_FINITE(size[i]) || size[i] <= 0) continue;
    if ((double) used + size[i] + 1 > cap) continue;
    size_t want = (size_t) size[i];
    const char *path = R_ExpandFileName(translateChar(STRING_ELT(files, i)));
    FILE *f = fopen(path, "rb");
    if (!f) continue;
    size_t got = fread(buf + used, 1, want, f);   /* its first `size` bytes, as readBin() read */
    fclose(f);
    if (got != want) continue;
    const unsigned char *b = (const unsigned char *) buf + used;
    double lines = 0;
    int ok = 1;
    for (size_t k = 0; k < want; k++) {
      if (!plain[b[k]]) { ok = 0; break; }
      if (b[k] == '\n') lines++;
    }
    if (!ok) continue;              /* its bytes are overwritten by the next file */
    used += want;
    if (b[want - 1] != '\n') { buf[used++] = '\n'; lines++; }
    REAL(n_lines)[i] = lines;
  }
  SEXP text = PROTECT(ScalarString(mkCharLenCE(buf, (int) used, CE_NATIVE)));
  const char *names[] = {"text", "n_lines"};
  const SEXP values[] = {text, n_lines};
  SEXP out = hm_named_list(2, names, values);
  UNPROTECT(2);
  return out;
}
