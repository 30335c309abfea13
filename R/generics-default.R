# The package's generics called on an object they have no method for. R's
# own "no applicable method for 'generate' applied to an object of class
# ..." names neither the argument nor what was meant; these say both, as
# classed bad_input errors (project.default lives in R/project.R).

# What a fitted-model argument should have been, for the messages: a list of
# fitted models, or recordings, get a hint of their own.
wrong_fit_hint <- function(x, fitter) {
  if (inherits(x, "grasps")) {
    return(c(i = sprintf("These are recordings: fit first, e.g. {.code %s(x)}.", fitter)))
  }
  if (is.list(x) && length(x) && all(vapply(x, inherits, logical(1), "grasp_model"))) {
    return(c(i = "A list of {.cls grasp_model}s is not a model set: fit one with {.fn fit_grasp_models}."))
  }
  NULL
}

#' Methods for objects that have none
#'
#' [generate()], [predict()] and [stats::simulate()] called on an object
#' handmotion has no method for (recordings, a plain list, text) raise a
#' classed error of class `handmotion_error_bad_input` naming the argument
#' and the class received, instead of R's "no applicable method".
#'
#' @param x,object The object given.
#' @param ... Ignored.
#' @return Nothing: these always raise an error.
#' @name handmotion-wrong-class
#' @keywords internal
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 2, seed = 1)
#' try(generate(g))
#' try(predict(list(1, 2)))
NULL

#' @rdname handmotion-wrong-class
#' @export
generate.default <- function(x, ...) {
  hm_abort(c("{.fn generate} needs a {.cls grasp_model} or {.cls grasp_models} fit for {.arg x}, not {.obj_type_friendly {x}} (class {.cls {class(x)}}).",
             wrong_fit_hint(x, "fit_grasp_models")),
           "bad_input", argument = "x", call = rlang::caller_env())
}

#' @rdname handmotion-wrong-class
#' @export
predict.grasps <- function(object, ...) {
  hm_abort(c("{.fn predict} needs a fitted classifier for {.arg object}, not recordings (a {.cls grasps} set).",
             i = "Fit one first, e.g. {.code predict(fit_grasp_models(train), object)}."),
           "bad_input", argument = "object", call = rlang::caller_env())
}

#' @rdname handmotion-wrong-class
#' @export
predict.list <- function(object, ...) {
  hm_abort(c("{.fn predict} has no method for a plain list given as {.arg object}; it needs a fitted model.",
             wrong_fit_hint(object, "fit_grasp_models")),
           "bad_input", argument = "object", call = rlang::caller_env())
}

#' @rdname handmotion-wrong-class
#' @export
simulate.grasps <- function(object, ...) {
  hm_abort(c("{.fn simulate} needs a fitted {.cls grasp_model} for {.arg object}, not recordings (a {.cls grasps} set).",
             i = "Simulate recordings with {.fn simulate_grasps}, or fit a model first: {.code simulate(fit_grasp_model(object))}."),
           "bad_input", argument = "object", call = rlang::caller_env())
}
