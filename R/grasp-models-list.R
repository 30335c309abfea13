# A model set read as the list of its models. The set is a member of the
# classifier family (R/classifier.R): its models are the field `models`
# beside the family's fields (classes, levels, n, temperature) and its own
# (seed, distance), as hardhat's new_model() keeps a model's parts. Users,
# generate(), the thesis tables and the Python front end index it by type,
# so these methods keep that reading: `ms[["Tripod"]]` and `ms[[1]]` are
# models, `names(ms)` and `length(ms)` count the types (failed ones
# included), `as.list(ms)` (and so lapply() and vapply()) the list of
# models; `ms[types]` (R/grasp-models.R) is a smaller set. `ms$field` reads
# a field; `ms$Tripod`, the old reading of a type, is an error that names
# the new one, not a silent NULL. `ms[[type]] <- model` replaces a model
# and keeps the fields (the set is built again, so checked again).
# `for (m in ms)` walks the fields (R does not dispatch there): iterate over
# `as.list(ms)`.

#' @export
`[[.grasp_models` <- function(x, i, ...) .subset2(x, "models")[[i, ...]]

#' @export
`[[<-.grasp_models` <- function(x, i, value) {
  m <- .subset2(x, "models")
  m[[i]] <- value
  new_grasp_models(m, seed = x$seed, levels = x$levels, temperature = x$temperature, distance = x$distance)
}

#' @export
names.grasp_models <- function(x) names(.subset2(x, "models"))

#' @export
length.grasp_models <- function(x) length(.subset2(x, "models"))

#' @export
as.list.grasp_models <- function(x, ...) .subset2(x, "models")

#' @export
`$.grasp_models` <- function(x, name) {
  out <- .subset2(x, name)
  if (is.null(out) && name %in% names(.subset2(x, "models"))) {
    hm_abort(c("A model set's models are read with {.code [[}, not {.code $}: {.code x[[\"{name}\"]]}.",
               i = "{.code $} reads the set's fields ({.field {setdiff(names(unclass(x)), 'models')}}, {.field models})."),
             "bad_input", argument = "x", call = rlang::caller_env())
  }
  out
}
