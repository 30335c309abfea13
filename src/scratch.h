/* Scratch arrays for one .Call, from R_alloc (R frees them when the call
 * returns, or at an error's jump). The arrays of one type and length are
 * made by one line, HM_SCRATCH_REALS(len, &a, &b, ...), rather than a cast
 * and a sizeof for each. The pointers to fill are passed as an array (a
 * compound literal ended by NULL), so the compiler checks each one's type. */
#ifndef HANDMOTION_SCRATCH_H
#define HANDMOTION_SCRATCH_H

#include <R.h>
#include <stddef.h>

static inline void hm_scratch_reals(size_t len, double **const *p) {
  for (; *p != NULL; p++) **p = (double *) R_alloc(len, sizeof(double));
}

static inline void hm_scratch_ints(size_t len, int **const *p) {
  for (; *p != NULL; p++) **p = (int *) R_alloc(len, sizeof(int));
}

#define HM_SCRATCH_REALS(len, ...) \
  hm_scratch_reals((size_t) (len), (double **const[]) {__VA_ARGS__, NULL})
#define HM_SCRATCH_INTS(len, ...) \
  hm_scratch_ints((size_t) (len), (int **const[]) {__VA_ARGS__, NULL})

#endif
