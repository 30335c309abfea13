# Arguments of fit_grasp_model() that need more than a check: the engine per
# step and the one grasp type to fit.

# engine: one of "fast"/"reference" for every step, or a named list per step.
resolve_engines <- function(engine, call) {
  steps <- c("align", "fpca", "gmm")
  choices <- c("fast", "reference")
  if (is.list(engine)) {
    bad <- setdiff(names(engine), steps)
    if (is.null(names(engine)) || length(bad)) {
      hm_abort(c("A list {.arg engine} must be named by step ({.val {steps}}).",
                 x = if (length(bad)) "Unknown step{?s}: {.val {bad}}."),
               "bad_input", argument = "engine", call = call)
    }
    out <- stats::setNames(as.list(rep("fast", 3)), steps)
    for (s in names(engine)) out[[s]] <- check_choice(engine[[s]], c("fast", "reference"), "engine", call = call)
    return(out)
  }
  if (is.character(engine) && identical(engine, choices)) engine <- "fast"
  e <- check_choice(engine, c("fast", "reference"), "engine", call = call)
  stats::setNames(as.list(rep(e, 3)), steps)
}

# Select the recordings of one type; refuse a set that mixes types.
select_one_type <- function(x, grasp, call) {
  if (!is.null(grasp)) {
    if (length(grasp) != 1L || is.na(grasp)) {
      hm_abort("{.arg grasp} must name one class label.", "bad_input", argument = "grasp", call = call)
    }
    g <- resolve_labels(grasp, levels(x$meta$grasp), "grasp", call = call)
    x <- x[!is.na(x$meta$grasp) & x$meta$grasp == g]
    if (length(x) == 0L) {
      hm_abort("No recordings of grasp type {.val {as.character(g)}} in {.arg x}.",
               "too_few_recordings", argument = "grasp", call = call)
    }
  }
  unlabelled <- is.na(x$meta$grasp)
  if (any(unlabelled)) {
    hm_abort(c("{sum(unlabelled)} of the {length(x)} recording{?s} in {.arg x} ha{?s/ve} no grasp type label.",
               i = "A model is fitted to the recordings of one labelled type; first unlabelled: {.val {x$meta$id[unlabelled][1]}}."),
             "no_labels", argument = "x", call = call)
  }
  types <- unique(as.character(x$meta$grasp))
  if (length(types) > 1L) {
    hm_abort(c("{.arg x} holds {length(types)} grasp types; {.fn fit_grasp_model} fits one.",
               i = "Types: {.val {types}}.",
               i = "Give {.arg grasp}, or use {.fn fit_grasp_models} for every type."),
             "multiple_grasps", argument = "x", call = call)
  }
  x
}
