# Grasp-type classification (thesis section 4.2). Two schemes share one
# result class, `grasp_classification`:
#   fpca        every recording is fed to every grasp model: warped into the
#               model's time by the model's mean warping function, projected on
#               its FPCs, and scored by the L2 distance to that projection
#               (eq. 4.4; computed by project()). Closest model wins.
#   last_frame  the same idea on the last frame only, with one ordinary PCA per
#               type (R/classifier-last-frame.R).
# The distance matrix (recordings x models) is kept, so Table 5.3
# (distance_table()) and the confusion matrices come from one computation.

#' Classify recordings by grasp type
#'
#' Assigns each recording of `x` to the grasp type whose model represents it
#' best, following the two schemes of the thesis (section 4.2):
#'
#' * `"fpca"` (Table 5.6): each recording is warped into each model's time by
#'   the model's mean warping function and projected on the model's FPCs. A
#'   set fitted with `fit_grasp_models(distance = "likelihood")` (the
#'   default) scores it by minus twice its log-likelihood under the model
#'   (its FPC scores and its residual; see [fit_grasp_models()]); one fitted
#'   with `distance = "residual"` (the thesis', used by [reproduce_thesis()])
#'   by the L2 distance between the warped recording and its projection
#'   (eq. 4.4, over all DoFs; see [project()]), measured as the
#'   thesis measured it: on a grid of frame numbers `1..T_i` (fda.usc's default
#'   for a matrix of curves), so model *i*'s distance is `project()`'s, which
#'   integrates over \[0, 1\], times `sqrt(T_i - 1)`. A longer model thus has
#'   larger distances, which is why the thesis' shortest model (Palmar Pinch)
#'   draws many recordings; the weighted FPCA distance does not have this
#'   bias. `models` is a `grasp_models` object from [fit_grasp_models()].
#' * `"last_frame"` (Table 5.8): the Euclidean distance between the recording's
#'   last frame and its projection on each type's first `k` PCs; `models` is a
#'   `fit_grasp_classifier(method = "last_frame")` result.
#' * `"weighted_fpca"` (the thesis' proposed fix): `models` is a
#'   `fit_grasp_classifier(method = "weighted_fpca")` result: per-type DoF
#'   weights and time weights.
#' * `"discriminant"` (beyond the thesis): `models` is a
#'   `fit_grasp_classifier(method = "discriminant")` result; the "distance"
#'   to a type is minus the log of its posterior probability.
#'
#' `classify()` is a thin wrapper over `predict(models, x, type =
#' "distance")` ([predict.grasp_models()], the contract every classifier
#' answers): it keeps the whole distance matrix with the recordings' true
#' types, ready for [grasp_confusion()] and Table 5.3. For class labels or
#' probabilities alone call `predict()`.
#'
#' The recording goes to the model with the smallest distance. The method
#' follows from the class of `models`; nothing is fitted here (the thesis
#' fitted and classified the same recordings: `classify(fit, x)` with a `fit`
#' on `x` does that visibly). See [evaluate_loso()] for an honest held-out
#' estimate.
#'
#' With many recordings (ten times the default data takes seconds) a progress
#' bar, one step per model, appears after 2 s (through `progressr`, in
#' interactive sessions or when you set its handlers or `progressr.enable`;
#' `options(handmotion.progress = FALSE)` turns it off).
#'
#' One-type data are not an error: with a single model every recording is
#' assigned to that type, so accuracy is 1 by construction. A model whose
#' projection fails gives a column of `NA` distances, recorded in `$failures`
#' with a warning; a recording with no finite distance gets `NA` as prediction.
#'
#' @param models A fitted classifier (of the family `grasp_classifier`, see
#'   [summary.grasp_classifier()]): a [fit_grasp_models()] result (FPCA
#'   distance), a [fit_grasp_classifier()] result (any `method`) or a
#'   [fit_grasp_recognizer()] result. A `grasps` object is refused with a
#'   hint: fitting is a separate, visible step (for a held-out estimate see
#'   [evaluate_loso()], which fits on training subjects only).
#' @param x A [grasps()] object to classify.
#' @param method `"fpca"`, `"last_frame"`, `"discriminant"` or
#'   `"weighted_fpca"`. Inferred from `models`; giving a method that
#'   contradicts it is an error. This default is the one list of the
#'   classifiers' method names ([evaluate_loso()] takes the same; the Python
#'   front end reads it as `eval(formals(handmotion::classify)$method)`). A
#'   [fit_grasp_recognizer()] result is classified from whole recordings
#'   (method `"recognizer"`, inferred only).
#' @param ... Not used; an error if given.
#' @return An object of class `grasp_classification`: a list with
#'   `predictions` (data frame: `id`, `subject`, `truth`, `predicted`,
#'   `distance` to the chosen model), `distances` (numeric matrix, recordings x
#'   models), `method`, `target_length` (per model, `fpca` only) and `failures`.
#'   Use [grasp_confusion()] for its confusion matrix and
#'   `thesis_table("5.3", classification = )` for the thesis' Table 5.3 (the
#'   mean distance per model and true type).
#' @seealso [grasp_confusion()], [thesis_table()], [evaluate_loso()]
#' @export
#' @examples
#' set.seed(1)
#' recs <- lapply(1:12, function(i) matrix(rnorm(10 * 16, mean = i %% 2 * 40), 10, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c("Tripod", "Ring"), 6)))
#' lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
#' cl <- classify(lf, g)
#' cl
#' grasp_confusion(cl)
classify <- function(models, x, method = c("fpca", "last_frame", "discriminant", "weighted_fpca"), ...) {
  call <- rlang::caller_env()
  # (non-finite values: those recordings are left unclassified, with a warning)
  check_new_recordings(x, "x", "classify", finite = FALSE, call = call)
  rlang::check_dots_empty(error = function(cnd) {
    hm_abort(c("{.fn classify} takes fitted models and the recordings, nothing more.",
               i = "Give fitting arguments to {.fn fit_grasp_models} or {.fn fit_grasp_classifier}."),
             "bad_input", argument = "...", call = call)
  })
  if (inherits(models, "grasps")) {
    hm_abort(c("{.arg models} must be fitted models, not a {.cls grasps} object.",
               i = "Fit first: {.code classify(fit_grasp_models(train), x)} or {.code classify(fit_grasp_classifier(train, method = \"last_frame\"), x)}.",
               i = "{.fn evaluate_loso} fits on training subjects and classifies the held-out ones."),
             "bad_input", argument = "models", call = call)
  }
  method <- resolve_method(models, method, missing(method), call = call)
  # the distances predict() gives, kept whole for the confusion matrix and Table 5.3
  d <- with_progress_shown(predict_classifier(models, x, "distance", list(), call, arg = "models", checked = TRUE))
  dist <- as.matrix(as.data.frame(unclass(d)[names(d)], check.names = FALSE))
  dimnames(dist) <- list(x$meta$id, sub("^\\.dist_", "", names(d)))
  out <- new_classification(dist, x$meta, method, attr(d, "target_length"), attr(d, "failures") %||% no_failures())
  # which FPCA distance ranked them (print() says)
  if (method == "fpca") out$fpca_distance <- models_distance(models)
  out
}

resolve_method <- function(models, method, defaulted, call = rlang::caller_env()) {
  check_classifier(models, "models", call = call)
  implied <- classifier_method(models)
  if (defaulted) return(implied)
  method <- check_choice(method, classify_methods(), arg = "method", call = call)
  if (method != implied) {
    hm_abort("{.arg method} is {.val {method}} but {.arg models} is a {.cls {class(models)[1]}} ({.val {implied}}) fit.",
             "bad_input", argument = "method", call = call)
  }
  method
}

# The methods classify() and evaluate_loso() take by name: the default of
# classify()'s `method` (the one list; the Python front end reads it there).
classify_methods <- function() eval(formals(classify)$method)

# Fit the models a method needs on a training set (evaluate_loso()); a
# method given as a function is the fitter of a classifier of the family.
fit_classifier <- function(train, method, fit_args) {
  if (is.function(method)) {
    fit <- do.call(method, c(list(train), fit_args))
    if (!inherits(fit, "grasp_classifier")) not_a_classifier(fit, "method", rlang::caller_env())
    return(fit)
  }
  if (method != "fpca") return(do.call(fit_grasp_classifier, c(list(train, method = method), fit_args)))
  # One Gaussian per DoF's scores (mixture_components = 1, closed form)
  # instead of the EM for two components halves the refit. Neither distance
  # reads the mixtures (the likelihood scores the joint score vector by a
  # kernel density, R/classifier-fpca-likelihood.R) except for a type of fewer than
  # three recordings.
  # Held-out classification needs no probabilities, so no temperature.
  if (is.null(fit_args$mixture_components)) fit_args$mixture_components <- 1L
  do.call(fit_model_set, c(list(train), fit_args, calibrate = FALSE))
}

no_failures <- function() data.frame(model = character(0), message = character(0))

# Eq. 4.4 for every (recording, model) pair. The recordings are stacked once
# and projected on one model at a time, keeping only the distances (the
# scores and residuals of every model at once would be n x 33 x p x ncomp
# numbers: 1 GB at ten times the default data); a model whose projection
# fails costs only its own column.
fpca_distances <- function(models, x, call = rlang::caller_env()) {
  # (each model is checked by project_models(), once)
  check_grasp_models(models, "models", "classify", each = FALSE, call = call)
  # types whose model could not be fitted can never be predicted: say so
  unfitted <- failed_types(models)
  failures <- no_failures()
  if (nrow(unfitted) > 0L) {
    failures <- rbind(failures, data.frame(model = unfitted$grasp,
                                           message = paste("not fitted:", unfitted$message)))
  }
  likelihood <- identical(models_distance(models), "likelihood")
  fitted <- fitted_models(models)
  input <- projection_input(fitted, x)
  columns <- project_models(fitted, input, "models", details = FALSE, call = call,
                            keep = function(pr, m) fpca_model_distance(m, pr, likelihood, x$meta$id),
                            keep_going = TRUE, distance_only = !likelihood,
                            progress = hm_progressor(length(fitted)))
  types <- names(columns)
  ids <- x$meta$id
  d <- matrix(NA_real_, length(ids), length(types), dimnames = list(ids, types))
  first_error <- NULL
  for (j in seq_along(types)) {
    dist <- columns[[j]]
    if (inherits(dist, "error")) {
      first_error <- first_error %||% dist
      failures <- rbind(failures, data.frame(model = types[j],
                                             message = cli::ansi_strip(conditionMessage(dist))))
      next
    }
    if (length(dist) != length(ids)) {
      failures <- rbind(failures, data.frame(model = types[j],
                                             message = "projection returned the wrong number of distances"))
      next
    }
    d[, j] <- dist
  }
  # no model could take the recordings (other DoFs, a bad recording): the
  # recordings are at fault, not the models, and there is nothing to return
  if (!is.null(first_error) && all(is.na(d))) stop(first_error)
  if (nrow(failures) > 0L) {
    hm_warn(c("{nrow(failures)} grasp type{?s} cannot be predicted: {.val {failures$model}}.",
              i = "See {.field failures} of the result."),
            "projection_failed")
  }
  tl <- vapply(fitted, function(m) as.numeric(m$target_length %||% NA_real_), numeric(1))
  names(tl) <- types
  list(distances = d, target_length = tl, failures = failures)
}

# The FPCA distance of every recording under one model, from its projection
# `pr`, in the order of `ids`: minus twice the log-likelihood (a set fitted
# with distance = "likelihood"), or the residual norm of eq. 4.4 as the
# thesis measured it. The one per-model step of fpca_distances() and of the
# temperature's sample (sample_distance(), R/grasp-models.R).
fpca_model_distance <- function(model, pr, likelihood, ids, terms = FALSE) {
  at <- if (is.null(pr$ids)) seq_along(ids) else match(ids, pr$ids)
  # (`terms`: the likelihood's score term and its residual curves apart, for
  # a set whose residual scale is not pooled yet: fit_grasp_models()'s
  # temperature sample, scored on the workers as each type is fitted)
  if (likelihood && terms) {
    return(list(score = unname(likelihood_score_term(model, pr))[at], residual = pr$residual[at, , drop = FALSE]))
  }
  d <- unname(if (likelihood) fpca_likelihood_distance(model, pr) else pr$distance)
  d <- d[at]
  if (likelihood) return(d)
  # the thesis' norm: its curves were fda.usc objects on frames 1..T_i,
  # where the L2 norm integrates with spacing 1; ours integrates over
  # [0, 1] (spacing 1 / (T_i - 1)), so the two differ by sqrt(T_i - 1) per
  # model. The rescaling changes which model is nearest whenever lengths
  # differ. (A likelihood has no such scale: it is not rescaled.)
  d * thesis_norm_scale(as.numeric(model$target_length %||% NA_real_))
}

# The factor that turns our residual norm into the thesis' (see above), per
# target length.
thesis_norm_scale <- function(target_length) sqrt(pmax(target_length - 1, 1))

new_classification <- function(d, meta, method, target_length = NULL, failures = no_failures()) {
  pred <- nearest_type(d)
  best <- suppressWarnings(apply(d, 1L, min, na.rm = TRUE))
  best[!is.finite(best)] <- NA_real_
  truth <- meta$grasp
  if (!is.factor(truth)) truth <- factor(truth)
  predictions <- data.frame(id = meta$id, subject = meta$subject %||% NA_character_,
                            truth = truth, predicted = pred, distance = unname(best),
                            stringsAsFactors = FALSE)
  structure(list(predictions = predictions, distances = d, method = method,
                 target_length = target_length, failures = failures),
            class = "grasp_classification")
}

#' @export
print.grasp_classification <- function(x, ...) {
  p <- x$predictions
  lab <- !is.na(p$truth) & !is.na(p$predicted)
  ok <- sum(as.character(p$truth[lab]) == as.character(p$predicted[lab]))
  method <- switch(x$method,
                   fpca = if (identical(x$fpca_distance, "likelihood")) "FPCA likelihood distance" else "FPCA projection distance",
                   last_frame = "last-frame PCA distance",
                   discriminant = "shrinkage LDA (distance = -log posterior)",
                   weighted_fpca = "weighted FPCA distance",
                   recognizer = "early recogniser, whole recordings (distance = -log posterior)",
                   paste(x$method, "distance"))
  cli::cat_line(cli::pluralize("<grasp_classification> {method}, {nrow(p)} recording{?s} x {ncol(x$distances)} model{?s}"))
  n_lab <- sum(lab)
  if (n_lab > 0) {
    cli::cat_line(cli::pluralize("  accuracy {sprintf('%.1f%%', 100 * ok / n_lab)} ({ok} of {n_lab} labelled recording{?s})"))
  }
  n_unlab <- sum(is.na(p$truth))
  if (n_unlab > 0) cli::cat_line(cli::pluralize("  {n_unlab} unlabelled recording{?s}"))
  n_unpred <- sum(is.na(p$predicted))
  if (n_unpred > 0) cli::cat_line(cli::pluralize("  {n_unpred} recording{?s} without a prediction"))
  if (nrow(x$failures) > 0) cli::cat_line("  failed models: ", paste(x$failures$model, collapse = ", "))
  invisible(x)
}

#' Summaries and plots of a grasp classification
#'
#' `summary()` gives the metrics of the classification's confusion matrix
#' ([summary.grasp_confusion()]); `autoplot()` its heatmap
#' ([autoplot.grasp_confusion()]); `as.data.frame()` the per-recording
#' predictions.
#'
#' @param object,x A [classify()] result.
#' @param row.names,optional Unused (for the generic).
#' @param ... Passed to [autoplot.grasp_confusion()] (e.g. `normalise = TRUE`).
#' @return A metrics data frame, a ggplot, or the predictions data frame.
#' @export
#' @examples
#' set.seed(1)
#' recs <- lapply(1:12, function(i) matrix(rnorm(10 * 16, mean = i %% 2 * 40), 10, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c("Tripod", "Ring"), 6)))
#' lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
#' cl <- classify(lf, g)
#' summary(cl)
#' head(as.data.frame(cl))
#' ggplot2::autoplot(cl)
summary.grasp_classification <- function(object, ...) {
  summary(as_grasp_confusion(object))
}

#' @rdname summary.grasp_classification
#' @export
#' @method autoplot grasp_classification
autoplot.grasp_classification <- function(object, ...) {
  autoplot.grasp_confusion(as_grasp_confusion(object), ...)
}

#' @rdname summary.grasp_classification
#' @export
as.data.frame.grasp_classification <- function(x, row.names = NULL, optional = FALSE, ...) {
  x$predictions
}

#' Mean projection distance per model and true type (Table 5.3)
#'
#' The thesis' Table 5.3: for model *i* and true grasp type *j*, the mean over
#' the recordings of type *j* of `100 * distance / T_i`, where `distance` is the
#' eq. 4.4 L2 distance between the recording warped into model *i*'s time and
#' its FPC projection, and `T_i` is model *i*'s target length (so rows are
#' comparable). For a last-frame classification there is no time axis and the
#' plain mean distance is returned.
#'
#' @param models A `grasp_models` object, or a [classify()] result (then `x`
#'   is not needed and nothing is recomputed).
#' @param x A [grasps()] object (labelled) when `models` are models.
#' @return A numeric matrix with rows = model and columns = true type (types
#'   present in `x`, in Feix order), dimnames named `model` and `truth`.
#'   `distance_minima()` counts its row and column minima.
#' @seealso [classify()], `distance_minima()`
#' @noRd
#' @examples
#' set.seed(1)
#' recs <- lapply(1:12, function(i) matrix(rnorm(10 * 16, mean = i %% 2 * 40), 10, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c("Tripod", "Ring"), 6)))
#' distance_table(classify(fit_grasp_classifier(g, method = "last_frame", ncomp = 2), g))
distance_table <- function(models, x = NULL) {
  call <- rlang::caller_env()
  cl <- if (inherits(models, "grasp_classification")) models else {
    if (!inherits(models, "grasp_models")) {
      hm_abort("{.arg models} must be a {.fn classify} result or {.cls grasp_models} from {.fn fit_grasp_models}, not {describe_value(models)}.",
               "bad_input", argument = "models", call = call)
    }
    if (is.null(x)) hm_abort("{.arg x} (the recordings to classify) is needed when {.arg models} are fitted models.",
                             "bad_input", argument = "x", call = call)
    classify(models, x, method = "fpca")
  }
  d <- cl$distances
  scale <- if (cl$method == "fpca") 100 / cl$target_length[colnames(d)] else rep(1, ncol(d))
  truth <- cl$predictions$truth
  types <- label_order(unique(as.character(stats::na.omit(truth))))
  if (length(types) == 0L) {
    hm_abort("No labelled recordings: a distance table needs true grasp types.", "no_labels",
             argument = "x", call = call)
  }
  tab <- vapply(types, function(type) {
    rows <- which(as.character(truth) == type)
    colMeans(sweep(d[rows, , drop = FALSE], 2L, scale, `*`), na.rm = TRUE)
  }, numeric(ncol(d)))
  matrix(tab, ncol(d), length(types), dimnames = list(model = colnames(d), truth = types))
}

#' Count the minima of a distance table
#'
#' The counts the thesis reports for Table 5.3: how many models have their
#' lowest mean distance for their own grasp type (row minimum on the diagonal),
#' how many grasp types have their lowest mean distance in their own model
#' (column minimum on the diagonal), how many both, and how many models are the
#' column minimum of no type.
#'
#' @param tab A `distance_table()` result.
#' @return A one-row data frame: `models`, `types`, `model_min_own_type`,
#'   `type_min_own_model`, `both`, `models_never_min`, and `most_attracting`
#'   (the model that is the minimum of most types) with `n_attracted`.
#' @noRd
#' @examples
#' tab <- matrix(c(1, 3, 2, 2, 1, 3, 4, 2, 5), 3,
#'               dimnames = list(model = c("A", "B", "C"), truth = c("A", "B", "C")))
distance_minima <- function(tab) {
  models <- rownames(tab)
  types <- colnames(tab)
  row_min <- colnames(tab)[apply(tab, 1L, which.min)]
  col_min <- rownames(tab)[apply(tab, 2L, which.min)]
  own_row <- row_min == models
  own_col <- col_min == types
  both <- intersect(models[own_row], types[own_col])
  attracted <- table(factor(col_min, levels = models))
  data.frame(models = length(models), types = length(types),
             model_min_own_type = sum(own_row), type_min_own_model = sum(own_col),
             both = length(both), models_never_min = sum(attracted == 0),
             most_attracting = names(attracted)[which.max(attracted)],
             n_attracted = as.integer(max(attracted)), stringsAsFactors = FALSE)
}
