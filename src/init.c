/* Registration of the package's native routines (R_registerRoutines), so that
 * .Call() entries are looked up by symbol and R CMD check finds them declared.
 * Each routine is named once, with its number of arguments, in HM_ROUTINES:
 * its prototype and its entry in the table are both made from that line, so
 * the two cannot disagree. Add new routines there. */
#include <R.h>
#include <Rinternals.h>
#include <R_ext/Rdynload.h>

/* X(name, number of SEXP arguments), one line per source file */
#define HM_ROUTINES(X)                                                     \
  X(hm_dtw_pair, 3) X(hm_dtw_batch, 4)                       /* dtw.c */   \
  X(hm_dtw_pattern, 3)                                 /* dtw-slope.c */   \
  X(hm_lwr_predict, 6)                              /* handover-lwr.c */   \
  X(hm_generate_batch, 14)                       /* generate-kernel.c */   \
  X(hm_gmm_em, 6) X(hm_gmm_kmeans, 3)                     /* gmm-em.c */   \
  X(hm_shape_features, 2) X(hm_linear_mean, 3) X(hm_stall_lengths, 1)      \
  X(hm_unshape_warped, 4)                               /* dba-prep.c */   \
  X(hm_copula_draw, 4)                               /* copula-draw.c */   \
  X(hm_project_batch, 8) X(hm_project_warped, 8)  /* project-kernel.c */   \
  X(hm_lda_w2, 5)                                    /* lda-moments.c */   \
  X(hm_mmd_permutations, 3)                     /* mmd-permutations.c */   \
  X(hm_channel_ranges, 2) X(hm_channel_outside, 4) /* channel-ranges.c */   \
  X(hm_plain_text, 2)                                 /* plain-text.c */   \
  X(hm_motion_base, 3)                            /* motion-signals.c */   \
  X(hm_kernel_loo_lse, 2)                             /* kernel-loo.c */   \
  X(hm_kernel_score_lse, 4)                         /* kernel-score.c */   \
  X(hm_stack_values, 2) X(hm_unstack_values, 4)      /* stack-values.c */ \
  X(hm_recording_faults, 4)                     /* recording-checks.c */ \
  X(hm_rows_of_two, 3)                                /* array-rows.c */ \
  X(hm_first_above, 2) X(hm_last_at_least, 2) X(hm_walk_back, 3)          \
  X(hm_walk_forward, 3) X(hm_col_max, 1)              /* motion-walks.c */ \
  X(hm_curve_spread, 1)                             /* curve-spread.c */

/* the argument lists of n SEXPs */
#define HM_ARGS_1 SEXP
#define HM_ARGS_2 HM_ARGS_1, SEXP
#define HM_ARGS_3 HM_ARGS_2, SEXP
#define HM_ARGS_4 HM_ARGS_3, SEXP
#define HM_ARGS_5 HM_ARGS_4, SEXP
#define HM_ARGS_6 HM_ARGS_5, SEXP
#define HM_ARGS_7 HM_ARGS_6, SEXP
#define HM_ARGS_8 HM_ARGS_7, SEXP
#define HM_ARGS_9 HM_ARGS_8, SEXP
#define HM_ARGS_10 HM_ARGS_9, SEXP
#define HM_ARGS_11 HM_ARGS_10, SEXP
#define HM_ARGS_12 HM_ARGS_11, SEXP
#define HM_ARGS_13 HM_ARGS_12, SEXP
#define HM_ARGS_14 HM_ARGS_13, SEXP

#define HM_PROTOTYPE(name, n) SEXP name(HM_ARGS_##n);
HM_ROUTINES(HM_PROTOTYPE)

#define HM_ENTRY(name, n) {#name, (DL_FUNC) &name, n},
static const R_CallMethodDef call_methods[] = {
  HM_ROUTINES(HM_ENTRY)
  {NULL, NULL, 0}
};

void R_init_handmotion(DllInfo *dll) {
  R_registerRoutines(dll, NULL, call_methods, NULL, NULL);
  R_useDynamicSymbols(dll, FALSE);
}
