# The thesis' chapter-5 tables, computed from the package's own results and
# laid beside the published values (thesis_results). The published values are
# joined on the grasp type only after our numbers are computed: they never
# feed a computation.

# What each table holds, for the error listing them (the order of `id`'s
# choices).
thesis_table_contents <- c(
  "5.1" = "warping and mixture fallbacks per model ({.arg models})",
  "5.2" = "variance explained by two FPCs per DoF ({.arg models})",
  "5.3" = "mean FPCA distance, model x true type ({.arg classification})",
  "5.3 claims" = "the counts section 5.2 states about Table 5.3 ({.arg classification})",
  "5.6" = "FPCA classifier: correct per true type and recall ({.arg confusion})",
  "5.7" = "cumulative variance of the last-frame PCs ({.arg fit})",
  "5.8" = "last-frame PCA classifier: correct per true type and recall ({.arg confusion})"
)

#' The thesis' chapter-5 tables, ours beside the published values
#'
#' `thesis_table(id, ...)` returns one of the tables of chapter 5 of Jeppsson
#' (2017) as a data frame ready for `knitr::kable()`, one row per grasp type,
#' with our values and the thesis' published value (prefixed `thesis_`) side by
#' side where one exists (see [thesis_results]).
#'
#' * `"5.1"` (`models`): warping target length, warping method (DTW or the
#'   linear fallback) and the DoFs whose mixture fell back to a single
#'   Gaussian, plus how many recordings were used and removed.
#' * `"5.2"` (`models`): variance explained (percent) by two FPCs per DoF,
#'   summarised over DoFs: min, median, mean and max.
#' * `"5.3"` (`classification`, optional `x`): mean FPCA distance x 100 / T
#'   (rows = model, columns = true type); `"5.3 claims"` checks the counts
#'   section 5.2 states about it (attribute `most_attracting`: the model that is
#'   closest for the most types).
#' * `"5.6"` / `"5.8"` (`confusion`, optional `held_out`): per true type, the
#'   correctly classified recordings (the confusion-matrix diagonal), the total
#'   and the recall, for the FPCA and the last-frame PCA classifier; a held-out
#'   (leave-one-subject-out) confusion matrix adds its recall beside.
#' * `"5.7"` (`fit`, optional `pcs`): cumulative variance explained by the
#'   first PCs of last-frame PCA per type.
#'
#' @param id Which table: `"5.1"`, `"5.2"`, `"5.3"`, `"5.3 claims"`, `"5.6"`,
#'   `"5.7"` or `"5.8"`.
#' @param ... The table's inputs, named as listed above: `models` (a
#'   [fit_grasp_models()] result), `classification` (a [classify()] result of
#'   the FPCA classifier) and `x`, `confusion` (a [grasp_confusion()] or
#'   [classify()] result) and `held_out` (a [grasp_confusion()] of a held-out
#'   evaluation, [evaluate_loso()]; its recall is added as `recall_held_out`),
#'   `fit` (a `fit_grasp_classifier(method = "last_frame")` result) and `pcs` (which cumulative
#'   proportions to show; default the first five, as the thesis classifies
#'   with five PCs).
#' @return A data frame (class `thesis_table`): shares (recalls, the
#'   cumulative proportions of Table 5.7) are stored as fractions and printed
#'   as percentages, other decimals printed to one place.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = c(9, 22), objects = 2, trials = 2, seed = 1)
#' ms <- fit_grasp_models(g, seed = 1)
#' thesis_table("5.1", models = ms)
#' thesis_table("5.2", models = ms)
#' cl <- classify(ms, g)
#' thesis_table("5.3", classification = cl)
#' thesis_table("5.6", confusion = grasp_confusion(cl))
#' lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
#' thesis_table("5.7", fit = lf, pcs = 1:3)
thesis_table <- function(id = c("5.1", "5.2", "5.3", "5.3 claims", "5.6", "5.7", "5.8"), ...) {
  call <- rlang::caller_env()
  if (is.numeric(id)) id <- format(id, nsmall = 1)
  if (identical(id, eval(formals(thesis_table)$id))) id <- id[1]
  if (!(is.character(id) && length(id) == 1L && !is.na(id) && id %in% names(thesis_table_contents))) {
    # not a guess at the nearest id: every table there is, with what it holds
    tables <- sprintf("{.val %s}: %s", names(thesis_table_contents), thesis_table_contents)
    hm_abort(c("{.arg id} must be one of the thesis' tables handmotion reproduces, not {describe_value(id)}.",
               i = "The tables (see {.help handmotion::thesis_table}):",
               stats::setNames(tables, rep("*", length(tables)))),
             "bad_input", argument = "id", call = call)
  }
  build <- switch(id,
    "5.1" = thesis_table_5_1, "5.2" = thesis_table_5_2, "5.3" = thesis_table_5_3,
    "5.3 claims" = thesis_table_5_3_claims, "5.6" = thesis_table_5_6,
    "5.7" = thesis_table_5_7, "5.8" = thesis_table_5_8)
  args <- list(...)
  known <- names(formals(build))
  if (length(args) && (is.null(names(args)) || any(!nzchar(names(args))) ||
                       any(!names(args) %in% known))) {
    hm_abort(c("Table {id} takes {.arg {known}}, named.",
               x = "Got: {.val {names(args) %||% rep('(unnamed)', length(args))}}."),
             "bad_input", argument = "...", call = call)
  }
  # the thesis' tables are per Feix type: say so for other labels
  for (a in names(args)) {
    lab <- thesis_input_labels(args[[a]])
    if (!is.null(lab) && length(lab) && !all(lab %in% feix_levels())) {
      check_feix_labels(factor(lab), sprintf("Table %s of the thesis", id), arg = a, call = call)
    }
  }
  out <- do.call(build, args)
  # shares print as percentages (the data keep the fractions)
  percent <- grep("^(thesis_)?(recall(_held_out)?|pc[0-9]+)$", names(out), value = TRUE)
  new_thesis_table(out, id, percent = percent, digits = 1L)
}

# The class labels an input of a thesis table holds (NULL when it has none).
thesis_input_labels <- function(x) {
  if (inherits(x, "grasp_models")) return(names(x))
  if (inherits(x, "grasp_classification")) return(colnames(x$distances))
  if (inherits(x, "grasp_confusion")) return(rownames(x$table))
  if (inherits(x, "grasps")) return(as.character(unique(stats::na.omit(x$meta$grasp))))
  NULL
}

thesis_table_5_1 <- function(models) {
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

thesis_table_5_2 <- function(models) {
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

thesis_table_5_3 <- function(classification, x = NULL) {
  tab <- distance_table(classification, x)
  out <- as.data.frame(unclass(tab), stringsAsFactors = FALSE, check.names = FALSE)
  ids <- match(colnames(tab), feix_levels())
  names(out) <- ids
  cbind(model_id = match(rownames(tab), feix_levels()), model = rownames(tab), out,
        stringsAsFactors = FALSE)
}

thesis_table_5_3_claims <- function(classification, x = NULL) {
  tab <- distance_table(classification, x)
  mins <- distance_minima(tab)
  th <- handmotion::thesis_results$table_5_3_claims
  ours <- as.integer(unlist(mins[th$claim]))
  out <- data.frame(claim = th$claim, description = th$description, ours = ours, thesis = th$thesis,
                    stringsAsFactors = FALSE)
  attr(out, "most_attracting") <- mins$most_attracting
  out
}

thesis_table_5_6 <- function(confusion, held_out = NULL) {
  diagonal_table(confusion, held_out, handmotion::thesis_results$table_5_6_diagonal)
}

thesis_table_5_7 <- function(fit, pcs = 1:5) {
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

thesis_table_5_8 <- function(confusion, held_out = NULL) {
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
    out$recall_held_out <- ifelse(ht > 0, hc / ht, NA_real_)
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
