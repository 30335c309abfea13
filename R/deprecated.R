# Deprecated aliases of renamed exports: each keeps working, says once per
# session (a classed warning, handmotion_warning_deprecated) what to call
# instead, and is removed in a later release.

#' Deprecated functions
#'
#' These names were renamed; they still work and warn once per session.
#'
#' | deprecated | use instead |
#' |---|---|
#' | `table_5_1(models)` ... `table_5_8(confusion)` | [thesis_table()]`("5.1", models = )` ... |
#' | `table_5_3_claims(classification)` | [thesis_table()]`("5.3 claims", classification = )` |
#'
#' @param models,classification,x,confusion,held_out,fit,pcs As for [thesis_table()].
#' @return What the replacement returns.
#' @name handmotion-deprecated
#' @keywords internal
#' @examples
#' g <- simulate_grasps(subjects = 3, grasps = 9, objects = 1, trials = 2, seed = 1)
#' ms <- fit_grasp_models(g, seed = 1)
#' table_5_1(ms)            # warns: use thesis_table("5.1", models = ms)
NULL

deprecation_state <- new.env(parent = emptyenv())

# Warn (once per session per name) that `old` is deprecated in favour of
# `new`, then return `value` (the replacement's result).
deprecated_alias <- function(old, new, value) {
  if (!isTRUE(deprecation_state[[old]])) {
    assign(old, TRUE, envir = deprecation_state)
    hm_warn("{.code {old}} is deprecated; use {.code {new}} instead.", "deprecated", old = old, new = new)
  }
  value
}
