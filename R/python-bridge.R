# The R side of the Python front end (inst/python/handmotion, through rpy2).
# Python reaches these internals through one exported, documented entry,
# python_bridge(), never through `:::`; they live here, not as R code in
# Python strings, so that testthat runs them (test-python-bridge.R).

#' The Python front end's entry into R
#'
#' The handmotion Python package (`inst/python`, through rpy2) reaches R
#' only through the package's exports: the user verbs, called by name, and
#' this function for the few steps of the bridge itself. Each `part` is one
#' step: R users have no need of it.
#'
#' * `"call"`: `(f, args)` calls the exported function named `f` with the
#'   list `args` and turns every condition into a value: a list with `ok`,
#'   `value`, `warnings` (each with its `message` and `class`) and, for an
#'   error, its `message` and `class`, for Python to raise as a classed
#'   exception.
#' * `"grasps_out"`: `(x)` flattens a [grasps()] set into one numeric vector
#'   of all recordings and its metadata (faster across rpy2 than a list of
#'   matrices); `"grasps_in"`: the inverse, rebuilt through [grasps()].
#' * `"default_dofs"`: `(p)` the DoF names [grasps()] gives `p` unnamed
#'   columns.
#' * `"fitted_types"`: `(models)` the types of a model set that have a fitted
#'   model; `"dependence_matrix"`: `(model)` the correlation a model
#'   generates its DoFs' first FPC scores with.
#' * `"widget_html"`: `(widget)` a [hand_3d()] widget as one self-contained
#'   HTML page (text).
#' * `"progress_setup"`: `(terminal)` progress bars on standard output in a
#'   terminal, none elsewhere (called once as Python starts R).
#' * `"print_text"`: `(x)` what `print(x)` writes, as lines of text (a
#'   Python handle's `repr()`).
#'
#' @param part Which step of the bridge (see above).
#' @param ... The step's arguments.
#' @return What the step returns (see above).
#' @keywords internal
#' @export
#' @examples
#' res <- python_bridge("call", "simulate_grasps",
#'                      list(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1))
#' res$ok
#' flat <- python_bridge("grasps_out", res$value)
#' length(flat$values)
#' python_bridge("call", "simulate_grasps", list(subjects = -1))$class
python_bridge <- function(part = c("call", "grasps_out", "grasps_in", "default_dofs", "fitted_types",
                                   "dependence_matrix", "widget_html", "progress_setup", "print_text"), ...) {
  part <- check_choice(part, arg = "part")
  step <- switch(part, call = py_call, grasps_out = py_grasps_out, grasps_in = py_grasps_in,
                 default_dofs = py_default_dofs, fitted_types = py_fitted_types,
                 dependence_matrix = py_dependence_matrix, widget_html = py_widget_html,
                 progress_setup = py_progress_setup, print_text = py_print_text)
  step(...)
}

# Call `f` (an exported handmotion function's name, or a function) with the list
# `args`, turning every condition into a value: an error becomes
# list(ok = FALSE, message, class) for Python to raise as a classed exception,
# and warnings are collected (not printed) for Python to re-issue.
py_call <- function(f, args) {
  fun <- if (is.function(f)) f else getExportedValue("handmotion", f)
  warned <- list()
  keep <- function(w) {
    warned[[length(warned) + 1L]] <<- list(message = cli::ansi_strip(conditionMessage(w)), class = class(w))
    invokeRestart("muffleWarning")
  }
  tryCatch(list(ok = TRUE, value = withCallingHandlers(do.call(fun, args), warning = keep), warnings = warned),
           error = function(e) list(ok = FALSE, message = cli::ansi_strip(conditionMessage(e)),
                                    class = class(e), warnings = warned))
}

# A grasps object flattened for the bridge: every recording's values in one
# numeric vector (column-major, recording after recording), which crosses rpy2
# far faster than a list of matrices; factors of meta become character, the
# label levels travel separately so their order survives, and so do the
# recordings' switch channels (GraspDB14, for segment_by_switch()).
py_grasps_out <- function(x) {
  meta <- x$meta
  for (nm in names(meta)) if (is.factor(meta[[nm]])) meta[[nm]] <- as.character(meta[[nm]])
  list(values = as.double(unlist(lapply(x$recordings, as.vector), use.names = FALSE)),
       n_frames = as.integer(x$meta$n_frames), meta = meta, dofs = x$dofs,
       rate = x$rate, unit = x$unit, levels = levels(x$meta$grasp),
       glove_name = x$glove$name, glove = x$glove$channels,
       switch = lapply(x$recordings, function(r) attr(r, "switch")))
}

# The inverse of py_grasps_out(): rebuilt through grasps(), so Python input is
# validated by the same constructor as R input.
py_grasps_in <- function(values, n_frames, meta, dofs, rate, unit, levels = NULL, glove = NULL,
                         glove_name = NULL, switch = NULL) {
  if (!is.null(levels) && "grasp" %in% names(meta)) meta$grasp <- factor(meta$grasp, levels = levels)
  if (is.data.frame(glove)) glove <- glove_profile(glove, name = glove_name)
  recs <- py_unstack(values, n_frames, dofs)
  x <- grasps(recs, meta = meta, dofs = dofs, rate = rate, unit = unit, glove = glove)
  # a recording's switch states, one per frame (NULL: it has none)
  for (i in seq_along(switch)) {
    if (!is.null(switch[[i]])) {
      check_switch(switch[[i]], n = n_frames[i], call = rlang::caller_env())
      attr(x$recordings[[i]], "switch") <- as.integer(switch[[i]])
    }
  }
  x
}

# The recordings of the values Python stacked (n_frames[i] rows of the DoFs
# each), cut apart by the routine the workers use (src/stack-values.c). The
# counts come from Python, so they are checked here, with a classed error,
# before the C routine trusts them.
py_unstack <- function(values, n_frames, dofs, call = rlang::caller_env()) {
  if (!is.character(dofs) || length(dofs) == 0L || anyNA(dofs)) {
    hm_abort("{.arg dofs} must name at least one DoF, not {describe_value(dofs)}.", "bad_input",
             argument = "dofs", call = call)
  }
  if (!is.numeric(n_frames) || anyNA(n_frames) || any(n_frames < 0 | n_frames != round(n_frames)) ||
      any(n_frames > .Machine$integer.max)) {
    hm_abort("{.arg n_frames} must be whole frame counts, one a recording.", "bad_input",
             argument = "n_frames", call = call)
  }
  if (!is.numeric(values) || length(values) != sum(n_frames) * length(dofs)) {
    hm_abort(c("{.arg values} must hold every frame of every DoF: {sum(n_frames)} frame{?s} of {length(dofs)} DoF{?s} are {sum(n_frames) * length(dofs)} value{?s}, not {length(values)}.",
               i = "Each recording's values go column after column (Fortran order), recording after recording."),
             "bad_input", argument = "values", call = call)
  }
  .Call(hm_unstack_values, as.double(values), as.integer(n_frames), dofs, NULL)
}

# The DoF names grasps() gives p unnamed columns (asked by Python's Grasps(), so
# the default list is written down once, in R).
py_default_dofs <- function(p) grasps(list(matrix(0, 1L, p)))$dofs

# The grasp types of a model set that have a fitted model (a failed type stays
# in the set without one).
py_fitted_types <- function(models) names(fitted_models(models))

# The correlation a model generates its DoFs' first FPC scores with.
py_dependence_matrix <- function(model) attr(summary(model), "dependence_matrix")

# A widget as one self-contained HTML page, returned as text.
py_widget_html <- function(widget) {
  file <- tempfile(fileext = ".html")
  on.exit(unlink(file))
  htmlwidgets::saveWidget(widget, file, selfcontained = TRUE)
  paste(readLines(file, warn = FALSE, encoding = "UTF-8"), collapse = "\n")
}

# Progress bars through Python (issue 42). rpy2's embedded R is interactive,
# so by progressr's conventions the long calls would draw their bar on
# standard error, which rpy2 logs one line per update ("R[write to console]:
# |====   |   6%"). In a terminal (`terminal`: Python's standard output is a
# tty) the bar goes to standard output instead, which rpy2 prints as it comes,
# so its carriage returns redraw one bar in place; elsewhere (a log, a
# notebook, pytest) no bar: `progressr.enable = FALSE`. Called once as R starts.
py_progress_setup <- function(terminal) {
  if (isTRUE(terminal)) {
    progressr::handlers(progressr::handler_txtprogressbar(file = stdout()))
  } else {
    options(progressr.enable = FALSE)
  }
  invisible(isTRUE(terminal))
}

# What print(x) writes, as lines: print() runs inside capture.output() (called
# from Python, R's print() ran first and wrote the whole object to the
# console, and the repr then showed it again).
py_print_text <- function(x) utils::capture.output(print(x))
