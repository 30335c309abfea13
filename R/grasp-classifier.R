# A discriminative grasp classifier beyond the thesis (its chapter 6: the
# FPCA distance weighs every DoF and the whole motion alike, while grasp
# types differ in a few DoFs and mostly in the final posture). Linear
# discriminant analysis with a shrunk covariance (R/shrunk-lda.R) on the
# postures at fixed fractions of the motion and the log duration learns
# which DoFs and which moments separate the types, and gives class
# probabilities.

#' Fit a discriminant grasp classifier
#'
#' Describes every recording by its posture (all DoFs) at `at` fractions of
#' its own duration (linear interpolation between frames), its log duration
#' and how far each DoF travels (log of 1 + the sum of its absolute
#' frame-to-frame changes: two grasps can end alike after very different
#' motions), and fits linear discriminant analysis on those features: one
#' Gaussian per grasp type with a covariance shared by all types, the pooled
#' within-type correlation shrunk towards the identity by the analytic rule
#' of Schäfer and Strimmer (2005) (no tuning parameter). Unlike the thesis'
#' FPCA distance ([classify()] with [fit_grasp_models()]) it weighs DoFs and
#' moments by how well they separate the types, and it gives class
#' probabilities. Evaluate it held out by subject with
#' `evaluate_loso(x, method = "discriminant")`.
#'
#' @param x A labelled [grasps()] object (at least two grasp types, each with
#'   at least two recordings). Unlabelled recordings are an error.
#' @param at Fractions of the motion (in `[0, 1]`) at which the posture is
#'   taken; the default, 0, 1/8, ..., 1, was the best of 4, 8, 12 and 16
#'   equal steps held out by subject on the default data.
#' @param prior `"equal"` (default: every type equally likely a priori) or
#'   `"data"` (the training shares).
#' @return An object of class `grasp_classifier`: a list with `classes`,
#'   `levels` (of the training labels, carried by predictions),
#'   `at`, `dofs`, `rate`, `prior`, `fit` (the discriminant: whitening
#'   matrix, class centres, log priors, `shrinkage`), `n` (training
#'   recordings per type). Use [predict.grasp_classifier()] for classes or
#'   probabilities and [classify()] for a `grasp_classification`.
#' @seealso [predict.grasp_classifier()], [evaluate_loso()],
#'   [fit_grasp_recognizer()] for recognition while the hand is still moving.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 6, grasps = 1:4, objects = 2, trials = 2, seed = 1)
#' train <- g[g$meta$subject != "S06"]
#' test <- g[g$meta$subject == "S06"]
#' cl <- fit_grasp_classifier(train)
#' cl
#' predict(cl, test)
#' head(predict(cl, test, type = "prob"))
#' classify(cl, test)
fit_grasp_classifier <- function(x, at = seq(0, 1, by = 0.125), prior = c("equal", "data")) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  at <- check_fractions(at, "at", call = call)
  prior <- check_choice(prior, arg = "prior", call = call)
  y <- check_training_labels(x, call = call)
  F <- classifier_features(x, at)
  new_grasp_classifier(fit_shrunk_lda(F, y, prior), at = at, dofs = x$dofs, rate = x$rate,
                       prior = prior, levels = grasp_levels(x))
}

classifier_features <- function(x, at) cbind(motion_features(x, at), travel_features(x))

# The levels predictions carry: those of the training labels (all Feix
# types when they are a Feix factor), so predictions compare with labels.
grasp_levels <- function(x) {
  g <- x$meta$grasp
  if (is.factor(g)) levels(g) else sort(unique(as.character(g)))
}

new_grasp_classifier <- function(fit, at, dofs, rate, prior, levels) {
  structure(list(classes = fit$classes, levels = levels, at = at, dofs = dofs, rate = rate, prior = prior,
                 fit = fit, n = stats::setNames(fit$n, fit$classes)),
            class = "grasp_classifier")
}

# Fractions of the motion: finite numbers in [0, 1], sorted, no duplicates.
check_fractions <- function(at, arg, call = rlang::caller_env()) {
  if (!is.numeric(at) || !length(at) || anyNA(at) || any(at < 0 | at > 1)) {
    hm_abort("{.arg {arg}} must be fractions of the motion: numbers in [0, 1], not {describe_value(at)}.", "bad_input",
             argument = arg, call = call)
  }
  sort(unique(as.numeric(at)))
}

# New recordings for a fitted classifier or recogniser: a grasps object with
# exactly the DoFs it was trained on, in that order.
check_trained_dofs <- function(x, dofs, what, call = rlang::caller_env()) {
  check_grasps(x, arg = "newdata", call = call)
  if (!identical(x$dofs, dofs)) {
    hm_abort(c("{.arg newdata} has other DoFs than the {what} was trained on.",
               i = "Trained on: {.val {dofs}}.", x = "Given: {.val {x$dofs}}."),
             "bad_input", argument = "newdata", call = call)
  }
  invisible(x)
}

# The grasp labels of a training set: every recording labelled, at least
# two types, at least two recordings each.
check_training_labels <- function(x, call = rlang::caller_env()) {
  y <- x$meta$grasp
  if (anyNA(y)) {
    hm_abort(c("{.arg x} has {sum(is.na(y))} unlabelled recording{?s}; a classifier is trained on labelled ones.",
               i = "Drop them first, e.g. {.code x[!is.na(x$meta$grasp)]}."),
             "bad_input", argument = "x", call = call)
  }
  y <- droplevels(as.factor(y))
  counts <- table(y)
  if (length(counts) < 2L) {
    hm_abort("{.arg x} holds {length(counts)} grasp type{?s}; a classifier needs at least two.",
             "bad_input", argument = "x", call = call)
  }
  if (any(counts < 2L)) {
    few <- names(counts)[counts < 2L]
    hm_abort("Grasp type{?s} {.val {few}} ha{?s/ve} fewer than two recordings in {.arg x}.",
             "bad_input", argument = "x", call = call)
  }
  y
}

#' Predict grasp types with a discriminant classifier
#'
#' @param object A [fit_grasp_classifier()] result.
#' @param newdata A [grasps()] object with the classifier's DoFs.
#' @param type `"class"` (a factor of predicted types) or `"prob"` (a
#'   matrix of class probabilities, recordings x types, rows summing to 1).
#' @param ... Not used.
#' @return A factor (with the levels of the training labels, so it compares
#'   with `newdata$meta$grasp`) or a probability matrix
#'   with the recordings' ids as row names.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 1:3, objects = 2, trials = 2, seed = 1)
#' cl <- fit_grasp_classifier(g)
#' table(predict(cl, g), g$meta$grasp)
predict.grasp_classifier <- function(object, newdata, type = c("class", "prob"), ...) {
  call <- rlang::caller_env()
  type <- check_choice(type, arg = "type", call = call)
  s <- classifier_log_posterior(object, newdata, call = call)
  if (type == "prob") return(softmax_rows(s))
  factor(top_class(object$classes, s), levels = object$levels)
}

# Log posteriors (rows: recordings of x, columns: types), after checking
# that x is what the classifier was trained on.
classifier_log_posterior <- function(object, x, call = rlang::caller_env()) {
  check_trained_dofs(x, object$dofs, "classifier", call = call)
  s <- shrunk_lda_scores(object$fit, classifier_features(x, object$at))
  rownames(s) <- x$meta$id
  s
}

#' @export
print.grasp_classifier <- function(x, ...) {
  cat(sprintf("<grasp_classifier> shrinkage LDA, %d grasp types, %d training recordings\n",
              length(x$classes), sum(x$n)))
  cat(sprintf("  features: %d DoFs at %d fractions of the motion (%s) + log duration + travel per DoF\n",
              length(x$dofs), length(x$at), paste(signif(x$at, 3), collapse = ", ")))
  cat(sprintf("  correlation shrinkage %.3f; %s priors\n", x$fit$shrinkage, x$prior))
  invisible(x)
}
