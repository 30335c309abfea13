# The family of fitted grasp classifiers, after hardhat's new_model(): one
# constructor, one parent class ("grasp_classifier") and the internal
# generics every operation of the family finds a classifier's parts
# through. predict(), classify(), evaluate_loso(), summary() and print()
# are written once against these generics, so a new classifier is one file
# holding its fit and its methods (tests/testthat/test-classifier.R
# builds one in the test alone):
#
#   classifier_distances()  recordings x classes, smaller is closer (required)
#   classifier_method()     its name among classify()'s methods
#   classifier_parts()      the fields its predict() reads, re-checked there
#   classifier_classes(), classifier_levels(), classifier_temperature():
#                           the family fields, read alike for every member
#
# The members: the FPCA model set (R/grasp-models.R, class grasp_models,
# which also reads as the list of its models: R/grasp-models-list.R), the
# discriminant (R/classifier-discriminant.R, grasp_discriminant), the
# last-frame PCA (R/classifier-last-frame.R, last_frame_pca), the weighted FPCA
# distance (R/classifier-weighted-fpca.R, weighted_fpca) and the early recogniser
# (R/classifier-recognizer.R, grasp_recognizer).

# The one constructor of the family. `...` are the classifier's own named
# fields; the family's fields are
#   classes      the classes it ranks, in its order (character)
#   levels       the levels of the training labels, which predictions carry
#                (so they compare with new_data$meta$grasp); the classes by
#                default
#   n            training recordings per class (integer, named by class)
#   temperature  of its probabilities, softmax(-distance / temperature);
#                NULL: it gives no probabilities
# `class` is the subclass, put before the parent "grasp_classifier".
new_grasp_classifier <- function(..., classes, levels = classes, n, temperature = NULL, class) {
  fields <- list(...)
  stopifnot(is.character(class), length(class) >= 1L,
            !length(fields) || (!is.null(names(fields)) && all(nzchar(names(fields)))))
  out <- c(fields, list(classes = classes, levels = levels,
                        n = stats::setNames(as.integer(n), classes), temperature = temperature))
  validate_grasp_classifier(structure(out, class = c(class, "grasp_classifier")))
}

# The family fields agree with one another: unique classes, all of them
# among the levels, a count for each, a positive temperature or none. (A
# model set whose every type failed has no class: it is kept as the record
# of why, and refuses to predict.)
validate_grasp_classifier <- function(x) {
  cls <- x$classes
  t <- x$temperature
  stopifnot(is.character(cls), !anyNA(cls), !anyDuplicated(cls),
            is.character(x$levels), all(cls %in% x$levels),
            is.integer(x$n), length(x$n) == length(cls), all(x$n >= 0L),
            is.null(t) || (is.numeric(t) && length(t) == 1L && is.finite(t) && t > 0))
  x
}

# ---- the internal generics ------------------------------------------------

# The distances of every recording of `new_data` to every class (recordings x
# classes, row names the recording ids, column names the classes; smaller is
# closer). A method may return the matrix alone, or a list with
# `distances` and the model set's `target_length` and `failures`.
# `seen` (frames seen per recording) is the recogniser's only.
classifier_distances <- function(object, new_data, ..., call = rlang::caller_env()) {
  UseMethod("classifier_distances")
}

#' @export
classifier_distances.default <- function(object, new_data, ..., call = rlang::caller_env()) {
  not_a_classifier(object, "object", call)
}

# The distances in the one shape predict() and classify() read.
distance_result <- function(object, new_data, call, seen = NULL) {
  res <- if (is.null(seen)) classifier_distances(object, new_data, call = call)
         else classifier_distances(object, new_data, seen = seen, call = call)
  if (is.matrix(res)) res <- list(distances = res)
  list(distances = res$distances, target_length = res$target_length,
       failures = res$failures %||% no_failures())
}

# The `method` of classify() and evaluate_loso() a classifier answers to;
# a classifier of a method neither knows answers with its class.
classifier_method <- function(object) UseMethod("classifier_method")

#' @export
classifier_method.default <- function(object) class(object)[1]

# The fields predict() reads, checked before every prediction
# (check_fitted_parts()); none by default.
classifier_parts <- function(object) UseMethod("classifier_parts")

#' @export
classifier_parts.default <- function(object) character(0)

#' @export
classifier_parts.grasp_classifier <- function(object) c("classes", "levels", "n")

classifier_classes <- function(object) UseMethod("classifier_classes")

#' @export
classifier_classes.default <- function(object) object$classes

# The levels of the predicted class: those of the training labels, or the
# classes for a classifier built without them.
classifier_levels <- function(object) UseMethod("classifier_levels")

#' @export
classifier_levels.default <- function(object) object$levels %||% classifier_classes(object)

classifier_temperature <- function(object) UseMethod("classifier_temperature")

#' @export
classifier_temperature.default <- function(object) object$temperature

# A temperature to compute probabilities with, or a classed error.
required_temperature <- function(object, call) {
  t <- classifier_temperature(object)
  if (is.null(t)) {
    hm_abort(c("This {.cls {class(object)[1]}} has no fitted temperature, so it gives no probabilities.",
               i = "Fit it with {.fn fit_grasp_models} or {.fn fit_grasp_classifier}."),
             "bad_model", argument = "object", call = call)
  }
  t
}

# A member of the family given as `arg`, or a classed error naming it.
check_classifier <- function(object, arg, call = rlang::caller_env()) {
  if (!inherits(object, "grasp_classifier") || identical(class(object), "grasp_classifier")) {
    not_a_classifier(object, arg, call)
  }
  invisible(object)
}

# Not a member of the family. The discriminant of earlier development
# versions was class "grasp_classifier" alone, the name the family's parent
# now has: such a saved fit is named as the old class it is, with the refit
# that gives a member (as R/renamed.R does for renamed arguments).
not_a_classifier <- function(object, arg, call) {
  if (identical(class(object), "grasp_classifier")) {
    hm_abort(c("{.arg {arg}} is a discriminant saved by an earlier version of handmotion (class {.cls grasp_classifier} alone).",
               i = "The discriminant is now class {.cls grasp_discriminant} of the family {.cls grasp_classifier}: refit it with {.code fit_grasp_classifier(x)}."),
             "bad_model", argument = arg, call = call)
  }
  hm_abort(c("{.arg {arg}} must be a fitted grasp classifier, not {.obj_type_friendly {object}}.",
             i = "Fit one with {.fn fit_grasp_models}, {.fn fit_grasp_classifier} or {.fn fit_grasp_recognizer}."),
           "bad_input", argument = arg, call = call)
}

# ---- the family's methods ---------------------------------------------------

#' @rdname predict.grasp_models
#' @export
predict.grasp_classifier <- function(object, new_data, type = c("class", "prob", "distance"), ...) {
  predict_classifier(object, new_data, type, list(...), rlang::caller_env())
}

#' Summaries of the fitted grasp classifiers
#'
#' One row per class the classifier was trained on. Every fitted classifier
#' (a [fit_grasp_models()] set, each [fit_grasp_classifier()] method and a
#' [fit_grasp_recognizer()]) is of the family `grasp_classifier`: it has a
#' `print()` and a `summary()` method and answers
#' [predict()][predict.grasp_models()], [classify()] and [evaluate_loso()]
#' alike.
#'
#' @param object A [fit_grasp_classifier()] or [fit_grasp_recognizer()]
#'   result (a [fit_grasp_models()] set has its own, longer summary:
#'   [summary.grasp_models()]).
#' @param ... Unused.
#' @return A data frame whose first columns are those of every classifier's
#'   summary, the set's included: `grasp_id` (the class's Feix id, `NA` for
#'   another label), `grasp` (the class) and `n` (its training recordings);
#'   then by classifier: `"discriminant"` `log_prior` and `subclasses` (the
#'   clusters the type was split into, by the finest fit of the ensemble); the recogniser `log_prior`;
#'   `"last_frame"` `ncomp_used` (PCs used) and `var_explained` (the fraction of
#'   the type's last-frame variance they explain); `"weighted_fpca"`
#'   `top_dofs` (the two DoFs it weighs most for the type) and `weight_range`
#'   (largest over smallest DoF weight).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 1:3, objects = 2, trials = 2, seed = 1)
#' summary(fit_grasp_classifier(g))
#' summary(fit_grasp_classifier(g, method = "last_frame", ncomp = 2))
#' summary(fit_grasp_recognizer(g))
summary.grasp_classifier <- function(object, ...) classifier_summary_frame(object)

# The columns every classifier's summary() begins with: `grasp_id` (the
# Feix id of the class, NA for another label), `grasp` (the class) and `n`
# (training recordings of the class), then the classifier's own (`...`, one
# value per class, in the order of its classes).
classifier_summary_frame <- function(object, ..., classes = classifier_classes(object), n = object$n[classes]) {
  data.frame(grasp_id = feix_ids(classes), grasp = classes, n = as.integer(n), ...,
             stringsAsFactors = FALSE, row.names = NULL)
}

# A member without its own print(): what every classifier has.
#' @export
print.grasp_classifier <- function(x, ...) {
  t <- classifier_temperature(x)
  cli::cat_line(sprintf("<%s> grasp classifier: %s, %s", class(x)[1],
                        cli::pluralize("{length(x$classes)} class{?es}"),
                        cli::pluralize("{sum(x$n)} training recording{?s}")))
  cli::cat_line("  classes: ", name_list(x$classes, 6L))
  if (!is.null(t)) cli::cat_line(sprintf("  class probabilities: softmax(-distance / %.3g)", t))
  invisible(x)
}
