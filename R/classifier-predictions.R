# One contract for every fitted classifier (the FPCA model set, the three
# fit_grasp_classifier() methods and the recogniser), in the tidymodels
# convention: predict(object, new_data, type) returns a data frame with one
# row per recording, `.pred_class` for type = "class", `.pred_<class>` for
# "prob" and `.dist_<class>` for "distance". Every classifier reduces to a
# distance matrix (recordings x classes, smaller is closer) and a
# temperature: the class is the nearest, the probabilities are
# softmax(-distance / temperature). For the discriminants the distance is
# minus the log posterior and the temperature 1, so the softmax gives back
# their posterior exactly; for the distance classifiers the temperature is
# fitted on the training data (fit_temperature()). The distances and the
# temperature come through the family's generics (R/classifier.R); this
# file only shapes the answer.

#' Predict grasp types with any fitted classifier
#'
#' Every classifier handmotion fits answers the same `predict()`: a
#' [fit_grasp_models()] set (the thesis' FPCA distance), each
#' [fit_grasp_classifier()] method (`"discriminant"`, `"last_frame"`,
#' `"weighted_fpca"`) and a [fit_grasp_recognizer()]: they are one family,
#' class `grasp_classifier` (see [summary.grasp_classifier()]), and this is
#' its `predict()` (the recogniser adds how much of each recording is
#' seen). The result follows the
#' tidymodels convention: a data frame with one row per recording of
#' `new_data`, in its order (row names: the recording ids), of class
#' `grasp_predictions`, whose `print()` shows the first rows only.
#'
#' * `type = "class"`: column `.pred_class`, a factor with the levels of the
#'   training labels (so it compares with `new_data$meta$grasp`).
#' * `type = "prob"`: one column `.pred_<class>` per class the classifier
#'   was trained on; each row sums to 1.
#' * `type = "distance"`: one column `.dist_<class>` per class, the distance
#'   the classifier ranks (smaller is closer; see below).
#'
#' **Distances and probabilities.** Each classifier ranks a distance per
#' class and predicts the nearest; its probabilities are
#' `softmax(-distance / temperature)`, so the most probable class is always
#' the predicted one:
#'
#' * FPCA model set: by default minus twice the recording's log-likelihood
#'   under each type's model (scores and residual, see the `distance`
#'   argument of [fit_grasp_models()]); with `distance = "residual"` the
#'   thesis' distance (eq. 4.4 on frames `1..T_i`, see [classify()]). The temperature is fitted by [fit_grasp_models()] by
#'   maximum likelihood: the value that maximises the sum over the training
#'   recordings of the log probability of their own type. The distances are
#'   in-sample (each model saw the recordings of its type); with dozens of
#'   recordings per type and a few FPCs per DoF the optimism is small.
#' * `"last_frame"`: the reconstruction error of the last frame; the
#'   temperature is fitted the same way on held-out distances: every type's
#'   PCA refitted without each subject in turn (without each recording when
#'   the recordings name fewer than two subjects).
#' * `"weighted_fpca"`: its distance is minus twice the recording's
#'   log-likelihood under each model, so the temperature is 2 and the
#'   probabilities are the models' posterior with equal priors.
#' * `"discriminant"` and the recogniser: the distance is minus the log
#'   posterior probability and the temperature 1: the probabilities are the
#'   discriminant's posterior.
#'
#' A temperature at its lower bound (the training data separated without
#' error) gives probabilities near 0 and 1.
#'
#' **Recordings that cannot be classified** (no finite distance to any
#' class: a recording holding non-finite values, or no model could project
#' it) come back as `NA` (class and every probability) with the reason in
#' the attribute `reasons`: a character vector named by recording id.
#' Recordings holding non-finite values (put in after [grasps()] built the
#' set, which refuses them) are named by a warning of class
#' `handmotion_warning_non_finite`; recordings of fewer than three frames
#' are classified with a warning of class
#' `handmotion_warning_short_recordings`. A classifier whose parts were
#' changed after fitting is refused (`handmotion_error_bad_model`).
#'
#' @param object A fitted classifier.
#' @param new_data A [grasps()] object with the DoFs the classifier was
#'   trained on.
#' @param type `"class"`, `"prob"` or `"distance"`.
#' @param frames,ms,fraction Recogniser only: how much of each recording is
#'   seen, as a number of frames, a time since the recording began in
#'   milliseconds (at the data's rate), or a fraction of each recording's
#'   own length. At most one; by default the whole recording (past the
#'   recogniser's horizon, its first `horizon` frames).
#' @param ... Not used; an error if given.
#' @return A `grasp_predictions` data frame (see above); `as.data.frame()`
#'   drops the class.
#' @seealso [classify()] for a confusion-ready classification,
#'   [project()] for the FPC projections of an FPCA model.
#' @name predict.grasp_models
#' @examples
#' g <- simulate_grasps(subjects = 5, grasps = 1:3, objects = 2, trials = 2, seed = 1)
#' train <- g[g$meta$subject != "S05"]
#' test <- g[g$meta$subject == "S05"]
#' cl <- fit_grasp_classifier(train)
#' predict(cl, test)
#' predict(cl, test, type = "prob")
#' ms <- fit_grasp_models(train, seed = 1, mixture_components = 1)
#' p <- predict(ms, test, type = "prob")
#' rowSums(p)
#' table(predict(ms, test)$.pred_class, test$meta$grasp)
#' rec <- fit_grasp_recognizer(train)
#' predict(rec, test, ms = 300)
NULL

#' @rdname predict.grasp_models
#' @export
predict.grasp_recognizer <- function(object, new_data, type = c("class", "prob", "distance"),
                                     frames = NULL, ms = NULL, fraction = NULL, ...) {
  call <- rlang::caller_env()
  check_trained_dofs(new_data, object$dofs, "recogniser", call = call)
  new_data <- from_onset(new_data, object$onset)   # time counts from the motion's onset
  seen <- seen_frames(new_data, frames, ms, fraction, call)
  predict_classifier(object, new_data, type, list(...), call, seen = seen)
}

# The one predict() of every classifier: its distances, then the answer of
# the type asked for.
# `arg`: the argument name of the classifier (classify() calls it `models`);
# `checked`: new_data was validated by the caller already (one pass, not two).
predict_classifier <- function(object, new_data, type, dots, call, seen = NULL, arg = "object", checked = FALSE) {
  if (length(dots)) {
    hm_abort(c("{.fn predict} takes a classifier, {.arg new_data} and {.arg type}; unknown argument{?s} {.arg {names(dots) %||% rep('', length(dots))}}.",
               i = "See {.help handmotion::predict.grasp_models}."),
             "bad_input", argument = "...", call = call)
  }
  type <- check_choice(type, c("class", "prob", "distance"), arg = "type", call = call)
  check_classifier(object, arg, call = call)
  check_fitted_parts(object, arg, call = call)
  if (!checked) {
    check_new_recordings(new_data, "new_data", "classify", finite = FALSE, call = call)
  }
  res <- finite_distances(object, new_data, call, seen)
  d <- res$distances
  reasons <- unclassified_reasons(d, new_data)
  out <- switch(type,
    class = data.frame(.pred_class = nearest_type(d, classifier_levels(object))),
    prob = prefixed_frame(distance_softmax(d, required_temperature(object, call)), ".pred_"),
    distance = prefixed_frame(d, ".dist_"))
  new_grasp_predictions(out, new_data$meta$id, type, reasons,
                        extra = if (type == "distance") res[c("target_length", "failures")])
}

# The distances of the recordings that hold finite values only; a recording
# with a NaN or an infinite value has none (NA), so one bad recording does
# not stop the others.
finite_distances <- function(object, x, call, seen) {
  finite <- recordings_finite(x$recordings)
  if (all(finite)) return(distance_result(object, x, call, seen))
  bad <- x$meta$id[!finite]
  hm_warn(c("{.arg new_data} has {length(bad)} recording{?s} with missing or infinite values, not classified: {.val {bad}}.",
            i = "Their predictions are {.val NA}; see {.code attr(, \"reasons\")}."),
          "non_finite", recording = bad)
  classes <- classifier_classes(object)
  d <- matrix(NA_real_, length(finite), length(classes), dimnames = list(x$meta$id, classes))
  if (!any(finite)) return(list(distances = d, target_length = NULL, failures = no_failures()))
  res <- distance_result(object, x[finite], call, seen[finite])
  d[finite, ] <- res$distances[, classes, drop = FALSE]
  res$distances <- d
  res
}

# A matrix as a data frame with prefixed column names (kept as given: class
# names may hold spaces).
prefixed_frame <- function(m, prefix) {
  out <- as.data.frame(unname(m))
  names(out) <- paste0(prefix, colnames(m))
  out
}

# Why each recording without any finite distance has no prediction (named
# by recording id; empty when all were classified).
unclassified_reasons <- function(d, x) {
  none <- which(rowSums(is.finite(d)) == 0L)
  if (!length(none)) return(stats::setNames(character(0), character(0)))
  bad_values <- vapply(x$recordings[none], function(r) !all(is.finite(r)), logical(1))
  stats::setNames(ifelse(bad_values, "the recording holds non-finite values",
                         "no class could score it (see the classifier's failures)"),
                  x$meta$id[none])
}

# Nearest class per row as a factor with `levels`; NA when a row has no
# finite distance.
nearest_type <- function(d, levels = colnames(d)) {
  best <- apply(d, 1L, function(r) if (!any(is.finite(r))) NA_integer_ else which.min(replace(r, !is.finite(r), Inf)))
  if (!length(best)) best <- integer(0)
  factor(colnames(d)[best], levels = levels)
}

# softmax(-d / temperature) by row; a non-finite distance has probability
# 0, a row without any finite distance is NA.
distance_softmax <- function(d, temperature) {
  s <- -d / temperature
  s[!is.finite(s)] <- -Inf
  # (each row's largest by max.col(), not apply(): the temperature's search
  # takes this softmax some 30 times over its sample's distances, 0.1 s of
  # the serial end of a fit of the default data with apply())
  top <- s[cbind(seq_len(nrow(s)), max.col(s, ties.method = "first"))]
  e <- exp(s - top)
  p <- e / rowSums(e)
  p[!is.finite(top), ] <- NA_real_
  p
}

# Minus the log posterior of every class from discriminant scores (log
# posteriors up to a constant per row): the distance of the discriminants.
neg_log_posterior <- function(s) {
  top <- apply(s, 1L, max)
  -(s - (top + log(rowSums(exp(s - top)))))
}

# The temperature of softmax(-d / t) that maximises the log-likelihood of
# the true classes `y` (one per row of d, a class name; rows with another
# label or without a finite own distance are left out). The log-likelihood
# is concave in 1 / t, so a one-dimensional search on log t finds its
# maximum; it is bounded to e^-10 .. e^10 times the spread of the distances.
# Separable data push t to the lower bound: probabilities near 0 and 1.
fit_temperature <- function(d, y) {
  y <- as.character(y)
  keep <- y %in% colnames(d)
  d <- d[keep, , drop = FALSE]
  own <- match(y[keep], colnames(d))
  own_d <- d[cbind(seq_len(nrow(d)), own)]
  ok <- is.finite(own_d)
  d <- d[ok, , drop = FALSE]
  own <- own[ok]
  spread <- stats::sd(d[is.finite(d)])
  if (!nrow(d) || ncol(d) < 2L || !is.finite(spread) || spread == 0) return(1)
  loglik <- function(log_t) {
    p <- distance_softmax(d, exp(log_t))
    sum(log(pmax(p[cbind(seq_len(nrow(p)), own)], 1e-300)))
  }
  exp(stats::optimize(loglik, log(spread) + c(-10, 10), maximum = TRUE)$maximum)
}

# The prediction frame: row names the recording ids, what could not be
# classified NA with its reason.
new_grasp_predictions <- function(df, ids, type, reasons, extra = NULL) {
  rownames(df) <- ids
  df[names(reasons), ] <- NA
  out <- structure(df, class = c("grasp_predictions", "data.frame"), type = type, reasons = reasons)
  for (nm in names(extra)) attr(out, nm) <- extra[[nm]]
  out
}

#' @export
print.grasp_predictions <- function(x, ..., n = 10L) {
  # (from the columns: a subset keeps the class but not the attributes)
  type <- if (identical(names(x), ".pred_class")) "class" else if (all(startsWith(names(x), ".dist_"))) "distance" else "prob"
  what <- switch(type, class = "predicted class", prob = "class probabilities",
                 distance = "distances to each class")
  classes <- if (type != "class") cli::pluralize(", {ncol(x)} class{?es}")
  cli::cat_line(cli::pluralize("<grasp_predictions> {what} of {nrow(x)} recording{?s}"), classes)
  shown <- as.data.frame(unclass(x)[names(x)], row.names = rownames(x), check.names = FALSE,
                         stringsAsFactors = FALSE)
  cols <- names(shown)
  if (length(cols) > 8L) shown <- shown[, 1:8, drop = FALSE]
  # (three decimals, "<0.001" and ">0.999" beyond: see format_probability())
  if (type == "prob") shown[] <- lapply(shown, function(v) if (is.numeric(v)) format_probability(v) else v)
  print(utils::head(shown, n), digits = 3)
  more <- c(if (nrow(x) > n) cli::pluralize("{nrow(x) - n} more row{?s}"),
            if (length(cols) > 8L) cli::pluralize("{length(cols) - 8L} more column{?s}: {name_list(cols[-(1:8)], 3L)}"))
  if (length(more)) cli::cat_line("# ... ", paste(more, collapse = "; "))
  r <- attr(x, "reasons")
  if (length(r)) {
    cli::cat_line(cli::pluralize("# {length(r)} recording{?s} not classified: {name_list(paste0(names(r), ' (', r, ')'), 3L)}"))
  }
  invisible(x)
}
