# Model and type effects of Table 5.3 (issue 14, claims G1 and G2). The log of
# a mean projection distance splits additively into an overall level, a model
# effect (how far a model is from every type), a type effect (how far a type's
# recordings are from every model) and a pairwise residual. A row minimum
# (G1) cannot depend on the model effect, which is constant along the row,
# nor a column minimum (G2) on the type effect, so the split says which part
# of the table sets each count. The thesis report (reproduce_thesis(), its
# Table 5.3 section) uses this decomposition; no other verb does.

#' Split a Table 5.3 distance table into model, type and pairwise effects
#'
#' `log(tab) = level + model_i + type_j + residual_ij`, with the model and type
#' effects centred (the two-way additive fit of a complete table, by row and
#' column means). The own-type residual (the diagonal) is how much better a
#' model fits its own type than its two effects predict.
#'
#' @param tab A `distance_table()` result over the same types in its rows
#'   (models) and columns (true types); the columns are put in the rows' order.
#' @return A list: `level`, `model` and `type` (named effect vectors),
#'   `residual` (matrix), `own` (mean diagonal residual), `closest_other` (a
#'   data frame per model: the other type with the smallest residual and that
#'   residual) and `counts`: G1 with the type effects removed
#'   (`model_min_own_type_without_type_effects`) and G2 with the model effects
#'   removed (`type_min_own_model_without_model_effects`).
#' @seealso `distance_minima()` counts the minima of the table as it is.
#' @noRd
#' @examples
#' tab <- exp(outer(c(a = 0, b = 0.2, c = 0.4), c(a = 0, b = 0, c = 0), `+`) - 0.5 * diag(3))
#' dimnames(tab) <- list(model = c("a", "b", "c"), truth = c("a", "b", "c"))
#' distance_effects(tab)$model
distance_effects <- function(tab, call = rlang::caller_env()) {
  if (!is.matrix(tab) || !is.numeric(tab) || nrow(tab) < 2L || is.null(rownames(tab)) ||
      !setequal(rownames(tab), colnames(tab)) || nrow(tab) != ncol(tab)) {
    hm_abort(c("{.arg tab} must be a distance table with the same types as models (rows) and true types (columns).",
               i = "Give the {.code thesis_table(\"5.3\", classification = )} of a classification over every modelled type."),
             "bad_input", argument = "tab", call = call)
  }
  tab <- tab[, rownames(tab), drop = FALSE]
  if (any(!is.finite(tab) | tab <= 0)) {
    hm_abort("{.arg tab} has distances that are missing, infinite or not positive; their logarithm cannot be split.",
             "bad_input", argument = "tab", call = call)
  }
  L <- log(tab)
  level <- mean(L)
  model <- rowMeans(L) - level
  type <- colMeans(L) - level
  residual <- L - level - outer(model, type, `+`)
  off <- residual
  diag(off) <- Inf
  closest <- max.col(-off, ties.method = "first")
  list(level = level, model = model, type = type, residual = residual, own = mean(diag(residual)),
       closest_other = data.frame(model = rownames(L), type = colnames(L)[closest],
                                  residual = off[cbind(seq_len(nrow(off)), closest)], stringsAsFactors = FALSE),
       # distance_minima() counts by name and only compares within a row or a
       # column, so it counts the log tables with an effect taken out as well
       counts = c(model_min_own_type_without_type_effects = distance_minima(sweep(L, 2L, type))$model_min_own_type,
                  type_min_own_model_without_model_effects = distance_minima(sweep(L, 1L, model))$type_min_own_model))
}
