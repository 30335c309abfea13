# The package's generics called on an object they have no method for. R's
# own "no applicable method for 'generate' applied to an object of class
# ..." names neither the argument nor what was meant; these say both, as
# classed bad_input errors (project.default lives in R/project.R).

# What each generic needs, and the way to it from recordings (cli markup):
# recordings are the commonest wrong argument, given where a fit was meant.
no_method_needs <- list(
  generate = c(needs = "a {.cls grasp_model} or {.cls grasp_models} fit",
               from_grasps = "These are recordings: fit first, e.g. {.code generate(fit_grasp_models(x))}."),
  predict = c(needs = "a fitted classifier",
              from_grasps = "Fit one first, e.g. {.code predict(fit_grasp_models(train), object)}."),
  project = c(needs = "a {.cls grasp_model} or {.cls grasp_models} fit",
              from_grasps = "These are recordings: fit first, e.g. {.code project(fit_grasp_models(x), x)}."),
  simulate = c(needs = "a fitted {.cls grasp_model}",
               from_grasps = "Simulate recordings with {.fn simulate_grasps}, or fit a model first: {.code simulate(fit_grasp_model(object))}.")
)

# The one error of the methods below and project.default(): `verb` needs
# what no_method_needs says for the argument `arg`, given `x`. Raised as
# class bad_input naming the argument, on behalf of the generic's caller
# (`call`).
abort_no_method <- function(verb, x, arg, call) {
  need <- no_method_needs[[verb]]
  given <- "{.obj_type_friendly {x}} (class {.cls {class(x)}})"
  hint <- NULL
  if (inherits(x, "grasps")) {
    given <- "recordings (a {.cls grasps} set)"
    hint <- c(i = need[["from_grasps"]])
  } else if (is.list(x) && length(x) && all(vapply(x, inherits, logical(1), "grasp_model"))) {
    hint <- c(i = "A list of {.cls grasp_model}s is not a model set: fit one with {.fn fit_grasp_models}.")
  }
  hm_abort(c(sprintf("{.fn %s} needs %s for {.arg %s}, not %s.", verb, need[["needs"]], arg, given), hint),
           "bad_input", argument = arg, call = call)
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
generate.default <- function(x, ...) abort_no_method("generate", x, "x", call = rlang::caller_env())

#' @rdname handmotion-wrong-class
#' @export
predict.grasps <- function(object, ...) abort_no_method("predict", object, "object", call = rlang::caller_env())

#' @rdname handmotion-wrong-class
#' @export
predict.list <- function(object, ...) abort_no_method("predict", object, "object", call = rlang::caller_env())

#' @rdname handmotion-wrong-class
#' @export
simulate.grasps <- function(object, ...) abort_no_method("simulate", object, "object", call = rlang::caller_env())
