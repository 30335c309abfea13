# The grasp_confusion class: a confusion matrix modelled on yardstick's
# conf_mat. A list holding `table` (a table with dimnames Prediction x Truth,
# i.e. rows = predicted type / model, columns = true type, the orientation of
# the thesis' Tables 5.6 and 5.8) plus bookkeeping of what could not be
# tabulated (unlabelled recordings, failed predictions), so nothing is lost
# silently.

#' Confusion matrix of grasp-type classifications
#'
#' `grasp_confusion()` cross-tabulates predicted against true grasp types,
#' modelled on `yardstick::conf_mat()`. Rows are the predicted type (the model
#' a recording was assigned to) and columns the true type, as in the thesis'
#' Tables 5.6 and 5.8. Given one argument it builds the matrix from the
#' result of [classify()], from a data frame with `truth` and `predicted`
#' columns, or from a square table (rows = prediction, columns = truth).
#'
#' Pairs where the truth or the prediction is missing cannot be tabulated; they
#' are counted in `$n_missing_truth` and `$n_missing_predicted` and reported by
#' `print()`, never dropped silently.
#'
#' @param truth True grasp types (factor or character); or, without
#'   `predicted`, a [classify()] result (`grasp_classification`), a data frame
#'   with columns `truth` and `predicted`, or a square table / matrix with
#'   rows = prediction and columns = truth.
#' @param predicted Predicted grasp types (factor or character), as long as
#'   `truth`.
#' @param levels Class labels, in display order. By default the union of the
#'   levels seen in `truth` and `predicted`, in Feix order when they are Feix
#'   type names.
#' @return An object of class `grasp_confusion`: a list with `table` (rows =
#'   `Prediction`, columns = `Truth`), `levels`, `n` (tabulated pairs),
#'   `n_missing_truth` and `n_missing_predicted`.
#' @seealso [summary.grasp_confusion()], [autoplot.grasp_confusion()],
#'   [classify()], [evaluate_loso()]
#' @export
#' @examples
#' truth <- c("Tripod", "Tripod", "Ring", "Ring", "Ring")
#' pred <- c("Tripod", "Ring", "Ring", "Ring", "Tripod")
#' cm <- grasp_confusion(truth, pred)
#' cm
#' summary(cm)
#' grasp_confusion(data.frame(truth = truth, predicted = pred))
grasp_confusion <- function(truth, predicted = NULL, levels = NULL) {
  call <- rlang::caller_env()
  if (is.null(predicted)) {
    if (!is.null(levels)) {
      hm_abort("{.arg levels} goes with {.arg truth} and {.arg predicted} vectors.", "bad_input",
               argument = "levels", call = call)
    }
    return(as_grasp_confusion(truth, call = call))
  }
  new_confusion(truth, predicted, levels, call = call)
}

new_confusion <- function(truth, predicted, levels = NULL, call = rlang::caller_env()) {
  if (length(truth) == 0L) {
    hm_abort("{.arg truth} and {.arg predicted} are empty: there is nothing to count.", "bad_input",
             argument = "truth", call = call)
  }
  if (length(truth) != length(predicted)) {
    hm_abort("{.arg truth} ({length(truth)}) and {.arg predicted} ({length(predicted)}) must have the same length.",
             "bad_input", argument = "predicted", call = call)
  }
  truth_chr <- as.character(truth)
  pred_chr <- as.character(predicted)
  if (is.null(levels)) levels <- confusion_levels(truth, predicted)
  levels <- as.character(levels)
  if (anyNA(levels) || anyDuplicated(levels)) {
    hm_abort("{.arg levels} must be unique and non-missing.", "bad_input",
             argument = "levels", call = call)
  }
  unknown <- setdiff(stats::na.omit(unique(c(truth_chr, pred_chr))), levels)
  if (length(unknown) > 0L) {
    hm_abort("Class{?es} {.val {unknown}} {?is/are} not among {.arg levels}.", "bad_input",
             argument = "levels", call = call)
  }
  miss_truth <- is.na(truth_chr)
  miss_pred <- !miss_truth & is.na(pred_chr)
  keep <- !miss_truth & !miss_pred
  tab <- table(Prediction = factor(pred_chr[keep], levels = levels),
               Truth = factor(truth_chr[keep], levels = levels))
  new_grasp_confusion(tab, n_missing_truth = sum(miss_truth), n_missing_predicted = sum(miss_pred))
}

# The one constructor of class "grasp_confusion", from a square table of
# counts (rows = prediction, columns = truth, same levels).
new_grasp_confusion <- function(table, n_missing_truth = 0L, n_missing_predicted = 0L) {
  validate_grasp_confusion(structure(
    list(table = table, levels = rownames(table), n = sum(table),
         n_missing_truth = as.integer(n_missing_truth),
         n_missing_predicted = as.integer(n_missing_predicted)),
    class = "grasp_confusion"))
}

validate_grasp_confusion <- function(x) {
  tab <- x$table
  stopifnot(is.table(tab), nrow(tab) == ncol(tab), identical(rownames(tab), colnames(tab)),
            identical(names(dimnames(tab)), c("Prediction", "Truth")), all(tab >= 0))
  x
}

# Union of the classes seen, in Feix order when all are Feix names (so the
# matrix reads like the thesis' tables, and a factor over all 33 types does not
# drag in 30 empty classes); otherwise factor levels / first-seen order.
confusion_levels <- function(truth, predicted) {
  seen <- unique(c(as.character(stats::na.omit(predicted)), as.character(stats::na.omit(truth))))
  feix <- feix_levels()
  if (all(seen %in% feix)) return(feix[feix %in% seen])
  lev_of <- function(v) if (is.factor(v)) levels(v) else unique(as.character(stats::na.omit(v)))
  unique(c(lev_of(predicted), lev_of(truth)))
}

# grasp_confusion() of one object: the classification result, a data frame
# or a table, each through new_confusion() / new_grasp_confusion().
#' @importFrom rlang %||%
#' @noRd
as_grasp_confusion <- function(x, ..., call = rlang::caller_env()) {
  UseMethod("as_grasp_confusion")
}

#' @export
as_grasp_confusion.default <- function(x, ..., call = rlang::caller_env()) {
  hm_abort(c("{.arg truth} alone must be a classification, a data frame or a table, not {.obj_type_friendly {x}}.",
             i = "Give {.arg predicted} to cross-tabulate two vectors."), "bad_input",
           argument = "truth", call = call)
}

#' @export
as_grasp_confusion.grasp_confusion <- function(x, ..., call = rlang::caller_env()) x

#' @export
as_grasp_confusion.grasp_classification <- function(x, ..., call = rlang::caller_env()) {
  p <- x$predictions
  # every model type and every true type present is a class of the matrix
  lev <- label_order(unique(c(colnames(x$distances), as.character(stats::na.omit(p$truth)))))
  new_confusion(p$truth, p$predicted, levels = lev)
}

#' @export
as_grasp_confusion.data.frame <- function(x, ..., call = rlang::caller_env()) {
  if (!all(c("truth", "predicted") %in% names(x))) {
    hm_abort("A data frame needs columns {.field truth} and {.field predicted}.", "bad_input",
             argument = "truth", call = call)
  }
  new_confusion(x$truth, x$predicted, call = call)
}

#' @export
as_grasp_confusion.table <- function(x, ..., call = rlang::caller_env()) {
  as_grasp_confusion.matrix(unclass(x), call = call)
}

#' @export
as_grasp_confusion.matrix <- function(x, ..., call = rlang::caller_env()) {
  if (nrow(x) != ncol(x) || any(!is.finite(x)) || any(x < 0) || any(x != round(x))) {
    hm_abort("A confusion table must be square with non-negative integer counts.", "bad_input",
             argument = "truth", call = call)
  }
  lev <- rownames(x) %||% colnames(x) %||% as.character(seq_len(nrow(x)))
  new_grasp_confusion(as.table(matrix(as.integer(x), nrow(x), dimnames = list(Prediction = lev, Truth = lev))))
}

# Short labels for compact printing/plotting: Feix ids for Feix names, else
# abbreviations.
confusion_labels <- function(levels) {
  id <- match(levels, feix_levels())
  if (!anyNA(id)) return(as.character(id))
  abbreviate(levels, minlength = 4)
}

#' @export
print.grasp_confusion <- function(x, ...) {
  tab <- x$table
  k <- length(x$levels)
  acc <- if (x$n > 0) sum(diag(tab)) / x$n else NA_real_
  acc <- if (is.na(acc)) "NA" else sprintf("%.1f%%", 100 * acc)
  n <- as.integer(x$n)
  cli::cat_line(cli::pluralize("<grasp_confusion> {k} class{?es}, {n} recording{?s}, accuracy {acc}"))
  cli::cat_line("  rows = predicted type (model), columns = true type")
  n_truth <- as.integer(x$n_missing_truth)
  if (n_truth > 0) cli::cat_line(cli::pluralize("  not tabulated: {n_truth} unlabelled recording{?s}"))
  n_pred <- as.integer(x$n_missing_predicted)
  if (n_pred > 0) cli::cat_line(cli::pluralize("  not tabulated: {n_pred} recording{?s} without a prediction"))
  m <- unclass(tab)
  if (k > 10) {
    # 33 classes do not fit a console as a matrix: one line per true type with
    # its most frequent wrong predictions; the full matrix is `$table` / autoplot().
    print_confusion_compact(m, x$levels)
  } else {
    lab <- x$levels
    if (max(nchar(lab)) > 10) {
      # long type names would wrap the matrix: short labels plus a legend
      lab <- confusion_labels(x$levels)
      cli::cat_line(strwrap(paste0(lab, " = ", x$levels, collapse = ", "), prefix = "  ", initial = "  labels: "))
    }
    dimnames(m) <- stats::setNames(list(lab, lab), names(dimnames(m)))
    print(m)
  }
  invisible(x)
}

print_confusion_compact <- function(m, levels) {
  lab <- confusion_labels(levels)
  correct <- diag(m)
  n_truth <- colSums(m)
  wrong <- vapply(seq_along(levels), function(j) {
    col <- m[, j]
    col[j] <- 0
    top <- utils::head(order(-col), 3)
    top <- top[col[top] > 0]
    if (length(top) == 0) "" else paste0(lab[top], " (", col[top], ")", collapse = ", ")
  }, character(1))
  d <- data.frame(id = lab, type = substr(levels, 1, 22), n = as.integer(n_truth),
                  correct = as.integer(correct), recall = fmt_pct(ifelse(n_truth > 0, correct / n_truth, NA)),
                  `most often predicted instead` = wrong, check.names = FALSE, stringsAsFactors = FALSE)
  d <- d[n_truth > 0, , drop = FALSE]
  cli::cat_line("  per true type (full matrix: `x$table`, `autoplot(x)`):")
  print(d, row.names = FALSE, right = FALSE)
}

#' Metrics of a grasp confusion matrix
#'
#' A tidy data frame of classification metrics, in the spirit of
#' `summary(yardstick::conf_mat)`: overall accuracy, balanced accuracy (= macro
#' recall) and macro precision, then recall and precision for every class.
#'
#' Definitions: recall of class *c* = correct *c* / recordings whose truth is
#' *c*; precision = correct *c* / recordings predicted as *c* (`NA` when the
#' class was never predicted, or for recall when it never occurs as truth).
#' Balanced accuracy is the mean recall over the classes that occur as truth
#' (the scikit-learn definition; yardstick's multiclass `bal_accuracy()`
#' averages (recall + specificity) / 2 instead). Macro precision averages the
#' defined precisions.
#'
#' @param object A [grasp_confusion()] object.
#' @param ... Unused.
#' @return A data frame of class `summary_grasp_confusion` with columns
#'   `.metric`, `class` (`NA` for overall metrics), `.estimate` and `n` (the
#'   denominator): yardstick's names for the metric and its value.
#' @export
#' @examples
#' cm <- grasp_confusion(c("Tripod", "Tripod", "Ring"), c("Tripod", "Ring", "Ring"))
#' summary(cm)
summary.grasp_confusion <- function(object, ...) {
  m <- unclass(object$table)
  correct <- diag(m)
  n_truth <- colSums(m)
  n_pred <- rowSums(m)
  recall <- ifelse(n_truth > 0, correct / n_truth, NA_real_)
  precision <- ifelse(n_pred > 0, correct / n_pred, NA_real_)
  n <- sum(m)
  overall <- data.frame(
    .metric = c("accuracy", "balanced_accuracy", "macro_precision"),
    class = NA_character_,
    .estimate = c(if (n > 0) sum(correct) / n else NA_real_, mean_or_na(recall), mean_or_na(precision)),
    n = c(n, sum(n_truth > 0), sum(n_pred > 0)),
    stringsAsFactors = FALSE)
  lev <- object$levels
  per_class <- data.frame(
    .metric = rep(c("recall", "precision"), each = length(lev)),
    class = rep(lev, 2),
    .estimate = c(unname(recall), unname(precision)),
    n = c(unname(n_truth), unname(n_pred)),
    stringsAsFactors = FALSE)
  out <- rbind(overall, per_class)
  rownames(out) <- NULL
  structure(out, class = c("summary_grasp_confusion", "data.frame"))
}

mean_or_na <- function(v) if (all(is.na(v))) NA_real_ else mean(v, na.rm = TRUE)

#' @export
print.summary_grasp_confusion <- function(x, ...) {
  d <- as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE)
  ov <- d[is.na(d$class), , drop = FALSE]
  cli::cat_line("Confusion-matrix metrics")
  if (nrow(ov)) cli::cat_line(sprintf("  %-18s %s  (n = %d)", ov$.metric, fmt_pct(ov$.estimate), as.integer(ov$n)))
  pc <- d[!is.na(d$class), , drop = FALSE]
  if (nrow(pc) > 0) {
    lev <- unique(pc$class)
    rec <- pc[pc$.metric == "recall", ]
    pre <- pc[pc$.metric == "precision", ]
    wide <- data.frame(class = lev,
                       truth_n = as.integer(rec$n[match(lev, rec$class)]),
                       recall = fmt_pct(rec$.estimate[match(lev, rec$class)]),
                       predicted_n = as.integer(pre$n[match(lev, pre$class)]),
                       precision = fmt_pct(pre$.estimate[match(lev, pre$class)]),
                       stringsAsFactors = FALSE)
    cli::cat_line("Per class:")
    print(wide, row.names = FALSE, right = FALSE)
  }
  invisible(x)
}

fmt_pct <- function(v) ifelse(is.na(v), "NA", sprintf("%5.1f%%", 100 * v))

#' Long form of a grasp confusion matrix
#'
#' @param x A [grasp_confusion()] object.
#' @param row.names,optional Unused (for the generic).
#' @param ... Unused.
#' @return A data frame with one row per (predicted, truth) cell: `predicted`,
#'   `truth` (factors over the classes) and `n` (count).
#' @export
#' @examples
#' cm <- grasp_confusion(c("Tripod", "Ring"), c("Tripod", "Tripod"))
#' as.data.frame(cm)
as.data.frame.grasp_confusion <- function(x, row.names = NULL, optional = FALSE, ...) {
  d <- as.data.frame(x$table, stringsAsFactors = FALSE, responseName = "n")
  out <- data.frame(predicted = factor(d$Prediction, levels = x$levels),
                    truth = factor(d$Truth, levels = x$levels),
                    n = as.integer(d$n))
  out
}

#' Heatmap of a grasp confusion matrix
#'
#' Tiles coloured by count (or by the share of each true type, `normalise =
#' TRUE`), with the counts written in the non-empty cells; predicted type on
#' the vertical axis and true type on the horizontal axis, as in the thesis.
#'
#' @param object A [grasp_confusion()] object.
#' @param type Plot type; only `"heatmap"`.
#' @param normalise Colour by the fraction of each true type's recordings
#'   (column share) instead of the raw count.
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot grasp_confusion
#' @examples
#' cm <- grasp_confusion(c("Tripod", "Tripod", "Ring"), c("Tripod", "Ring", "Ring"))
#' ggplot2::autoplot(cm)
autoplot.grasp_confusion <- function(object, type = "heatmap", normalise = FALSE, ...) {
  type <- check_choice(type, "heatmap", arg = "type", call = rlang::current_env())
  d <- as.data.frame(object)
  lab <- confusion_labels(object$levels)
  d$truth <- factor(lab[as.integer(d$truth)], levels = lab)
  d$predicted <- factor(lab[as.integer(d$predicted)], levels = rev(lab))
  col_tot <- tapply(d$n, d$truth, sum)
  d$share <- ifelse(col_tot[as.character(d$truth)] > 0, d$n / col_tot[as.character(d$truth)], 0)
  d$fill <- if (normalise) d$share else d$n
  d$label <- ifelse(d$n > 0, as.character(d$n), "")
  # counts at 8 points with many types (a 33-type matrix in a figure 7 inches
  # wide leaves cells about 13 points across), 10 with few; at a figure's
  # natural size in a page that is 11 and 13 CSS pixels
  many <- length(lab) > 15
  text_size <- (if (many) 8 else 10) / ggplot2::.pt
  p <- ggplot2::ggplot(d, ggplot2::aes(x = .data$truth, y = .data$predicted)) +
    ggplot2::geom_tile(ggplot2::aes(fill = .data$fill), colour = "white", linewidth = 0.2) +
    ggplot2::geom_text(ggplot2::aes(label = .data$label), size = text_size) +
    ggplot2::scale_fill_gradient(low = "grey97", high = "steelblue",
                                 name = if (normalise) "share of\ntrue type" else "count") +
    ggplot2::labs(x = "true type", y = "predicted type (model)",
                  caption = confusion_key(object$levels, lab)) +
    ggplot2::theme_minimal() +
    ggplot2::theme(panel.grid = ggplot2::element_blank(),
                   plot.caption = ggplot2::element_text(hjust = 0, size = 9, colour = "grey30"))
  if (!many) return(p)
  # many types: the colour bar below the matrix, so that the matrix has the
  # figure's whole width and a three-digit count fits its cell
  p + ggplot2::guides(fill = ggplot2::guide_colourbar(barwidth = ggplot2::unit(10, "lines"),
                                                      title.position = "top")) +
    ggplot2::theme(legend.position = "bottom")
}

# Key to the short axis labels (Feix ids or abbreviations), wrapped into a
# caption, so a 33-class heatmap stays readable; NULL when names are shown.
confusion_key <- function(levels, lab) {
  if (identical(as.character(levels), as.character(lab))) return(NULL)
  # a label short enough to be its own abbreviation is written once ("ball",
  # not "ball ball")
  key <- ifelse(lab == levels, levels, paste(lab, levels))
  # pack whole entries into lines of at most ~80 characters: at the caption's
  # 9 points that is about 6 inches, narrower than the figures it goes in
  line <- cumsum(nchar(key) + 3L) %/% 80L
  paste(vapply(split(key, line), paste, character(1), collapse = " \u00b7 "), collapse = "\n")
}
