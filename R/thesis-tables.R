# The thesis' chapter-5 tables, computed from the package's own results and
# laid beside the published values (thesis_results). The published values are
# joined on the grasp type only after our numbers are computed: they never
# feed a computation.

#' The thesis' chapter-5 tables, ours beside the published values
#'
#' Each function returns a data frame ready for `knitr::kable()`, one row per
#' grasp type, with our values and the thesis' published value (prefixed
#' `thesis_`) side by side where one exists (see [thesis_results]).
#'
#' * `table_5_1()`: warping target length, warping method (DTW or the linear
#'   fallback) and the DoFs whose mixture fell back to a single Gaussian, plus
#'   how many recordings were used and removed.
#' * `table_5_2()`: variance explained (percent) by two FPCs per DoF, summarised
#'   over DoFs: min, median, mean and max.
#' * `table_5_3()`: mean FPCA distance x 100 / T (rows = model, columns = true
#'   type); `table_5_3_claims()` checks the counts section 5.2 states about it.
#' * `table_5_6()` / `table_5_8()`: per true type, the correctly classified
#'   recordings (the confusion-matrix diagonal), the total and the recall, for
#'   the FPCA and the last-frame PCA classifier; an optional held-out
#'   (leave-one-subject-out) confusion matrix adds its recall beside.
#' * `table_5_7()`: cumulative variance explained by the first PCs of
#'   last-frame PCA per type.
#'
#' @param models A [fit_grasp_models()] result.
#' @return A data frame.
#' @name thesis_tables
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = c(9, 22), objects = 2, trials = 2, seed = 1)
#' ms <- fit_grasp_models(g, seed = 1)
#' table_5_1(ms)
#' table_5_2(ms)
#' cl <- classify(ms, g)
#' table_5_3(cl)
#' table_5_6(as_grasp_confusion(cl))
#' lf <- fit_last_frame_pca(g, k = 2)
#' table_5_7(lf, pcs = 1:3)
NULL

#' @rdname thesis_tables
#' @export
table_5_1 <- function(models) {
  s <- model_summary(models)
  out <- data.frame(grasp_id = s$grasp_id, grasp = s$grasp, n_used = s$n_used,
                    n_overlong = s$n_overlong, n_degenerate = s$n_degenerate,
                    target_frames = s$target_length, warping = s$warping,
                    em_fallback_dofs = s$em_fallback, stringsAsFactors = FALSE)
  th <- handmotion::thesis_results$table_5_1
  beside(out, th[c("grasp_id", "target_frames", "warping", "em_failed_dofs")],
         c(target_frames = "thesis_target_frames", warping = "thesis_warping",
           em_failed_dofs = "thesis_em_failed_dofs"))
}

#' @rdname thesis_tables
#' @export
table_5_2 <- function(models) {
  s <- model_summary(models)
  out <- data.frame(grasp_id = s$grasp_id, grasp = s$grasp, min = s$min_var,
                    median = s$median_var, mean = s$mean_var, max = s$max_var)
  th <- handmotion::thesis_results$table_5_2
  out <- beside(out, th[c("grasp_id", "min", "median", "mean", "max")],
                c(min = "thesis_min", median = "thesis_median", mean = "thesis_mean",
                  max = "thesis_max"))
  out$diff_mean <- out$mean - out$thesis_mean
  out[c("grasp_id", "grasp", "min", "thesis_min", "median", "thesis_median", "mean",
        "thesis_mean", "diff_mean", "max", "thesis_max")]
}

#' @rdname thesis_tables
#' @param classification A [classify()] result with `method = "fpca"` (or
#'   `grasp_models`, then `x` is classified first).
#' @param x A labelled [grasps()] object, when `classification` is models.
#' @export
table_5_3 <- function(classification, x = NULL) {
  tab <- distance_table(classification, x)
  out <- as.data.frame(unclass(tab), stringsAsFactors = FALSE, check.names = FALSE)
  ids <- match(colnames(tab), feix_levels())
  names(out) <- ids
  cbind(model_id = match(rownames(tab), feix_levels()), model = rownames(tab), out,
        stringsAsFactors = FALSE)
}

#' @rdname thesis_tables
#' @export
table_5_3_claims <- function(classification, x = NULL) {
  tab <- distance_table(classification, x)
  mins <- distance_minima(tab)
  th <- handmotion::thesis_results$table_5_3_claims
  ours <- as.integer(unlist(mins[th$claim]))
  data.frame(claim = th$claim, description = th$description, ours = ours, thesis = th$thesis,
             stringsAsFactors = FALSE)
}

#' @rdname thesis_tables
#' @param confusion A [grasp_confusion()] (or [classify()] result) of the
#'   in-sample classification.
#' @param held_out Optional [grasp_confusion()] of a held-out evaluation
#'   ([evaluate_loso()]); its recall is added as `recall_loso`.
#' @export
table_5_6 <- function(confusion, held_out = NULL) {
  diagonal_table(confusion, held_out, handmotion::thesis_results$table_5_6_diagonal)
}

#' @rdname thesis_tables
#' @param fit A [fit_last_frame_pca()] result.
#' @param pcs Which cumulative proportions to show (default the first five: the
#'   thesis classifies with five PCs).
#' @export
table_5_7 <- function(fit, pcs = 1:5) {
  cv <- cumulative_variance(fit)
  cols <- paste0("pc", pcs)
  th <- handmotion::thesis_results$table_5_7
  out <- cv[c("grasp_id", "grasp", cols)]
  ref <- th[c("grasp_id", cols)]
  names(ref) <- c("grasp_id", paste0("thesis_", cols))
  out <- merge(out, ref, by = "grasp_id", all.x = TRUE, sort = FALSE)
  out <- out[order(out$grasp_id), c("grasp_id", "grasp", as.vector(rbind(cols, paste0("thesis_", cols))))]
  rownames(out) <- NULL
  out
}

#' @rdname thesis_tables
#' @export
table_5_8 <- function(confusion, held_out = NULL) {
  diagonal_table(confusion, held_out, handmotion::thesis_results$table_5_8_diagonal)
}

# Per true type: correct (diagonal), total (column sum) and recall, ours beside
# the thesis' recovered diagonal and total, plus the held-out recall if given.
diagonal_table <- function(confusion, held_out, thesis) {
  cm <- as_grasp_confusion(confusion)
  m <- unclass(cm$table)
  types <- colnames(m)
  correct <- vapply(types, function(t) if (t %in% rownames(m)) m[t, t] else 0, numeric(1))
  total <- colSums(m)
  out <- data.frame(grasp_id = match(types, feix_levels()), grasp = types,
                    correct = as.integer(correct), total = as.integer(total),
                    recall = ifelse(total > 0, correct / total, NA_real_), stringsAsFactors = FALSE)
  if (!is.null(held_out)) {
    h <- unclass(as_grasp_confusion(held_out)$table)
    hc <- vapply(types, function(t) if (t %in% rownames(h) && t %in% colnames(h)) h[t, t] else NA_real_,
                 numeric(1))
    ht <- vapply(types, function(t) if (t %in% colnames(h)) sum(h[, t]) else NA_real_, numeric(1))
    out$recall_loso <- ifelse(ht > 0, hc / ht, NA_real_)
  }
  ref <- thesis[c("grasp_id", "correct", "total")]
  ref$recall <- ref$correct / ref$total
  beside(out, ref, c(correct = "thesis_correct", total = "thesis_total", recall = "thesis_recall"))
}

# Join the thesis' values (renamed) onto ours by grasp id, keeping our row order.
beside <- function(ours, thesis, rename) {
  names(thesis)[match(names(rename), names(thesis))] <- unname(rename)
  out <- merge(ours, thesis, by = "grasp_id", all.x = TRUE, sort = FALSE)
  out <- out[order(out$grasp_id), , drop = FALSE]
  rownames(out) <- NULL
  out
}

model_summary <- function(models) {
  if (!inherits(models, "grasp_models")) {
    hm_abort("{.arg models} must be a {.cls grasp_models} object from {.fn fit_grasp_models}, not {.obj_type_friendly {models}}.",
             "bad_input", argument = "models", call = rlang::caller_env(2))
  }
  summary(models)
}
