/* Registration of the package's native routines (R_registerRoutines), so that
 * .Call() entries are looked up by symbol and R CMD check finds them declared.
 * Each routine's prototype is declared here; add new ones to call_methods. */
#include <R.h>
#include <Rinternals.h>
#include <R_ext/Rdynload.h>

SEXP hm_dtw_pair(SEXP x, SEXP y, SEXP window); /* dtw.c */
SEXP hm_dtw_batch(SEXP recs, SEXP tmpl, SEXP window, SEXP full); /* dtw.c */
SEXP hm_dtw_pattern(SEXP x, SEXP y, SEXP table); /* dtw-slope.c */
SEXP hm_lwr_predict(SEXP ref_x, SEXP ref_y, SEXP query, SEXP k, SEXP ridge, SEXP eps); /* handover-lwr.c */
SEXP hm_generate_batch(SEXP n, SEXP dof_smp, SEXP warp_smp, SEXP mean, SEXP comps,
                       SEXP warp_mean, SEXP warp_comps, SEXP do_warp, SEXP dofs, SEXP alpha_in,
                       SEXP beta_in, SEXP lim_lo, SEXP lim_hi, SEXP margin); /* generate-kernel.c */
SEXP hm_gmm_em(SEXP P, SEXP state, SEXP k, SEXP max_iter, SEXP tol, SEXP logdet0); /* gmm-em.c */
SEXP hm_gmm_kmeans(SEXP Y, SEXP centres, SEXP iters); /* gmm-em.c */
SEXP hm_shape_features(SEXP recs, SEXP k); /* dba-prep.c */
SEXP hm_linear_mean(SEXP recs, SEXP warps, SEXP which); /* dba-prep.c */
SEXP hm_stall_lengths(SEXP warps); /* dba-prep.c */
SEXP hm_copula_draw(SEXP n, SEXP root, SEXP grid, SEXP quantiles); /* copula-draw.c */
SEXP hm_project_batch(SEXP values, SEXP rows, SEXP nxt, SEXP frac, SEXP mean, SEXP comps,
                      SEXP weights, SEXP norm_weights); /* project-kernel.c */
SEXP hm_project_warped(SEXP recs, SEXP cols, SEXP u, SEXP mean, SEXP comps, SEXP weights,
                       SEXP norm_weights, SEXP mode); /* project-kernel.c */
SEXP hm_lda_w2(SEXP F, SEXP rows, SEXP cls, SEXP means, SEXP inv_s); /* lda-moments.c */
SEXP hm_mmd_permutations(SEXP K, SEXP n, SEXP perms); /* mmd-permutations.c */
SEXP hm_channel_ranges(SEXP recs, SEXP p); /* channel-ranges.c */
SEXP hm_plain_text(SEXP files, SEXP sizes); /* plain-text.c */
SEXP hm_motion_base(SEXP X, SEXP rest_n, SEXP lag); /* motion-signals.c */
SEXP hm_kernel_loo_lse(SEXP D2, SEXP grid); /* kernel-loo.c */
SEXP hm_kernel_score_lse(SEXP A, SEXP rs, SEXP cs, SEXP h); /* kernel-score.c */
SEXP hm_stack_values(SEXP recs, SEXP dofs); /* stack-values.c */

static const R_CallMethodDef call_methods[] = {
  {"hm_dtw_pair", (DL_FUNC) &hm_dtw_pair, 3}, {"hm_dtw_batch", (DL_FUNC) &hm_dtw_batch, 4},
  {"hm_dtw_pattern", (DL_FUNC) &hm_dtw_pattern, 3},
  {"hm_lwr_predict", (DL_FUNC) &hm_lwr_predict, 6},
  {"hm_generate_batch", (DL_FUNC) &hm_generate_batch, 14},
  {"hm_gmm_em", (DL_FUNC) &hm_gmm_em, 6}, {"hm_gmm_kmeans", (DL_FUNC) &hm_gmm_kmeans, 3},
  {"hm_shape_features", (DL_FUNC) &hm_shape_features, 2},
  {"hm_linear_mean", (DL_FUNC) &hm_linear_mean, 3},
  {"hm_stall_lengths", (DL_FUNC) &hm_stall_lengths, 1},
  {"hm_project_batch", (DL_FUNC) &hm_project_batch, 8},
  {"hm_project_warped", (DL_FUNC) &hm_project_warped, 8},
  {"hm_copula_draw", (DL_FUNC) &hm_copula_draw, 4},
  {"hm_lda_w2", (DL_FUNC) &hm_lda_w2, 5},
  {"hm_mmd_permutations", (DL_FUNC) &hm_mmd_permutations, 3},
  {"hm_channel_ranges", (DL_FUNC) &hm_channel_ranges, 2},
  {"hm_plain_text", (DL_FUNC) &hm_plain_text, 2},
  {"hm_motion_base", (DL_FUNC) &hm_motion_base, 3},
  {"hm_kernel_loo_lse", (DL_FUNC) &hm_kernel_loo_lse, 2},
  {"hm_kernel_score_lse", (DL_FUNC) &hm_kernel_score_lse, 4},
  {"hm_stack_values", (DL_FUNC) &hm_stack_values, 2},
  {NULL, NULL, 0}
};

void R_init_handmotion(DllInfo *dll) {
  R_registerRoutines(dll, NULL, call_methods, NULL, NULL);
  R_useDynamicSymbols(dll, FALSE);
}
