# Progress of the package's long calls (issue 36: no wait without a
# reason; issue 42: drawn where progressr's conventions say). Every loop that
# can take more than a couple of seconds (the fits per type, the folds, the
# horizons, the models a set of recordings is projected on) counts its steps
# with a progressr progressor, which also works from future workers. Whether
# a bar is drawn follows progressr's conventions:
#
# * in an interactive session, the outermost long call draws a bar without
#   any set-up (after 2 s: progressr's `progressr.enable_after`, unless the
#   user set it), so quick calls stay quiet;
# * in a script (`Rscript script.R > log`, knitr, Python) nothing is drawn
#   unless the user asked: `options(progressr.enable = TRUE)`, or handlers
#   chosen with `progressr::handlers(...)`;
# * the user's own `progressr::with_progress()` or global handlers
#   (`progressr::handlers(global = TRUE)`) receive the steps and draw them as
#   they were set up to (the package adds no bar of its own);
# * `options(handmotion.progress = FALSE)` turns it off (nothing is
#   signalled or shown);
# * inside a call that already counts (reproduce_thesis(), an outer long call
#   of the package, a fold on a worker) inner calls count nothing.
#
# Steps are signalled once per type, fold, horizon or model (tens per call),
# never per recording: from workers each is one small message.

progress_wanted <- function() isTRUE(getOption("handmotion.progress", TRUE))

# Does the session ask for bars (progressr's conventions, see above)?
# (progressr sets progressr.enable to interactive() as it loads, so the option
# says both: interactive, or turned on by the user)
progress_drawn_here <- function() {
  isTRUE(getOption("progressr.enable", interactive())) || !is.null(getOption("progressr.handlers"))
}

# Evaluate `expr` showing the progress of the package's progressors in it
# when the session asks for bars and nobody else receives the steps.
with_progress_shown <- function(expr) {
  if (!progress_wanted() || isTRUE(progress_state$active) || isTRUE(progress_state$listener) ||
      !progress_drawn_here() || isTRUE(progressr::handlers(global = NA)) || inside_with_progress()) {
    return(expr)
  }
  # (progressr's handlers check progressr.enable themselves, with
  # interactive() as its default: set here, where the session asked for bars)
  opts <- list(progressr.enable = TRUE)
  if (is.null(getOption("progressr.enable_after"))) opts$progressr.enable_after <- 2
  old <- options(opts)
  on.exit(options(old), add = TRUE)
  progressr::with_progress(expr, handlers = progressr::handlers(), enable = TRUE,
                           delay_stdout = FALSE, delay_conditions = character(0))
}

# A progressor of `steps` steps for the calling function, or a function that
# does nothing when progress is off or another progressor of the package is
# already counting (progressr draws one bar at a time: the outermost long
# step counts, the steps inside it do not).
hm_progressor <- function(steps, envir = parent.frame()) {
  if (!progress_wanted() || isTRUE(progress_state$active) || steps < 1) return(progress_noop)
  progress_state$active <- TRUE
  # (the release function itself goes into the caller's on.exit, as withr's
  # defer() does it)
  do.call(base::on.exit, list(as.call(list(progress_release)), add = TRUE), envir = envir)
  progressr::progressor(steps = steps, envir = envir)
}

# The progressor that counts nothing. Top-level (its environment is the
# namespace) because progressors travel to future workers with every chunk:
# a closure made inside hm_progressor() would carry its frame along, and with
# it the caller's (the whole data set and every type's part, serialised into
# each chunk: issue 43, where two workers took twice the time of one).
progress_noop <- function(...) invisible(NULL)

progress_state <- new.env(parent = emptyenv())
progress_state$active <- FALSE
progress_state$listener <- FALSE

progress_release <- function() progress_state$active <- FALSE

# Until the calling function returns, the package's long calls in this
# process count nothing: an outer progressor counts for them. A fold or
# chunk run on a future worker calls it (the worker's own process does not
# know the main process already counts: without it every inner fit would
# send its own steps back, and the bar would jump between progressors).
local_counted_outside <- function(envir = parent.frame()) local_progress_flag("active", envir)

# Until the calling function returns, a listener of its own (reproduce_thesis()'s
# report printer) receives the steps: the long calls count but draw no bar
# (a bar's with_progress() would catch the steps before the listener).
local_progress_listener <- function(envir = parent.frame()) local_progress_flag("listener", envir)

# Sets one flag of progress_state to TRUE until `envir`'s function returns,
# then puts back what it was (the two local_*() above).
local_progress_flag <- function(flag, envir) {
  old <- progress_state[[flag]]
  progress_state[[flag]] <- TRUE
  do.call(base::on.exit, list(as.call(list(progress_flag_restore, flag, old)), add = TRUE), envir = envir)
  invisible()
}

progress_flag_restore <- function(flag, old) assign(flag, old, envir = progress_state)

# Is the call inside the user's own progressr::with_progress()? Then the
# progress goes to the user's handlers: a second with_progress() here would
# catch (and muffle) every update before it reached them.
inside_with_progress <- function() {
  wp <- progressr::with_progress
  n <- sys.nframe()
  for (i in seq_len(max(0L, n - 1L))) if (identical(sys.function(i), wp)) return(TRUE)
  FALSE
}
