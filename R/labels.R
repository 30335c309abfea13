# Class labels of recordings. A recording's class is whatever the user says it
# is: an object, a gesture, a Feix grasp type. Labels are stored as a factor
# in `meta$grasp`. When every label names a Feix type (by name in any
# spelling, or by id 1-33) the factor has the 33 Feix levels in id order, so
# Feix-labelled sets keep the thesis' order and tables; otherwise the levels
# are the user's own (a factor keeps its levels, other labels are sorted).

#' Feix grasp type names, in id order 1-33
#' @noRd
feix_levels <- function() handmotion::feix_taxonomy$name

# Are these the levels of a Feix-labelled set?
is_feix_levels <- function(levels) identical(as.character(levels), feix_levels())

# Feix ids of labels (NA where a label is not a Feix type, e.g. user labels).
feix_ids <- function(labels) match(as.character(labels), feix_levels())

# Integer codes 1-33 of the labels that name a Feix type by id or by a loose
# spelling of its name ("power sphere", "Sphere-4-Finger"); NA otherwise.
feix_codes <- function(x) {
  lev <- feix_levels()
  if (is.factor(x)) x <- as.character(x)
  out <- rep(NA_integer_, length(x))
  if (is.numeric(x)) {
    ok <- !is.na(x) & x %in% seq_along(lev)
    out[ok] <- as.integer(x[ok])
    return(out)
  }
  x <- as.character(x)
  key <- function(s) gsub("[^a-z0-9]", "", tolower(s))
  num <- suppressWarnings(as.integer(x))
  by_id <- !is.na(num) & num %in% seq_along(lev) & grepl("^\\s*[0-9]+\\s*$", x)
  out[by_id] <- num[by_id]
  m <- match(key(x), key(lev))
  out[!by_id] <- m[!by_id]
  # the thesis prints type 33 as "Inferrior Pincer"
  out[!by_id & key(x) == "inferriorpincer"] <- 33L
  out
}

#' Convert grasp ids or names to a factor over the 33 Feix types
#'
#' Accepts integer ids (1-33), names in any case with spaces, hyphens or
#' underscores, an existing factor, or NA; anything else is an error of class
#' `unknown_grasp`. Used where a Feix type is required (the simulator, the
#' thesis' tables).
#' @noRd
as_feix_grasp <- function(x, ids = NULL, call = rlang::caller_env(), arg = NULL) {
  lev <- feix_levels()
  out <- feix_codes(x)
  bad <- !is.na(x) & is.na(out)
  if (any(bad)) {
    # character, so cli pluralises on its length rather than reading a number as a count
    where <- as.character(if (!is.null(ids)) ids[bad] else which(bad))
    hm_abort(c("Unknown grasp type{?s} {.val {unique(as.character(x[bad]))}}.",
               i = if (!is.null(arg)) "In {.arg {arg}}." else NULL,
               i = if (!is.null(ids)) "In recording{?s} {.val {where}}." else "At position{?s} {.val {where}}.",
               i = "Use a Feix type name (see {.code feix_taxonomy$name}) or an id from 1 to 33."),
             "unknown_grasp", recording = where, argument = arg, call = call)
  }
  factor(lev[out], levels = lev)
}

# The labels of a new set: Feix types when every label is one, else the
# user's labels as they are. When only some labels look like Feix types the
# user may have misspelt one, or mixed vocabularies: say so (classed warning)
# and keep every label as given.
as_grasp_label <- function(x, ids = NULL, call = rlang::caller_env()) {
  if (is.factor(x) && is_feix_levels(levels(x))) return(x)
  given <- !is.na(x)
  if (!any(given)) return(factor(rep(NA_character_, length(x)), levels = feix_levels()))
  codes <- feix_codes(x)
  if (all(!is.na(codes[given]))) return(factor(feix_levels()[codes], levels = feix_levels()))
  lab <- if (is.factor(x)) droplevels(x) else as.character(x)
  if (!is.factor(lab) && !is.character(x) && !is.numeric(x) && !is.logical(x)) {
    hm_abort("Labels ({.field grasp}) must be strings, a factor or Feix ids, not {.obj_type_friendly {x}}.",
             "bad_input", argument = "meta", call = call)
  }
  if (!is.factor(lab)) lab <- factor(lab, levels = sort(unique(lab[given])))
  if (any(!is.na(codes[given]))) {
    feixy <- unique(as.character(x[given & !is.na(codes)]))
    other <- unique(as.character(x[given & is.na(codes)]))
    hm_warn(c("Some labels name Feix grasp types ({.val {utils::head(feixy, 3)}}), others do not ({.val {utils::head(other, 3)}}).",
              i = "All labels are kept as given, as your own classes; Feix ids and taxonomy are not attached.",
              i = "If these are Feix types, check the spelling against {.code feix_taxonomy$name}."),
            "mixed_labels", call = call)
  }
  lab
}

# Labels asked for by the user (`grasp = ` of generate(), `grasps = ` of a
# fit), resolved against the labels a set has: for Feix-labelled sets any id
# or spelling of a Feix type, otherwise the labels exactly. NULL stays NULL
# (all); an empty selection is an error (it would silently select nothing).
resolve_labels <- function(values, levels, arg, call = rlang::caller_env()) {
  if (is.null(values)) return(NULL)
  if (length(values) == 0L) {
    hm_abort("{.arg {arg}} must name at least one class label (or be {.code NULL} for all).",
             "bad_input", argument = arg, call = call)
  }
  if (anyNA(values)) {
    hm_abort("{.arg {arg}} must not contain missing labels.", "bad_input", argument = arg, call = call)
  }
  if (is.null(levels) || is_feix_levels(levels)) {
    codes <- feix_codes(values)
    if (!anyNA(codes)) return(feix_levels()[codes])
    if (!is.null(levels)) {
      # a Feix set asked for something that is not a Feix type
      as_feix_grasp(values, call = call, arg = arg)
    }
  }
  v <- as.character(values)
  bad <- setdiff(v, levels)
  if (length(bad)) {
    shown <- utils::head(levels, 12)
    more <- if (length(levels) > 12) " ..." else ""
    what <- if (length(bad) == 1L) "label" else "labels"
    hm_abort(c("Unknown {what} {.val {bad}} in {.arg {arg}}.",
               i = "The labels here are {.val {shown}}{more}."),
             "unknown_grasp", argument = arg, grasp = bad, call = call)
  }
  v
}

# Order labels for tables: Feix id order when all are Feix types, else the
# order of `levels` when given (the set's factor levels), else as given.
label_order <- function(types, levels = NULL) {
  feix <- feix_levels()
  if (length(types) && all(types %in% feix)) return(feix[feix %in% types])
  if (!is.null(levels)) return(c(levels[levels %in% types], setdiff(types, levels)))
  types
}

# A classed error where a Feix-typed set is required (the thesis' tables,
# the taxonomy-driven simulator and report).
check_feix_labels <- function(x, what, arg = "x", call = rlang::caller_env()) {
  lab <- if (inherits(x, "grasps")) x$meta$grasp else x
  if (!(is.factor(lab) && is_feix_levels(levels(lab)))) {
    shown <- utils::head(unique(as.character(stats::na.omit(lab))), 4)
    hm_abort(c("{what} needs recordings labelled by Feix grasp type; {.arg {arg}} has labels {.val {shown}}.",
               i = "Feix types are named as in {.code feix_taxonomy$name} or by id 1-33.",
               i = "Every other verb (fits, classifiers, evaluation, generation, plots) works with any labels."),
             "not_feix_labels", argument = arg, call = call)
  }
  invisible(x)
}

# The labels a model was fitted among (models from before labels were the
# user's have none stored: those were Feix types).
model_levels <- function(model) model$levels %||% feix_levels()

# The labels of a model set: those of its first fitted model, else its names.
model_set_levels <- function(x) {
  m <- fitted_models(x)
  if (length(m)) model_levels(m[[1]]) else names(x)
}
